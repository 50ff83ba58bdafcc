/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - plain-data view of a triangle mesh and its uniform bin grid
   (built on the host by build_mesh_grid, polydem_stl.h), host and device.
   The grid lives in the mesh's own frame: a rigidly moving mesh keeps it,
   and particles are transformed into that frame instead.

   Candidate triangles of a sphere (c, r): the bins overlapping the sphere's
   box. A triangle listed in several of these bins is visited once, in the
   first bin of (its bin box) ∩ (the query box), so no visited list is
   needed. Along each direction that bin is the triangle's own first bin or
   the query's first, so each entry of a bin's list carries, beside the
   triangle, three bits: is this bin the triangle's first along x, y, z
   (mesh_item). A query decides from the entry alone, without loading the
   triangle's data, which of the bin's triangles it visits there. The work
   per query depends on the triangles near the sphere, not on the mesh size.
------------------------------------------------------------------------- */

#ifndef POLYDEM_MESH_GRID_H
#define POLYDEM_MESH_GRID_H

#include "polydem_math.h"

namespace polydem {

template <typename T> struct MeshGridView {
  const T *tri;         // 9 per triangle, mesh frame
  int ntri;
  T lo[3];              // grid origin
  T h;                  // bin edge [length]
  int n[3];             // bins per direction
  const int *start;     // n0 n1 n2 + 1 offsets into items
  const int *items;     // mesh_item(t, first): triangle t and its first-bin bits
  const T *plane;       // 4 per triangle: unit normal, offset n . t0
  const T *box;         // 6 per triangle: min xyz, max xyz
  const int *region = nullptr;    // per triangle: smooth region (mesh_regions, polydem_stl.h), or none
  const T *sphere = nullptr;      // 4 per triangle: a bounding sphere (centre, radius), or none
};

// at most this many triangles (an entry of a bin's list holds 8 t + 7)
constexpr int MESH_MAX_TRIANGLES = (1 << 28) - 1;

// entry of a bin's list: triangle t, and in bit d whether the bin is t's
// first along direction d
POLYDEM_FN int mesh_item(int t, int first) { return 8 * t + first; }
POLYDEM_FN int mesh_item_tri(int e) { return e >> 3; }

// bin index of coordinate x along direction d, clamped to [0, n-1]; the
// host build and the device query use this same expression
template <typename T> POLYDEM_FN int mesh_bin(T x, T lo, T h, int n)
{
  const T u = (x - lo) / h;
  if (!(u > T(0))) return 0;    // also NaN
  if (u >= T(n)) return n - 1;
  const int b = (int) u;
  return b < n - 1 ? b : n - 1;
}

template <typename T> POLYDEM_FN int mesh_bin_id(const int *n, int i, int j, int k)
{
  return (k * n[1] + j) * n[0] + i;
}

// bounding box of triangle t in bins
template <typename T>
POLYDEM_FN void mesh_tri_bins(const MeshGridView<T> &g, int t, int *blo, int *bhi)
{
  const T *p = g.tri + 9 * t;
  for (int d = 0; d < 3; ++d) {
    T a = p[d], b = p[d];
    for (int v = 1; v < 3; ++v) {
      a = p[3 * v + d] < a ? p[3 * v + d] : a;
      b = p[3 * v + d] > b ? p[3 * v + d] : b;
    }
    blo[d] = mesh_bin(a, g.lo[d], g.h, g.n[d]);
    bhi[d] = mesh_bin(b, g.lo[d], g.h, g.n[d]);
  }
}

// Squared distance from p to the triangle (a, b, c): closest point by
// Voronoi regions of the vertices, edges and face (Ericson, Real-Time
// Collision Detection, 5.1.5; written here from the geometry).
template <typename T>
POLYDEM_FN T point_triangle_dist2(const Vec3<T> &p, const Vec3<T> &a, const Vec3<T> &b,
                                  const Vec3<T> &c)
{
  const Vec3<T> ab = b - a, ac = c - a, ap = p - a;
  const T d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= T(0) && d2 <= T(0)) return norm2(ap);
  const Vec3<T> bp = p - b;
  const T d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= T(0) && d4 <= d3) return norm2(bp);
  const T vc = d1 * d4 - d3 * d2;
  if (vc <= T(0) && d1 >= T(0) && d3 <= T(0)) return norm2(ap - (d1 / (d1 - d3)) * ab);
  const Vec3<T> cp = p - c;
  const T d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= T(0) && d5 <= d6) return norm2(cp);
  const T vb = d5 * d2 - d1 * d6;
  if (vb <= T(0) && d2 >= T(0) && d6 <= T(0)) return norm2(ap - (d2 / (d2 - d6)) * ac);
  const T va = d3 * d6 - d5 * d4;
  if (va <= T(0) && (d4 - d3) >= T(0) && (d5 - d6) >= T(0))
    return norm2(bp - ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b));
  const T den = T(1) / (va + vb + vc);
  return norm2(ap - (vb * den) * ab - (vc * den) * ac);
}

