/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - the patches of one convex polyhedron on a triangle mesh (fix
   wall/mesh): candidate triangles (grid query or the particle's near list),
   exact cheap rejects, grouping by plane, clipping (polydem_clip.h) and the
   sums per patch of near-coplanar facets. Host and device, no LAMMPS
   includes. The contact forces of the patches: polydem_wall_contact.h.
------------------------------------------------------------------------- */

#ifndef POLYDEM_WALL_PATCHES_H
#define POLYDEM_WALL_PATCHES_H

#include "polydem_wall_patch_set.h"

#include <cmath>
#include <utility>

namespace polydem {

template <typename T, int MF, int ME> struct WallAccumulate {
  const PosedShape<T> *a;
  const MeshGridView<T> *g;
  WallWorkspace<T, MF, ME> *ws;
  WallPatches<T> *out;
  T cosmax;    // cos(patch angle)
  const WallSides<T> *sides;    // null: the front of every triangle

  // Exact cheap reject. The part of the particle behind the triangle's plane
  // is the convex hull of the vertices behind it and of the edges' crossing
  // points; separated if it is empty, if the bounding box of its projection
  // on the plane misses the triangle's, or if it lies outside one side of the
  // prism. Distances and box are kept for the next triangle of the plane.
  // The plane of triangle t, cached: its side (wall_side) and, for the
  // reject below, the particle's distances to it as met on that side.
  POLYDEM_FN void plane_of(int t) const
  {
    const ShapeView<T> &sv = *a->view;
    const T *pc = g->plane + 4 * t;
    if (!(ws->pvalid && pc[0] == ws->pc[0] && pc[1] == ws->pc[1] && pc[2] == ws->pc[2] &&
          pc[3] == ws->pc[3])) {
      for (int k = 0; k < 4; ++k) ws->pc[k] = pc[k];
      ws->pside = wall_side(sides, pc, a->x, posed_radius(*a), &ws->pclaimed);
      for (int k = 0; k < 4; ++k) ws->po[k] = T(ws->pside) * pc[k];
      const T *pl = ws->po;
      ws->pvalid = 1;
      ws->pany = 0;
      for (int k = 0; k < 3; ++k) {
        ws->pbox[k] = T(1e300);
        ws->pbox[3 + k] = T(-1e300);
      }
      if (sv.vadj) {
        // The vertex lowest along the normal, by a climb over the template's
        // edges from the last plane's: if it lies in front of the plane by
        // more than the round-off of these distances, so does every vertex,
        // the part behind is empty (separated() needs no dist[]), and the
        // scan below would find none either.
        ws->vlow = support_index_points_inl(ws->verts, sv.nverts, sv.vadj,
                                            make_vec3(-pl[0], -pl[1], -pl[2]), ws->vlow);
        const Vec3<T> v = wall_vert(ws->vlow);
        const T h = pl[0] * v.x + pl[1] * v.y + pl[2] * v.z - pl[3];
        const T scale = posed_radius(*a) + fabs(pl[3]) + fabs(a->x.x) + fabs(a->x.y) + fabs(a->x.z);
        if (h > T(1e-12) * scale) return;
      }
      ws->nbehind = 0;
      for (int i = 0; i < sv.nverts; ++i) {
        const Vec3<T> v = wall_vert(i);
        ws->dist[i] = pl[0] * v.x + pl[1] * v.y + pl[2] * v.z - pl[3];
        if (ws->dist[i] < T(0)) {
          ws->pany = 1;
          ws->behind[ws->nbehind++] = i;
          grow_box(v - ws->dist[i] * make_vec3(pl[0], pl[1], pl[2]));    // onto the plane
        }
      }
      if (ws->pany)
        for_each_crossing([&](const Vec3<T> &p) {
          grow_box(p);
          return true;
        });
      // the triangle's prism meets the behind part only where the triangle
      // meets its projection: compare boxes in the plane, with a margin for
      // round-off across the plane [length]
      const T margin = T(1e-9) * posed_radius(*a);
      for (int k = 0; k < 3; ++k) {
        ws->pbox[k] -= margin;
        ws->pbox[3 + k] += margin;
      }
    }
  }

  // f(p) for the point p where each edge of the particle crosses the plane of
  // plane_of (one end behind it, the other not), each computed from the
  // edge's lower-numbered end as in the template's edge list (i < j): the
  // edges of the vertices behind where the template has its adjacency, else
  // a scan of all edges; f returns false to stop
  template <typename F> POLYDEM_FN void for_each_crossing(F f) const
  {
    const ShapeView<T> &sv = *a->view;
    if (sv.vadj) {
      for (int b = 0; b < ws->nbehind; ++b) {
        const int u = ws->behind[b];
        for (int k = sv.vadj[u]; k < sv.vadj[u + 1]; ++k) {
          const int w = sv.vadj[k];
          if (ws->dist[w] < T(0)) continue;
          const int i = u < w ? u : w, j = u < w ? w : u;
          const T di = ws->dist[i], dj = ws->dist[j];
          const Vec3<T> vi = wall_vert(i);
          if (!f(vi + (di / (di - dj)) * (wall_vert(j) - vi))) return;
        }
      }
      return;
    }
    for (int k = 0; k < sv.nedges; ++k) {
      const int i = sv.edges[2 * k], j = sv.edges[2 * k + 1];
      const T di = ws->dist[i], dj = ws->dist[j];
      if ((di < T(0)) == (dj < T(0))) continue;
      const Vec3<T> vi = wall_vert(i);
      if (!f(vi + (di / (di - dj)) * (wall_vert(j) - vi))) return;
    }
  }

  // tri: triangle t as met (plane_of(t) first)
  POLYDEM_FN bool separated(int t, const Triangle<T> &tri) const
  {
    if (!ws->pany) return true;
    const T *b = g->box + 6 * t;
    for (int k = 0; k < 3; ++k)
      if (b[3 + k] < ws->pbox[k] || b[k] > ws->pbox[3 + k]) return true;
    const T *pl = ws->po;
    const Vec3<T> nr = make_vec3(pl[0], pl[1], pl[2]);
    for (int e = 0; e < 3; ++e) {
      const Vec3<T> o = tri.v[e], side = cross(tri.v[(e + 1) % 3] - o, nr);    // outward
      bool out = true;
      for (int k = 0; k < ws->nbehind && out; ++k)
        out = dot(side, wall_vert(ws->behind[k]) - o) > T(0);
      if (out)
        for_each_crossing([&](const Vec3<T> &p) {
          out = dot(side, p - o) > T(0);
          return out;
        });
      if (out) return true;
    }
    return false;
  }

  POLYDEM_FN void grow_box(const Vec3<T> &p) const
  {
    for (int k = 0; k < 3; ++k) {
      ws->pbox[k] = p[k] < ws->pbox[k] ? p[k] : ws->pbox[k];
      ws->pbox[3 + k] = p[k] > ws->pbox[3 + k] ? p[k] : ws->pbox[3 + k];
    }
  }

  POLYDEM_FN Vec3<T> wall_vert(int i) const
  {
    return make_vec3(ws->verts[3 * i], ws->verts[3 * i + 1], ws->verts[3 * i + 2]);
  }

  // triangle t as met from side (+1 front; -1 back: reversed, (t0, t2, t1))
  POLYDEM_FN Triangle<T> triangle(int t, int side = 1) const
  {
    Triangle<T> tri;
    const T *q = g->tri + 9 * t;
    for (int v = 0; v < 3; ++v) {
      const int w = side > 0 ? v : (3 - v) % 3;
      tri.v[v] = make_vec3(q[3 * w], q[3 * w + 1], q[3 * w + 2]);
    }
    return tri;
  }

  // candidates that survive the reject wait in ws->cand for finish()
  POLYDEM_FN void operator()(int t)
  {
    plane_of(t);
    int side = ws->pside;
    Triangle<T> tri = triangle(t, side);
    if (separated(t, tri)) return;
    if (!ws->pclaimed && sides && sides->both && !centroid_in_prism(tri)) {
      // Two-sided, a contact beginning, the centroid outside the triangle's
      // prism (beside an open border or a curved mesh's small facet): the
      // particle's part within the prism may lie wholly on the centroid's
      // side of the plane (no contact) or straddle it, so the centroid's
      // side can give a first overlap that jumps from zero when the
      // centroid crosses the extended plane. The side with the smaller
      // overlap is the one the particle came from: its overlap grows from
      // zero as the contact begins, and W(V) stays continuous.
      const Triangle<T> other = triangle(t, -side);
      const ClipResult<T> rs = polyhedron_triangle(*a, tri, ws->clip, ws->verts);
      const ClipResult<T> ro = polyhedron_triangle(*a, other, ws->clip, ws->verts);
      const T vs = rs.status == STATUS_OK ? rs.volume : T(0);
      const T vo = ro.status == STATUS_OK ? ro.volume : T(0);
      if (vo < vs) {
        side = -side;
        tri = other;
      }
    }
    if (ws->ncand < WALL_MAX_CAND) {
      ws->cside[ws->ncand] = (signed char) side;
      ws->cand[ws->ncand++] = t;
    } else
      clip_add(tri, t, wall_region_key(*g, t, side));
  }

  // the particle's centroid within the prism of tri (the triangle swept
  // along its normal, both ways)
  POLYDEM_FN bool centroid_in_prism(const Triangle<T> &tri) const
  {
    const Vec3<T> n = cross(tri.v[1] - tri.v[0], tri.v[2] - tri.v[0]);
    for (int e = 0; e < 3; ++e)
      if (dot(cross(tri.v[(e + 1) % 3] - tri.v[e], n), a->x - tri.v[e]) > T(0)) return false;
    return true;
  }

  // Group the candidates by plane. If the coplanar triangles of a group
  // cover the projection of the particle's part behind that plane, their
  // prisms partition that part (polydem_clip.h), and one clip against a
  // large triangle of the plane gives the same V, S, M (to round-off) at
  // the cost of one volume instead of one per triangle. Else (mesh border,
  // holes, overlaps, curved meshes) each triangle is clipped on its own.
  POLYDEM_FN void finish()
  {
    const T L = posed_radius(*a);
    // candidates by triangle index: the grouping below, and so the patches,
    // do not depend on the order in which the grid or the near list gave them
    for (int c = 1; c < ws->ncand; ++c) {
      const int t = ws->cand[c];
      const signed char sd = ws->cside[c];
      int k = c;
      for (; k > 0 && ws->cand[k - 1] > t; --k) {
        ws->cand[k] = ws->cand[k - 1];
        ws->cside[k] = ws->cside[k - 1];
      }
      ws->cand[k] = t;
      ws->cside[k] = sd;
    }
    for (int c = 0; c < ws->ncand; ++c) ws->cflag[c] = 0;
    for (int c = 0; c < ws->ncand; ++c) {
      if (ws->cflag[c]) continue;
      const Triangle<T> tc = triangle(ws->cand[c], ws->cside[c]);
      Vec3<T> n = cross(tc.v[1] - tc.v[0], tc.v[2] - tc.v[0]);
      n = (T(1) / norm(n)) * n;
      const T d = dot(n, tc.v[0]);
      int ng = 0;    // members flagged 2
      for (int k = c; k < ws->ncand; ++k) {
        if (ws->cflag[k]) continue;
        const Triangle<T> tk = k == c ? tc : triangle(ws->cand[k], ws->cside[k]);
        Vec3<T> nk = cross(tk.v[1] - tk.v[0], tk.v[2] - tk.v[0]);
        nk = (T(1) / norm(nk)) * nk;
        const T tol = T(1e-12);
        if (fabs(nk.x - n.x) <= tol && fabs(nk.y - n.y) <= tol && fabs(nk.z - n.z) <= tol &&
            fabs(dot(nk, tk.v[0]) - d) <= tol * L) {
          ws->cflag[k] = 2;
          ng++;
        }
      }
      // one clip for the group only if its triangles share a patch key
      const int key = wall_region_key(*g, ws->cand[c], ws->cside[c]);
      bool onekey = true;
      for (int k = c + 1; k < ws->ncand && onekey; ++k)
        if (ws->cflag[k] == 2) onekey = wall_region_key(*g, ws->cand[k], ws->cside[k]) == key;
      Triangle<T> big;
      if (ng > 1 && onekey && !ws->record && covered(tc.v[0], n, big)) {
        clip_add(big, -1, key);
        for (int k = c; k < ws->ncand; ++k)
          if (ws->cflag[k] == 2) ws->cflag[k] = 1;
      } else {
        for (int k = c; k < ws->ncand; ++k)
          if (ws->cflag[k] == 2) {
            ws->cflag[k] = 1;
            clip_add(triangle(ws->cand[k], ws->cside[k]), ws->cand[k],
                     wall_region_key(*g, ws->cand[k], ws->cside[k]));
          }
      }
    }
  }

  // Is the projection of the part behind the plane (o, n) covered by the
  // group's triangles (cflag 2)? If so, big is a triangle of the plane
  // (counter-clockwise about n) containing it.
  POLYDEM_FN bool covered(const Vec3<T> &o, const Vec3<T> &n, Triangle<T> &big)
  {
    const ShapeView<T> &sv = *a->view;
    Vec3<T> e1 = fabs(n.x) < T(0.9) ? cross(n, make_vec3(T(1), T(0), T(0)))
                                    : cross(n, make_vec3(T(0), T(1), T(0)));
    e1 = (T(1) / norm(e1)) * e1;
    const Vec3<T> e2 = cross(n, e1);
    // points: vertices behind the plane and edge crossings, in (e1, e2)
    ws->pvalid = 0;    // dist[] is reused below
    // A quick refusal first (most groups of a curved mesh's flat pairs, e.g.
    // a tube's rectangles, are not covered): a point of the part behind the
    // plane (a vertex behind it, an edge's crossing) outside every triangle
    // of a small group by more than 1e-3 of the particle's radius leaves
    // part of the projection uncovered. The full test below accepts an
    // uncovered sliver of 1e-9 of the area, which a point that far out
    // leaves only in a needle-thin projection: the refusal agreed with the
    // full test in every call of the short fixed bed (32,000 refusals).
    // The triangles' edge planes, normal to the group's plane: m_e . p <=
    // c_e inside (ngq = -1: a larger group, the full test only).
    constexpr int NQ = 4;
    Vec3<T> qm[NQ][3];
    T qc[NQ][3];
    int ngq = 0;
    for (int c = 0; c < ws->ncand; ++c) ngq += ws->cflag[c] == 2;
    if (ngq > NQ) ngq = -1;
    if (ngq > 0) {
      const T margin = T(1e-3) * posed_radius(*a);
      ngq = 0;
      for (int c = 0; c < ws->ncand; ++c) {
        if (ws->cflag[c] != 2) continue;
        const Triangle<T> t = triangle(ws->cand[c], ws->cside[c]);
        for (int e = 0; e < 3; ++e) {
          qm[ngq][e] = cross(t.v[(e + 1) % 3] - t.v[e], n);
          qc[ngq][e] = dot(qm[ngq][e], t.v[e]) + margin * norm(qm[ngq][e]);
        }
        ++ngq;
      }
    }
    auto outside = [&](const Vec3<T> &v) {
      for (int g = 0; g < ngq; ++g)
        if (dot(qm[g][0], v) <= qc[g][0] && dot(qm[g][1], v) <= qc[g][1] &&
            dot(qm[g][2], v) <= qc[g][2])
          return false;
      return ngq > 0;
    };
    int m = 0;
    for (int i = 0; i < sv.nverts; ++i) {
      ws->dist[i] = dot(n, wall_vert(i) - o);
      if (ws->dist[i] < T(0)) {
        if (outside(wall_vert(i))) return false;
        ws->hu[m] = dot(wall_vert(i) - o, e1);
        ws->hv[m++] = dot(wall_vert(i) - o, e2);
      }
    }
    for (int k = 0; k < sv.nedges; ++k) {
      const int i = sv.edges[2 * k], j = sv.edges[2 * k + 1];
      const T di = ws->dist[i], dj = ws->dist[j];
      if ((di < T(0)) == (dj < T(0))) continue;
      const Vec3<T> vi = wall_vert(i);
      const Vec3<T> x = vi + (di / (di - dj)) * (wall_vert(j) - vi);
      if (outside(x)) return false;
      const Vec3<T> p = x - o;
      ws->hu[m] = dot(p, e1);
      ws->hv[m++] = dot(p, e2);
    }
    if (m < 3) return false;
    // convex hull (monotone chain) into pu/pv, counter-clockwise
    for (int i = 1; i < m; ++i) {    // insertion sort by (u, v)
      const T u = ws->hu[i], v = ws->hv[i];
      int j = i - 1;
      while (j >= 0 && (ws->hu[j] > u || (ws->hu[j] == u && ws->hv[j] > v))) {
        ws->hu[j + 1] = ws->hu[j];
        ws->hv[j + 1] = ws->hv[j];
        --j;
      }
      ws->hu[j + 1] = u;
      ws->hv[j + 1] = v;
    }
    int h = 0;
    for (int pass = 0; pass < 2; ++pass) {
      const int start = h;
      for (int ii = 0; ii < m; ++ii) {
        const int i = pass == 0 ? ii : m - 1 - ii;
        while (h >= start + 2 &&
               (ws->pu[h - 1] - ws->pu[h - 2]) * (ws->hv[i] - ws->pv[h - 2]) -
                       (ws->pv[h - 1] - ws->pv[h - 2]) * (ws->hu[i] - ws->pu[h - 2]) <= T(0))
          --h;
        ws->pu[h] = ws->hu[i];
        ws->pv[h++] = ws->hv[i];
      }
      --h;    // last point is the first of the other chain
    }
    if (h < 3) return false;
    T area = T(0), cu = T(0), cv = T(0), rad = T(0);
    for (int i = 0; i < h; ++i) {
      const int j = (i + 1) % h;
      area += T(0.5) * (ws->pu[i] * ws->pv[j] - ws->pu[j] * ws->pv[i]);
      cu += ws->pu[i] / T(h);
      cv += ws->pv[i] / T(h);
    }
    if (!(area > T(0))) return false;
    // area of the hull inside each triangle of the group
    T cov = T(0);
    for (int c = 0; c < ws->ncand; ++c) {
      if (ws->cflag[c] != 2) continue;
      const Triangle<T> t = triangle(ws->cand[c], ws->cside[c]);
      T tu[3], tv[3];
      for (int k = 0; k < 3; ++k) {
        tu[k] = dot(t.v[k] - o, e1);
        tv[k] = dot(t.v[k] - o, e2);
      }
      int q = h;
      for (int k = 0; k < h; ++k) {
        ws->qu[k] = ws->pu[k];    // keep the hull: clip a copy
        ws->qv[k] = ws->pv[k];
        ws->qz[k] = T(0);
      }
      T *iu = ws->qu, *iv = ws->qv, *iz = ws->qz;
      clip_detail::clip_to_triangle(tu, tv, q, iu, iv, iz, ws->hu, ws->hv, ws->hz);
      for (int i = 1; i + 1 < q; ++i)
        cov += T(0.5) * ((iu[i] - iu[0]) * (iv[i + 1] - iv[0]) - (iv[i] - iv[0]) * (iu[i + 1] - iu[0]));
    }
    if (!(fabs(cov - area) <= T(1e-9) * area)) return false;
    for (int i = 0; i < h; ++i) {
      const T du = ws->pu[i] - cu, dv = ws->pv[i] - cv;
      const T r2 = sqrt(du * du + dv * dv);
      rad = r2 > rad ? r2 : rad;
    }
    // equilateral triangle with inradius 2 rad around (cu, cv)
    const T R = T(4) * rad + posed_radius(*a) * T(1e-3);
    for (int k = 0; k < 3; ++k) {
      const T ang = T(1.5707963267948966) + T(2.0943951023931957) * T(k);
      big.v[k] = o + (cu + R * cos(ang)) * e1 + (cv + R * sin(ang)) * e2;
    }
    return true;
  }

  // t: the triangle's index, or -1 for a coplanar group's large triangle;
  // key: its patch key (wall_region_key)
  POLYDEM_FN void clip_add(const Triangle<T> &tri, int t, int key)
  {
    const ClipResult<T> r = polyhedron_triangle(*a, tri, ws->clip, ws->verts);
    if (r.status == STATUS_SEPARATED) return;
    if (r.status == STATUS_OVERFLOW) {
      out->noverflow++;
      return;
    }
    if (r.status != STATUS_OK) {
      out->ndegenerate++;
      return;
    }
    out->ntri++;
    bool opened;
    const int k = wall_patch_slot(*out, *g, key, r.normal, cosmax, opened);
    if (opened) {
      WallPatch<T> &p = out->p[k];
      const Vec3<T> z = make_vec3(T(0), T(0), T(0));
      p.p0 = tri.v[0];
      p.volume = p.area = T(0);
      p.depth = T(0);
      p.behind = 0;
      for (int i = 0; i < a->view->nverts; ++i) {
        const T d = dot(r.normal, tri.v[0] - wall_vert(i));
        p.depth = d > p.depth ? d : p.depth;
      }
      p.S = p.M = p.ac = p.vc = z;
    }
    WallPatch<T> &p = out->p[k];
    // centroid behind the triangle as met, inside its prism (a coplanar
    // group's large triangle covers the part behind, so the centroid too)
    if (!p.behind && dot(r.normal, tri.v[0] - a->x) > T(0)) {
      bool inside = true;
      for (int e = 0; e < 3 && inside; ++e)
        inside = dot(cross(tri.v[(e + 1) % 3] - tri.v[e], r.normal), a->x - tri.v[e]) <= T(0);
      p.behind = inside ? 1 : 0;
    }
    if (ws->record && t >= 0 && ws->nrec >= WALL_MAX_CAND) out->nunrecorded++;
    if (ws->record && t >= 0 && ws->nrec < WALL_MAX_CAND) {
      ws->rtri[ws->nrec] = t;
      ws->rpatch[ws->nrec] = (signed char) k;
      ws->rarea[ws->nrec] = r.area;
      ws->rvol[ws->nrec] = r.volume;
      ws->nrec++;
    }
    p.volume += r.volume;
    p.area += r.area;
    p.S += r.S;
    p.M += r.M;
    p.ac += r.area * r.acentroid;
    p.vc += r.volume * r.vcentroid;
  }
};

// Certified lower bound of the motion (of any point of the particle: posed
// vertices ws.verts, centre c, bounding radius r) before triangle t can meet
// its volume within the sphere (c, reach). One-sided: the distance to the
// part of the prism behind the plane. The plane alone bounds it when the
// particle is in front of it; else GJK against the prism truncated at the
// sphere's deepest point behind the plane. Two-sided (both): the same for
// the side opposite the centroid, as the centroid's side is what acts;
// the other side can act only once the centroid is within WALL_SIDE_TOL r
// of the plane (wall_side, while no kept contact has crossed its plane:
// wall_sides_crossed), so its bound is |h_c| - WALL_SIDE_TOL r.
template <typename T, int MF, int ME>
POLYDEM_FN T wall_prism_gap(const MeshGridView<T> &g, int t, const WallWorkspace<T, MF, ME> &ws,
                            int nv, const Vec3<T> &c, T r, T reach, T stop, int both,
                            const int *vadj, int &vstart)
{
  const T *pc = g.plane + 4 * t;
  const T hc = pc[0] * c.x + pc[1] * c.y + pc[2] * c.z - pc[3];
  const T sd = both && hc < T(0) ? T(-1) : T(1);
  const T pl[4] = {sd * pc[0], sd * pc[1], sd * pc[2], sd * pc[3]};
  const T other = both ? sd * hc - T(WALL_SIDE_TOL) * r : T(1e300);
  // the vertex nearest the plane: a support search along -n (climbing the
  // template's edges from the previous triangle's answer, where vadj is set)
  vstart =
      support_index_points_inl(ws.verts, nv, vadj, make_vec3(-pl[0], -pl[1], -pl[2]), vstart);
  const T *vm = ws.verts + 3 * vstart;
  const T hmin = pl[0] * vm[0] + pl[1] * vm[1] + pl[2] * vm[2] - pl[3];
  if (hmin > T(0)) return hmin < other ? hmin : other;
  const T depth = reach - sd * hc;
  T B[18];
  const T *q = g.tri + 9 * t;
  for (int v = 0; v < 3; ++v)
    for (int k = 0; k < 3; ++k) {
      B[3 * v + k] = q[3 * v + k];
      B[9 + 3 * v + k] = q[3 * v + k] - depth * pl[k];
    }
  const T gap = hull_gap_lower_bound(ws.verts, nv, B, 6, T(1e-12) * reach, stop, vadj);
  return gap < other ? gap : other;
}

// grid visitor of a near-list build. A triangle can become a candidate only
// once m >= e_t = max(g_t, d_t - r), d_t its distance from the centre (the
// step's sphere test): keeps (t, e_t) for e_t <= skin; valid = the smallest
// e_t (or a lower bound of it) of the triangles left out, starting at the
// query's extra reach S. A full list drops its largest e_t for a smaller one
// (valid then shrinks to the dropped value), so it keeps the cap smallest.
// The entries within reach at every step are marked once valid is known
// (wall_near_visit).
template <typename T, int MF, int ME> struct WallNearBuild {
  const MeshGridView<T> *g;
  const WallWorkspace<T, MF, ME> *ws;
  WallNear<T> *near;
  Vec3<T> c;
  T r, reach, skin, valid;
  int nv, n, both;
  const int *vadj;    // the template's vertex adjacency, or null (support scans)
  int vstart;         // the last support vertex
  // d2: the squared distance from c to triangle t (mesh_for_each_near_dist2)
  POLYDEM_FN void operator()(int t, T d2)
  {
    const T ds = sqrt(d2) - r;
    if (ds > skin) {    // out of the step's sphere for m < ds
      valid = ds < valid ? ds : valid;
      return;
    }
    T gap = wall_prism_gap(*g, t, *ws, nv, c, r, reach, valid, both, vadj, vstart);
    if (!(gap == gap)) gap = T(0);    // no bound: always examined
    gap = ds > gap ? ds : gap;
    if (gap > skin) {
      valid = gap < valid ? gap : valid;
      return;
    }
    const float e = float(gap * T(1 - 1e-6));    // float rounding is < 1e-7 relative
    near_list_keep(*near, n, t, e, valid);
  }
};

// Visits the candidate triangles of a through its near list (rebuilt when
// the motion bound exceeds the skin). False if the list cannot be used (it
// overflowed, or the pose is not finite): the caller queries the grid.
template <typename T, int MF, int ME>
POLYDEM_FN bool wall_near_visit(const PosedShape<T> &a, const MeshGridView<T> &g,
                                WallWorkspace<T, MF, ME> &ws, WallNear<T> &near,
                                WallAccumulate<T, MF, ME> &acc)
{
  near.built = 0;
  if (*near.count == NEAR_OVERFLOW || wall_sides_crossed(acc.sides)) return false;
  const T r = posed_radius(a);
  if (!(norm2(a.x) < T(1e300)) || !(r > T(0))) return false;
  T amax = fabs(a.x.x) > fabs(a.x.y) ? fabs(a.x.x) : fabs(a.x.y);
  amax = fabs(a.x.z) > amax ? fabs(a.x.z) : amax;
  // round-off of the motion bound and of the gaps [length]
  const T slack = T(1e-7) * r + T(1e-13) * amax;
  T m = T(0);
  if (*near.count >= 0) {
    const T *ref = near.ref;
    T tr = T(0);
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k) tr += a.R.m[i][k] * ref[3 + 3 * i + k];
    const T rot = T(3) - tr;
    m = norm(a.x - make_vec3(ref[0], ref[1], ref[2])) + r * sqrt(rot > T(0) ? rot : T(0)) + slack;
    if (!(m <= ref[12])) *near.count = NEAR_REBUILD;
  }
  if (*near.count == NEAR_REBUILD) {
    // The query reaches NEAR_REACH skins beyond r, and the list stays valid
    // while m is below the smallest e_t of the triangles it left out: a
    // particle with no triangle near (inside a bed, in flight) rebuilds
    // NEAR_REACH times less often, and a list that is full is valid for a
    // shorter motion instead of failing.
    WallNearBuild<T, MF, ME> b;
    b.g = &g;
    b.ws = &ws;
    b.near = &near;
    b.c = a.x;
    b.nv = a.view->nverts;
    b.vadj = a.view->vadj;
    b.vstart = 0;
    b.both = acc.sides && acc.sides->both;
    b.r = r;
    b.skin = near.skin;
    b.valid = T(NEAR_REACH) * b.skin;
    b.reach = r + b.valid;
    b.n = 0;
    near.built = 1;
    mesh_for_each_near_dist2(g, a.x, b.reach, b);
    if (!(b.valid * T(1 - 1e-6) >= T(0.0625) * b.skin)) {
      // more than cap triangles within skin/16: a list would be rebuilt
      // nearly every step, so none until invalidated (the grid every step)
      *near.count = NEAR_OVERFLOW;
      return false;
    }
    near.ref[12] = b.valid * T(1 - 1e-6);    // excluded triangles: e_t > m
    *near.count = b.n;
    // The list serves while m <= ref[12], and the centre moves less than m:
    // a kept triangle whose distance d_t from the centre here is below r by
    // more than that (and a margin for the round-off of the distances)
    // passes every step's sphere test, so it is kept as -1 - t and the steps
    // skip that test for it (a particle at rest on a fine mesh: most of its
    // list). The same triangles reach the candidates either way.
    {
      const T margin = T(1e-9) * r + T(1e-12) * (fabs(a.x.x) + fabs(a.x.y) + fabs(a.x.z));
      const T lim = r - near.ref[12] - margin;
      for (int e = 0; e < b.n && lim > T(0); ++e) {
        const int t = near.tri[e];
        const T *q = g.tri + 9 * t;
        const T dd = point_triangle_dist2(a.x, make_vec3(q[0], q[1], q[2]),
                                          make_vec3(q[3], q[4], q[5]), make_vec3(q[6], q[7], q[8]));
        if (sqrt(dd) < lim) near.tri[e] = -1 - t;
      }
    }
    near.ref[0] = a.x.x;
    near.ref[1] = a.x.y;
    near.ref[2] = a.x.z;
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k) near.ref[3 + 3 * i + k] = a.R.m[i][k];
    m = slack;
  }
  const int n = *near.count;
  for (int e = 0; e < n; ++e) {
    if (!(T(near.gap[e]) <= m)) continue;
    const int code = near.tri[e];
    if (code < 0)    // within r of the centre while the list is valid
      acc(-1 - code);
    else if (mesh_tri_near(g, code, a.x, r))
      acc(code);
  }
  return true;
}

