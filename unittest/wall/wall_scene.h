// A small granular scene for fix wall/mesh tests: dodecahedra thrown into a
// closed box mesh (inward normals) under gravity, with friction, written as
// a data file by rank 0 so that atom IDs do not depend on the rank count.
#ifndef POLYDEM_TEST_WALL_SCENE_H
#define POLYDEM_TEST_WALL_SCENE_H

#include "polydem_allgather.h"
#include "polydem_lmp.h"
#include "wall_meshes.h"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <random>
#include <string>
#include <vector>

namespace wall_test {

// box [0, B]^3, each face n x n cells, normals pointing inside
inline Tris closed_box(double B, int n)
{
  Tris out;
  const Tris f = flat(0, B, 0, B, 0, n, n, true, 0.2, 3);    // z = 0, facing +z
  for (int face = 0; face < 6; face++)
    for (size_t k = 0; k < f.size(); k += 9) {
      double v[3][3];
      for (int i = 0; i < 3; i++) {
        const double x = f[k + 3 * i], y = f[k + 3 * i + 1];
        double p[3];
        switch (face) {
          case 0: p[0] = x, p[1] = y, p[2] = 0; break;         // floor, +z
          case 1: p[0] = y, p[1] = x, p[2] = B; break;         // ceiling, -z
          case 2: p[0] = 0, p[1] = x, p[2] = y; break;         // x = 0, +x
          case 3: p[0] = B, p[1] = y, p[2] = x; break;         // x = B, -x
          case 4: p[0] = y, p[1] = 0, p[2] = x; break;         // y = 0, +y
          default: p[0] = x, p[1] = B, p[2] = y; break;        // y = B, -y
        }
        for (int d = 0; d < 3; d++) v[i][d] = p[d];
      }
      for (auto &vv : v)
        for (double c : vv) out.push_back(c);
    }
  return out;
}

// Rank 0 writes a data file: two layers (heights z0, z0 + dz) of nx x nx
// particles of scale s and density 1500 in a box of edge B, randomly
// oriented, thrown with velocity (3 g, 1.5 g, vz) and angular momentum L g
// (g uniform in [-1, 1], from seed), so that atom IDs do not depend on the
// rank count.
inline std::string layered_data(const std::string &file, const char *title, int nx, double B,
                                unsigned seed, double s, double z0, double dz, double vz, double L)
{
  int me;
  MPI_Comm_rank(MPI_COMM_WORLD, &me);
  if (me == 0) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> g(-1.0, 1.0);
    std::ofstream o(file);
    o.precision(17);
    const int n = nx * nx * 2;
    o << title << "\n\n" << n << " atoms\n1 atom types\n0 " << B << " xlo xhi\n0 " << B
      << " ylo yhi\n0 " << B << " zlo zhi\n\nAtoms # polyhedron\n\n";
    int id = 0;
    const double h = B / nx;
    for (int k = 0; k < 2; k++)
      for (int j = 0; j < nx; j++)
        for (int i = 0; i < nx; i++) {
          double q[4], qn = 0;
          for (double &c : q) c = g(rng), qn += c * c;
          o << ++id << " 1 1 " << s << " 1500 " << (i + 0.5) * h << " " << (j + 0.5) * h << " "
            << z0 + k * dz;
          for (double c : q) o << " " << c / std::sqrt(qn);
          o << "\n";
        }
    o << "\nVelocities\n\n";
    for (int i = 1; i <= n; i++)
      o << i << " " << 3.0 * g(rng) << " " << 1.5 * g(rng) << " " << vz << " " << L * g(rng)
        << " " << L * g(rng) << " " << L * g(rng) << "\n";
  }
  MPI_Barrier(MPI_COMM_WORLD);
  return file;
}

// dodecahedra of scale 4 mm, thrown down at 0.5 m/s, spinning at ~40 rad/s
inline std::string scene_data(const std::string &file, int nx, double B, unsigned seed)
{
  return layered_data(file, "wall scene", nx, B, seed, 0.004, 0.008, 0.014, -0.5, 3e-7);
}

// commands up to (not including) the wall fix and the run
inline std::vector<std::string> scene_setup(const std::string &data)
{
  return {"units si", "atom_style polyhedron", "atom_modify map array", "boundary f f f",
          "comm_modify vel yes",
          "polyhedron_shape d " + polydem_test::potentials() + "/dodecahedron.shape",
          "read_data " + data, "pair_style polyhedron",
          "pair_coeff * * 1.0e7 0.3 0.5 0.5", "neighbor 0.002 bin",
          "neigh_modify every 1 delay 0 check yes", "fix nve all nve/polyhedron",
          "fix g all gravity 9.81 vector 0 0 -1", "timestep 2e-5"};
}

// every rank's atoms as (ID, x, v) records sorted by ID, on every rank (the
// 1 vs N ranks comparisons)
inline std::vector<double> gathered_state(polydem_test::Lmp &l, MPI_Comm comm)
{
  std::vector<double> mine;
  for (auto &kv : l.local_state()) {
    mine.push_back((double) kv.first);
    for (int k = 0; k < 3; k++) mine.push_back(kv.second.x[k]);
    for (int k = 0; k < 3; k++) mine.push_back(kv.second.v[k]);
  }
  return polydem_test::allgather_by_tag(mine, 7, comm);
}

// 1 vs N ranks: the largest |dx| and |dv| between two gathered_state()s
struct StateDiff {
  double dx = 0.0, dv = 0.0;
};
inline StateDiff state_diff(const std::vector<double> &a, const std::vector<double> &b)
{
  StateDiff d;
  for (size_t i = 0; i + 7 <= a.size() && i + 7 <= b.size(); i += 7) {
    for (int k = 1; k <= 3; k++) d.dx = std::max(d.dx, std::abs(a[i + k] - b[i + k]));
    for (int k = 4; k <= 6; k++) d.dv = std::max(d.dv, std::abs(a[i + k] - b[i + k]));
  }
  return d;
}

// two runs' per-atom records by atom ID (f, torque, x, v: 12 values each):
// the largest |f, torque|, the largest |d f, torque| and |d x, v|
struct RecordDiff {
  double fmax = 0.0, df = 0.0, dx = 0.0;
};
inline RecordDiff record_diff(const std::map<long, std::vector<double>> &a,
                              const std::map<long, std::vector<double>> &b)
{
  RecordDiff d;
  for (auto &kv : a) {
    const auto &q = b.at(kv.first);
    for (int m = 0; m < 6; m++) {
      d.fmax = std::fmax(d.fmax, std::fabs(kv.second[m]));
      d.df = std::fmax(d.df, std::fabs(kv.second[m] - q[m]));
    }
    for (int m = 6; m < 12; m++) d.dx = std::fmax(d.dx, std::fabs(kv.second[m] - q[m]));
  }
  return d;
}

}    // namespace wall_test

#endif
