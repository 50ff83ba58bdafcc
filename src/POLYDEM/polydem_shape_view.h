/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - plain-data view of one convex shape template, as the kernels
   see it (host or device). The host class PolyShapeTemplate owns the
   storage; the Kokkos styles copy all templates into flat device arrays
   and hand out views into them. No LAMMPS includes (DESIGN.md 4.1).

   Template frame: centroid at the origin, axes = principal axes of
   inertia, unit scale. A particle is the template scaled by s, rotated by
   its quaternion q and translated to x:  p_lab = x + s R(q) p_body.
------------------------------------------------------------------------- */

#ifndef POLYDEM_SHAPE_VIEW_H
#define POLYDEM_SHAPE_VIEW_H

#include "polydem_math.h"

namespace polydem {

// Compile-time caps for templates (fixed workspaces are sized from these).
constexpr int MAX_TEMPLATE_VERTS = 128;
constexpr int MAX_TEMPLATE_FACES = 128;
// ints per triangle of ShapeView::dual (polydem_dual_seed.h)
constexpr int DUAL_SEED_STRIDE_K = 7;

template <typename T> struct ShapePart;

template <typename T> struct ShapeView {
  int nverts;             // number of hull vertices
  int nfaces;             // number of (merged, planar, convex) faces
  int nedges;             // number of hull edges
  const T *verts;         // 3*nverts, body frame, unit scale
  const T *planes;        // 4*nfaces: outward unit normal n, offset d; inside: n.p <= d
  const int *face_start;  // nfaces+1 offsets into face_verts
  const int *face_verts;  // vertex loops, counter-clockwise seen from outside
  const int *edges;       // 2*nedges vertex indices
  T radius;               // bounding radius about the origin (unit scale)
  T volume;               // volume at unit scale
  T inertia[3];           // principal moments per unit density, unit scale (I ~ s^5)
  // dual triangulation (polydem_dual_seed.h), or null: the overlap kernel
  // then starts from a bounding tetrahedron instead of from this shape
  const int *dual = nullptr;
  // vertex adjacency (build_vertex_adjacency), or null: the support search
  // then scans every vertex instead of climbing along the edges.
  // vadj[v]..vadj[v+1]-1 index the neighbours of v within vadj itself.
  const int *vadj = nullptr;
  // an ellipsoid template (no vertices or faces): its semi-axes along the
  // body axes at unit scale; zero for a polyhedron (view_is_ellipsoid)
  T axes[3] = {T(0), T(0), T(0)};
  // a composite template (a rigid union of convex parts, each a polyhedron
  // or an ellipsoid): its parts, or nparts = 0. A composite has no
  // vertices, faces or axes of its own (view_is_composite).
  int nparts = 0;
  const ShapePart<T> *parts = nullptr;
};

// Maximum parts of a composite template (history keys, workspaces).
constexpr int MAX_COMPOSITE_PARTS = 16;

// One part of a composite: its convex template and its placement in the
// composite's body frame at unit scale, p_body = x + R p_part.
template <typename T> struct ShapePart {
  const ShapeView<T> *view;
  T x[3];
  T R[3][3];
  T q[4];    // R as a unit quaternion (w, x, y, z)
  // the part's bounding box in its own frame (unit scale): centre mid,
  // half-extents half (an ellipsoid's: its semi-axes); by default a box
  // that holds everything (the composite template sets the real one)
  T mid[3] = {T(0), T(0), T(0)};
  T half[3] = {T(3e38), T(3e38), T(3e38)};
};

template <typename T> POLYDEM_FN bool view_is_composite(const ShapeView<T> &v)
{
  return v.nparts > 0;
}

template <typename T> POLYDEM_FN bool view_is_ellipsoid(const ShapeView<T> &v)
{
  return v.axes[0] > T(0);
}

// ints in a view's dual triangulation array (0 if it has none)
template <typename T> POLYDEM_FN int dual_seed_ints(const ShapeView<T> &v)
{
  return v.dual ? 1 + DUAL_SEED_STRIDE_K * v.dual[0] : 0;
}

// ints in a view's vertex adjacency array (0 if it has none)
template <typename T> POLYDEM_FN int vertex_adjacency_ints(const ShapeView<T> &v)
{
  return v.vadj ? v.vadj[v.nverts] : 0;
}

// First dual triangle of vertex v's fan: the dual triangulation lists the
// fans in vertex order, v's with degree - 2 triangles, the degree read from
// the vertex adjacency (both checked to agree at load: dual_fans_match)
template <typename T> POLYDEM_FN int dual_fan_first(const ShapeView<T> &s, int v)
{
  return s.vadj[v] - (s.nverts + 1) - 2 * v;
}

// Pose of one particle: position, orientation, scale.
template <typename T> struct Pose {
  Vec3<T> x;
  Quat<T> q;    // unit quaternion, body -> lab
  T s;          // scale factor
};

}    // namespace polydem

#endif
