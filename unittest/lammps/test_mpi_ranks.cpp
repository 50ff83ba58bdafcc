// 1 vs 2 MPI ranks (run under mpirun -np 2): non-interacting polyhedra that
// cross subdomain and periodic boundaries follow identical trajectories on
// 1 and on 2 ranks, and the particle count never changes (issue 2, item 3).

#include "polydem_allgather.h"
#include "polydem_lmp.h"

#include "force.h"
#include "pair.h"
#include "polydem_pair_counts.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>

using polydem_test::Lmp;
using polydem_test::potentials;

namespace {

// A data file (written by rank 0) fixes atom IDs, positions, orientations and
// velocities independently of the number of ranks (create_atoms and velocity
// would number atoms or sum momenta per rank).
std::string write_data(int n)
{
  // one file per rank count: ctest runs the 2- and 4-rank tests side by side
  int me, nprocs;
  MPI_Comm_rank(MPI_COMM_WORLD, &me);
  MPI_Comm_size(MPI_COMM_WORLD, &nprocs);
  const std::string file =
      ::testing::TempDir() + "polydem_mpi_" + std::to_string(nprocs) + "ranks.data";
  if (me == 0) {
    std::mt19937_64 rng(20261122);
    std::uniform_real_distribution<double> u(0.0, 1.0), g(-1.0, 1.0);
    std::ofstream o(file);
    o.precision(17);
    o << "POLYDEM 1 vs 2 ranks\n\n" << 2 * n << " atoms\n2 atom types\n"
      << "0 10 xlo xhi\n0 10 ylo yhi\n0 10 zlo zhi\n\nAtoms # polyhedron\n\n";
    for (int i = 1; i <= 2 * n; i++) {
      double q[4], qn = 0;
      for (double &c : q) c = g(rng), qn += c * c;
      const int type = i <= n ? 1 : 2;
      o << i << " " << type << " " << type << " " << (type == 1 ? 1.0 : 0.7) << " 1.5";
      for (int k = 0; k < 3; k++) o << " " << 10.0 * u(rng);
      for (double c : q) o << " " << c / std::sqrt(qn);
      o << "\n";
    }
    o << "\nVelocities\n\n";
    for (int i = 1; i <= 2 * n; i++) {
      o << i;
      for (int k = 0; k < 3; k++) o << " " << 3.0 * g(rng);
      for (int k = 0; k < 3; k++) o << " " << 0.5 * g(rng);
      o << "\n";
    }
  }
  MPI_Barrier(MPI_COMM_WORLD);
  return file;
}

std::vector<std::string> setup(const std::string &data)
{
  return {"units lj", "atom_style polyhedron", "atom_modify map array", "boundary p p p",
          "polyhedron_shape cube " + potentials() + "/cube.shape",
          "polyhedron_shape ico " + potentials() + "/icosahedron.shape",
          "read_data " + data, "neighbor 0.3 bin",
          "fix 1 all nve/polyhedron", "timestep 0.01", "thermo 100",
          "thermo_style custom step atoms"};
}

// gather (tag, x, quat, angmom) of all atoms to every rank, sorted by tag
std::vector<double> gather(Lmp &l, MPI_Comm comm)
{
  auto st = l.local_state();
  std::vector<double> mine;
  for (auto &kv : st) {
    mine.push_back((double) kv.first);
    for (int k = 0; k < 3; k++) mine.push_back(kv.second.x[k]);
    for (int k = 0; k < 4; k++) mine.push_back(kv.second.q[k]);
    for (int k = 0; k < 3; k++) mine.push_back(kv.second.L[k]);
  }
  return polydem_test::allgather_by_tag(mine, 11, comm);
}

}    // namespace

