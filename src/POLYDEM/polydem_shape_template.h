/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - host-side convex shape template (seed polyhedral 2.1).

   Reads a shape file (doc/Howto_polyhedron_shapes.rst) or a point list,
   builds the convex hull with CGAL, computes volume, centroid and inertia
   exactly (rational arithmetic), moves the centroid to the origin, rotates
   into the principal frame, merges coplanar hull triangles into convex
   polygonal faces and hands the result to the kernels as ShapeView<T>.

   Host only. No LAMMPS includes and no CGAL here: CGAL lives in
   polydem_shape_hull.cpp and polydem_shape_mass.cpp so that LAMMPS
   translation units can include this header cheaply.
------------------------------------------------------------------------- */

#ifndef POLYDEM_SHAPE_TEMPLATE_H
#define POLYDEM_SHAPE_TEMPLATE_H

#include "polydem_shape_view.h"

#include <array>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace polydem {

// Every problem with a shape (unreadable file, bad numbers, degenerate or
// non-convex geometry, caps exceeded). what() names the source and, for
// files, the line: "cube.shape:7: expected 3 numbers, got 2".
class ShapeError : public std::runtime_error {
 public:
  explicit ShapeError(const std::string &msg) : std::runtime_error(msg) {}
};

struct ShapeOptions {
  // Accept points strictly inside the hull (non-convex input) and use the
  // hull, with a warning. Default: such input is an error.
  bool hull = false;
  // Extra factor applied to the coordinates after the file's own `scale`.
  double scale = 1.0;
};

class PolyShapeTemplate {
 public:
  using Point = std::array<double, 3>;

  // Load a shape file. Throws ShapeError.
  static PolyShapeTemplate from_file(const std::string &path,
                                     const ShapeOptions &opt = ShapeOptions());
  // Build from points (+ optional faces, 0-based indices, used only for
  // validation). `name` is used in messages and as name(). Throws ShapeError.
  static PolyShapeTemplate from_points(const std::vector<Point> &pts,
                                       const std::vector<std::vector<int>> &faces = {},
                                       const ShapeOptions &opt = ShapeOptions(),
                                       const std::string &name = "points");

  // An ellipsoid template (ellipsoid seed): semi-axes a, b, c along the
  // body x, y, z axes, centroid at the origin. Mass properties are analytic
  // (V = 4/3 pi abc, I_x = V (b^2 + c^2) / 5 per unit density, ...); it has
  // no vertices or faces. Throws ShapeError for non-positive or non-finite axes.
  static PolyShapeTemplate ellipsoid(double a, double b, double c, const std::string &name);
  bool is_ellipsoid() const { return ellipsoid_; }
  // an ellipsoid template with three equal semi-axes
  bool is_sphere() const { return ellipsoid_ && axes_[0] == axes_[1] && axes_[0] == axes_[2]; }
  // semi-axes at unit scale (ellipsoids only; zero for polyhedra)
  const std::array<double, 3> &semi_axes() const { return axes_; }

  // A composite template: the rigid union of convex parts (polyhedra or
  // ellipsoids), each placed by a position and an orientation in the
  // composite's input frame. Parts may overlap where both are polyhedra
  // (the union's mass properties are computed exactly, with CGAL's Nef
  // polyhedra); a part that is an ellipsoid must be disjoint from the others.
  // The contact parts (nparts, part_shape, part) have disjoint interiors, so
  // that the overlap of two grains is the sum over pairs of parts: the parts
  // as given where they are disjoint, else the ellipsoids and the convex
  // decomposition of the polyhedral parts' union (CGAL convex_decomposition_3).
  // A composite of one part has that part's body frame. Throws ShapeError.
  struct InputPart {
    std::shared_ptr<const PolyShapeTemplate> shape;    // convex (not a composite)
    std::string id;                                    // name of the part in messages
    Point x;                                           // position of its centroid
    Quat<double> q;                                    // its orientation (unit)
  };
  static PolyShapeTemplate composite(const std::vector<InputPart> &parts, const std::string &name);
  // The convex pieces of a closed, consistently oriented triangulated surface
  // (9 coordinates per triangle; either orientation) by CGAL's convex
  // decomposition of its Nef polyhedron (convex_decomposition_3): the corner
  // points of each piece. Throws ShapeError (not closed, not a 2-manifold).
  static std::vector<std::vector<Point>> convex_pieces(const std::vector<double> &tri,
                                                       const std::string &name);
  bool is_composite() const { return !input_parts_.empty(); }
  const std::vector<InputPart> &input_parts() const { return input_parts_; }
  // the contact parts: count, contact part k's template, and its position
  // and rotation in the body frame (unit scale)
  int nparts() const { return (int) part_shapes_.size(); }
  const PolyShapeTemplate &part_shape(int k) const { return *part_shapes_[k]; }
  const ShapePart<double> &part(int k) const { return (*parts_)[k]; }
  // the contact parts are the convex decomposition of the parts' union
  bool decomposed() const { return decomposed_; }
  // volume of the union over the sum of the parts' volumes (1: disjoint)
  double union_fraction() const { return union_fraction_; }

