// POLYDEM geometry-kernel benchmark: ns per pair for GJK alone and for the
// full overlap (V, centroid, S, M) of dodecahedron pairs and 42-point
// cylinder pairs (D = 8 mm, L = 5.3 mm, 20 points per rim) in random
// orientations at overlaps of 0.1-1 % of the particle volume; ns per
// polyhedron-triangle clip (fix wall/mesh) for triangles near a particle's
// lowest point; ns per polyhedron-sphere and polyhedron-ellipsoid overlap
// (the same volume as the polyhedron) at the same overlaps; ns per pair of
// composite grains (chains of 1, 2, 4 separate dodecahedra) in contact:
// every pair of parts by bounding spheres, GJK and overlap, as the pipeline's
// composite_pair_contact does before the law.
// Results: bench/RESULTS.md, section "Geometry kernels".
#include "polydem_clip.h"
#include "polydem_ellipsoid_overlap.h"
#include "polydem_gjk.h"
#include "polydem_overlap.h"
#include "polydem_shape_template.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <random>
#include <string>
#include <vector>

using namespace polydem;

namespace {

// A convex shape from its vertices, built as the pair style builds it
// (PolyShapeTemplate: hull, merged faces, principal frame, dual
// triangulation). `seeded = false` hides the dual triangulation, so the
// overlap kernel starts from a bounding tetrahedron (the pre-seed path).
struct Shape {
  std::shared_ptr<PolyShapeTemplate> tmpl;
  ShapeView<double> view;
  Shape(const std::vector<Vec3<double>> &p, bool seeded)
  {
    std::vector<PolyShapeTemplate::Point> pts;
    for (auto &v : p) pts.push_back({v.x, v.y, v.z});
    tmpl = std::make_shared<PolyShapeTemplate>(PolyShapeTemplate::from_points(pts));
    view = tmpl->view();
    if (!seeded) view.dual = nullptr;
  }
};

Shape dodecahedron(bool seeded)
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
  return Shape(p, seeded);
}

Shape cylinder(bool seeded)    // 42 points: 2 x 20 on the rims + the 2 cap centres
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
  return Shape(p, seeded);
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

// the 512 pairs of a shape, made on first use and shared by the benchmarks that
// take them; seeded = false: the same pairs (same random stream) without the seed
template <Shape (*shape)(bool), bool seeded> PairSet &pairs()
{
  static PairSet *p = make_pairs(shape(seeded), 512);
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

// a polyhedron against an ellipsoid of the polyhedron's volume, semi-axes in
// the ratios `ratio`, at overlap V / V_particle uniform in [1e-3, 1e-2]
struct MixedSet {
  Shape shape;
  std::vector<PosedShape<double>> a;
  std::vector<EllipsoidPose<double>> b;
  double vp = 0;
};

MixedSet *make_mixed(Shape s, Vec3<double> ratio, int n)
{
  auto *ms = new MixedSet{std::move(s), {}, {}, 0};
  ms->vp = ms->shape.tmpl->volume();
  const double k = std::cbrt(ms->vp / (4.0 / 3.0 * M_PI * ratio.x * ratio.y * ratio.z));
  const Vec3<double> axes = k * ratio;
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<double> u(0, 1);
  std::normal_distribution<double> g(0, 1);
  while ((int) ms->a.size() < n) {
    Pose<double> pa;
    pa.x = make_vec3(0.0, 0.0, 0.0);
    pa.q = rquat(rng);
    pa.s = 1.0;
    EllipsoidPose<double> e;
    e.q = rquat(rng);
    e.axes = axes;
    Vec3<double> d = make_vec3(g(rng), g(rng), g(rng));
    d = (1.0 / norm(d)) * d;
    const double target = ms->vp * (1e-3 + 9e-3 * u(rng));
    double lo = 0, hi = 1.1 * (ms->shape.view.radius + std::fmax(axes.x, std::fmax(axes.y, axes.z)));
    for (int it = 0; it < 60; ++it) {
      const double mid = 0.5 * (lo + hi);
      e.x = mid * d;
      const double v = polyhedron_ellipsoid_overlap(make_posed(ms->shape.view, pa), e).volume;
      (v > target ? lo : hi) = mid;
    }
    e.x = lo * d;
    ms->a.push_back(make_posed(ms->shape.view, pa));
    ms->b.push_back(e);
  }
  for (auto &a : ms->a) a.view = &ms->shape.view;
  return ms;
}

void ellipsoid_overlap(benchmark::State &st, MixedSet *ms)
{
  size_t i = 0, n = ms->a.size();
  double vsum = 0;
  int bad = 0;
  for (auto _ : st) {
    auto r = polyhedron_ellipsoid_overlap(ms->a[i], ms->b[i]);
    benchmark::DoNotOptimize(r);
    vsum += r.volume;
    bad += r.status != STATUS_OK;
    if (++i == n) i = 0;
  }
  st.counters["V/Vp"] = vsum / st.iterations() / ms->vp;
  st.counters["not_ok"] = bad;
}

}    // namespace

