// 1 vs 2 MPI ranks (run under mpirun -np 2): non-interacting polyhedra that
// cross subdomain and periodic boundaries follow identical trajectories on
// 1 and on 2 ranks, and the particle count never changes (issue 2, item 3).

#include "polydem_lmp.h"

#include <gtest/gtest.h>

#include <cmath>

using polydem_test::Lmp;
using polydem_test::potentials;

namespace {

std::vector<std::string> setup(int n)
{
  return {"units lj", "atom_style polyhedron", "atom_modify map array", "boundary p p p",
          "region box block 0 10 0 10 0 10", "create_box 2 box",
          "polyhedron_shape cube " + potentials() + "/cube.shape",
          "polyhedron_shape ico " + potentials() + "/icosahedron.shape",
          "create_atoms 1 random " + std::to_string(n) + " 4711 NULL",
          "create_atoms 2 random " + std::to_string(n) + " 4712 NULL",
          "polyhedron_set type 2 shape ico scale 0.7 quat/random 5",
          "polyhedron_set type 1 quat/random 6 omega 1.0 2.0 -0.5",
          "velocity all create 5.0 999 loop geom", "neighbor 0.3 bin",
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
  int nprocs;
  MPI_Comm_size(comm, &nprocs);
  int n = (int) mine.size();
  std::vector<int> counts(nprocs), displs(nprocs);
  MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
  int total = 0;
  for (int p = 0; p < nprocs; p++) displs[p] = total, total += counts[p];
  std::vector<double> all(total);
  MPI_Allgatherv(mine.data(), n, MPI_DOUBLE, all.data(), counts.data(), displs.data(),
                 MPI_DOUBLE, comm);
  // sort records by tag
  const int rec = 11;
  std::vector<std::vector<double>> recs;
  for (int i = 0; i < total; i += rec) recs.emplace_back(all.begin() + i, all.begin() + i + rec);
  std::sort(recs.begin(), recs.end());
  std::vector<double> out;
  for (auto &r : recs) out.insert(out.end(), r.begin(), r.end());
  return out;
}

}    // namespace

TEST(MpiRanks, OneVsTwoRanksIdentical)
{
  int me, nprocs;
  MPI_Comm_rank(MPI_COMM_WORLD, &me);
  MPI_Comm_size(MPI_COMM_WORLD, &nprocs);
  const int n = 60;
  std::vector<double> multi;
  double natoms_min = 1e30, natoms_max = -1;
  {
    Lmp l({}, MPI_COMM_WORLD);
    l.cmds(setup(n));
    for (int r = 0; r < 10; r++) {
      l.cmd("run 100");
      const double na = l.thermo("atoms");
      natoms_min = std::fmin(natoms_min, na);
      natoms_max = std::fmax(natoms_max, na);
    }
    multi = gather(l, MPI_COMM_WORLD);
  }
  EXPECT_EQ(natoms_min, 2 * n);
  EXPECT_EQ(natoms_max, 2 * n);
  // the same on one rank
  MPI_Comm self;
  MPI_Comm_split(MPI_COMM_WORLD, me, 0, &self);
  if (me == 0) {
    Lmp l({}, self);
    l.cmds(setup(n));
    for (int r = 0; r < 10; r++) l.cmd("run 100");
    std::vector<double> single = gather(l, self);
    ASSERT_EQ(single.size(), multi.size());
    // particles travel ~ several box lengths: every one crosses boundaries
    double maxdiff = 0.0;
    for (size_t i = 0; i < single.size(); i++)
      maxdiff = std::fmax(maxdiff, std::fabs(single[i] - multi[i]));
    EXPECT_EQ(maxdiff, 0.0) << "on " << nprocs << " ranks";
  }
  MPI_Comm_free(&self);
}
