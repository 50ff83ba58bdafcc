// POLYDEM geometry-kernel benchmark: ns per pair for GJK alone and for the
// full overlap (V, centroid, S, M) of dodecahedron pairs and 42-point
// cylinder pairs (D = 8 mm, L = 5.3 mm, 20 points per rim) in random
// orientations at overlaps of 0.1-1 % of the particle volume.
// Results: bench/RESULTS.md, section "Geometry kernels".
#include "polydem_gjk.h"
#include "polydem_overlap.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

using namespace polydem;

namespace {

// A convex shape from its vertices: face planes by brute force (fine for the
// few dozen vertices here), centred on the vertex mean (centroid for these
// symmetric shapes).
struct Shape {
  std::vector<double> verts, planes;
  ShapeView<double> view;
  explicit Shape(std::vector<Vec3<double>> p)
  {
    Vec3<double> c = make_vec3(0.0, 0.0, 0.0);
    for (auto &v : p) c += v;
    c = (1.0 / p.size()) * c;
    double rad = 0;
    for (auto &v : p) {
      v -= c;
      rad = std::max(rad, norm(v));
    }
    const int n = (int) p.size();
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j)
        for (int k = j + 1; k < n; ++k) {
          Vec3<double> nr = cross(p[j] - p[i], p[k] - p[i]);
          if (norm(nr) < 1e-9 * rad * rad) continue;
          nr = (1.0 / norm(nr)) * nr;
          double d = dot(nr, p[i]);
          int pos = 0, neg = 0;
          for (auto &v : p) {
            double s = dot(nr, v) - d;
            pos += s > 1e-9 * rad;
            neg += s < -1e-9 * rad;
          }
          if (pos && neg) continue;
          if (pos) {
            nr = -nr;
            d = -d;
          }
          bool dup = false;
          for (size_t f = 0; f < planes.size(); f += 4)
            dup = dup || (std::fabs(planes[f] - nr.x) + std::fabs(planes[f + 1] - nr.y) +
                              std::fabs(planes[f + 2] - nr.z) <
                          1e-9);
          if (dup) continue;
          planes.insert(planes.end(), {nr.x, nr.y, nr.z, d});
        }
    for (auto &v : p) verts.insert(verts.end(), {v.x, v.y, v.z});
    view.nverts = n;
    view.nfaces = (int) planes.size() / 4;
    view.nedges = 0;
    view.verts = verts.data();
    view.planes = planes.data();
    view.face_start = nullptr;
    view.face_verts = nullptr;
    view.edges = nullptr;
    view.radius = rad;
    view.volume = 0;
  }
};

Shape dodecahedron()
{
  const double phi = (1 + std::sqrt(5.0)) / 2, s = 1e-3;    // circumradius sqrt(3) mm
  std::vector<Vec3<double>> p;
  for (int i = 0; i < 8; ++i)
    p.push_back(make_vec3((i & 1 ? 1 : -1) * s, (i & 2 ? 1 : -1) * s, (i & 4 ? 1 : -1) * s));
  for (int i = 0; i < 4; ++i) {
    const double a = (i & 1 ? 1 : -1) * s / phi, b = (i & 2 ? 1 : -1) * s * phi;
    p.push_back(make_vec3(0.0, a, b));
    p.push_back(make_vec3(a, b, 0.0));
    p.push_back(make_vec3(b, 0.0, a));
  }
  return Shape(p);
}

Shape cylinder()    // 42 points: 2 x 20 on the rims + the 2 cap centres
{
  const double D = 8e-3, L = 5.3e-3;
  std::vector<Vec3<double>> p;
  for (int k = 0; k < 20; ++k) {
    const double t = 2 * M_PI * k / 20;
    p.push_back(make_vec3(0.5 * D * std::cos(t), 0.5 * D * std::sin(t), -0.5 * L));
    p.push_back(make_vec3(0.5 * D * std::cos(t), 0.5 * D * std::sin(t), 0.5 * L));
  }
  p.push_back(make_vec3(0.0, 0.0, -0.5 * L));
  p.push_back(make_vec3(0.0, 0.0, 0.5 * L));
  return Shape(p);
}

struct PairSet {
  Shape shape;
  std::vector<PosedShape<double>> a, b;
  double vp = 0;
};

Quat<double> rquat(std::mt19937_64 &rng)
{
  std::normal_distribution<double> g(0, 1);
  return qnormalize(make_quat(g(rng), g(rng), g(rng), g(rng)));
}

