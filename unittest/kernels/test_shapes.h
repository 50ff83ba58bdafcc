// POLYDEM kernel tests: shape templates built from point sets with CGAL
// (Epick convex hull, coplanar triangles merged into faces), random poses.
#ifndef POLYDEM_TEST_SHAPES_H
#define POLYDEM_TEST_SHAPES_H

#include "polydem_shape_view.h"

#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace polydem_test {

// Owning storage behind a ShapeView<T>; body frame centred on the centroid.
struct ShapeData {
  std::vector<double> verts, planes;    // 3*nv, 4*nf
  std::vector<int> face_start, face_verts, edges;
  std::vector<int> dual;    // polydem_dual_seed.h
  std::vector<int> vadj;    // vertex adjacency (polydem_dual_seed.h)
  double radius = 0, volume = 0;
  int nverts() const { return (int) verts.size() / 3; }
  int nfaces() const { return (int) planes.size() / 4; }
};

template <typename T> struct TypedShape {
  std::vector<T> verts, planes;
  polydem::ShapeView<T> view;
};

// Hull of the points (double precision), faces merged, centroid at origin.
ShapeData make_shape(const std::vector<std::array<double, 3>> &pts);

template <typename T> TypedShape<T> *typed(const ShapeData &s)
{
  auto *t = new TypedShape<T>;
  t->verts.assign(s.verts.begin(), s.verts.end());
  t->planes.assign(s.planes.begin(), s.planes.end());
  auto &v = t->view;
  v.nverts = s.nverts();
  v.nfaces = s.nfaces();
  v.nedges = (int) s.edges.size() / 2;
  v.verts = t->verts.data();
  v.planes = t->planes.data();
  v.face_start = s.face_start.data();
  v.face_verts = s.face_verts.data();
  v.edges = s.edges.data();
  v.radius = (T) s.radius;
  v.volume = (T) s.volume;
  v.inertia[0] = v.inertia[1] = v.inertia[2] = T(0);
  v.dual = s.dual.empty() ? nullptr : s.dual.data();
  v.vadj = s.vadj.empty() ? nullptr : s.vadj.data();
  return t;
}

// vertices of a shipped template (potentials/<file>), in its principal
// frame, scaled to bounding radius 1
std::vector<std::array<double, 3>> shipped_points(const std::string &file);
extern const char *const SHIPPED_SHAPES[6];

// families
std::vector<std::array<double, 3>> random_points(std::mt19937_64 &rng, int n, double aspect);
std::vector<std::array<double, 3>> cube_points(double side);
std::vector<std::array<double, 3>> dodecahedron_points(double circumradius);
std::vector<std::array<double, 3>> cylinder_points(double diameter, double length, int nrim);

// uniformly random unit quaternion
polydem::Quat<double> random_quat(std::mt19937_64 &rng);

// lab-frame vertices of a posed shape (double)
std::vector<std::array<double, 3>> posed_vertices(const ShapeData &s,
                                                  const polydem::Pose<double> &p);

}    // namespace polydem_test

#endif
