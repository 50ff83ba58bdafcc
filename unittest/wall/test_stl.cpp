// STL reader and mesh bin grid (issue 5, acceptance 5 at the reader level):
// ASCII and binary give the same triangles, load transform, dropped
// triangles counted, clear errors with file and line, grid candidates equal
// a brute-force search.
#include "polydem_mesh_grid.h"
#include "polydem_stl.h"
#include "polydem_wall_mesh.h"
#include "wall_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <set>

using namespace polydem;
using namespace wall_test;

namespace {

std::string write_text(const std::string &name, const std::string &text)
{
  const std::string p = tmpdir() + "/" + name;
  std::ofstream(p) << text;
  return p;
}

std::string error_of(const std::string &path, const StlTransform &xf = StlTransform())
{
  try {
    read_stl(path, xf);
  } catch (StlError &e) {
    return e.what();
  }
  return "";
}

}    // namespace

TEST(Stl, AsciiAndBinaryAgree)
{
  const Tris t = flat(-1, 1, -0.5, 0.5, 0.25, 5, 3, true, 0.3, 7);
  const std::string a = tmpdir() + "/a.stl", b = tmpdir() + "/b.stl";
  write_ascii(a, t);
  write_binary(b, t);
  const StlMesh ma = read_stl(a, StlTransform()), mb = read_stl(b, StlTransform());
  EXPECT_FALSE(ma.binary);
  EXPECT_TRUE(mb.binary);
  ASSERT_EQ(ma.ntri(), 30);
  ASSERT_EQ(mb.ntri(), 30);
  for (size_t k = 0; k < t.size(); k++) {
    EXPECT_EQ(ma.tri[k], t[k]);                          // ASCII: %.17g round trip
    EXPECT_NEAR(mb.tri[k], t[k], 1e-7 * std::fabs(t[k]) + 1e-30);    // binary: float32
  }
}

TEST(Stl, BinaryHeaderStartingWithSolid)
{
  const Tris t = flat(0, 1, 0, 1, 0, 2, 2);
  const std::string b = tmpdir() + "/solidhdr.stl";
  write_binary(b, t);
  {
    std::fstream f(b, std::ios::in | std::ios::out | std::ios::binary);
    f.write("solid binary", 12);
  }
  const StlMesh m = read_stl(b, StlTransform());
  EXPECT_TRUE(m.binary);
  EXPECT_EQ(m.ntri(), 8);
  EXPECT_EQ(m.trailing, 0);
  {    // and with bytes after the last triangle: still binary, the bytes counted
    std::ofstream f(b, std::ios::binary | std::ios::app);
    f.write("\n\n\n", 3);
  }
  const StlMesh m2 = read_stl(b, StlTransform());
  EXPECT_TRUE(m2.binary);
  EXPECT_EQ(m2.ntri(), 8);
  EXPECT_EQ(m2.trailing, 3);
}

TEST(Stl, TransformScaleRotateOffsetFlip)
{
  const Tris t = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  const std::string a = tmpdir() + "/one.stl";
  write_ascii(a, t);
  StlTransform xf;
  xf.scale = 2.0;
  // 90 degrees about x: y -> z
  xf.R[1][1] = 0;
  xf.R[1][2] = -1;
  xf.R[2][1] = 1;
  xf.R[2][2] = 0;
  xf.offset[0] = 10;
  xf.flip = true;
  const StlMesh m = read_stl(a, xf);
  ASSERT_EQ(m.ntri(), 1);
  const double expect[9] = {10, 0, 0, 10, 0, 2, 12, 0, 0};    // t1, t2 swapped
  for (int k = 0; k < 9; k++) EXPECT_NEAR(m.tri[k], expect[k], 1e-15);
}

TEST(Stl, DropsZeroAreaAndDuplicates)
{
  Tris t = flat(0, 1, 0, 1, 0, 2, 2);    // 8 triangles
  const Tris dup(t.begin() + 9, t.begin() + 18);
  // same triangle, vertices rotated and reversed
  const Tris dup2 = {dup[6], dup[7], dup[8], dup[3], dup[4], dup[5], dup[0], dup[1], dup[2]};
  const Tris line = {0, 0, 0, 1, 1, 1, 2, 2, 2};     // collinear
  const Tris point = {3, 3, 3, 3, 3, 3, 3, 3, 3};    // one point
  for (const Tris *x : {&dup, &dup2, &line, &point}) t.insert(t.end(), x->begin(), x->end());
  const std::string a = tmpdir() + "/drop.stl";
  write_ascii(a, t);
  const StlMesh m = read_stl(a, StlTransform());
  EXPECT_EQ(m.nread, 12);
  EXPECT_EQ(m.ntri(), 8);
  EXPECT_EQ(m.nduplicate, 2);
  EXPECT_EQ(m.ndegenerate, 2);
}