// pairs at overlap V / V_particle uniform in [1e-3, 1e-2], placed by bisection
// on the centre distance along a random direction
PairSet *make_pairs(Shape s, int n)
{
  auto *ps = new PairSet{std::move(s), {}, {}, 0};
  static OverlapWorkspace<double> ws;
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(0, 1);
  std::normal_distribution<double> g(0, 1);
  Pose<double> p0;
  p0.x = make_vec3(0.0, 0.0, 0.0);
  p0.q = make_quat(1.0, 0.0, 0.0, 0.0);
  p0.s = 1.0;
  const PosedShape<double> self = make_posed(ps->shape.view, p0);
  ps->vp = polyhedron_overlap(self, self, ws).volume;
  while ((int) ps->a.size() < n) {
    Pose<double> pa, pb;
    pa.x = make_vec3(0.0, 0.0, 0.0);
    pa.q = rquat(rng);
    pa.s = 1.0;
    pb = pa;
    pb.q = rquat(rng);
    Vec3<double> d = make_vec3(g(rng), g(rng), g(rng));
    d = (1.0 / norm(d)) * d;
    const double target = ps->vp * (1e-3 + 9e-3 * u(rng));
    double lo = 0, hi = 2.2 * ps->shape.view.radius;
    for (int it = 0; it < 60; ++it) {
      const double mid = 0.5 * (lo + hi);
      pb.x = mid * d;
      const double v =
          polyhedron_overlap(make_posed(ps->shape.view, pa), make_posed(ps->shape.view, pb), ws)
              .volume;
      (v > target ? lo : hi) = mid;
    }
    pb.x = lo * d;
    ps->a.push_back(make_posed(ps->shape.view, pa));
    ps->b.push_back(make_posed(ps->shape.view, pb));
  }
  // views must point at the copy inside ps
  for (size_t i = 0; i < ps->a.size(); ++i) ps->a[i].view = ps->b[i].view = &ps->shape.view;
  return ps;
}

PairSet &dodeca_pairs()
{
  static PairSet *p = make_pairs(dodecahedron(), 512);
  return *p;
}
PairSet &cyl_pairs()
{
  static PairSet *p = make_pairs(cylinder(), 512);
  return *p;
}

void gjk_only(benchmark::State &st, PairSet &ps)
{
  size_t i = 0, n = ps.a.size();
  for (auto _ : st) {
    auto r = gjk_intersect(ps.a[i], ps.b[i]);
    benchmark::DoNotOptimize(r);
    if (++i == n) i = 0;
  }
  st.counters["faces"] = ps.shape.view.nfaces;
}

template <int MF> void overlap_full(benchmark::State &st, PairSet &ps)
{
  static OverlapWorkspace<double, MF> ws;
  size_t i = 0, n = ps.a.size();
  double vsum = 0;
  int bad = 0;
  for (auto _ : st) {
    auto r = polyhedron_overlap(ps.a[i], ps.b[i], ws);
    benchmark::DoNotOptimize(r);
    vsum += r.volume;
    bad += r.status != STATUS_OK;
    if (++i == n) i = 0;
  }
  st.counters["V/Vp"] = vsum / st.iterations() / ps.vp;
  st.counters["not_ok"] = bad;
  st.counters["ws_bytes"] = sizeof(ws);
}

template <int MF> void gjk_then_overlap(benchmark::State &st, PairSet &ps)
{
  static OverlapWorkspace<double, MF> ws;
  size_t i = 0, n = ps.a.size();
  for (auto _ : st) {
    auto g = gjk_intersect(ps.a[i], ps.b[i]);
    if (g.status == STATUS_OK) {
      auto r = polyhedron_overlap(ps.a[i], ps.b[i], ws);
      benchmark::DoNotOptimize(r);
    }
    if (++i == n) i = 0;
  }
}

}    // namespace

void overlap_ws12(benchmark::State &st, PairSet &ps)
{
  overlap_full<12>(st, ps);
}
void overlap_ws22(benchmark::State &st, PairSet &ps)
{
  overlap_full<22>(st, ps);
}
void overlap_wsmax(benchmark::State &st, PairSet &ps)
{
  overlap_full<MAX_TEMPLATE_FACES>(st, ps);
}
void gjk_overlap_ws12(benchmark::State &st, PairSet &ps)
{
  gjk_then_overlap<12>(st, ps);
}
void gjk_overlap_ws22(benchmark::State &st, PairSet &ps)
{
  gjk_then_overlap<22>(st, ps);
}

BENCHMARK_CAPTURE(gjk_only, dodecahedron, dodeca_pairs());
BENCHMARK_CAPTURE(overlap_ws12, dodecahedron, dodeca_pairs());
BENCHMARK_CAPTURE(overlap_wsmax, dodecahedron, dodeca_pairs());
BENCHMARK_CAPTURE(gjk_overlap_ws12, dodecahedron, dodeca_pairs());
BENCHMARK_CAPTURE(gjk_only, cylinder42, cyl_pairs());
BENCHMARK_CAPTURE(overlap_ws22, cylinder42, cyl_pairs());
BENCHMARK_CAPTURE(overlap_wsmax, cylinder42, cyl_pairs());
BENCHMARK_CAPTURE(gjk_overlap_ws22, cylinder42, cyl_pairs());

BENCHMARK_MAIN();
