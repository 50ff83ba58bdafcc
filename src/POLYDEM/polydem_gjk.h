/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - narrow-phase intersection test for two posed convex polyhedra:
   support function (seed Eq. 2-3), bounding-sphere rejection (seed 2.2,
   Fig. 4) and GJK (seed Algorithm I) in its distance form, which gives a
   separation distance and so a size-relative touching tolerance. The
   signed distance with witness points (gjk_witness, EPA) is in
   polydem_signed_distance.h.
   Header-only, host and device (DESIGN.md section 4).
------------------------------------------------------------------------- */

#ifndef POLYDEM_GJK_H
#define POLYDEM_GJK_H

#include "polydem_shape_view.h"

namespace polydem {

// A shape template placed in the lab frame: p_lab = x + s R p_body.
template <typename T> struct PosedShape {
  const ShapeView<T> *view;
  Vec3<T> x;    // centroid (lab)
  Mat3<T> R;    // body -> lab rotation
  T s;          // scale
};

template <typename T>
POLYDEM_FN PosedShape<T> make_posed(const ShapeView<T> &view, const Pose<T> &pose)
{
  PosedShape<T> p;
  p.view = &view;
  p.x = pose.x;
  p.R = quat_to_mat(pose.q);
  p.s = pose.s;
  return p;
}

// part k of a posed composite (the body itself if it is not one): the
// part's template at x + s R x_k, rotated by R R_k
template <typename T> POLYDEM_FN PosedShape<T> posed_part(const PosedShape<T> &body, int k)
{
  const ShapeView<T> &v = *body.view;
  if (!view_is_composite(v)) return body;
  const ShapePart<T> &p = v.parts[k];
  PosedShape<T> r;
  r.view = p.view;
  r.s = body.s;
  r.x = body.x + body.s * matvec(body.R, make_vec3(p.x[0], p.x[1], p.x[2]));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      r.R.m[i][j] = body.R.m[i][0] * p.R[0][j] + body.R.m[i][1] * p.R[1][j] +
          body.R.m[i][2] * p.R[2][j];
  return r;
}

// Bounding radius of the posed shape [length]
template <typename T> POLYDEM_FN T posed_radius(const PosedShape<T> &a)
{
  return a.s * a.view->radius;
}

// Volume of the posed shape s^3 V [length^3]
template <typename T> POLYDEM_FN T posed_volume(const PosedShape<T> &a)
{
  return a.view->volume * a.s * a.s * a.s;
}

// Index of the point of P (np points, xyz) maximising d . p. With an
// adjacency (vadj layout of ShapeView: the edges of the convex polytope
// whose vertices the points are, in any affine image): hill climbing along
// the edges from the point `start` (a vertex that is not a maximiser of a
// linear function on a convex polytope has a neighbour with a strictly
// larger value, so the climb ends at a maximiser; at most np moves).
// Without it: a scan of every point (start ignored). Ties keep the first
// point reached. The _inl form is always inlined, for the wall's per-candidate
// climbs (fix wall/mesh: 3-4 % of its time went to the calls).
template <typename T>
POLYDEM_FORCE_FN int support_index_points_inl(const T *v, int nv, const int *adj,
                                              const Vec3<T> &db, int start = 0)
{
  int best = adj != nullptr && start >= 0 && start < nv ? start : 0;
  T bestd = v[3 * best] * db.x + v[3 * best + 1] * db.y + v[3 * best + 2] * db.z;
  if (adj == nullptr) {
    for (int i = 1; i < nv; ++i) {
      const T d = v[3 * i] * db.x + v[3 * i + 1] * db.y + v[3 * i + 2] * db.z;
      if (d > bestd) {
        bestd = d;
        best = i;
      }
    }
    return best;
  }
  for (int moves = 0; moves < nv; ++moves) {
    const int cur = best;
    for (int k = adj[cur]; k < adj[cur + 1]; ++k) {
      const int i = adj[k];
      const T d = v[3 * i] * db.x + v[3 * i + 1] * db.y + v[3 * i + 2] * db.z;
      if (d > bestd) {
        bestd = d;
        best = i;
      }
    }
    if (best == cur) break;
  }
  return best;
}

template <typename T>
POLYDEM_FN int support_index_points(const T *v, int nv, const int *adj, const Vec3<T> &db,
                                    int start = 0)
{
  return support_index_points_inl(v, nv, adj, db, start);
}

// Index of the template vertex maximising db . v (db in the body frame),
// climbing along the view's vertex adjacency where it has one
template <typename T>
POLYDEM_FN int support_index(const ShapeView<T> &s, const Vec3<T> &db, int start = 0)
{
  return support_index_points(s.verts, s.nverts, s.vadj, db, start);
}

// Lab-frame position of template vertex i of the posed shape a
template <typename T> POLYDEM_FN Vec3<T> posed_vertex(const PosedShape<T> &a, int i)
{
  const T *v = a.view->verts + 3 * i;
  return a.x + a.s * matvec(a.R, make_vec3(v[0], v[1], v[2]));
}

// Seed Eq. 2: lab-frame vertex of A maximising dir . p (dir need not be unit),
// found by support_index from the vertex `start`; `start` receives the index
// found, so that a sequence of nearby directions (GJK) climbs only a little.
template <typename T>
POLYDEM_FN Vec3<T> support_point(const PosedShape<T> &a, const Vec3<T> &dir, int &start)
{
  start = support_index(*a.view, matTvec(a.R, dir), start);
  return posed_vertex(a, start);
}

template <typename T> POLYDEM_FN Vec3<T> support_point(const PosedShape<T> &a, const Vec3<T> &dir)
{
  int start = 0;
  return support_point(a, dir, start);
}

// Broad phase (seed 2.2): true if the bounding spheres overlap or touch.
template <typename T>
POLYDEM_FN bool bounding_spheres_overlap(const PosedShape<T> &a, const PosedShape<T> &b)
{
  const T rr = posed_radius(a) + posed_radius(b);
  return norm2(a.x - b.x) <= rr * rr;
}

// Size scale of a pair [length], used to scale all tolerances.
template <typename T> POLYDEM_FN T pair_length_scale(const PosedShape<T> &a, const PosedShape<T> &b)
{
  const T ra = posed_radius(a), rb = posed_radius(b);
  return ra > rb ? ra : rb;
}

constexpr int GJK_MAX_ITER = 64;    // GJK converges in < 20 iterations in practice

template <typename T> struct GjkResult {
  int status;    // STATUS_OK = intersecting (distance <= tol), STATUS_SEPARATED,
                 // STATUS_NO_CONVERGENCE (distance unknown), STATUS_DEGENERATE (NaN input)
  T distance;    // upper bound of the separation distance [length]; 0 if intersecting
  int iterations;
  // STATUS_SEPARATED: a separating axis (A lies beyond B along it by more
  // than the tolerance; not unit) and the support vertices of A along -axis
  // and of B along +axis, for gjk_axis_separates at the next step
  Vec3<T> axis;
  int ia, ib;
};

namespace gjk_detail {

