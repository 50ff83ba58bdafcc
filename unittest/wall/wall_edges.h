// The open and sharp mesh edges of issue 32 (a thin fin, a half-plate, a box's
// outer edge, a concave corner, a ridge of two 30 degree plates, a faceted
// rod) and the
// elastic impact run that measures the largest |E / E_0 - 1| of one particle
// on them (E = translation + rotation + the wall's elastic energy W(V), all
// global, so a run on several MPI ranks measures the same).
#ifndef POLYDEM_TEST_WALL_EDGES_H
#define POLYDEM_TEST_WALL_EDGES_H

#include "polydem_lmp.h"
#include "wall_meshes.h"

#include "fix.h"
#include "modify.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace wall_test {

using polydem_test::Lmp;
using polydem_test::num;

using P3 = std::array<double, 3>;

// one triangle, counter-clockwise seen from its front
inline void tri(Tris &t, const P3 &a, const P3 &b, const P3 &c)
{
  for (const P3 *p : {&a, &b, &c}) t.insert(t.end(), p->begin(), p->end());
}
// quad a b c d (counter-clockwise from the front) as two triangles
inline void quad(Tris &t, const P3 &a, const P3 &b, const P3 &c, const P3 &d)
{
  tri(t, a, b, c);
  tri(t, a, c, d);
}

const double W = 0.03;    // half-width of the plates [m]

// fin: the plane y = 0 for z <= 0, front +y (a two-sided plate)
inline Tris fin()
{
  Tris t;
  quad(t, {-W, 0, -W}, {-W, 0, 0}, {W, 0, 0}, {W, 0, -W});
  return t;
}
// half-plate: z = 0 for x <= 0, front +z
inline Tris half_plate()
{
  Tris t;
  quad(t, {-2 * W, -W, 0}, {0, -W, 0}, {0, W, 0}, {-2 * W, W, 0});
  return t;
}
// a box's outer edge along y: top z = 0 for x <= 0 (front +z), side x = 0
// for z <= 0 (front +x)
inline Tris box_edge()
{
  Tris t = half_plate();
  quad(t, {0, -W, 0}, {0, -W, -2 * W}, {0, W, -2 * W}, {0, W, 0});
  return t;
}
// concave corner: floor z = 0 for x >= 0 (front +z), wall x = 0 for z >= 0
// (front +x)
inline Tris corner()
{
  Tris t;
  quad(t, {0, -W, 0}, {2 * W, -W, 0}, {2 * W, W, 0}, {0, W, 0});
  quad(t, {0, -W, 0}, {0, W, 0}, {0, W, 2 * W}, {0, -W, 2 * W});
  return t;
}
// ridge along y: two plates falling away at 30 degrees from the line z = 0
inline Tris ridge()
{
  Tris t;
  const double c = std::cos(M_PI / 6) * 2 * W, s = std::sin(M_PI / 6) * 2 * W;
  quad(t, {0, -W, 0}, {0, W, 0}, {-c, W, -s}, {-c, -W, -s});
  quad(t, {0, -W, 0}, {c, -W, -s}, {c, W, -s}, {0, W, 0});
  return t;
}

// a faceted rod along y: radius R, nseg facets around, facing out (a convex
// curved mesh: no two facets coplanar), facet 0 starting at the top
inline Tris rod(double R, int nseg)
{
  Tris t;
  auto p = [&](int k, double y) -> P3 {
    const double a = 2 * M_PI * k / nseg;
    return {R * std::sin(a), y, R * std::cos(a)};
  };
  for (int k = 0; k < nseg; k++) quad(t, p(k, -W), p(k, W), p(k + 1, W), p(k + 1, -W));
  return t;
}

struct Case {
  std::string name, shape;
  Tris mesh;
  P3 x, v;            // start [m], velocity [m/s]
  std::string quat;   // polyhedron_set orientation
  double dt = 5e-8;   // [s]: Verlet's energy error is O(dt^2); a face landing flat on
                      // an edge line is the stiffest case (1e-6 needs 1e-8 there)
};

