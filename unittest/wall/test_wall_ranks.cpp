// fix wall/mesh on 1 vs 2 MPI ranks (run under mpirun -np 2): dodecahedra
// thrown into a closed box mesh slide and bounce across the subdomain
// boundary; the per-atom wall history migrates with them. The particle count
// stays, no particle leaves the box, and trajectories agree with one rank.
#include "wall_scene.h"

#include "fix.h"
#include "modify.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using polydem_test::Lmp;
using namespace wall_test;

namespace {

constexpr double B = 0.06;

struct Result {
  std::vector<double> state;
  double fmesh[3];
  int nlocal_min, nlocal_max;
  double natoms;
  double contacts_max;    // most particle-wall contacts seen at once
};

Result run(MPI_Comm comm, const std::string &data, const std::string &stl, const std::string &args)
{
  Lmp l({}, comm);
  l.cmd("processors * 1 1");    // split along x, the direction the particles slide
  l.cmds(scene_setup(data));
  l.cmds({"fix w all wall/mesh " + stl + " friction 0.5" + args,
          "thermo_style custom step atoms f_w[3]", "thermo 100"});
  Result r;
  r.nlocal_min = 1 << 30;
  r.nlocal_max = 0;
  r.contacts_max = 0.0;
  auto *fix = l.lmp->modify->fix[l.lmp->modify->find_fix("w")];
  for (int k = 0; k < 12; k++) {
    l.cmd("run 100");
    r.contacts_max = std::fmax(r.contacts_max, fix->compute_vector(6));
    r.nlocal_min = std::min(r.nlocal_min, l.lmp->atom->nlocal);
    r.nlocal_max = std::max(r.nlocal_max, l.lmp->atom->nlocal);
  }
  r.natoms = l.thermo("atoms");
  for (int k = 0; k < 3; k++) r.fmesh[k] = fix->compute_vector(k);
  r.state = gathered_state(l, comm);
  return r;
}

}    // namespace

TEST(WallRanks, OneVsTwoRanks)
{
  int me, np;
  MPI_Comm_rank(MPI_COMM_WORLD, &me);
  MPI_Comm_size(MPI_COMM_WORLD, &np);
  const std::string data = scene_data(::testing::TempDir() + "wall_ranks.data", 3, B, 7);
  const std::string stl = ::testing::TempDir() + "wall_ranks_box.stl";
  if (me == 0) write_binary(stl, closed_box(B, 6));
  MPI_Barrier(MPI_COMM_WORLD);
  // the box as written (inward normals), and reversed: every contact met
  // from the back, its side kept in the history that migrates with atoms
  for (const std::string args : {"", " flip yes"}) {
    const Result multi = run(MPI_COMM_WORLD, data, stl, args);
    EXPECT_EQ(multi.natoms, 18);
    if (np > 1) EXPECT_LT(multi.nlocal_min, multi.nlocal_max);    // atoms migrated
    // every particle inside the box
    for (size_t i = 0; i < multi.state.size(); i += 7)
      for (int k = 0; k < 3; k++) {
        EXPECT_GT(multi.state[i + 1 + k], 0.0);
        EXPECT_LT(multi.state[i + 1 + k], B);
      }
    // the particles did hit the walls
    EXPECT_GE(multi.contacts_max, 3.0);
    MPI_Comm self;
    MPI_Comm_split(MPI_COMM_WORLD, me, 0, &self);
    if (me == 0) {
      const Result single = run(self, data, stl, args);
      ASSERT_EQ(single.state.size(), multi.state.size());
      const auto [dx, dv] = state_diff(single.state, multi.state);
      std::printf("[ wall     ] %d ranks vs 1%s: max |dx| = %.3g m, max |dv| = %.3g m/s, mesh "
                  "force z %.6g vs %.6g N\n",
                  np, args.c_str(), dx, dv, multi.fmesh[2], single.fmesh[2]);
      EXPECT_LT(dx, 1e-9);
      EXPECT_LT(dv, 1e-6);
      for (int k = 0; k < 3; k++)
        EXPECT_NEAR(multi.fmesh[k], single.fmesh[k], 1e-8 * (1.0 + std::fabs(single.fmesh[k])));
    }
    MPI_Comm_free(&self);
  }
}
