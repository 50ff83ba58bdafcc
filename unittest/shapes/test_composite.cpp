// Composite shape templates (issue 29, part 2): the union's mass properties
// against closed forms (overlapping parts count once), the body frame of
// the parts, one-part composites, the restart record, and refused input.
// Reference values are analytic formulas, never numbers from the code.

#include "polydem_shape_record.h"
#include "polydem_shape_template.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

using namespace polydem;
using Part = PolyShapeTemplate::InputPart;

namespace {

const std::string POT = POLYDEM_POTENTIALS_DIR;

std::shared_ptr<const PolyShapeTemplate> cube()    // unit cube, volume 1, centred
{
  static auto c = std::make_shared<PolyShapeTemplate>(PolyShapeTemplate::from_file(POT + "/cube.shape"));
  return c;
}

Part part(std::shared_ptr<const PolyShapeTemplate> s, double x, double y, double z,
          Quat<double> q = make_quat(1.0, 0.0, 0.0, 0.0), const std::string &id = "p")
{
  Part p;
  p.shape = std::move(s);
  p.id = id;
  p.x = {x, y, z};
  p.q = q;
  return p;
}

// sorted principal moments
std::vector<double> moments(const PolyShapeTemplate &t)
{
  std::vector<double> m(t.moments().begin(), t.moments().end());
  std::sort(m.begin(), m.end());
  return m;
}

void expect_rel(double got, double want, double tol, const char *what)
{
  EXPECT_LE(std::fabs(got - want), tol * std::fabs(want)) << what << ": got " << got << " want "
                                                         << want;
}

// A box a x b x c: V = abc, I = V (b^2 + c^2)/12, ...
std::vector<double> box_moments(double a, double b, double c)
{
  const double V = a * b * c;
  std::vector<double> m = {V * (b * b + c * c) / 12, V * (a * a + c * c) / 12,
                           V * (a * a + b * b) / 12};
  std::sort(m.begin(), m.end());
  return m;
}

}    // namespace

// two unit cubes overlapping by half: the union is a 1.5 x 1 x 1 box
// (volume 1.5, not 2), centroid (0.25, 0, 0) in the input frame
TEST(Composite, OverlappingCubesGiveTheUnionsMassProperties)
{
  const auto t = PolyShapeTemplate::composite({part(cube(), 0, 0, 0), part(cube(), 0.5, 0, 0)}, "bar");
  expect_rel(t.volume(), 1.5, 1e-14, "volume");
  expect_rel(t.union_fraction(), 0.75, 1e-14, "union fraction");
  EXPECT_NEAR(t.input_centroid()[0], 0.25, 1e-15);
  EXPECT_NEAR(t.input_centroid()[1], 0.0, 1e-15);
  const auto m = moments(t), want = box_moments(1.5, 1.0, 1.0);
  for (int k = 0; k < 3; k++) expect_rel(m[k], want[k], 1e-13, "moment");
  // the contact parts do not overlap: the union (a convex box) is one
  // piece, at the centroid, of the box's half-diagonal as radius
  EXPECT_TRUE(t.decomposed());
  const auto v = t.view();
  EXPECT_TRUE(view_is_composite(v));
  ASSERT_EQ(v.nparts, 1);
  EXPECT_EQ(v.nverts, 0);
  expect_rel(t.part_shape(0).volume(), 1.5, 1e-14, "piece volume");
  for (int i = 0; i < 3; i++) EXPECT_NEAR(t.part(0).x[i], 0.0, 1e-15);
  EXPECT_NEAR(t.radius(), std::sqrt(0.75 * 0.75 + 0.5), 1e-14);
}

