// fix wall/mesh with ellipsoids on 1 vs 2 MPI ranks (issue 16; run under
// mpirun -np 2): 18 ellipsoids thrown into a closed 3 cm box mesh cross the
// subdomain boundary for 1,500 steps, their wall history migrating with
// them; the box as written and reversed and moving (every contact met from
// its back); with rolling resistance and cohesion on the walls, and the box
// servo-controlled (issue 30: the servo's force is summed over ranks);
// spheres with liquid bridges on the walls. Checks: wall_ranks_compare.h (30 or more wall contacts summed
// over the 150 samples).
#include "wall_ellipsoid_scene.h"
#include "wall_ranks_compare.h"

using namespace wall_test;

TEST(WallEllipsoidRanks, OneVsTwoRanks)
{
  int me;
  MPI_Comm_rank(MPI_COMM_WORLD, &me);
  const std::string data = ellipsoid_scene_data(::testing::TempDir() + "wall_ell_ranks.data", 7);
  const std::string stl = ::testing::TempDir() + "wall_ell_ranks_box.stl";
  if (me == 0) write_binary(stl, closed_box(EB, 5));
  MPI_Barrier(MPI_COMM_WORLD);
  const RanksCase c = {ellipsoid_scene_setup(data), {}, 150, 10, EB, 0.001, 30.0, 0.0,
                       "ell wall"};
  for (const std::string args : {"", " flip yes move translate 0.03 0 0", " rolling 0.2 cohesion 0.05",
                                 " move servo 0 0 -1 0.02 0.05 0.01"})
    ranks_one_vs_n(c, 18, stl + " friction 0.5" + args);
  // spheres with liquid bridges (and their viscous part) on the walls (their bridges
  // migrate in the wall history)
  RanksCase s = c;
  for (auto &cmd : s.setup)
    if (cmd.rfind("polyhedron_shape e", 0) == 0) cmd = "polyhedron_shape e ellipsoid 0.7 0.7 0.7";
  ranks_one_vs_n(s, 18, stl + " friction 0.5 bridge 5e-12 0.072 10 viscous 1e-3 1e-6");
}
