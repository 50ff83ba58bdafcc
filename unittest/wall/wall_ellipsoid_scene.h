// A small ellipsoid scene for fix wall/mesh tests (issue 16): 18 ellipsoids
// (semi-axes 3, 1.8, 1.2 mm) thrown into a closed 3 cm box mesh under
// gravity, with friction between them (pair_style ellipsoid) and on the
// walls; written as a data file by rank 0 so that atom IDs do not depend on
// the rank count. t_c = pi sqrt(m / k_n) = 90 us, 45 steps; the bottom
// layer is thrown at the floor (1.5 m/s) and the side walls (up to 3 m/s).
#ifndef POLYDEM_TEST_WALL_ELLIPSOID_SCENE_H
#define POLYDEM_TEST_WALL_ELLIPSOID_SCENE_H

#include "wall_scene.h"

namespace wall_test {

constexpr double EB = 0.03;    // box edge [m]

// scale 3 mm, thrown down at 1.5 m/s, spinning at ~10 rad/s
inline std::string ellipsoid_scene_data(const std::string &file, unsigned seed)
{
  return layered_data(file, "wall ellipsoid scene", 3, EB, seed, 0.003, 0.0032, 0.007, -1.5, 1e-9);
}

// commands up to (not including) the wall fix and the run
inline std::vector<std::string> ellipsoid_scene_setup(const std::string &data)
{
  return {"units si", "atom_style polyhedron", "atom_modify map array", "boundary f f f",
          "comm_modify vel yes", "polyhedron_shape e ellipsoid 1.0 0.6 0.4",
          "read_data " + data, "pair_style ellipsoid", "pair_coeff * * 5e4 0.6 0.3",
          "neighbor 0.0006 bin", "neigh_modify every 1 delay 0 check yes",
          "fix nve all nve/polyhedron", "fix g all gravity 9.81 vector 0 0 -1",
          "timestep 2e-6"};
}

}    // namespace wall_test

#endif