  // Closest point to the origin of the simplex w[0..n-1]; reduces the simplex
  // to the support feature and returns the point. Ericson, RTCD 5.1.2/5.1.5/5.1.6.
  template <typename T> POLYDEM_FN Vec3<T> closest_segment(Vec3<T> *w, int &n)
  {
    const Vec3<T> a = w[0], b = w[1];
    const Vec3<T> ab = b - a;
    const T t = -dot(a, ab);
    if (t <= T(0)) {
      n = 1;
      return a;
    }
    const T den = dot(ab, ab);
    if (t >= den) {
      w[0] = b;
      n = 1;
      return b;
    }
    return a + (t / den) * ab;
  }

  template <typename T> POLYDEM_FN Vec3<T> closest_triangle(Vec3<T> *w, int &n)
  {
    const Vec3<T> a = w[0], b = w[1], c = w[2];
    const Vec3<T> ab = b - a, ac = c - a, ap = -a;
    const T d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= T(0) && d2 <= T(0)) {
      n = 1;
      return a;
    }
    const Vec3<T> bp = -b;
    const T d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= T(0) && d4 <= d3) {
      w[0] = b;
      n = 1;
      return b;
    }
    const T vc = d1 * d4 - d3 * d2;
    if (vc <= T(0) && d1 >= T(0) && d3 <= T(0)) {
      const T v = d1 / (d1 - d3);
      n = 2;
      return a + v * ab;
    }
    const Vec3<T> cp = -c;
    const T d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d6 >= T(0) && d5 <= d6) {
      w[0] = c;
      n = 1;
      return c;
    }
    const T vb = d5 * d2 - d1 * d6;
    if (vb <= T(0) && d2 >= T(0) && d6 <= T(0)) {
      const T v = d2 / (d2 - d6);
      w[1] = c;
      n = 2;
      return a + v * ac;
    }
    const T va = d3 * d6 - d5 * d4;
    if (va <= T(0) && (d4 - d3) >= T(0) && (d5 - d6) >= T(0)) {
      const T v = (d4 - d3) / ((d4 - d3) + (d5 - d6));
      w[0] = b;
      w[1] = c;
      n = 2;
      return b + v * (c - b);
    }
    const T den = va + vb + vc;
    if (!(den > T(0))) {    // collinear triangle: fall back to its edges
      Vec3<T> best = a;
      T bd = norm2(a);
      int keep0 = 0, keep1 = 0;
      const int pairs[3][2] = {{0, 1}, {0, 2}, {1, 2}};
      for (int k = 0; k < 3; ++k) {
        Vec3<T> s[2] = {w[pairs[k][0]], w[pairs[k][1]]};
        int m = 2;
        const Vec3<T> p = closest_segment(s, m);
        if (norm2(p) < bd) {
          bd = norm2(p);
          best = p;
          keep0 = pairs[k][0];
          keep1 = pairs[k][1];
        }
      }
      const Vec3<T> k0 = w[keep0], k1 = w[keep1];
      w[0] = k0;
      w[1] = k1;
      n = 2;
      return best;
    }
    const T v = vb / den, u = vc / den;
    n = 3;
    return a + v * ab + u * ac;
  }

  // true if the origin and d are strictly on different sides of plane (a,b,c)
  // or the tetrahedron is flat there (then the face must be examined).
  template <typename T>
  POLYDEM_FN bool origin_outside(const Vec3<T> &a, const Vec3<T> &b, const Vec3<T> &c,
                                 const Vec3<T> &d)
  {
    const Vec3<T> nrm = cross(b - a, c - a);
    const T sp = -dot(a, nrm), sd = dot(d - a, nrm);
    return sp * sd <= T(0);
  }

  template <typename T> POLYDEM_FN Vec3<T> closest_tetra(Vec3<T> *w, int &n)
  {
    const int faces[4][4] = {{0, 1, 2, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {1, 3, 2, 0}};
    T bestd = T(-1);
    Vec3<T> best = make_vec3(T(0), T(0), T(0));
    Vec3<T> bw[3] = {w[0], w[0], w[0]};
    int bn = 0;
    for (int f = 0; f < 4; ++f) {
      if (!origin_outside(w[faces[f][0]], w[faces[f][1]], w[faces[f][2]], w[faces[f][3]])) continue;
      Vec3<T> s[3] = {w[faces[f][0]], w[faces[f][1]], w[faces[f][2]]};
      int m = 3;
      const Vec3<T> p = closest_triangle(s, m);
      const T d = norm2(p);
      if (bestd < T(0) || d < bestd) {
        bestd = d;
        best = p;
        bn = m;
        for (int k = 0; k < m; ++k) bw[k] = s[k];
      }
    }
    if (bestd < T(0)) {    // origin inside the tetrahedron
      n = 4;
      return make_vec3(T(0), T(0), T(0));
    }
    for (int k = 0; k < bn; ++k) w[k] = bw[k];
    n = bn;
    return best;
  }

  // closest point of the simplex w[0..n-1] (n = 2, 3, 4) to the origin; reduces it
  template <typename T> POLYDEM_FN Vec3<T> closest_simplex(Vec3<T> *w, int &n)
  {
    if (n == 2) return closest_segment(w, n);
    if (n == 3) return closest_triangle(w, n);
    return closest_tetra(w, n);
  }

}    // namespace gjk_detail