// keywords in upper case read like lower case; an ASCII file that ends
// after a complete facet without 'endsolid' is read and flagged (warned)
TEST(Stl, AsciiCaseAndMissingEndsolid)
{
  const std::string facet = " facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n"
                            "   vertex 1 0 0\n   vertex 0 1 0\n  endloop\n endfacet\n";
  std::string upper = "SOLID X\n" + facet + "ENDSOLID X\n";
  for (size_t k = 8; k < upper.size(); k++)
    upper[k] = (char) std::toupper((unsigned char) upper[k]);
  const StlMesh a = read_stl(write_text("upper.stl", upper), StlTransform());
  const StlMesh b = read_stl(write_text("lower.stl", "solid x\n" + facet + "endsolid x\n"),
                             StlTransform());
  EXPECT_FALSE(a.binary);
  EXPECT_EQ(a.tri, b.tri);
  EXPECT_FALSE(a.no_endsolid);
  const StlMesh c = read_stl(write_text("noend.stl", "solid x\n" + facet), StlTransform());
  EXPECT_EQ(c.ntri(), 1);
  EXPECT_TRUE(c.no_endsolid);
  const std::string junk = write_text("junk.stl", "solid x\n" + facet + "endsolid x\nfacet\n");
  EXPECT_NE(error_of(junk).find("junk.stl:10: expected 'solid' or the end of the file"),
            std::string::npos) << error_of(junk);
  // stored normals against the vertex order: counted (the fix warns)
  const std::string down = " facet normal 0 0 -1\n  outer loop\n   vertex 0 0 0\n"
                           "   vertex 1 0 0\n   vertex 0 1 0\n  endloop\n endfacet\n";
  const StlMesh d = read_stl(write_text("down.stl", "solid x\n" + down + "endsolid x\n"),
                             StlTransform());
  EXPECT_EQ(d.nopposite, 1);
  EXPECT_EQ(d.nalong, 0);
  EXPECT_EQ(b.nalong, 1);
  EXPECT_EQ(b.nopposite, 0);
  StlTransform flipped;
  flipped.flip = true;
  EXPECT_EQ(read_stl(write_text("down2.stl", "solid x\n" + down + "endsolid x\n"), flipped).nalong, 1);
  StlTransform big;
  big.scale = 1e308;
  big.offset[0] = 1e308;
  EXPECT_NE(error_of(write_text("big.stl", "solid x\n" + facet + "endsolid x\n"), big)
                .find("not finite after scale, rotate and offset"),
            std::string::npos);
}

TEST(Stl, Errors)
{
  EXPECT_NE(error_of("/nonexistent/x.stl").find("/nonexistent/x.stl: cannot open"),
            std::string::npos);
  // issue 17 item 4: a directory (was an uncaught std::ios_failure) and a device
  EXPECT_NE(error_of(tmpdir()).find(tmpdir() + ": cannot read: is a directory"), std::string::npos)
      << error_of(tmpdir());
  EXPECT_NE(error_of("/dev/null").find("/dev/null: cannot read: not a regular file"),
            std::string::npos)
      << error_of("/dev/null");
  const std::string e = write_text("empty.stl", "");
  EXPECT_NE(error_of(e).find("empty file"), std::string::npos);
  const std::string es = write_text("emptysolid.stl", "solid x\nendsolid x\n");
  EXPECT_NE(error_of(es).find("empty mesh"), std::string::npos);

  const std::string bad = write_text("bad.stl", "solid x\n facet normal 0 0 1\n  outer loop\n"
                                                "   vertex 0 0 0\n   vertex 1 0 zero\n");
  const std::string m = error_of(bad);
  EXPECT_NE(m.find("bad.stl:5: bad number 'zero'"), std::string::npos) << m;

  const std::string kw = write_text("kw.stl", "solid x\n facet normal 0 0 1\n  outer loop\n"
                                              "   vertex 0 0 0\n   vertex 1 0 0\n"
                                              "   vertex 0 1 0\n  endloop\n endfacett\n");
  EXPECT_NE(error_of(kw).find("kw.stl:8: expected 'endfacet'"), std::string::npos)
      << error_of(kw);

  const std::string two = write_text("two.stl", "solid x\n facet normal 0 0 1\n  outer loop\n"
                                                "   vertex 0 0 0\n   vertex 1 0 0\n"
                                                "  endloop\n");
  EXPECT_NE(error_of(two).find("two.stl:6: facet has 2 vertices"), std::string::npos);

  const std::string cut = write_text("cut.stl", "solid x\n facet normal 0 0 1\n  outer loop\n"
                                                "   vertex 0 0 0\n");
  EXPECT_NE(error_of(cut).find("unexpected end of file"), std::string::npos);

  const std::string nan = write_text("nan.stl", "solid x\n facet normal 0 0 1\n  outer loop\n"
                                                "   vertex 0 0 0\n   vertex nan 0 0\n"
                                                "   vertex 0 1 0\n  endloop\n endfacet\n"
                                                "endsolid\n");
  EXPECT_NE(error_of(nan).find("nan.stl:2: facet: non-finite"), std::string::npos)
      << error_of(nan);

  const Tris t = flat(0, 1, 0, 1, 0, 2, 2);
  const std::string tr = tmpdir() + "/trunc.stl";
  write_binary(tr, t, 84 + 50 * 8 - 7);
  EXPECT_NE(error_of(tr).find("truncated binary STL"), std::string::npos) << error_of(tr);
  write_binary(tr, t, 50);
  EXPECT_NE(error_of(tr).find("truncated binary STL"), std::string::npos);

  Tris tn = t;
  tn[4] = std::nan("");
  const std::string bn = tmpdir() + "/nanbin.stl";
  write_binary(bn, tn);
  EXPECT_NE(error_of(bn).find("triangle 1: non-finite"), std::string::npos) << error_of(bn);
}

