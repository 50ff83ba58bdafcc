/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - polyhedron-triangle contact for triangulated walls (seed 2.4):
   the section of a posed convex polyhedron with the triangle's plane,
   clipped to the triangle by Sutherland-Hodgman (Algorithm VII, Eqs. 10-11),
   and the volume (and its centroid) of the part of the polyhedron behind the
   plane inside the triangle's prism, by the divergence theorem: the faces'
   parts behind the plane, projected on it and clipped to the triangle by the
   same Sutherland-Hodgman passes, each integrated as a column of linear depth.

   Triangle (t0, t1, t2) is counter-clockwise seen from the front; its unit
   normal n_w = (t1-t0)x(t2-t0)/|..| points to the side where particles live.
   The prisms of a flat triangulated wall partition the half-space behind it,
   so summed volumes and areas do not depend on the triangulation.

   Gradients. V is the volume of R, the part of P behind the plane inside the prism; a
   rigid motion of P moves only the part of R's boundary that is P's surface:
     dV/dx = S = int_{dP in R} n dA,  dV/dtheta = M = int_{dP in R} (r - x) x n dA
   (Reynolds transport theorem; n the particle's outward normal). As the
   closed surface of R has int n dA = 0 and int r x n dA = 0,
     S = -n_w A - sum_e m_e B_e,  M = -(c_A - x) x n_w A - sum_e (c_e - x) x m_e B_e,
   with A, c_A the section in the triangle and B_e, c_e the section of R with
   the prism's side e (outward normal m_e). When R stays inside the prism
   (no face polygon was cut by the triangle's edges) the B_e vanish and the
   kernel returns the section form, S = -n_w A. Otherwise it sums the
   particle's clipped face polygons themselves (their area vectors and
   moments): exact at open borders and at edges between non-coplanar
   triangles, where the sides do not cancel and the section form is not the
   gradient of V (so W(V) would not be conserved). On a flat triangulated
   wall the sides of neighbouring prisms cancel, so the sum over the wall is
   -n_w A whatever the triangulation (round-off apart), and
   F = -W'(V) S = W'(V) A n_w pushes the particle out of the wall.
   Header-only, host and device.
------------------------------------------------------------------------- */

#ifndef POLYDEM_CLIP_H
#define POLYDEM_CLIP_H

#include "polydem_gjk.h"

namespace polydem {

template <typename T> struct Triangle {
  Vec3<T> v[3];    // lab frame, CCW seen from the front
};

// Polygons: a section has at most one vertex per template edge, a face loop
// at most one per template vertex, plus one per clipping line (plane, three
// triangle edges). Posed vertices: nverts <= nedges <= MaxEdges.
template <typename T, int MaxFaces = MAX_TEMPLATE_FACES, int MaxEdges = 3 * MAX_TEMPLATE_VERTS>
struct ClipWorkspace {
  static constexpr int MAX_POLY = MaxEdges + 4;
  T vu[MaxEdges], vv[MaxEdges], vs[MaxEdges];    // posed vertices (u, v, height)
  unsigned char uv[MaxEdges];                    // vu, vv computed (only near the plane)
  T pu[MAX_POLY], pv[MAX_POLY], pz[MAX_POLY];    // polygon (2-D, depth)
  T qu[MAX_POLY], qv[MAX_POLY], qz[MAX_POLY];    // Sutherland-Hodgman ping-pong
  T key[MAX_POLY];                               // sort keys of the section
  unsigned char behind[MaxFaces];                // faces with a vertex behind the plane
  int low[MaxEdges];      // the vertices on or behind the plane, in vertex order
  int cross[MaxEdges];    // the section's edges (i << 16) | j (i < j), sorted
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
  Vec3<T> S;            // dV/dx [length^2] (-n_w area where no prism side is reached)
  Vec3<T> M;            // dV/dtheta [length^3] (-(acentroid - x) x n_w area likewise)
  Vec3<T> normal;       // n_w
};

// volumes below this x eps x the sum of |column integrals| are 0
constexpr int CLIP_TOUCH_TOL = 16;

// every field zero (value-initialised aggregate), then the status
template <typename T> POLYDEM_FN void clip_result_zero(ClipResult<T> &r, int status)
{
  r = ClipResult<T>{};
  r.status = status;
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
  // of polygon (iu, iv, n) left of the directed line a -> b (CCW clip polygon),
  // carrying a value z that is linear along the polygon's edges
  template <typename T>
  POLYDEM_FN int sh_pass(const T *iu, const T *iv, const T *iz, int n, T au, T av, T bu, T bv,
                         T *ou, T *ov, T *oz, int *cut = nullptr)
  {
    const T eu = bu - au, ev = bv - av;
    int m = 0;
    if (n == 0) return 0;
    T pu = iu[n - 1], pv = iv[n - 1], pz = iz[n - 1];
    T sp = eu * (pv - av) - ev * (pu - au);
    for (int i = 0; i < n; ++i) {
      const T cu = iu[i], cv = iv[i], cz = iz[i];
      const T sc = eu * (cv - av) - ev * (cu - au);    // cross2D(edgeDir, v - v0) >= 0: inside
      const bool inc = sc >= T(0), inp = sp >= T(0);
      if (cut && !inc) *cut = 1;    // a vertex beyond the line: the polygon is cut
      if (inc != inp) {    // crossing: Eqs. 10-11
        const T t = sp / (sp - sc);
        ou[m] = pu + t * (cu - pu);
        ov[m] = pv + t * (cv - pv);
        oz[m] = pz + t * (cz - pz);
        ++m;
      }
      if (inc) {
        ou[m] = cu;
        ov[m] = cv;
        oz[m] = cz;
        ++m;
      }
      pu = cu;
      pv = cv;
      pz = cz;
      sp = sc;
    }
    return m;
  }

  // the polygon (iu, iv, iz), m vertices, clipped by the triangle (tu, tv)
  // (CCW): three passes, ping-pong with the scratch (qu, qv, qz); on return
  // i* point at the result; *cut (if given) is set to 1 if a vertex lay
  // outside the triangle
  template <typename T>
  POLYDEM_FN void clip_to_triangle(const T *tu, const T *tv, int &m, T *&iu, T *&iv, T *&iz, T *qu,
                                   T *qv, T *qz, int *cut = nullptr)
  {
    for (int e = 0; e < 3 && m > 0; ++e) {
      // a polygon wholly inside the edge's line passes unchanged (the same
      // test as sh_pass's): no pass, no copy
      const T au = tu[e], av = tv[e], eu = tu[(e + 1) % 3] - au, ev = tv[(e + 1) % 3] - av;
      int i = 0;
      while (i < m && eu * (iv[i] - av) - ev * (iu[i] - au) >= T(0)) ++i;
      if (i == m) continue;
      m = sh_pass(iu, iv, iz, m, tu[e], tv[e], tu[(e + 1) % 3], tv[(e + 1) % 3], qu, qv, qz, cut);
      T *su = iu, *sv = iv, *sz = iz;
      iu = qu;
      iv = qv;
      iz = qz;
      qu = su;
      qv = sv;
      qz = sz;
    }
  }
}    // namespace clip_detail

template <typename T, int MF, int ME>
POLYDEM_FN ClipResult<T> polyhedron_triangle(const PosedShape<T> &a, const Triangle<T> &tri,
                                             ClipWorkspace<T, MF, ME> &ws, const T *posed = nullptr)
{
  // posed: the caller's posed vertices x + s R v (3 nverts, same frame), or null
  ClipResult<T> res;
  clip_result_zero(res, STATUS_OK);
  const ShapeView<T> &sv = *a.view;
  if (sv.nfaces > MF || sv.nedges > ME || sv.nverts > ME || sv.nfaces < 4) {
    clip_result_zero(res, STATUS_OVERFLOW);
    return res;
  }
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
  // --- posed vertices in the frame (e1, e2, nw) whose origin o is the foot of
  // the particle's centre on the plane: (u, v) in the plane, s = signed
  // height above it (behind: s < 0). The heights of all; (u, v) only of the
  // vertices on or behind the plane and of their edges' other ends, the
  // only ones the section and the faces' parts behind use.
  const Vec3<T> d0 = a.x - t0;
  const T sx = dot(d0, nw);
  const Vec3<T> o = a.x - sx * nw;
  auto rel = [&](int i) {    // vertex i relative to the centre (lab)
    return posed ? make_vec3(posed[3 * i], posed[3 * i + 1], posed[3 * i + 2]) - a.x
                 : a.s * matvec(a.R, make_vec3(sv.verts[3 * i], sv.verts[3 * i + 1],
                                              sv.verts[3 * i + 2]));
  };
  auto in_plane = [&](int i, const Vec3<T> &r) {
    ws.vu[i] = dot(r, e1);
    ws.vv[i] = dot(r, e2);
    ws.uv[i] = 1;
  };
  int nbehind = 0, nlow = 0;
  for (int i = 0; i < sv.nverts; ++i) {
    const Vec3<T> r = rel(i);
    ws.vs[i] = sx + dot(r, nw);
    if (!(ws.vs[i] == ws.vs[i])) {
      clip_result_zero(res, STATUS_DEGENERATE);
      return res;
    }
    ws.uv[i] = 0;
    if (ws.vs[i] <= T(0)) {
      in_plane(i, r);
      ws.low[nlow++] = i;
      if (ws.vs[i] < T(0)) ++nbehind;
    }
  }
  if (nbehind == 0) {
    res.status = STATUS_SEPARATED;
    return res;
  }
  // the triangle in that frame (CCW seen from the front)
  const T ou = dot(d0, e1), ov = dot(d0, e2);
  const T tu[3] = {-ou, l1 - ou, dot(e2r, e1) - ou}, tv[3] = {-ov, -ov, dot(e2r, e2) - ov};
  // --- section polygon: template edges crossing the plane (Algorithm VII),
  // in the template's edge order. With the vertex adjacency, from the
  // vertices on or behind the plane only: their neighbours' (u, v) (the
  // faces' loops below use them), and the edges with one end behind and the
  // other not, sorted as the edge list is (i < j, lexicographic); else a
  // scan of every edge. The same points in the same order either way.
  int ncross = 0;
  if (sv.vadj) {
    for (int b = 0; b < nlow; ++b) {
      const int u = ws.low[b];
      const bool ub = ws.vs[u] < T(0);
      for (int k = sv.vadj[u]; k < sv.vadj[u + 1]; ++k) {
        const int w = sv.vadj[k];
        if (!ws.uv[w]) in_plane(w, rel(w));
        if (ub && !(ws.vs[w] < T(0)))
          ws.cross[ncross++] = u < w ? (u << 16) | w : (w << 16) | u;
      }
    }
    for (int a = 1; a < ncross; ++a) {    // a handful: insertion sort
      const int key = ws.cross[a];
      int b = a - 1;
      for (; b >= 0 && ws.cross[b] > key; --b) ws.cross[b + 1] = ws.cross[b];
      ws.cross[b + 1] = key;
    }
  } else {
    for (int k = 0; k < sv.nedges; ++k) {
      const int i = sv.edges[2 * k], j = sv.edges[2 * k + 1];
      const T si = ws.vs[i], sj = ws.vs[j];
      if (si > T(0) && sj > T(0)) continue;
      if (!ws.uv[i]) in_plane(i, rel(i));
      if (!ws.uv[j]) in_plane(j, rel(j));
      if ((si < T(0)) != (sj < T(0))) ws.cross[ncross++] = (i << 16) | j;
    }
  }
  int n = 0;
  T mu = T(0), mv = T(0);
  for (int c = 0; c < ncross; ++c) {
    const int i = ws.cross[c] >> 16, j = ws.cross[c] & 0xffff;
    const T si = ws.vs[i], sj = ws.vs[j];
    const T t = si / (si - sj);
    ws.pu[n] = ws.vu[i] + t * (ws.vu[j] - ws.vu[i]);
    ws.pv[n] = ws.vv[i] + t * (ws.vv[j] - ws.vv[i]);
    ws.pz[n] = T(0);
    mu += ws.pu[n];
    mv += ws.pv[n];
    ++n;
  }
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
    // Sutherland-Hodgman against the triangle's three edges (Eqs. 10-11)
    int m = n;
    T *iu = ws.pu, *iv = ws.pv, *iz = ws.pz;
    clip_detail::clip_to_triangle(tu, tv, m, iu, iv, iz, ws.qu, ws.qv, ws.qz);
    // area and centroid (fan from the first vertex)
    T area = T(0), cu = T(0), cv = T(0);
    for (int i = 1; i + 1 < m; ++i) {
      const T au = iu[i] - iu[0], av = iv[i] - iv[0];
      const T bu = iu[i + 1] - iu[0], bv = iv[i + 1] - iv[0];
      const T da = T(0.5) * (au * bv - av * bu);
      area += da;
      cu += da * (iu[0] + iu[i] + iu[i + 1]);
      cv += da * (iv[0] + iv[i] + iv[i + 1]);
    }
    if (area > T(0)) {
      res.area = area;
      res.acentroid = o + (cu / (T(3) * area)) * e1 + (cv / (T(3) * area)) * e2;
      res.S = -area * nw;
      res.M = -area * cross(res.acentroid - a.x, nw);
    }
  }
  // --- volume behind the plane inside the prism, by the divergence theorem
  // with the field z e_z, z = -s the depth behind the plane: the section
  // (z = 0) and the prism sides (parallel to e_z) add nothing, so
  //   V = sum_f  sign(n_f . -n_w) int_{P_f} z_f dA,
  // P_f = projection of face f's part behind the plane, clipped to the
  // triangle; z_f is linear on it. A face loop (CCW about n_f) projects with
  // signed area A_f (n_f . n_w), so its signed integral carries -sign: sum
  // the signed integrals of every face and negate. Same with the moments:
  // a column of depth z over (u, v) holds int (u, v, -zeta) dzeta.
  // The same clipped face polygons, as polygons in space (u, v, s = -z),
  // give the exact gradient where the region is cut by the prism's sides
  // (see the header): Sf = sum of their area vectors, Mf = sum of their
  // moments (centroid - x) x area vector about the particle's centre (0, 0, sx).
  T V = T(0), Vabs = T(0), Mu = T(0), Mv = T(0), Mz = T(0);
  T Sfu = T(0), Sfv = T(0), Sfs = T(0), Mfu = T(0), Mfv = T(0), Mfs = T(0);
  int cut = 0;
  // the faces with a vertex behind the plane: through the dual triangulation
  // where the template has one (each triangle names a vertex and three of its
  // faces, and the triangles of a vertex name all its faces), else per face
  if (sv.dual != nullptr) {
    for (int f = 0; f < sv.nfaces; ++f) ws.behind[f] = 0;
    if (sv.vadj) {
      // the fans of the vertices behind (dual_fan_first), not every triangle
      for (int b = 0; b < nlow; ++b) {
        const int v = ws.low[b];
        if (!(ws.vs[v] < T(0))) continue;
        const int t0 = dual_fan_first(sv, v), t1 = t0 + sv.vadj[v + 1] - sv.vadj[v] - 2;
        for (int t = t0; t < t1; ++t) {
          const int *q = sv.dual + 1 + DUAL_SEED_STRIDE_K * t;
          ws.behind[q[0]] = ws.behind[q[1]] = ws.behind[q[2]] = 1;
        }
      }
    } else
      for (int t = 0; t < sv.dual[0]; ++t) {
        const int *q = sv.dual + 1 + DUAL_SEED_STRIDE_K * t;
        if (ws.vs[q[6]] < T(0)) ws.behind[q[0]] = ws.behind[q[1]] = ws.behind[q[2]] = 1;
      }
  } else {
    for (int f = 0; f < sv.nfaces; ++f) {
      bool any = false;
      for (int k = sv.face_start[f]; k < sv.face_start[f + 1] && !any; ++k)
        any = ws.vs[sv.face_verts[k]] < T(0);
      ws.behind[f] = any;
    }
  }
  for (int f = 0; f < sv.nfaces; ++f) {
    if (!ws.behind[f]) continue;
    const int f0 = sv.face_start[f], f1 = sv.face_start[f + 1];
    // the loop's part behind the plane (z = -s >= 0), then the triangle
    int m = 0;
    {
      int jp = sv.face_verts[f1 - 1];
      T zp = -ws.vs[jp];
      for (int k = f0; k < f1; ++k) {
        const int j = sv.face_verts[k];
        const T zc = -ws.vs[j];
        if ((zc >= T(0)) != (zp >= T(0))) {
          const T t = zp / (zp - zc);
          ws.pu[m] = ws.vu[jp] + t * (ws.vu[j] - ws.vu[jp]);
          ws.pv[m] = ws.vv[jp] + t * (ws.vv[j] - ws.vv[jp]);
          ws.pz[m] = T(0);
          ++m;
        }
        if (zc >= T(0)) {
          ws.pu[m] = ws.vu[j];
          ws.pv[m] = ws.vv[j];
          ws.pz[m] = zc;
          ++m;
        }
        jp = j;
        zp = zc;
      }
    }
    T *iu = ws.pu, *iv = ws.pv, *iz = ws.pz;
    clip_detail::clip_to_triangle(tu, tv, m, iu, iv, iz, ws.qu, ws.qv, ws.qz, &cut);
    // fan: over a triangle, int z = A sum(z)/3, int u z = A (sum u sum z +
    // sum u z)/12, int z^2 = A (sum(z)^2 + sum z^2)/12
    for (int i = 1; i + 1 < m; ++i) {
      const T du1 = iu[i] - iu[0], dv1 = iv[i] - iv[0], dz1 = iz[i] - iz[0];
      const T du2 = iu[i + 1] - iu[0], dv2 = iv[i + 1] - iv[0], dz2 = iz[i + 1] - iz[0];
      const T da = T(0.5) * (du1 * dv2 - dv1 * du2);
      const T z0 = iz[0], z1 = iz[i], z2 = iz[i + 1], sz = z0 + z1 + z2;
      const T su = iu[0] + iu[i] + iu[i + 1], svv = iv[0] + iv[i] + iv[i + 1];
      V += da * sz;
      Vabs += fabs(da * sz);
      Mu += da * (sz * su + iu[0] * z0 + iu[i] * z1 + iu[i + 1] * z2);
      Mv += da * (sz * svv + iv[0] * z0 + iv[i] * z1 + iv[i + 1] * z2);
      Mz += da * (sz * sz + z0 * z0 + z1 * z1 + z2 * z2);
      // area vector (d1 x d2) / 2 with s = -z, and its moment about (0, 0, sx)
      const T au = T(0.5) * (dz1 * dv2 - dv1 * dz2), av = T(0.5) * (du1 * dz2 - dz1 * du2);
      const T cu = su / T(3), cvv = svv / T(3), cs = -sz / T(3) - sx;
      Sfu += au;
      Sfv += av;
      Sfs += da;
      Mfu += cvv * da - cs * av;
      Mfv += cs * au - cu * da;
      Mfs += cu * av - cvv * au;
    }
  }
  V = -V / T(3);
  if (!(V == V)) {
    clip_result_zero(res, STATUS_DEGENERATE);
    return res;
  }
  // below the round-off of the signed sum: a touching contact
  if (V > T(CLIP_TOUCH_TOL) * Eps<T>::value * Vabs / T(3)) {
    res.volume = V;
    const T w = T(-1) / (T(12) * V);
    res.vcentroid = o + (w * Mu) * e1 + (w * Mv) * e2 - (T(0.5) * w * Mz) * nw;
    // the part behind the plane reaches beyond the triangle's prism: the
    // prism's sides bound the region too, and dV/dx, dV/dtheta are the
    // particle's surface inside it (Sf, Mf), not the section alone
    if (cut) {
      res.S = Sfu * e1 + Sfv * e2 + Sfs * nw;
      res.M = Mfu * e1 + Mfv * e2 + Mfs * nw;
    }
  }
  if (res.volume == T(0) && res.area == T(0)) res.status = STATUS_SEPARATED;
  return res;
}

}    // namespace polydem

#endif
