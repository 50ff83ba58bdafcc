// Elastic impacts (e = 1, mu = 0, no gravity) of polyhedra and ellipsoids on
// the open and sharp edges of meshes, through LAMMPS: the total energy (translation +
// rotation + the wall's elastic energy W(V)) is conserved to 1e-6 of the
// impact's energy over the whole impact. The cases (issue 32, item 1): the
// top edge of a thin vertical fin, the open border of a half-plate, a box's
// outer (convex) edge, a concave corner, a ridge of two 30 degree plates, and
// a grazing slide along an open border; several offsets and orientations;
// fix wall/mesh/kk the same (fin, box edge and ridge at dt 5e-8).
// Before the prisms' side sections were part of dV/dx (polydem_clip.h) a
// cube falling onto the fin's edge left it with many times its energy.
#include "polydem_lmp.h"
#include "wall_meshes.h"

#include "atom.h"
#include "fix.h"
#include "modify.h"

#include <gtest/gtest.h>

#include <cmath>

using polydem_test::Lmp;
using polydem_test::num;
using namespace wall_test;

namespace {

using P3 = std::array<double, 3>;

// one triangle, counter-clockwise seen from its front
void tri(Tris &t, const P3 &a, const P3 &b, const P3 &c)
{
  for (const P3 *p : {&a, &b, &c}) t.insert(t.end(), p->begin(), p->end());
}
// quad a b c d (counter-clockwise from the front) as two triangles
void quad(Tris &t, const P3 &a, const P3 &b, const P3 &c, const P3 &d)
{
  tri(t, a, b, c);
  tri(t, a, c, d);
}

const double W = 0.03;    // half-width of the plates [m]

// fin: the plane y = 0 for z <= 0, front +y (a two-sided plate)
Tris fin()
{
  Tris t;
  quad(t, {-W, 0, -W}, {-W, 0, 0}, {W, 0, 0}, {W, 0, -W});
  return t;
}
// half-plate: z = 0 for x <= 0, front +z
Tris half_plate()
{
  Tris t;
  quad(t, {-2 * W, -W, 0}, {0, -W, 0}, {0, W, 0}, {-2 * W, W, 0});
  return t;
}
// a box's outer edge along y: top z = 0 for x <= 0 (front +z), side x = 0
// for z <= 0 (front +x)
Tris box_edge()
{
  Tris t = half_plate();
  quad(t, {0, -W, 0}, {0, -W, -2 * W}, {0, W, -2 * W}, {0, W, 0});
  return t;
}
// concave corner: floor z = 0 for x >= 0 (front +z), wall x = 0 for z >= 0
// (front +x)
Tris corner()
{
  Tris t;
  quad(t, {0, -W, 0}, {2 * W, -W, 0}, {2 * W, W, 0}, {0, W, 0});
  quad(t, {0, -W, 0}, {0, W, 0}, {0, W, 2 * W}, {0, -W, 2 * W});
  return t;
}
// ridge along y: two plates falling away at 30 degrees from the line z = 0
Tris ridge()
{
  Tris t;
  const double c = std::cos(M_PI / 6) * 2 * W, s = std::sin(M_PI / 6) * 2 * W;
  quad(t, {0, -W, 0}, {0, W, 0}, {-c, W, -s}, {-c, -W, -s});
  quad(t, {0, -W, 0}, {c, -W, -s}, {c, W, -s}, {0, W, 0});
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

// Largest |E / E_0 - 1| over the run; the wall's contact count must rise.
double energy_drift(const Case &c, const std::vector<std::string> &extra, double &touched)
{
  const std::string stl = tmpdir() + "/edge_" + c.name + ".stl";
  const bool ell = c.shape.compare(0, 9, "ellipsoid") == 0;
  write_ascii(stl, c.mesh);
  Lmp l(extra);
  l.cmds({"units si", "atom_style polyhedron", "atom_modify map array", "boundary f f f",
          "comm_modify vel yes", "newton off", "region box block -0.5 0.5 -0.5 0.5 -0.5 0.5",
          "create_box 1 box",
          ell ? "polyhedron_shape s " + c.shape
              : "polyhedron_shape s " + polydem_test::potentials() + "/" + c.shape + ".shape",
          "create_atoms 1 single " + num(c.x[0]) + " " + num(c.x[1]) + " " + num(c.x[2]),
          "polyhedron_set atom 1 shape s " + std::string(ell ? "" : "scale 0.006 ") +
              "density 2500 " + c.quat,
          "velocity all set " + num(c.v[0]) + " " + num(c.v[1]) + " " + num(c.v[2]),
          ell ? "pair_style ellipsoid" : "pair_style polyhedron",
          ell ? "pair_coeff * * 1.0e4 1.0" : "pair_coeff * * 1.0e7 0.3 1.0 0.0",
          "neighbor 0.002 bin",
          "fix nve all nve/polyhedron", "fix w all wall/mesh " + stl,
          "compute er all erotate/polyhedron", "thermo_style custom step c_er",
          "timestep " + num(c.dt), "run 0 post no"});
  auto energy = [&]() {
    const double *v = l.lmp->atom->v[0];
    return 0.5 * l.lmp->atom->rmass[0] * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) +
        l.thermo("c_er") + l.lmp->modify->fix[l.lmp->modify->find_fix("w")]->compute_scalar();
  };
  const double e0 = energy();
  double dev = 0.0;
  touched = 0.0;
  // 0.008 s: the approach (at most 1 mm at 1 m/s), the impacts and the way out
  const int chunk = (int) std::lround(1e-4 / c.dt);
  for (int k = 0; k < 80; k++) {
    l.cmd("run " + std::to_string(chunk) + " post no");
    touched = std::fmax(touched, l.lmp->modify->fix[l.lmp->modify->find_fix("w")]->compute_vector(6));
    dev = std::fmax(dev, std::fabs(energy() / e0 - 1.0));
  }
  return dev;
}

std::vector<Case> cases()
{
  const std::string tilt = "quat 1 2 0.5 23", tilt2 = "quat -0.3 1 0.7 41", flat = "quat 0 0 1 0";
  std::vector<Case> out;
  // the fin's top edge: centroid 0.5 mm and 2 mm off its plane, falling 1 m/s
  for (double off : {0.0005, 0.002})
    for (const std::string &q : {flat, tilt})
      out.push_back({"fin", "cube", fin(), {0.001, off, 0.0056}, {0, 0, -1}, q, q == flat ? 1e-8 : 5e-8});
  // across the half-plate's open border (x = 0), at several offsets
  for (double off : {-0.001, 0.0, 0.002})
    out.push_back({"half", "cube", half_plate(), {off, 0.0, 0.0056}, {0.05, 0, -1}, tilt2});
  // a grazing slide along the border: straddling it, moving along it
  out.push_back({"graze", "cube", half_plate(), {0.0008, -0.01, 0.0056}, {0, 0.8, -0.3}, tilt});
  // a box's outer edge, hit diagonally
  out.push_back({"boxedge", "cube", box_edge(), {0.004, 0.0, 0.004}, {-0.7, 0, -0.7}, tilt});
  // into a concave corner
  out.push_back({"corner", "cube", corner(), {0.006, 0.0, 0.006}, {-0.7, 0.1, -0.7}, tilt2});
  // a dodecahedron onto a ridge of two 30 degree plates
  out.push_back({"ridge", "dodecahedron", ridge(), {0.0005, 0.0, 0.008}, {0, 0, -1}, tilt});
  // ellipsoids (semi-axes 4, 2.5, 1.5 mm; pair_style ellipsoid's linear law)
  const std::string ell = "ellipsoid 0.004 0.0025 0.0015";
  for (const std::string &q : {tilt, tilt2}) {
    out.push_back({"fin", ell, fin(), {0.001, 0.0005, 0.0056}, {0, 0, -1}, q});
    out.push_back({"half", ell, half_plate(), {0.0, 0.0, 0.0056}, {0.05, 0, -1}, q});
    out.push_back({"graze", ell, half_plate(), {-0.0005, -0.01, 0.0042}, {0, 0.8, -0.5}, q});
    out.push_back({"boxedge", ell, box_edge(), {0.004, 0.0, 0.004}, {-0.7, 0, -0.7}, q});
    out.push_back({"corner", ell, corner(), {0.006, 0.0, 0.006}, {-0.7, 0.1, -0.7}, q});
    out.push_back({"ridge", ell, ridge(), {0.0005, 0.0, 0.008}, {0, 0, -1}, q});
  }
  return out;
}

}    // namespace