BENCHMARK_CAPTURE(ellipsoid_overlap, dodecahedron_sphere,
                  make_mixed(dodecahedron(true), make_vec3(1.0, 1.0, 1.0), 512));
BENCHMARK_CAPTURE(ellipsoid_overlap, dodecahedron_ellipsoid,
                  make_mixed(dodecahedron(true), make_vec3(1.4, 1.0, 0.7), 512));
BENCHMARK_CAPTURE(ellipsoid_overlap, cylinder42_sphere,
                  make_mixed(cylinder(true), make_vec3(1.0, 1.0, 1.0), 512));

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

// Particle-triangle cases as on a finely meshed wall: random orientation,
// random wall normal n, plane 0-5 % of the radius above the particle's lowest
// point, an equilateral triangle of circumradius `size` x radius, randomly
// turned, centred within `size` x radius of that point's projection.
struct TriSet {
  Shape shape;
  std::vector<PosedShape<double>> a;
  std::vector<Triangle<double>> t;
};

TriSet *make_tris(Shape s, double size, int n)
{
  auto *ts = new TriSet{std::move(s), {}, {}};
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<double> u(0, 1);
  std::normal_distribution<double> g(0, 1);
  const double r = ts->shape.view.radius;
  for (int k = 0; k < n; ++k) {
    Pose<double> p;
    p.x = make_vec3(0.0, 0.0, 0.0);
    p.q = rquat(rng);
    p.s = 1.0;
    const PosedShape<double> a = make_posed(ts->shape.view, p);
    Vec3<double> nw = make_vec3(g(rng), g(rng), g(rng));
    nw = (1.0 / norm(nw)) * nw;
    const Vec3<double> low = support_point(a, -1.0 * nw);
    const Vec3<double> o = low + (0.05 * r * u(rng)) * nw;
    Vec3<double> e1 = cross(nw, make_vec3(g(rng), g(rng), g(rng)));
    e1 = (1.0 / norm(e1)) * e1;
    const Vec3<double> e2 = cross(nw, e1);
    const double ph = 2 * M_PI * u(rng), R = size * r;
    const Vec3<double> c = o + (R * (2 * u(rng) - 1)) * e1 + (R * (2 * u(rng) - 1)) * e2;
    Triangle<double> t;
    for (int v = 0; v < 3; ++v) {
      const double ang = ph + 2 * M_PI * v / 3;
      t.v[v] = c + (R * std::cos(ang)) * e1 + (R * std::sin(ang)) * e2;    // CCW about nw
    }
    ts->a.push_back(a);
    ts->t.push_back(t);
  }
  for (auto &a : ts->a) a.view = &ts->shape.view;
  return ts;
}