// GJK (seed Algorithm I, distance form). Reports STATUS_OK (intersecting) if
// the polyhedra overlap or are closer than tol_rel * L, where L is the larger
// bounding radius [length]; tol_rel is dimensionless (default 1e3 eps).
template <typename T>
POLYDEM_FN GjkResult<T> gjk_intersect(const PosedShape<T> &a, const PosedShape<T> &b,
                                      T tol_rel = T(1000) * Eps<T>::value)
{
  GjkResult<T> res;
  res.status = STATUS_NO_CONVERGENCE;
  res.distance = T(0);
  res.iterations = 0;
  res.axis = make_vec3(T(0), T(0), T(0));
  res.ia = res.ib = 0;
  const T L = pair_length_scale(a, b);
  if (!(L > T(0)) || !(norm2(a.x - b.x) < T(1e30) * L * L)) {
    res.status = STATUS_DEGENERATE;    // NaN, zero or absurd input
    return res;
  }
  const T tol = tol_rel * L;    // [length]
  Vec3<T> w[4];
  int n = 0;
  // seed Algorithm I line 1: start from the centroid difference
  Vec3<T> v = a.x - b.x;
  if (norm2(v) <= tol * tol) v = make_vec3(T(1), T(0), T(0));
  int ia = 0, ib = 0;    // support vertices, each search starting from the last
  const Vec3<T> v0 = v;
  v = support_point(a, -v, ia) - support_point(b, v, ib);
  w[n++] = v;
  // the centre line itself separates with a gap larger than tol: apart (the
  // common case of near neighbours in a loose bed, decided by two supports)
  if (dot(v0, v) > tol * norm(v0)) {
    res.status = STATUS_SEPARATED;
    res.distance = norm(v);
    res.iterations = 1;
    res.axis = v0;
    res.ia = ia;
    res.ib = ib;
    return res;
  }
  for (int it = 0; it < GJK_MAX_ITER; ++it) {
    res.iterations = it + 1;
    const T vv = norm2(v);
    if (vv <= tol * tol) {
      res.status = STATUS_OK;
      return res;
    }
    // new support point of A - B in direction -v (seed Eq. 3)
    const Vec3<T> sp = support_point(a, -v, ia) - support_point(b, v, ib);
    const T vw = dot(v, sp);
    const T vn = sqrt(vv);
    // separating plane found with a gap larger than tol (seed Algorithm I line 7)
    if (vw > tol * vn) {
      res.status = STATUS_SEPARATED;
      res.distance = vn;
      res.axis = v;
      res.ia = ia;
      res.ib = ib;
      return res;
    }
    // no progress: |v| is the distance up to the relative tolerance
    if (vv - vw <= T(64) * Eps<T>::value * vv) {
      res.distance = vn;
      res.status = vn <= tol ? STATUS_OK : STATUS_SEPARATED;
      res.axis = v;
      res.ia = ia;
      res.ib = ib;
      return res;
    }
    w[n++] = sp;
    v = gjk_detail::closest_simplex(w, n);
    if (n == 4) {    // origin enclosed by the simplex
      res.status = STATUS_OK;
      return res;
    }
    if (!(norm2(v) < vv)) {    // no decrease (round-off): converged
      res.distance = sqrt(norm2(v) < vv ? norm2(v) : vv);
      res.status = res.distance <= tol ? STATUS_OK : STATUS_SEPARATED;
      res.axis = v;
      res.ia = ia;
      res.ib = ib;
      return res;
    }
  }
  res.distance = sqrt(norm2(v));
  return res;
}

