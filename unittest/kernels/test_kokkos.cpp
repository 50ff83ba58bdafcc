// POLYDEM kernel tests: the kernels inside Kokkos::parallel_for (Serial
// backend, compiled with -DPOLYDEM_USE_KOKKOS so POLYDEM_FN is
// KOKKOS_INLINE_FUNCTION) must equal the plain host call bit for bit.
#include "pair_gen.h"

#include "polydem_clip.h"
#include "polydem_gjk.h"
#include "polydem_overlap.h"

#include <Kokkos_Core.hpp>
#include <gtest/gtest.h>

#include <cstring>

using namespace polydem;
using namespace polydem_test;

namespace {

template <typename T> bool same_bits(const T &a, const T &b)
{
  return std::memcmp(&a, &b, sizeof(T)) == 0;
}

template <typename T> void check(const OverlapResult<T> &a, const OverlapResult<T> &b,
                                 const GjkResult<T> &ga, const GjkResult<T> &gb,
                                 const ClipResult<T> &ca, const ClipResult<T> &cb, int i)
{
  EXPECT_EQ(a.status, b.status) << i;
  EXPECT_TRUE(same_bits(a.volume, b.volume)) << i;
  EXPECT_TRUE(same_bits(a.centroid, b.centroid)) << i;
  EXPECT_TRUE(same_bits(a.S_A, b.S_A)) << i;
  EXPECT_TRUE(same_bits(a.M_A, b.M_A)) << i;
  EXPECT_TRUE(same_bits(a.M_B, b.M_B)) << i;
  EXPECT_EQ(ga.status, gb.status) << i;
  EXPECT_TRUE(same_bits(ga.distance, gb.distance)) << i;
  EXPECT_EQ(ca.status, cb.status) << i;
  EXPECT_TRUE(same_bits(ca.area, cb.area)) << i;
  EXPECT_TRUE(same_bits(ca.volume, cb.volume)) << i;
  EXPECT_TRUE(same_bits(ca.S, cb.S)) << i;
  EXPECT_TRUE(same_bits(ca.M, cb.M)) << i;
}

template <typename T> void run(const ShapePool &pool, const std::vector<Pair> &pairs)
{
  const int n = (int) pairs.size();
  // views of the templates and poses (Serial: host memory)
  Kokkos::View<ShapeView<T> *, Kokkos::HostSpace> va("va", n), vb("vb", n);
  Kokkos::View<Pose<T> *, Kokkos::HostSpace> pa("pa", n), pb("pb", n);
  Kokkos::View<Triangle<T> *, Kokkos::HostSpace> tri("tri", n);
  for (int i = 0; i < n; ++i) {
    if constexpr (std::is_same<T, float>::value) {
      va(i) = pool.f[pairs[i].a]->view;
      vb(i) = pool.f[pairs[i].b]->view;
      pa(i) = to_float(pairs[i].pa);
      pb(i) = to_float(pairs[i].pb);
    } else {
      va(i) = pool.d[pairs[i].a]->view;
      vb(i) = pool.d[pairs[i].b]->view;
      pa(i) = pairs[i].pa;
      pb(i) = pairs[i].pb;
    }
    // triangle through B's centre, normal towards A
    const Vec3<T> c = pb(i).x;
    Vec3<T> nrm = pa(i).x - pb(i).x;
    if (norm(nrm) == T(0)) nrm = make_vec3(T(0), T(0), T(1));
    Vec3<T> e1 = cross(nrm, make_vec3(T(0.3), T(0.5), T(0.7)));
    e1 = (T(1) / norm(e1)) * e1;
    const Vec3<T> e2 = (T(1) / norm(nrm)) * cross(nrm, e1);
    tri(i).v[0] = c - T(2) * e1;
    tri(i).v[1] = c + e1 - e2;
    tri(i).v[2] = c + e1 + T(2) * e2;
  }
  Kokkos::View<OverlapResult<T> *, Kokkos::HostSpace> ro("ro", n);
  Kokkos::View<GjkResult<T> *, Kokkos::HostSpace> rg("rg", n);
  Kokkos::View<ClipResult<T> *, Kokkos::HostSpace> rc("rc", n);
  Kokkos::parallel_for(
      "polydem_kernels", Kokkos::RangePolicy<Kokkos::Serial>(0, n), KOKKOS_LAMBDA(const int i) {
        OverlapWorkspace<T, 64> ws;
        ClipWorkspace<T, 64> cws;
        const PosedShape<T> a = make_posed(va(i), pa(i)), b = make_posed(vb(i), pb(i));
        rg(i) = gjk_intersect(a, b);
        ro(i) = polyhedron_overlap(a, b, ws);
        rc(i) = polyhedron_triangle(a, tri(i), cws);
      });
  Kokkos::fence();
  static OverlapWorkspace<T, 64> ws;
  static ClipWorkspace<T, 64> cws;
  int nok = 0;
  for (int i = 0; i < n; ++i) {
    const PosedShape<T> a = make_posed(va(i), pa(i)), b = make_posed(vb(i), pb(i));
    const GjkResult<T> g = gjk_intersect(a, b);
    const OverlapResult<T> r = polyhedron_overlap(a, b, ws);
    const ClipResult<T> c = polyhedron_triangle(a, tri(i), cws);
    check(ro(i), r, rg(i), g, rc(i), c, i);
    nok += r.status == STATUS_OK;
  }
  EXPECT_GT(nok, n / 4);
}

}    // namespace

TEST(KernelKokkos, SerialBitForBit)
{
  Kokkos::initialize();
  {
    // templates with at most 64 faces: random hulls of 4-32 points
    ShapePool pool(0, 77);
    std::mt19937_64 rng(77);
    std::uniform_int_distribution<int> nv(4, 32);
    for (int i = 0; i < 50; ++i) pool.add(make_shape(random_points(rng, nv(rng), 3.0)));
    std::vector<Pair> pairs;
    for (int i = 0; i < 2000; ++i) pairs.push_back(random_pair(pool, rng));
    run<double>(pool, pairs);
    run<float>(pool, pairs);
  }
  Kokkos::finalize();
}
