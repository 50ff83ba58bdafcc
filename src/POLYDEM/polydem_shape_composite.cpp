/* ----------------------------------------------------------------------
   POLYDEM - composite shape templates: a non-convex grain as the rigid
   union of convex parts (polyhedra, ellipsoids), each placed by a position
   and an orientation in the composite's input frame.

   Mass properties are those of the union, not of the sum: the polyhedral
   parts are joined as Nef polyhedra (CGAL, exact constructions) and the
   union's volume, first and second moments summed over its triangulated
   boundary in exact arithmetic (the tetrahedron moment formulas of
   polydem_shape_mass.cpp), rounded once. Ellipsoid parts must be disjoint
   from every other part (checked with the exact overlap kernels,
   polydem_ellipsoid_overlap.h) and add their analytic moments. The body
   frame is the union's principal frame; a composite of one part is that
   part, in its own frame.
------------------------------------------------------------------------- */

#include "polydem_shape_template.h"

#include "polydem_ellipsoid_overlap.h"
#include "polydem_shape_template_impl.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Nef_polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/convert_nef_polyhedron_to_polygon_mesh.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/convex_decomposition_3.h>
#include <CGAL/convex_hull_3.h>

#include <map>
#include <tuple>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace polydem {

using namespace shape_impl;

namespace {

  using K = CGAL::Epeck;
  using Mesh = CGAL::Surface_mesh<K::Point_3>;
  using Nef = CGAL::Nef_polyhedron_3<K>;
  using ET = K::Exact_kernel::FT;

  // volume and raw moments int x, int x x^T of a body (input frame)
  struct RawMoments {
    double V = 0.0, m1[3] = {0.0, 0.0, 0.0}, m2[3][3] = {{0.0}};
  };

  // exact moments of the closed, outward triangulated mesh: tetrahedra
  // (0, a, b, c), 6V = det, 24 int x = det s, 120 int x x^T = det (sum_v v v^T + s s^T)
  RawMoments mesh_moments(const Mesh &m)
  {
    ET vol6(0), m1[3], m2[3][3];
    for (int i = 0; i < 3; ++i) {
      m1[i] = 0;
      for (int j = 0; j < 3; ++j) m2[i][j] = 0;
    }
    for (auto f : m.faces()) {
      ET p[3][3];
      int k = 0;
      for (auto v : CGAL::vertices_around_face(m.halfedge(f), m)) {
        if (k < 3) {
          const auto &pt = m.point(v);
          p[k][0] = CGAL::exact(pt.x());
          p[k][1] = CGAL::exact(pt.y());
          p[k][2] = CGAL::exact(pt.z());
        }
        ++k;
      }
      if (k != 3) throw ShapeError("composite: the union's boundary is not triangulated");
      const ET det = p[0][0] * (p[1][1] * p[2][2] - p[1][2] * p[2][1]) -
          p[0][1] * (p[1][0] * p[2][2] - p[1][2] * p[2][0]) +
          p[0][2] * (p[1][0] * p[2][1] - p[1][1] * p[2][0]);
      vol6 += det;
      ET s[3];
      for (int i = 0; i < 3; ++i) s[i] = p[0][i] + p[1][i] + p[2][i];
      for (int i = 0; i < 3; ++i) {
        m1[i] += det * s[i];
        for (int j = i; j < 3; ++j)
          m2[i][j] += det * (p[0][i] * p[0][j] + p[1][i] * p[1][j] + p[2][i] * p[2][j] + s[i] * s[j]);
      }
    }
    RawMoments r;
    r.V = CGAL::to_double(vol6 / 6);
    for (int i = 0; i < 3; ++i) {
      r.m1[i] = CGAL::to_double(m1[i] / 24);
      for (int j = i; j < 3; ++j) r.m2[i][j] = r.m2[j][i] = CGAL::to_double(m2[i][j] / 120);
    }
    return r;
  }

  Mat3<double> rotation_of(const Quat<double> &q)
  {
    return quat_to_mat(q);
  }

