// Elastic impacts on open and sharp mesh edges on 1 vs 2 MPI ranks (run under
// mpirun -np 2): the subdomain boundary x = 0 lies on the half-plate's open
// border and across the fin's edge, and the particle moves across it during
// the impact, so it changes owner (with its wall history) while touching the
// edge. The energy (global sums) is conserved to 1e-6 on two ranks as on one
// (dt 2e-7 s: Verlet's error up to 7e-7 here), and the two runs agree.
#include "wall_edges.h"

#include "atom.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace wall_test;

TEST(WallEdgesRanks, OneVsTwoRanks)
{
  int me, np;
  MPI_Comm_rank(MPI_COMM_WORLD, &me);
  MPI_Comm_size(MPI_COMM_WORLD, &np);
  const std::string tilt = "quat 1 2 0.5 23", tilt2 = "quat -0.3 1 0.7 41";
  const std::string ell = "ellipsoid 0.004 0.0025 0.0015";
  // x starts below 0 and the velocity carries the particle 4 mm across x = 0
  const std::vector<Case> cases = {
      {"fin", "cube", fin(), {-0.002, 0.0005, 0.0056}, {0.5, 0, -1}, tilt, 2e-7},
      {"half", "cube", half_plate(), {-0.002, 0.0, 0.0056}, {0.5, 0, -1}, tilt2, 2e-7},
      {"ridge", "dodecahedron", ridge(), {-0.002, 0.0, 0.008}, {0.5, 0, -1}, tilt, 2e-7},
      {"fin", ell, fin(), {-0.002, 0.0005, 0.0056}, {0.5, 0, -1}, tilt2, 2e-7},
  };
  for (const Case &c : cases) {
    int owners = 0;    // on how many ranks the particle was owned (at a chunk's end)
    int was_here = 0;
    double touched;
    const double dev = energy_drift(c, {}, touched, MPI_COMM_WORLD, "processors * 1 1",
                                    [&](Lmp &l) { was_here |= l.lmp->atom->nlocal > 0; });
    MPI_Allreduce(&was_here, &owners, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
    EXPECT_EQ(owners, np) << c.name << " " << c.shape << ": the particle did not change ranks";
    EXPECT_GT(touched, 0.0) << c.name;
    EXPECT_LT(dev, 1e-6) << c.name;
    MPI_Comm self;
    MPI_Comm_split(MPI_COMM_WORLD, me, 0, &self);
    if (me == 0) {
      double touched1;
      const double dev1 = energy_drift(c, {}, touched1, self, "", [](Lmp &) {});
      std::printf("[ edges ] %-5s %-29s: %d ranks max |E/E0 - 1| %.3g, 1 rank %.3g\n",
                  c.name.c_str(), c.shape.c_str(), np, dev, dev1);
      std::fflush(stdout);
      EXPECT_EQ(touched1, touched) << c.name;
      EXPECT_NEAR(dev, dev1, 1e-9) << c.name;
    }
    MPI_Comm_free(&self);
  }
}
