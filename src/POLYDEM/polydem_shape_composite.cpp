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

   Contacts sum over pairs of parts, so the contact parts must not overlap
   (a common volume would count twice): where polyhedral parts overlap, the
   contact parts are the convex pieces of their union (CGAL
   convex_decomposition_3), the ellipsoid parts as given.
------------------------------------------------------------------------- */

#include "polydem_shape_template.h"

#include "polydem_ellipsoid_overlap.h"
#include "polydem_shape_template_impl.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
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

  void add_moments(RawMoments &a, const RawMoments &b)
  {
    a.V += b.V;
    for (int i = 0; i < 3; ++i) {
      a.m1[i] += b.m1[i];
      for (int j = 0; j < 3; ++j) a.m2[i][j] += b.m2[i][j];
    }
  }

  // the largest volume two convex parts share (exact: the hull of the
  // corners of their Nef intersection, itself convex), over the smaller
  // part's volume
  double largest_shared_fraction(const std::vector<Nef> &nefs, const std::vector<Mesh> &hulls)
  {
    double worst = 0.0;
    for (size_t a = 0; a < nefs.size(); ++a)
      for (size_t b = a + 1; b < nefs.size(); ++b) {
        const Nef both = nefs[a] * nefs[b];
        std::vector<K::Point_3> pts;
        for (auto v = both.vertices_begin(); v != both.vertices_end(); ++v)
          pts.push_back(v->point());
        if (pts.size() < 4) continue;
        Mesh h;
        CGAL::convex_hull_3(pts.begin(), pts.end(), h);
        if (h.number_of_faces() < 4) continue;    // coplanar: no volume
        const double v = mesh_moments(h).V;
        const double vmin = std::min(mesh_moments(hulls[a]).V, mesh_moments(hulls[b]).V);
        worst = std::max(worst, v / vmin);
      }
    return worst;
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

  // the convex pieces of a Nef polyhedron (decomposed in place): corner
  // points (rounded to doubles) and exact volumes
  struct Piece {
    std::vector<PolyShapeTemplate::Point> corners;
    double volume;
  };
  std::vector<Piece> nef_pieces(Nef &nef)
  {
    CGAL::convex_decomposition_3(nef);
    std::vector<Piece> pieces;
    for (auto c = ++nef.volumes_begin(); c != nef.volumes_end(); ++c) {
      if (!c->mark()) continue;
      CGAL::Polyhedron_3<K> piece;
      nef.convert_inner_shell_to_polyhedron(c->shells_begin(), piece);
      Piece pc;
      for (auto p = piece.points_begin(); p != piece.points_end(); ++p)
        pc.corners.push_back(
            {CGAL::to_double(p->x()), CGAL::to_double(p->y()), CGAL::to_double(p->z())});
      // 6 V = sum over the facets' fans of a . (b x c)
      ET vol6(0);
      for (auto f = piece.facets_begin(); f != piece.facets_end(); ++f) {
        auto h = f->facet_begin();
        const auto a = h->vertex()->point();
        ++h;
        for (auto b = h; std::next(b) != f->facet_begin(); ++b) {
          const auto p1 = b->vertex()->point(), p2 = std::next(b)->vertex()->point();
          vol6 += CGAL::exact(CGAL::determinant(a.x(), a.y(), a.z(), p1.x(), p1.y(), p1.z(),
                                                p2.x(), p2.y(), p2.z()));
        }
      }
      pc.volume = CGAL::to_double(vol6 / 6);
      std::sort(pc.corners.begin(), pc.corners.end());
      pc.corners.erase(std::unique(pc.corners.begin(), pc.corners.end()), pc.corners.end());
      pieces.push_back(std::move(pc));
    }
    // in a canonical order: the Nef structure's order of volumes and points
    // may change from one build to the next (it follows memory addresses),
    // and a restart rebuilds the template bit for bit
    std::sort(pieces.begin(), pieces.end(),
              [](const Piece &a, const Piece &b) { return a.corners < b.corners; });
    return pieces;
  }

  // corners that lie within tol of the convex hull of the others removed,
  // one at a time (a piece of rounded corners may have faces that are not
  // quite planar: a template needs its vertices clear of the others' faces)
  std::vector<PolyShapeTemplate::Point> simplify_corners(std::vector<PolyShapeTemplate::Point> pts,
                                                         double tol)
  {
    using KI = CGAL::Epick;
    bool removed = true;
    while (removed && pts.size() > 4) {
      removed = false;
      for (size_t k = 0; k < pts.size() && !removed; ++k) {
        std::vector<KI::Point_3> others;
        for (size_t j = 0; j < pts.size(); ++j)
          if (j != k) others.emplace_back(pts[j][0], pts[j][1], pts[j][2]);
        CGAL::Surface_mesh<KI::Point_3> h;
        CGAL::convex_hull_3(others.begin(), others.end(), h);
        if (h.number_of_faces() < 4) continue;    // the others are flat: k is needed
        double out = -1e300;
        for (auto f : h.faces()) {
          std::array<KI::Point_3, 3> v;
          int i = 0;
          for (auto u : CGAL::vertices_around_face(h.halfedge(f), h))
            if (i < 3) v[i++] = h.point(u);
          const auto n = CGAL::cross_product(v[1] - v[0], v[2] - v[0]);
          const double nn = std::sqrt(n.squared_length());
          if (!(nn > 0.0)) continue;
          const KI::Point_3 p(pts[k][0], pts[k][1], pts[k][2]);
          out = std::max(out, (n * (p - v[0])) / nn);
        }
        if (out <= tol) {
          pts.erase(pts.begin() + (long) k);
          removed = true;
        }
      }
    }
    return pts;
  }

  // volume of the convex hull of points (double)
  double hull_volume(const std::vector<PolyShapeTemplate::Point> &pts,
                     std::vector<PolyShapeTemplate::Point> *corners = nullptr)
  {
    using KI = CGAL::Epick;
    std::vector<KI::Point_3> p;
    for (const auto &a : pts) p.emplace_back(a[0], a[1], a[2]);
    CGAL::Surface_mesh<KI::Point_3> h;
    CGAL::convex_hull_3(p.begin(), p.end(), h);
    double v6 = 0.0;
    for (auto f : h.faces()) {
      std::vector<KI::Point_3> v;
      for (auto u : CGAL::vertices_around_face(h.halfedge(f), h)) v.push_back(h.point(u));
      for (size_t k = 1; k + 1 < v.size(); ++k)
        v6 += CGAL::determinant(v[0] - CGAL::ORIGIN, v[k] - CGAL::ORIGIN, v[k + 1] - CGAL::ORIGIN);
    }
    if (corners) {
      corners->clear();
      for (auto u : h.vertices()) corners->push_back({h.point(u).x(), h.point(u).y(), h.point(u).z()});
    }
    return v6 / 6.0;
  }

  // adjacent pieces whose union is convex (its hull no larger than the two
  // by 1e-9 of the union's volume vtot) joined, greedily: exact cuts through
  // the nearly flat edges of rounded faces leave more pieces than the shape has
  void join_convex_pieces(std::vector<Piece> &pieces, double vtot)
  {
    bool joined = true;
    while (joined) {
      joined = false;
      for (size_t i = 0; i < pieces.size() && !joined; ++i)
        for (size_t j = i + 1; j < pieces.size() && !joined; ++j) {
          std::vector<PolyShapeTemplate::Point> both = pieces[i].corners, hull;
          both.insert(both.end(), pieces[j].corners.begin(), pieces[j].corners.end());
          const double vh = hull_volume(both, &hull);
          if (vh <= pieces[i].volume + pieces[j].volume + 1e-9 * vtot) {
            std::sort(hull.begin(), hull.end());
            pieces[i].corners = hull;
            pieces[i].volume += pieces[j].volume;
            pieces.erase(pieces.begin() + (long) j);
            joined = true;
          }
        }
    }
  }

  // corners closer than tol merged (the first kept)
  std::vector<PolyShapeTemplate::Point> merge_close(const std::vector<PolyShapeTemplate::Point> &in,
                                                    double tol)
  {
    std::vector<PolyShapeTemplate::Point> out;
    for (const auto &p : in) {
      bool dup = false;
      for (const auto &q : out)
        dup = dup || std::hypot(p[0] - q[0], std::hypot(p[1] - q[1], p[2] - q[2])) <= tol;
      if (!dup) out.push_back(p);
    }
    return out;
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

  // the contact parts: as given, or (overlapping polyhedra) the ellipsoids
  // and the convex pieces of the polyhedral parts' union
  std::vector<InputPart> contact = parts;
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
    std::vector<Mesh> hulls;
    std::vector<Nef> nefs;
    int npoly = 0;
    for (const auto &p : parts) {
      if (p.shape->is_ellipsoid()) continue;
      const auto pts = placed_vertices(p);
      hulls.emplace_back();
      CGAL::convex_hull_3(pts.begin(), pts.end(), hulls.back());
      nefs.emplace_back(hulls.back());
      if (npoly++ == 0)
        joined = nefs.back();
      else
        joined += nefs.back();
    }
    if (npoly > 0 && !joined.is_simple()) {
      // parts that meet face to face once their corners are rounded to
      // doubles (the pieces of a decomposed surface, sectors turned by
      // irrational angles) can meet in slivers that leave the union not a
      // 2-manifold: if no two parts share more than 1e-9 of the smaller
      // one's volume they are taken as disjoint, and their moments summed
      const double shared = largest_shared_fraction(nefs, hulls);
      if (!(shared <= 1e-9))
        throw ShapeError(head + ": the union of the polyhedral parts is not a 2-manifold "
                         "(parts that meet only along an edge or at a corner?)");
      for (const auto &h : hulls) add_moments(raw, mesh_moments(h));
    } else if (npoly > 0) {
      Mesh boundary;
      CGAL::convert_nef_polyhedron_to_polygon_mesh(joined, boundary, true);
      raw = mesh_moments(boundary);
      double poly_sum = 0.0;
      for (const auto &p : parts)
        if (!p.shape->is_ellipsoid()) poly_sum += p.shape->volume();
      if (raw.V < poly_sum * (1.0 - 1e-12)) {
        // overlapping parts would count their common volume twice in a
        // contact: the contact parts are the union's disjoint convex pieces
        Nef cut = joined;
        auto pieces = nef_pieces(cut);
        join_convex_pieces(pieces, raw.V);
        contact.clear();
        for (const auto &p : parts)
          if (p.shape->is_ellipsoid()) contact.push_back(p);
        ShapeOptions opt;
        opt.hull = true;    // corners on a piece's edges or faces are not vertices
        // slivers (parts turned by irrational angles have rounded, not
        // exactly planar faces, and their union's pieces may be thinner than
        // a template can be) are left out of the contact parts: below 1e-9
        // of the union's volume always, below 1e-6 where no template can be
        // made of them; the mass properties stay the union's
        double dropped = 0.0;
        int ndropped = 0;
        for (size_t k = 0; k < pieces.size(); ++k) {
          InputPart ip;
          ip.id = "piece" + std::to_string(k + 1);
          if (pieces[k].volume < 1e-9 * raw.V) {
            dropped += pieces[k].volume;
            ++ndropped;
            continue;
          }
          double diam = 0.0;
          for (const auto &a : pieces[k].corners)
            for (const auto &b : pieces[k].corners)
              diam = std::max(diam, std::hypot(a[0] - b[0], std::hypot(a[1] - b[1], a[2] - b[2])));
          std::shared_ptr<PolyShapeTemplate> pt;
          try {
            const auto corners = merge_close(pieces[k].corners, 1e-9 * diam);
            try {
              pt = std::make_shared<PolyShapeTemplate>(
                  PolyShapeTemplate::from_points(corners, {}, opt, name + "_" + ip.id));
            } catch (const ShapeError &) {
              // near-coplanar faces: without the corners within 1e-7 of the
              // others' hull, closer corners merged (the piece moves by at
              // most 1e-7 of its size)
              std::vector<Point> hull;
              hull_volume(merge_close(corners, 1e-7 * diam), &hull);
              std::sort(hull.begin(), hull.end());
              pt = std::make_shared<PolyShapeTemplate>(PolyShapeTemplate::from_points(
                  simplify_corners(hull, 1e-7 * diam), {}, opt, name + "_" + ip.id));
            }
          } catch (const ShapeError &e) {
            if (pieces[k].volume >= 1e-6 * raw.V)
              throw ShapeError(head + ": overlapping parts are cut into disjoint convex "
                               "pieces for the contacts, and piece " + std::to_string(k + 1) +
                               " (" + fmt_num(pieces[k].volume / raw.V) +
                               " of the volume) is no valid convex template (" + e.what() +
                               "); give parts that do not overlap (they may touch), or the "
                               "grain as a closed STL surface");
            dropped += pieces[k].volume;
            ++ndropped;
            continue;
          }
          ip.x = pt->input_centroid();
          ip.q = pt->input_orientation();
          ip.shape = std::move(pt);
          contact.push_back(std::move(ip));
        }
        if (dropped > 1e-12 * raw.V)    // else round-off: 1e-16 for crosses turned by 90 degrees
          t.warnings_.push_back(head + ": " + std::to_string(ndropped) +
                                " sliver pieces of the union (" + fmt_num(dropped / raw.V) +
                                " of its volume) are not contact parts");
        if ((int) contact.size() > MAX_COMPOSITE_PARTS)
          throw ShapeError(head + ": the union of the overlapping parts has " +
                           std::to_string(contact.size()) + " convex pieces, more than " +
                           std::to_string(MAX_COMPOSITE_PARTS));
        t.decomposed_ = true;
        body.resize(contact.size());
      }
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
    // each contact part in the body frame: x_b = R^T (x - c), R_b = R^T R_part
    t.radius_ = 0.0;
    for (size_t k = 0; k < contact.size(); ++k) {
      const Mat3<double> Rp = rotation_of(contact[k].q);
      for (int i = 0; i < 3; ++i) {
        long double x = 0.0L;
        for (int j = 0; j < 3; ++j) x += (long double) R[j][i] * (contact[k].x[j] - c[j]);
        body[k].x[i] = (double) x;
        for (int j = 0; j < 3; ++j) {
          long double r = 0.0L;
          for (int l = 0; l < 3; ++l) r += (long double) R[l][i] * Rp.m[l][j];
          body[k].R[i][j] = (double) r;
        }
      }
      // the bounding radius: the farthest corner of a polyhedral part (the
      // part's own sphere about its centroid can reach well past the grain:
      // a ring's sectors, 0.95 against 0.72 of the ring's diameter), an
      // ellipsoid part's centre distance plus its largest semi-axis
      const auto &ps = *contact[k].shape;
      if (ps.is_ellipsoid()) {
        const double d = std::sqrt(body[k].x[0] * body[k].x[0] + body[k].x[1] * body[k].x[1] +
                                   body[k].x[2] * body[k].x[2]);
        t.radius_ = std::max(t.radius_, d + ps.radius());
      } else {
        for (int v = 0; v < ps.nverts(); ++v) {
          const auto b = ps.vertex(v);
          double w2 = 0.0;
          for (int i = 0; i < 3; ++i) {
            const double w =
                body[k].x[i] + body[k].R[i][0] * b[0] + body[k].R[i][1] * b[1] + body[k].R[i][2] * b[2];
            w2 += w * w;
          }
          t.radius_ = std::max(t.radius_, std::sqrt(w2));
        }
      }
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

  // each contact part's bounding box in its own frame
  for (size_t k = 0; k < body.size(); ++k) {
    const auto &ps = *contact[k].shape;
    if (ps.is_ellipsoid()) {
      for (int i = 0; i < 3; ++i) {
        body[k].mid[i] = 0.0;
        body[k].half[i] = ps.semi_axes()[i];
      }
      continue;
    }
    for (int i = 0; i < 3; ++i) {
      double lo = ps.vertex(0)[i], hi = lo;
      for (int v = 1; v < ps.nverts(); ++v) {
        lo = std::min(lo, ps.vertex(v)[i]);
        hi = std::max(hi, ps.vertex(v)[i]);
      }
      body[k].mid[i] = 0.5 * (lo + hi);
      body[k].half[i] = 0.5 * (hi - lo);
    }
  }

  auto views = std::make_shared<std::vector<ShapeView<double>>>();
  for (const auto &p : contact) {
    views->push_back(p.shape->view());
    t.part_shapes_.push_back(p.shape);
  }
  for (size_t k = 0; k < contact.size(); ++k) body[k].view = &(*views)[k];
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
  const auto pieces = nef_pieces(nef);
  if (pieces.empty()) throw ShapeError(head + ": no solid inside the surface");
  std::vector<std::vector<Point>> out;
  for (const auto &p : pieces) out.push_back(p.corners);
  return out;
}

}    // namespace polydem