// Temporal coherence of the separating axis (Ericson, Real-Time Collision
// Detection 9.5.3 "separating-axis caching"): a pair that GJK found apart
// at the last step is mostly still apart along the same axis. True if A
// lies beyond B along axis by more than GJK's tolerance, i.e.
//   min_A axis . p - max_B axis . p > tol_rel L |axis|,
// which is GJK's own separation test, so that whenever this holds
// gjk_intersect reports STATUS_SEPARATED too. The two supports climb from
// the vertices ia, ib of the last search (updated); a few dot products
// against GJK's iterations. A zero axis (no cache) gives false.
template <typename T>
POLYDEM_FN bool gjk_axis_separates(const PosedShape<T> &a, const PosedShape<T> &b,
                                   const Vec3<T> &axis, int &ia, int &ib,
                                   T tol_rel = T(1000) * Eps<T>::value)
{
  const T an2 = norm2(axis);
  if (!(an2 > T(0)) || ia < 0 || ia >= a.view->nverts || ib < 0 || ib >= b.view->nverts)
    return false;
  const T tol = tol_rel * pair_length_scale(a, b);
  const Vec3<T> sp = support_point(a, -axis, ia) - support_point(b, axis, ib);
  return dot(axis, sp) > tol * sqrt(an2);
}

