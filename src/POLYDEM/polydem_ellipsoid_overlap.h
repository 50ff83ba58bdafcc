/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - exact overlap of a convex polyhedron A and an ellipsoid B
   (a sphere when its three semi-axes are equal): volume, centroid and the
   derivatives of the volume that the energy-conserving contact law needs,
   in the same OverlapResult as a polyhedron pair (polydem_overlap.h).

   Method. The affine map x' = D^-1 R_B^T (x - x_B), D = diag(a, b, c),
   takes B to the unit ball U and A to a convex polyhedron A'; volumes
   scale by det D = abc, area vectors by abc R_B D^-1, points by x_B + R_B D.
   In the mapped frame, with the ball's centre at the origin, every ray from
   the centre leaves A' through one face and enters through at most one, so
   the signed cones from the centre over the faces (sign of the face's
   offset s_f = n_f . x on its plane) add up to A' (divergence theorem; the
   decomposition of Strobl, Formella and Poeschel, J. Comput. Phys. 311
   (2016) 158, for the ball). Each cone cut by the ball is the spherical
   sector outside the face's disk D_f (radius rho = sqrt(1 - s^2) about the
   foot o_f = s_f n_f) plus the pyramid over F_f n D_f. Summed over the faces
   and using that the solid angles of all faces add up to 4 pi for a centre
   inside A' and to 0 outside,

     V' = ( 4 pi [0 in A'] - sum_f sgn(s_f) Omega(F_f n D_f)
            + sum_f s_f |F_f n D_f| ) / 3,

   where only the faces whose plane cuts the ball (|s_f| < 1) contribute.
   F_f n D_f is fanned from o_f over the face's edges: each fan triangle cut
   by the circle is a triangle from o_f and up to two circular sectors, whose
   area, first and polar moments and solid angle seen from the centre have
   closed forms (a sector of angle phi: phi (1 - |s|); a triangle: the
   Van Oosterom-Strackee formula with the apex height |s| factored out, so
   that it stays finite as s -> 0).

   The derivatives are surface integrals over A's faces inside B (the parts
   of the boundary of A n B that move with A):
     S_A = dV/dx_A = sum_f n_f |F_f n B|,
     M_A = dV/dtheta_A = sum_f int (x - x_A) x n_f dA,
     M_B = -M_A - (x_A - x_B) x S_A  (V is invariant under a common rotation);
   the centroid from the divergence theorem, int x' dV' =
     1/2 sum_f n_f ( s_f^2 |F_f n D_f| + J_f - |F_f n D_f| ),
   J_f the polar moment of F_f n D_f about o_f (on the sphere part |x'| = 1
   and its area vector is minus the sum of the flat ones).

   No workspace, no allocation: one pass over A's faces, the edges of those
   whose plane cuts the ball; host and device (POLYDEM_FN).
------------------------------------------------------------------------- */

#ifndef POLYDEM_ELLIPSOID_OVERLAP_H
#define POLYDEM_ELLIPSOID_OVERLAP_H

#include "polydem_ellipsoid.h"
#include "polydem_overlap.h"

namespace polydem {

using std::atan2;

namespace ellipsoid_overlap_detail {

  // moments of a piece of F n D in its plane, relative to the foot o
  template <typename T> struct FaceMoments {
    T area;         // signed area (counter-clockwise about n positive)
    Vec3<T> m1;     // first moment int (x - o) dA
    T J;            // polar moment int |x - o|^2 dA
    T omega;        // solid angle of F n D seen from the centre at height |s| above o
    T wout;         // solid angle of F \ D (only if robust)
    bool robust;
  };

  // apart: V = 0, every field zero
  template <typename T> POLYDEM_FN OverlapResult<T> no_overlap()
  {
    OverlapResult<T> r;
  r.status = STATUS_SEPARATED;
  r.volume = T(0);
  r.centroid = r.S_A = r.M_A = r.M_B = r.normal = make_vec3(T(0), T(0), T(0));
  r.area = T(0);
  r.depth = T(0);
  r.nverts = 0;
  r.localized = 0;
    return r;
  }

  template <typename T> POLYDEM_FN void zero(FaceMoments<T> &f, bool robust)
  {
    f.area = T(0);
    f.m1 = make_vec3(T(0), T(0), T(0));
    f.J = T(0);
    f.omega = T(0);
    f.wout = T(0);
    f.robust = robust;
  }

