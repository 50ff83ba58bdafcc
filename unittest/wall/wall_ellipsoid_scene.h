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

inline std::string ellipsoid_scene_data(const std::string &file, unsigned seed)
{
  int me;
  MPI_Comm_rank(MPI_COMM_WORLD, &me);
  if (me == 0) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> g(-1.0, 1.0);
    std::ofstream o(file);
    o.precision(17);
    const int nx = 3, n = nx * nx * 2;
    o << "wall ellipsoid scene\n\n" << n << " atoms\n1 atom types\n0 " << EB << " xlo xhi\n0 "
      << EB << " ylo yhi\n0 " << EB << " zlo zhi\n\nAtoms # polyhedron\n\n";
    int id = 0;
    const double h = EB / nx;
    for (int k = 0; k < 2; k++)
      for (int j = 0; j < nx; j++)
        for (int i = 0; i < nx; i++) {
          double q[4], qn = 0;
          for (double &c : q) c = g(rng), qn += c * c;
          o << ++id << " 1 1 0.003 1500 " << (i + 0.5) * h << " " << (j + 0.5) * h << " "
            << 0.0032 + k * 0.007;
          for (double c : q) o << " " << c / std::sqrt(qn);
          o << "\n";
        }
    o << "\nVelocities\n\n";
    for (int i = 1; i <= n; i++)
      o << i << " " << 3.0 * g(rng) << " " << 1.5 * g(rng) << " " << -1.5 << " "
        << 1e-9 * g(rng) << " " << 1e-9 * g(rng) << " " << 1e-9 * g(rng)
        << "\n";    // angmom: ~10 rad/s
  }
  MPI_Barrier(MPI_COMM_WORLD);
  return file;
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