// Support functor of a point set (na points, xyz): the point maximising d . p.
template <typename T> POLYDEM_FN Vec3<T> support_of_points(const T *P, int np, const Vec3<T> &d)
{
  const int best = support_index_points(P, np, (const int *) nullptr, d);
  return make_vec3(P[3 * best], P[3 * best + 1], P[3 * best + 2]);
}

// The same as a functor; with adj (the points are a posed template's
// vertices in template order, adj its vadj) the search climbs from the point
// the previous call found.
template <typename T> struct PointsSupport {
  const T *P;
  int np;
  const int *adj = nullptr;
  mutable int start = 0;
  POLYDEM_FN Vec3<T> operator()(const Vec3<T> &d) const
  {
    start = support_index_points(P, np, adj, d, start);
    return make_vec3(P[3 * start], P[3 * start + 1], P[3 * start + 2]);
  }
};

// Certified bounds lb <= d <= ub of the distance d between two convex sets
// given by their support functors sa(d), sb(d) (the point maximising d . p),
// by GJK on A - B: every support point s of A - B in direction -v gives the
// separating plane v . p >= v . s, so (v . s)/|v| bounds d from below
// whatever the convergence, and v, a point of A - B, bounds it from above.
// v: a first direction (e.g. the centres' difference). Touching or overlap
// (within tol [length]) gives lb = 0 and ub = |v| <= tol. Stops once lb >
// lo_stop, or ub <= hi_stop, or lb is within 1e-3 of ub. Bounded: at most
// GJK_MAX_ITER iterations. Works for smooth sets (ellipsoids) as well.
template <typename T, typename SA, typename SB>
POLYDEM_FN void gjk_gap_bounds(const SA &sa, const SB &sb, Vec3<T> v, T tol, T lo_stop, T hi_stop,
                               T &lb, T &ub)
{
  Vec3<T> w[4];
  int n = 0;
  if (!(norm2(v) > tol * tol)) v = make_vec3(T(1), T(0), T(0));
  v = sa(-v) - sb(v);
  w[n++] = v;
  lb = T(0);
  for (int it = 0; it < GJK_MAX_ITER; ++it) {
    const T vv = norm2(v);
    ub = sqrt(vv);
    if (!(vv > tol * tol)) {    // touching (or NaN)
      lb = T(0);
      return;
    }
    const Vec3<T> sp = sa(-v) - sb(v);
    const T vn = ub;
    const T b = dot(v, sp) / vn;
    if (b > lb) lb = b;
    if (lb > lo_stop || vn <= hi_stop || vn - lb <= T(1e-3) * vn) return;
    w[n++] = sp;
    v = gjk_detail::closest_simplex(w, n);
    if (n == 4) {    // origin enclosed: the sets overlap
      lb = ub = T(0);
      return;
    }
    if (!(norm2(v) < vv)) return;    // no progress (round-off)
  }
}

// Certified lower bound of the distance (gjk_gap_bounds), 0 if the sets
// overlap or touch; stops early once the bound exceeds stop.
template <typename T, typename SA, typename SB>
POLYDEM_FN T gjk_gap_lower_bound(const SA &sa, const SB &sb, Vec3<T> v, T tol, T stop)
{
  T lb, ub;
  gjk_gap_bounds(sa, sb, v, tol, stop, T(-1), lb, ub);
  return lb;
}

// The same for the convex hulls of the point sets A (na points) and B (nb);
// adja: A's vertex adjacency if A is a posed template's vertex set.
template <typename T>
POLYDEM_FN T hull_gap_lower_bound(const T *A, int na, const T *B, int nb, T tol, T stop,
                                  const int *adja = nullptr)
{
  PointsSupport<T> sa, sb;
  sa.P = A;
  sa.np = na;
  sa.adj = adja;
  sb.P = B;
  sb.np = nb;
  return gjk_gap_lower_bound(sa, sb, make_vec3(A[0] - B[0], A[1] - B[1], A[2] - B[2]), tol, stop);
}

}    // namespace polydem

#endif
