// A gas of identical prolate ellipsoids (semi-axes xi*b, b, b) on a simple
// cubic lattice in a periodic cube, random orientations, Gaussian velocities
// with zero total momentum, no spin: the homogeneous cooling set-up of the ellipsoid
// seed §4. Written by rank 0 as a LAMMPS data file so that atom IDs and
// initial state do not depend on the number of ranks.
#ifndef POLYDEM_TEST_ELLIPSOID_GAS_H
#define POLYDEM_TEST_ELLIPSOID_GAS_H

#include "polydem_lmp.h"    // num()

#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <string>
#include <vector>

namespace polydem_test {

// the mass of an ellipsoid of semi-axes a, b, c at density rho
inline double ellipsoid_mass(double rho, double a, double b, double c)
{
  return rho * 4.0 / 3.0 * M_PI * a * b * c;
}

// the duration of a binary collision of two grains of mass m on the linear
// spring k_n (no damping): pi sqrt(m12 / k_n), m12 = m / 2
inline double pair_contact_time(double m, double kn)
{
  return M_PI * std::sqrt(0.5 * m / kn);
}

struct GasSpec {
  int n_side = 8;          // N = n_side^3
  double xi = 2.0;         // elongation a/b
  double phi = 0.058;      // solid fraction
  double box = 1.0;        // cube edge (m)
  double vrms = 1.0;       // per-component translational velocity spread (m/s)
  unsigned seed = 1;
  // semi-axis b from phi: N 4/3 pi xi b^3 = phi box^3
  double b() const
  {
    const double n = (double) n_side * n_side * n_side;
    return std::cbrt(phi * box * box * box / (n * 4.0 / 3.0 * M_PI * xi));
  }
  // a grain's mass at density rho
  double mass(double rho = 2000.0) const
  {
    const double bb = b();
    return rho * 4.0 / 3.0 * M_PI * xi * bb * bb * bb;
  }
  // the first commands of a scene of this gas read from `data` (write_gas)
  std::vector<std::string> scene(const std::string &data) const
  {
    const double bb = b();
    return {"units si", "atom_style polyhedron", "atom_modify map array", "boundary p p p",
            "comm_modify vel yes",
            "polyhedron_shape e ellipsoid " + num(xi * bb) + " " + num(bb) + " " + num(bb),
            "read_data " + data};
  }
};

// a gas of n_side^3 grains at solid fraction phi in a cube of edge box,
// velocity spread vrms, velocities from seed
inline GasSpec gas(int n_side, double phi, double box, double vrms, unsigned seed = 1)
{
  GasSpec g;
  g.n_side = n_side;
  g.phi = phi;
  g.box = box;
  g.vrms = vrms;
  g.seed = seed;
  return g;
}

inline std::string write_gas(const std::string &file, const GasSpec &g)
{
  int me = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &me);
  if (me == 0) {
    std::mt19937_64 rng(g.seed);
    std::normal_distribution<double> nd(0.0, 1.0);
    const int n = g.n_side * g.n_side * g.n_side;
    std::vector<double> v(3 * n);
    double vm[3] = {0, 0, 0};
    for (int i = 0; i < n; i++)
      for (int k = 0; k < 3; k++) {
        v[3 * i + k] = g.vrms * nd(rng);
        vm[k] += v[3 * i + k] / n;
      }
    std::ofstream o(file);
    o.precision(17);
    o << "POLYDEM ellipsoid gas\n\n"
      << n << " atoms\n1 atom types\n0 " << g.box << " xlo xhi\n0 " << g.box << " ylo yhi\n0 "
      << g.box << " zlo zhi\n\nAtoms # polyhedron\n\n";
    const double h = g.box / g.n_side;
    int id = 0;
    for (int ix = 0; ix < g.n_side; ix++)
      for (int iy = 0; iy < g.n_side; iy++)
        for (int iz = 0; iz < g.n_side; iz++) {
          double q[4], qn = 0;
          for (double &c : q) c = nd(rng), qn += c * c;
          id++;
          // shape 1, scale 1, density 2000 kg/m^3
          o << id << " 1 1 1 2000 " << (ix + 0.5) * h << " " << (iy + 0.5) * h << " "
            << (iz + 0.5) * h;
          for (double c : q) o << " " << c / std::sqrt(qn);
          o << "\n";
        }
    o << "\nVelocities\n\n";
    for (int i = 0; i < n; i++) o << i + 1 << " " << v[3 * i] - vm[0] << " "
                                  << v[3 * i + 1] - vm[1] << " " << v[3 * i + 2] - vm[2]
                                  << " 0 0 0\n";
  }
  MPI_Barrier(MPI_COMM_WORLD);
  return file;
}

}    // namespace polydem_test

#endif
