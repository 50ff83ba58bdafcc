/* ----------------------------------------------------------------------
   POLYDEM - the header-only kernels on the device against the host.

   Runs GJK, the overlap polyhedron (V, centroid, S, M), the polyhedron-
   triangle section (Sutherland-Hodgman), the contact step and the free
   rotor for many random pairs of real shape templates inside a
   Kokkos::parallel_for on the default execution space (Kokkos::Cuda on a
   GPU, OpenMP/Serial on the CPU), then the same calls on the host, and
   compares them value by value, for float and double.

   Workspaces live in device memory (one per pair, in a View), not on each
   thread's stack: an OverlapWorkspace is ~49 KB, a ClipWorkspace ~31 KB,
   which a CUDA thread's stack does not hold.

   Two uses:
   - compiled with -c only by unittest/scripts/cuda-compile-check.sh (ctest
     cuda_compile_check): nvcc must compile every kernel's device code;
   - linked (with -DPOLYDEM_KERNELS_MAIN, libpolydem_shapes and Kokkos) as
     polydem_kernels_device SHAPE_FILE...: exit 0 if device and host agree
     (ctest kernel_device_vs_host on Kokkos Serial here; tools/gpu/run.sh on
     a GPU).

   Tolerances (relative to the larger of |host| and 1e-3 of the largest
   |host| of that quantity): the device may contract a*b+c into FMAs and
   order sums differently; 1e-9 (double) and 2e-3 (float). Near-degenerate
   cases can take the other branch (touching vs overlapping, slip vs
   stick): up to 1 % of the pairs may disagree (reported), more fails.
   The same compiler on the same CPU gives zero differences.
------------------------------------------------------------------------- */

#ifndef POLYDEM_USE_KOKKOS
#define POLYDEM_USE_KOKKOS
#endif

#include <Kokkos_Core.hpp>

#include "polydem_clip.h"
#include "polydem_contact_law.h"
#include "polydem_defs.h"
#include "polydem_ellipsoid_overlap.h"
#include "polydem_gjk.h"
#include "polydem_math.h"
#include "polydem_overlap.h"
#include "polydem_rigid.h"
#include "polydem_shape_view.h"

#ifdef POLYDEM_KERNELS_MAIN
#include "polydem_shape_template.h"    // host: shape files -> templates (CGAL)
#endif

#if defined(POLYDEM_REQUIRE_CUDA) && !defined(KOKKOS_ENABLE_CUDA)
#error "POLYDEM CUDA compile check: this Kokkos has no CUDA backend"
#endif

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <vector>

