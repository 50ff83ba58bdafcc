/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - the signed distance of two posed convex polyhedra, for forces
   that act across a gap (liquid bridges): apart, their distance and nearest
   points (GJK in its distance form with witness points); overlapping, their
   penetration depth and deepest points (EPA); and the centre of the region
   their extreme features share, where the force acts when those features
   are not unique (face on face, edge on face).
   Header-only, host and device (DESIGN.md section 4).
------------------------------------------------------------------------- */

#ifndef POLYDEM_SIGNED_DISTANCE_H
#define POLYDEM_SIGNED_DISTANCE_H

#include "polydem_gjk.h"

namespace polydem {

// The distance of two separated posed convex polyhedra and its witness
// points (GJK in its distance form, Gilbert, Johnson and Keerthi, IEEE J.
// Robot. Autom. 4 (1988) 193, with the support points of A and B kept per
// simplex vertex): pa on A and pb on B with |pb - pa| = distance, so that
// the distance's gradient is -(pb - pa)/distance in A's position and
// (pa - x_A) x that in A's rotation (and the opposite for B) wherever the
// nearest features are unique. The simplex's nearest point to the origin
// is found over all its faces (at most 15 subsets of 4 points) by their
// barycentric coordinates. status: STATUS_SEPARATED (distance > tol_rel L),
// STATUS_OK (touching or overlapping: distance 0, pa pb unset),
// STATUS_NO_CONVERGENCE, STATUS_DEGENERATE.
template <typename T> struct GjkWitness {
  int status;
  T distance;
  Vec3<T> pa, pb;
  // STATUS_OK with the origin enclosed: the tetrahedron of A - B that holds
  // it (w = wa - wb), the start of epa_penetration; nsimplex < 4 otherwise
  int nsimplex = 0;
  Vec3<T> w[4], wa[4], wb[4];
};

namespace gjk_detail {
// the point of the affine hull of the points w[idx[0..k-1]] nearest to the
// origin, its barycentric coordinates lam; false if that hull is degenerate
template <typename T>
POLYDEM_FN bool affine_nearest(const Vec3<T> *w, const int *idx, int k, T *lam)
{
  if (k == 1) {
    lam[0] = T(1);
    return true;
  }
  // v = w0 + sum_j mu_j e_j, e_j = w_j - w0: G mu = -(e_j . w0)
  Vec3<T> e[3];
  T G[3][3], r[3];
  const Vec3<T> w0 = w[idx[0]];
  for (int j = 1; j < k; ++j) e[j - 1] = w[idx[j]] - w0;
  const int m = k - 1;
  T scale = T(0);
  for (int i = 0; i < m; ++i) {
    r[i] = -dot(e[i], w0);
    for (int j = 0; j < m; ++j) G[i][j] = dot(e[i], e[j]);
    scale += G[i][i];
  }
  T mu[3];
  if (m == 1) {
    if (!(G[0][0] > T(0))) return false;
    mu[0] = r[0] / G[0][0];
  } else if (m == 2) {
    const T det = G[0][0] * G[1][1] - G[0][1] * G[1][0];
    if (!(fabs(det) > T(1e-14) * scale * scale)) return false;
    mu[0] = (r[0] * G[1][1] - G[0][1] * r[1]) / det;
    mu[1] = (G[0][0] * r[1] - r[0] * G[1][0]) / det;
  } else {
    const T c00 = G[1][1] * G[2][2] - G[1][2] * G[2][1];
    const T c01 = G[1][2] * G[2][0] - G[1][0] * G[2][2];
    const T c02 = G[1][0] * G[2][1] - G[1][1] * G[2][0];
    const T det = G[0][0] * c00 + G[0][1] * c01 + G[0][2] * c02;
    if (!(fabs(det) > T(1e-14) * scale * scale * scale)) return false;
    // Cramer's rule, column by column
    for (int c = 0; c < 3; ++c) {
      T M[3][3];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) M[i][j] = j == c ? r[i] : G[i][j];
      mu[c] = (M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) -
               M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
               M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0])) /
          det;
    }
  }
  T sum = T(0);
  for (int j = 0; j < m; ++j) {
    lam[j + 1] = mu[j];
    sum += mu[j];
  }
  lam[0] = T(1) - sum;
  return true;
}
}    // namespace gjk_detail