  // the part's vertices in the composite's input frame
  std::vector<K::Point_3> placed_vertices(const PolyShapeTemplate::InputPart &p)
  {
    const Mat3<double> R = rotation_of(p.q);
    std::vector<K::Point_3> pts;
    for (int v = 0; v < p.shape->nverts(); ++v) {
      const auto b = p.shape->vertex(v);
      const Vec3<double> w =
          make_vec3(p.x[0], p.x[1], p.x[2]) + matvec(R, make_vec3(b[0], b[1], b[2]));
      pts.emplace_back(w.x, w.y, w.z);
    }
    return pts;
  }

  // the ellipsoid part's moments (disjoint from the rest): V, V c, C + V c c^T
  void add_ellipsoid(const PolyShapeTemplate::InputPart &p, RawMoments &r)
  {
    const auto &ax = p.shape->semi_axes();
    const double V = p.shape->volume();
    const Mat3<double> R = rotation_of(p.q);
    const double d[3] = {V * ax[0] * ax[0] / 5, V * ax[1] * ax[1] / 5, V * ax[2] * ax[2] / 5};
    r.V += V;
    for (int i = 0; i < 3; ++i) {
      r.m1[i] += V * p.x[i];
      for (int j = 0; j < 3; ++j) {
        double c = 0.0;
        for (int k = 0; k < 3; ++k) c += R.m[i][k] * d[k] * R.m[j][k];
        r.m2[i][j] += c + V * p.x[i] * p.x[j];
      }
    }
  }

  // an ellipsoid part against another part: error if they overlap
  void check_disjoint(const PolyShapeTemplate::InputPart &e, const PolyShapeTemplate::InputPart &o,
                      const std::string &head)
  {
    const auto &ae = e.shape->semi_axes();
    const Vec3<double> xe = make_vec3(e.x[0], e.x[1], e.x[2]), xo = make_vec3(o.x[0], o.x[1], o.x[2]);
    const double d = norm(xe - xo);
    if (d >= e.shape->radius() + o.shape->radius()) return;
    const std::string what = head + ": parts '" + e.id + "' and '" + o.id + "' ";
    if (o.shape->is_ellipsoid()) {
      if (e.shape->is_sphere() && o.shape->is_sphere())
        throw ShapeError(what + "overlap (a part that is a sphere or an ellipsoid must be "
                         "disjoint from the other parts)");
      throw ShapeError(what + "may overlap (their bounding spheres intersect; a part that is an "
                       "ellipsoid must be disjoint from the other parts)");
    }
    const ShapeView<double> ov = o.shape->view();
    Pose<double> pose;
    pose.x = xo;
    pose.q = o.q;
    pose.s = 1.0;
    const auto r = polyhedron_ellipsoid_overlap(make_posed(ov, pose), xe, rotation_of(e.q),
                                                make_vec3(ae[0], ae[1], ae[2]), true);
    const double vmin = std::min(e.shape->volume(), o.shape->volume());
    if (r.status == STATUS_OK && r.volume > 1e-12 * vmin)
      throw ShapeError(what + "overlap by " + fmt_num(r.volume / vmin) +
                       " of the smaller one's volume (a part that is a sphere or an ellipsoid "
                       "must be disjoint from the other parts)");
  }

}    // namespace