namespace polydem_device_check {

using Space = Kokkos::DefaultExecutionSpace;
using Mem = Space::memory_space;
#if defined(POLYDEM_REQUIRE_CUDA)
static_assert(std::is_same<Space, Kokkos::Cuda>::value,
              "POLYDEM CUDA compile check: the default execution space must be Kokkos::Cuda");
#endif

using namespace polydem;

// the values compared per pair
enum Slot : int {
  R_GJK_DIST,
  R_V,
  R_CX, R_CY, R_CZ,
  R_SX, R_SY, R_SZ,
  R_MAX, R_MAY, R_MAZ,
  R_MBX, R_MBY, R_MBZ,
  R_CLIP_A, R_CLIP_V,
  R_CLIP_SX, R_CLIP_SY, R_CLIP_SZ,
  R_CLIP_MX, R_CLIP_MY, R_CLIP_MZ,
  R_FX, R_FY, R_FZ,
  R_TX, R_TY, R_TZ,
  R_E,
  R_Q0, R_Q1, R_Q2, R_Q3,
  R_EV, R_ESX, R_ESY, R_ESZ, R_EMX, R_EMY, R_EMZ,
  NSLOT
};
enum StatusSlot : int { S_GJK, S_OVERLAP, S_CLIP, NSTATUS };
#ifdef POLYDEM_KERNELS_MAIN
static const char *const slot_name[NSLOT] = {
    "gjk distance", "V", "centroid.x", "centroid.y", "centroid.z", "S.x", "S.y", "S.z",
    "M_A.x", "M_A.y", "M_A.z", "M_B.x", "M_B.y", "M_B.z", "clip area", "clip volume",
    "clip S.x", "clip S.y", "clip S.z", "clip M.x", "clip M.y", "clip M.z", "F.x", "F.y",
    "F.z", "tau.x", "tau.y", "tau.z", "energy", "q.w", "q.x", "q.y", "q.z",
    "ellipsoid V", "ellipsoid S.x", "ellipsoid S.y", "ellipsoid S.z", "ellipsoid M_A.x",
    "ellipsoid M_A.y", "ellipsoid M_A.z"};
#endif

// one pair's input: two posed templates, a triangle, the velocities
template <typename T> struct PairCase {
  int a, b;    // template indices
  Pose<T> pa, pb;
  Triangle<T> tri;
  Vec3<T> vb, wa;
};

// r[k..k+2] = v
template <typename T> KOKKOS_INLINE_FUNCTION void put3(T *r, int k, const Vec3<T> &v)
{
  r[k] = v.x;
  r[k + 1] = v.y;
  r[k + 2] = v.z;
}

// Everything a pair computes; the same function on the device and the host.
template <typename T, int MF, int ME>
KOKKOS_INLINE_FUNCTION void run_pair(const ShapeView<T> &va, const ShapeView<T> &vb,
                                     const PairCase<T> &c, OverlapWorkspace<T, MF> &ows,
                                     ClipWorkspace<T, MF, ME> &cws, T *r, int *st)
{
  const PosedShape<T> a = make_posed(va, c.pa), b = make_posed(vb, c.pb);
  const GjkResult<T> g = gjk_intersect(a, b);
  st[S_GJK] = g.status;
  r[R_GJK_DIST] = g.status == STATUS_SEPARATED ? g.distance : T(0);
  const OverlapResult<T> o = polyhedron_overlap(a, b, ows);
  st[S_OVERLAP] = o.status;
  r[R_V] = o.volume;
  put3(r, R_CX, o.centroid);
  put3(r, R_SX, o.S_A);
  put3(r, R_MAX, o.M_A);
  put3(r, R_MBX, o.M_B);
  const ClipResult<T> k = polyhedron_triangle(a, c.tri, cws);
  st[S_CLIP] = k.status;
  r[R_CLIP_A] = k.area;
  r[R_CLIP_V] = k.volume;
  put3(r, R_CLIP_SX, k.S);
  put3(r, R_CLIP_MX, k.M);
  // contact step of the overlap (Feng's law with its core, twisting friction),
  // three steps on one history so that the spring and the cap act
  Vec3<T> F = make_vec3(T(0), T(0), T(0)), tau = F;
  T energy = T(0);
  if (o.status == STATUS_OK) {
    const ContactGeometry<T> geo = contact_geometry<T>(o);
    DampingLaw<T> d;    // damping_law(e) is host-only: zeta(0.5, 1/3), zeta(0.5, 1)
    d.z[0] = T(0.2157);
    d.z[1] = T(0.2154);
    d.local = 1;
    const T V = T(0.5);
    const ContactLaw<T> law =
        feng_law(T(1e7), T(0.3), V, T(1e7), T(0.3), V, d, T(0.5), T(1e-3), 1);
    const ContactKinematics<T> kin = make_kinematics(c.pa.x, c.pb.x, make_vec3(T(0), T(0), T(0)),
                                                     c.vb, c.wa, make_vec3(T(0), T(0), T(0)),
                                                     T(2), T(1e-5));
    T h[CONTACT_HIST] = {T(0), T(0), T(0), T(0), T(0)};
    for (int s = 0; s < 3; ++s) {
      const ContactForce<T> cf = contact_step(geo, law, kin, h, CONTACT_HIST);
      F = cf.F_A;
      tau = cf.tau_A;
      energy = cf.energy;
    }
  }
  put3(r, R_FX, F);
  put3(r, R_TX, tau);
  r[R_E] = energy;
  // free rotor (polydem_rigid.h): 20 steps of A's orientation
  const T inertia[3] = {va.inertia[0], va.inertia[1], va.inertia[2]};
  T L[3] = {c.wa.x * inertia[0], c.wa.y * inertia[1], c.wa.z * inertia[2]};
  T q[4] = {c.pa.q.w, c.pa.q.x, c.pa.q.y, c.pa.q.z};
  for (int s = 0; s < 20; ++s) free_rotor_step(T(1e-3), inertia, L, q);
  r[R_Q0] = q[0];
  r[R_Q1] = q[1];
  r[R_Q2] = q[2];
  r[R_Q3] = q[3];
  // A against an ellipsoid at B's pose, semi-axes (1, 0.7, 0.5) x B's bounding radius
  EllipsoidPose<T> e;
  e.x = c.pb.x;
  e.q = c.pb.q;
  const T rb = c.pb.s * vb.radius;
  e.axes = make_vec3(rb, T(0.7) * rb, T(0.5) * rb);
  const OverlapResult<T> eo = polyhedron_ellipsoid_overlap(a, e);
  r[R_EV] = eo.volume;
  put3(r, R_ESX, eo.S_A);
  put3(r, R_EMX, eo.M_A);
}

// The arrays of all templates (type T) in one memory space, and views into them.
template <typename T, typename M> struct Templates {
  Kokkos::View<T *, M> verts, planes;
  Kokkos::View<int *, M> face_start, face_verts, edges, dual;
  Kokkos::View<ShapeView<T> *, M> views;
  // the arrays of n templates of nv vertex and np plane values, nfs face
  // starts, nfv face vertices, ne edge and nd dual/adjacency values (host)
  void allocate(int n, size_t nv, size_t np, size_t nfs, size_t nfv, size_t ne, size_t nd)
  {
    verts = Kokkos::View<T *, M>("verts", nv);
    planes = Kokkos::View<T *, M>("planes", np);
    face_start = Kokkos::View<int *, M>("face_start", nfs);
    face_verts = Kokkos::View<int *, M>("face_verts", nfv);
    edges = Kokkos::View<int *, M>("edges", ne);
    dual = Kokkos::View<int *, M>("dual", std::max<size_t>(nd, 1));
    views = Kokkos::View<ShapeView<T> *, M>("views", n);
  }
};

constexpr int MF = MAX_TEMPLATE_FACES, ME = 384;

#ifdef POLYDEM_KERNELS_MAIN

// host templates -> flat arrays in host memory, then a device copy whose
// views point into device memory
template <typename T> struct DeviceTemplates {
  using HostM = Kokkos::HostSpace;
  Templates<T, HostM> h;
  Templates<T, Mem> d;
  explicit DeviceTemplates(const std::vector<ShapeView<double>> &src)
  {
    const int n = (int) src.size();
    size_t nv = 0, np = 0, nfs = 0, nfv = 0, ne = 0, nd = 0;
    for (const auto &s : src) {
      nv += 3 * s.nverts;
      np += 4 * s.nfaces;
      nfs += s.nfaces + 1;
      nfv += s.face_start[s.nfaces];
      ne += 2 * s.nedges;
      nd += dual_seed_ints(s) + vertex_adjacency_ints(s);
    }
    h.allocate(n, nv, np, nfs, nfv, ne, nd);
    d.allocate(n, nv, np, nfs, nfv, ne, nd);
    auto dviews = Kokkos::create_mirror_view(d.views);
    size_t ov = 0, op = 0, ofs = 0, ofv = 0, oe = 0, od = 0;
    for (int i = 0; i < n; ++i) {
      const ShapeView<double> &s = src[i];
      ShapeView<T> hv, dv;
      hv.nverts = dv.nverts = s.nverts;
      hv.nfaces = dv.nfaces = s.nfaces;
      hv.nedges = dv.nedges = s.nedges;
      hv.radius = dv.radius = T(s.radius);
      hv.volume = dv.volume = T(s.volume);
      for (int k = 0; k < 3; ++k) hv.inertia[k] = dv.inertia[k] = T(s.inertia[k]);
      for (int k = 0; k < 3 * s.nverts; ++k) h.verts(ov + k) = T(s.verts[k]);
      for (int k = 0; k < 4 * s.nfaces; ++k) h.planes(op + k) = T(s.planes[k]);
      for (int k = 0; k <= s.nfaces; ++k) h.face_start(ofs + k) = s.face_start[k];
      for (int k = 0; k < s.face_start[s.nfaces]; ++k) h.face_verts(ofv + k) = s.face_verts[k];
      for (int k = 0; k < 2 * s.nedges; ++k) h.edges(oe + k) = s.edges[k];
      const int nds = dual_seed_ints(s), nadj = vertex_adjacency_ints(s);
      for (int k = 0; k < nds; ++k) h.dual(od + k) = s.dual[k];
      for (int k = 0; k < nadj; ++k) h.dual(od + nds + k) = s.vadj[k];    // adjacency after the seed
      hv.verts = h.verts.data() + ov;
      dv.verts = d.verts.data() + ov;
      hv.planes = h.planes.data() + op;
      dv.planes = d.planes.data() + op;
      hv.face_start = h.face_start.data() + ofs;
      dv.face_start = d.face_start.data() + ofs;
      hv.face_verts = h.face_verts.data() + ofv;
      dv.face_verts = d.face_verts.data() + ofv;
      hv.edges = h.edges.data() + oe;
      dv.edges = d.edges.data() + oe;
      hv.dual = nds ? h.dual.data() + od : nullptr;
      dv.dual = nds ? d.dual.data() + od : nullptr;
      hv.vadj = nadj ? h.dual.data() + od + nds : nullptr;
      dv.vadj = nadj ? d.dual.data() + od + nds : nullptr;
      h.views(i) = hv;
      dviews(i) = dv;
      ov += 3 * s.nverts;
      op += 4 * s.nfaces;
      ofs += s.nfaces + 1;
      ofv += s.face_start[s.nfaces];
      oe += 2 * s.nedges;
      od += nds + nadj;
    }
    Kokkos::deep_copy(d.verts, h.verts);
    Kokkos::deep_copy(d.planes, h.planes);
    Kokkos::deep_copy(d.face_start, h.face_start);
    Kokkos::deep_copy(d.face_verts, h.face_verts);
    Kokkos::deep_copy(d.edges, h.edges);
    Kokkos::deep_copy(d.dual, h.dual);
    Kokkos::deep_copy(d.views, dviews);
  }
};

template <typename T> Quat<T> random_quat(std::mt19937_64 &rng)
{
  std::normal_distribution<double> g;
  const Quat<double> q = qnormalize(make_quat(g(rng), g(rng), g(rng), g(rng)));
  return make_quat(T(q.w), T(q.x), T(q.y), T(q.z));
}

// random pairs at 0.3-1.0 of the sum of their bounding radii apart (most
// overlap), a triangle through B's centre facing A
template <typename T>
std::vector<PairCase<T>> make_cases(const std::vector<ShapeView<double>> &src, int n,
                                    unsigned seed)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> g;
  std::vector<PairCase<T>> cs(n);
  const int ns = (int) src.size();
  for (int i = 0; i < n; ++i) {
    PairCase<T> &c = cs[i];
    c.a = i % ns;
    c.b = (i / ns) % ns;
    const double sa = 0.5 + u(rng), sb = 0.5 + u(rng);
    Vec3<double> dir = make_vec3(g(rng), g(rng), g(rng));
    dir = (1.0 / norm(dir)) * dir;
    const double dist = (0.3 + 0.7 * u(rng)) * (sa * src[c.a].radius + sb * src[c.b].radius);
    const Vec3<double> xa = make_vec3(u(rng), u(rng), u(rng)), xb = xa + dist * dir;
    c.pa.x = make_vec3(T(xa.x), T(xa.y), T(xa.z));
    c.pb.x = make_vec3(T(xb.x), T(xb.y), T(xb.z));
    c.pa.q = random_quat<T>(rng);
    c.pb.q = random_quat<T>(rng);
    c.pa.s = T(sa);
    c.pb.s = T(sb);
    Vec3<double> e1 = cross(dir, make_vec3(0.3, 0.5, 0.7));
    e1 = (1.0 / norm(e1)) * e1;
    const Vec3<double> e2 = cross(dir, e1);
    const double r = 2.0 * sa * src[c.a].radius;
    const Vec3<double> p0 = xb - 0.5 * dist * dir - r * e1, p1 = xb - 0.5 * dist * dir + r * (e1 - e2),
                       p2 = xb - 0.5 * dist * dir + r * (e1 + e2);
    c.tri.v[0] = make_vec3(T(p0.x), T(p0.y), T(p0.z));
    c.tri.v[1] = make_vec3(T(p1.x), T(p1.y), T(p1.z));
    c.tri.v[2] = make_vec3(T(p2.x), T(p2.y), T(p2.z));
    c.vb = make_vec3(T(0.3 * g(rng)), T(0.3 * g(rng)), T(0.3 * g(rng)));
    c.wa = make_vec3(T(5 * g(rng)), T(5 * g(rng)), T(5 * g(rng)));
  }
  return cs;
}

