// fix wall/mesh on 1 vs 2 MPI ranks (run under mpirun -np 2): 18
// dodecahedra thrown into a closed 6 cm box mesh slide and bounce across the
// subdomain boundary for 1,200 steps; the box as written (inward normals) and
// reversed (every contact met from the back, its side kept in the history
// that migrates with the atoms); and with rolling resistance and cohesion
// between the particles and on the box. Checks: wall_ranks_compare.h.
#include "wall_ranks_compare.h"

using namespace wall_test;

TEST(WallRanks, OneVsTwoRanks)
{
  int me;
  MPI_Comm_rank(MPI_COMM_WORLD, &me);
  const double B = 0.06;
  const std::string data = scene_data(::testing::TempDir() + "wall_ranks.data", 3, B, 7);
  const std::string stl = ::testing::TempDir() + "wall_ranks_box.stl";
  if (me == 0) write_binary(stl, closed_box(B, 6));
  MPI_Barrier(MPI_COMM_WORLD);
  const RanksCase c = {scene_setup(data), {"thermo_style custom step atoms f_w[3]", "thermo 100"},
                       12, 100, B, 0.0, 0.0, 3.0, "wall    "};
  for (const std::string args : {"", " flip yes"})
    ranks_one_vs_n(c, 18, stl + " friction 0.5" + args);
  // rolling resistance and cohesion (issue 30) between the dodecahedra
  // (their rolling torques in the pair history that migrates) and on the box
  RanksCase rc = c;
  rc.setup.push_back("pair_coeff * * 1.0e7 0.3 0.5 0.5 rolling 0.1 cohesion 1e3");
  ranks_one_vs_n(rc, 18, stl + " friction 0.5 rolling 0.1 cohesion 1e3");
}
