/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - polyhedron-triangle contact for triangulated walls (seed 2.4):
   the section of a posed convex polyhedron with the triangle's plane,
   clipped to the triangle by Sutherland-Hodgman (Algorithm VII, Eqs. 10-11),
   and the part of the polyhedron behind the plane inside the triangle's
   prism (intersection of the polyhedron's half-spaces with the wall plane and
   the three prism sides, built by the dual Quickhull of polydem_dual_hull.h).

   Triangle (t0, t1, t2) is counter-clockwise seen from the front; its unit
   normal n_w = (t1-t0)x(t2-t0)/|..| points to the side where particles live.
   The prisms of a flat triangulated wall partition the half-space behind it,
   so summed volumes and areas do not depend on the triangulation.

   Gradients (flat wall): the volume behind an infinite flat wall has
     dV/dx = S = -n_w A,   dV/dtheta = M = -(c_A - x) x n_w A,
   with A the section area and c_A its centroid. Per triangle the kernel
   returns these with A clipped to the triangle, so that their sum over a flat
   triangulated wall is exact and F = -W'(V) S = W'(V) A n_w pushes the
   particle out of the wall (the prism sides are internal and cancel).
   Header-only, host and device.
------------------------------------------------------------------------- */

#ifndef POLYDEM_CLIP_H
#define POLYDEM_CLIP_H

#include "polydem_dual_hull.h"
#include "polydem_gjk.h"
#include "polydem_lp.h"

namespace polydem {

template <typename T> struct Triangle {
  Vec3<T> v[3];    // lab frame, CCW seen from the front
};

// Section polygon: at most one vertex per template edge, plus one per
// clipping edge. Hull: the template's planes + wall plane + 3 prism sides.
template <typename T, int MaxFaces = MAX_TEMPLATE_FACES, int MaxEdges = 3 * MAX_TEMPLATE_VERTS>
struct ClipWorkspace {
  static constexpr int MAX_POLY = MaxEdges + 4;
  static constexpr int MAX_PLANES = MaxFaces + 4 + DUAL_HULL_BOUND_PLANES;
  T pu[MAX_POLY], pv[MAX_POLY], key[MAX_POLY];    // section (2-D) and sort keys
  T qu[MAX_POLY], qv[MAX_POLY];                   // Sutherland-Hodgman ping-pong
  DualHullWorkspace<T, MAX_PLANES> hull;
};

template <typename T, int MaxFaces = MAX_TEMPLATE_FACES, int MaxEdges = 3 * MAX_TEMPLATE_VERTS>
constexpr unsigned long clip_workspace_bytes()
{
  return sizeof(ClipWorkspace<T, MaxFaces, MaxEdges>);
}

template <typename T> struct ClipResult {
  int status;           // STATUS_OK (V > 0 or A > 0), STATUS_SEPARATED (both zero),
                        // STATUS_OVERFLOW, STATUS_DEGENERATE (zero-area triangle, NaN)
  T area;               // section area inside the triangle [length^2] (Algorithm VII)
  Vec3<T> acentroid;    // its centroid (lab) [length]
  T volume;             // volume behind the plane inside the prism [length^3]
  Vec3<T> vcentroid;    // its centroid (lab) [length]
  Vec3<T> S;            // -n_w area: dV/dx of a flat wall [length^2]
  Vec3<T> M;            // -(acentroid - x) x n_w area: dV/dtheta [length^3]
  Vec3<T> normal;       // n_w
};

constexpr int CLIP_HULL_TOL = 64;      // x eps x particle radius [length]
constexpr int CLIP_TOUCH_TOL = 256;    // x eps x particle radius [length]

template <typename T> POLYDEM_FN void clip_result_zero(ClipResult<T> &r, int status)
{
  const Vec3<T> z = make_vec3(T(0), T(0), T(0));
  r.status = status;
  r.area = T(0);
  r.acentroid = z;
  r.volume = T(0);
  r.vcentroid = z;
  r.S = z;
  r.M = z;
  r.normal = z;
}

namespace clip_detail {
  // monotone in the polar angle of (x, y), range [0, 4)
  template <typename T> POLYDEM_FN T pseudo_angle(T x, T y)
  {
    const T d = fabs(x) + fabs(y);
    if (!(d > T(0))) return T(0);
    const T p = y / d;
    return x >= T(0) ? (y >= T(0) ? p : T(4) + p) : T(2) - p;
  }