// candidates from the grid = brute force over all triangles (same near test)
TEST(MeshGrid, CandidatesEqualBruteForce)
{
  Tris t = flat(-1, 1, -1, 1, 0, 12, 9, true, 0.35, 3);
  const Tris w = flat(-1, 1, -1, 1, 0.5, 3, 3, false, 0.0, 1);
  for (size_t k = 0; k < w.size(); k += 3) {    // a tilted second sheet
    t.push_back(w[k]);
    t.push_back(w[k + 1]);
    t.push_back(w[k + 2] + 0.2 * w[k]);
  }
  for (double h : {0.05, 0.3, 5.0}) {
    const MeshGrid g = build_mesh_grid(t, h);
    MeshGridView<double> v{t.data(), (int) (t.size() / 9), {g.lo[0], g.lo[1], g.lo[2]}, g.h,
                           {g.n[0], g.n[1], g.n[2]}, g.start.data(), g.items.data(),
                           g.plane.data(), g.box.data()};
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-1.3, 1.3);
    for (int trial = 0; trial < 300; trial++) {
      const Vec3<double> c = make_vec3(u(rng), u(rng), 0.5 * u(rng));
      const double r = 0.02 + 0.2 * std::fabs(u(rng));
      std::multiset<int> got;
      auto f = [&](int k) { got.insert(k); };
      mesh_for_each_near(v, c, r, f);
      std::multiset<int> want;
      for (int k = 0; k < v.ntri; k++)
        if (mesh_tri_near(v, k, c, r)) want.insert(k);
      ASSERT_EQ(got, want) << "h " << h << " trial " << trial;
    }
  }
}

// The triangles' bounding spheres (MeshGrid::sphere) only speed up the near
// test: with them and without, mesh_tri_near answers the same, also for
// spheres whose surface passes within round-off of a triangle (r set to the
// exact distance times 1 -+ 1e-15) and for triangles far from the origin.
TEST(MeshGrid, BoundingSpheresKeepTheNearTest)
{
  for (double off : {0.0, 1.0e3}) {
    Tris t = flat(-1, 1, -1, 1, 0, 7, 5, true, 0.35, 3);
    for (size_t k = 0; k < t.size(); k++) t[k] += off;
    const MeshGrid g = build_mesh_grid(t, 0.3);
    ASSERT_EQ(g.sphere.size(), 4 * (t.size() / 9));
    MeshGridView<double> v{t.data(), (int) (t.size() / 9), {g.lo[0], g.lo[1], g.lo[2]}, g.h,
                           {g.n[0], g.n[1], g.n[2]}, g.start.data(), g.items.data(),
                           g.plane.data(), g.box.data()};
    MeshGridView<double> vs = v;
    vs.sphere = g.sphere.data();
    // every vertex within its triangle's sphere
    for (int k = 0; k < v.ntri; k++)
      for (int c = 0; c < 3; c++) {
        double d2 = 0.0;
        for (int d = 0; d < 3; d++)
          d2 += std::pow(t[9 * k + 3 * c + d] - g.sphere[4 * k + d], 2);
        EXPECT_LE(std::sqrt(d2), g.sphere[4 * k + 3] * (1 + 1e-15)) << "triangle " << k;
      }
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1.3, 1.3);
    int near = 0, far = 0;
    for (int trial = 0; trial < 400; trial++) {
      const Vec3<double> c = make_vec3(off + u(rng), off + u(rng), off + 0.5 * u(rng));
      const double r = 0.02 + 0.4 * std::fabs(u(rng));
      for (int k = 0; k < v.ntri; k++) {
        const bool a = mesh_tri_near(v, k, c, r), b = mesh_tri_near(vs, k, c, r);
        ASSERT_EQ(a, b) << "off " << off << " trial " << trial << " triangle " << k;
        (a ? near : far)++;
        // at the boundary: the exact distance, a hair inside and outside
        const double *q = &t[9 * k];
        const double d = std::sqrt(point_triangle_dist2(c, make_vec3(q[0], q[1], q[2]),
                                                        make_vec3(q[3], q[4], q[5]),
                                                        make_vec3(q[6], q[7], q[8])));
        for (double f : {1.0 - 1e-15, 1.0, 1.0 + 1e-15})
          ASSERT_EQ(mesh_tri_near(v, k, c, d * f), mesh_tri_near(vs, k, c, d * f))
              << "off " << off << " trial " << trial << " triangle " << k << " f " << f;
      }
    }
    EXPECT_GT(near, 1000);    // both answers met often
    EXPECT_GT(far, 1000);
    // the tight case of the bounding sphere: c on the ray from the centroid
    // through the farthest vertex, beyond it, where the distance to the
    // triangle is |c - centroid| - R; spheres reaching the vertex by
    // 1e-15 of r or missing it by as much
    int tight = 0;
    for (int k = 0; k < v.ntri; k++) {
      const double *sp = &g.sphere[4 * k];
      int far_v = 0;
      double best = -1.0;
      for (int c = 0; c < 3; c++) {
        double d2 = 0.0;
        for (int d = 0; d < 3; d++) d2 += std::pow(t[9 * k + 3 * c + d] - sp[d], 2);
        if (d2 > best) best = d2, far_v = c;
      }
      const Vec3<double> vx = make_vec3(t[9 * k + 3 * far_v], t[9 * k + 3 * far_v + 1],
                                        t[9 * k + 3 * far_v + 2]);
      const Vec3<double> dir = (1.0 / std::sqrt(best)) * (vx - make_vec3(sp[0], sp[1], sp[2]));
      for (double L : {0.01, 0.3, 2.0}) {
        const Vec3<double> c = vx + L * dir;
        for (double f : {1.0 - 1e-15, 1.0, 1.0 + 1e-15, 1.0 + 1e-13}) {
          const bool a = mesh_tri_near(v, k, c, L * f);
          ASSERT_EQ(a, mesh_tri_near(vs, k, c, L * f)) << "tight, triangle " << k << " L " << L << " f " << f;
          tight += a;
        }
      }
    }
    EXPECT_GT(tight, v.ntri);    // the exact test reaches the vertex in some of them
  }
}