// device run, host run, comparison; returns the number of failures
// perturb: relative change of A's scale on the device only (a planted
// defect: the comparison must then fail)
template <typename T>
int check(const char *tname, const std::vector<ShapeView<double>> &src, int n, double tol,
          double perturb)
{
  DeviceTemplates<T> tp(src);
  const auto cases = make_cases<T>(src, n, 12345);
  Kokkos::View<PairCase<T> *, Mem> dcases("cases", n);
  {
    auto h = Kokkos::create_mirror_view(dcases);
    for (int i = 0; i < n; ++i) {
      h(i) = cases[i];
      h(i).pa.s = T(double(cases[i].pa.s) * (1.0 + perturb));
    }
    Kokkos::deep_copy(dcases, h);
  }
  // the workspaces: one per pair in device memory
  Kokkos::View<OverlapWorkspace<T, MF> *, Mem> ows("overlap workspaces", n);
  Kokkos::View<ClipWorkspace<T, MF, ME> *, Mem> cws("clip workspaces", n);
  Kokkos::View<T **, Mem> res("results", n, (int) NSLOT);
  Kokkos::View<int **, Mem> sts("status", n, (int) NSTATUS);
  const auto views = tp.d.views;
  Kokkos::parallel_for(
      "polydem_kernels_device", Kokkos::RangePolicy<Space>(0, n), KOKKOS_LAMBDA(const int i) {
        const PairCase<T> c = dcases(i);
        T r[NSLOT];
        int st[NSTATUS];
        run_pair(views(c.a), views(c.b), c, ows(i), cws(i), r, st);
        for (int k = 0; k < NSLOT; ++k) res(i, k) = r[k];
        for (int k = 0; k < NSTATUS; ++k) sts(i, k) = st[k];
      });
  Kokkos::fence();
  auto hres = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), res);
  auto hsts = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sts);

  auto ows_h = std::make_unique<OverlapWorkspace<T, MF>>();
  auto cws_h = std::make_unique<ClipWorkspace<T, MF, ME>>();
  std::vector<T> ref((size_t) n * NSLOT);
  std::vector<int> rst((size_t) n * NSTATUS);
  for (int i = 0; i < n; ++i)
    run_pair(tp.h.views(cases[i].a), tp.h.views(cases[i].b), cases[i], *ows_h, *cws_h,
             &ref[(size_t) i * NSLOT], &rst[(size_t) i * NSTATUS]);

  double scale[NSLOT] = {0.0};
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < NSLOT; ++k)
      scale[k] = std::max(scale[k], 1e-3 * std::fabs((double) ref[(size_t) i * NSLOT + k]));
  int nover = 0, nclip = 0, nbad = 0;
  double worst = 0.0;
  int worst_slot = 0;
  for (int i = 0; i < n; ++i) {
    nover += rst[(size_t) i * NSTATUS + S_OVERLAP] == STATUS_OK;
    nclip += rst[(size_t) i * NSTATUS + S_CLIP] == STATUS_OK;
    bool bad = false;
    for (int k = 0; k < NSTATUS; ++k) bad |= hsts(i, k) != rst[(size_t) i * NSTATUS + k];
    double pair_worst = 0.0;
    int pair_slot = 0;
    for (int k = 0; k < NSLOT; ++k) {
      const double h = ref[(size_t) i * NSLOT + k], d = hres(i, k);
      const double den = std::max(std::max(std::fabs(h), std::fabs(d)), scale[k]);
      const double e = den > 0.0 ? std::fabs(d - h) / den : 0.0;
      if (!(e <= tol)) bad = true;    // NaN too
      if (!(e <= pair_worst)) {
        pair_worst = e;
        pair_slot = k;
      }
    }
    if (bad) {
      if (nbad < 5)
        std::printf("  %s pair %d: status device %d/%d/%d host %d/%d/%d, worst %s rel %.3g\n",
                    tname, i, hsts(i, 0), hsts(i, 1), hsts(i, 2), rst[(size_t) i * NSTATUS],
                    rst[(size_t) i * NSTATUS + 1], rst[(size_t) i * NSTATUS + 2],
                    slot_name[pair_slot], pair_worst);
      nbad++;
    } else if (pair_worst > worst) {
      worst = pair_worst;
      worst_slot = pair_slot;
    }
  }
  const int allowed = n / 100;
  const bool enough = nover >= n / 4 && nclip >= n / 10;
  const bool pass = nbad <= allowed && enough;
  std::printf("kernels %s on %s: %d pairs (%d overlap, %d cut the triangle), %d disagree "
              "(allowed %d), largest difference of the others %.3g relative (%s; tolerance "
              "%.0e): %s\n",
              tname, Space::name(), n, nover, nclip, nbad, allowed, worst, slot_name[worst_slot],
              tol, pass ? "PASS" : (enough ? "FAIL" : "FAIL (too few overlapping pairs)"));
  return pass ? 0 : 1;
}

}    // namespace polydem_device_check