// Patches of posed particle a (mesh frame) against the mesh; r: bounding
// radius. near: the particle's near list, or nullptr for the grid query.
// sides: which side of each triangle acts (null: the front only).
template <typename T, int MF, int ME>
POLYDEM_FN void wall_patches(const PosedShape<T> &a, const MeshGridView<T> &g, T cosmax,
                             WallWorkspace<T, MF, ME> &ws, WallPatches<T> &out,
                             WallNear<T> *near = nullptr, const WallSides<T> *sides = nullptr)
{
  out.n = out.noverflow = out.ndegenerate = out.nmerged = out.ntri = out.nunrecorded = 0;
  const ShapeView<T> &sv = *a.view;
  if (sv.nverts > MAX_TEMPLATE_VERTS) {
    out.noverflow++;
    return;
  }
  for (int i = 0; i < sv.nverts; ++i) {
    const Vec3<T> x = a.x + a.s * matvec(a.R, make_vec3(sv.verts[3 * i], sv.verts[3 * i + 1],
                                                         sv.verts[3 * i + 2]));
    ws.verts[3 * i] = x.x;
    ws.verts[3 * i + 1] = x.y;
    ws.verts[3 * i + 2] = x.z;
  }
  WallAccumulate<T, MF, ME> acc;
  acc.a = &a;
  acc.g = &g;
  acc.ws = &ws;
  acc.out = &out;
  acc.cosmax = cosmax;
  acc.sides = sides;
  ws.ncand = 0;
  ws.pvalid = 0;
  ws.vlow = 0;
  ws.nrec = 0;
  if (!(near && near->cap > 0 && wall_near_visit(a, g, ws, *near, acc)))
    mesh_for_each_near(g, a.x, posed_radius(a), acc);
  acc.finish();
}

}    // namespace polydem

#endif