TEST(MeshGrid, BinCountCapped)
{
  const Tris t = flat(0, 100, 0, 100, 0, 2, 2);
  const MeshGrid g = build_mesh_grid(t, 1e-3, 1000);
  EXPECT_LE((long) g.n[0] * g.n[1] * g.n[2], 1000);
  EXPECT_EQ(g.start.back(), (int) g.items.size());
  // an edge so small that the bin counts would overflow int and long
  Tris box = t;
  for (size_t k = 0; k < t.size(); k += 3) {
    box.push_back(t[k + 2]);
    box.push_back(t[k]);
    box.push_back(t[k + 1]);
  }
  const MeshGrid tiny = build_mesh_grid(box, 1e-15);
  EXPECT_LE((long) tiny.n[0] * tiny.n[1] * tiny.n[2], 1L << 22);
  EXPECT_GT(tiny.n[2], 1);
  EXPECT_EQ(tiny.start.back(), (int) tiny.items.size());
  EXPECT_GE(tiny.items.size(), box.size() / 9);
}

// Coplanar merging (fix wall/mesh keyword merge)
namespace {
double total_area(const Tris &t, double *nz_min = nullptr)
{
  double a = 0.0, nz = 1.0;
  for (size_t k = 0; k < t.size(); k += 9) {
    const double e1[3] = {t[k + 3] - t[k], t[k + 4] - t[k + 1], t[k + 5] - t[k + 2]};
    const double e2[3] = {t[k + 6] - t[k], t[k + 7] - t[k + 1], t[k + 8] - t[k + 2]};
    const double c[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                         e1[0] * e2[1] - e1[1] * e2[0]};
    const double l = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    a += 0.5 * l;
    nz = std::fmin(nz, c[2] / l);
  }
  if (nz_min) *nz_min = nz;
  return a;
}
}    // namespace

// an irregular flat floor (jittered interior vertices, alternating
// diagonals) becomes the two triangles of its square; area and facing kept
TEST(MergeCoplanar, FlatFloorBecomesTwoTriangles)
{
  Tris t = flat(0, 3, -1, 1, 0, 12, 8, true, 0.35, 11);
  const double a0 = total_area(t);
  const MergeStats st = merge_coplanar(t, 1e-12);
  double nz = 0.0;
  EXPECT_EQ(st.before, 192);
  EXPECT_EQ(st.after, 2);
  EXPECT_EQ((int) t.size(), 18);
  EXPECT_NEAR(total_area(t, &nz), a0, 1e-12 * a0);
  EXPECT_EQ(nz, 1.0);
}

// a closed box with subdivided faces: each face merges on its own (12
// triangles), the sharp edges are kept; a cylinder mantle (24 sectors, 10
// rings) merges along the axis only (one quad per sector)
TEST(MergeCoplanar, BoxAndCylinder)
{
  Tris box;
  // six faces of [0,1]^3 from a 5 x 4 flat grid: (u, v, 0) -> face frame, outward normals
  const Tris f = flat(0, 1, 0, 1, 0, 5, 4, true, 0.3, 2);
  const int map[6][3] = {{0, 1, 2}, {1, 0, 2}, {1, 2, 0}, {2, 1, 0}, {2, 0, 1}, {0, 2, 1}};
  for (int face = 0; face < 6; face++)
    for (size_t k = 0; k < f.size(); k += 9)
      for (int v = 0; v < 3; v++) {
        // reverse the vertex order on the faces whose frame is left-handed
        const int vv = (face % 2 == 0) ? v : 2 - v;
        const double u[3] = {f[k + 3 * vv], f[k + 3 * vv + 1], face < 3 ? 0.0 : 1.0};
        double p[3];
        for (int d = 0; d < 3; d++) p[map[face][d]] = u[d];
        for (int d = 0; d < 3; d++) box.push_back(p[d]);
      }
  const double a0 = total_area(box);
  const int n0 = (int) box.size() / 9;
  const MergeStats st = merge_coplanar(box, 1e-12);
  EXPECT_EQ(st.after, 12) << "from " << n0;
  EXPECT_NEAR(total_area(box), a0, 1e-12 * a0);

  Tris cyl;
  const int ns = 24, nr = 10;
  auto P = [&](int s, int r, double *p) {
    p[0] = std::cos(2 * M_PI * s / ns);
    p[1] = std::sin(2 * M_PI * s / ns);
    p[2] = 0.1 * r;
  };
  for (int s = 0; s < ns; s++)
    for (int r = 0; r < nr; r++) {
      double a[3], b[3], c[3], d[3];
      P(s, r, a);
      P(s + 1, r, b);
      P(s, r + 1, c);
      P(s + 1, r + 1, d);
      for (const double *q : {a, b, d, a, d, c})
        for (int k = 0; k < 3; k++) cyl.push_back(q[k]);
    }
  const double c0 = total_area(cyl);
  const MergeStats sc = merge_coplanar(cyl, 1e-12);
  EXPECT_EQ(sc.after, 2 * ns);
  EXPECT_NEAR(total_area(cyl), c0, 1e-12 * c0);
}