TEST(MpiRanks, OneVsTwoRanksIdentical)
{
  int me, nprocs;
  MPI_Comm_rank(MPI_COMM_WORLD, &me);
  MPI_Comm_size(MPI_COMM_WORLD, &nprocs);
  const int n = 60;
  const std::string data = write_data(n);
  std::vector<double> multi;
  double natoms_min = 1e30, natoms_max = -1;
  int nlocal_min = 1 << 30, nlocal_max = 0;
  {
    Lmp l({}, MPI_COMM_WORLD);
    l.cmds(setup(data));
    for (int r = 0; r < 10; r++) {
      l.cmd("run 100");
      nlocal_min = std::min(nlocal_min, l.lmp->atom->nlocal);
      nlocal_max = std::max(nlocal_max, l.lmp->atom->nlocal);
      const double na = l.thermo("atoms");
      natoms_min = std::fmin(natoms_min, na);
      natoms_max = std::fmax(natoms_max, na);
    }
    multi = gather(l, MPI_COMM_WORLD);
  }
  EXPECT_EQ(natoms_min, 2 * n);
  EXPECT_EQ(natoms_max, 2 * n);
  // atoms migrated between the ranks (exchange happened)
  if (nprocs > 1) EXPECT_LT(nlocal_min, nlocal_max);
  // the same on one rank
  MPI_Comm self;
  MPI_Comm_split(MPI_COMM_WORLD, me, 0, &self);
  if (me == 0) {
    Lmp l({}, self);
    l.cmds(setup(data));
    for (int r = 0; r < 10; r++) l.cmd("run 100");
    std::vector<double> single = gather(l, self);
    ASSERT_EQ(single.size(), multi.size());
    // speeds ~1.7 over 10 time units: particles cross the box and the
    // subdomain boundary several times
    double maxdiff = 0.0;
    for (size_t i = 0; i < single.size(); i++)
      maxdiff = std::fmax(maxdiff, std::fabs(single[i] - multi[i]));
    EXPECT_EQ(maxdiff, 0.0) << "on " << nprocs << " ranks";
  }
  MPI_Comm_free(&self);
  if (me == 0) std::remove(data.c_str());
}

// With contacts (pair_style polyhedron, damping and friction history): 1 and
// 2 ranks agree to 1e-10 over the first 100 steps (summation order differs,
// so not bit for bit), and no particle is lost (issue 4, item 5, short).
void contacts_one_vs_two(const std::vector<std::string> &extra)
{
  int me, nprocs;
  MPI_Comm_rank(MPI_COMM_WORLD, &me);
  MPI_Comm_size(MPI_COMM_WORLD, &nprocs);
  const int n = 60;
  const std::string data = write_data(n);
  auto cmds = setup(data);
  cmds.insert(cmds.end() - 4, {"comm_modify vel yes", "pair_style polyhedron",
                               "pair_coeff * * 1.0e4 0.3 0.8 0.5"});
  cmds.insert(cmds.end() - 4, extra.begin(), extra.end());
  cmds.push_back("timestep 0.001");
  std::vector<double> multi;
  double contacts = 0.0;
  {
    Lmp l({}, MPI_COMM_WORLD);
    l.cmds(cmds);
    l.cmd("run 100");
    EXPECT_EQ(l.thermo("atoms"), 2 * n);
    int dim;
    contacts = ((double *) l.lmp->force->pair->extract("counters", dim))[polydem::PP_CONTACTS];
    multi = gather(l, MPI_COMM_WORLD);
  }
  MPI_Comm self;
  MPI_Comm_split(MPI_COMM_WORLD, me, 0, &self);
  if (me == 0) {
    Lmp l({}, self);
    l.cmds(cmds);
    l.cmd("run 100");
    std::vector<double> single = gather(l, self);
    ASSERT_EQ(single.size(), multi.size());
    double maxrel = 0.0;
    for (size_t i = 0; i < single.size(); i++)
      maxrel = std::fmax(maxrel, std::fabs(single[i] - multi[i]) /
                                     std::fmax(1.0, std::fabs(single[i])));
    std::printf("%.0f contact evaluations in 100 steps; 1 vs %d ranks: max difference %.3g\n",
                contacts, nprocs, maxrel);
    EXPECT_GT(contacts, 100.0) << "the particles must touch";
    EXPECT_LE(maxrel, 1e-10);
  }
  MPI_Comm_free(&self);
  if (me == 0) std::remove(data.c_str());
}

