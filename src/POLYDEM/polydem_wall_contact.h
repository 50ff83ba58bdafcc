/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - contact of one convex polyhedron with a triangle mesh (fix
   wall/mesh and /kk), host and device. No LAMMPS includes.

   Seed §2.4 (Algorithm VII, Eqs. 10-11) weights a facet's force by the
   clipped section area. Here the facets a particle touches are grouped into
   patches of near-coplanar normals (|angle| < patch angle to the patch's
   first facet). Per patch the kernel's per-triangle results are summed:
     V = sum V_t,  S = sum S_t = -sum n_t A_t,  M = sum M_t
   (polydem_clip.h: prisms of a flat triangulated wall partition the space
   behind it, so V, S, M of a flat patch equal those of the infinite plane
   whatever the triangulation), and the patch is one contact of the pair
   model (polydem_contact_law.h, Eqs. 12-20):
     F = -W'(V) S,  tau = -W'(V) M   (+ damping, Cundall-Strack friction),
   so each patch force is the exact gradient of W(V_patch), with no double
   counting or spikes at shared edges and vertices. A sharp edge of the
   mesh (angle > patch angle) gives two contacts, each with its own
   tangential history.

   Wall material: a half-space of (E_w, nu_w) sized like the particle
   (R_w = R_p), so K = (E_p + E_w)/R_p, K_t likewise; m_eff = m_p.

   Sides (issue 17): the seed's walls act from the front (the side n_w
   points to). Here both sides act by default: a triangle met from the back
   is clipped reversed, (t0, t2, t1), so the part of the particle in front
   of it is the overlap. The side is where the particle's centroid is when
   the contact begins, and it is kept while the contact lasts (WallSides).
------------------------------------------------------------------------- */

#ifndef POLYDEM_WALL_CONTACT_H
#define POLYDEM_WALL_CONTACT_H

#include "polydem_clip.h"
#include "polydem_contact_law.h"
#include "polydem_mesh_grid.h"

#include <cmath>
#include <utility>
#include <vector>