// holes are bridged into the outline: a 6 x 6 plate with a 2 x 2 hole
// (silo bottom with its outlet) becomes 8 triangles, two holes 14; area,
// facing and the hole (no triangle covers its centre) are kept. A pinched
// region (two squares touching at a corner) is kept as read. A tolerance
// below the vertices' distance from the plane keeps them as read too.
TEST(MergeCoplanar, HolesPinchesAndTolerance)
{
  auto cut = [](const Tris &full, std::vector<std::array<double, 4>> boxes) {
    Tris out;
    for (size_t k = 0; k < full.size(); k += 9) {
      const double cx = (full[k] + full[k + 3] + full[k + 6]) / 3.0;
      const double cy = (full[k + 1] + full[k + 4] + full[k + 7]) / 3.0;
      bool in = false;
      for (const auto &b : boxes) in = in || (cx > b[0] && cx < b[1] && cy > b[2] && cy < b[3]);
      if (!in) out.insert(out.end(), full.begin() + (long) k, full.begin() + (long) k + 9);
    }
    return out;
  };
  auto covers = [](const Tris &t, double x, double y) {
    for (size_t k = 0; k < t.size(); k += 9) {
      const double *a = &t[k], *b = &t[k + 3], *c = &t[k + 6];
      auto o = [](const double *p, const double *q, double px, double py) {
        return (q[0] - p[0]) * (py - p[1]) - (q[1] - p[1]) * (px - p[0]);
      };
      if (o(a, b, x, y) > 0 && o(b, c, x, y) > 0 && o(c, a, x, y) > 0) return true;
    }
    return false;
  };
  const Tris full = flat(0, 6, 0, 6, 0, 6, 6, true);
  Tris holed = cut(full, {{2, 4, 2, 4}});
  const double a1 = total_area(holed);
  MergeStats st = merge_coplanar(holed, 1e-12);
  double nz = 0.0;
  EXPECT_EQ(st.after, 8);
  EXPECT_EQ(st.bridged_holes, 1);
  EXPECT_NEAR(total_area(holed, &nz), a1, 1e-12 * a1);
  EXPECT_GT(nz, 0.0);
  EXPECT_FALSE(covers(holed, 3.1, 2.9));
  EXPECT_TRUE(covers(holed, 0.7, 1.3));

  Tris two = cut(flat(0, 8, 0, 6, 0, 8, 6, true), {{1, 3, 1, 3}, {5, 7, 2, 5}});
  const double a2 = total_area(two);
  st = merge_coplanar(two, 1e-12);
  EXPECT_EQ(st.bridged_holes, 2);
  EXPECT_EQ(st.after, 14);
  EXPECT_NEAR(total_area(two), a2, 1e-12 * a2);
  EXPECT_FALSE(covers(two, 2.1, 1.9));
  EXPECT_FALSE(covers(two, 6.1, 3.4));

  // 3 x 3 cells without the centre and the corner cell (2, 2): the hole and
  // the notch meet at the vertex (2, 2), so the outline is pinched there
  Tris pinched = cut(flat(0, 3, 0, 3, 0, 3, 3), {{1, 2, 1, 2}, {2, 3, 2, 3}});
  const int np = (int) pinched.size() / 9;
  EXPECT_EQ(np, 14);
  st = merge_coplanar(pinched, 1e-12);
  EXPECT_EQ(st.after, np);
  EXPECT_EQ(st.kept_holes, 1);

  // a disc fanned from its centre with 3000 rim vertices: the outline is too
  // long for ear clipping (> 2048 vertices), kept as read; 300 rim vertices merge
  for (int nrim : {3000, 300}) {
    Tris disc;
    std::vector<double> cx(nrim), cy(nrim);    // rim vertices, shared exactly by neighbours
    for (int k = 0; k < nrim; k++) {
      cx[k] = std::cos(2 * M_PI * k / nrim);
      cy[k] = std::sin(2 * M_PI * k / nrim);
    }
    for (int k = 0; k < nrim; k++) {
      const int l = (k + 1) % nrim;
      for (double v : {0.0, 0.0, 0.0, cx[k], cy[k], 0.0, cx[l], cy[l], 0.0}) disc.push_back(v);
    }
    const double ad = total_area(disc);
    const MergeStats sd = merge_coplanar(disc, 1e-12);
    EXPECT_NEAR(total_area(disc), ad, 1e-12 * ad);
    if (nrim > 2048) {
      EXPECT_EQ(sd.after, nrim);
      EXPECT_EQ(sd.kept_holes, 1);
    } else {
      EXPECT_EQ(sd.after, nrim - 2);
    }
  }

  Tris bumpy = flat(0, 3, -1, 1, 0, 12, 8, true, 0.35, 11);
  for (size_t k = 2; k < bumpy.size(); k += 3)
    if (bumpy[k - 2] > 0 && bumpy[k - 2] < 3 && bumpy[k - 1] > -1 && bumpy[k - 1] < 1)
      bumpy[k] = 1e-10 * std::sin(1e3 * bumpy[k - 2] + 7 * bumpy[k - 1]);    // interior z noise
  Tris strict = bumpy;
  EXPECT_GT(merge_coplanar(strict, 1e-13).after, 150);
  EXPECT_EQ(merge_coplanar(bumpy, 1e-9).after, 2);
}