// Largest |E / E_0 - 1| over the run; touched: the particle-wall contacts
// summed over the run's steps (a grazing contact may last a few steps).
// extra: command-line words (e.g. /kk); comm: the ranks that run it; procs: a
// processors command (or empty); after each chunk, probe() sees the instance.
template <class Probe>
double energy_drift(const Case &c, const std::vector<std::string> &extra, double &touched,
                    MPI_Comm comm, const std::string &procs, Probe probe)
{
  // rank 0's scratch folder (each process has its own)
  int me;
  MPI_Comm_rank(comm, &me);
  char dir[4096] = {0};
  if (me == 0) std::snprintf(dir, sizeof(dir), "%s", tmpdir().c_str());
  MPI_Bcast(dir, sizeof(dir), MPI_CHAR, 0, comm);
  const std::string stl = std::string(dir) + "/edge_" + c.name + ".stl";
  const bool ell = c.shape.compare(0, 9, "ellipsoid") == 0;
  if (me == 0) write_ascii(stl, c.mesh);
  MPI_Barrier(comm);
  Lmp l(extra, comm);
  if (!procs.empty()) l.cmd(procs);
  l.cmds({"units si", "atom_style polyhedron", "atom_modify map array", "boundary f f f",
          "comm_modify vel yes", "newton off", "region box block -0.5 0.5 -0.5 0.5 -0.5 0.5",
          "create_box 1 box",
          // a composite's parts: a unit cube and a sphere of radius 1/2
          "polyhedron_shape cube " + polydem_test::potentials() + "/cube.shape",
          "polyhedron_shape ball ellipsoid 0.5 0.5 0.5",
          ell || c.shape.compare(0, 9, "composite") == 0
              ? "polyhedron_shape s " + c.shape
              : "polyhedron_shape s " +
                  (c.shape[0] == '/' ? c.shape : polydem_test::potentials() + "/" + c.shape + ".shape"),
          "create_atoms 1 single " + num(c.x[0]) + " " + num(c.x[1]) + " " + num(c.x[2]),
          "polyhedron_set atom 1 shape s " + std::string(ell ? "" : "scale 0.006 ") +
              "density 2500 " + c.quat,
          "velocity all set " + num(c.v[0]) + " " + num(c.v[1]) + " " + num(c.v[2]),
          ell ? "pair_style ellipsoid" : "pair_style polyhedron",
          ell ? "pair_coeff * * 1.0e4 1.0" : "pair_coeff * * 1.0e7 0.3 1.0 0.0",
          "neighbor 0.002 bin",
          "fix nve all nve/polyhedron", "fix w all wall/mesh " + stl,
          "compute ke all ke", "compute er all erotate/polyhedron", "thermo_style custom step c_er",
          "timestep " + num(c.dt), "fix tch all ave/time 1 1 1 f_w[7] ave running",
          "run 0 post no"});
  // every term a global sum: all ranks call it
  auto energy = [&]() {
    return l.thermo("c_ke") + l.thermo("c_er") +
        l.lmp->modify->fix[l.lmp->modify->find_fix("w")]->compute_scalar();
  };
  const double e0 = energy();
  double dev = 0.0;
  touched = 0.0;
  // 0.008 s: the approach (at most 1 mm at 1 m/s), the impacts and the way out
  const int chunk = (int) std::lround(1e-4 / c.dt);
  for (int k = 0; k < 80; k++) {
    l.cmd("run " + std::to_string(chunk) + " post no");
    dev = std::fmax(dev, std::fabs(energy() / e0 - 1.0));
    probe(l);
  }
  // the running mean of the contact count over the 80 chunk + 1 samples
  touched = std::round(l.lmp->modify->fix[l.lmp->modify->find_fix("tch")]->compute_scalar() *
                       (80.0 * chunk + 1.0));
  return dev;
}

inline double energy_drift(const Case &c, const std::vector<std::string> &extra, double &touched)
{
  return energy_drift(c, extra, touched, MPI_COMM_WORLD, "", [](Lmp &) {});
}

}    // namespace wall_test

#endif