// Does the sphere (c, r) reach triangle t? The triangle's bounding sphere,
// plane and box first (cheap), then the exact distance to the triangle, so
// that on a fine or curved mesh only the triangles under the sphere's cap
// reach the clipping kernel. The bounding-sphere reject has a margin of
// 1e-9 (r + R) over the exact test's round-off, so it only drops triangles
// the exact test drops: the answer does not depend on g.sphere being set.
// d2: where not null, gets the squared distance from c to the triangle when
// the exact test ran (the cheap rejects leave it as it was).
template <typename T>
POLYDEM_FN bool mesh_tri_near(const MeshGridView<T> &g, int t, const Vec3<T> &c, T r,
                              T *d2 = nullptr)
{
  if (g.sphere) {
    const T *s = g.sphere + 4 * t;
    const T dx = c.x - s[0], dy = c.y - s[1], dz = c.z - s[2];
    const T rr = (r + s[3]) * T(1 + 1e-9);
    if (!(dx * dx + dy * dy + dz * dz < rr * rr)) return false;
  }
  const T *pl = g.plane + 4 * t, *b = g.box + 6 * t;
  const T d = pl[0] * c.x + pl[1] * c.y + pl[2] * c.z - pl[3];
  if (!(d < r) || !(d > -r)) return false;
  for (int k = 0; k < 3; ++k)
    if (c[k] + r < b[k] || c[k] - r > b[3 + k]) return false;
  const T *q = g.tri + 9 * t;
  const T dd = point_triangle_dist2(c, make_vec3(q[0], q[1], q[2]), make_vec3(q[3], q[4], q[5]),
                                    make_vec3(q[6], q[7], q[8]));
  if (d2) *d2 = dd;
  return dd < r * r;
}

// Calls f(t, d2) once for every triangle t near the sphere (c, r), d2 its
// squared distance from c (that of the near test, point_triangle_dist2).
// Loops are bounded by the grid size and the bin lists.
template <typename T, typename F>
POLYDEM_FN void mesh_for_each_near_dist2(const MeshGridView<T> &g, const Vec3<T> &c, T r, F &f)
{
  int qlo[3], qhi[3];
  for (int d = 0; d < 3; ++d) {
    if (c[d] + r < g.lo[d] || c[d] - r > g.lo[d] + g.h * T(g.n[d])) return;
    qlo[d] = mesh_bin(c[d] - r, g.lo[d], g.h, g.n[d]);
    qhi[d] = mesh_bin(c[d] + r, g.lo[d], g.h, g.n[d]);
  }
  for (int k = qlo[2]; k <= qhi[2]; ++k)
    for (int j = qlo[1]; j <= qhi[1]; ++j)
      for (int i = qlo[0]; i <= qhi[0]; ++i) {
        const int b = mesh_bin_id<T>(g.n, i, j, k);
        // this bin is the first of (t's bin box) ∩ (the query box) if, along
        // each direction, it is t's first bin or the query's first
        const int qfirst = (i == qlo[0]) | (j == qlo[1]) << 1 | (k == qlo[2]) << 2;
        for (int s = g.start[b]; s < g.start[b + 1]; ++s) {
          const int e = g.items[s];
          if (((e | qfirst) & 7) != 7) continue;
          const int t = mesh_item_tri(e);
          T d2 = T(0);
          if (!mesh_tri_near(g, t, c, r, &d2)) continue;
          f(t, d2);
        }
      }
}

// Calls f(t) once for every triangle t near the sphere (c, r).
template <typename T, typename F>
POLYDEM_FN void mesh_for_each_near(const MeshGridView<T> &g, const Vec3<T> &c, T r, F &f)
{
  auto visit = [&](int t, T) { f(t); };
  mesh_for_each_near_dist2(g, c, r, visit);
}

}    // namespace polydem

#endif