// A cone's strip between two generators is planar, but a binary STL stores
// its vertices as float32: they are off the generator lines by ~1e-8 m, so
// dropping the "collinear" ones changes the area by ~tol x outline, not 1e-9.
// With merge tolerance 1e-6 m the strip (40 rings, 79 triangles) becomes one
// triangle, its area kept to tol x outline; with 1e-12 it stays mostly as read.
TEST(MergeCoplanar, Float32ConeStrip)
{
  const double R = 0.15, D = 0.1, dth = 2 * M_PI / 300;
  const int nc = 40;
  Tris t;
  auto P = [&](int i, double f) {    // f: fraction of the way to the apex
    const double r = R * (1 - f), th = i * dth;
    return std::array<double, 3>{(double) (float) (R + r * std::cos(th)),
                                 (double) (float) (R + r * std::sin(th)), (double) (float) (-D * f)};
  };
  double area = 0.0, perim = 0.0;
  for (int k = 0; k < nc; k++) {
    const auto a = P(0, (double) k / nc), b = P(1, (double) k / nc);
    const auto c = P(0, (double) (k + 1) / nc), d = P(1, (double) (k + 1) / nc);
    const std::array<std::array<double, 3>, 3> tt[2] = {{a, d, c}, {a, b, d}};
    for (int m = 0; m < (k == nc - 1 ? 1 : 2); m++) {
      const auto &tr = k == nc - 1 ? std::array<std::array<double, 3>, 3>{a, b, c} : tt[m];
      for (auto &v : tr) t.insert(t.end(), v.begin(), v.end());
      const double u[3] = {tr[1][0] - tr[0][0], tr[1][1] - tr[0][1], tr[1][2] - tr[0][2]};
      const double w[3] = {tr[2][0] - tr[0][0], tr[2][1] - tr[0][1], tr[2][2] - tr[0][2]};
      area += 0.5 * std::sqrt(std::pow(u[1] * w[2] - u[2] * w[1], 2) +
                              std::pow(u[2] * w[0] - u[0] * w[2], 2) +
                              std::pow(u[0] * w[1] - u[1] * w[0], 2));
    }
  }
  perim = 2 * std::hypot(R, D) + R * dth;
  Tris strict = t, loose = t;
  const auto s1 = merge_coplanar(strict, 1e-12);
  const auto s2 = merge_coplanar(loose, 1e-6);
  double merged_area = 0.0;
  for (size_t k = 0; k < loose.size(); k += 9) {
    const double u[3] = {loose[k + 3] - loose[k], loose[k + 4] - loose[k + 1], loose[k + 5] - loose[k + 2]};
    const double w[3] = {loose[k + 6] - loose[k], loose[k + 7] - loose[k + 1], loose[k + 8] - loose[k + 2]};
    merged_area += 0.5 * std::sqrt(std::pow(u[1] * w[2] - u[2] * w[1], 2) +
                                   std::pow(u[2] * w[0] - u[0] * w[2], 2) +
                                   std::pow(u[0] * w[1] - u[1] * w[0], 2));
  }
  std::printf("[ merge    ] float32 cone strip: %d triangles; tol 1e-12 -> %d, tol 1e-6 -> %d "
              "(area %.9g -> %.9g)\n", s2.before, s1.after, s2.after, area, merged_area);
  EXPECT_GT(s1.after, 20);    // only the few exactly coplanar pieces merge
  EXPECT_LE(s2.after, 3);
  EXPECT_NEAR(merged_area, area, 1e-9 * area + 1e-6 * perim);
}

// exact point-triangle distance (used by the grid's near test) against an
// independent construction: projection inside the triangle, else the
// nearest of the three edges (segments); random triangles incl. slivers
TEST(MeshGrid, PointTriangleDistance)
{
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto seg2 = [](const Vec3<double> &p, const Vec3<double> &a, const Vec3<double> &b) {
    const Vec3<double> ab = b - a;
    double s = dot(p - a, ab) / norm2(ab);
    s = s < 0 ? 0 : (s > 1 ? 1 : s);
    return norm2(p - (a + s * ab));
  };
  double worst = 0.0;
  for (int trial = 0; trial < 200000; trial++) {
    Vec3<double> a = make_vec3(u(rng), u(rng), u(rng)), b = make_vec3(u(rng), u(rng), u(rng)),
                 c = make_vec3(u(rng), u(rng), u(rng));
    if (trial % 4 == 0) c = a + (0.5 + 0.3 * u(rng)) * (b - a) + 1e-4 * make_vec3(u(rng), u(rng), u(rng));
    const Vec3<double> p = make_vec3(2 * u(rng), 2 * u(rng), 2 * u(rng));
    Vec3<double> n = cross(b - a, c - a);
    const double nn = norm2(n);
    if (!(nn > 1e-20)) continue;
    const double h = dot(p - a, n) / nn;
    const Vec3<double> q = p - h * n;    // projection on the plane
    const double w1 = dot(cross(b - a, q - a), n), w2 = dot(cross(c - b, q - b), n),
                 w3 = dot(cross(a - c, q - c), n);
    double ref;
    if (w1 >= 0 && w2 >= 0 && w3 >= 0) ref = h * h * nn;
    else ref = std::fmin(seg2(p, a, b), std::fmin(seg2(p, b, c), seg2(p, c, a)));
    const double got = point_triangle_dist2(p, a, b, c);
    worst = std::fmax(worst, std::fabs(got - ref) / (1.0 + ref));
  }
  EXPECT_LT(worst, 1e-12);
}

