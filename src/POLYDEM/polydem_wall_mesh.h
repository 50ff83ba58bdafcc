/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - a wall's mesh, apart from the wall's physics: the triangles of
   an STL file as loaded (transform, coplanar merging), their smooth
   regions (the patches' keys), the bin grid, the rigid motion of the mesh,
   and the geometric queries the insertion and the wall ask of it. No LAMMPS:
   fix wall/mesh owns one and keeps keywords, material, forces and history.
------------------------------------------------------------------------- */

#ifndef POLYDEM_WALL_MESH_H
#define POLYDEM_WALL_MESH_H

#include "polydem_insert.h"
#include "polydem_mesh_grid.h"
#include "polydem_stl.h"
#include "polydem_wall_contact.h"

#include <memory>
#include <string>
#include <vector>

namespace polydem {

// The order in which a wall keeps its triangles: by the cell (edge `cell`)
// of their bounding box's lowest corner, cells in the bin grid's order (x
// fastest, then y, then z), the order as given within a cell. A bin's
// triangles then lie together in memory, whatever order the file has: a
// query reads a few runs of adjacent triangles, not one cache line per
// triangle (the 150k-triangle bench bowl shuffled at random cost 1.4 times
// the bowl in row order). Returns order[new] = old.
std::vector<int> spatial_order(const std::vector<double> &tri, double cell);

// The mesh frame is the lab frame at the time the wall was defined; at time
// t since then the mesh has moved by pose(t).
struct MeshMotion {
  enum { NONE, TRANSLATE, ROTATE, WIGGLE, SERVO };
  int style = NONE;
  double vel[3] = {0.0, 0.0, 0.0};       // translate
  double origin[3] = {0.0, 0.0, 0.0};    // rotate: a point of the axis
  double axis[3] = {0.0, 0.0, 0.0};      // rotate: unit axis
  double omega = 0.0;                    // rotate: rad per time unit
  double amp[3] = {0.0, 0.0, 0.0};       // wiggle: d = amp sin(2 pi t / period)
  double period = 1.0;
  // servo: the mesh moves along the unit direction dir (which compresses
  // the particles) at v = clamp(gain (target - F_c), -vmax, vmax), F_c the
  // particles' force on the mesh against dir; state: displacement s and
  // velocity v along dir (servo_step)
  double dir[3] = {0.0, 0.0, 0.0};
  double target = 0.0, vmax = 0.0, gain = 0.0;
  double s = 0.0, v = 0.0;
  // servo: the new velocity for the force f on the mesh (lab frame)
  void servo_step(const double f[3]);

  MeshPose<double> pose(double t) const;
  // the largest speed of a point of the triangles tri (9 per triangle)
  double max_speed(const std::vector<double> &tri) const;
};

class WallMesh {
 public:
  StlMesh mesh;                // the triangles in the mesh frame, after merging
  MergeStats merged;           // what coplanar merging did
  std::vector<int> regions;    // per triangle: smooth region (mesh_regions)
  // the triangles are kept in spatial order (spatial_order); row[t] is
  // triangle t's place in the order as read and merged (pertriangle's
  // rows), tri_of_row the inverse
  std::vector<int> row, tri_of_row;
  int nregions = 0;
  double diag = 0.0;           // bounding-box diagonal
  double cosmax = 1.0;         // cos(patch angle): neighbours in one smooth region
  MeshGrid grid;
  MeshMotion motion;

  // read the STL file (StlError if it cannot), merge coplanar regions
  // (tolerance merge_tol x diag; < 0: off) and find the smooth regions of
  // the patch angle (degrees); the regions are found in the file's order,
  // then the triangles are put in spatial order
  void load(const std::string &file, const StlTransform &xf, double merge_tol,
            double patch_angle_deg);
  int ntri() const { return mesh.ntri(); }
  double median_edge() const;
  // bin edge for particles of largest bounding radius rmax: max(rmax / 2,
  // twice the median triangle edge), so that a query scans little beyond
  // the sphere's box and a bin holds a few triangles
  double automatic_bin(double rmax) const;
  // the grid of bin edge h, unless it has it already; true if built
  bool set_grid(double h);
  MeshGridView<double> grid_view() const;
  // is the point c (mesh frame) behind the mesh, as a one-sided wall sees it?
  bool behind(const Vec3<double> &c) const;
  // fix insert/polyhedron's query: body b (lab frame, orientation q) at the
  // mesh's pose mp is certified farther than gap from every triangle and
  // has no contact with it (a polyhedron no contact volume, an ellipsoid no
  // closest point), nor is behind a one-sided (twosided = 0) mesh
  bool insertion_clear(const MeshPose<double> &mp, const InsertBody<double> &b,
                       const Quat<double> &q, double gap, int twosided) const;

 private:
  mutable std::unique_ptr<WallWorkspace<double>> ws;    // insertion_clear's
};

}    // namespace polydem

#endif
