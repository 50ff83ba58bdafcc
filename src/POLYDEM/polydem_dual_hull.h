/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - intersection of half-spaces n_i . p <= h_i (h_i > 0, i.e. the
   origin x_o strictly inside) as the convex hull of their dual points
   y_i = n_i / h_i (seed 2.3, Eqs. 4-8), built by incremental Quickhull
   (seed Algorithms III-V) in a fixed workspace.

   Representation: each dual hull triangle (three plane indices, CCW seen
   from outside in dual space) is one vertex of the primal polyhedron; its
   unpolarised point (seed Eq. 8) is stored explicitly as P. The Quickhull
   "point above face" test of Algorithm IV, y_l . m_t - e_t > 0, equals
   (n_l . P_t - h_l) / (h_l |P_t|) with a positive factor, so it is evaluated
   in primal form as the violation n_l . P_t - h_l [length] against a
   size-scaled tolerance. New vertices are placed on the old primal edge by
   linear interpolation of the violations, which keeps the polyhedron convex
   under round-off and avoids the 1/d amplification of Eq. 8 for planes
   that nearly touch x_o. The hull starts from the dual of a large bounding
   tetrahedron (planes 0-3), which contains the dual origin; these planes
   must all disappear when the real planes are inserted.

   Each plane carries an owner bit mask (bit 0: particle A, bit 1: B), so
   every face of the result knows which particle's plane it came from.
   Header-only, host and device: no allocation, bounded loops.
------------------------------------------------------------------------- */

#ifndef POLYDEM_DUAL_HULL_H
#define POLYDEM_DUAL_HULL_H

#include "polydem_math.h"