// fuzz: plates of 10 x 8 cells (regular or jittered) with 1-6 random
// single-cell holes, no two holes touching each other or the border: every
// region merges with all its holes bridged, the area is kept to 1e-12 and
// no triangle covers a hole's centre
TEST(MergeCoplanar, RandomHolesFuzz)
{
  std::mt19937 rng(17);
  int merged = 0, cases = 0;
  for (int trial = 0; trial < 300; trial++) {
    const int nx = 10, ny = 8;
    const double jit = (trial % 2) ? 0.2 : 0.0;
    const Tris full = flat(0, nx, 0, ny, 0, nx, ny, trial % 3 == 0, jit, (unsigned) trial + 1);
    std::vector<std::pair<int, int>> holes;
    const int want = 1 + (int) (rng() % 6);
    for (int tries = 0; tries < 200 && (int) holes.size() < want; tries++) {
      const int i = 1 + (int) (rng() % (nx - 2)), j = 1 + (int) (rng() % (ny - 2));
      bool ok = true;
      for (auto &h : holes) ok = ok && (std::abs(h.first - i) > 1 || std::abs(h.second - j) > 1);
      if (ok) holes.emplace_back(i, j);
    }
    // cells of the (possibly jittered) grid: triangles of cell (i, j) are 2 (j nx + i) + {0, 1}
    Tris t;
    for (size_t k = 0; k < full.size() / 9; k++) {
      const int cell = (int) k / 2, i = cell % nx, j = cell / nx;
      bool hole = false;
      for (auto &h : holes) hole = hole || (h.first == i && h.second == j);
      if (!hole) t.insert(t.end(), full.begin() + 9 * (long) k, full.begin() + 9 * (long) k + 9);
    }
    const double a0 = total_area(t);
    const MergeStats st = merge_coplanar(t, 1e-12);
    cases++;
    EXPECT_NEAR(total_area(t), a0, 1e-12 * a0) << "trial " << trial;
    if (st.merged_regions != 1) std::printf("trial %d jitter %g holes %zu: kept %d failed %d\n", trial, jit, holes.size(), st.kept_holes, st.kept_failed);
    if (st.merged_regions == 1) {
      merged++;
      EXPECT_EQ(st.bridged_holes, (int) holes.size()) << "trial " << trial;
    }
    // hole centres (regular grid: exact; jittered: the centroid of the cell's first triangle pair)
    for (auto &h : holes) {
      const size_t k = 9 * 2 * (size_t) (h.second * nx + h.first);
      double cx = 0, cy = 0;
      for (int v = 0; v < 6; v++) {
        cx += full[k + 3 * v] / 6.0;
        cy += full[k + 3 * v + 1] / 6.0;
      }
      for (size_t m = 0; m < t.size(); m += 9) {
        const double *a = &t[m], *b = &t[m + 3], *c = &t[m + 6];
        auto o = [](const double *p, const double *q, double px, double py) {
          return (q[0] - p[0]) * (py - p[1]) - (q[1] - p[1]) * (px - p[0]);
        };
        EXPECT_FALSE(o(a, b, cx, cy) > 0 && o(b, c, cx, cy) > 0 && o(c, a, cx, cy) > 0)
            << "trial " << trial << " hole " << h.first << " " << h.second;
      }
    }
  }
  std::printf("[ merge    ] %d of %d plates with holes re-triangulated\n", merged, cases);
  EXPECT_EQ(merged, cases);
}

// Smooth regions (the wall's patch keys): a flat irregular floor is one
// region, also with every third triangle's vertex order reversed (those
// that differ from the seed's, triangle 0, join reversed: odd code); two
// floors apart are two; each face of a box is one;
// a faceted tube of 120 sectors at a patch angle of 20 degrees is cut into
// regions whose every normal is within 20 degrees of the seed's, each region
// connected, 9 to 19 of them (the first spans both ways from its seed).
TEST(MeshRegions, SeedAngleConnectivityAndFlips)
{
  const double c20 = std::cos(20.0 * M_PI / 180.0);
  Tris floor = flat(0, 3, -1, 1, 0, 12, 8, true, 0.35, 11);
  const int nf = (int) floor.size() / 9;
  std::vector<int> r = mesh_regions(floor, 1.0, 1e-12);    // patch angle 0
  for (int t = 0; t < nf; t++) EXPECT_EQ(r[t], 0) << t;
  Tris mixed = floor;
  for (int t = 0; t < nf; t += 3)
    for (int k = 0; k < 3; k++) std::swap(mixed[9 * t + 3 + k], mixed[9 * t + 6 + k]);
  r = mesh_regions(mixed, c20, 1e-12);
  for (int t = 0; t < nf; t++) EXPECT_EQ(r[t], t % 3 == 0 ? 0 : 1) << t;    // seed 0 reversed
  Tris two = floor;
  const Tris far = flat(4, 5, -1, 1, 0, 3, 3);
  two.insert(two.end(), far.begin(), far.end());
  r = mesh_regions(two, c20, 1e-12);
  for (int t = 0; t < (int) two.size() / 9; t++) EXPECT_EQ(r[t], t < nf ? 0 : 2 * nf) << t;

  // box [0,1]^3, two triangles per face, outward
  Tris box;
  const int faces[6][4][3] = {{{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}},
                              {{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}},
                              {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}},
                              {{0, 1, 0}, {0, 1, 1}, {1, 1, 1}, {1, 1, 0}},
                              {{0, 0, 0}, {0, 0, 1}, {0, 1, 1}, {0, 1, 0}},
                              {{1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1}}};
  for (const auto &f : faces)
    for (const int v : {0, 1, 2, 0, 2, 3})
      for (int d = 0; d < 3; d++) box.push_back(f[v][d]);
  r = mesh_regions(box, std::cos(80.0 * M_PI / 180.0), 1e-12);
  for (int t = 0; t < 12; t++) EXPECT_EQ(r[t], 2 * (t - t % 2)) << t;

  // tube: 120 sectors, 4 rings
  Tris tube;
  const int ns = 120, nr = 4;
  auto P = [&](int s, int q) -> std::array<double, 3> {
    return {std::cos(2 * M_PI * s / ns), std::sin(2 * M_PI * s / ns), 0.1 * q};
  };
  for (int s = 0; s < ns; s++)
    for (int q = 0; q < nr; q++)
      for (const auto &p : {P(s, q), P(s + 1, q), P(s + 1, q + 1), P(s, q), P(s + 1, q + 1), P(s, q + 1)})
        tube.insert(tube.end(), p.begin(), p.end());
  const int nt = (int) tube.size() / 9;
  r = mesh_regions(tube, c20, 1e-9);
  auto normal = [&](int t) {
    const double *p = tube.data() + 9 * t;
    const double e1[3] = {p[3] - p[0], p[4] - p[1], p[5] - p[2]};
    const double e2[3] = {p[6] - p[0], p[7] - p[1], p[8] - p[2]};
    std::array<double, 3> n = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                               e1[0] * e2[1] - e1[1] * e2[0]};
    const double l = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (double &x : n) x /= l;
    return n;
  };
  std::set<int> seeds;
  for (int t = 0; t < nt; t++) {
    const int s = r[t] >> 1;
    seeds.insert(s);
    EXPECT_EQ(r[t] & 1, 0) << t;
    EXPECT_EQ(r[s], 2 * s) << "seed of " << t;
    const auto a = normal(t), b = normal(s);
    EXPECT_GE(a[0] * b[0] + a[1] * b[1] + a[2] * b[2], c20 - 1e-12) << t;
  }
  EXPECT_GE((int) seeds.size(), 9);
  EXPECT_LE((int) seeds.size(), 19);
  // connected: each region's sectors form one run around the tube
  for (const int s : seeds) {
    std::set<int> sectors;
    for (int t = 0; t < nt; t++)
      if (r[t] >> 1 == s) sectors.insert(t / (2 * nr));
    int runs = 0;
    for (const int k : sectors) runs += sectors.count((k + ns - 1) % ns) ? 0 : 1;
    EXPECT_EQ(runs, 1) << "region of seed " << s;
  }
}