int main(int argc, char **argv)
{
  using namespace polydem_device_check;
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s SHAPE_FILE... [-n PAIRS] [--perturb REL]\n", argv[0]);
    return 2;
  }
  int n = 2048;
  double perturb = 0.0;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "-n" && i + 1 < argc)
      n = std::atoi(argv[++i]);
    else if (a == "--perturb" && i + 1 < argc)
      perturb = std::atof(argv[++i]);
    else if (a.rfind("--kokkos", 0) != 0)
      files.push_back(a);
  }
  int fails = 0;
  Kokkos::initialize(argc, argv);
  {
    std::vector<polydem::PolyShapeTemplate> shapes;
    std::vector<polydem::ShapeView<double>> views;
    try {
      for (const auto &f : files) shapes.push_back(polydem::PolyShapeTemplate::from_file(f));
    } catch (const std::exception &e) {
      std::fprintf(stderr, "polydem_kernels_device: %s\n", e.what());
      fails = 1;
    }
    for (const auto &s : shapes) views.push_back(s.view());
    if (!fails) {
      fails += check<double>("double", views, n, 1e-9, perturb);
      fails += check<float>("float", views, n, 2e-3, perturb);
    }
  }
  Kokkos::finalize();
  return fails ? 1 : 0;
}
#else
// compile check only: instantiate the device lambda's function for both types
template void run_pair<float, MF, ME>(const ShapeView<float> &, const ShapeView<float> &,
                                      const PairCase<float> &, OverlapWorkspace<float, MF> &,
                                      ClipWorkspace<float, MF, ME> &, float *, int *);