template <typename T>
POLYDEM_FN GjkWitness<T> gjk_witness(const PosedShape<T> &a, const PosedShape<T> &b,
                                     T tol_rel = T(1000) * Eps<T>::value)
{
  GjkWitness<T> res;
  res.status = STATUS_NO_CONVERGENCE;
  res.distance = T(0);
  const T L = pair_length_scale(a, b);
  if (!(L > T(0)) || !(norm2(a.x - b.x) < T(1e30) * L * L)) {
    res.status = STATUS_DEGENERATE;
    return res;
  }
  const T tol = tol_rel * L;
  Vec3<T> wa[4], wb[4], w[4];
  T lam[4] = {T(1), T(0), T(0), T(0)};
  int n = 0, ia = 0, ib = 0;
  Vec3<T> v = a.x - b.x;
  if (norm2(v) <= tol * tol) v = make_vec3(T(1), T(0), T(0));
  wa[0] = support_point(a, -v, ia);
  wb[0] = support_point(b, v, ib);
  w[0] = wa[0] - wb[0];
  n = 1;
  v = w[0];
  for (int it = 0; it < GJK_MAX_ITER; ++it) {
    const T vv = norm2(v);
    if (vv <= tol * tol) {
      res.status = STATUS_OK;
      return res;
    }
    const Vec3<T> sa = support_point(a, -v, ia), sb = support_point(b, v, ib);
    const Vec3<T> sp = sa - sb;
    // converged: the support point adds nothing (relative gap of |v|^2)
    bool repeated = false;
    for (int k = 0; k < n; ++k) repeated = repeated || (norm2(w[k] - sp) == T(0));
    if (repeated || vv - dot(v, sp) <= T(64) * Eps<T>::value * vv) break;
    wa[n] = sa;
    wb[n] = sb;
    w[n] = sp;
    ++n;
    // the nearest point of the simplex: the valid subset (all barycentric
    // coordinates >= 0) nearest to the origin
    T best = T(-1), bl[4] = {T(0), T(0), T(0), T(0)};
    int bidx[4] = {0, 0, 0, 0}, bk = 0;
    for (int mask = 1; mask < (1 << n); ++mask) {
      int idx[4], k = 0;
      for (int j = 0; j < n; ++j)
        if (mask & (1 << j)) idx[k++] = j;
      T l[4];
      if (!gjk_detail::affine_nearest(w, idx, k, l)) continue;
      bool ok = true;
      Vec3<T> p = make_vec3(T(0), T(0), T(0));
      for (int j = 0; j < k; ++j) {
        ok = ok && l[j] >= T(0);
        p += l[j] * w[idx[j]];
      }
      if (!ok) continue;
      const T d2 = norm2(p);
      if (best < T(0) || d2 < best) {
        best = d2;
        bk = k;
        for (int j = 0; j < k; ++j) {
          bidx[j] = idx[j];
          bl[j] = l[j];
        }
      }
    }
    if (bk == 4) {    // the origin inside the tetrahedron: overlapping
      res.status = STATUS_OK;
      res.nsimplex = 4;
      for (int j = 0; j < 4; ++j) {
        res.w[j] = w[j];
        res.wa[j] = wa[j];
        res.wb[j] = wb[j];
      }
      return res;
    }
    if (!(best < vv)) break;    // no decrease (round-off): converged with the last simplex
    Vec3<T> na[4], nb[4], nw[4];
    for (int j = 0; j < bk; ++j) {
      na[j] = wa[bidx[j]];
      nb[j] = wb[bidx[j]];
      nw[j] = w[bidx[j]];
    }
    n = bk;
    v = make_vec3(T(0), T(0), T(0));
    for (int j = 0; j < n; ++j) {
      wa[j] = na[j];
      wb[j] = nb[j];
      w[j] = nw[j];
      lam[j] = bl[j];
      v += lam[j] * w[j];
    }
  }
  res.distance = sqrt(norm2(v));
  if (!(res.distance > tol)) {
    res.status = STATUS_OK;
    return res;
  }
  res.pa = make_vec3(T(0), T(0), T(0));
  res.pb = make_vec3(T(0), T(0), T(0));
  for (int j = 0; j < n; ++j) {
    res.pa += lam[j] * wa[j];
    res.pb += lam[j] * wb[j];
  }
  res.status = STATUS_SEPARATED;
  return res;
}