// The wall keeps its triangles in spatial order (WallMesh::load,
// spatial_order): a mesh read in shuffled order is stored cell by cell (cells
// of twice the median edge, by the lowest corner of each triangle's box, x
// fastest), the order as read within a cell; row / tri_of_row map each
// stored triangle to its place in the file and back, and each keeps the
// smooth region (the patch key) found in the file's order. A bowl of 40 x 40
// cells, with a patch angle small enough to cut it into several regions.
TEST(WallMeshOrder, ShuffledFileStoredByCell)
{
  const Tris ordered = bowl(0, 1, 0, 1, 0, 2.0, 40);
  const int n = (int) ordered.size() / 9;
  std::vector<int> perm(n);
  for (int t = 0; t < n; t++) perm[t] = t;
  std::mt19937 rng(7);
  std::shuffle(perm.begin(), perm.end(), rng);
  Tris shuffled(ordered.size());
  for (int t = 0; t < n; t++)
    for (int k = 0; k < 9; k++) shuffled[9 * t + k] = ordered[9 * perm[t] + k];
  const std::string path = tmpdir() + "/shuffled_bowl.stl";
  write_binary(path, shuffled);
  const Tris as_read = read_stl(path, StlTransform()).tri;
  const double cosmax = std::cos(5.0 * M_PI / 180.0);
  WallMesh m;
  m.load(path, StlTransform(), -1.0, 5.0);    // merge no, patch angle 5 degrees
  ASSERT_EQ(m.ntri(), n);
  const std::vector<int> file_regions = mesh_regions(as_read, cosmax, 1e-9 * m.diag);
  std::set<int> keys(file_regions.begin(), file_regions.end());
  EXPECT_GE(keys.size(), 4u);

  // the cell of each stored triangle's lowest corner
  double lo[3] = {1e300, 1e300, 1e300};
  for (size_t k = 0; k < as_read.size(); k++) lo[k % 3] = std::min(lo[k % 3], as_read[k]);
  const double h = 2.0 * m.median_edge();
  auto cell = [&](int t) {
    std::array<long, 3> c;
    for (int d = 0; d < 3; d++) {
      const double *p = &m.mesh.tri[9 * t + d];
      c[2 - d] = (long) std::floor((std::min(p[0], std::min(p[3], p[6])) - lo[d]) / h);
    }
    return c;    // z, y, x: compared as a tuple, x fastest
  };
  std::vector<int> seen(n, 0);
  for (int t = 0; t < n; t++) {
    const int r = m.row[t];
    ASSERT_GE(r, 0);
    ASSERT_LT(r, n);
    seen[r]++;
    EXPECT_EQ(m.tri_of_row[r], t);
    for (int k = 0; k < 9; k++) ASSERT_EQ(m.mesh.tri[9 * t + k], as_read[9 * r + k]) << t;
    EXPECT_EQ(m.regions[t], file_regions[r]) << t;
    if (t > 0) {
      EXPECT_LE(cell(t - 1), cell(t)) << t;
      if (cell(t - 1) == cell(t)) EXPECT_LT(m.row[t - 1], r) << t;
    }
  }
  for (int r = 0; r < n; r++) EXPECT_EQ(seen[r], 1) << r;
  // the stored order is local: consecutive triangles lie within a few cells
  // (the file's order jumps across the bowl)
  auto gap = [&](const Tris &t, int a) {
    double s = 0.0;
    for (int d = 0; d < 3; d++) s += std::fabs(t[9 * a + d] - t[9 * (a + 1) + d]);
    return s;
  };
  double stored = 0.0, file = 0.0;
  for (int t = 0; t + 1 < n; t++) stored += gap(m.mesh.tri, t), file += gap(as_read, t);
  std::printf("[ stl      ] mean step between consecutive triangles: stored %.4g, file %.4g "
              "(cell %.4g)\n", stored / (n - 1), file / (n - 1), h);
  EXPECT_LT(stored / (n - 1), 0.1 * file / (n - 1));
}
