/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - overlap polyhedron of two posed convex polyhedra (seed 2.3):
   dual points of the face planes (Eqs. 4-5, Algorithm II), dual Quickhull
   and unpolarisation (Algorithms III-VI, polydem_dual_hull.h), then volume
   (Eq. 9), centroid and the exact gradients of V. The hull starts from the
   part of A facing B, cut from A's precomputed dual triangulation, and only
   B's planes near A are inserted (local_seeded_hull: the seed's Sec. 5
   localization to the contacting faces); the full path (all of A, or a
   bounding tetrahedron about the Chebyshev centre x_o of both half-space
   systems, polydem_lp.h) serves templates without a dual triangulation and
   the rare pairs where the local start is not a simple cut.

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
  // both shapes' planes, the bounding ones and the localized path's cut
  static constexpr int MAX_PLANES = 2 * MaxFaces + DUAL_HULL_BOUND_PLANES + 1;
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
  int localized;       // 1: built by the localized start (local_seeded_hull)
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

  // plane f of a posed shape relative to the hull origin (xo = a.x - origin):
  // n_lab, h = d_lab - n_lab . origin, into d[0..3]
  template <typename T>
  POLYDEM_FN void posed_plane(const PosedShape<T> &a, int f, const Vec3<T> &xo, T *d)
  {
    const T *q = a.view->planes + 4 * f;
    const Vec3<T> n = matvec(a.R, make_vec3(q[0], q[1], q[2]));
    d[0] = n.x;
    d[1] = n.y;
    d[2] = n.z;
    d[3] = a.s * q[3] + dot(n, xo);
  }
  // all planes of a posed shape relative to the point o
  template <typename T>
  POLYDEM_FN void posed_planes(const PosedShape<T> &a, const Vec3<T> &o, T *pl)
  {
    const Vec3<T> xo = a.x - o;
    for (int f = 0; f < a.view->nfaces; ++f) posed_plane(a, f, xo, pl + 4 * f);
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
  // vertex iv of the posed shape a, relative to the hull origin (xa = a.x - x0)
  template <typename T>
  POLYDEM_FN Vec3<T> posed_vertex(const PosedShape<T> &a, const Vec3<T> &xa, int iv)
  {
    const T *v = a.view->verts + 3 * iv;
    return xa + a.s * matvec(a.R, make_vec3(v[0], v[1], v[2]));
  }

  // Localized start (the polyhedral seed's Sec. 5 "overlap calculations
  // confined to the contacting facets"). Along the centre line n (A -> B),
  // B lies in n . p >= sB and A in n . p <= sA. The overlap's faces lie on
  // faces of A that meet B and faces of B that meet A, and its half-spaces
  // define it exactly; a face of B meets A only if one of its vertices has
  // n . p <= sA, and B lies in the half-space pi: n . p >= sB - delta. So
  //   A n B = (A n pi) n {B's planes of faces reaching below sA},
  // exactly. A n pi is cut from A's dual triangulation directly: its kept
  // vertices are known from the projections (no flood fill over the part of
  // A that pi removes), and only A's planes on the kept part are posed.
  // pi (owner none) lies delta outside B, so B's planes remove its face
  // entirely; if round-off leaves a trace of it, or the cut is not a simple
  // ring, the caller takes the full path. Returns STATUS_OK (the hull is in
  // w, np planes, x0 its origin), STATUS_SEPARATED, or OVERLAP_FULL_PATH.
  constexpr int OVERLAP_FULL_PATH = -100;
  template <typename T, int MP>
  POLYDEM_FN int local_seeded_hull(const PosedShape<T> &a, const PosedShape<T> &b,
                                   DualHullWorkspace<T, MP> &w, T tol, T Lmin, const Vec3<T> &x0,
                                   int &np)
  {
    constexpr int NB = DUAL_HULL_BOUND_PLANES;
    const ShapeView<T> &va = *a.view, &vb = *b.view;
    const int fa = va.nfaces, fb = vb.nfaces, nva = va.nverts, nvb = vb.nverts;
    if (nva + nvb > w.MAXT || NB + fa + 1 + fb > MP) return OVERLAP_FULL_PATH;
    Vec3<T> n = b.x - a.x;
    const T nn = norm(n);
    n = nn > T(0) ? (T(1) / nn) * n : make_vec3(T(0), T(0), T(1));
    // projections n . (p - x0) of every vertex: A's in tviol[0..nva), B's after
    T *pa = w.tviol, *pb = w.tviol + nva;
    T sA = -T(1e30), sB = T(1e30);
    // A template's dual triangles are the fans of its vertices in vertex
    // order (polydem_dual_seed.h), vertex v's the dual_fan_first(v) ..
    // + degree - 3: where both have the vertex adjacency, the kept part of A
    // and B's reaching faces are found from the vertices concerned, not by
    // a scan of every triangle. act and freelist are scratch until the hull
    // starts (dual_hull_expand sets them up).
    const bool fans = va.vadj != nullptr && vb.vadj != nullptr && vb.dual != nullptr;
    short *low = w.act;
    int nlow = 0;
    {
      const Vec3<T> na = a.s * matTvec(a.R, n), nb = b.s * matTvec(b.R, n);
      const T ca = dot(n, a.x - x0), cb = dot(n, b.x - x0);
      for (int i = 0; i < nva; ++i) {
        const T *v = va.verts + 3 * i;
        pa[i] = ca + na.x * v[0] + na.y * v[1] + na.z * v[2];
        sA = pa[i] > sA ? pa[i] : sA;
      }
      for (int i = 0; i < nvb; ++i) {
        const T *v = vb.verts + 3 * i;
        pb[i] = cb + nb.x * v[0] + nb.y * v[1] + nb.z * v[2];
        sB = pb[i] < sB ? pb[i] : sB;
        low[nlow] = (short) i;    // B's vertices that reach below sA + tol
        nlow += pb[i] <= sA + tol;
      }
    }
    if (sB > sA + tol) return STATUS_SEPARATED;    // n separates them
    // pi as a hull plane: (-n) . P <= -(sB - delta); its violation at an A
    // vertex is (sB - delta) - pa[i]
    const T cut = sB - (T(1e-6) * Lmin + T(16) * tol);
    const int ipi = NB + fa;
    {
      T *q = w.pl + 4 * ipi;
      q[0] = -n.x;
      q[1] = -n.y;
      q[2] = -n.z;
      q[3] = -cut;
      w.owner[ipi] = OWNER_NONE;
      w.conflict[ipi] = -2;
    }
    // A n pi from A's dual triangulation: kept triangles (their vertex within
    // tol of pi or inside) get compact slots 0..nk-1 (w.stack: old -> new)
    const int *seed = va.dual;
    const int nt = seed[0];
    short *map = w.stack;
    short *kept = w.freelist;    // the kept triangles, ascending
    int nk = 0;
    if (fans) {
      for (int t = 0; t < nt; ++t) map[t] = -1;
      for (int i = 0; i < nva; ++i) {
        if (!(cut - pa[i] <= tol)) continue;
        const int t0 = dual_fan_first(va, i), t1 = t0 + va.vadj[i + 1] - va.vadj[i] - 2;
        for (int t = t0; t < t1; ++t) {
          kept[nk] = (short) t;
          map[t] = (short) nk++;
        }
      }
    } else {
      for (int t = 0; t < nt; ++t) {
        const int iv = seed[1 + DUAL_SEED_STRIDE_K * t + 6];
        kept[nk] = (short) t;
        map[t] = cut - pa[iv] <= tol ? (short) nk++ : (short) -1;
      }
    }
    if (nk == 0) return STATUS_SEPARATED;
    // A's planes on the kept part are posed once (w.hz_new[l] = 1 marks them,
    // w.hz_tri lists them and w.cviol their n.x until the hull starts);
    // each vertex is posed once (w.vis: vertex -> its first slot)
    short *vslot = w.vis;
    for (int i = 0; i < nva; ++i) vslot[i] = -1;
    for (int f = 0; f < fa; ++f) w.hz_new[NB + f] = 0;
    const Vec3<T> xa = a.x - x0;
    int nka = 0;    // A's kept planes, listed in w.hz_tri
    int ns = nk;    // slots: kept ones first, then the ring of new ones on pi
    for (int i = 0; i <= ipi; ++i) w.new_by_start[i] = w.new_by_end[i] = -1;
    for (int kk = 0; kk < nk; ++kk) {
      const int t = kept[kk];
      const short k = (short) kk;
      const int *q = seed + 1 + DUAL_SEED_STRIDE_K * t;
      const int iv = q[6];
      w.tstate[k] = 1;
      if (vslot[iv] >= 0) {    // a vertex of degree d is d - 2 triangles
        w.P[k] = w.P[vslot[iv]];
        w.tstamp[k] = DUAL_HULL_COPY;
      } else {
        w.P[k] = posed_vertex(a, xa, iv);
        vslot[iv] = k;
        w.tstamp[k] = -1;
      }
      for (int e = 0; e < 3; ++e) {
        const short l = (short) (NB + q[e]);
        w.tc[k][e] = l;
        if (!w.hz_new[l]) {
          w.hz_new[l] = 1;
          posed_plane(a, q[e], xa, w.pl + 4 * l);
          w.cviol[nka] = w.pl[4 * l];    // n.x, for the coincident-plane check
          w.hz_tri[nka++] = l;
          w.owner[l] = OWNER_A;
          w.conflict[l] = -2;
        }
      }
      for (int e = 0; e < 3; ++e) {
        const int r = q[3 + e];
        if (map[r] >= 0) {
          w.tadj[k][e] = map[r];
          continue;
        }
        // edge (u, v) of the removed neighbour r becomes the new triangle
        // (u, v, pi), as dual_hull_expand builds it; its vertex is where pi
        // cuts the primal edge from r's vertex to k's
        if (ns >= w.MAXT) return OVERLAP_FULL_PATH;
        const short u = (short) (NB + q[(e + 1) % 3]), v = (short) (NB + q[e]);
        if (w.new_by_start[u] != -1 || w.new_by_end[v] != -1) return OVERLAP_FULL_PATH;
        const short s = (short) ns++;
        w.new_by_start[u] = s;
        w.new_by_end[v] = s;
        const int ir = seed[1 + DUAL_SEED_STRIDE_K * r + 6];
        const T v1 = cut - pa[ir], v2 = cut - pa[iv];
        T f = v1 / (v1 - v2);
        f = f < T(0) ? T(0) : (f > T(1) ? T(1) : f);
        const Vec3<T> Pr = posed_vertex(a, xa, ir);
        w.P[s] = Pr + f * (w.P[k] - Pr);
        w.tc[s][0] = u;
        w.tc[s][1] = v;
        w.tc[s][2] = (short) ipi;
        w.tadj[s][0] = k;
        w.tadj[k][e] = s;
        w.tstate[s] = 1;
        w.tstamp[s] = -1;
      }
    }
    // link the ring: edge (v, pi) meets the new triangle starting at v,
    // edge (pi, u) the one ending at u
    for (int s = nk; s < ns; ++s) {
      const short ks = w.new_by_start[w.tc[s][1]], ke = w.new_by_end[w.tc[s][0]];
      if (ks < 0 || ke < 0) return OVERLAP_FULL_PATH;
      w.tadj[s][1] = ks;
      w.tadj[s][2] = ke;
    }
    for (int s = nk; s < ns; ++s) w.new_by_start[w.tc[s][0]] = w.new_by_end[w.tc[s][1]] = -1;
    w.ntslots = ns;
    // B's planes whose faces reach below sA (+ tol), posed; a plane of B that
    // coincides with one of A's kept planes is merged into it (owner both)
    // (marked in w.hz_edge through B's dual triangulation where it has one:
    // each triangle names a vertex and three of its faces, and the fan of a
    // vertex names all its faces)
    const Vec3<T> xb = b.x - x0;
    np = ipi + 1;
    short *reach = w.hz_edge;
    if (fans && fb <= MP) {
      for (int f = 0; f < fb; ++f) reach[f] = 0;
      for (int k = 0; k < nlow; ++k) {
        const int i = low[k];
        const int t0 = dual_fan_first(vb, i), t1 = t0 + vb.vadj[i + 1] - vb.vadj[i] - 2;
        for (int t = t0; t < t1; ++t) {
          const int *q = vb.dual + 1 + DUAL_SEED_STRIDE_K * t;
          reach[q[0]] = reach[q[1]] = reach[q[2]] = 1;
        }
      }
    } else if (vb.dual != nullptr && fb <= MP) {
      for (int f = 0; f < fb; ++f) reach[f] = 0;
      const int *sb = vb.dual;
      for (int t = 0; t < sb[0]; ++t) {
        const int *q = sb + 1 + DUAL_SEED_STRIDE_K * t;
        if (pb[q[6]] <= sA + tol) reach[q[0]] = reach[q[1]] = reach[q[2]] = 1;
      }
    } else {
      for (int f = 0; f < fb; ++f) {
        reach[f] = 0;
        for (int k = vb.face_start[f]; k < vb.face_start[f + 1] && !reach[f]; ++k)
          reach[f] = pb[vb.face_verts[k]] <= sA + tol;
      }
    }
    for (int f = 0; f < fb; ++f) {
      if (!reach[f]) continue;
      // posed into slot np, kept there unless merged
      T *d = w.pl + 4 * np;
      posed_plane(b, f, xb, d);
      bool merged = false;
      for (int i = 0; i < nka && !merged; ++i) {
        const T dx = w.cviol[i] - d[0];
        if (fabs(dx) > T(16) * Eps<T>::value) continue;
        const int j = w.hz_tri[i];
        const T *pj = w.pl + 4 * j;
        const T dy = pj[1] - d[1], dz = pj[2] - d[2];
        if (dx * dx + dy * dy + dz * dz <= T(256) * Eps<T>::value * Eps<T>::value &&
            fabs(pj[3] - d[3]) <= tol) {
          w.owner[j] = OWNER_BOTH;
          merged = true;
        }
      }
      if (merged) continue;
      w.owner[np] = OWNER_B;
      ++np;
    }
    w.nplanes = np;
    const int st = dual_hull_expand(w, tol, ipi + 1, false);
    if (st != STATUS_OK) return st == STATUS_SEPARATED ? st : OVERLAP_FULL_PATH;
    for (int t = 0; t < w.ntslots; ++t)
      if (w.tstate[t] == 1 && (w.tc[t][0] == ipi || w.tc[t][1] == ipi || w.tc[t][2] == ipi))
        return OVERLAP_FULL_PATH;
    return STATUS_OK;
  }
}    // namespace overlap_detail

