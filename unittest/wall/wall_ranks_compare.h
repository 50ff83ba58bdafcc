// fix wall/mesh on 1 vs N MPI ranks (run under mpirun -np 2) in a scene of
// wall_scene.h (dodecahedra) or wall_ellipsoid_scene.h (ellipsoids): the
// particles cross the subdomain boundary (split along x), their per-atom wall
// history migrating with them. The particle count stays, atoms migrate, no
// particle leaves the box, the walls are touched, and trajectories agree
// with one rank (positions to 1e-9 m, velocities to 1e-6 m/s, the mesh force
// to 1e-8 relative).
#ifndef POLYDEM_TEST_WALL_RANKS_COMPARE_H
#define POLYDEM_TEST_WALL_RANKS_COMPARE_H

#include "wall_scene.h"

#include "fix.h"
#include "modify.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace wall_test {

struct RanksCase {
  std::vector<std::string> setup;    // the scene's commands (read_data of its file)
  std::vector<std::string> after;    // commands after the fix (fix ID w)
  int samples, steps;                // samples of `run steps`
  double box, slack;                 // every particle within [-slack, box + slack]^3
  double min_contacts_sum;           // wall contacts summed over samples at least
  double min_contacts_max;           // most contacts in one sample at least
  const char *tag;
};

struct RanksResult {
  std::vector<double> state;
  double fmesh[3];
  int nlocal_min = 1 << 30, nlocal_max = 0;
  double natoms = 0.0, contacts = 0.0, contacts_max = 0.0;
};

inline RanksResult ranks_run(const RanksCase &c, MPI_Comm comm, const std::string &fixargs)
{
  polydem_test::Lmp l({}, comm);
  l.cmd("processors * 1 1");    // split along x, the direction the particles slide
  l.cmds(c.setup);
  l.cmd("fix w all wall/mesh " + fixargs);
  l.cmds(c.after);
  RanksResult r;
  auto *fix = l.lmp->modify->fix[l.lmp->modify->find_fix("w")];
  for (int k = 0; k < c.samples; k++) {
    l.cmd("run " + std::to_string(c.steps));
    const double n = fix->compute_vector(6);
    r.contacts += n;
    r.contacts_max = std::fmax(r.contacts_max, n);
    r.nlocal_min = std::min(r.nlocal_min, l.lmp->atom->nlocal);
    r.nlocal_max = std::max(r.nlocal_max, l.lmp->atom->nlocal);
  }
  r.natoms = (double) l.lmp->atom->natoms;
  for (int k = 0; k < 3; k++) r.fmesh[k] = fix->compute_vector(k);
  r.state = gathered_state(l, comm);
  return r;
}

// the run on all ranks of MPI_COMM_WORLD against rank 0 alone
inline void ranks_one_vs_n(const RanksCase &c, double natoms, const std::string &fixargs)
{
  int me, np;
  MPI_Comm_rank(MPI_COMM_WORLD, &me);
  MPI_Comm_size(MPI_COMM_WORLD, &np);
  const RanksResult multi = ranks_run(c, MPI_COMM_WORLD, fixargs);
  EXPECT_EQ(multi.natoms, natoms);
  if (np > 1) EXPECT_LT(multi.nlocal_min, multi.nlocal_max);    // atoms migrated
  for (size_t i = 0; i < multi.state.size(); i += 7)
    for (int k = 0; k < 3; k++) {
      EXPECT_GT(multi.state[i + 1 + k], -c.slack);
      EXPECT_LT(multi.state[i + 1 + k], c.box + c.slack);
    }
  EXPECT_GE(multi.contacts, c.min_contacts_sum);    // the walls were touched
  EXPECT_GE(multi.contacts_max, c.min_contacts_max);
  MPI_Comm self;
  MPI_Comm_split(MPI_COMM_WORLD, me, 0, &self);
  if (me == 0) {
    const RanksResult single = ranks_run(c, self, fixargs);
    ASSERT_EQ(single.state.size(), multi.state.size());
    const auto [dx, dv] = state_diff(single.state, multi.state);
    std::printf("[ %s ] %d ranks vs 1 (%s): max |dx| = %.3g m, max |dv| = %.3g m/s, mesh force "
                "z %.6g vs %.6g N, %g contacts seen (most %g)\n",
                c.tag, np, fixargs.c_str(), dx, dv, multi.fmesh[2], single.fmesh[2],
                multi.contacts, multi.contacts_max);
    EXPECT_LT(dx, 1e-9);
    EXPECT_LT(dv, 1e-6);
    for (int k = 0; k < 3; k++)
      EXPECT_NEAR(multi.fmesh[k], single.fmesh[k], 1e-8 * (1.0 + std::fabs(single.fmesh[k])));
  }
  MPI_Comm_free(&self);
}

}    // namespace wall_test

#endif