// The penetration of two overlapping posed convex polyhedra (EPA, the
// expanding polytope algorithm of van den Bergen, "Proximity queries and
// penetration depth computation on 3D game objects", GDC 2001): the
// smallest translation of A along -normal that makes them touch, from the
// tetrahedron of A - B that gjk_witness found around the origin. The
// polytope of A - B grows towards its face nearest to the origin until the
// support point in that face's normal adds nothing (to 64 eps of the
// size); depth = that face's distance, normal = its unit normal (from A
// towards B), pa pb the witness points on A and B (pa - pb = depth normal
// up to round-off). Minus the depth is the signed distance of A and B,
// continuous with gjk_witness's distance through contact, and its gradient
// is normal in A's position (A moved towards B deepens) and (pa - x_A) x
// normal in A's rotation wherever the deepest features are unique. Fixed
// arrays: at most EPA_MAX_FACES faces; STATUS_OK, or STATUS_NO_CONVERGENCE
// (the polytope full or the iterations spent: the best face so far),
// STATUS_DEGENERATE (no enclosing tetrahedron).
constexpr int EPA_MAX_VERTS = 64;
constexpr int EPA_MAX_FACES = 2 * EPA_MAX_VERTS - 4;    // a convex polytope's triangles

template <typename T> struct EpaResult {
  int status;
  T depth;
  Vec3<T> normal, pa, pb;
};