// every field zero (value-initialised aggregate), then the status
template <typename T> POLYDEM_FN void overlap_result_zero(OverlapResult<T> &r, int status)
{
  r = OverlapResult<T>{};
  r.status = status;
}

namespace overlap_detail {
  // V, centroid, gradients from the hull in w (np planes, origin x0): shared
  // by the localized and the full path. seeded: the hull started from A's
  // dual triangulation (touching is decided by V / surface area), else from a
  // tetrahedron about the Chebyshev centre of in-radius r.
  template <typename T, int MP>
  POLYDEM_FN OverlapResult<T> hull_result(DualHullWorkspace<T, MP> &w, int np, Vec3<T> x0,
                                          bool seeded, T r, const PosedShape<T> &a,
                                          const PosedShape<T> &b, T Lmin, T ttouch)
  {
    constexpr int NB = DUAL_HULL_BOUND_PLANES;
    OverlapResult<T> res;
    overlap_result_zero(res, STATUS_OK);
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
}    // namespace overlap_detail

// Overlap of two posed polyhedra. Call after GJK has reported intersection
// (it is also correct, only slower, on separated pairs). localize = false
// takes the full path (for the tests that compare the two).
template <typename T, int MF>
POLYDEM_FN OverlapResult<T> polyhedron_overlap(const PosedShape<T> &a, const PosedShape<T> &b,
                                               OverlapWorkspace<T, MF> &ws, bool localize = true)
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
  const int *seed = a.view->dual;
  const bool seeded =
      seed != nullptr && seed[0] >= 4 && seed[0] <= w.MAXT && a.view->nverts <= w.MAXT;
  if (seeded && localize) {
    int np = 0;
    const int st = overlap_detail::local_seeded_hull(a, b, w, tol, Lmin, xs, np);
    if (st == STATUS_OK) {
      res = overlap_detail::hull_result(w, np, xs, true, T(0), a, b, Lmin, ttouch);
      res.localized = 1;
      return res;
    }
    if (st == STATUS_SEPARATED) {
      overlap_result_zero(res, STATUS_SEPARATED);
      return res;
    }
  }
  // the full path: all of A, B's planes that cut it
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
  if (st != STATUS_OK) {
    overlap_result_zero(res, st);
    return res;
  }
  return overlap_detail::hull_result(w, np, x0, seeded, r, a, b, Lmin, ttouch);
}

}    // namespace polydem

#endif
