/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - what one particle's contact with a triangle mesh keeps (fix
   wall/mesh): its patches (the sums per group of near-coplanar facets, or
   an ellipsoid's closest points), the clipping workspace, the near list of
   candidate triangles, and the patch a facet joins. Host and device, no
   LAMMPS includes. Filled by polydem_wall_patches.h (polyhedra) and
   polydem_wall_ellipsoid.h (ellipsoids).
------------------------------------------------------------------------- */

#ifndef POLYDEM_WALL_PATCH_SET_H
#define POLYDEM_WALL_PATCH_SET_H

#include "polydem_clip.h"
#include "polydem_contact_law.h"
#include "polydem_mesh_grid.h"
#include "polydem_wall_sides.h"

namespace polydem {

// per patch: normal (3), distance from the centroid to its plane (1), the
// contact's history (s, k_old, phi, rolling M_k: polydem_contact_law.h)
constexpr int WALL_HIST = 4 + CONTACT_HIST_ROLL;
constexpr int WALL_HIST_SIZE = WALL_MAX_PATCH * WALL_HIST;
constexpr int WALL_MAX_CAND = 1024;    // candidate triangles kept per particle (more: clipped at once)

// One patch. Ellipsoids (polydem_wall_ellipsoid.h) fill the same fields
// with the patch's closest point: volume the overlap volume of the support
// plane (diagnostic: overlap/warn), area 0, S and M the gradient of the
// overlap delta (mesh frame), ac the contact point, vc the deepest point,
// depth delta, tri the triangle of the closest point.
template <typename T> struct WallPatch {
  Vec3<T> nseed;    // first facet's normal n_w (mesh frame)
  Vec3<T> p0;       // a vertex of the first facet: with nseed, the contact's plane (kept side)
  T volume, area;
  Vec3<T> S, M;     // sums (mesh frame)
  Vec3<T> ac;       // area-weighted sum of section centroids
  Vec3<T> vc;       // volume-weighted sum of volume centroids
  T depth;          // deepest particle vertex behind the first clipped facet's plane
  int behind;       // the particle's centroid is behind a clipped triangle (in its prism)
  int tri;          // ellipsoids: the triangle of the patch's closest point
  int key;          // wall_region_key of its triangles, -1 without regions
  T gap;            // spheres: the gap to the patch (>= 0) when it only holds a
                    // liquid bridge (depth 0); -1 for a contact
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
  int behind[MAX_TEMPLATE_VERTS], nbehind;    // the vertices behind it (dist < 0), in order
  T pc[4], pbox[6];              // that plane (as stored), the box of the part behind it
  T po[4];                       // that plane as the particle meets it (pside x pc)
  int pvalid, pany, pside;       // cache valid; a vertex behind it; side (+1 front, -1 back)
  int pclaimed;                  // a kept contact chose pside (else the centroid did)
  int vlow;                      // the particle's vertex lowest along the last plane's normal
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
  int *tri;      // cap entries: t, or -1 - t where t stays within r (WallNearBuild)
  float *gap;    // cap e_t [length], rounded down
  int cap;
  T skin;        // [length]
  int built;     // out: 1 if the list was (re)built by this call
};
constexpr int NEAR_REACH = 8;    // query reach r + NEAR_REACH x skin at a build

// a build's new entry (code, e_t) among the n kept so far: appended while
// there is room; a full list keeps the cap smallest e_t, and valid (the
// smallest e_t left out) takes the one dropped
template <typename T>
POLYDEM_FN void near_list_keep(WallNear<T> &near, int &n, int code, float e, T &valid)
{
  if (n < near.cap) {
    near.tri[n] = code;
    near.gap[n++] = e;
    return;
  }
  int kmax = 0;    // full: the entry with the largest e_t
  for (int k = 1; k < n; ++k) kmax = near.gap[k] > near.gap[kmax] ? k : kmax;
  if (near.gap[kmax] > e) {
    valid = T(near.gap[kmax]) < valid ? T(near.gap[kmax]) : valid;
    near.tri[kmax] = code;
    near.gap[kmax] = e;
  } else {
    valid = T(e) < valid ? T(e) : valid;
  }
}
constexpr int NEAR_REBUILD = -1;
constexpr int NEAR_OVERFLOW = -2;

// The patch whose nseed is closest to n (largest cosine,
// returned in best), -1 if there is none yet; the caller opens a new patch
// if best < cos(patch angle). Polyhedra and ellipsoids (polydem_wall_ellipsoid.h).
template <typename T>
POLYDEM_FN int wall_closest_patch(const WallPatches<T> &P, const Vec3<T> &n, T &best)
{
  int k = -1;
  best = T(-2);
  for (int i = 0; i < P.n; ++i) {
    const T c = dot(P.p[i].nseed, n);
    if (c > best) {
      best = c;
      k = i;
    }
  }
  return k;
}

// The patch key of triangle t met from side (+1 front, -1 back): its smooth
// region (2 x seed triangle) and whether the region's seed normal is met
// reversed; -1 if the mesh has no regions. Patches group the triangles of
// one key, so a triangle never changes patch: the wall energy, the sum of
// W(V) over patches, is then a function of the pose alone (no jump when a
// particle's first facet changes, as grouping by the first facet's normal
// gave on curved meshes).
template <typename T> POLYDEM_FN int wall_region_key(const MeshGridView<T> &g, int t, int side)
{
  if (!g.region || t < 0) return -1;
  const int r = g.region[t];
  return (r & ~1) | ((r & 1) ^ (side < 0 ? 1 : 0));
}

// The patch a clipped triangle of key (normal n as met) joins: the patch of
// that key, else (no regions) the closest normal within the patch angle,
// else a new patch (opened: the caller fills its sums), else (all
// WALL_MAX_PATCH taken) the closest normal, counted in nmerged. A new
// patch's nseed is n, its first facet's normal: with a vertex of that facet
// (p0) it names the plane of the contact for the kept side (wall_side), so
// it must be a facet's own plane, not a region's (whose seed facet may lie
// far away and 20 degrees off).
template <typename T>
POLYDEM_FN int wall_patch_slot(WallPatches<T> &P, const MeshGridView<T> &g, int key,
                               const Vec3<T> &n, T cosmax, bool &opened)
{
  opened = false;
  T best;
  if (key >= 0) {
    for (int i = 0; i < P.n; ++i)
      if (P.p[i].key == key) return i;
  } else {
    const int k = wall_closest_patch(P, n, best);
    if (k >= 0 && best >= cosmax) return k;
  }
  if (P.n < WALL_MAX_PATCH) {
    const int k = P.n++;
    WallPatch<T> &p = P.p[k];
    p.key = key;
    p.nseed = n;
    opened = true;
    return k;
  }
  P.nmerged++;    // more regions or orientations than patches: join the closest
  return wall_closest_patch(P, n, best);
}

}    // namespace polydem

#endif
