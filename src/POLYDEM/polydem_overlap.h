/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - overlap polyhedron of two posed convex polyhedra (seed 2.3):
   Chebyshev centre of the combined half-spaces as polarisation point x_o
   (polydem_lp.h), dual points of all face planes (Eqs. 4-5, Algorithm II),
   dual Quickhull and unpolarisation (Algorithms III-VI, polydem_dual_hull.h),
   then volume (Eq. 9), centroid and the exact gradients of V:

     S_A = int_{dA in B} n_A dA   = dV/dx_A          (S_B = -S_A)
     M_A = int_{dA in B} (p - x_A) x n_A dA = dV/dtheta_A   (rotation of A
           about x_A by the small lab-frame angle vector theta_A)
     M_B likewise for B's faces inside A about x_B.

   With a contact potential W(V) (seed 2.5, Feng) the exact forces are
     F_A = -W'(V) S_A,  tau_A = -W'(V) M_A,  F_B = +W'(V) S_A,  tau_B = -W'(V) M_B.
   S_A points from A into B; |S_A| is the contact area A_n (Eq. 13) and
   S_A / |S_A| the contact normal. (Checked by finite differences in
   unittest/kernels.) Faces lying in a plane of both particles (coincident
   faces) count half for each. Header-only, host and device.
------------------------------------------------------------------------- */

#ifndef POLYDEM_OVERLAP_H
#define POLYDEM_OVERLAP_H

#include "polydem_dual_hull.h"
#include "polydem_gjk.h"
#include "polydem_lp.h"

namespace polydem {

// Per-pair workspace. MaxFaces = the largest face count of the two templates.
template <typename T, int MaxFaces = MAX_TEMPLATE_FACES> struct OverlapWorkspace {
  static constexpr int MAX_PLANES = 2 * MaxFaces + DUAL_HULL_BOUND_PLANES;
  DualHullWorkspace<T, MAX_PLANES> hull;
};

// Bytes of one per-pair workspace (for batching on the device, seed 2.3).
template <typename T, int MaxFaces = MAX_TEMPLATE_FACES>
constexpr unsigned long overlap_workspace_bytes()
{
  return sizeof(OverlapWorkspace<T, MaxFaces>);
}

template <typename T> struct OverlapResult {
  int status;          // STATUS_OK (V > 0), STATUS_SEPARATED (V = 0, touching or apart),
                       // STATUS_OVERFLOW, STATUS_DEGENERATE (then all fields zero)
  T volume;            // overlap volume V [length^3]
  Vec3<T> centroid;    // centroid of the overlap polyhedron (lab) [length]
  Vec3<T> S_A;         // dV/dx_A [length^2]; S_B = -S_A
  Vec3<T> M_A;         // dV/dtheta_A about x_A [length^3]
  Vec3<T> M_B;         // dV/dtheta_B about x_B [length^3]
  T area;              // |S_A|, contact area [length^2]
  Vec3<T> normal;      // S_A / |S_A| (from A towards B); zero if area = 0
  T depth;             // in-radius of the overlap (Chebyshev radius) when the hull
                       // starts from a tetrahedron; V / surface area (= in-radius of
                       // a thin slab) when it starts from A's dual triangulation [length]
  int nverts;          // vertices of the overlap polyhedron
};

// Tolerances, dimensionless; multiplied by eps and the smaller bounding radius
// Lmin (plus a few eps of the larger one, L): planes cutting off less than
// HULL_TOL*eps*Lmin are redundant; an overlap with in-radius below
// TOUCH_TOL*eps*Lmin is touching (V = 0).
constexpr int OVERLAP_HULL_TOL = 64;
constexpr int OVERLAP_TOUCH_TOL = 256;

namespace overlap_detail {
  template <typename T> POLYDEM_FN bool finite3(const Vec3<T> &v)
  {
    const T s = v.x + v.y + v.z;
    return s - s == T(0);
  }