  // one Sutherland-Hodgman pass (seed Algorithm VII lines 3-21): keep the part
  // of polygon (iu, iv, n) left of the directed line a -> b (CCW clip polygon).
  template <typename T>
  POLYDEM_FN int sh_pass(const T *iu, const T *iv, int n, T au, T av, T bu, T bv, T *ou, T *ov)
  {
    const T eu = bu - au, ev = bv - av;
    int m = 0;
    if (n == 0) return 0;
    T pu = iu[n - 1], pv = iv[n - 1];
    T sp = eu * (pv - av) - ev * (pu - au);    // cross2D(edgeDir, v - v0) >= 0: inside
    for (int i = 0; i < n; ++i) {
      const T cu = iu[i], cv = iv[i];
      const T sc = eu * (cv - av) - ev * (cu - au);
      const bool inc = sc >= T(0), inp = sp >= T(0);
      if (inc != inp) {    // crossing: Eqs. 10-11
        const T t = sp / (sp - sc);
        ou[m] = pu + t * (cu - pu);
        ov[m] = pv + t * (cv - pv);
        ++m;
      }
      if (inc) {
        ou[m] = cu;
        ov[m] = cv;
        ++m;
      }
      pu = cu;
      pv = cv;
      sp = sc;
    }
    return m;
  }
}    // namespace clip_detail

template <typename T, int MF, int ME> POLYDEM_FN ClipResult<T>
polyhedron_triangle(const PosedShape<T> &a, const Triangle<T> &tri, ClipWorkspace<T, MF, ME> &ws)
{
  ClipResult<T> res;
  clip_result_zero(res, STATUS_OK);
  const ShapeView<T> &sv = *a.view;
  if (sv.nfaces > MF || sv.nedges > ME || sv.nfaces < 4) {
    clip_result_zero(res, STATUS_OVERFLOW);
    return res;
  }
  const T eps = Eps<T>::value;
  const T L = posed_radius(a);    // [length]
  const Vec3<T> t0 = tri.v[0];
  const Vec3<T> e1r = tri.v[1] - t0, e2r = tri.v[2] - t0;
  const Vec3<T> nr = cross(e1r, e2r);
  const T nn = norm(nr), l1 = norm(e1r);
  if (!(L > T(0)) || !(nn > T(0)) || !(nn < T(1e30)) || !(L < T(1e30))) {
    clip_result_zero(res, STATUS_DEGENERATE);
    return res;
  }
  const Vec3<T> nw = (T(1) / nn) * nr;
  const Vec3<T> e1 = (T(1) / l1) * e1r;
  const Vec3<T> e2 = cross(nw, e1);
  res.normal = nw;
  // --- section polygon: template edges crossing the plane (2-D frame e1, e2 at t0)
  int n = 0;
  T mu = T(0), mv = T(0);
  for (int k = 0; k < sv.nedges; ++k) {
    const int i = sv.edges[2 * k], j = sv.edges[2 * k + 1];
    const Vec3<T> pi =
        a.x +
        a.s * matvec(a.R, make_vec3(sv.verts[3 * i], sv.verts[3 * i + 1], sv.verts[3 * i + 2])) -
        t0;
    const Vec3<T> pj =
        a.x +
        a.s * matvec(a.R, make_vec3(sv.verts[3 * j], sv.verts[3 * j + 1], sv.verts[3 * j + 2])) -
        t0;
    const T si = dot(nw, pi), sj = dot(nw, pj);
    if ((si < T(0)) == (sj < T(0))) continue;
    const T t = si / (si - sj);
    const Vec3<T> p = pi + t * (pj - pi);
    ws.pu[n] = dot(p, e1);
    ws.pv[n] = dot(p, e2);
    mu += ws.pu[n];
    mv += ws.pv[n];
    ++n;
  }
  T area = T(0), cu = T(0), cv = T(0);
  if (n >= 3) {
    mu /= T(n);
    mv /= T(n);
    // order the convex section counter-clockwise (insertion sort by angle)
    for (int i = 0; i < n; ++i) ws.key[i] = clip_detail::pseudo_angle(ws.pu[i] - mu, ws.pv[i] - mv);
    for (int i = 1; i < n; ++i) {
      const T k = ws.key[i], u = ws.pu[i], v = ws.pv[i];
      int j = i - 1;
      while (j >= 0 && ws.key[j] > k) {
        ws.key[j + 1] = ws.key[j];
        ws.pu[j + 1] = ws.pu[j];
        ws.pv[j + 1] = ws.pv[j];
        --j;
      }
      ws.key[j + 1] = k;
      ws.pu[j + 1] = u;
      ws.pv[j + 1] = v;
    }
    // clip polygon = the triangle in the same frame (CCW)
    const T tu[3] = {T(0), l1, dot(e2r, e1)}, tv[3] = {T(0), T(0), dot(e2r, e2)};
    int m = n;
    T *iu = ws.pu, *iv = ws.pv, *ou = ws.qu, *ov = ws.qv;
    for (int e = 0; e < 3 && m > 0; ++e) {
      m = clip_detail::sh_pass(iu, iv, m, tu[e], tv[e], tu[(e + 1) % 3], tv[(e + 1) % 3], ou, ov);
      T *su = iu, *sv2 = iv;
      iu = ou;
      iv = ov;
      ou = su;
      ov = sv2;
    }
    // area and centroid (fan from the first vertex)
    for (int i = 1; i + 1 < m; ++i) {
      const T au = iu[i] - iu[0], av = iv[i] - iv[0];
      const T bu = iu[i + 1] - iu[0], bv = iv[i + 1] - iv[0];
      const T da = T(0.5) * (au * bv - av * bu);
      area += da;
      cu += da * (iu[0] + iu[i] + iu[i + 1]) / T(3);
      cv += da * (iv[0] + iv[i] + iv[i + 1]) / T(3);
    }
    if (area > T(0)) {
      res.area = area;
      res.acentroid = t0 + (cu / area) * e1 + (cv / area) * e2;
      res.S = -area * nw;
      res.M = -area * cross(res.acentroid - a.x, nw);
    } else {
      area = T(0);
    }
  }
  // --- volume behind the plane inside the prism
  auto &w = ws.hull;
  constexpr int NB = DUAL_HULL_BOUND_PLANES;
  const int nf = sv.nfaces;
  const Vec3<T> xs = a.x;    // LP start / coordinate origin
  T *pl = w.pl + 4 * NB;
  {
    const Vec3<T> xo = a.x - xs;
    for (int f = 0; f < nf; ++f) {
      const T *q = sv.planes + 4 * f;
      const Vec3<T> nb = matvec(a.R, make_vec3(q[0], q[1], q[2]));
      pl[4 * f] = nb.x;
      pl[4 * f + 1] = nb.y;
      pl[4 * f + 2] = nb.z;
      pl[4 * f + 3] = a.s * q[3] + dot(nb, xo);
    }
    T *q = pl + 4 * nf;    // wall plane: behind is n_w . p <= n_w . t0
    q[0] = nw.x;
    q[1] = nw.y;
    q[2] = nw.z;
    q[3] = dot(nw, t0 - xs);
    for (int e = 0; e < 3; ++e) {    // prism sides, outward = edge x n_w
      const Vec3<T> ta = tri.v[e], tb = tri.v[(e + 1) % 3];
      Vec3<T> s = cross(tb - ta, nw);
      const T ls = norm(s);
      if (!(ls > T(0))) {
        clip_result_zero(res, STATUS_DEGENERATE);
        return res;
      }
      s = (T(1) / ls) * s;
      q = pl + 4 * (nf + 1 + e);
      q[0] = s.x;
      q[1] = s.y;
      q[2] = s.z;
      q[3] = dot(s, ta - xs);
    }
  }
  const int m = nf + 4;
  Vec3<T> xc;
  T r;
  chebyshev_centre(pl, m, xc, r);
  const T tol = T(CLIP_HULL_TOL) * eps * L, ttouch = T(CLIP_TOUCH_TOL) * eps * L;
  if (!(r == r)) {
    clip_result_zero(res, STATUS_DEGENERATE);
    return res;
  }
  if (r > ttouch) {
    for (int i = 0; i < m; ++i) {
      T *q = pl + 4 * i;
      q[3] -= q[0] * xc.x + q[1] * xc.y + q[2] * xc.z;
      w.owner[NB + i] = i < nf ? OWNER_A : (i == nf ? OWNER_B : OWNER_NONE);
    }
    w.nplanes = NB + m;
    const T H = T(1.5) * (norm(xc) + L) + L;    // tetrahedron around the particle
    const int st = dual_hull_build(w, H, tol);
    if (st == STATUS_OK) {
      const Vec3<T> x0 = xs + xc;
      Vec3<T> ref[2] = {a.x - x0, a.x - x0};
      HullIntegrals<T> hi;
      dual_hull_integrate(w, ref, hi);
      if (hi.volume > T(0)) {
        res.volume = hi.volume;
        res.vcentroid = x0 + (T(1) / hi.volume) * hi.vmoment;
      }
    } else if (st != STATUS_SEPARATED) {
      clip_result_zero(res, st);
      return res;
    }
  }
  if (res.volume == T(0) && res.area == T(0)) res.status = STATUS_SEPARATED;
  return res;
}

}    // namespace polydem

#endif
