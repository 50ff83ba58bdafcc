// Shape templates (issue 2, acceptance 1 and 4): mass properties against
// closed-form values, face merging, face/plane consistency, invariance
// under rotation and translation, and bad input with file:line messages.
// Reference values are analytic formulas, never numbers from the code.

#include "polydem_shape_template.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iterator>
#include <fstream>
#include <map>
#include <random>
#include <string>
#include <unistd.h>

using namespace polydem;
using Pt = PolyShapeTemplate::Point;

namespace {

const std::string POT = POLYDEM_POTENTIALS_DIR;
const double PHI = (1.0 + std::sqrt(5.0)) / 2.0;
double max_err = 0.0;                        // largest relative error seen in the analytic tests
std::map<std::string, double> max_err_by;    // ... per kind of check

std::string pot(const std::string &f)
{
  return POT + "/" + f;
}

void expect_rel(double got, double want, double tol, const char *what)
{
  double err = std::fabs(got - want) / std::fabs(want);
  max_err = std::max(max_err, err);
  max_err_by[what] = std::max(max_err_by[what], err);
  EXPECT_LE(err, tol) << what << ": got " << got << " want " << want;
}

struct Analytic {
  const char *file;
  double volume;
  double moments[3];    // per unit density, ascending
  int nverts, nfaces, nedges;
};

// regular n-gon prism, circumradius r, height l, axis z: area A, polar
// second moment of the polygon J = n r^4/12 sin(2pi/n)(2 + cos(2pi/n)).
void prism(int n, double r, double l, double &vol, double &iax, double &itr)
{
  const double t = 2.0 * M_PI / n;
  double area = 0.5 * n * r * r * std::sin(t);
  double j = n * std::pow(r, 4) / 12.0 * std::sin(t) * (2.0 + std::cos(t));
  vol = area * l;
  iax = j * l;
  itr = 0.5 * j * l + area * l * l * l / 12.0;
}

std::vector<Analytic> analytic_shapes()
{
  std::vector<Analytic> a;
  const double s5 = std::sqrt(5.0), s2 = std::sqrt(2.0);
  double v;
  v = 1.0 / (6.0 * s2);    // tetrahedron, I = V a^2/20
  a.push_back({"tetrahedron.shape", v, {v / 20, v / 20, v / 20}, 4, 4, 6});
  a.push_back({"cube.shape", 1.0, {1.0 / 6, 1.0 / 6, 1.0 / 6}, 8, 6, 12});
  v = s2 / 3.0;    // octahedron, I = V a^2/10
  a.push_back({"octahedron.shape", v, {v / 10, v / 10, v / 10}, 6, 8, 12});
  v = (15.0 + 7.0 * s5) / 4.0;    // dodecahedron, I = V a^2 (95 + 39 sqrt5)/300
  double i = v * (95.0 + 39.0 * s5) / 300.0;
  a.push_back({"dodecahedron.shape", v, {i, i, i}, 20, 12, 30});
  v = 5.0 * (3.0 + s5) / 12.0;    // icosahedron, I = V a^2 (3 + sqrt5)/20
  i = v * (3.0 + s5) / 20.0;
  a.push_back({"icosahedron.shape", v, {i, i, i}, 12, 20, 30});
  double iax, itr;
  prism(20, 0.004, 0.0053, v, iax, itr);    // seed 3.1: D = 8 mm, L = 5.3 mm
  a.push_back({"cylinder42.shape", v, {itr, itr, iax}, 40, 22, 60});
  prism(24, 0.00275, 0.0055, v, iax, itr);    // seed 4.2: 5.5 x 5.5 mm
  a.push_back({"catalyst_cylinder.shape", v, {iax, itr, itr}, 48, 26, 72});
  v = std::pow(0.025, 3);    // seed 3.2 cube, I = V a^2/6
  a.push_back({"cuboid_2p5cm.shape",
               v,
               {v * 0.025 * 0.025 / 6, v * 0.025 * 0.025 / 6, v * 0.025 * 0.025 / 6},
               8,
               6,
               12});
  return a;
}

// Independent check (plain double, fan triangulation of the merged faces):
// volume, first moment and products of inertia of the stored vertices.
void plain_moments(const PolyShapeTemplate &s, double &vol, double c[3], double prod[3])
{
  vol = 0;
  double m1[3] = {0, 0, 0}, m2[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  for (int f = 0; f < s.nfaces(); ++f) {
    auto loop = s.face(f);
    for (size_t k = 1; k + 1 < loop.size(); ++k) {
      Pt a = s.vertex(loop[0]), b = s.vertex(loop[k]), d = s.vertex(loop[k + 1]);
      double det = a[0] * (b[1] * d[2] - b[2] * d[1]) - a[1] * (b[0] * d[2] - b[2] * d[0]) +
                   a[2] * (b[0] * d[1] - b[1] * d[0]);
      vol += det / 6;
      for (int i = 0; i < 3; ++i) {
        double si = a[i] + b[i] + d[i];
        m1[i] += det * si / 24;
        for (int j = 0; j < 3; ++j)
          m2[i][j] +=
              det / 120 * (a[i] * a[j] + b[i] * b[j] + d[i] * d[j] + si * (a[j] + b[j] + d[j]));
      }
    }
  }
  for (int i = 0; i < 3; ++i) c[i] = m1[i] / vol;
  prod[0] = m2[0][1];
  prod[1] = m2[0][2];
  prod[2] = m2[1][2];
}

std::string tmpdir()
{
  static std::string d;
  if (d.empty()) {
    char buf[] = "/tmp/polydem_shapes_XXXXXX";
    d = mkdtemp(buf);
  }
  return d;
}

std::string write_tmp(const std::string &name, const std::string &text)
{
  std::string p = tmpdir() + "/" + name;
  std::ofstream(p) << text;
  return p;
}

// message of the ShapeError thrown by loading `text` (empty if none)
std::string load_error(const std::string &name, const std::string &text,
                       const ShapeOptions &opt = ShapeOptions())
{
  std::string p = write_tmp(name, text);
  try {
    PolyShapeTemplate::from_file(p, opt);
  } catch (const ShapeError &e) {
    return e.what();
  }
  return "";
}

const char *CUBE8 = "0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n";

Pt rotate(const double r[3][3], const Pt &p, const Pt &t)
{
  Pt q;
  for (int i = 0; i < 3; ++i) q[i] = r[i][0] * p[0] + r[i][1] * p[1] + r[i][2] * p[2] + t[i];
  return q;
}

void random_rotation(std::mt19937_64 &rng, double r[3][3])
{
  std::normal_distribution<double> g;
  double w = g(rng), x = g(rng), y = g(rng), z = g(rng);
  Quat<double> q = qnormalize(make_quat(w, x, y, z));
  Mat3<double> m = quat_to_mat(q);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r[i][j] = m.m[i][j];
}

}    // namespace

// ---------------------------------------------------------------------
// acceptance 1: mass properties and face counts vs closed forms
// ---------------------------------------------------------------------

TEST(ShapeTemplate, AnalyticMassProperties)
{
  for (const auto &a : analytic_shapes()) {
    SCOPED_TRACE(a.file);
    auto s = PolyShapeTemplate::from_file(pot(a.file));
    expect_rel(s.volume(), a.volume, 1e-12, "volume");
    for (int k = 0; k < 3; ++k) expect_rel(s.moments()[k], a.moments[k], 1e-12, "moment");
    // the files are centred: analytic centroid 0 (relative to the size)
    for (int k = 0; k < 3; ++k) EXPECT_LE(std::fabs(s.input_centroid()[k]), 1e-12 * s.radius());
    EXPECT_EQ(s.nverts(), a.nverts);
    EXPECT_EQ(s.nfaces(), a.nfaces);
    EXPECT_EQ(s.nedges(), a.nedges);
    auto v = s.view();
    EXPECT_EQ(v.nverts, a.nverts);
    EXPECT_EQ(v.nfaces, a.nfaces);
    EXPECT_DOUBLE_EQ(v.volume, s.volume());
  }
  std::printf("[ shapes ] max relative error vs analytic: %.3g\n", max_err);
}

TEST(ShapeTemplate, CylinderFileHasSeedCounts)
{
  // seed 3.1: 42 vertices, 80 triangles; the two cap centres are not corners
  auto s = PolyShapeTemplate::from_file(pot("cylinder42.shape"));
  EXPECT_EQ(s.ninput_verts(), 42);
  EXPECT_EQ(s.nverts(), 40);
  EXPECT_TRUE(s.warnings().empty());
  // z is the axis and stays the body z axis (ascending: I_x = I_y < I_z)
  EXPECT_EQ(s.rotation()[2][2], 1.0);
  EXPECT_NEAR(s.radius(), std::sqrt(0.004 * 0.004 + 0.00265 * 0.00265), 1e-15);
}

TEST(ShapeTemplate, MineralGrainCounts)
{
  auto s = PolyShapeTemplate::from_file(pot("mineral18.shape"));
  EXPECT_EQ(s.nverts(), 18);
  EXPECT_EQ(s.nfaces(), 32);
  EXPECT_EQ(s.nedges(), 48);
  EXPECT_LT(s.moments()[0], s.moments()[1]);
  EXPECT_LT(s.moments()[1], s.moments()[2]);
}

TEST(ShapeTemplate, TranslatedCubeCentroid)
{
  // cube [0,1]^3 + t: analytic centroid t + 1/2
  const Pt t = {3.25, -2.0, 1e3};
  std::vector<Pt> p;
  for (int i = 0; i < 8; ++i)
    p.push_back({t[0] + (i & 1), t[1] + ((i >> 1) & 1), t[2] + ((i >> 2) & 1)});
  auto s = PolyShapeTemplate::from_points(p);
  for (int k = 0; k < 3; ++k) expect_rel(s.input_centroid()[k], t[k] + 0.5, 1e-12, "centroid");
  expect_rel(s.volume(), 1.0, 1e-12, "volume");
  for (int k = 0; k < 3; ++k) expect_rel(s.moments()[k], 1.0 / 6, 1e-12, "moment");
  EXPECT_NEAR(s.radius(), std::sqrt(3.0) / 2, 1e-15);
}

TEST(ShapeTemplate, BoxPrincipalAxes)
{
  // box a x b x c with a > b > c, rotated: moments V/12 (b^2+c^2) etc., ascending
  const double a = 3, b = 2, c = 1, vol = a * b * c;
  std::mt19937_64 rng(7);
  double r[3][3];
  random_rotation(rng, r);
  std::vector<Pt> p;
  for (int i = 0; i < 8; ++i)
    p.push_back(
        rotate(r, {a * ((i & 1) - 0.5), b * (((i >> 1) & 1) - 0.5), c * (((i >> 2) & 1) - 0.5)},
               {0.1, 0.2, 0.3}));
  auto s = PolyShapeTemplate::from_points(p);
  expect_rel(s.volume(), vol, 1e-12, "volume");
  expect_rel(s.moments()[0], vol / 12 * (b * b + c * c), 1e-12, "I0");
  expect_rel(s.moments()[1], vol / 12 * (a * a + c * c), 1e-12, "I1");
  expect_rel(s.moments()[2], vol / 12 * (a * a + b * b), 1e-12, "I2");
  // body frame = principal frame: the long edge lies along body x
  for (int k = 0; k < s.nverts(); ++k) {
    Pt v = s.vertex(k);
    EXPECT_NEAR(std::fabs(v[0]), a / 2, 1e-13);
    EXPECT_NEAR(std::fabs(v[1]), b / 2, 1e-13);
    EXPECT_NEAR(std::fabs(v[2]), c / 2, 1e-13);
  }
  // R is a proper rotation and maps body vertices back onto the input
  const auto &R = s.rotation();
  double det = R[0][0] * (R[1][1] * R[2][2] - R[1][2] * R[2][1]) -
               R[0][1] * (R[1][0] * R[2][2] - R[1][2] * R[2][0]) +
               R[0][2] * (R[1][0] * R[2][1] - R[1][1] * R[2][0]);
  EXPECT_NEAR(det, 1.0, 1e-14);
  for (int j = 0; j < 2; ++j) {    // documented sign convention of axes 1 and 2
    int k = 0;
    for (int i = 1; i < 3; ++i)
      if (std::fabs(R[i][j]) > std::fabs(R[k][j])) k = i;
    EXPECT_GT(R[k][j], 0.0) << "axis " << j;
  }
  Mat3<double> m = quat_to_mat(s.input_orientation());
  for (int k = 0; k < 8; ++k) {
    Pt v = s.vertex(k);    // hull corners keep the input order
    for (int i = 0; i < 3; ++i) {
      double back = s.input_centroid()[i] + m.m[i][0] * v[0] + m.m[i][1] * v[1] + m.m[i][2] * v[2];
      EXPECT_NEAR(back, p[k][i], 1e-13);
    }
  }
}

// ---------------------------------------------------------------------
// faces, planes, loops, edges of every shipped file
// ---------------------------------------------------------------------

TEST(ShapeTemplate, EveryShippedFileIsConsistent)
{
  const char *files[] = {"tetrahedron.shape",       "cube.shape",         "octahedron.shape",
                         "dodecahedron.shape",      "icosahedron.shape",  "cylinder42.shape",
                         "catalyst_cylinder.shape", "cuboid_2p5cm.shape", "mineral18.shape"};
  for (const char *f : files) {
    SCOPED_TRACE(f);
    PolyShapeTemplate s = PolyShapeTemplate::from_file(pot(f));
    EXPECT_TRUE(s.warnings().empty());
    EXPECT_EQ(s.name(), f);
    std::printf("[ shapes ] %-24s V=%2d F=%2d E=%2d volume=%.10g I=(%.6g %.6g %.6g) r=%.6g\n", f,
                s.nverts(), s.nfaces(), s.nedges(), s.volume(), s.moments()[0], s.moments()[1],
                s.moments()[2], s.radius());
    const double r = s.radius(), tol = 1e-12 * r;
    EXPECT_EQ(s.nverts() - s.nedges() + s.nfaces(), 2);
    // dual triangulation (overlap kernel's seed): 2F-4 triangles, each at
    // a vertex lying on its three planes, neighbours mutual across reversed edges
    const int *dual = s.view().dual;
    ASSERT_NE(dual, nullptr);
    EXPECT_EQ(dual[0], 2 * s.nfaces() - 4);
    for (int t = 0; t < dual[0]; ++t) {
      const int *q = dual + 1 + polydem::DUAL_SEED_STRIDE_K * t;
      const auto v = s.vertex(q[6]);
      for (int e = 0; e < 3; ++e) {
        const auto pl = s.plane(q[e]);
        EXPECT_NEAR(pl[0] * v[0] + pl[1] * v[1] + pl[2] * v[2], pl[3], tol);
        const int *o = dual + 1 + polydem::DUAL_SEED_STRIDE_K * q[3 + e];
        int back = 0;
        for (int g = 0; g < 3; ++g)
          back += o[g] == q[(e + 1) % 3] && o[(g + 1) % 3] == q[e] && o[3 + g] == t;
        EXPECT_EQ(back, 1) << "triangle " << t << " edge " << e;
      }
    }
    std::vector<int> edge_use(s.nedges(), 0);
    for (int i = 0; i < s.nfaces(); ++i) {
      auto pl = s.plane(i);
      EXPECT_NEAR(pl[0] * pl[0] + pl[1] * pl[1] + pl[2] * pl[2], 1.0, 1e-14);
      auto loop = s.face(i);
      ASSERT_GE(loop.size(), 3u);
      for (int k : loop) {    // the plane contains its loop
        Pt v = s.vertex(k);
        EXPECT_NEAR(pl[0] * v[0] + pl[1] * v[1] + pl[2] * v[2], pl[3], tol);
      }
      for (int k = 0; k < s.nverts(); ++k) {    // and supports the polyhedron
        Pt v = s.vertex(k);
        EXPECT_LE(pl[0] * v[0] + pl[1] * v[1] + pl[2] * v[2], pl[3] + tol);
      }
      for (size_t k = 0; k < loop.size(); ++k) {    // counter-clockwise seen from outside
        Pt a = s.vertex(loop[k]), b = s.vertex(loop[(k + 1) % loop.size()]),
           c = s.vertex(loop[(k + 2) % loop.size()]);
        double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        double w[3] = {c[0] - b[0], c[1] - b[1], c[2] - b[2]};
        double turn = pl[0] * (u[1] * w[2] - u[2] * w[1]) + pl[1] * (u[2] * w[0] - u[0] * w[2]) +
                      pl[2] * (u[0] * w[1] - u[1] * w[0]);
        EXPECT_GT(turn, 0.0) << "face " << i << " corner " << k;
        int lo = std::min(loop[k], loop[(k + 1) % loop.size()]);
        int hi = std::max(loop[k], loop[(k + 1) % loop.size()]);
        int found = 0;
        for (int e = 0; e < s.nedges(); ++e)
          if (s.edge(e)[0] == lo && s.edge(e)[1] == hi) {
            ++edge_use[e];
            ++found;
          }
        EXPECT_EQ(found, 1);
      }
    }
    for (int e = 0; e < s.nedges(); ++e) EXPECT_EQ(edge_use[e], 2) << "edge " << e;
    // principal frame: centroid at the origin, products of inertia vanish
    double vol, c[3], prod[3];
    plain_moments(s, vol, c, prod);
    expect_rel(vol, s.volume(), 1e-12, "volume (independent sum)");
    const double scale = s.moments()[2];
    for (int k = 0; k < 3; ++k) {
      EXPECT_LE(std::fabs(c[k]), 1e-12 * r);
      EXPECT_LE(std::fabs(prod[k]), 1e-12 * scale);
    }
    // float view mirrors the double one
    auto vf = s.view_float();
    auto vd = s.view();
    for (int k = 0; k < 3 * s.nverts(); ++k) EXPECT_NEAR(vf.verts[k], vd.verts[k], 1e-6 * r);
    EXPECT_FLOAT_EQ(vf.radius, (float)vd.radius);
  }
}

// ---------------------------------------------------------------------
// invariance: a rotated and translated copy has the same template
// ---------------------------------------------------------------------

TEST(ShapeTemplate, RotatedTranslatedCopySameMoments)
{
  std::mt19937_64 rng(2026);
  const char *files[] = {"cube.shape", "dodecahedron.shape", "cylinder42.shape",
                         "catalyst_cylinder.shape", "mineral18.shape"};
  for (const char *f : files) {
    SCOPED_TRACE(f);
    auto s = PolyShapeTemplate::from_file(pot(f));
    for (int trial = 0; trial < 3; ++trial) {
      double r[3][3];
      random_rotation(rng, r);
      Pt t = {(3.0 * trial - 1.0) * s.radius(), 7.0 * s.radius(), -2.5 * s.radius()};
      std::vector<Pt> p;
      for (int k = 0; k < s.nverts(); ++k) p.push_back(rotate(r, s.vertex(k), t));
      auto c = PolyShapeTemplate::from_points(p, {}, ShapeOptions(), "copy");
      EXPECT_EQ(c.nverts(), s.nverts());
      EXPECT_EQ(c.nfaces(), s.nfaces());
      EXPECT_EQ(c.nedges(), s.nedges());
      expect_rel(c.volume(), s.volume(), 1e-12, "volume");
      expect_rel(c.radius(), s.radius(), 1e-12, "radius");
      for (int k = 0; k < 3; ++k) {
        expect_rel(c.moments()[k], s.moments()[k], 1e-12, "moment");
        EXPECT_NEAR(c.input_centroid()[k], t[k], 1e-12 * s.radius());
      }
    }
  }
}

TEST(ShapeTemplate, RotatedDodecahedronAnalytic)
{
  // all 20 corners rotated: still 12 pentagons; moments still the closed form
  const double s5 = std::sqrt(5.0), vol = (15.0 + 7.0 * s5) / 4.0;
  const double mom = vol * (95.0 + 39.0 * s5) / 300.0;
  std::vector<Pt> p;
  const double h = PHI / 2;
  for (int i = 0; i < 8; ++i)
    p.push_back({h * ((i & 1) ? 1 : -1), h * ((i & 2) ? 1 : -1), h * ((i & 4) ? 1 : -1)});
  for (int a = -1; a <= 1; a += 2)
    for (int b = -1; b <= 1; b += 2) {
      p.push_back({0.0, a * h / PHI, b * h * PHI});
      p.push_back({a * h / PHI, b * h * PHI, 0.0});
      p.push_back({b * h * PHI, 0.0, a * h / PHI});
    }
  std::mt19937_64 rng(11);
  double r[3][3];
  random_rotation(rng, r);
  for (auto &q : p) q = rotate(r, q, {1.0, 2.0, 3.0});
  auto s = PolyShapeTemplate::from_points(p);
  EXPECT_EQ(s.nfaces(), 12);
  EXPECT_EQ(s.nedges(), 30);
  expect_rel(s.volume(), vol, 1e-12, "volume");
  for (int k = 0; k < 3; ++k) expect_rel(s.moments()[k], mom, 1e-12, "moment");
  for (int k = 0; k < 3; ++k) expect_rel(s.input_centroid()[k], k + 1.0, 1e-12, "centroid");
}

TEST(ShapeTemplate, FileScaleAndOptionScale)
{
  std::string p = write_tmp("scaled.shape", std::string("scale 2\nvertices 8\n") + CUBE8);
  ShapeOptions o;
  o.scale = 1.5;
  auto s = PolyShapeTemplate::from_file(p, o);
  expect_rel(s.volume(), 27.0, 1e-12, "volume");
  expect_rel(s.moments()[0], std::pow(3.0, 5) / 6, 1e-12, "moment");
}

// ---------------------------------------------------------------------
// acceptance 4: bad input -> ShapeError naming file and line
// ---------------------------------------------------------------------

#define EXPECT_MSG(msg, text) EXPECT_NE((msg).find(text), std::string::npos) << "message: " << (msg)

TEST(ShapeTemplateErrors, BadFiles)
{
  const std::string d = tmpdir() + "/";
  // file name, text, the message after "<dir>/<file>"
  const struct {
    const char *file;
    std::string text, msg;
  } cases[] = {
      {"missing.shape", "# no vertices\nvertices 8\n0 0 0\n1 0\n", ":4: expected 3 numbers, got 2"},
      {"extra.shape", "vertices 4\n0 0 0 0\n", ":2: expected 3 numbers, got 4"},
      {"word.shape", "vertices 4\n0 0 0\n1 x 0\n", ":3: coordinate 'x' is not a number"},
      {"nan.shape", "vertices 4\n0 0 0\n1 0 0\n0 nan 1\n0 0 1\n",
       ":4: coordinate 'nan' is not finite"},
      {"inf.shape", "vertices 4\n0 0 0\n1 0 0\n0 1 0\n0 0 -inf\n",
       ":5: coordinate '-inf' is not finite"},
      {"three.shape", "# triangle\n\nvertices 3\n0 0 0\n1 0 0\n0 1 0\n",
       ":3: a polyhedron needs at least 4 vertices, got 3"},
      {"flat.shape", "vertices 5\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n0.5 0.25 0\n",
       ":1: all 5 vertices are coplanar (zero volume)"},
      {"line.shape", "vertices 4\n0 0 0\n1 1 1\n2 2 2\n3 3 3\n",
       ":1: all 4 vertices are collinear (zero volume)"},
      {"dup.shape", std::string("vertices 9\n") + CUBE8 + "1 0 0\n",
       ":10: vertex 8 duplicates vertex 1 (line 3)"},
      {"key.shape", std::string("vertexes 8\n") + CUBE8, ":1: unknown keyword 'vertexes'"},
      {"count.shape", "vertices eight\n", ":1: count 'eight' is not an integer"},
      {"eof.shape", "vertices 8\n0 0 0\n1 0 0\n", ":3: end of file after 2 of 8 vertex lines"},
      {"none.shape", "# nothing\nscale 2\n", ":2: no 'vertices' section"},
      {"range.shape", std::string("vertices 8\n") + CUBE8 + "faces 1\n0 1 9\n",
       ":11: vertex index 9 out of range 0..7"},
      {"badface.shape", std::string("vertices 8\n") + CUBE8 + "faces 1\n0 1\n",
       ":11: a face needs at least 3 vertex indices, got 2"},
      {"scale.shape", std::string("scale -1\nvertices 8\n") + CUBE8,
       ":1: scale must be positive, got -1"},
      {"twice.shape", std::string("vertices 8\n") + CUBE8 + "vertices 8\n" + CUBE8,
       ":10: second 'vertices' section (first at line 1)"},
      {"twice_faces.shape",
       std::string("vertices 8\n") + CUBE8 + "faces 1\n0 1 2 3\nfaces 1\n0 1 2 3\n",
       ":12: second 'faces' section (first at line 10)"},
  };
  for (const auto &c : cases) EXPECT_MSG(load_error(c.file, c.text), d + c.file + c.msg);

  std::string nofile = d + "does_not_exist.shape";
  try {
    PolyShapeTemplate::from_file(nofile);
    ADD_FAILURE() << "no error for a missing file";
  } catch (const ShapeError &e) {
    EXPECT_MSG(std::string(e.what()), nofile + ": cannot open file");
  }
}

TEST(ShapeTemplateErrors, NonConvex)
{
  const std::string d = tmpdir() + "/";
  // a point strictly inside: error by default, hull + warning with the option
  std::string text = std::string("vertices 9\n") + CUBE8 + "0.5 0.5 0.25\n";
  std::string m = load_error("dent.shape", text);
  EXPECT_MSG(m, d + "dent.shape:10: vertex 8 lies inside the convex hull");
  EXPECT_MSG(m, "'hull' option");
  ShapeOptions o;
  o.hull = true;
  auto s = PolyShapeTemplate::from_file(write_tmp("dent.shape", text), o);
  EXPECT_EQ(s.nverts(), 8);
  EXPECT_EQ(s.nfaces(), 6);
  ASSERT_EQ(s.warnings().size(), 1u);
  EXPECT_MSG(s.warnings()[0], d + "dent.shape:10: vertex 8 lies inside the convex hull");
  expect_rel(s.volume(), 1.0, 1e-12, "hull volume");

  // a listed face that cuts the body
  m = load_error("cut.shape", std::string("vertices 8\n") + CUBE8 + "faces 1\n0 1 6\n");
  EXPECT_MSG(m, d + "cut.shape:11: vertices lie on both sides of this face");

  // non-planar listed face
  m = load_error("warp.shape", std::string("vertices 8\n") + CUBE8 + "faces 1\n0 1 3 6\n");
  EXPECT_MSG(m, d + "warp.shape:11: face is not planar");

  // a point on a face (not a corner) is fine: not a template vertex, no warning
  auto c = PolyShapeTemplate::from_file(
      write_tmp("centre.shape", std::string("vertices 9\n") + CUBE8 + "0.5 0.5 1\n"));
  EXPECT_EQ(c.nverts(), 8);
  EXPECT_TRUE(c.warnings().empty());
}

TEST(ShapeTemplateErrors, FromPointsAndCaps)
{
  try {
    PolyShapeTemplate::from_points({{0, 0, 0}, {1, 0, 0}, {0, NAN, 0}, {0, 0, 1}}, {},
                                   ShapeOptions(), "mine");
    ADD_FAILURE() << "NaN accepted";
  } catch (const ShapeError &e) {
    EXPECT_MSG(std::string(e.what()), "mine: vertex 2: coordinate");
  }
  // more hull vertices than MAX_TEMPLATE_VERTS: points on a sphere
  std::vector<Pt> p;
  const int n = MAX_TEMPLATE_VERTS + 1;
  for (int i = 0; i < n; ++i) {
    double z = 1.0 - (2.0 * i + 1.0) / n, rr = std::sqrt(1 - z * z), t = 2.399963229728653 * i;
    p.push_back({rr * std::cos(t), rr * std::sin(t), z});
  }
  try {
    PolyShapeTemplate::from_points(p, {}, ShapeOptions(), "ball");
    ADD_FAILURE() << "cap not enforced";
  } catch (const ShapeError &e) {
    EXPECT_MSG(std::string(e.what()),
               "ball: the hull has 129 vertices, more than MAX_TEMPLATE_VERTS = 128");
  }
}

TEST(ShapeTemplate, ZSummary)
{
  for (const auto &kv : max_err_by)
    std::printf("[ shapes ] max relative error, %-26s %.3g\n", kv.first.c_str(), kv.second);
  std::printf("[ shapes ] max relative error of all checks at 1e-12: %.3g\n", max_err);
  EXPECT_LE(max_err, 1e-12);
}

TEST(ShapeTemplate, RebuildFromInputPointsIsBitIdentical)
{
  // restart records store input_points(); the rebuild must match exactly
  for (const char *f : {"dodecahedron.shape", "cylinder42.shape", "mineral18.shape"}) {
    SCOPED_TRACE(f);
    auto s = PolyShapeTemplate::from_file(pot(f));
    auto r = PolyShapeTemplate::from_points(s.input_points(), {}, ShapeOptions(), s.name());
    ASSERT_EQ(r.nverts(), s.nverts());
    ASSERT_EQ(r.nfaces(), s.nfaces());
    for (int k = 0; k < s.nverts(); ++k) EXPECT_TRUE(r.vertex(k) == s.vertex(k));
    for (int k = 0; k < s.nfaces(); ++k) {
      EXPECT_TRUE(r.plane(k) == s.plane(k));
      EXPECT_TRUE(r.face(k) == s.face(k));
    }
    EXPECT_EQ(r.volume(), s.volume());
    EXPECT_TRUE(r.moments() == s.moments());
  }
}

TEST(ShapeTemplate, EveryFileInPotentialsLoads)
{
  int n = 0;
  for (const auto &e : std::filesystem::directory_iterator(POT)) {
    if (e.path().extension() != ".shape") continue;
    SCOPED_TRACE(e.path().string());
    EXPECT_NO_THROW(PolyShapeTemplate::from_file(e.path().string()));
    ++n;
  }
  EXPECT_GE(n, 9);
}

TEST(ShapeTemplateErrors, EmptyFileAndNearDuplicates)
{
  const std::string d = tmpdir() + "/";
  EXPECT_EQ(load_error("empty.shape", ""), d + "empty.shape: no 'vertices' section");
  // two corners 1e-15 apart: either a clean template or a ShapeError, never a crash
  for (double eps : {1e-15, 1e-12, 1e-9}) {
    std::vector<Pt> p;
    for (int i = 0; i < 8; ++i)
      p.push_back({double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
    p.push_back({1.0 + eps, 1.0, 1.0 - eps});
    try {
      auto s = PolyShapeTemplate::from_points(p, {}, ShapeOptions(), "near");
      EXPECT_EQ(s.nverts() - s.nedges() + s.nfaces(), 2);
      expect_rel(s.volume(), 1.0, 1e-8, "near-duplicate volume");
    } catch (const ShapeError &e) {
      EXPECT_LT(eps, 1e-10);
      EXPECT_MSG(std::string(e.what()), "near: vertex 8 is within");
    }
  }
}

TEST(ShapeTemplateErrors, MutatedFilesNeverCrash)
{
  // random byte edits of a valid file: each loads or throws ShapeError
  std::ifstream in(pot("cube.shape"));
  std::string good((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::mt19937_64 rng(42);
  const char alphabet[] = "0123456789.-+eE \n#xnaif";
  int loaded = 0, rejected = 0;
  for (int trial = 0; trial < 400; ++trial) {
    std::string t = good;
    int edits = 1 + (int)(rng() % 4);
    for (int k = 0; k < edits; ++k) {
      size_t pos = rng() % t.size();
      switch (rng() % 3) {
      case 0:
        t.erase(pos, 1 + rng() % 3);
        break;
      case 1:
        t.insert(pos, 1, alphabet[rng() % (sizeof(alphabet) - 1)]);
        break;
      default:
        t[pos] = alphabet[rng() % (sizeof(alphabet) - 1)];
      }
      if (t.empty()) t = "#";
    }
    std::string p = write_tmp("mutant.shape", t);
    try {
      auto s = PolyShapeTemplate::from_file(p);
      EXPECT_EQ(s.nverts() - s.nedges() + s.nfaces(), 2);
      EXPECT_GT(s.volume(), 0.0);
      ++loaded;
    } catch (const ShapeError &e) {
      EXPECT_EQ(std::string(e.what()).rfind(p, 0), 0u) << e.what();    // names the file
      ++rejected;
    }
  }
  EXPECT_GT(loaded, 0);
  EXPECT_GT(rejected, 0);
}

TEST(ShapeTemplate, CatalystAxisBecomesBodyX)
{
  // D = L: the axial moment is the smallest, so body x = file z (exactly)
  auto s = PolyShapeTemplate::from_file(pot("catalyst_cylinder.shape"));
  const auto &R = s.rotation();
  EXPECT_EQ(R[2][0], 1.0);    // column 0 (body x) = file z
  EXPECT_EQ(R[0][1], 1.0);    // body y = file x (the in-plane file axis kept)
  EXPECT_EQ(R[1][2], 1.0);    // body z = file y, right-handed
  for (int k = 0; k < s.nverts(); ++k)
    EXPECT_NEAR(std::fabs(s.vertex(k)[0]), 0.00275, 1e-15);
}

// Issue 17 items 5, 9, 11: extreme sizes and slivers give a clear error (the
// file, the line, the cause) instead of SIGFPE in GMP (coordinates 1e61 ..
// 1e199), zero moments (scale 1e-80) or 'map::at' (a 1e-11 thick sliver)
TEST(ShapeTemplateErrors, ExtremeSizesAndSlivers)
{
  const std::string d = tmpdir() + "/";
  for (const char *c : {"1e61", "1e70", "1e150", "1e199"}) {
    const std::string m =
        load_error("huge.shape",
                   std::string("vertices 4\n0 0 0\n") + c + " 0 0\n0 " + c + " 0\n0 0 " + c + "\n");
    EXPECT_MSG(m, d + "huge.shape:1: the shape's size");
    EXPECT_MSG(m, "is outside [1e-50, 1e50]");
  }
  std::string m =
      load_error("tiny80.shape", "scale 1e-80\nvertices 4\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n");
  EXPECT_MSG(m, d + "tiny80.shape:2: the shape's size");
  ShapeOptions o;
  o.scale = 1e-80;
  m = load_error("tiny80b.shape", "vertices 4\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n", o);
  EXPECT_MSG(m, "is outside [1e-50, 1e50]");
  m = load_error("far2.shape", "vertices 4\n1e14 0 0\n100000000000001 0 0\n1e14 1 0\n1e14 0 1\n");
  EXPECT_MSG(m, "more than 1e12 times its size: translate it");
  for (const char *t : {"1e-11", "1e-13", "1e-15", "1e-18"}) {
    m = load_error("sliver.shape",
                   std::string("vertices 4\n0 0 0\n1 0 0\n0 1 0\n0.3 0.3 ") + t + "\n");
    EXPECT_MSG(m, d + "sliver.shape: degenerate hull");
  }
  // within the bounds: finite, normal mass properties (moments ~ size^5)
  for (double c : {5e49, 1e-50}) {
    char text[200];
    std::snprintf(text, sizeof text, "vertices 4\n0 0 0\n%.17g 0 0\n0 %.17g 0\n0 0 %.17g\n", c, c,
                  c);
    const std::string p = write_tmp("edge.shape", text);
    const auto s = PolyShapeTemplate::from_file(p);
    expect_rel(s.volume(), c * c * c / 6.0, 1e-12, "extreme volume");
    for (double mo : s.moments()) EXPECT_TRUE(std::isnormal(mo)) << c;
  }
}

// Issue 17 item 8: an ellipsoid whose volume or moments are not normal
// numbers (1e-160: volume 0, 1e120: moments inf) is an error
TEST(ShapeTemplateErrors, EllipsoidMassPropertiesMustBeNormal)
{
  for (double a : {1e-160, 1e-110, 1e120, 1e160}) {
    std::string m;
    try {
      PolyShapeTemplate::ellipsoid(a, a, a, "e");
    } catch (const ShapeError &e) {
      m = e.what();
    }
    EXPECT_MSG(m, "are zero or not finite");
  }
  const auto e = PolyShapeTemplate::ellipsoid(1e-40, 1e-40, 2e-40, "small");
  for (double mo : e.moments()) EXPECT_TRUE(std::isnormal(mo));
}