namespace polydem {

constexpr int WALL_MAX_PATCH = 4;    // contacts per particle and mesh
// per patch: normal (3), distance from the centroid to its plane (1), shear history
constexpr int WALL_HIST = 4 + CONTACT_HIST;
constexpr int WALL_HIST_SIZE = WALL_MAX_PATCH * WALL_HIST;
constexpr int WALL_MAX_CAND = 1024;    // candidate triangles kept per particle (more: clipped at once)

// One patch. Ellipsoids (polydem_wall_ellipsoid.h) fill the same fields
// with the patch's closest point: volume the overlap volume of the support
// plane (diagnostic: overlap/warn), area 0, S and M the gradient of the
// overlap delta (mesh frame), ac the contact point, vc the deepest point,
// depth delta, tri the triangle of the closest point.
template <typename T> struct WallPatch {
  Vec3<T> nseed;    // first facet's normal n_w (mesh frame)
  T volume, area;
  Vec3<T> S, M;     // sums (mesh frame)
  Vec3<T> ac;       // area-weighted sum of section centroids
  Vec3<T> vc;       // volume-weighted sum of volume centroids
  T depth;          // deepest particle vertex behind the first facet's plane
  int behind;       // the particle's centroid is behind a clipped triangle (in its prism)
  int tri;          // ellipsoids: the triangle of the patch's closest point
};

template <typename T> struct WallPatches {
  int n;
  int noverflow, ndegenerate, nmerged, ntri;    // counts for the host's warnings
  int nunrecorded;    // clipped triangles beyond the per-triangle record (pertriangle)
  WallPatch<T> p[WALL_MAX_PATCH];
};

// Clipping workspace plus the particle's posed vertices (mesh frame), computed
// once per particle for the exact cheap rejects of wall_patches.
template <typename T, int MF = MAX_TEMPLATE_FACES, int ME = 3 * MAX_TEMPLATE_VERTS>
struct WallWorkspace {
  ClipWorkspace<T, MF, ME> clip;
  T verts[3 * MAX_TEMPLATE_VERTS];
  T dist[MAX_TEMPLATE_VERTS];    // signed distances to the current plane
  T pc[4], pbox[6];              // that plane (as stored), the box of the part behind it
  T po[4];                       // that plane as the particle meets it (pside x pc)
  int pvalid, pany, pside;       // cache valid; a vertex behind it; side (+1 front, -1 back)
  // candidates of one particle, and the coplanar-group coverage test
  static constexpr int MAXH = 4 * MAX_TEMPLATE_VERTS + 8;
  int cand[WALL_MAX_CAND];
  signed char cside[WALL_MAX_CAND];    // side each candidate is met on
  unsigned char cflag[WALL_MAX_CAND];
  int ncand;
  // per-triangle record (fix wall/mesh pertriangle yes): triangle, patch,
  // section area and volume of every clipped triangle
  int record, nrec;
  int rtri[WALL_MAX_CAND];
  signed char rpatch[WALL_MAX_CAND];
  T rarea[WALL_MAX_CAND], rvol[WALL_MAX_CAND];
  T hu[MAXH], hv[MAXH], pu[MAXH], pv[MAXH], qu[MAXH], qv[MAXH], hz[MAXH], qz[MAXH];    // hz, qz: 0
};

// Near list of one particle (cache, keyword 'cache'): a Verlet list of
// particle-triangle pairs in the mesh frame. Built with the particle's pose
// at reference (x_ref, R_ref): every triangle within r + S of the centre
// (S = NEAR_REACH x skin), each with a certified lower bound g_t of the
// distance from the particle to the part of the triangle's prism behind its
// plane that lies within that sphere (hull_gap_lower_bound), and with
// e_t = max(g_t, d_t - r) (d_t: distance from the centre), kept with e_t if
// e_t <= skin. The list is valid up to s_v = min(S, e_t of the triangles
// left out) >= skin. While every point of the particle has moved by at most
// m = |x - x_ref| + r |R R_ref^T - I|_2 <= s_v (|R R_ref^T - I|_2 =
// sqrt(3 - tr R R_ref^T)), a triangle with g_t > m cannot meet the
// particle's volume, one with d_t - r > m is beyond r of x (the step's
// sphere test), and one beyond r + S of x_ref too, so only the triangles
// with e_t <= m are examined; the others are skipped without reading the
// mesh.
// The candidates, and so the forces, are those of the full grid query (to
// round-off; finish() sorts them, so the order does not depend on the path).
// The lists index local atoms: the fix invalidates them when atoms move
// between ranks or are sorted (reneighboring) and at setup.
template <typename T> struct WallNear {
  T *ref;        // 13: x_ref (3), R_ref row-major (9), mesh frame; s_v, the list's validity
  int *count;    // entries; NEAR_REBUILD: build now; NEAR_OVERFLOW: no list until invalidated
  int *tri;      // cap triangle indices
  float *gap;    // cap e_t [length], rounded down
  int cap;
  T skin;        // [length]
  int built;     // out: 1 if the list was (re)built by this call
};
constexpr int NEAR_REACH = 8;    // query reach r + NEAR_REACH x skin at a build
constexpr int NEAR_REBUILD = -1;
constexpr int NEAR_OVERFLOW = -2;

// Which side of a triangle acts on a particle (two-sided walls). The side
// is where the centroid is when the contact begins, kept while it lasts:
// a contact kept from the previous step (normal n_c from the particle into
// the wall, e_c = n_c . (p_c - x) the distance from the centroid x to its
// plane through the section centroid p_c) claims a triangle whose plane,
// met on side s (normal -s n_t into the wall, distance e = s h, h the
// centroid's height above the front), agrees with it: normals within 45
// degrees, planes within WALL_SIDE_TOL x the bounding radius (the closest
// wins). Any other triangle is met on the centroid's side. A particle pushed
// beyond its centroid is then still pushed back, two parallel walls on
// either side of a particle are told apart by their planes, and a closed
// mesh acts alike with either normal convention.
constexpr double WALL_SIDE_COS = 0.70710678118654752;    // cos 45 degrees
constexpr double WALL_SIDE_TOL = 0.1;                    // x bounding radius

template <typename T> struct WallSides {
  int both;                      // 1: two-sided; 0: the front only (sides front)
  int n;                         // contacts kept from the previous step
  Vec3<T> nc[WALL_MAX_PATCH];    // their normals (mesh frame)
  T ec[WALL_MAX_PATCH];          // their plane distances [length]
};

// +1: front, -1: back, for the plane pl (unit normal, offset) of a triangle,
// centroid c and bounding radius r (mesh frame); s null: the front
template <typename T>
POLYDEM_FN int wall_side(const WallSides<T> *s, const T *pl, const Vec3<T> &c, T r)
{
  if (!s || !s->both) return 1;
  const T h = pl[0] * c.x + pl[1] * c.y + pl[2] * c.z - pl[3];
  int side = h >= T(0) ? 1 : -1;
  T best = T(WALL_SIDE_TOL) * r;
  for (int k = 0; k < s->n; ++k) {
    const T cn = s->nc[k].x * pl[0] + s->nc[k].y * pl[1] + s->nc[k].z * pl[2];
    const int sk = cn <= -T(WALL_SIDE_COS) ? 1 : (cn >= T(WALL_SIDE_COS) ? -1 : 0);
    if (!sk) continue;
    const T d = fabs(T(sk) * h - s->ec[k]);
    if (d <= best) {
      best = d;
      side = sk;
    }
  }
  return side;
}

// a kept contact whose centroid has crossed its plane (e_c < 0) may claim
// the back of a triangle the centroid is in front of: the near lists'
// side bound (wall_prism_gap) assumes there is none
template <typename T> POLYDEM_FN bool wall_sides_crossed(const WallSides<T> *s)
{
  if (!s || !s->both) return false;
  for (int k = 0; k < s->n; ++k)
    if (!(s->ec[k] >= T(0))) return true;
  return false;
}

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
      ws->pside = wall_side(sides, pc, a->x, posed_radius(*a));
      for (int k = 0; k < 4; ++k) ws->po[k] = T(ws->pside) * pc[k];
      const T *pl = ws->po;
      ws->pvalid = 1;
      ws->pany = 0;
      for (int k = 0; k < 3; ++k) {
        ws->pbox[k] = T(1e300);
        ws->pbox[3 + k] = T(-1e300);
      }
      for (int i = 0; i < sv.nverts; ++i) {
        const Vec3<T> v = wall_vert(i);
        ws->dist[i] = pl[0] * v.x + pl[1] * v.y + pl[2] * v.z - pl[3];
        if (ws->dist[i] < T(0)) {
          ws->pany = 1;
          grow_box(v - ws->dist[i] * make_vec3(pl[0], pl[1], pl[2]));    // onto the plane
        }
      }
      for (int k = 0; k < sv.nedges && ws->pany; ++k) {
        const int i = sv.edges[2 * k], j = sv.edges[2 * k + 1];
        const T di = ws->dist[i], dj = ws->dist[j];
        if ((di < T(0)) == (dj < T(0))) continue;
        const Vec3<T> vi = wall_vert(i);
        grow_box(vi + (di / (di - dj)) * (wall_vert(j) - vi));
      }
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

