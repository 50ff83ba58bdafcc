/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - STL reader (ASCII and binary) and the uniform bin grid of a
   triangle mesh, host only (fix wall/mesh setup). No LAMMPS includes: errors
   are thrown as StlError with the file name and, for ASCII, the line number;
   the LAMMPS style turns them into error->all.

   Vertices are transformed at load: p' = R (scale p) + offset. Orientation:
   the vertex order (t0, t1, t2), counter-clockwise seen from the front,
   defines the side particles live on (the stored facet normal is ignored);
   flip reverses it. Zero-area and duplicate triangles are dropped and
   counted; NaN/Inf coordinates and an empty mesh are errors.
------------------------------------------------------------------------- */

#ifndef POLYDEM_STL_H
#define POLYDEM_STL_H

#include <stdexcept>
#include <string>
#include <vector>

namespace polydem {

struct StlError : public std::runtime_error {
  explicit StlError(const std::string &what) : std::runtime_error(what) {}
};

struct StlTransform {
  double scale = 1.0;
  double R[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};    // rotation, applied after scale
  double offset[3] = {0, 0, 0};                          // applied last
  bool flip = false;                                     // reverse vertex order
};

struct StlMesh {
  std::vector<double> tri;    // 9 values per kept triangle (t0, t1, t2)
  bool binary = false;
  long nread = 0;              // triangles in the file
  long ndegenerate = 0;        // dropped: zero area (relative 1e-12 of the longest edge squared)
  long nduplicate = 0;         // dropped: same three vertices as an earlier triangle
  bool no_endsolid = false;    // ASCII: complete facets, then the file ends (truncated?)
  long trailing = 0;           // binary: bytes after the announced triangles (ignored)
  long nalong = 0, nopposite = 0;    // kept triangles whose stored facet normal points along
                                     // / against the vertex order's (after flip)
  int ntri() const { return (int) (tri.size() / 9); }
};

// Throws StlError naming the file (and line for ASCII).
StlMesh read_stl(const std::string &path, const StlTransform &xf);

// Coplanar merging (polydem_mesh_merge.cpp): every region of at least three
// edge-connected triangles whose vertices lie within tol of the plane of the
// region's first triangle (same side, consistent orientation, manifold
// edges) is replaced by an ear-clipping triangulation of its outline, with
// outline vertices within tol of the line of their neighbours dropped;
// holes are joined to the outer outline by bridge edges. Pinched outlines,
// outlines of more than 2048 vertices (after the collinear ones are dropped)
// or 256 loops, and any triangulation whose area differs from the region's
// by more than 1e-9 of it plus tol x the outline's length, are kept as read. The wall
// contact of a flat patch does not depend on its triangulation, so forces
// are unchanged (to round-off, and to tol where vertices were not exactly
// coplanar); the cost per particle then follows the geometry of the wall.
struct MergeStats {
  int before = 0, after = 0;    // triangles
  int regions = 0;              // regions of >= 3 triangles
  int merged_regions = 0;       // re-triangulated
  int bridged_holes = 0;        // holes joined to their region's outline
  int kept_holes = 0;           // kept: pinched, > 2048 outline vertices or > 256 loops
  int kept_failed = 0;          // kept: ear clipping or area check failed
};
MergeStats merge_coplanar(std::vector<double> &tri, double tol);

// Smooth regions of a mesh for the wall's patches: region growing from the
// lowest-numbered unassigned triangle (the seed) through triangles that
// share a vertex (vertices are the same point when their coordinates,
// rounded to multiples of tol, agree) and whose normal is within the patch
// angle of the seed's (cos >= cosmax), either way round: a triangle whose
// normal is within the angle of the seed's reversed normal joins reversed
// (a mesh with mixed vertex orders). Per triangle: 2 x seed + (1 if
// reversed). Connected coplanar triangles always share a region, so the
// patches of a flat region do not depend on its triangulation; regions are
// fixed at load, so a facet never changes patch while it carries overlap.
std::vector<int> mesh_regions(const std::vector<double> &tri, double cosmax, double tol);

// Uniform grid of cubic bins of edge h over the mesh's bounding box; each
// triangle is listed in every bin its bounding box overlaps (CSR arrays).
struct MeshGrid {
  double lo[3] = {0, 0, 0};
  double h = 1.0;
  int n[3] = {1, 1, 1};
  std::vector<int> start;       // nbins + 1
  std::vector<int> items;       // mesh_item(t, first-bin bits), polydem_mesh_grid.h
  std::vector<double> plane;    // 4 per triangle: unit normal, offset
  std::vector<double> box;      // 6 per triangle: bounding box
  std::vector<double> sphere;   // 4 per triangle: centroid, largest vertex distance from it
};

// h: requested bin edge; enlarged (x 1.25 at a time) until there are at most
// max_bins bins and 2^28 list entries.
MeshGrid build_mesh_grid(const std::vector<double> &tri, double h, long max_bins = 1L << 22);

}    // namespace polydem

#endif