template <typename T>
POLYDEM_FN EpaResult<T> epa_penetration(const PosedShape<T> &a, const PosedShape<T> &b,
                                        const GjkWitness<T> &g)
{
  EpaResult<T> res;
  res.status = STATUS_DEGENERATE;
  res.depth = T(0);
  if (g.nsimplex != 4) return res;
  const T L = pair_length_scale(a, b);
  Vec3<T> w[EPA_MAX_VERTS], wa[EPA_MAX_VERTS], wb[EPA_MAX_VERTS];
  int fv[EPA_MAX_FACES][3];
  Vec3<T> fn[EPA_MAX_FACES];
  T fd[EPA_MAX_FACES];
  bool alive[EPA_MAX_FACES];
  int nv = 4, nf = 0;
  for (int j = 0; j < 4; ++j) {
    w[j] = g.w[j];
    wa[j] = g.wa[j];
    wb[j] = g.wb[j];
  }
  // face (i, j, k), counter-clockwise seen from outside (a horizon edge u -> v
  // of a removed face and the new point keep its orientation); false if it
  // is degenerate or there is no room
  auto add_face = [&](int i, int j, int k) {
    if (nf >= EPA_MAX_FACES) return false;
    Vec3<T> n = cross(w[j] - w[i], w[k] - w[i]);
    const T nn = norm(n);
    if (!(nn > T(1e-12) * (norm2(w[j] - w[i]) + norm2(w[k] - w[i])))) return false;    // a sliver
    n = (T(1) / nn) * n;
    const T d = dot(n, w[i]);
    fv[nf][0] = i;
    fv[nf][1] = j;
    fv[nf][2] = k;
    fn[nf] = n;
    fd[nf] = d;
    alive[nf] = true;
    ++nf;
    return true;
  };
  // the tetrahedron's faces, each oriented away from the opposite vertex
  const int tf[4][4] = {{0, 1, 2, 3}, {0, 1, 3, 2}, {0, 2, 3, 1}, {1, 2, 3, 0}};
  for (int f = 0; f < 4; ++f) {
    const int i = tf[f][0], j = tf[f][1], k = tf[f][2], o = tf[f][3];
    Vec3<T> n = cross(w[j] - w[i], w[k] - w[i]);
    const T nn = norm(n);
    if (!(nn > T(1e-300))) return res;
    n = (T(1) / nn) * n;
    const bool flip = dot(n, w[o] - w[i]) > T(0);
    fv[nf][0] = i;
    fv[nf][1] = flip ? k : j;
    fv[nf][2] = flip ? j : k;
    fn[nf] = flip ? -n : n;
    fd[nf] = dot(fn[nf], w[i]);
    alive[nf] = true;
    ++nf;
  }
  // the nearest point of face f to the origin, depth n, by its barycentric
  // coordinates: the witness points; false if the face is degenerate
  auto take = [&](int f, EpaResult<T> &r) {
    const int i = fv[f][0], j = fv[f][1], k = fv[f][2];
    const Vec3<T> n = fn[f], c = fd[f] * n;
    const T l0 = dot(cross(w[j] - c, w[k] - c), n), l1 = dot(cross(w[k] - c, w[i] - c), n),
            l2 = dot(cross(w[i] - c, w[j] - c), n), sum = l0 + l1 + l2;
    if (!(fabs(sum) > T(0))) return false;
    r.depth = fd[f];
    // n is the outward normal of A - B at its point nearest the origin: A
    // moved by -depth n touches B, so n points from A towards B
    r.normal = n;
    r.pa = (l0 / sum) * wa[i] + (l1 / sum) * wa[j] + (l2 / sum) * wa[k];
    r.pb = (l0 / sum) * wb[i] + (l1 / sum) * wb[j] + (l2 / sum) * wb[k];
    return true;
  };
  // grow until the support point in the nearest face's normal adds nothing;
  // out of room, or a face that cannot be made: the last valid polytope's
  // nearest face, STATUS_NO_CONVERGENCE (a lower bound of the depth)
  const T tol = T(4096) * Eps<T>::value * L;    // 1e-12 of the size in double
  for (int it = 0; it < EPA_MAX_VERTS; ++it) {
    int best = -1;
    for (int f = 0; f < nf; ++f)
      if (alive[f] && (best < 0 || fd[f] < fd[best])) best = f;
    if (best < 0 || !take(best, res)) {
      res.status = it ? STATUS_NO_CONVERGENCE : STATUS_DEGENERATE;
      return res;
    }
    res.status = STATUS_NO_CONVERGENCE;
    const Vec3<T> n = fn[best];
    int ia = 0, ib = 0;
    const Vec3<T> sa = support_point(a, n, ia), sb = support_point(b, -n, ib);
    const Vec3<T> p = sa - sb;
    if (dot(n, p) - fd[best] <= tol) {
      res.status = STATUS_OK;
      return res;
    }
    if (nv >= EPA_MAX_VERTS) return res;
    // the faces that see p; their edges not shared by two of them form the
    // horizon (checked before anything changes: no room, no change)
    int edges[EPA_MAX_FACES + 2][2];
    int ne = 0, nsee = 0;
    bool room = true;
    // (a face that p lies on, to round-off, is seen too: ties in the
    // support searches put p on an edge or face of A - B, and a face kept
    // in p's plane would leave a sliver of no normal along that edge)
    const T vis = T(64) * Eps<T>::value * L;
    for (int f = 0; f < nf && room; ++f) {
      if (!alive[f] || !(dot(fn[f], p - w[fv[f][0]]) > -vis)) continue;
      ++nsee;
      for (int e = 0; e < 3 && room; ++e) {
        const int u = fv[f][e], v = fv[f][(e + 1) % 3];
        bool shared = false;
        for (int k = 0; k < ne; ++k)
          if (edges[k][0] == v && edges[k][1] == u) {    // the neighbour's reverse edge
            edges[k][0] = edges[ne - 1][0];
            edges[k][1] = edges[ne - 1][1];
            --ne;
            shared = true;
            break;
          }
        if (!shared) {
          room = ne < EPA_MAX_FACES + 2;
          if (room) {
            edges[ne][0] = u;
            edges[ne][1] = v;
            ++ne;
          }
        }
      }
    }
    if (!room || nsee == 0 || nf + ne > EPA_MAX_FACES) return res;
    // the new faces first (a degenerate one: stop with the polytope as it was)
    w[nv] = p;
    wa[nv] = sa;
    wb[nv] = sb;
    const int q = nv;
    const int nf0 = nf;
    bool ok = true;
    for (int k = 0; k < ne && ok; ++k) ok = add_face(edges[k][0], edges[k][1], q);
    if (!ok) return res;
    ++nv;
    // drop the faces that see p
    int m = 0;
    for (int f = 0; f < nf; ++f) {
      const bool seen = f < nf0 && alive[f] && dot(fn[f], p - w[fv[f][0]]) > -vis;
      if (!alive[f] || seen) continue;
      for (int c = 0; c < 3; ++c) fv[m][c] = fv[f][c];
      fn[m] = fn[f];
      fd[m] = fd[f];
      alive[m] = true;
      ++m;
    }
    nf = m;
  }
  return res;
}

// Where the pull between two convex polyhedra along the unit normal n (from
// A towards B) acts when their nearest (apart) or deepest (overlapping)
// features are not unique, as between parallel faces or edges: the centre
// of the region their extreme features share, so that it does not jump
// with round-off between corners of the region as GJK's or EPA's witness
// points do. A's vertices within 1e-9 of the size of its extreme plane
// along n, B's of its extreme plane along -n, projected on the plane normal
// to n: the intersection of their convex hulls (a polygon, a segment or a
// point), its centroid, on the plane midway between the two. Unique
// features (a vertex against a face, crossing edges) give the witness point
// itself. fallback (the witness points' midpoint) where the region is empty
// after round-off or the bands hold more than WITNESS_MAX_BAND vertices.
constexpr int WITNESS_MAX_BAND = 32;