template void run_pair<double, MF, ME>(const ShapeView<double> &, const ShapeView<double> &,
                                       const PairCase<double> &, OverlapWorkspace<double, MF> &,
                                       ClipWorkspace<double, MF, ME> &, double *, int *);

// a parallel_for over device-resident workspaces, as in main()
template <typename T> void exercise(int n)
{
  Templates<T, Mem> tp;
  tp.views = Kokkos::View<ShapeView<T> *, Mem>("views", 1);
  Kokkos::View<PairCase<T> *, Mem> dcases("cases", n);
  Kokkos::View<OverlapWorkspace<T, MF> *, Mem> ows("ows", n);
  Kokkos::View<ClipWorkspace<T, MF, ME> *, Mem> cws("cws", n);
  Kokkos::View<T **, Mem> res("results", n, (int) NSLOT);
  const auto views = tp.views;
  Kokkos::parallel_for(
      "polydem_kernels_device", Kokkos::RangePolicy<Space>(0, n), KOKKOS_LAMBDA(const int i) {
        T r[NSLOT];
        int st[NSTATUS];
        const PairCase<T> c = dcases(i);
        run_pair(views(c.a), views(c.b), c, ows(i), cws(i), r, st);
        for (int k = 0; k < NSLOT; ++k) res(i, k) = r[k];
      });
}
template void exercise<float>(int);
template void exercise<double>(int);
}    // namespace polydem_device_check
#endif