TEST(WallEdges, ElasticImpactsKeepTheEnergy)
{
  double worst = 0.0;
  for (const Case &c : cases()) {
    double touched;
    const double dev = energy_drift(c, {}, touched);
    // /kk: the same kernels, the same energy (the fin, box edge and ridge cases)
    if (polydem_test::has_kokkos() && c.dt > 2e-8 &&
        (c.name == "fin" || c.name == "boxedge" || c.name == "ridge")) {
      double touched_kk;
      const double dev_kk =
          energy_drift(c, polydem_test::kk({"-sf", "kk", "-pk", "kokkos", "newton", "off"}),
                       touched_kk);
      EXPECT_EQ(touched_kk, touched) << c.name;
      EXPECT_NEAR(dev_kk, dev, 1e-9) << c.name;
    }
    std::printf("[ edges ] %-8s %-29s x (%.4f %.4f %.4f) %-18s dt %.0e: contacts %g, "
                "max |E/E0 - 1| %.3g\n", c.name.c_str(), c.shape.c_str(), c.x[0], c.x[1], c.x[2],
                c.quat.c_str(), c.dt, touched, dev);
    EXPECT_GT(touched, 0.0) << c.name;
    EXPECT_LT(dev, 1e-6) << c.name;
    worst = std::fmax(worst, dev);
  }
  std::printf("[ edges ] largest energy deviation %.3g\n", worst);
}