namespace polydem {

enum PlaneOwner : unsigned char { OWNER_NONE = 0, OWNER_A = 1, OWNER_B = 2, OWNER_BOTH = 3 };

constexpr int DUAL_HULL_BOUND_PLANES = 4;
// tstamp of a triangle that repeats an earlier one's vertex (the fan of a
// vertex of degree > 3): the initial conflict scan skips it (same violation)
constexpr int DUAL_HULL_COPY = -2;

// Fixed workspace for up to MaxPlanes planes including the 4 bounding planes.
// A hull of n dual points has at most 2n-4 triangles; visible triangles are
// freed before new ones are allocated, so 2*MaxPlanes triangle slots suffice.
template <typename T, int MaxPlanes> struct DualHullWorkspace {
  static constexpr int MAXP = MaxPlanes;
  static constexpr int MAXT = 2 * MaxPlanes;
  // planes (input): pl[4i..4i+3] = (n, h), in coordinates centred on x_o
  T pl[4 * MAXP];
  unsigned char owner[MAXP];
  int nplanes;
  // Quickhull conflict data per plane: triangle index, or -1 discarded, -2 inserted
  short conflict[MAXP];
  T cviol[MAXP];
  // triangles = primal vertices
  short tc[MAXT][3];             // plane indices (dual vertices)
  short tadj[MAXT][3];           // neighbour across edge (tc[k], tc[k+1])
  Vec3<T> P[MAXT];               // unpolarised primal vertex (seed Eq. 8)
  T tviol[MAXT];                 // violation of the current apex plane
  int tstamp[MAXT];              // iteration at which tviol was computed
  unsigned char tstate[MAXT];    // 0 free, 1 alive, 2 visible
  int ntslots;                   // high-water mark of used slots
  short freelist[MAXT];
  int nfree;
  // per-iteration scratch
  short stack[MAXT];
  short vis[MAXT];
  short hz_tri[MAXP], hz_edge[MAXP], hz_new[MAXP];
  Vec3<T> hz_P[MAXP];
  short new_by_start[MAXP], new_by_end[MAXP];
  short act[MAXP];    // planes still in conflict, in index order
};

// Integrals over the intersection polyhedron (coordinates centred on x_o).
template <typename T> struct HullIntegrals {
  T volume;              // seed Eq. 9
  Vec3<T> vmoment;       // int p dV (centroid = vmoment / volume)
  Vec3<T> S[2];          // int n dA over faces owned by A (0) / B (1)
  Vec3<T> M[2];          // int (p - ref_k) x n dA over those faces
  T area[2];             // scalar area of those faces
  int nverts;            // primal vertices (= dual triangles)
};

namespace hull_detail {
  template <typename T, int MP>
  POLYDEM_FN T viol(const DualHullWorkspace<T, MP> &w, int l, const Vec3<T> &p)
  {
    const T *q = w.pl + 4 * l;
    return q[0] * p.x + q[1] * p.y + q[2] * p.z - q[3];
  }
  // fan triangle (F_a, P_t, P_t2) of face a = tc[t][e]: plane normal n, foot
  // F_a = h_a n of the origin, the edge P_t -> P_t2; returns its signed area
  template <typename T, int MP>
  POLYDEM_FN T fan_triangle(const DualHullWorkspace<T, MP> &w, int t, int e, Vec3<T> &n, Vec3<T> &F,
                            Vec3<T> &p1, Vec3<T> &p2)
  {
    const T *q = w.pl + 4 * w.tc[t][e];
    n = make_vec3(q[0], q[1], q[2]);
    F = q[3] * n;
    p1 = w.P[t];
    p2 = w.P[w.tadj[t][e]];
    return T(0.5) * dot(n, cross(p1 - F, p2 - F));
  }
}    // namespace hull_detail

template <typename T, int MP>
POLYDEM_FN int dual_hull_expand(DualHullWorkspace<T, MP> &w, T tol, int first,
                                bool preset = false);

// Build the intersection of planes 4..nplanes-1 (already in w.pl / w.owner)
// inside a bounding tetrahedron of in-radius H [length] about x_o.
// tol [length]: planes cutting off less than tol are redundant.
template <typename T, int MP>
POLYDEM_FN int dual_hull_build(DualHullWorkspace<T, MP> &w, T H, T tol)
{
  using hull_detail::viol;
  constexpr int NB = DUAL_HULL_BOUND_PLANES;
  const int np = w.nplanes;
  if (np > MP) return STATUS_OVERFLOW;
  // bounding tetrahedron: normals (+-1,+-1,+-1)/sqrt(3), even number of minus signs
  const T c = T(1) / sqrt(T(3));
  const T sg[4][3] = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  for (int i = 0; i < NB; ++i) {
    w.pl[4 * i] = c * sg[i][0];
    w.pl[4 * i + 1] = c * sg[i][1];
    w.pl[4 * i + 2] = c * sg[i][2];
    w.pl[4 * i + 3] = H;
    w.owner[i] = OWNER_NONE;
    w.conflict[i] = -2;
  }
  // 4 initial triangles: triangle i = vertex opposite face i, at -3H n_i
  for (int i = 0; i < NB; ++i) {
    short a = (short) ((i + 1) % 4), b = (short) ((i + 2) % 4), d = (short) ((i + 3) % 4);
    // orient CCW seen from outside in dual space: ((y_b-y_a) x (y_d-y_a)) . y_a > 0
    const Vec3<T> ya = make_vec3(w.pl[4 * a], w.pl[4 * a + 1], w.pl[4 * a + 2]);
    const Vec3<T> yb = make_vec3(w.pl[4 * b], w.pl[4 * b + 1], w.pl[4 * b + 2]);
    const Vec3<T> yd = make_vec3(w.pl[4 * d], w.pl[4 * d + 1], w.pl[4 * d + 2]);
    if (dot(cross(yb - ya, yd - ya), ya) < T(0)) {
      const short t = b;
      b = d;
      d = t;
    }
    w.tc[i][0] = a;
    w.tc[i][1] = b;
    w.tc[i][2] = d;
    w.P[i] = make_vec3(-T(3) * H * w.pl[4 * i], -T(3) * H * w.pl[4 * i + 1],
                       -T(3) * H * w.pl[4 * i + 2]);
    w.tstate[i] = 1;
    w.tstamp[i] = -1;
  }
  for (int i = 0; i < NB; ++i)
    for (int e = 0; e < 3; ++e) {
      const short u = w.tc[i][e], v = w.tc[i][(e + 1) % 3];
      w.tadj[i][e] = -1;
      for (int j = 0; j < NB; ++j)
        for (int f = 0; f < 3; ++f)
          if (j != i && w.tc[j][f] == v && w.tc[j][(f + 1) % 3] == u) w.tadj[i][e] = (short) j;
    }
  w.ntslots = NB;
  return dual_hull_expand(w, tol, NB);
}

// Insert planes first..nplanes-1 into the hull held in w (triangles
// 0..ntslots-1 alive, with tc, tadj, P; planes below first already in it).
// Used after the bounding tetrahedron (dual_hull_build) or after a seed
// polyhedron copied from a template's dual triangulation (polydem_overlap.h).
// preset: conflict[l] (l >= first) already holds the triangle of the hull
// vertex furthest beyond plane l (e.g. from a support search), so the
// initial conflicts need no scan of every triangle; -1 falls back to the scan.
template <typename T, int MP>
POLYDEM_FN int dual_hull_expand(DualHullWorkspace<T, MP> &w, T tol, int first, bool preset)
{
  using hull_detail::viol;
  constexpr int NB = DUAL_HULL_BOUND_PLANES;
  const int np = w.nplanes;
  if (np > MP) return STATUS_OVERFLOW;
  w.nfree = 0;
  for (int p = 0; p < np; ++p) w.new_by_start[p] = w.new_by_end[p] = -1;
  // initial conflicts (seed Algorithm IV)
  for (int l = first; l < np; ++l) {
    const int t0 = preset ? w.conflict[l] : -1;
    if (t0 >= 0 && t0 < w.ntslots) {
      const T v = viol(w, l, w.P[t0]);
      w.conflict[l] = v > tol ? (short) t0 : (short) -1;
      w.cviol[l] = v > tol ? v : tol;
      continue;
    }
    // the furthest vertex beyond plane l (kept in registers: the stores
    // would be repeated at every new maximum)
    const T *q = w.pl + 4 * l;
    const T nx = q[0], ny = q[1], nz = q[2], h = q[3];
    T best = tol;
    short bt = -1;
    for (int t = 0; t < w.ntslots; ++t) {
      if (w.tstamp[t] == DUAL_HULL_COPY) continue;
      const T v = nx * w.P[t].x + ny * w.P[t].y + nz * w.P[t].z - h;
      if (v > best) {
        best = v;
        bt = (short) t;
      }
    }
    w.conflict[l] = bt;
    w.cviol[l] = best;
  }
  // the planes in conflict (the others are redundant for good): the loops
  // over planes below visit only these
  int nact = 0;
  for (int l = first; l < np; ++l)
    if (w.conflict[l] >= 0) w.act[nact++] = (short) l;
  // expansion (seed Algorithm V); each pass inserts one plane for good
  for (int iter = 0; iter < np; ++iter) {
    int apex = -1;
    T best = T(0);
    for (int k = 0; k < nact; ++k) {
      const int l = w.act[k];
      if (apex < 0 || w.cviol[l] > best) {
        apex = l;
        best = w.cviol[l];
      }
    }
    if (apex < 0) break;
    // visible set by flood fill from the conflict triangle
    int nvis = 0, nst = 0;
    const short t0 = w.conflict[apex];
    w.tviol[t0] = w.cviol[apex];
    w.tstamp[t0] = iter;
    w.tstate[t0] = 2;
    w.stack[nst++] = t0;
    while (nst > 0) {
      const short t = w.stack[--nst];
      w.vis[nvis++] = t;
      for (int e = 0; e < 3; ++e) {
        const short nb = w.tadj[t][e];
        if (w.tstamp[nb] != iter) {
          w.tstamp[nb] = iter;
          w.tviol[nb] = viol(w, apex, w.P[nb]);
        }
        if (w.tstate[nb] == 1 && w.tviol[nb] > tol) {
          w.tstate[nb] = 2;
          w.stack[nst++] = nb;
        }
      }
    }
    // horizon edges (visible -> non-visible), each with its new primal vertex
    int nh = 0;
    for (int k = 0; k < nvis; ++k) {
      const short t = w.vis[k];
      for (int e = 0; e < 3; ++e) {
        const short nb = w.tadj[t][e];
        if (w.tstate[nb] == 2) continue;
        if (nh >= MP) return STATUS_DEGENERATE;
        const short u = w.tc[t][e], v = w.tc[t][(e + 1) % 3];
        if (w.new_by_start[u] != -1 || w.new_by_end[v] != -1) return STATUS_DEGENERATE;
        w.new_by_start[u] = (short) nh;
        w.new_by_end[v] = (short) nh;
        w.hz_tri[nh] = nb;
        w.hz_edge[nh] = (short) e;
        // new vertex on the primal edge P_t -> P_nb where the apex plane cuts it
        const T v1 = w.tviol[t], v2 = w.tviol[nb];
        T s = v1 / (v1 - v2);
        s = s < T(0) ? T(0) : (s > T(1) ? T(1) : s);
        w.hz_P[nh] = w.P[t] + s * (w.P[nb] - w.P[t]);
        // remember the corner pair in hz_new temporarily as u; v is tc of nb
        w.hz_new[nh] = u;
        ++nh;
      }
    }
    if (nh == 0) return STATUS_SEPARATED;    // every vertex cut off: empty intersection
    // planes whose conflict triangle is about to vanish must be reassigned
    for (int k = 0; k < nact; ++k)
      if (w.tstate[w.conflict[w.act[k]]] == 2) w.conflict[w.act[k]] = -3;
    w.conflict[apex] = -2;
    // free visible triangles (seed: removeAllVisibleFaces)
    for (int k = 0; k < nvis; ++k) {
      w.tstate[w.vis[k]] = 0;
      w.freelist[w.nfree++] = w.vis[k];
    }
    // create the new triangles (u, v, apex) (seed: appendNewFace)
    for (int k = 0; k < nh; ++k) {
      short t;
      if (w.nfree > 0)
        t = w.freelist[--w.nfree];
      else if (w.ntslots < w.MAXT)
        t = (short) w.ntslots++;
      else
        return STATUS_OVERFLOW;
      const short u = w.hz_new[k];
      const short nb = w.hz_tri[k];
      short v = -1;
      for (int f = 0; f < 3; ++f)
        if (w.tc[nb][(f + 1) % 3] == u) {
          v = w.tc[nb][f];
          w.tadj[nb][f] = t;
        }
      w.tc[t][0] = u;
      w.tc[t][1] = v;
      w.tc[t][2] = (short) apex;
      w.tadj[t][0] = nb;
      w.P[t] = w.hz_P[k];
      w.tstate[t] = 1;
      w.tstamp[t] = iter;
      w.tviol[t] = T(0);
      w.hz_tri[k] = t;    // now the new triangle
    }
    // link the new fan: edge (v, apex) meets the new triangle starting at v,
    // edge (apex, u) the one ending at u
    bool ok = true;
    for (int k = 0; k < nh; ++k) {
      const short t = w.hz_tri[k];
      const short ks = w.new_by_start[w.tc[t][1]];
      const short ke = w.new_by_end[w.tc[t][0]];
      if (ks < 0 || ke < 0) {
        ok = false;
        continue;
      }
      w.tadj[t][1] = w.hz_tri[ks];
      w.tadj[t][2] = w.hz_tri[ke];
    }
    for (int k = 0; k < nh; ++k) {
      const short t = w.hz_tri[k];
      w.new_by_start[w.tc[t][0]] = -1;
      w.new_by_end[w.tc[t][1]] = -1;
    }
    if (!ok) return STATUS_DEGENERATE;
    // reassign orphaned planes to the new triangles (seed Algorithm IV)
    int nkeep = 0;
    for (int k = 0; k < nact; ++k) {
      const int l = w.act[k];
      if (w.conflict[l] != -3) {
        if (w.conflict[l] >= 0) w.act[nkeep++] = (short) l;
        continue;
      }
      const T *q = w.pl + 4 * l;
      const T nx = q[0], ny = q[1], nz = q[2], h = q[3];
      T best = tol;
      short bt = -1;
      for (int j = 0; j < nh; ++j) {
        const short t = w.hz_tri[j];
        const T v = nx * w.P[t].x + ny * w.P[t].y + nz * w.P[t].z - h;
        if (v > best) {
          best = v;
          bt = t;
        }
      }
      w.conflict[l] = bt;
      w.cviol[l] = best;
      if (bt >= 0) w.act[nkeep++] = (short) l;
    }
    nact = nkeep;
  }
  // the bounding planes must be gone, else the input was unbounded
  for (int t = 0; t < w.ntslots; ++t)
    if (w.tstate[t] == 1)
      for (int e = 0; e < 3; ++e)
        if (w.tc[t][e] < NB) return STATUS_DEGENERATE;
  // polish: each vertex is the meeting point of its three planes (seed Eq. 8
  // in primal form). The interpolated P carries the round-off of every cut
  // it went through; where the three normals are well conditioned
  // (|det| >= 1e-2) the direct solution replaces it, which keeps the
  // vertices of a 1e-9-thin sliver at the round-off of the size.
  for (int t = 0; t < w.ntslots; ++t) {
    if (w.tstate[t] != 1) continue;
    const T *q0 = w.pl + 4 * w.tc[t][0], *q1 = w.pl + 4 * w.tc[t][1], *q2 = w.pl + 4 * w.tc[t][2];
    const Vec3<T> n0 = make_vec3(q0[0], q0[1], q0[2]), n1 = make_vec3(q1[0], q1[1], q1[2]),
                  n2 = make_vec3(q2[0], q2[1], q2[2]);
    const Vec3<T> c12 = cross(n1, n2), c20 = cross(n2, n0), c01 = cross(n0, n1);
    const T det = dot(n0, c12);
    if (!(fabs(det) >= T(1e-2))) continue;
    // solve around the current P: P + d with n_i . d = h_i - n_i . P (small residuals)
    const Vec3<T> &P = w.P[t];
    const T r0 = q0[3] - dot(n0, P), r1 = q1[3] - dot(n1, P), r2 = q2[3] - dot(n2, P);
    w.P[t] = P + (T(1) / det) * (r0 * c12 + r1 * c20 + r2 * c01);
  }
  return STATUS_OK;
}

// Integrals over the polyhedron built by dual_hull_build. Each dual edge
// (a -> b) of triangle t, with neighbour t2 across it, is one edge P_t -> P_t2
// of face a; faces are fanned from the foot F_a = h_a n_a of x_o on plane a.
// Planes owned by both particles count half for each. ref[k] = reference
// point of particle k for the moments M (coordinates centred on x_o).
//
// Volume and first moment use the divergence theorem with fields along one
// direction u (the contact normal S_A/|S_A| from the first pass):
//   V = sum_f (n_f.u) int_f (p.u) dA,    int p.e dV = sum_f (n_f.u) int_f (p.e)(p.u) dA
// (e perpendicular to u; for e = u the integrand is (p.u)^2/2). This equals
// seed Eq. 9 in exact arithmetic, but the thin side faces of a sliver overlap
// (depth << size), whose areas carry the round-off of the depth, enter only
// with the small factor p.u; on each face p.u is taken from the plane's
// offset h and the in-plane part of u, so the faces parallel to the contact
// plane contribute h * area without the round-off of their vertices' heights.
// V and the centroid stay accurate to round-off of the size even for depths
// of 1e-9 of it. Triangle integrals of products
// of linear functions are exact: int_T f g dA = A/12 (sum f_i g_i + sum f_i sum g_i).
// An overlap thicker than thin_below [length] (thickness 2V / surface area
// from the first pass) takes V and the moment from the pyramids of the first
// pass (seed Eq. 9), accurate to round-off there, and skips the second pass.
// The default (infinite) always takes the second pass.
template <typename T, int MP>
POLYDEM_FN void dual_hull_integrate(DualHullWorkspace<T, MP> &w, const Vec3<T> ref[2],
                                    HullIntegrals<T> &out, T thin_below = T(1e30))
{
  const Vec3<T> zero = make_vec3(T(0), T(0), T(0));
  T vol = T(0);    // 3 x (pyramids from x_o)
  Vec3<T> vm = zero;
  Vec3<T> S[2] = {zero, zero}, M[2] = {zero, zero};
  T ar[2] = {T(0), T(0)};
  int nv = 0;
  // one face at a time: its area A_f and first moment m_f = int_f p dA from
  // the fan triangles (F_a, P_t, P_t2) walked around the face, then
  //   V = 1/3 sum_f h_f A_f,   int p dV = 1/4 sum_f h_f m_f   (seed Eq. 9),
  //   S_k = sum_f A_f n_f,     M_k = sum_f (m_f - A_f ref_k) x n_f
  // over the faces of particle k (w.hz_edge: plane -> face done)
  short *done = w.hz_edge;
  for (int l = 0; l < w.nplanes; ++l) done[l] = 0;
  for (int t = 0; t < w.ntslots; ++t) {
    if (w.tstate[t] != 1) continue;
    ++nv;
    for (int e = 0; e < 3; ++e) {
      const int a = w.tc[t][e];
      if (done[a]) continue;
      done[a] = 1;
      const T *q = w.pl + 4 * a;
      const Vec3<T> n = make_vec3(q[0], q[1], q[2]);
      const Vec3<T> F = q[3] * n;
      T fa = T(0);
      Vec3<T> fm = zero;
      // edge e of t is (a, b); the triangle across it holds a as well, and
      // its edge from a continues the face's boundary
      int tt = t, ee = e;
      for (int k = 0; k < w.ntslots; ++k) {
        const int t2 = w.tadj[tt][ee];
        const Vec3<T> &p1 = w.P[tt], &p2 = w.P[t2];
        const T sa = T(0.5) * dot(n, cross(p1 - F, p2 - F));
        fa += sa;
        fm += sa * (F + p1 + p2);
        ee = w.tc[t2][0] == a ? 0 : (w.tc[t2][1] == a ? 1 : 2);
        tt = t2;
        if (tt == t) break;
      }
      fm = (T(1) / T(3)) * fm;
      vol += q[3] * fa;
      vm += (T(0.25) * q[3]) * fm;
      const unsigned char own = w.owner[a];
      if (own == OWNER_NONE) continue;
      // a face of both particles counts half for each
      const T half = own == OWNER_BOTH ? T(0.5) : T(1);
      const T s = half * fa;
      if (own & OWNER_A) {
        S[0] += s * n;
        M[0] += cross(half * fm - s * ref[0], n);
        ar[0] += s;
      }
      if (own & OWNER_B) {
        S[1] += s * n;
        M[1] += cross(half * fm - s * ref[1], n);
        ar[1] += s;
      }
    }
  }
  // global orientation of the dual triangles: volume must be positive
  const T sgn = vol < T(0) ? T(-1) : T(1);
  for (int k = 0; k < 2; ++k) {
    out.S[k] = sgn * S[k];
    out.M[k] = sgn * M[k];
    out.area[k] = sgn * ar[k];
  }
  out.nverts = nv;
  const T atot = sgn * (ar[0] + ar[1]);
  if (T(2) * sgn * vol / T(3) > thin_below * atot) {
    out.volume = sgn * vol / T(3);
    out.vmoment = sgn * vm;
    return;
  }
  // frame (e1, e2, u), u along the contact normal
  Vec3<T> u = S[0] - S[1];
  const T un = norm(u);
  u = un > T(0) ? (T(1) / un) * u : make_vec3(T(0), T(0), T(1));
  const Vec3<T> e1 = any_perpendicular(u);
  const Vec3<T> e2 = cross(u, e1);
  T V = T(0), m1 = T(0), m2 = T(0), mu = T(0);
  for (int t = 0; t < w.ntslots; ++t) {
    if (w.tstate[t] != 1) continue;
    for (int e = 0; e < 3; ++e) {
      const T *q = w.pl + 4 * w.tc[t][e];
      Vec3<T> n, F, p1, p2;
      const T sa = hull_detail::fan_triangle(w, t, e, n, F, p1, p2);
      // p.u on plane a as (u.n) h + p.u_perp: exact for the face parallel
      // to the contact plane whatever the round-off of its vertices
      const T un_a = dot(n, u);
      const Vec3<T> up = u - un_a * n;
      const T wu = sa * un_a, zh = un_a * q[3];
      const T z0 = zh, z1 = zh + dot(p1, up), z2 = zh + dot(p2, up), zs = z0 + z1 + z2;
      const T x0 = dot(F, e1), x1 = dot(p1, e1), x2 = dot(p2, e1);
      const T y0 = dot(F, e2), y1 = dot(p1, e2), y2 = dot(p2, e2);
      V += wu * zs;
      m1 += wu * (x0 * z0 + x1 * z1 + x2 * z2 + (x0 + x1 + x2) * zs);
      m2 += wu * (y0 * z0 + y1 * z1 + y2 * z2 + (y0 + y1 + y2) * zs);
      mu += wu * (z0 * z0 + z1 * z1 + z2 * z2 + zs * zs);
    }
  }
  V *= T(1) / T(3);
  m1 *= T(1) / T(12);
  m2 *= T(1) / T(12);
  mu *= T(1) / T(24);
  out.volume = sgn * V;
  out.vmoment = sgn * (m1 * e1 + m2 * e2 + mu * u);
}

}    // namespace polydem

#endif