  // solid angle of the triangle (o, p, q) (p, q relative to o, in the plane
  // of normal n) seen from height as above o: Van Oosterom-Strackee with
  // the common factor as divided out, so that it stays finite as as -> 0
  template <typename T>
  POLYDEM_FN T foot_triangle_omega(const Vec3<T> &p, const Vec3<T> &q, const Vec3<T> &n, T as)
  {
    const T s2 = as * as;
    const T lp = sqrt(s2 + dot(p, p)), lq = sqrt(s2 + dot(q, q));
    return T(2) * atan2(dot(n, cross(p, q)), lp * lq + as * (lp + lq) + s2 + dot(p, q));
  }

  // circular sector of D (radius rho, centre o) from the direction of u1 to
  // that of u2 (relative to o, in the plane of normal n), counter-clockwise
  // about n for a positive angle; as = |s|
  template <typename T>
  POLYDEM_FN void add_sector(FaceMoments<T> &f, const Vec3<T> &u1, const Vec3<T> &u2,
                             const Vec3<T> &n, T rho, T as)
  {
    const T phi = atan2(dot(n, cross(u1, u2)), dot(u1, u2));
    if (phi == T(0)) return;
    const T l1 = norm(u1), l2 = norm(u2);
    if (!(l1 > T(0)) || !(l2 > T(0))) return;
    const T r2 = rho * rho;
    f.area += T(0.5) * phi * r2;
    // int x dA over the sector = rho^3/3 (e2 - e1) x n, e = unit directions
    const Vec3<T> de = (T(1) / l2) * u2 - (T(1) / l1) * u1;
    f.m1 += (rho * r2 / T(3)) * cross(de, n);
    f.J += T(0.25) * phi * r2 * r2;
    f.omega += phi * (T(1) - as);
    // the part of the fan triangle (o, u1, u2) beyond the circle
    if (f.robust) f.wout += foot_triangle_omega(u1, u2, n, as) - phi * (T(1) - as);
  }

  // triangle (o, p, q), p and q relative to o
  template <typename T>
  POLYDEM_FN void add_triangle(FaceMoments<T> &f, const Vec3<T> &p, const Vec3<T> &q,
                               const Vec3<T> &n, T as)
  {
    const T tr = dot(n, cross(p, q));
    const T a = T(0.5) * tr;
    const T pp = dot(p, p), qq = dot(q, q), pq = dot(p, q);
    f.area += a;
    f.m1 += (a / T(3)) * (p + q);
    f.J += (a / T(6)) * (pp + qq + pq);
    f.omega += foot_triangle_omega(p, q, n, as);
  }