void clip_triangle(benchmark::State &st, TriSet *ts)
{
  static ClipWorkspace<double> ws;
  size_t i = 0, n = ts->a.size();
  int hit = 0;
  for (auto _ : st) {
    auto r = polyhedron_triangle(ts->a[i], ts->t[i], ws);
    benchmark::DoNotOptimize(r);
    hit += r.volume > 0;
    if (++i == n) i = 0;
  }
  st.counters["with_volume"] = double(hit) / st.iterations();
}

BENCHMARK_CAPTURE(clip_triangle, dodecahedron_small_tri, make_tris(dodecahedron(true), 0.1, 512));
BENCHMARK_CAPTURE(clip_triangle, dodecahedron_large_tri, make_tris(dodecahedron(true), 1.0, 512));
BENCHMARK_CAPTURE(clip_triangle, cylinder42_small_tri, make_tris(cylinder(true), 0.1, 512));
BENCHMARK_CAPTURE(clip_triangle, cylinder42_large_tri, make_tris(cylinder(true), 1.0, 512));

BENCHMARK_CAPTURE(gjk_only, dodecahedron, pairs<dodecahedron, true>());
BENCHMARK_CAPTURE(overlap_ws12, dodecahedron, pairs<dodecahedron, true>());
BENCHMARK_CAPTURE(overlap_wsmax, dodecahedron, pairs<dodecahedron, true>());
BENCHMARK_CAPTURE(gjk_overlap_ws12, dodecahedron, pairs<dodecahedron, true>());
BENCHMARK_CAPTURE(overlap_ws12, dodecahedron_tetra_start, pairs<dodecahedron, false>());
BENCHMARK_CAPTURE(gjk_only, cylinder42, pairs<cylinder, true>());
BENCHMARK_CAPTURE(overlap_ws22, cylinder42, pairs<cylinder, true>());
BENCHMARK_CAPTURE(overlap_wsmax, cylinder42, pairs<cylinder, true>());
BENCHMARK_CAPTURE(gjk_overlap_ws22, cylinder42, pairs<cylinder, true>());
BENCHMARK_CAPTURE(overlap_ws22, cylinder42_tetra_start, pairs<cylinder, false>());

// Fixed work for instruction counts (repeatable where wall time is not):
//   valgrind --tool=callgrind --toggle-collect='*fixed_loop*' bench_kernels --fixed 4 [SHAPE]
// runs GJK, then the overlap, over each pair set (or SHAPE: dodecahedron or
// cylinder42 alone) `reps` times; instructions
// per call = the inclusive count of gjk_intersect / polyhedron_overlap
// divided by 512 x reps.
__attribute__((noinline)) double fixed_loop(PairSet &ps, int reps)
{
  static OverlapWorkspace<double, 22> ws;
  double sum = 0;
  for (int r = 0; r < reps; ++r)
    for (size_t i = 0; i < ps.a.size(); ++i) sum += gjk_intersect(ps.a[i], ps.b[i]).iterations;
  for (int r = 0; r < reps; ++r)
    for (size_t i = 0; i < ps.a.size(); ++i) sum += polyhedron_overlap(ps.a[i], ps.b[i], ws).volume;
  return sum;
}