TEST(MpiRanks, ContactsOneVsTwoRanksAgree)
{
  contacts_one_vs_two({});
}

// every second particle a sphere (issue 29): polyhedron-sphere and sphere
// pairs across the subdomain boundary
TEST(MpiRanks, SpheresOneVsTwoRanksAgree)
{
  contacts_one_vs_two({"polyhedron_shape ball ellipsoid 0.8 0.8 0.8", "variable odd atom id%2",
                       "group odd variable odd", "polyhedron_set group odd shape ball"});
}

// every third particle an ellipsoid of unequal semi-axes and every third a
// sphere (issue 29): the ellipsoid pairs' algebraic contacts cross the
// subdomain boundary with their friction histories
TEST(MpiRanks, EllipsoidsOneVsTwoRanksAgree)
{
  contacts_one_vs_two({"polyhedron_shape ball ellipsoid 0.8 0.8 0.8",
                       "polyhedron_shape egg ellipsoid 0.9 0.7 0.55", "variable m0 atom id%3==0",
                       "group m0 variable m0", "variable m1 atom id%3==1", "group m1 variable m1",
                       "polyhedron_set group m0 shape ball", "polyhedron_set group m1 shape egg",
                       "pair_coeff * * 1.0e4 0.3 0.8 0.5 ellipsoid 5000"});
}

// every third particle a composite (issue 29): two cubes and a sphere, whose
// part contacts cross the subdomain boundary with their keyed histories
TEST(MpiRanks, CompositesOneVsTwoRanksAgree)
{
  contacts_one_vs_two({"polyhedron_shape ball ellipsoid 0.5 0.5 0.5",
                       "polyhedron_shape dumb composite part cube -0.4 0 0 part cube 0.4 0 0 quat "
                       "0.92 0.38 0 0 part ball 0 1.3 0",
                       "variable third atom id%3==0", "group third variable third",
                       "polyhedron_set group third shape dumb scale 0.6"});
}


// all particles spheres joined by liquid bridges (pair_coeff ... bridge): the
// bridges' touch flags migrate with the atoms and cross the subdomain boundary
TEST(MpiRanks, LiquidBridgesOneVsTwoRanksAgree)
{
  contacts_one_vs_two({"polyhedron_shape ball ellipsoid 0.8 0.8 0.8",
                       "polyhedron_set group all shape ball",
                       "pair_coeff * * 1.0e4 0.3 0.8 0.5 bridge 0.008 20 10"});
}

// every third particle a dumbbell of two spheres (a composite), the others
// spheres, all under a liquid bridge law: the part pairs' bridges, kept in
// their keyed slots across the gap, agree on 1 and 2 ranks
TEST(MpiRanks, CompositeBridgesOneVsTwoRanksAgree)
{
  contacts_one_vs_two({"polyhedron_shape ball ellipsoid 0.8 0.8 0.8",
                       "polyhedron_shape dumb composite part ball -0.9 0 0 part ball 0.9 0 0",
                       "polyhedron_set group all shape ball", "variable third atom id%3==0",
                       "group third variable third",
                       "polyhedron_set group third shape dumb scale 0.6",
                       "pair_coeff * * 1.0e4 0.3 0.8 0.5 bridge 0.008 20 10"});
}

// every other particle a sphere among the cubes and icosahedra, all under a
// liquid bridge law with a viscous part: the sphere-polyhedron bridges
// (kept across their gaps by the touch flags) agree on 1 and 2 ranks
TEST(MpiRanks, SpherePolyhedronBridgesOneVsTwoRanksAgree)
{
  contacts_one_vs_two({"polyhedron_shape ball ellipsoid 0.8 0.8 0.8", "variable odd atom id%2",
                       "group odd variable odd", "polyhedron_set group odd shape ball",
                       "pair_coeff * * 1.0e4 0.3 0.8 0.5 bridge 0.008 20 10 viscous 0.05 0.01"});
}