  // the fan triangle (o, p, q) cut by the disk |x - o| <= rho
  template <typename T>
  POLYDEM_FN void add_edge(FaceMoments<T> &f, const Vec3<T> &p, const Vec3<T> &q,
                           const Vec3<T> &n, T rho, T as)
  {
    const Vec3<T> e = q - p;
    const T ee = dot(e, e);
    const T pe = dot(p, e);
    const T r2 = rho * rho;
    const T c0 = dot(p, p) - r2;    // |p + t e|^2 - rho^2 = ee t^2 + 2 pe t + c0
    const T disc = pe * pe - ee * c0;
    if (!(ee > T(0)) || !(disc > T(0))) {
      add_sector(f, p, q, n, rho, as);
      return;
    }
    // roots t1 <= t2, the stable way
    const T sq = sqrt(disc);
    const T qq = pe >= T(0) ? -(pe + sq) : -(pe - sq);    // = -(pe + sgn(pe) sq)
    T t1 = qq / ee, t2 = qq != T(0) ? c0 / qq : -t1;
    if (t1 > t2) {
      const T tmp = t1;
      t1 = t2;
      t2 = tmp;
    }
    const T tl = t1 > T(0) ? t1 : T(0);
    const T th = t2 < T(1) ? t2 : T(1);
    if (!(tl < th)) {    // the segment stays outside the disk
      add_sector(f, p, q, n, rho, as);
      return;
    }
    const Vec3<T> x1 = p + tl * e, x2 = p + th * e;
    if (tl > T(0)) add_sector(f, p, x1, n, rho, as);
    add_triangle(f, x1, x2, n, as);
    if (th < T(1)) add_sector(f, x2, q, n, rho, as);
  }

}    // namespace ellipsoid_overlap_detail

// Overlap of polyhedron A and ellipsoid B. Fields as for a polyhedron pair
// (OverlapResult); depth = V / (2 x the area of A's faces inside B), the
// half-thickness of a thin lens; nverts = 0. STATUS_SEPARATED when the
// mapped volume is below a round-off floor (touching or apart),
// STATUS_DEGENERATE for non-finite or non-positive input. always_robust:
// take the well-conditioned solid-angle sum even where it is not needed
// (tests compare the two).
// B given by its centre xB, rotation RB (body -> lab) and lab semi-axes.
template <typename T>
POLYDEM_FN OverlapResult<T> polyhedron_ellipsoid_overlap(const PosedShape<T> &A,
                                                         const Vec3<T> &xB, const Mat3<T> &RB,
                                                         const Vec3<T> &axes,
                                                         bool always_robust = false)
{
  namespace D = ellipsoid_overlap_detail;
  OverlapResult<T> r = D::no_overlap<T>();

  const ShapeView<T> &sv = *A.view;
  const Vec3<T> ax = axes;
  if (!(ax.x > T(0) && ax.y > T(0) && ax.z > T(0)) || !(A.s > T(0)) || sv.nfaces < 4) {
    r.status = STATUS_DEGENERATE;
    return r;
  }
  const Vec3<T> dAB = A.x - xB;
  const T amax = ax.x > ax.y ? (ax.x > ax.z ? ax.x : ax.z) : (ax.y > ax.z ? ax.y : ax.z);
  const T reach = A.s * sv.radius + amax;
  if (!(dot(dAB, dAB) <= reach * reach)) {
    if (!overlap_detail::finite3(dAB)) r.status = STATUS_DEGENERATE;
    return r;
  }

  // B's frame: Q = R_B^T R_A takes A's body axes to B's, t = A's centroid
  Mat3<T> Q;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      Q.m[i][j] = RB.m[0][i] * A.R.m[0][j] + RB.m[1][i] * A.R.m[1][j] + RB.m[2][i] * A.R.m[2][j];
  const Vec3<T> t = matTvec(RB, dAB);
  const Vec3<T> inv = make_vec3(T(1) / ax.x, T(1) / ax.y, T(1) / ax.z);
  auto map_vertex = [&](int v) {
    const T *p = sv.verts + 3 * v;
    const Vec3<T> y = t + A.s * matvec(Q, make_vec3(p[0], p[1], p[2]));
    return make_vec3(y.x * inv.x, y.y * inv.y, y.z * inv.z);
  };

  // face f's plane in the mapped frame: n' . x' = s, n' = D R_B^T n / L
  // (a sphere: n' = R_B^T n, already a unit vector, and L = r)
  const bool sphere = ax.x == ax.y && ax.x == ax.z;
  auto mapped_plane = [&](int f, Vec3<T> &n, T &s) {
    const T *pl = sv.planes + 4 * f;
    const Vec3<T> nB = matvec(Q, make_vec3(pl[0], pl[1], pl[2]));
    if (sphere) {
      n = nB;
      s = (A.s * pl[3] + dot(nB, t)) * inv.x;
      return;
    }
    const Vec3<T> nD = make_vec3(nB.x * ax.x, nB.y * ax.y, nB.z * ax.z);
    const T L = norm(nD);
    n = (T(1) / L) * nD;
    s = (A.s * pl[3] + dot(nB, t)) / L;
  };

  // pass 1: is the centre inside A', which planes cut the ball, how close
  // to the centre does the closest pass
  int inside = 1, nnear = 0;
  T smin = T(1);
  for (int f = 0; f < sv.nfaces; ++f) {
    Vec3<T> n;
    T s;
    mapped_plane(f, n, s);
    if (!(s - s == T(0))) {
      r.status = STATUS_DEGENERATE;
      return r;
    }
    if (s < T(0)) inside = 0;
    const T as = s >= T(0) ? s : -s;
    if (as < T(1)) {
      ++nnear;
      if (as < smin) smin = as;
    }
  }
  const T abc = ax.x * ax.y * ax.z;
  constexpr T FOUR_PI = T(12.566370614359172953850573533118);
  if (nnear == 0) {    // apart, or the ellipsoid inside A: all of B, no gradient
    if (inside) {
      r.status = STATUS_OK;
      r.volume = abc * FOUR_PI / T(3);
      r.centroid = xB;
      r.M_B = r.M_A = make_vec3(T(0), T(0), T(0));
    }
    return r;
  }
  // The solid-angle sum 4 pi [inside] - sum sgn(s) Omega(F n D) is exact
  // but ill-conditioned where a face plane passes within |s| of the centre
  // (Omega(F n D) then turns by ~pi over a distance ~|s|). There the sum is
  // taken as sum sgn(s) Omega(F \ D) over all faces instead: every term is
  // a smooth function of the pose.
  const bool robust = always_robust || smin < T(1e-2);

  // pass 2: the faces whose plane cuts the ball
  T omega = T(0), wout = T(0), vflat = T(0);
  Vec3<T> area_m = make_vec3(T(0), T(0), T(0));     // sum n' |F n D| (mapped)
  Vec3<T> torque_b = make_vec3(T(0), T(0), T(0));   // M_A / (abc), B's frame
  Vec3<T> moment = make_vec3(T(0), T(0), T(0));     // int x' dV' (mapped)
  T area_abs = T(0);                                  // sum |a_f| (lab)
  for (int f = 0; f < sv.nfaces; ++f) {
    Vec3<T> n;
    T s;
    mapped_plane(f, n, s);
    const int k0 = sv.face_start[f], k1 = sv.face_start[f + 1];
    // Omega(F), signed, by the fan from the face's first vertex
    auto fan_omega = [&]() {
      const Vec3<T> v0 = map_vertex(sv.face_verts[k0]);
      Vec3<T> v1 = map_vertex(sv.face_verts[k0 + 1]);
      const T l0 = norm(v0);
      T w = T(0);
      for (int k = k0 + 2; k < k1; ++k) {
        const Vec3<T> v2 = map_vertex(sv.face_verts[k]);
        const T l1 = norm(v1), l2 = norm(v2);
        w += T(2) * atan2(dot(v0, cross(v1, v2)),
                          l0 * l1 * l2 + dot(v0, v1) * l2 + dot(v0, v2) * l1 + dot(v1, v2) * l0);
        v1 = v2;
      }
      return w;
    };
    if (!(s < T(1) && s > T(-1))) {
      if (robust) wout += fan_omega();
      continue;
    }
    const Vec3<T> o = s * n;
    const T as = s >= T(0) ? s : -s;
    const T rho = sqrt((T(1) - s) * (T(1) + s));
    // the disk wholly beyond one of the face's edges: F n D is empty (its
    // fan's pieces would cancel exactly)
    {
      bool apart = false;
      const Vec3<T> first = map_vertex(sv.face_verts[k0]) - o;
      Vec3<T> p = first;
      for (int k = k0; k < k1 && !apart; ++k) {
        const Vec3<T> q = k + 1 < k1 ? map_vertex(sv.face_verts[k + 1]) - o : first;
        const Vec3<T> m = cross(q - p, n);    // outward in the face's plane
        const T out = -dot(p, m);             // |m| x distance of o beyond the edge
        apart = out > T(0) && out * out > rho * rho * dot(m, m);
        p = q;
      }
      if (apart) {
        if (robust) wout += fan_omega();
        continue;
      }
    }
    D::FaceMoments<T> fm;
    D::zero(fm, robust);
    const Vec3<T> first = map_vertex(sv.face_verts[k0]) - o;
    Vec3<T> p = first;
    for (int k = k0; k < k1; ++k) {
      const Vec3<T> q = k + 1 < k1 ? map_vertex(sv.face_verts[k + 1]) - o : first;
      D::add_edge(fm, p, q, n, rho, as);
      p = q;
    }
    const T sg = s >= T(0) ? T(1) : T(-1);
    omega += sg * fm.omega;
    wout += sg * fm.wout;
    vflat += s * fm.area;
    area_m += fm.area * n;
    // A's face inside B, back in B's frame (unscaled by abc): normal
    // D^-1 n', first moment about A's centre D (o |F n D| + m1) - t |F n D|
    const Vec3<T> nb = make_vec3(n.x * inv.x, n.y * inv.y, n.z * inv.z);
    const Vec3<T> g = fm.area * o + fm.m1;
    const Vec3<T> gB = make_vec3(g.x * ax.x, g.y * ax.y, g.z * ax.z) - fm.area * t;
    torque_b += cross(gB, nb);
    moment += (T(0.5) * ((s * s - T(1)) * fm.area + fm.J)) * n;
    area_abs += abc * norm(nb) * (fm.area >= T(0) ? fm.area : -fm.area);
  }

  const T omega_in = robust ? wout : T(inside) * FOUR_PI - omega;    // sphere inside A'
  const T vmap = (omega_in + vflat) / T(3);
  // round-off floor: the mapped terms are O(1), the unit ball's volume 4.19
  if (!(vmap > T(1024) * Eps<T>::value)) {
    if (!(vmap - vmap == T(0))) r.status = STATUS_DEGENERATE;
    return r;
  }
  r.status = STATUS_OK;
  r.volume = abc * vmap;
  const Vec3<T> cm = (T(1) / vmap) * moment;
  r.centroid = xB + matvec(RB, make_vec3(cm.x * ax.x, cm.y * ax.y, cm.z * ax.z));
  r.S_A = abc * matvec(RB, make_vec3(area_m.x * inv.x, area_m.y * inv.y, area_m.z * inv.z));
  r.M_A = abc * matvec(RB, torque_b);
  r.M_B = -r.M_A - cross(dAB, r.S_A);
  r.area = norm(r.S_A);
  if (r.area > T(0)) r.normal = (T(1) / r.area) * r.S_A;
  if (area_abs > T(0)) r.depth = r.volume / (T(2) * area_abs);
  return r;
}

template <typename T>
POLYDEM_FN OverlapResult<T> polyhedron_ellipsoid_overlap(const PosedShape<T> &A,
                                                         const EllipsoidPose<T> &B,
                                                         bool always_robust = false)
{
  return polyhedron_ellipsoid_overlap(A, B.x, quat_to_mat(B.q), B.axes, always_robust);
}

// Two spheres (a lens, two caps): V = pi (ra + rb - d)^2 (d^2 + 2 d (ra + rb)
// - 3 (ra - rb)^2) / (12 d); S_A = pi a^2 (xB - xA)/d, a the radius of the
// circle where the spheres meet; M_A = M_B = 0; the centroid from the caps'.
// A sphere inside the other: the smaller sphere, no gradient.
template <typename T>
POLYDEM_FN OverlapResult<T> sphere_pair_overlap(const Vec3<T> &xA, T ra, const Vec3<T> &xB, T rb)
{
  OverlapResult<T> r = ellipsoid_overlap_detail::no_overlap<T>();
  const Vec3<T> dv = xB - xA;
  const T d = norm(dv);
  if (!(ra > T(0) && rb > T(0)) || !(d - d == T(0))) {
    r.status = STATUS_DEGENERATE;
    return r;
  }
  if (!(d < ra + rb)) return r;
  constexpr T PI = T(3.14159265358979323846264338327950288);
  const T rmin = ra < rb ? ra : rb;
  if (d <= (ra > rb ? ra - rb : rb - ra)) {    // one inside the other
    r.status = STATUS_OK;
    r.volume = T(4) / T(3) * PI * rmin * rmin * rmin;
    r.centroid = ra < rb ? xA : xB;
    r.depth = rmin;
    return r;
  }
  const Vec3<T> n = (T(1) / d) * dv;
  // the circle's plane at distance ha from xA; the caps' heights
  const T ha = T(0.5) * (d + (ra - rb) * (ra + rb) / d);
  const T capa = ra - ha, capb = rb - (d - ha);
  const T vol_a = PI * capa * capa * (T(3) * ra - capa) / T(3);
  const T vol_b = PI * capb * capb * (T(3) * rb - capb) / T(3);
  const T V = vol_a + vol_b;
  if (!(V > T(1024) * Eps<T>::value * rmin * rmin * rmin)) return r;
  // a cap's centroid from its sphere's centre: 3 (2r - h)^2 / (4 (3r - h))
  const T za = T(3) * (T(2) * ra - capa) * (T(2) * ra - capa) / (T(4) * (T(3) * ra - capa));
  const T zb = T(3) * (T(2) * rb - capb) * (T(2) * rb - capb) / (T(4) * (T(3) * rb - capb));
  const T a2 = capa * (ra + ha);
  r.status = STATUS_OK;
  r.volume = V;
  r.centroid = xA + ((vol_a * za + vol_b * (d - zb)) / V) * n;
  r.area = PI * (a2 > T(0) ? a2 : T(0));
  r.S_A = r.area * n;
  r.normal = n;
  if (r.area > T(0)) r.depth = V / (T(2) * r.area);
  return r;
}

}    // namespace polydem

#endif