PolyShapeTemplate PolyShapeTemplate::composite(const std::vector<InputPart> &parts_in,
                                               const std::string &name)
{
  const std::string head = name + ": composite";
  if (parts_in.empty()) throw ShapeError(head + ": no parts");
  if ((int) parts_in.size() > MAX_COMPOSITE_PARTS)
    throw ShapeError(head + ": " + std::to_string(parts_in.size()) + " parts, at most " +
                     std::to_string(MAX_COMPOSITE_PARTS));
  std::vector<InputPart> parts = parts_in;
  for (auto &p : parts) {
    if (!p.shape) throw ShapeError(head + ": part '" + p.id + "' has no shape");
    if (p.shape->is_composite())
      throw ShapeError(head + ": part '" + p.id + "' is itself a composite (parts are convex "
                       "polyhedra or ellipsoids)");
    const double qn = std::sqrt(p.q.w * p.q.w + p.q.x * p.q.x + p.q.y * p.q.y + p.q.z * p.q.z);
    bool finite = std::isfinite(qn);
    for (double c : p.x) finite = finite && std::isfinite(c);
    if (!finite || !(qn > 0.0))
      throw ShapeError(head + ": part '" + p.id + "' needs a finite position and a nonzero "
                       "orientation quaternion");
    p.q = qnormalize(p.q);
  }

  PolyShapeTemplate t;
  t.name_ = name;
  t.face_start_ = {0};    // no faces or vertices of its own
  t.input_parts_ = parts;
  double sum_volume = 0.0;
  for (const auto &p : parts) sum_volume += p.shape->volume();

  std::vector<ShapePart<double>> body(parts.size());
  if (parts.size() == 1) {
    // one part: its own frame (the input places the whole grain)
    const auto &p = parts[0];
    t.volume_ = p.shape->volume();
    t.moments_ = p.shape->moments();
    t.radius_ = p.shape->radius();
    t.centroid_ = p.x;
    const Mat3<double> R = rotation_of(p.q);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        t.rot_[i][j] = R.m[i][j];
        body[0].R[i][j] = i == j ? 1.0 : 0.0;
      }
    for (int i = 0; i < 3; ++i) body[0].x[i] = 0.0;
  } else {
    for (size_t a = 0; a < parts.size(); ++a)
      for (size_t b = 0; b < parts.size(); ++b)
        if (a != b && parts[a].shape->is_ellipsoid() && (a < b || !parts[b].shape->is_ellipsoid()))
          check_disjoint(parts[a], parts[b], head);

    // the union of the polyhedral parts, exactly
    RawMoments raw;
    Nef joined;
    int npoly = 0;
    for (const auto &p : parts) {
      if (p.shape->is_ellipsoid()) continue;
      const auto pts = placed_vertices(p);
      Mesh hull;
      CGAL::convex_hull_3(pts.begin(), pts.end(), hull);
      Nef one(hull);
      if (npoly++ == 0)
        joined = one;
      else
        joined += one;
    }
    if (npoly > 0) {
      if (!joined.is_simple())
        throw ShapeError(head + ": the union of the polyhedral parts is not a 2-manifold "
                         "(parts that meet only along an edge or at a corner?)");
      Mesh boundary;
      CGAL::convert_nef_polyhedron_to_polygon_mesh(joined, boundary, true);
      raw = mesh_moments(boundary);
    }
    for (const auto &p : parts)
      if (p.shape->is_ellipsoid()) add_ellipsoid(p, raw);

    // centroid, central inertia, principal frame
    const double V = raw.V;
    if (!(V > 0.0)) throw ShapeError(head + ": the union has zero volume");
    double c[3], I[3][3];
    for (int i = 0; i < 3; ++i) c[i] = raw.m1[i] / V;
    double C[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) C[i][j] = raw.m2[i][j] - V * c[i] * c[j];
    const double tr = C[0][0] + C[1][1] + C[2][2];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) I[i][j] = (i == j ? tr : 0.0) - C[i][j];
    double R[3][3];
    principal_axes(I, R);
    for (int k = 0; k < 3; ++k) {
      long double m = 0.0L;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) m += (long double) R[i][k] * I[i][j] * R[j][k];
      t.moments_[k] = (double) m;
    }
    t.volume_ = V;
    for (int i = 0; i < 3; ++i) {
      t.centroid_[i] = c[i];
      for (int j = 0; j < 3; ++j) t.rot_[i][j] = R[i][j];
    }
    // each part in the body frame: x_b = R^T (x - c), R_b = R^T R_part
    t.radius_ = 0.0;
    for (size_t k = 0; k < parts.size(); ++k) {
      const Mat3<double> Rp = rotation_of(parts[k].q);
      for (int i = 0; i < 3; ++i) {
        long double x = 0.0L;
        for (int j = 0; j < 3; ++j) x += (long double) R[j][i] * (parts[k].x[j] - c[j]);
        body[k].x[i] = (double) x;
        for (int j = 0; j < 3; ++j) {
          long double r = 0.0L;
          for (int l = 0; l < 3; ++l) r += (long double) R[l][i] * Rp.m[l][j];
          body[k].R[i][j] = (double) r;
        }
      }
      const double d = std::sqrt(body[k].x[0] * body[k].x[0] + body[k].x[1] * body[k].x[1] +
                                 body[k].x[2] * body[k].x[2]);
      t.radius_ = std::max(t.radius_, d + parts[k].shape->radius());
    }
  }
  t.union_fraction_ = t.volume_ / sum_volume;
  for (auto &b : body) {
    std::array<std::array<double, 3>, 3> m;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) m[i][j] = b.R[i][j];
    const Quat<double> q = rotation_quat(m);
    b.q[0] = q.w;
    b.q[1] = q.x;
    b.q[2] = q.y;
    b.q[3] = q.z;
  }

  auto views = std::make_shared<std::vector<ShapeView<double>>>();
  for (const auto &p : parts) views->push_back(p.shape->view());
  for (size_t k = 0; k < parts.size(); ++k) body[k].view = &(*views)[k];
  t.part_views_ = views;
  t.parts_ = std::make_shared<const std::vector<ShapePart<double>>>(std::move(body));
  t.check_mass_properties(head);
  return t;
}

