// fix wall/mesh with ellipsoids on 1 vs 2 MPI ranks (issue 16; run under
// mpirun -np 2): 18 ellipsoids thrown into a closed box mesh cross the
// subdomain boundary, their wall history migrating with them; the box as
// written and reversed (every contact met from its back). The particle
// count stays, no particle leaves the box, trajectories agree with one rank
// (positions to 1e-9 m, velocities to 1e-6 m/s, the mesh force to 1e-8).
#include "wall_ellipsoid_scene.h"

#include "fix.h"
#include "modify.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using polydem_test::Lmp;
using namespace wall_test;

namespace {

struct Result {
  std::vector<double> state;
  double fmesh[3];
  int nlocal_min, nlocal_max;
  double natoms, contacts;
};

Result run(MPI_Comm comm, const std::string &data, const std::string &stl, const std::string &args)
{
  Lmp l({}, comm);
  l.cmd("processors * 1 1");    // split along x
  l.cmds(ellipsoid_scene_setup(data));
  l.cmd("fix w all wall/mesh " + stl + " friction 0.5" + args);
  Result r;
  r.nlocal_min = 1 << 30;
  r.nlocal_max = 0;
  r.contacts = 0.0;
  auto *fix = l.lmp->modify->fix[l.lmp->modify->find_fix("w")];
  for (int k = 0; k < 150; k++) {
    l.cmd("run 10");
    r.contacts += fix->compute_vector(6);
    r.nlocal_min = std::min(r.nlocal_min, l.lmp->atom->nlocal);
    r.nlocal_max = std::max(r.nlocal_max, l.lmp->atom->nlocal);
  }
  r.natoms = (double) l.lmp->atom->natoms;
  for (int k = 0; k < 3; k++) r.fmesh[k] = fix->compute_vector(k);
  r.state = gathered_state(l, comm);
  return r;
}

}    // namespace

TEST(WallEllipsoidRanks, OneVsTwoRanks)
{
  int me, np;
  MPI_Comm_rank(MPI_COMM_WORLD, &me);
  MPI_Comm_size(MPI_COMM_WORLD, &np);
  const std::string data = ellipsoid_scene_data(::testing::TempDir() + "wall_ell_ranks.data", 7);
  const std::string stl = ::testing::TempDir() + "wall_ell_ranks_box.stl";
  if (me == 0) write_binary(stl, closed_box(EB, 5));
  MPI_Barrier(MPI_COMM_WORLD);
  for (const std::string args : {"", " flip yes move translate 0.03 0 0"}) {
    const Result multi = run(MPI_COMM_WORLD, data, stl, args);
    EXPECT_EQ(multi.natoms, 18);
    if (np > 1) EXPECT_LT(multi.nlocal_min, multi.nlocal_max);    // atoms migrated
    for (size_t i = 0; i < multi.state.size(); i += 7)
      for (int k = 0; k < 3; k++) {
        EXPECT_GT(multi.state[i + 1 + k], -0.001);
        EXPECT_LT(multi.state[i + 1 + k], EB + 0.001);
      }
    EXPECT_GE(multi.contacts, 30.0);    // the walls were touched
    MPI_Comm self;
    MPI_Comm_split(MPI_COMM_WORLD, me, 0, &self);
    if (me == 0) {
      const Result single = run(self, data, stl, args);
      ASSERT_EQ(single.state.size(), multi.state.size());
      const auto [dx, dv] = state_diff(single.state, multi.state);
      std::printf("[ ell wall ] %d ranks vs 1%s: max |dx| = %.3g m, max |dv| = %.3g m/s, mesh "
                  "force z %.6g vs %.6g N, %g contacts seen\n",
                  np, args.c_str(), dx, dv, multi.fmesh[2], single.fmesh[2], multi.contacts);
      EXPECT_LT(dx, 1e-9);
      EXPECT_LT(dv, 1e-6);
      for (int k = 0; k < 3; k++)
        EXPECT_NEAR(multi.fmesh[k], single.fmesh[k], 1e-8 * (1.0 + std::fabs(single.fmesh[k])));
    }
    MPI_Comm_free(&self);
  }
}
