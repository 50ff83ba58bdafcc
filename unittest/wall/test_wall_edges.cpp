// Elastic impacts (e = 1, mu = 0, no gravity) of polyhedra and ellipsoids on
// the open and sharp edges of meshes, through LAMMPS: the total energy (translation +
// rotation + the wall's elastic energy W(V)) is conserved to 1e-6 of the
// impact's energy over the whole impact. The cases (issue 32, item 1): the
// top edge of a thin vertical fin, the open border of a half-plate, a box's
// outer (convex) edge, a concave corner, a ridge of two 30 degree plates, and
// a grazing slide along an open border, a rod passing beside one, impacts
// on a faceted rod (a convex curved mesh), a composite grain; several
// offsets and orientations;
// fix wall/mesh/kk the same (fin, box edge, ridge, beside and rod at dt 5e-8).
// Before the prisms' side sections were part of dV/dx (polydem_clip.h) a
// cube falling onto the fin's edge left it with many times its energy.
#include "wall_edges.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace wall_test;

namespace {

// a rod 2 x 1/3 x 1/3 (x 0.006 m in energy_drift): its shape file
std::string rod_shape()
{
  const std::string path = tmpdir() + "/rod.shape";
  FILE *f = std::fopen(path.c_str(), "w");
  std::fprintf(f, "vertices 8\n");
  for (int k = 0; k < 8; k++)
    std::fprintf(f, "%g %.17g %.17g\n", k & 1 ? 1.0 : -1.0, (k & 2 ? 1.0 : -1.0) / 6.0,
                 (k & 4 ? 1.0 : -1.0) / 6.0);
  std::fclose(f);
  return path;
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
  // beside an open border: a rod (12 x 2 x 2 mm) at 45 degrees whose centroid
  // (outside the plate's prism) crosses the plate's extended plane 1 mm before
  // its upper end, overhanging the plate, lands on the border. Before the side
  // of a beginning two-sided contact was the smaller overlap's, the centroid's
  // crossing turned the overhang into an overlap from below, out of nothing.
  out.push_back({"beside", rod_shape(), half_plate(), {0.0025, 0.0, 0.0005}, {0, 0, -1},
                 "quat 0 1 0 45"});
  // onto a rod of 48 facets (7.5 degrees each, radius 3 mm): the contact
  // spreads over more facets than the patch angle (20 degrees). Before
  // patches were the mesh's smooth regions (fixed at load), a facet's patch
  // followed the first facet met, changed while it carried overlap, and W(V)
  // jumped (+2.7e-2 and +1.9e-2 of the energy in these two impacts).
  out.push_back({"rod", "cube", rod(0.003, 48), {0.0, 0.0, 0.0085}, {0, 0, -1}, tilt});
  out.push_back({"rod", "cube", rod(0.003, 48), {0.001, 0.0, 0.0085}, {0, 0, -1}, tilt2});
  // a composite (issue 29: two overlapping cubes and a sphere, 6 mm cubes):
  // each part on the wall with its own history, the torques moved to the
  // grain's centre
  const std::string comp = "composite part cube 0 0 0 part cube 0.8 0 0 quat 0.95 0 0.31 0 "
                           "part ball 0 1.1 0";
  out.push_back({"half", comp, half_plate(), {0.0, 0.0, 0.0085}, {0.05, 0, -1}, tilt2});
  out.push_back({"boxedge", comp, box_edge(), {0.0085, 0.0, 0.0085}, {-0.7, 0, -0.7}, tilt});
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
  // the rod: each patch keeps its deepest triangle (before, the smallest r',
  // which on non-coplanar facets is not the deepest: delta jumped, 2e-2)
  for (const std::string &q : {tilt, tilt2})
    out.push_back({"rod", ell, rod(0.003, 48), {0.001, 0.0, 0.0073}, {0, 0, -1}, q});
  out.push_back({"beside", "ellipsoid 0.006 0.001 0.001", half_plate(), {0.0025, 0.0, 0.0005},
                 {0, 0, -1}, "quat 0 1 0 45"});
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
        (c.name == "fin" || c.name == "boxedge" || c.name == "ridge" || c.name == "beside" ||
         c.name == "rod")) {
      double touched_kk;
      const double dev_kk =
          energy_drift(c, polydem_test::kk_styles(),
                       touched_kk);
      EXPECT_EQ(touched_kk, touched) << c.name;
      EXPECT_NEAR(dev_kk, dev, 1e-9) << c.name;
    }
    std::printf("[ edges ] %-8s %-29s x (%.4f %.4f %.4f) %-18s dt %.0e: contact-steps %g, "
                "max |E/E0 - 1| %.3g\n", c.name.c_str(),
                c.shape[0] == '/' ? "rod 12 x 2 x 2 mm" : c.shape.c_str(), c.x[0], c.x[1], c.x[2],
                c.quat.c_str(), c.dt, touched, dev);
    EXPECT_GT(touched, 0.0) << c.name;
    EXPECT_LT(dev, 1e-6) << c.name;
    worst = std::fmax(worst, dev);
  }
  std::printf("[ edges ] largest energy deviation %.3g\n", worst);
}