std::vector<std::vector<PolyShapeTemplate::Point>>
PolyShapeTemplate::convex_pieces(const std::vector<double> &tri, const std::string &name)
{
  const std::string head = name + ": convex decomposition";
  // the surface with its corners merged (equal coordinates), outward
  std::map<std::tuple<double, double, double>, int> index;
  std::vector<Point> pts;
  std::vector<std::array<int, 3>> faces;
  for (size_t t = 0; t + 9 <= tri.size(); t += 9) {
    std::array<int, 3> f;
    for (int k = 0; k < 3; ++k) {
      const auto key = std::make_tuple(tri[t + 3 * k], tri[t + 3 * k + 1], tri[t + 3 * k + 2]);
      auto it = index.find(key);
      if (it == index.end()) {
        it = index.emplace(key, (int) pts.size()).first;
        pts.push_back({tri[t + 3 * k], tri[t + 3 * k + 1], tri[t + 3 * k + 2]});
      }
      f[k] = it->second;
    }
    faces.push_back(f);
  }
  auto build = [&](bool reverse) {
    Mesh m;
    std::vector<Mesh::Vertex_index> v;
    for (const auto &p : pts) v.push_back(m.add_vertex(K::Point_3(p[0], p[1], p[2])));
    for (const auto &f : faces) {
      const auto fi = reverse ? m.add_face(v[f[0]], v[f[2]], v[f[1]])
                              : m.add_face(v[f[0]], v[f[1]], v[f[2]]);
      if (fi == Mesh::null_face())
        throw ShapeError(head + ": the surface is not a consistently oriented 2-manifold (an "
                         "edge shared by more than two triangles, or two triangles running "
                         "along it the same way)");
    }
    return m;
  };
  Mesh surface = build(false);
  if (!CGAL::is_closed(surface))
    throw ShapeError(head + ": the surface is not closed (" + std::to_string(faces.size()) +
                     " triangles with open edges)");
  if (mesh_moments(surface).V < 0.0) surface = build(true);    // inward: turned outward
  Nef nef(surface);
  if (!nef.is_simple())
    throw ShapeError(head + ": the surface does not bound a simple solid");
  CGAL::convex_decomposition_3(nef);
  std::vector<std::vector<Point>> pieces;
  for (auto c = ++nef.volumes_begin(); c != nef.volumes_end(); ++c) {
    if (!c->mark()) continue;
    CGAL::Polyhedron_3<K> piece;
    nef.convert_inner_shell_to_polyhedron(c->shells_begin(), piece);
    std::vector<Point> corners;
    for (auto p = piece.points_begin(); p != piece.points_end(); ++p)
      corners.push_back({CGAL::to_double(p->x()), CGAL::to_double(p->y()), CGAL::to_double(p->z())});
    pieces.push_back(std::move(corners));
  }
  if (pieces.empty()) throw ShapeError(head + ": no solid inside the surface");
  return pieces;
}

}    // namespace polydem