  // Kernel view into this object's storage: valid while the object lives
  // (a move keeps the storage, a copy has its own).
  ShapeView<double> view() const;
  ShapeView<float> view_float() const;

  const std::string &name() const { return name_; }    // file name or given name
  const std::string &file() const { return file_; }    // path as given ("" if from points)
  const std::vector<std::string> &warnings() const { return warnings_; }

  int nverts() const { return (int) verts_.size() / 3; }
  int nfaces() const { return (int) face_start_.size() - 1; }
  int nedges() const { return (int) edges_.size() / 2; }
  int ninput_verts() const { return (int) input_.size(); }    // points read
  // The points exactly as they entered the hull computation (all scales
  // applied). from_points(input_points(), {}, {hull}) rebuilds this
  // template bit for bit (used for restart records).
  const std::vector<Point> &input_points() const { return input_; }
  int nhull_triangles() const { return ntri_; }    // hull triangles before merging

  Point vertex(int i) const { return {verts_[3 * i], verts_[3 * i + 1], verts_[3 * i + 2]}; }
  // Face i: vertex indices (CCW seen from outside) and plane n.p = d (|n| = 1).
  std::vector<int> face(int i) const;
  std::array<double, 4> plane(int i) const
  {
    return {planes_[4 * i], planes_[4 * i + 1], planes_[4 * i + 2], planes_[4 * i + 3]};
  }
  std::array<int, 2> edge(int i) const { return {edges_[2 * i], edges_[2 * i + 1]}; }

  double volume() const { return volume_; }    // unit scale, length^3
  double max_face_area() const;                // unit scale, length^2 (0: ellipsoid)
  double radius() const { return radius_; }    // max |vertex| about the centroid
  // inscribed radius about the centroid, unit scale: the nearest face plane
  // (polyhedron), the smallest semi-axis (ellipsoid)
  double inradius() const;
  // Principal moments per unit density (length^5), ascending (ellipsoids:
  // in the order of the body axes).
  const std::array<double, 3> &moments() const { return moments_; }

  // Where the template came from: p_input = centroid + R p_body, with R's
  // columns the principal axes in input coordinates (proper rotation).
  const Point &input_centroid() const { return centroid_; }
  const std::array<std::array<double, 3>, 3> &rotation() const { return rot_; }
  // Same rotation as a unit quaternion (w,x,y,z). A particle with this
  // orientation at position x appears exactly as written in the file, with
  // the file's centroid at x.
  Quat<double> input_orientation() const;

 private:
  PolyShapeTemplate() = default;
  // vlines/flines: file line of each vertex/face (empty: from points);
  // vkey: line of the `vertices` keyword.
  void build(const std::vector<Point> &pts, const std::vector<std::vector<int>> &faces,
             const std::vector<int> &vlines, const std::vector<int> &flines, int vkey,
             const ShapeOptions &opt);
  // build()'s phases that fill members (the others are file-local in polydem_shape_hull.cpp)
  std::vector<Point> principal_frame(const std::vector<Point> &hv,
                                     const std::vector<std::array<int, 3>> &tri,
                                     const std::string &head);
  void set_mass_properties(const std::vector<Point> &bv, const std::vector<std::array<int, 3>> &tri,
                           const std::string &head);
  void set_faces(const std::vector<Point> &bv, const std::vector<std::vector<int>> &loops,
                 const std::string &src);
  void make_float_copy();
  void check_mass_properties(const std::string &what) const;

  std::string name_, file_;
  std::vector<std::string> warnings_;
  std::vector<Point> input_;
  int ntri_ = 0;

  std::vector<double> verts_, planes_;
  std::vector<int> face_start_, face_verts_, edges_;
  std::vector<int> dual_;    // dual triangulation (polydem_dual_seed.h)
  std::vector<int> vadj_;    // vertex adjacency (polydem_dual_seed.h)
  std::vector<float> verts_f_, planes_f_;

  // composites: the parts as given, their views (shared by copies, so that
  // the pointers of parts_ stay valid) and their body-frame placements
  std::vector<InputPart> input_parts_;
  std::vector<std::shared_ptr<const PolyShapeTemplate>> part_shapes_;    // contact parts
  bool decomposed_ = false;
  std::shared_ptr<const std::vector<ShapeView<double>>> part_views_;
  std::shared_ptr<const std::vector<ShapePart<double>>> parts_;
  double union_fraction_ = 1.0;

  bool ellipsoid_ = false;
  std::array<double, 3> axes_ = {0.0, 0.0, 0.0};
  double volume_ = 0.0, radius_ = 0.0;
  std::array<double, 3> moments_ = {0.0, 0.0, 0.0};
  Point centroid_ = {0.0, 0.0, 0.0};
  std::array<std::array<double, 3>, 3> rot_ = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
};

}    // namespace polydem

#endif