// an L of three unit cubes meeting face to face: V = 3, centroid (1/3, 1/3, 0),
// inertia about it by the parallel-axis theorem
// two unit cubes that meet only along an edge (centres (0,0,0) and (1,1,0)):
// the union is no 2-manifold, but the parts share no volume, so they are a
// rigid body of two disjoint parts: volume 2, centroid (1/2, 1/2, 0),
// principal moments 1/3, 4/3, 4/3 (2 (1/6 + 1/4) -+ 1/2 in the xy plane,
// 2 (1/6 + 1/2) about z)
TEST(Composite, CubesMeetingAlongAnEdge)
{
  const auto t = PolyShapeTemplate::composite({part(cube(), 0, 0, 0), part(cube(), 1, 1, 0)}, "edge");
  expect_rel(t.volume(), 2.0, 1e-14, "volume");
  EXPECT_FALSE(t.decomposed());
  EXPECT_EQ(t.nparts(), 2);
  EXPECT_NEAR(t.input_centroid()[0], 0.5, 1e-15);
  EXPECT_NEAR(t.input_centroid()[1], 0.5, 1e-15);
  const auto m = moments(t);
  expect_rel(m[0], 1.0 / 3, 1e-13, "moment");
  expect_rel(m[1], 4.0 / 3, 1e-13, "moment");
  expect_rel(m[2], 4.0 / 3, 1e-13, "moment");
}

TEST(Composite, LShapeOfTouchingCubes)
{
  const auto t = PolyShapeTemplate::composite(
      {part(cube(), 0, 0, 0), part(cube(), 1, 0, 0), part(cube(), 0, 1, 0)}, "L");
  expect_rel(t.volume(), 3.0, 1e-14, "volume");
  EXPECT_FALSE(t.decomposed());    // disjoint interiors: the parts as given
  EXPECT_EQ(t.nparts(), 3);
  EXPECT_NEAR(t.input_centroid()[0], 1.0 / 3, 1e-15);
  EXPECT_NEAR(t.input_centroid()[1], 1.0 / 3, 1e-15);
  // I about the centroid: sum of 1/6 + |d|^2 - d d^T per cube
  const double c[3][2] = {{0, 0}, {1, 0}, {0, 1}};
  double I[3][3] = {{0}};
  for (auto &p : c) {
    const double d[3] = {p[0] - 1.0 / 3, p[1] - 1.0 / 3, 0.0};
    const double d2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    for (int i = 0; i < 3; i++)
      for (int j = 0; j < 3; j++) I[i][j] += (i == j ? 1.0 / 6 + d2 : 0.0) - d[i] * d[j];
  }
  // eigenvalues: I_zz, and the xy block's a +- b
  const double mid = 0.5 * (I[0][0] + I[1][1]), dev = std::hypot(0.5 * (I[0][0] - I[1][1]), I[0][1]);
  std::vector<double> want = {mid - dev, mid + dev, I[2][2]};
  std::sort(want.begin(), want.end());
  const auto m = moments(t);
  for (int k = 0; k < 3; k++) expect_rel(m[k], want[k], 1e-13, "moment");
}

// a cube and the same cube turned 45 degrees about z: the union is an
// eight-pointed star prism of area 2 - 8 (1/2)^2 tan(pi/8) (two unit
// squares less their regular octagon of apothem 1/2)
TEST(Composite, RotatedPartsOverlapExactly)
{
  const double h = std::sin(M_PI / 8);
  const auto t = PolyShapeTemplate::composite(
      {part(cube(), 0, 0, 0), part(cube(), 0, 0, 0, make_quat(std::cos(M_PI / 8), 0.0, 0.0, h))},
      "star");
  expect_rel(t.volume(), 2.0 - 2.0 * std::tan(M_PI / 8), 1e-14, "volume");
  // the contact parts are disjoint convex pieces filling the union
  EXPECT_TRUE(t.decomposed());
  EXPECT_GE(t.nparts(), 2);
  double sum = 0.0;
  for (int k = 0; k < t.nparts(); k++) sum += t.part_shape(k).volume();
  expect_rel(sum, t.volume(), 1e-13, "pieces' volume");
  std::printf("star prism: %d convex pieces\n", t.nparts());
}

