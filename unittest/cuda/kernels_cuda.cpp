/* ----------------------------------------------------------------------
   POLYDEM - CUDA compile check for the header-only kernels.

   Instantiates every kernel of src/POLYDEM/polydem_*.h inside a
   Kokkos::parallel_for on the default execution space (Kokkos::Cuda in the
   check), for float and double, so that nvcc compiles their device code.
   Compiled with -c only by tools/cuda-compile-check.sh (ctest
   cuda_compile_check); never linked or run (no GPU here).

   Kernel headers still being written are included when they exist
   (__has_include). Whoever adds or changes a kernel adds its call to the
   matching exercise_* function below: a kernel that is never called from a
   device lambda is not checked.
------------------------------------------------------------------------- */

#ifndef POLYDEM_USE_KOKKOS
#define POLYDEM_USE_KOKKOS
#endif

#include <Kokkos_Core.hpp>

#include "polydem_defs.h"
#include "polydem_math.h"
#include "polydem_shape_view.h"

#if __has_include("polydem_rigid.h")
#include "polydem_rigid.h"
#define POLYDEM_CHECK_RIGID 1
#endif
#if __has_include("polydem_gjk.h")
#include "polydem_gjk.h"
#define POLYDEM_CHECK_GJK 1
#endif
#if __has_include("polydem_overlap.h")
#include "polydem_overlap.h"
#define POLYDEM_CHECK_OVERLAP 1
#endif
#if __has_include("polydem_clip.h")
#include "polydem_clip.h"
#define POLYDEM_CHECK_CLIP 1
#endif
#if __has_include("polydem_contact_law.h")
#include "polydem_contact_law.h"
#define POLYDEM_CHECK_CONTACT_MODEL 1
#endif

#if defined(POLYDEM_REQUIRE_CUDA) && !defined(KOKKOS_ENABLE_CUDA)
#error "POLYDEM CUDA compile check: this Kokkos has no CUDA backend"
#endif