int main(int argc, char **argv)
{
  if ((argc == 3 || argc == 4) && std::string(argv[1]) == "--fixed") {
    const int reps = std::atoi(argv[2]);
    const std::string only = argc == 4 ? argv[3] : "";
    if (only != "cylinder42")
      std::printf("dodecahedron %.17g\n", fixed_loop(pairs<dodecahedron, true>(), reps));
    if (only != "dodecahedron")
      std::printf("cylinder42 %.17g\n", fixed_loop(pairs<cylinder, true>(), reps));
    return 0;
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

namespace {

// composite grains: a chain of P dodecahedra 3.3 mm apart along x (their
// half-width along x is 1.62 mm: disjoint parts, so that the contact parts
// are the dodecahedra themselves), pairs in random orientations and
// directions at a total overlap of 0.1-1 % of one part's volume
struct CompositeSet {
  std::shared_ptr<PolyShapeTemplate> tmpl;
  ShapeView<double> view;
  std::vector<PosedShape<double>> a, b;
  double vp = 0;
  int parts_in_reach = 0;    // part pairs within reach, over all pairs
};

template <int MF>
double composite_overlap(const PosedShape<double> &A, const PosedShape<double> &B,
                         OverlapWorkspace<double, MF> &ws, int *reach = nullptr)
{
  double v = 0;
  for (int ka = 0; ka < A.view->nparts; ++ka) {
    const auto a = posed_part(A, ka);
    for (int kb = 0; kb < B.view->nparts; ++kb) {
      const auto b = posed_part(B, kb);
      const double r = a.s * a.view->radius + b.s * b.view->radius;
      if (norm2(a.x - b.x) >= r * r) continue;
      if (reach) ++*reach;
      if (gjk_intersect(a, b).status == STATUS_SEPARATED) continue;
      const auto o = polyhedron_overlap(a, b, ws);
      if (o.status == STATUS_OK) v += o.volume;
    }
  }
  return v;
}

CompositeSet *make_composites(int P, int n)
{
  auto *cs = new CompositeSet;
  auto d = std::make_shared<PolyShapeTemplate>(*dodecahedron(true).tmpl);
  std::vector<PolyShapeTemplate::InputPart> parts;
  for (int k = 0; k < P; ++k) {
    PolyShapeTemplate::InputPart ip;
    ip.shape = d;
    ip.id = "d";
    ip.x = {3.3e-3 * k, 0.0, 0.0};
    ip.q = make_quat(1.0, 0.0, 0.0, 0.0);
    parts.push_back(ip);
  }
  cs->tmpl = std::make_shared<PolyShapeTemplate>(PolyShapeTemplate::composite(parts, "chain"));
  cs->view = cs->tmpl->view();
  cs->vp = d->volume();
  static OverlapWorkspace<double, 12> ws;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  std::normal_distribution<double> g(0, 1);
  while ((int) cs->a.size() < n) {
    Pose<double> pa, pb;
    pa.x = make_vec3(0.0, 0.0, 0.0);
    pa.q = rquat(rng);
    pa.s = pb.s = 1.0;
    pb.q = rquat(rng);
    Vec3<double> dir = make_vec3(g(rng), g(rng), g(rng));
    dir = (1.0 / norm(dir)) * dir;
    const double target = cs->vp * (1e-3 + 9e-3 * u(rng));
    double lo = 0, hi = 2.2 * cs->view.radius;
    for (int it = 0; it < 60; ++it) {
      const double mid = 0.5 * (lo + hi);
      pb.x = mid * dir;
      const double v = composite_overlap(make_posed(cs->view, pa), make_posed(cs->view, pb), ws);
      (v > target ? lo : hi) = mid;
    }
    pb.x = lo * dir;
    cs->a.push_back(make_posed(cs->view, pa));
    cs->b.push_back(make_posed(cs->view, pb));
  }
  for (auto &a : cs->a) a.view = &cs->view;
  for (auto &b : cs->b) b.view = &cs->view;
  for (int i = 0; i < n; ++i) composite_overlap(cs->a[i], cs->b[i], ws, &cs->parts_in_reach);
  return cs;
}

void composite_pair(benchmark::State &st, CompositeSet *cs)
{
  static OverlapWorkspace<double, 12> ws;
  size_t i = 0, n = cs->a.size();
  double vsum = 0;
  for (auto _ : st) {
    const double v = composite_overlap(cs->a[i], cs->b[i], ws);
    benchmark::DoNotOptimize(v);
    vsum += v;
    if (++i == n) i = 0;
  }
  st.counters["V/Vpart"] = vsum / st.iterations() / cs->vp;
  st.counters["part_pairs_in_reach"] = (double) cs->parts_in_reach / n;
}

}    // namespace

BENCHMARK_CAPTURE(composite_pair, chain1, make_composites(1, 512));
BENCHMARK_CAPTURE(composite_pair, chain2, make_composites(2, 512));
BENCHMARK_CAPTURE(composite_pair, chain4, make_composites(4, 512));