// a cube and a disjoint sphere: V, centroid and inertia are sums
// (sphere I = 2/5 V r^2), an overlapping sphere is refused
TEST(Composite, SpherePartAddsAnalyticMoments)
{
  auto ball = std::make_shared<PolyShapeTemplate>(PolyShapeTemplate::ellipsoid(0.5, 0.5, 0.5, "ball"));
  const auto t = PolyShapeTemplate::composite({part(cube(), 0, 0, 0), part(ball, 1.5, 0, 0)}, "cb");
  const double Vs = 4.0 / 3 * M_PI * 0.125;
  expect_rel(t.volume(), 1.0 + Vs, 1e-14, "volume");
  const double xc = 1.5 * Vs / (1.0 + Vs);
  EXPECT_NEAR(t.input_centroid()[0], xc, 1e-15);
  const double Iaxis = 1.0 / 6 + 0.4 * Vs * 0.25;    // about the x axis
  const double Iperp = Iaxis + 1.0 * xc * xc + Vs * (1.5 - xc) * (1.5 - xc);
  const auto m = moments(t);
  expect_rel(m[0], Iaxis, 1e-13, "axial moment");
  expect_rel(m[1], Iperp, 1e-13, "transverse moment");
  expect_rel(m[2], Iperp, 1e-13, "transverse moment");
  try {
    PolyShapeTemplate::composite({part(cube(), 0, 0, 0, make_quat(1.0, 0.0, 0.0, 0.0), "box"),
                                  part(ball, 0.9, 0, 0, make_quat(1.0, 0.0, 0.0, 0.0), "ball")},
                                 "bad");
    FAIL() << "an overlapping sphere part was accepted";
  } catch (const ShapeError &e) {
    EXPECT_NE(std::string(e.what()).find("'ball' and 'box' overlap"), std::string::npos) << e.what();
  }
}

// one part: the part itself, in its own frame (volume, moments, radius bit
// for bit; its placement the identity), the input pose in input_centroid
TEST(Composite, OnePartIsThePart)
{
  auto dode = std::make_shared<PolyShapeTemplate>(PolyShapeTemplate::from_file(POT + "/dodecahedron.shape"));
  const auto t = PolyShapeTemplate::composite({part(dode, 1, 2, 3, make_quat(0.8, 0.6, 0.0, 0.0))}, "one");
  EXPECT_EQ(t.volume(), dode->volume());
  EXPECT_EQ(t.radius(), dode->radius());
  for (int k = 0; k < 3; k++) EXPECT_EQ(t.moments()[k], dode->moments()[k]);
  const auto &p = t.part(0);
  for (int i = 0; i < 3; i++) {
    EXPECT_EQ(p.x[i], 0.0);
    for (int j = 0; j < 3; j++) EXPECT_EQ(p.R[i][j], i == j ? 1.0 : 0.0);
  }
  EXPECT_EQ(t.input_centroid()[2], 3.0);
}

// the restart record rebuilds the composite bit for bit; bad parts are refused
TEST(Composite, RecordRoundTripAndErrors)
{
  std::string rec_cube, rec_ball, err;
  std::vector<std::string> warn;
  ASSERT_TRUE(shape_from_file(POT + "/cube.shape", false, rec_cube, warn, err)) << err;
  ASSERT_TRUE(shape_ellipsoid(0.3, 0.2, 0.25, "egg", rec_ball, err)) << err;
  std::vector<CompositePartRecord> parts(3);
  parts[0] = {"cube", rec_cube, {0.0, 0.0, 0.0}, {1.0, 0.0, 0.0, 0.0}};
  parts[1] = {"cube", rec_cube, {0.7, 0.1, 0.0}, {0.9, 0.1, 0.3, -0.2}};
  parts[2] = {"egg", rec_ball, {0.0, 1.4, 0.2}, {1.0, 0.0, 0.0, 0.0}};
  std::string record;
  auto a = shape_composite(parts, "thing", record, err);
  ASSERT_TRUE(a) << err;
  auto b = shape_from_record(record, err);
  ASSERT_TRUE(b) << err;
  ASSERT_TRUE(b->is_composite());
  EXPECT_EQ(a->volume(), b->volume());
  EXPECT_EQ(a->radius(), b->radius());
  for (int k = 0; k < 3; k++) EXPECT_EQ(a->moments()[k], b->moments()[k]);
  ASSERT_EQ(b->nparts(), a->nparts());    // the egg and the pieces of the cubes' union
  EXPECT_TRUE(a->decomposed());
  std::printf("two cubes at a general angle and an ellipsoid: %d contact parts\n", a->nparts());
  for (int k = 0; k < a->nparts(); k++)
    for (int i = 0; i < 3; i++) {
      EXPECT_EQ(a->part(k).x[i], b->part(k).x[i]);
      for (int j = 0; j < 3; j++) EXPECT_EQ(a->part(k).R[i][j], b->part(k).R[i][j]);
    }
  EXPECT_LT(a->volume(), 2.0 + 4.0 / 3 * M_PI * 0.3 * 0.2 * 0.25);    // the cubes overlap

  // a composite as a part, a zero quaternion, the record cut short
  std::vector<CompositePartRecord> nested = {{"thing", record, {0, 0, 0}, {1, 0, 0, 0}}};
  EXPECT_FALSE(shape_composite(nested, "nest", record, err));
  EXPECT_NE(err.find("is itself a composite"), std::string::npos) << err;
  parts[1].q[0] = parts[1].q[1] = parts[1].q[2] = parts[1].q[3] = 0.0;
  EXPECT_FALSE(shape_composite(parts, "zero", record, err));
  EXPECT_NE(err.find("nonzero orientation"), std::string::npos) << err;
  std::string rec2;
  parts[1].q[0] = 1.0;
  ASSERT_TRUE(shape_composite(parts, "thing", rec2, err)) << err;
  EXPECT_FALSE(shape_from_record(rec2.substr(0, rec2.size() / 2), err));
}