namespace gjk_detail {
template <typename T> struct P2 {
  T x, y;
};
template <typename T> POLYDEM_FN T cross2(const P2<T> &o, const P2<T> &a, const P2<T> &b)
{
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}
// convex hull of p[0..n-1] in place, counter-clockwise (Andrew's monotone
// chain; collinear points dropped); returns its size (1 or 2 for a point or
// a segment)
template <typename T> POLYDEM_FN int hull2(P2<T> *p, int n, T tol)
{
  for (int i = 1; i < n; ++i) {    // insertion sort by x, then y
    const P2<T> k = p[i];
    int j = i - 1;
    while (j >= 0 && (p[j].x > k.x || (p[j].x == k.x && p[j].y > k.y))) {
      p[j + 1] = p[j];
      --j;
    }
    p[j + 1] = k;
  }
  if (n < 3) {
    if (n == 2 && fabs(p[0].x - p[1].x) + fabs(p[0].y - p[1].y) <= tol) return 1;
    return n;
  }
  P2<T> h[2 * WITNESS_MAX_BAND + 2];
  int k = 0;
  for (int i = 0; i < n; ++i) {
    while (k >= 2 && cross2(h[k - 2], h[k - 1], p[i]) <= tol * tol) --k;
    h[k++] = p[i];
  }
  for (int i = n - 2, t = k + 1; i >= 0; --i) {
    while (k >= t && cross2(h[k - 2], h[k - 1], p[i]) <= tol * tol) --k;
    h[k++] = p[i];
  }
  k = k > 1 ? k - 1 : k;
  if (k == 2 && fabs(h[0].x - h[1].x) + fabs(h[0].y - h[1].y) <= tol) k = 1;
  if (k < 1) {
    k = 1;
    h[0] = p[0];
  }
  // all collinear: the chain gives the two ends
  for (int i = 0; i < k; ++i) p[i] = h[i];
  return k;
}
}    // namespace gjk_detail