namespace polydem_cuda_check {

using Space = Kokkos::DefaultExecutionSpace;
using Mem = Space::memory_space;
#if defined(POLYDEM_REQUIRE_CUDA)
static_assert(std::is_same<Space, Kokkos::Cuda>::value,
              "POLYDEM CUDA compile check: the default execution space must be Kokkos::Cuda");
#endif

using namespace polydem;

// A unit cube as a ShapeView in device memory (the layout the /kk styles use).
template <typename T> struct DeviceCube {
  Kokkos::View<T *, Mem> verts{"verts", 3 * 8};
  Kokkos::View<T *, Mem> planes{"planes", 4 * 6};
  Kokkos::View<int *, Mem> face_start{"face_start", 6 + 1};
  Kokkos::View<int *, Mem> face_verts{"face_verts", 4 * 6};
  Kokkos::View<int *, Mem> edges{"edges", 2 * 12};

  KOKKOS_INLINE_FUNCTION ShapeView<T> view() const
  {
    ShapeView<T> s;
    s.nverts = 8;
    s.nfaces = 6;
    s.nedges = 12;
    s.verts = verts.data();
    s.planes = planes.data();
    s.face_start = face_start.data();
    s.face_verts = face_verts.data();
    s.edges = edges.data();
    s.radius = T(0.8660254037844386);
    s.volume = T(1);
    s.inertia[0] = s.inertia[1] = s.inertia[2] = T(1) / T(6);
    return s;
  }
};

template <typename T> KOKKOS_INLINE_FUNCTION Pose<T> pose_of(int i)
{
  Pose<T> p;
  p.x = make_vec3(T(i), T(0.5) * T(i), T(-1));
  p.q = qnormalize(make_quat(T(1), T(0.1) * T(i), T(0.2), T(-0.3)));
  p.s = T(1) + T(0.01) * T(i);
  return p;
}

// polydem_math.h, polydem_shape_view.h
template <typename T> void exercise_math(int n)
{
  DeviceCube<T> cube;
  Kokkos::View<T *[3], Mem> out("out", n);
  Kokkos::parallel_for(
      "polydem_check_math", Kokkos::RangePolicy<Space>(0, n), KOKKOS_LAMBDA(const int i) {
        const ShapeView<T> s = cube.view();
        const Pose<T> p = pose_of<T>(i);
        Vec3<T> a = make_vec3(s.verts[0], s.verts[1], s.verts[2]);
        Vec3<T> b = make_vec3(s.planes[0], s.planes[1], s.planes[2]);
        a += b;
        a -= T(0.5) * b;
        a = a * T(2) - (-b);
        const Vec3<T> c = cross(a, b);
        const T d = dot(a, c) + norm(c) + norm2(b) + fabs(s.radius) + sqrt(s.volume);
        const Quat<T> q = qmul(p.q, qconj(p.q));
        const Mat3<T> r = quat_to_mat(q);
        Vec3<T> v = matvec(r, a) + matTvec(r, b);
        v += qrotate(p.q, v) - qrotate_inv(p.q, c);
        v = p.x + p.s * v;
        v[0] += d + T(s.face_start[1] + s.face_verts[0] + s.edges[0]);
        out(i, 0) = v[0];
        out(i, 1) = v.y;
        out(i, 2) = v.z;
      });
}

#ifdef POLYDEM_CHECK_RIGID
// polydem_rigid.h
template <typename T> void exercise_rigid(int n)
{
  Kokkos::View<T *[8], Mem> out("out", n);
  Kokkos::parallel_for(
      "polydem_check_rigid", Kokkos::RangePolicy<Space>(0, n), KOKKOS_LAMBDA(const int i) {
        const T inertia[3] = {T(1), T(2), T(3)};
        T L[3] = {T(0.1) * T(i), T(1), T(0.01)};
        T q[4] = {T(1), T(0), T(0), T(0)};
        T w[3];
        free_rotor_step(T(1e-3), inertia, L, q);
        free_rotor_substep(1, T(1e-3), inertia, L, q);
        omega_from_angmom(inertia, L, q, w);
        angmom_from_omega(inertia, w, q, L);
        const T e = rotational_energy(inertia, L, q);
        for (int k = 0; k < 3; ++k) out(i, k) = L[k];
        for (int k = 0; k < 4; ++k) out(i, 3 + k) = q[k];
        out(i, 7) = e;
      });
}
#endif

#ifdef POLYDEM_CHECK_GJK
// polydem_gjk.h: bounding spheres, support function, GJK
template <typename T> void exercise_gjk(int n)
{
  DeviceCube<T> cube;
  Kokkos::View<T *[4], Mem> out("out", n);
  Kokkos::View<int *, Mem> status("status", n);
  Kokkos::parallel_for(
      "polydem_check_gjk", Kokkos::RangePolicy<Space>(0, n), KOKKOS_LAMBDA(const int i) {
        const ShapeView<T> s = cube.view();
        const PosedShape<T> a = make_posed(s, pose_of<T>(i));
        const PosedShape<T> b = make_posed(s, pose_of<T>(i + 1));
        const Vec3<T> p = support_point(a, make_vec3(T(1), T(0), T(0)));
        const GjkResult<T> g = gjk_intersect(a, b);
        const GjkResult<T> g2 = gjk_intersect(a, b, T(10) * Eps<T>::value);
        out(i, 0) = p.x + posed_radius(a);
        out(i, 1) = pair_length_scale(a, b);
        out(i, 2) = g.distance + g2.distance;
        out(i, 3) = T(g.iterations);
        status(i) = bounding_spheres_overlap(a, b) ? g.status : -1;
      });
}
#endif

#ifdef POLYDEM_CHECK_OVERLAP
// polydem_overlap.h (with polydem_dual_hull.h, polydem_lp.h): overlap
// polyhedron, V, centroid, S, M, in a per-thread fixed workspace
template <typename T> void exercise_overlap(int n)
{
  DeviceCube<T> cube;
  Kokkos::View<T *[8], Mem> out("out", n);
  Kokkos::View<int *, Mem> status("status", n);
  Kokkos::parallel_for(
      "polydem_check_overlap", Kokkos::RangePolicy<Space>(0, n), KOKKOS_LAMBDA(const int i) {
        const ShapeView<T> s = cube.view();
        const PosedShape<T> a = make_posed(s, pose_of<T>(i));
        const PosedShape<T> b = make_posed(s, pose_of<T>(i + 1));
        OverlapWorkspace<T> ws;
        const OverlapResult<T> r = polyhedron_overlap(a, b, ws);
        out(i, 0) = r.volume;
        out(i, 1) = r.centroid.x;
        out(i, 2) = r.S_A.y;
        out(i, 3) = r.M_A.z + r.M_B.z;
        out(i, 4) = r.area;
        out(i, 5) = r.normal.x;
        out(i, 6) = r.depth;
        out(i, 7) = T(r.nverts);
        status(i) = r.status;
      });
}
#endif

#ifdef POLYDEM_CHECK_CLIP
// polydem_clip.h: polyhedron-triangle section (Sutherland-Hodgman) and prism volume
template <typename T> void exercise_clip(int n)
{
  DeviceCube<T> cube;
  Kokkos::View<T *[8], Mem> out("out", n);
  Kokkos::View<int *, Mem> status("status", n);
  Kokkos::parallel_for(
      "polydem_check_clip", Kokkos::RangePolicy<Space>(0, n), KOKKOS_LAMBDA(const int i) {
        const ShapeView<T> s = cube.view();
        const PosedShape<T> a = make_posed(s, pose_of<T>(i));
        Triangle<T> tri;
        tri.v[0] = make_vec3(T(-2), T(-2), T(i));
        tri.v[1] = make_vec3(T(2), T(-2), T(i));
        tri.v[2] = make_vec3(T(0), T(2), T(i));
        ClipWorkspace<T> ws;
        const ClipResult<T> r = polyhedron_triangle(a, tri, ws);
        out(i, 0) = r.area;
        out(i, 1) = r.acentroid.x;
        out(i, 2) = r.volume;
        out(i, 3) = r.vcentroid.y;
        out(i, 4) = r.S.z;
        out(i, 5) = r.M.x;
        out(i, 6) = r.normal.z;
        out(i, 7) = T(0);
        status(i) = r.status;
      });
}
#endif

#ifdef POLYDEM_CHECK_CONTACT_MODEL
// polydem_contact_law.h: contact force from the overlap geometry
template <typename T> void exercise_contact_model(int n)
{
  Kokkos::View<T *[3], Mem> shear("shear", n);
  Kokkos::View<T *[4], Mem> out("out", n);
  Kokkos::parallel_for(
      "polydem_check_contact_model", Kokkos::RangePolicy<Space>(0, n), KOKKOS_LAMBDA(const int i) {
        const Vec3<T> z = make_vec3(T(0), T(0), T(0));
        ContactGeometry<T> g;
        g.volume = T(1e-3) * T(i + 1);
        g.area = T(0.1);
        g.normal = make_vec3(T(1), T(0), T(0));
        g.centroid = make_vec3(T(0.5), T(0), T(0));
        g.S_A = make_vec3(T(-0.1), T(0), T(0));
        g.M_A = z;
        g.M_B = z;
        DampingLaw<T> d;    // damping_law(e) is host-only
        d.z[0] = T(0.1);
        d.z[1] = T(0.2);
        d.local = 1;
        ContactLaw<T> law = feng_law(T(1e6), T(0.25), T(1e-3), T(1e6), T(0.25), T(1e-3), d,
                                     T(0.3), T(1e-4), 1);
        ContactKinematics<T> kin;
        kin.xA = z;
        kin.xB = make_vec3(T(1), T(0), T(0));
        kin.vA = z;
        kin.vB = make_vec3(T(-0.1), T(0.01), T(0));
        kin.wA = z;
        kin.wB = make_vec3(T(0), T(0), T(0.5));
        kin.meff = T(0.5);
        kin.dt = T(1e-6);
        T sh[CONTACT_HIST] = {shear(i, 0), shear(i, 1), shear(i, 2), T(0), T(0)};
        const ContactForce<T> f = contact_step(g, law, kin, sh, CONTACT_HIST);
        for (int k = 0; k < 3; ++k) shear(i, k) = sh[k];
        out(i, 0) = f.F_A.x + f.tau_A.y + f.tau_B.z;
        out(i, 1) = f.energy;
        out(i, 2) = f.fn;
        out(i, 3) = f.ft;
      });
}
#endif

// A new kernel header: include it above (guarded with __has_include while it
// is being written), add an exercise_* function that calls it in a lambda,
// and instantiate it below. A kernel never called from a lambda is only
// parsed, not compiled for the device.

// Explicit instantiation: nvcc generates device code for every lambda above.
#define POLYDEM_INSTANTIATE(T)                                                                     \
  template void exercise_math<T>(int);                                                             \
  POLYDEM_INSTANTIATE_RIGID(T)                                                                     \
  POLYDEM_INSTANTIATE_GJK(T)                                                                       \
  POLYDEM_INSTANTIATE_OVERLAP(T)                                                                   \
  POLYDEM_INSTANTIATE_CLIP(T)                                                                      \
  POLYDEM_INSTANTIATE_CONTACT_MODEL(T)

#ifdef POLYDEM_CHECK_RIGID
#define POLYDEM_INSTANTIATE_RIGID(T) template void exercise_rigid<T>(int);
#else
#define POLYDEM_INSTANTIATE_RIGID(T)
#endif

#ifdef POLYDEM_CHECK_GJK
#define POLYDEM_INSTANTIATE_GJK(T) template void exercise_gjk<T>(int);
#else
#define POLYDEM_INSTANTIATE_GJK(T)
#endif
#ifdef POLYDEM_CHECK_OVERLAP
#define POLYDEM_INSTANTIATE_OVERLAP(T) template void exercise_overlap<T>(int);
#else
#define POLYDEM_INSTANTIATE_OVERLAP(T)
#endif
#ifdef POLYDEM_CHECK_CLIP
#define POLYDEM_INSTANTIATE_CLIP(T) template void exercise_clip<T>(int);
#else
#define POLYDEM_INSTANTIATE_CLIP(T)
#endif
#ifdef POLYDEM_CHECK_CONTACT_MODEL
#define POLYDEM_INSTANTIATE_CONTACT_MODEL(T) template void exercise_contact_model<T>(int);
#else
#define POLYDEM_INSTANTIATE_CONTACT_MODEL(T)
#endif

POLYDEM_INSTANTIATE(float)
POLYDEM_INSTANTIATE(double)

}    // namespace polydem_cuda_check