namespace {

// the L prism: outline (0,0) (2,0) (2,1) (1,1) (1,2) (0,2), z in [0, 1],
// as an ASCII STL (outward), without triangle `drop` (-1: none)
std::string l_prism_stl(const std::string &path, int drop = -1)
{
  const double o[6][2] = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  std::vector<std::array<double, 9>> tri;
  auto add = [&](std::array<double, 3> a, std::array<double, 3> b, std::array<double, 3> c) {
    tri.push_back({a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2]});
  };
  for (int k = 1; k < 5; k++) {    // a fan from (0, 0): top up, bottom down
    add({o[0][0], o[0][1], 1}, {o[k][0], o[k][1], 1}, {o[k + 1][0], o[k + 1][1], 1});
    add({o[0][0], o[0][1], 0}, {o[k + 1][0], o[k + 1][1], 0}, {o[k][0], o[k][1], 0});
  }
  for (int k = 0; k < 6; k++) {    // the sides, outward for a counter-clockwise outline
    const double *a = o[k], *b = o[(k + 1) % 6];
    add({a[0], a[1], 0}, {b[0], b[1], 0}, {b[0], b[1], 1});
    add({a[0], a[1], 0}, {b[0], b[1], 1}, {a[0], a[1], 1});
  }
  std::ofstream f(path);
  f << "solid L\n";
  for (int t = 0; t < (int) tri.size(); t++) {
    if (t == drop) continue;
    f << " facet normal 0 0 0\n  outer loop\n";
    for (int v = 0; v < 3; v++)
      f << "   vertex " << tri[t][3 * v] << " " << tri[t][3 * v + 1] << " " << tri[t][3 * v + 2] << "\n";
    f << "  endloop\n endfacet\n";
  }
  f << "endsolid L\n";
  return path;
}

// a ring (genus 1): regular 12-gons of vertex radius 1 (outside) and 0.75
// (inside), z in [-0.5, 0.5], as an ASCII STL (outward)
std::string ring_stl(const std::string &path)
{
  const int n = 12;
  auto corner = [&](double r, int k, double z) {
    const double a = (2 * (k % n) - 1) * M_PI / n;
    return std::array<double, 3>{r * std::cos(a), r * std::sin(a), z};
  };
  std::ofstream f(path);
  f.precision(17);
  auto add = [&](std::array<double, 3> a, std::array<double, 3> b, std::array<double, 3> c) {
    f << " facet normal 0 0 0\n  outer loop\n";
    for (const auto &p : {a, b, c}) f << "   vertex " << p[0] << " " << p[1] << " " << p[2] << "\n";
    f << "  endloop\n endfacet\n";
  };
  f << "solid ring\n";
  for (int k = 0; k < n; k++) {
    const double R = 1.0, r = 0.75, h = 0.5;
    add(corner(R, k, -h), corner(R, k + 1, -h), corner(R, k + 1, h));    // outside
    add(corner(R, k, -h), corner(R, k + 1, h), corner(R, k, h));
    add(corner(r, k, -h), corner(r, k, h), corner(r, k + 1, h));    // inside (the hole)
    add(corner(r, k, -h), corner(r, k + 1, h), corner(r, k + 1, -h));
    add(corner(r, k, h), corner(R, k, h), corner(R, k + 1, h));    // top
    add(corner(r, k, h), corner(R, k + 1, h), corner(r, k + 1, h));
    add(corner(r, k, -h), corner(R, k + 1, -h), corner(R, k, -h));    // bottom
    add(corner(r, k, -h), corner(r, k + 1, -h), corner(R, k + 1, -h));
  }
  f << "endsolid ring\n";
  return path;
}

}    // namespace

