// POLYDEM kernel tests: random fuzzing of GJK, overlap and clipping over
// extreme scales (1e-6 .. 1e3) and positions; run under ASan + UBSan when
// POLYDEM_SANITIZE=ON. Checks: no NaN/Inf, valid status, 0 <= V <= V_particle.
// POLYDEM_FUZZ_PAIRS overrides the number of pairs (default 1e6).
#include "pair_gen.h"

#include "polydem_clip.h"
#include "polydem_gjk.h"
#include "polydem_overlap.h"

#include <gtest/gtest.h>

#include <cstdio>

using namespace polydem;
using namespace polydem_test;

namespace {

template <typename T> bool finite(T v)
{
  return std::isfinite((double) v);
}
template <typename T> bool finite(const Vec3<T> &v)
{
  return finite(v.x) && finite(v.y) && finite(v.z);
}

ShapePool &pool()
{
  static ShapePool p(60, 4242);
  return p;
}

long fuzz_pairs()
{
  const char *e = std::getenv("POLYDEM_FUZZ_PAIRS");
  return e ? std::atol(e) : 1000000L;
}

template <typename T> struct Counts {
  long n = 0, ok = 0, sep = 0, other = 0, gjk_hit = 0;
};

template <typename T> void fuzz_overlap(long n, unsigned seed, Counts<T> &c)
{
  static OverlapWorkspace<T> ws;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::uniform_int_distribution<int> pick(0, (int) pool().data.size() - 1);
  for (long i = 0; i < n; ++i) {
    const double sig = std::pow(10.0, -6.0 + 9.0 * u(rng));    // pair length scale
    const double pos = std::pow(10.0, -6.0 + 9.0 * u(rng));    // distance from the origin
    const int a = pick(rng), b = pick(rng);
    const double sa = sig * (0.3 + u(rng)), sb = sig * (0.3 + 3 * u(rng));
    Pose<double> pa = make_pose(pos * random_unit(rng), random_quat(rng), sa);
    const double rr = sa * pool().data[a].radius + sb * pool().data[b].radius;
    Pose<double> pb =
        make_pose(pa.x + (1.05 * rr * u(rng)) * random_unit(rng), random_quat(rng), sb);
    if (i % 97 == 0) pb = pa;                                          // coincident
    if (i % 89 == 0) pb.x = pa.x + make_vec3(rr * 1e-12, 0.0, 0.0);    // nearly coincident
    Pose<T> fa, fb;
    if constexpr (std::is_same<T, float>::value) {
      fa = to_float(pa);
      fb = to_float(pb);
    } else {
      fa = pa;
      fb = pb;
    }
    const ShapeView<T> &va = std::is_same<T, float>::value
                                 ? (const ShapeView<T> &) pool().f[a]->view
                                 : (const ShapeView<T> &) pool().d[a]->view;
    const ShapeView<T> &vb = std::is_same<T, float>::value
                                 ? (const ShapeView<T> &) pool().f[b]->view
                                 : (const ShapeView<T> &) pool().d[b]->view;
    const PosedShape<T> A = make_posed(va, fa), B = make_posed(vb, fb);
    const GjkResult<T> g = gjk_intersect(A, B);
    ASSERT_TRUE(finite(g.distance));
    if (g.status == STATUS_OK) ++c.gjk_hit;
    if (g.status == STATUS_SEPARATED && (i % 7 != 0)) continue;    // also run some separated ones
    const OverlapResult<T> r = polyhedron_overlap(A, B, ws);
    ++c.n;
    ASSERT_TRUE(finite(r.volume) && finite(r.centroid) && finite(r.S_A) && finite(r.M_A) &&
                finite(r.M_B) && finite(r.area) && finite(r.depth))
        << "pair " << i;
    ASSERT_GE(r.volume, T(0));
    const double vmin = std::min(std::pow(pa.s, 3) * pool().data[a].volume,
                                 std::pow(pb.s, 3) * pool().data[b].volume);
    // allowance: coordinates carry eps * |x| absolute error
    const double slack = 1e-3 * vmin + 1e3 * (double) Eps<T>::value * (pos + rr) / rr * vmin;
    EXPECT_LE((double) r.volume, vmin + slack) << "pair " << i;
    if (r.status == STATUS_OK)
      ++c.ok;
    else if (r.status == STATUS_SEPARATED)
      ++c.sep;
    else
      ++c.other;
  }
}

}    // namespace

// the share of the pairs that may end in overflow, degeneracy or no
// convergence: 1 in 10,000 (double), 1 in 1,000 (float)
template <typename T> void fuzz_overlap_case(const char *name, unsigned seed, long allowed_per)
{
  Counts<T> c;
  fuzz_overlap<T>(fuzz_pairs() / 2, seed, c);
  std::printf("[ fuzz %s ] %ld pairs run through overlap: ok %ld separated %ld "
              "overflow/degenerate/no-convergence %ld (GJK hits %ld)\n",
              name, c.n, c.ok, c.sep, c.other, c.gjk_hit);
  EXPECT_LE(c.other, c.n / allowed_per);
}

TEST(KernelFuzz, OverlapDouble)
{
  fuzz_overlap_case<double>("double", 1, 10000);
}

TEST(KernelFuzz, OverlapFloat)
{
  fuzz_overlap_case<float>("float", 2, 1000);
}

TEST(KernelFuzz, Clip)
{
  static ClipWorkspace<double> ws;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  std::uniform_int_distribution<int> pick(0, (int) pool().data.size() - 1);
  long other = 0;
  const long n = fuzz_pairs() / 10;
  for (long i = 0; i < n; ++i) {
    const double sig = std::pow(10.0, -6.0 + 9.0 * u(rng));
    const int a = pick(rng);
    Pose<double> p = make_pose(sig * random_unit(rng), random_quat(rng), sig);
    Triangle<double> t;
    for (int k = 0; k < 3; ++k) t.v[k] = p.x + (2 * sig * u(rng)) * random_unit(rng);
    if (i % 50 == 0) t.v[2] = t.v[1];    // degenerate triangle
    const ClipResult<double> r = polyhedron_triangle(make_posed(pool().d[a]->view, p), t, ws);
    ASSERT_TRUE(finite(r.volume) && finite(r.area) && finite(r.S) && finite(r.M) &&
                finite(r.vcentroid) && finite(r.acentroid));
    ASSERT_GE(r.volume, 0.0);
    ASSERT_LE(r.volume, std::pow(sig, 3) * pool().data[a].volume * (1 + 1e-6));
    if (r.status != STATUS_OK && r.status != STATUS_SEPARATED && i % 50 != 0) ++other;
  }
  std::printf("[ fuzz clip ] %ld triangles, non-ok statuses %ld\n", n, other);
  EXPECT_LE(other, n / 10000);
}