  // planes of a posed shape relative to the point o: n_lab, h = d_lab - n_lab . o
  template <typename T>
  POLYDEM_FN void posed_planes(const PosedShape<T> &a, const Vec3<T> &o, T *pl)
  {
    const ShapeView<T> &v = *a.view;
    const Vec3<T> xo = a.x - o;
    for (int f = 0; f < v.nfaces; ++f) {
      const T *q = v.planes + 4 * f;
      const Vec3<T> n = matvec(a.R, make_vec3(q[0], q[1], q[2]));
      pl[4 * f] = n.x;
      pl[4 * f + 1] = n.y;
      pl[4 * f + 2] = n.z;
      pl[4 * f + 3] = a.s * q[3] + dot(n, xo);
    }
  }
  // -1 if the posed shape o lies inside n . (p - xs) <= h - tol: the plane
  // cannot bound the overlap with o and may be dropped; else the index of
  // o's vertex furthest along n (its support, searched from `start`)
  // (ext: o's extent along n beyond the plane, n . (p_sup - xs) - h)
  template <typename T>
  POLYDEM_FN int plane_cuts(const PosedShape<T> &o, const T *q, const Vec3<T> &xs, T tol,
                            int start, T &ext)
  {
    const Vec3<T> n = make_vec3(q[0], q[1], q[2]);
    const T c = dot(n, o.x - xs);
    const T lim = q[3] - tol;
    if (c + posed_radius(o) <= lim) return -1;    // bounding sphere inside
    const Vec3<T> nb = matTvec(o.R, n);
    const int i = support_index(*o.view, nb, start);
    const T *v = o.view->verts + 3 * i;
    const T m = c + o.s * (nb.x * v[0] + nb.y * v[1] + nb.z * v[2]);
    ext = m - q[3];
    return m > lim ? i : -1;
  }
}    // namespace overlap_detail

// every field zero (value-initialised aggregate), then the status
template <typename T> POLYDEM_FN void overlap_result_zero(OverlapResult<T> &r, int status)
{
  r = OverlapResult<T>{};
  r.status = status;
}

// Overlap of two posed polyhedra. Call after GJK has reported intersection
// (it is also correct, only slower, on separated pairs).
template <typename T, int MF>
POLYDEM_FN OverlapResult<T> polyhedron_overlap(const PosedShape<T> &a, const PosedShape<T> &b,
                                               OverlapWorkspace<T, MF> &ws)
{
  OverlapResult<T> res;
  overlap_result_zero(res, STATUS_OK);
  auto &w = ws.hull;
  constexpr int NB = DUAL_HULL_BOUND_PLANES;
  const int fa = a.view->nfaces, fb = b.view->nfaces;
  if (fa > MF || fb > MF || fa < 4 || fb < 4) {
    overlap_result_zero(res, STATUS_OVERFLOW);
    return res;
  }
  const T L = pair_length_scale(a, b);    // [length]
  if (!(L > T(0)) || !overlap_detail::finite3(a.x - b.x) || !(L < T(1e30))) {
    overlap_result_zero(res, STATUS_DEGENERATE);
    return res;
  }
  const T eps = Eps<T>::value;
  // the overlap lies inside the smaller particle: scale by its radius, plus
  // the round-off of the larger one's planes
  const T ra = posed_radius(a), rb = posed_radius(b);
  const T Lmin = ra < rb ? ra : rb;
  const T tol = eps * (T(OVERLAP_HULL_TOL) * Lmin + L);               // [length]
  const T ttouch = eps * (T(OVERLAP_TOUCH_TOL) * Lmin + T(4) * L);    // [length]
  // planes relative to the start point xs (midpoint of the centroids)
  const Vec3<T> xs = T(0.5) * (a.x + b.x);
  T *pl = w.pl + 4 * NB;
  overlap_detail::posed_planes(a, xs, pl);
  overlap_detail::posed_planes(b, xs, pl + 4 * fa);
  // drop the planes of B that do not cut A: A n B' = A n B exactly. (Dropping
  // on both sides at once would not be exact: B' is larger than B.) The
  // support vertex of A along each kept plane of B is its furthest point
  // beyond it, the plane's first conflict on the seeded hull (kept in
  // w.conflict until the hull starts). The support searches start from A's
  // vertex furthest from B or nearest to it, whichever side the plane faces.
  const Vec3<T> dab = a.x - b.x;
  const Vec3<T> dab_b = matTvec(a.R, dab);
  const int far_a = support_index(*a.view, dab_b), near_a = support_index(*a.view, -dab_b);
  int ka = 0, kb = 0;
  for (int i = 0; i < fa + fb; ++i) {
    const T *q = pl + 4 * i;
    int sup = -1;
    T ext = T(0);
    if (i >= fa) {
      const int start = q[0] * dab.x + q[1] * dab.y + q[2] * dab.z > T(0) ? far_a : near_a;
      sup = overlap_detail::plane_cuts(a, q, xs, tol, start, ext);
      if (sup < 0) continue;
    }
    w.cviol[NB + ka + kb] = ext;
    T *d = pl + 4 * (ka + kb);    // compaction: d <= q
    d[0] = q[0];
    d[1] = q[1];
    d[2] = q[2];
    d[3] = q[3];
    w.conflict[NB + ka + kb] = (short) sup;
    if (i < fa)
      ++ka;
    else
      ++kb;
  }
  // Start of the hull: A itself when its template carries a dual
  // triangulation (then only B's planes are inserted, and no interior point
  // is needed to build), else a bounding tetrahedron about the Chebyshev
  // centre of both half-space systems (polarisation point, seed Eq. 4).
  const int *seed = a.view->dual;
  const bool seeded =
      seed != nullptr && seed[0] >= 4 && seed[0] <= w.MAXT && a.view->nverts <= w.MAXT;
  Vec3<T> xc = make_vec3(T(0), T(0), T(0));
  T r = T(0);
  if (!seeded) {
    chebyshev_centre(pl, ka + kb, xc, r);
    if (!(r == r)) {
      overlap_result_zero(res, STATUS_DEGENERATE);
      return res;
    }
    if (r <= ttouch) {    // touching or apart: V = 0
      overlap_result_zero(res, STATUS_SEPARATED);
      res.depth = r > T(0) ? r : T(0);
      return res;
    }
  }
  Vec3<T> x0 = xs + xc;
  // shift to x_o (seeded: xc = 0, no shift) and set owners; B planes that
  // coincide with an A plane are merged into it (owner both)
  int np = NB;
  for (int i = 0; i < ka + kb; ++i) {
    T *q = pl + 4 * i;
    const T h = seeded ? q[3] : offset_minus_dot(q[3], make_vec3(q[0], q[1], q[2]), xc);
    unsigned char own = i < ka ? OWNER_A : OWNER_B;
    // a plane of B can coincide with one of A only if A reaches just to it
    // (A's face on that plane: its extent equals h up to the offsets' tol
    // and the normals' 16 eps): the others skip the search
    const T ext = w.cviol[NB + i];
    if (i >= ka && fabs(ext) <= tol + T(64) * eps * L) {
      bool merged = false;
      for (int j = NB; j < NB + ka && !merged; ++j) {
        const T *p = w.pl + 4 * j;
        const T dx = p[0] - q[0];
        if (fabs(dx) > T(16) * eps) continue;    // the common case, decided by one component
        const T dy = p[1] - q[1], dz = p[2] - q[2];
        if (dx * dx + dy * dy + dz * dz <= T(256) * eps * eps && fabs(p[3] - h) <= tol) {
          w.owner[j] = OWNER_BOTH;
          merged = true;
        }
      }
      if (merged) continue;
    }
    T *d = w.pl + 4 * np;    // compaction: d <= q
    d[0] = q[0];
    d[1] = q[1];
    d[2] = q[2];
    d[3] = h;
    w.owner[np] = own;
    w.conflict[np] = w.conflict[NB + i];    // np <= NB + i
    ++np;
  }
  w.nplanes = np;
  int st;
  if (seeded) {
    // A's planes are NB..NB+fa-1 in face order, its vertices the seed's;
    // each vertex is posed once (w.stack maps vertex -> its first triangle:
    // a polyhedron has nverts <= 2 nfaces - 4 < MAXT)
    const int nt = seed[0];
    const Vec3<T> xa = a.x - x0;
    short *vt = w.stack;
    for (int i = 0; i < a.view->nverts; ++i) vt[i] = -1;
    for (int t = 0; t < nt; ++t) {
      const int *q = seed + 1 + DUAL_SEED_STRIDE_K * t;
      for (int e = 0; e < 3; ++e) {
        w.tc[t][e] = (short) (NB + q[e]);
        w.tadj[t][e] = (short) q[3 + e];
      }
      const int iv = q[6];
      if (vt[iv] >= 0) {
        w.P[t] = w.P[vt[iv]];
      } else {
        const T *v = a.view->verts + 3 * iv;
        w.P[t] = xa + a.s * matvec(a.R, make_vec3(v[0], v[1], v[2]));
        vt[iv] = (short) t;
      }
      w.tstate[t] = 1;
      w.tstamp[t] = -1;
    }
    w.ntslots = nt;
    for (int l = NB; l < NB + fa; ++l) w.conflict[l] = -2;
    // B's first conflicts: the triangles of their support vertices
    for (int l = NB + fa; l < np; ++l) w.conflict[l] = vt[w.conflict[l]];
    st = dual_hull_expand(w, tol, NB + fa, true);
  } else {
    // bounding tetrahedron around A (the overlap lies inside A)
    const T H = T(1.5) * (norm(a.x - x0) + posed_radius(a)) + L;
    st = dual_hull_build(w, H, tol);
  }
  if (st == STATUS_SEPARATED) {
    overlap_result_zero(res, STATUS_SEPARATED);
    return res;
  }
  if (st != STATUS_OK) {
    overlap_result_zero(res, st);
    return res;
  }
  if (seeded) {
    // integrate about a point inside the overlap (the mean of its vertices):
    // pyramids from a far point would cancel
    Vec3<T> c = make_vec3(T(0), T(0), T(0));
    int nc = 0;
    for (int t = 0; t < w.ntslots; ++t)
      if (w.tstate[t] == 1) {
        c += w.P[t];
        ++nc;
      }
    c = (T(1) / T(nc > 0 ? nc : 1)) * c;
    for (int t = 0; t < w.ntslots; ++t) w.P[t] -= c;
    // move the planes of the overlap's faces (only those are integrated;
    // w.hz_new marks them)
    for (int l = NB; l < np; ++l) w.hz_new[l] = 0;
    for (int t = 0; t < w.ntslots; ++t)
      if (w.tstate[t] == 1)
        for (int e = 0; e < 3; ++e) w.hz_new[w.tc[t][e]] = 1;
    for (int l = NB; l < np; ++l) {
      if (!w.hz_new[l]) continue;
      T *q = w.pl + 4 * l;
      q[3] = offset_minus_dot(q[3], make_vec3(q[0], q[1], q[2]), c);
    }
    x0 += c;
  }
  Vec3<T> ref[2] = {a.x - x0, b.x - x0};
  HullIntegrals<T> hi;
  dual_hull_integrate(w, ref, hi, T(1e-3) * Lmin);
  // half-thickness V / (surface area), which is the in-radius of a thin slab
  // (and r/3 of a ball): the in-radius r decides touching on the Chebyshev
  // path, this on the seeded path, with the same threshold
  const T atot = hi.area[0] + hi.area[1];
  const T thick = atot > T(0) ? hi.volume / atot : T(0);
  if (!(hi.volume > T(0)) || (seeded && thick <= ttouch)) {
    overlap_result_zero(res, STATUS_SEPARATED);
    res.depth = thick > T(0) ? thick : T(0);
    return res;
  }
  res.volume = hi.volume;
  res.centroid = x0 + (T(1) / hi.volume) * hi.vmoment;
  // S_B = -S_A exactly for the closed polyhedron; average the two for symmetry
  res.S_A = T(0.5) * (hi.S[0] - hi.S[1]);
  res.M_A = hi.M[0];
  res.M_B = hi.M[1];
  res.area = norm(res.S_A);
  res.normal = res.area > T(0) ? (T(1) / res.area) * res.S_A : make_vec3(T(0), T(0), T(0));
  res.depth = seeded ? thick : r;
  res.nverts = hi.nverts;
  return res;
}

}    // namespace polydem

#endif