// a non-convex surface decomposed into convex parts (CGAL convex_decomposition_3):
// the L prism's volume 3, centroid and moments those of the L of three unit
// cubes (closed form, the test above); the record rebuilds it bit for bit; an
// open surface is refused
TEST(Composite, ConvexDecompositionOfAnLPrism)
{
  const std::string dir = ::testing::TempDir();
  std::string record, err;
  auto t = shape_composite_from_surface(l_prism_stl(dir + "L.stl"), 0.5, "L", record, err);
  ASSERT_TRUE(t) << err;
  EXPECT_GE(t->nparts(), 2);
  const double s3 = 0.125, s5 = 0.03125;    // scale 0.5: volume ~ s^3, moments ~ s^5
  expect_rel(t->volume(), 3.0 * s3, 1e-14, "volume");
  EXPECT_NEAR(t->input_centroid()[0], 0.5 * (1.0 / 3 + 0.5), 1e-15);
  EXPECT_NEAR(t->input_centroid()[1], 0.5 * (1.0 / 3 + 0.5), 1e-15);
  EXPECT_NEAR(t->input_centroid()[2], 0.25, 1e-15);
  const auto L3 = PolyShapeTemplate::composite(
      {part(cube(), 0, 0, 0), part(cube(), 1, 0, 0), part(cube(), 0, 1, 0)}, "L3");
  const auto m = moments(*t), want = moments(L3);
  for (int k = 0; k < 3; k++) expect_rel(m[k], want[k] * s5, 1e-13, "moment");
  EXPECT_NEAR(t->union_fraction(), 1.0, 1e-14);    // the pieces do not overlap
  std::printf("L prism: %d convex pieces\n", t->nparts());
  auto b = shape_from_record(record, err);
  ASSERT_TRUE(b) << err;
  EXPECT_EQ(b->volume(), t->volume());
  for (int k = 0; k < 3; k++) EXPECT_EQ(b->moments()[k], t->moments()[k]);
  EXPECT_FALSE(shape_composite_from_surface(l_prism_stl(dir + "L_open.stl", 3), 1.0, "Lo", record, err));
  EXPECT_NE(err.find("not closed"), std::string::npos) << err;
}

// a surface with a hole: the ring of 12-gons is cut into its 12 sectors; the
// volume, principal moments and bounding radius against the closed forms
// (prism of the polygonal annulus: area A = 3 (R^2 - r^2), polar moment
// J = n rho^4 sin(30 deg) (2 + cos(30 deg)) / 12 per polygon, I_axis = J h,
// I_across = J h / 2 + A h^3 / 12 for length h = 1; the farthest corner
// sqrt(R^2 + 1/4))
TEST(Composite, ConvexDecompositionOfARing)
{
  const double A = 3.0 * (1.0 - 0.5625);
  const double J = 12.0 * (1.0 - std::pow(0.75, 4)) * 0.5 * (2.0 + std::cos(M_PI / 6)) / 12.0;
  std::string record, err;
  const auto t =
      shape_composite_from_surface(ring_stl(::testing::TempDir() + "ring.stl"), 1.0, "ring", record, err);
  ASSERT_TRUE(t) << err;
  EXPECT_EQ(t->nparts(), 12);
  expect_rel(t->volume(), A, 1e-13, "volume");
  for (int i = 0; i < 3; i++) EXPECT_NEAR(t->input_centroid()[i], 0.0, 1e-14);
  const auto m = moments(*t);    // principal, ascending: two across, one along the axis
  expect_rel(m[0], J / 2 + A / 12, 1e-13, "moment across");
  expect_rel(m[1], J / 2 + A / 12, 1e-13, "moment across");
  expect_rel(m[2], J, 1e-13, "moment along the axis");
  expect_rel(t->radius(), std::sqrt(1.25), 1e-14, "bounding radius");
  EXPECT_NEAR(t->union_fraction(), 1.0, 1e-14);
}