  // tri: triangle t as met (plane_of(t) first)
  POLYDEM_FN bool separated(int t, const Triangle<T> &tri) const
  {
    const ShapeView<T> &sv = *a->view;
    if (!ws->pany) return true;
    const T *b = g->box + 6 * t;
    for (int k = 0; k < 3; ++k)
      if (b[3 + k] < ws->pbox[k] || b[k] > ws->pbox[3 + k]) return true;
    const T *pl = ws->po;
    const Vec3<T> nr = make_vec3(pl[0], pl[1], pl[2]);
    for (int e = 0; e < 3; ++e) {
      const Vec3<T> o = tri.v[e], side = cross(tri.v[(e + 1) % 3] - o, nr);    // outward
      bool out = true;
      for (int i = 0; i < sv.nverts && out; ++i)
        if (ws->dist[i] < T(0)) out = dot(side, wall_vert(i) - o) > T(0);
      for (int k = 0; k < sv.nedges && out; ++k) {
        const int i = sv.edges[2 * k], j = sv.edges[2 * k + 1];
        const T di = ws->dist[i], dj = ws->dist[j];
        if ((di < T(0)) == (dj < T(0))) continue;
        const Vec3<T> vi = wall_vert(i);
        const Vec3<T> p = vi + (di / (di - dj)) * (wall_vert(j) - vi);
        out = dot(side, p - o) > T(0);
      }
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
    const Triangle<T> tri = triangle(t, ws->pside);
    if (separated(t, tri)) return;
    if (ws->ncand < WALL_MAX_CAND) {
      ws->cside[ws->ncand] = (signed char) ws->pside;
      ws->cand[ws->ncand++] = t;
    } else
      clip_add(tri, t);
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
      Triangle<T> big;
      if (ng > 1 && !ws->record && covered(tc.v[0], n, big)) {
        clip_add(big, -1);
        for (int k = c; k < ws->ncand; ++k)
          if (ws->cflag[k] == 2) ws->cflag[k] = 1;
      } else {
        for (int k = c; k < ws->ncand; ++k)
          if (ws->cflag[k] == 2) {
            ws->cflag[k] = 1;
            clip_add(triangle(ws->cand[k], ws->cside[k]), ws->cand[k]);
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
    int m = 0;
    for (int i = 0; i < sv.nverts; ++i) {
      ws->dist[i] = dot(n, wall_vert(i) - o);
      if (ws->dist[i] < T(0)) {
        ws->hu[m] = dot(wall_vert(i) - o, e1);
        ws->hv[m++] = dot(wall_vert(i) - o, e2);
      }
    }
    for (int k = 0; k < sv.nedges; ++k) {
      const int i = sv.edges[2 * k], j = sv.edges[2 * k + 1];
      const T di = ws->dist[i], dj = ws->dist[j];
      if ((di < T(0)) == (dj < T(0))) continue;
      const Vec3<T> vi = wall_vert(i);
      const Vec3<T> p = vi + (di / (di - dj)) * (wall_vert(j) - vi) - o;
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

  // t: the triangle's index, or -1 for a coplanar group's large triangle
  POLYDEM_FN void clip_add(const Triangle<T> &tri, int t)
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
    int k = -1;
    T best = T(-2);
    for (int i = 0; i < out->n; ++i) {
      const T c = dot(out->p[i].nseed, r.normal);
      if (c > best) {
        best = c;
        k = i;
      }
    }
    if (k < 0 || best < cosmax) {
      if (out->n < WALL_MAX_PATCH) {
        k = out->n++;
        WallPatch<T> &p = out->p[k];
        const Vec3<T> z = make_vec3(T(0), T(0), T(0));
        p.nseed = r.normal;
        p.volume = p.area = T(0);
        p.depth = T(0);
        p.behind = 0;
        for (int i = 0; i < a->view->nverts; ++i) {
          const T d = dot(r.normal, tri.v[0] - wall_vert(i));
          p.depth = d > p.depth ? d : p.depth;
        }
        p.S = p.M = p.ac = p.vc = z;
      } else
        out->nmerged++;    // more facet orientations than patches: join the closest
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
                            int nv, const Vec3<T> &c, T r, T reach, T stop, int both)
{
  const T *pc = g.plane + 4 * t;
  const T hc = pc[0] * c.x + pc[1] * c.y + pc[2] * c.z - pc[3];
  const T sd = both && hc < T(0) ? T(-1) : T(1);
  const T pl[4] = {sd * pc[0], sd * pc[1], sd * pc[2], sd * pc[3]};
  const T other = both ? sd * hc - T(WALL_SIDE_TOL) * r : T(1e300);
  T hmin = T(1e300);
  for (int i = 0; i < nv; ++i) {
    const T h = pl[0] * ws.verts[3 * i] + pl[1] * ws.verts[3 * i + 1] +
        pl[2] * ws.verts[3 * i + 2] - pl[3];
    hmin = h < hmin ? h : hmin;
  }
  if (hmin > T(0)) return hmin < other ? hmin : other;
  const T depth = reach - sd * hc;
  T B[18];
  const T *q = g.tri + 9 * t;
  for (int v = 0; v < 3; ++v)
    for (int k = 0; k < 3; ++k) {
      B[3 * v + k] = q[3 * v + k];
      B[9 + 3 * v + k] = q[3 * v + k] - depth * pl[k];
    }
  const T gap = hull_gap_lower_bound(ws.verts, nv, B, 6, T(1e-12) * reach, stop);
  return gap < other ? gap : other;
}

// grid visitor of a near-list build. A triangle can become a candidate only
// once m >= e_t = max(g_t, d_t - r), d_t its distance from the centre (the
// step's sphere test): keeps (t, e_t) for e_t <= skin; valid = the smallest
// e_t (or a lower bound of it) of the triangles left out, starting at the
// query's extra reach S. A full list drops its largest e_t for a smaller one
// (valid then shrinks to the dropped value), so it keeps the cap smallest.
template <typename T, int MF, int ME> struct WallNearBuild {
  const MeshGridView<T> *g;
  const WallWorkspace<T, MF, ME> *ws;
  WallNear<T> *near;
  Vec3<T> c;
  T r, reach, skin, valid;
  int nv, n, both;
  POLYDEM_FN void operator()(int t)
  {
    const T *q = g->tri + 9 * t;
    const T ds = sqrt(point_triangle_dist2(c, make_vec3(q[0], q[1], q[2]),
                                           make_vec3(q[3], q[4], q[5]),
                                           make_vec3(q[6], q[7], q[8]))) - r;
    if (ds > skin) {    // out of the step's sphere for m < ds
      valid = ds < valid ? ds : valid;
      return;
    }
    T gap = wall_prism_gap(*g, t, *ws, nv, c, r, reach, valid, both);
    if (!(gap == gap)) gap = T(0);    // no bound: always examined
    gap = ds > gap ? ds : gap;
    if (gap > skin) {
      valid = gap < valid ? gap : valid;
      return;
    }
    const float e = float(gap * T(1 - 1e-6));    // float rounding is < 1e-7 relative
    if (n < near->cap) {
      near->tri[n] = t;
      near->gap[n++] = e;
      return;
    }
    int kmax = 0;    // full: the entry with the largest e_t
    for (int k = 1; k < n; ++k) kmax = near->gap[k] > near->gap[kmax] ? k : kmax;
    if (near->gap[kmax] > e) {
      valid = T(near->gap[kmax]) < valid ? T(near->gap[kmax]) : valid;
      near->tri[kmax] = t;
      near->gap[kmax] = e;
    } else {
      valid = T(e) < valid ? T(e) : valid;
    }
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
    b.both = acc.sides && acc.sides->both;
    b.r = r;
    b.skin = near.skin;
    b.valid = T(NEAR_REACH) * b.skin;
    b.reach = r + b.valid;
    b.n = 0;
    near.built = 1;
    mesh_for_each_near(g, a.x, b.reach, b);
    if (!(b.valid * T(1 - 1e-6) >= T(0.0625) * b.skin)) {
      // more than cap triangles within skin/16: a list would be rebuilt
      // nearly every step, so none until invalidated (the grid every step)
      *near.count = NEAR_OVERFLOW;
      return false;
    }
    near.ref[12] = b.valid * T(1 - 1e-6);    // excluded triangles: e_t > m
    *near.count = b.n;
    near.ref[0] = a.x.x;
    near.ref[1] = a.x.y;
    near.ref[2] = a.x.z;
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k) near.ref[3 + 3 * i + k] = a.R.m[i][k];
    m = slack;
  }
  const int n = *near.count;
  for (int e = 0; e < n; ++e)
    if (T(near.gap[e]) <= m && mesh_tri_near(g, near.tri[e], a.x, r)) acc(near.tri[e]);
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
  ws.nrec = 0;
  if (!(near && near->cap > 0 && wall_near_visit(a, g, ws, *near, acc)))
    mesh_for_each_near(g, a.x, posed_radius(a), acc);
  acc.finish();
}

// Rigid motion of the mesh: p_lab = o + d + Rm (p_mesh - o); wall velocity
// at p_lab: vw + w x (p_lab - o - d).
template <typename T> struct MeshPose {
  Vec3<T> o, d;    // rotation origin (mesh frame = lab at t=0), displacement
  Mat3<T> R;       // rotation
  Quat<T> q;       // same rotation as a quaternion
  Vec3<T> vw, w;   // translation velocity, angular velocity (lab)
};

// Normal damping of a wall contact. The pair's damping ratio is that of a
// face contact (V = A delta, W' ~ V^(1/3)) of a free particle. A corner or
// edge hitting a wall is a different self-similar contact: with V ~ delta^a
// (a = 1 face, 2 edge, 3 vertex) and W' ~ V^q (q = dlnW'/dlnV: 1/3 for
// Feng's law, 1 deep in the quadratic core V << V0), F = W'(V) A ~
// delta^(a(q+1) - 1) and the model's local stiffness W''(V) A^2 = q a F /
// delta. The damping ratio for restitution e then depends on q (exactly, not
// on a: polydem_damping.h), and the contact point sees the mass m_c = 1 /
// (1/m + (r x n).I^-1 (r x n)) (r: centre to contact point), not m. The wall
// contact uses m_c and zeta(e, q) (DampingLaw with local = 1), so that a
// corner impact reverses the contact point's normal velocity by e (the
// assumption of seed Eqs. 27-28).

template <typename T> struct WallForce {
  Vec3<T> f, tau;    // on the particle (torque about its centroid)
  T energy;          // sum of W(V) over patches
  int ncontact;
  int fresh;                         // bit k: patch k has no kept history (its contact begins)
  Vec3<T> fpatch[WALL_MAX_PATCH];    // force of each patch of P on the particle (lab)
};

// The contacts of one particle with one mesh as the contact layer sees them
// (lab frame), indexed like the patches they come from: on[k] = 0 when
// patch k makes no contact. Polyhedron patches (wall_patch_contacts) and
// ellipsoid patches (polydem_wall_ellipsoid.h) both end here, and
// wall_contact_forces is the one loop of slot matching, contact_step and
// history for both.
template <typename T> struct WallContacts {
  int n;
  int on[WALL_MAX_PATCH];
  ContactGeometry<T> g[WALL_MAX_PATCH];
};

// Polyhedron patches: V, S = -sum n_t A_t, M summed over the patch's
// triangles (mesh frame) -> one contact each, normal S / |S| from the
// particle into the wall, contact point the area-weighted section centroid
// (the volume centroid if the patch has no section area).
template <typename T>
POLYDEM_FN WallContacts<T> wall_patch_contacts(const WallPatches<T> &P, const MeshPose<T> &mp)
{
  WallContacts<T> C;
  C.n = P.n;
  const Vec3<T> xw = mp.o + mp.d;    // a point of the wall's rotation axis (lab)
  for (int k = 0; k < P.n; ++k) {
    const WallPatch<T> &q = P.p[k];
    const T an = norm(q.S);
    C.on[k] = q.volume > T(0) && an > T(0);
    if (!C.on[k]) continue;
    ContactGeometry<T> &g = C.g[k];
    g.volume = q.volume;
    g.area = an;
    g.S_A = matvec(mp.R, q.S);
    g.M_A = matvec(mp.R, q.M);
    g.M_B = make_vec3(T(0), T(0), T(0));
    g.normal = (T(1) / an) * g.S_A;    // from the particle into the wall
    const Vec3<T> cm = q.area > T(0) ? (T(1) / q.area) * q.ac : (T(1) / q.volume) * q.vc;
    g.centroid = xw + matvec(mp.R, cm - mp.o);
    g.gradient_damping = 0;
  }
  return C;
}

// Forces of all contacts on the particle (lab frame) and the update of its
// tangential history hist[WALL_HIST_SIZE] for this mesh: each contact takes
// the old slot whose normal is closest within the patch angle (else a fresh
// spring); unmatched slots are cleared. Each slot also keeps its plane's
// distance from the centroid (WallSides). law: the particle's wall law
// (wall_law, or ellipsoid_law); m its mass, Iinv its inverse principal
// moments, R its rotation (body -> frame of the contact normals, for the
// contact point's mass); dt the time step (0: no history increment, setup).
template <typename T>
POLYDEM_FN WallForce<T> wall_contact_forces(const WallContacts<T> &C, const MeshPose<T> &mp,
                                            const ContactLaw<T> &law, T m, const Vec3<T> &Iinv,
                                            const Mat3<T> &R, T cosmax, const Vec3<T> &x,
                                            const Vec3<T> &v, const Vec3<T> &w, T dt, T *hist,
                                            bool update)
{
  WallForce<T> out;
  out.f = out.tau = make_vec3(T(0), T(0), T(0));
  out.energy = T(0);
  out.ncontact = 0;
  out.fresh = 0;
  for (int k = 0; k < WALL_MAX_PATCH; ++k) out.fpatch[k] = make_vec3(T(0), T(0), T(0));
  T newh[WALL_HIST_SIZE];
  for (int i = 0; i < WALL_HIST_SIZE; ++i) newh[i] = T(0);
  bool used[WALL_MAX_PATCH] = {false, false, false, false};
  const Vec3<T> xw = mp.o + mp.d;    // a point of the wall's rotation axis (lab)
  ContactKinematics<T> kin;
  kin.xA = x;
  kin.xB = xw;
  kin.vA = v;
  kin.vB = mp.vw;
  kin.wA = w;
  kin.wB = mp.w;
  kin.dt = dt;
  for (int k = 0; k < C.n; ++k) {
    if (!C.on[k]) continue;
    const ContactGeometry<T> &g = C.g[k];
    // history slot with the closest normal (lab frame)
    int best = -1;
    T bc = cosmax;
    for (int s = 0; s < WALL_MAX_PATCH; ++s) {
      const T *h = hist + WALL_HIST * s;
      const T c = h[0] * g.normal.x + h[1] * g.normal.y + h[2] * g.normal.z;
      if (!used[s] && c >= bc) {
        bc = c;
        best = s;
      }
    }
    T shear[CONTACT_HIST];
    for (int i = 0; i < CONTACT_HIST; ++i) shear[i] = T(0);
    if (best >= 0) {
      used[best] = true;
      for (int i = 0; i < CONTACT_HIST; ++i) shear[i] = hist[WALL_HIST * best + 4 + i];
    } else
      out.fresh |= 1 << k;
    // the mass the contact point sees
    const Vec3<T> rn = matTvec(R, cross(g.centroid - x, g.normal));
    const T im = T(1) / m + rn.x * rn.x * Iinv.x + rn.y * rn.y * Iinv.y + rn.z * rn.z * Iinv.z;
    kin.meff = T(1) / im;
    const ContactForce<T> cf = contact_step(g, law, kin, shear, CONTACT_HIST);
    T *h = newh + WALL_HIST * out.ncontact;
    h[0] = g.normal.x;
    h[1] = g.normal.y;
    h[2] = g.normal.z;
    h[3] = dot(g.normal, g.centroid - x);
    for (int i = 0; i < CONTACT_HIST; ++i) h[4 + i] = shear[i];
    out.f += cf.F_A;
    out.fpatch[k] = cf.F_A;
    out.tau += cf.tau_A;
    out.energy += cf.energy;
    out.ncontact++;
  }
  if (update)    // setup (no time step yet) leaves the history as it was
    for (int i = 0; i < WALL_HIST_SIZE; ++i) hist[i] = newh[i];
  return out;
}

// Forces of the polyhedron patches P (wall_patch_contacts, wall_contact_forces).
template <typename T>
POLYDEM_FN WallForce<T> wall_forces(const WallPatches<T> &P, const MeshPose<T> &mp,
                                    const ContactLaw<T> &law, T m, const Vec3<T> &Iinv,
                                    const Mat3<T> &R, T cosmax, const Vec3<T> &x,
                                    const Vec3<T> &v, const Vec3<T> &w, T dt, T *hist, bool update)
{
  return wall_contact_forces(wall_patch_contacts(P, mp), mp, law, m, Iinv, R, cosmax, x, v, w, dt,
                             hist, update);
}

// Wall law of a particle (volume V, material E, nu) on the wall (wE, wnu):
// the wall is a half-space sized like the particle (R_w = R_p) and of
// infinite mass; damping of restitution e at the contact's exponent
// (damping_law(e, 1) on the host).
template <typename T>
POLYDEM_FN ContactLaw<T> wall_law(T E, T nu, T wE, T wnu, T V, const DampingLaw<T> &d, T mu,
                                  T core, int twist)
{
  return feng_law(E, nu, V, wE, wnu, V, d, mu, core, twist);
}

// Torque on the mesh about its axis point o + d balancing the particle's
// force f and torque tau (about x).
template <typename T>
POLYDEM_FN Vec3<T> wall_reaction_torque(const Vec3<T> &x, const WallForce<T> &wf,
                                        const MeshPose<T> &mp)
{
  return -(wf.tau + cross(x - (mp.o + mp.d), wf.f));
}

// The sides the contacts kept in hist claim (mesh frame; WallSides)
template <typename T>
POLYDEM_FN WallSides<T> wall_kept_sides(const T *hist, const MeshPose<T> &mp, int both)
{
  WallSides<T> s;
  s.both = both;
  s.n = 0;
  for (int k = 0; k < WALL_MAX_PATCH && both; ++k) {
    const T *h = hist + WALL_HIST * k;
    if (h[0] == T(0) && h[1] == T(0) && h[2] == T(0)) continue;
    s.nc[s.n] = matTvec(mp.R, make_vec3(h[0], h[1], h[2]));
    s.ec[s.n++] = h[3];
  }
  return s;
}

// Everything for one particle (lab pose x, q, s; velocity v, spin w):
// pose into the mesh frame, patches, forces back in the lab frame.
// both: two-sided wall (else the front of each triangle only).
template <typename T, int MF, int ME>
POLYDEM_FN WallForce<T>
wall_particle(const ShapeView<T> &sv, const Pose<T> &lab, const MeshPose<T> &mp,
              const MeshGridView<T> &g, const ContactLaw<T> &law, T m, T dt, T cosmax, int both,
              const Vec3<T> &v, const Vec3<T> &w, T *hist, bool update,
              WallWorkspace<T, MF, ME> &ws, WallPatches<T> &P, WallNear<T> *near = nullptr)
{
  Pose<T> pm;
  pm.x = mp.o + matTvec(mp.R, lab.x - mp.o - mp.d);
  pm.q = qmul(qconj(mp.q), lab.q);
  pm.s = lab.s;
  const PosedShape<T> a = make_posed(sv, pm);
  const WallSides<T> sides = wall_kept_sides(hist, mp, both);
  wall_patches(a, g, cosmax, ws, P, near, &sides);
  // inverse principal moments: I = rho s^5 I_unit, rho = m / (s^3 V_unit)
  const T rho = m / (lab.s * lab.s * lab.s * sv.volume), s5 = lab.s * lab.s * lab.s * lab.s * lab.s;
  const Vec3<T> Iinv = make_vec3(T(1) / (rho * s5 * sv.inertia[0]), T(1) / (rho * s5 * sv.inertia[1]),
                                 T(1) / (rho * s5 * sv.inertia[2]));
  // the contact-point mass needs the particle's lab rotation (a.R is in the
  // mesh frame: on a rotating mesh it used the wrong body axes until
  // December 2026)
  return wall_forces(P, mp, law, m, Iinv, quat_to_mat(lab.q), cosmax, lab.x, v, w, dt, hist,
                     update);
}

// What fix wall/mesh warns about, per particle (issue 17): contacts whose
// particle's centroid is behind the triangle it is met on (a one-sided wall
// met from behind, or a two-sided one pushed beyond the centroid), deeper
// than depth_warn x the bounding radius r, or with an overlap volume beyond
// overlap_warn x the particle's volume Vp; and contacts that begin (no kept
// history; at setup: particles created or moved into the mesh) with their
// largest V / Vp, depth / r, and the particle's wall energy per mass.
template <typename T> struct WallWarnings {
  int behind, deep, large, fresh;
  T fresh_v, fresh_d, fresh_em;
};

template <typename T>
POLYDEM_FN WallWarnings<T> wall_warnings(const WallPatches<T> &P, const WallForce<T> &wf, T Vp, T r,
                                         T m, T depth_warn, T overlap_warn)
{
  WallWarnings<T> w;
  w.behind = w.deep = w.large = w.fresh = 0;
  w.fresh_v = w.fresh_d = w.fresh_em = T(0);
  for (int k = 0; k < P.n; ++k) {
    const WallPatch<T> &q = P.p[k];
    if (!(q.volume > T(0))) continue;
    w.behind += q.behind;
    w.deep += q.depth > depth_warn * r ? 1 : 0;
    w.large += q.volume > overlap_warn * Vp ? 1 : 0;
    if (!((wf.fresh >> k) & 1)) continue;
    w.fresh++;
    w.fresh_v = q.volume / Vp > w.fresh_v ? q.volume / Vp : w.fresh_v;
    w.fresh_d = q.depth / r > w.fresh_d ? q.depth / r : w.fresh_d;
    w.fresh_em = wf.energy / m;
  }
  return w;
}

// d += s for two WallTally (either may be volatile: Kokkos 3 joins)
template <class D, class S> POLYDEM_FN void wall_tally_merge(D &d, const S &s)
{
  for (int k = 0; k < 3; ++k) {
    d.force[k] += s.force[k];
    d.torque[k] += s.torque[k];
  }
  d.ncontact += s.ncontact;
  d.ntri += s.ntri;
  d.energy += s.energy;
  d.noverflow += s.noverflow;
  d.ndegenerate += s.ndegenerate;
  d.nmerged += s.nmerged;
  d.near_overflow += s.near_overflow;
  d.near_builds += s.near_builds;
  d.nunrecorded += s.nunrecorded;
  d.behind += s.behind;
  d.deep += s.deep;
  d.large += s.large;
  d.fresh += s.fresh;
  if (s.fresh_v > d.fresh_v) d.fresh_v = s.fresh_v;
  if (s.fresh_d > d.fresh_d) d.fresh_d = s.fresh_d;
  if (s.fresh_em > d.fresh_em) d.fresh_em = s.fresh_em;
}

// What one call of fix wall/mesh sums over its particles (plain: a loop;
// /kk: a reduction over threads): the reaction on the mesh, contacts,
// energy, kernel counts and warnings; maxima for the contacts that begin.
template <typename T> struct WallTally {
  T force[3], torque[3];    // reaction on the mesh (lab; torque about its axis point)
  T ncontact, ntri, energy;
  T noverflow, ndegenerate, nmerged;    // kernel counts (WallPatches)
  T near_overflow, near_builds, nunrecorded;
  T behind, deep, large, fresh;         // WallWarnings: counts
  T fresh_v, fresh_d, fresh_em;         // WallWarnings: maxima
  POLYDEM_FN WallTally()
  {
    for (int k = 0; k < 3; ++k) force[k] = torque[k] = T(0);
    ncontact = ntri = energy = noverflow = ndegenerate = nmerged = T(0);
    near_overflow = near_builds = nunrecorded = behind = deep = large = fresh = T(0);
    fresh_v = fresh_d = fresh_em = T(0);
  }
  // one particle at x (lab): its forces wf, patches P, warnings w
  POLYDEM_FN void add(const Vec3<T> &x, const WallForce<T> &wf, const MeshPose<T> &mp,
                      const WallPatches<T> &P, const WallWarnings<T> &w)
  {
    const Vec3<T> tm = wall_reaction_torque(x, wf, mp);
    force[0] -= wf.f.x;
    force[1] -= wf.f.y;
    force[2] -= wf.f.z;
    torque[0] += tm.x;
    torque[1] += tm.y;
    torque[2] += tm.z;
    ncontact += T(wf.ncontact);
    ntri += T(P.ntri);
    energy += wf.energy;
    noverflow += T(P.noverflow);
    ndegenerate += T(P.ndegenerate);
    nmerged += T(P.nmerged);
    nunrecorded += T(P.nunrecorded);
    behind += T(w.behind);
    deep += T(w.deep);
    large += T(w.large);
    fresh += T(w.fresh);
    fresh_v = w.fresh_v > fresh_v ? w.fresh_v : fresh_v;
    fresh_d = w.fresh_d > fresh_d ? w.fresh_d : fresh_d;
    fresh_em = w.fresh_em > fresh_em ? w.fresh_em : fresh_em;
  }
  POLYDEM_FN void operator+=(const WallTally &o) { wall_tally_merge(*this, o); }
#if defined(KOKKOS_VERSION) && KOKKOS_VERSION < 40000
  // Kokkos 3 joins through volatile references (Kokkos 4 rejects this form)
  POLYDEM_FN void operator+=(const volatile WallTally &o) volatile { wall_tally_merge(*this, o); }
#endif
};

// Per-triangle forces (fix wall/mesh pertriangle yes): each patch's force on
// the wall (-F of the patch on the particle) shared among its clipped
// triangles in proportion to their section areas A_t (by volume if the patch
// has no section area), so the triangles' forces add up to the patch force;
// for a flat patch this is a uniform pressure over the contact section.
// The shares are of the patch's totals (P), so a triangle beyond the record
// (more than WALL_MAX_CAND under one particle, counted in P.nunrecorded)
// leaves its share out rather than inflating the others.
// add(t, fx, fy, fz) receives each share (lab frame).
template <typename T, int MF, int ME, typename F>
POLYDEM_FN void wall_triangle_forces(const WallWorkspace<T, MF, ME> &ws, const WallPatches<T> &P,
                                     const WallForce<T> &wf, F &add)
{
  T asum[WALL_MAX_PATCH], vsum[WALL_MAX_PATCH];
  for (int k = 0; k < WALL_MAX_PATCH; ++k) {
    asum[k] = k < P.n ? P.p[k].area : T(0);
    vsum[k] = k < P.n ? P.p[k].volume : T(0);
  }
  for (int e = 0; e < ws.nrec; ++e) {
    const int k = ws.rpatch[e];
    const T w = asum[k] > T(0) ? ws.rarea[e] / asum[k]
                               : (vsum[k] > T(0) ? ws.rvol[e] / vsum[k] : T(0));
    if (w != T(0)) add(ws.rtri[e], -w * wf.fpatch[k].x, -w * wf.fpatch[k].y, -w * wf.fpatch[k].z);
  }
}

}    // namespace polydem

#endif