template <typename T>
POLYDEM_FN Vec3<T> witness_region_centre(const PosedShape<T> &a, const PosedShape<T> &b,
                                         const Vec3<T> &n, const Vec3<T> &fallback)
{
  using gjk_detail::P2;
  const T L = pair_length_scale(a, b), eps = T(1e-9) * L;
  const Vec3<T> t1 = any_perpendicular(n), t2 = cross(n, t1);
  P2<T> pa[WITNESS_MAX_BAND], pb[WITNESS_MAX_BAND];
  T ha = T(0), hb = T(0);
  // the band of shape s's vertices within eps of its extreme plane along d
  // (sign +1: the largest n . p; -1: the smallest), projected
  auto band = [&](const PosedShape<T> &sh, T sign, P2<T> *out, T &h) {
    const int nv = sh.view->nverts;
    h = T(-1e300);
    for (int i = 0; i < nv; ++i) {
      const T d = sign * dot(n, posed_vertex(sh, i));
      h = d > h ? d : h;
    }
    int k = 0;
    for (int i = 0; i < nv; ++i) {
      const Vec3<T> v = posed_vertex(sh, i);
      if (sign * dot(n, v) < h - eps) continue;
      if (k >= WITNESS_MAX_BAND) return -1;
      out[k].x = dot(t1, v);
      out[k].y = dot(t2, v);
      ++k;
    }
    h *= sign;
    return k;
  };
  int na = band(a, T(1), pa, ha), nb = band(b, T(-1), pb, hb);
  if (na < 1 || nb < 1) return fallback;
  na = gjk_detail::hull2(pa, na, eps);
  nb = gjk_detail::hull2(pb, nb, eps);
  const T mid = T(0.5) * (ha + hb);
  auto lift = [&](T x, T y) { return x * t1 + y * t2 + mid * n; };
  // a point against anything: the point
  if (na == 1) return lift(pa[0].x, pa[0].y);
  if (nb == 1) return lift(pb[0].x, pb[0].y);
  // two segments: their crossing, or the middle of their common part
  if (na == 2 && nb == 2) {
    const T dx = pa[1].x - pa[0].x, dy = pa[1].y - pa[0].y;
    const T ex = pb[1].x - pb[0].x, ey = pb[1].y - pb[0].y;
    const T den = dx * ey - dy * ex;
    const T la = sqrt(dx * dx + dy * dy), lb = sqrt(ex * ex + ey * ey);
    if (fabs(den) > T(1e-9) * la * lb) {
      const T t = ((pb[0].x - pa[0].x) * ey - (pb[0].y - pa[0].y) * ex) / den;
      return lift(pa[0].x + t * dx, pa[0].y + t * dy);
    }
    // parallel: the overlap of the two intervals along the first
    const T ux = dx / la, uy = dy / la;
    const T b0 = (pb[0].x - pa[0].x) * ux + (pb[0].y - pa[0].y) * uy;
    const T b1 = (pb[1].x - pa[0].x) * ux + (pb[1].y - pa[0].y) * uy;
    const T lo = fmax(T(0), fmin(b0, b1)), hi = fmin(la, fmax(b0, b1));
    if (!(hi >= lo)) return fallback;
    const T c = T(0.5) * (lo + hi);
    return lift(pa[0].x + c * ux, pa[0].y + c * uy);
  }
  // a segment against a polygon: the part of the segment inside it
  if (na == 2 || nb == 2) {
    const P2<T> *sg = na == 2 ? pa : pb, *pg = na == 2 ? pb : pa;
    const int m = na == 2 ? nb : na;
    T lo = T(0), hi = T(1);
    const T dx = sg[1].x - sg[0].x, dy = sg[1].y - sg[0].y;
    for (int i = 0; i < m; ++i) {
      const P2<T> &q0 = pg[i], &q1 = pg[(i + 1) % m];
      // inside: cross(q1 - q0, p - q0) >= 0, p = sg0 + t d
      const T c0 = gjk_detail::cross2(q0, q1, sg[0]);
      const T cd = (q1.x - q0.x) * dy - (q1.y - q0.y) * dx;
      if (cd > T(0)) lo = fmax(lo, -c0 / cd);
      else if (cd < T(0)) hi = fmin(hi, -c0 / cd);
      else if (c0 < T(0)) return fallback;
    }
    if (!(hi >= lo)) return fallback;
    const T t = T(0.5) * (lo + hi);
    return lift(sg[0].x + t * dx, sg[0].y + t * dy);
  }
  // two polygons: A's clipped by each edge of B (Sutherland-Hodgman), the
  // area centroid of what is left
  P2<T> buf[2][2 * WITNESS_MAX_BAND + 2];
  int cnt = na, cur = 0;
  for (int i = 0; i < na; ++i) buf[0][i] = pa[i];
  for (int e = 0; e < nb && cnt > 0; ++e) {
    const P2<T> &q0 = pb[e], &q1 = pb[(e + 1) % nb];
    const P2<T> *in = buf[cur];
    P2<T> *out = buf[1 - cur];
    int k = 0;
    for (int i = 0; i < cnt; ++i) {
      const P2<T> &p0 = in[i], &p1 = in[(i + 1) % cnt];
      const T s0 = gjk_detail::cross2(q0, q1, p0), s1 = gjk_detail::cross2(q0, q1, p1);
      if (s0 >= T(0) && k < 2 * WITNESS_MAX_BAND + 2) out[k++] = p0;
      if ((s0 >= T(0)) != (s1 >= T(0)) && k < 2 * WITNESS_MAX_BAND + 2) {
        const T t = s0 / (s0 - s1);
        out[k].x = p0.x + t * (p1.x - p0.x);
        out[k].y = p0.y + t * (p1.y - p0.y);
        ++k;
      }
    }
    cnt = k;
    cur = 1 - cur;
  }
  if (cnt == 0) return fallback;
  const P2<T> *r = buf[cur];
  T A = T(0), cx = T(0), cy = T(0), mx = T(0), my = T(0);
  for (int i = 0; i < cnt; ++i) {
    const P2<T> &p0 = r[i], &p1 = r[(i + 1) % cnt];
    const T c = p0.x * p1.y - p1.x * p0.y;
    A += c;
    cx += (p0.x + p1.x) * c;
    cy += (p0.y + p1.y) * c;
    mx += p0.x;
    my += p0.y;
  }
  if (fabs(A) > T(1e-12) * L * L) return lift(cx / (T(3) * A), cy / (T(3) * A));
  return lift(mx / T(cnt), my / T(cnt));    // a sliver: the mean of its corners
}

}    // namespace polydem

#endif
