// POLYDEM kernel tests: exact reference geometry (see cgal_ref.h).
#include "cgal_ref.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Gmpzf.h>
#include <CGAL/Polytope_distance_d.h>
#include <CGAL/Polytope_distance_d_traits_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <cmath>

namespace polydem_test {

using EK = CGAL::Exact_predicates_exact_constructions_kernel;
using IK = CGAL::Exact_predicates_inexact_constructions_kernel;
using P3 = EK::Point_3;
using Mesh = CGAL::Surface_mesh<P3>;

namespace {

  struct ExactHull {
    std::vector<P3> pts;
    std::vector<EK::Triangle_3> tris;
    std::vector<EK::Segment_3> segs;
    std::vector<CGAL::Bbox_3> tbox, sbox;
    std::vector<std::array<double, 4>> tplane;        // approximate planes for a safe prefilter
    std::vector<std::array<IK::Point_3, 3>> itris;    // the same triangles, double input points
    std::vector<std::array<double, 6>> sd;            // segment end points (double)
    IK::Point_3 inside;                               // a point strictly inside
    double scale = 0;
  };

  // hull with exact predicates on the (double) input points, then exact copies
  void build(const Pts &in, ExactHull &h)
  {
    std::vector<IK::Point_3> p;
    for (auto &q : in) p.emplace_back(q[0], q[1], q[2]);
    CGAL::Surface_mesh<IK::Point_3> m;
    CGAL::convex_hull_3(p.begin(), p.end(), m);
    double sx = 0, sy = 0, sz = 0;
    int n = 0;
    for (auto v : m.vertices()) {
      const auto &q = m.point(v);
      h.pts.emplace_back(q.x(), q.y(), q.z());
      sx += q.x();
      sy += q.y();
      sz += q.z();
      h.scale = std::max({h.scale, std::fabs(q.x()), std::fabs(q.y()), std::fabs(q.z())});
      ++n;
    }
    h.inside = IK::Point_3(sx / n, sy / n, sz / n);
    for (auto f : m.faces()) {
      std::array<IK::Point_3, 3> t;
      int k = 0;
      for (auto v : CGAL::vertices_around_face(m.halfedge(f), m)) t[k++] = m.point(v);
      h.itris.push_back(t);
      h.tris.emplace_back(P3(t[0].x(), t[0].y(), t[0].z()), P3(t[1].x(), t[1].y(), t[1].z()),
                          P3(t[2].x(), t[2].y(), t[2].z()));
      h.tbox.push_back(t[0].bbox() + t[1].bbox() + t[2].bbox());
      const IK::Vector_3 nr = CGAL::cross_product(t[1] - t[0], t[2] - t[0]);
      const double l = std::sqrt(nr.squared_length());
      h.tplane.push_back({nr.x() / l, nr.y() / l, nr.z() / l,
                          (nr.x() * t[0].x() + nr.y() * t[0].y() + nr.z() * t[0].z()) / l});
    }
    for (auto e : m.edges()) {
      auto he = m.halfedge(e);
      const auto &a = m.point(m.source(he)), &b = m.point(m.target(he));
      h.segs.emplace_back(P3(a.x(), a.y(), a.z()), P3(b.x(), b.y(), b.z()));
      h.sbox.push_back(a.bbox() + b.bbox());
      h.sd.push_back({a.x(), a.y(), a.z(), b.x(), b.y(), b.z()});
    }
  }

  // closed containment of an input (double) point: exact predicates
  bool contains(const ExactHull &h, const P3 &pe)
  {
    const IK::Point_3 p(CGAL::to_double(pe.x()), CGAL::to_double(pe.y()), CGAL::to_double(pe.z()));
    for (auto &t : h.itris) {
      auto in = CGAL::orientation(t[0], t[1], t[2], h.inside);
      auto o = CGAL::orientation(t[0], t[1], t[2], p);
      if (o != CGAL::COPLANAR && o != in) return false;
    }
    return true;
  }

  void add_crossings(const ExactHull &s, const ExactHull &t, std::vector<P3> &out)
  {
    for (size_t i = 0; i < s.segs.size(); ++i)
      for (size_t j = 0; j < t.tris.size(); ++j) {
        if (!CGAL::do_overlap(s.sbox[i], t.tbox[j])) continue;
        // safe floating-point prefilter: both end points clearly on one side
        const auto &q = t.tplane[j];
        const auto &e = s.sd[i];
        const double m = 1e-9 * (t.scale + s.scale + 1.0);
        const double s0 = q[0] * e[0] + q[1] * e[1] + q[2] * e[2] - q[3];
        const double s1 = q[0] * e[3] + q[1] * e[4] + q[2] * e[5] - q[3];
        if ((s0 > m && s1 > m) || (s0 < -m && s1 < -m)) continue;
        if (!CGAL::do_intersect(s.segs[i], t.tris[j])) continue;
        auto r = CGAL::intersection(s.segs[i], t.tris[j]);
        if (!r) continue;
        if (const P3 *p = boost::get<P3>(&*r))
          out.push_back(*p);
        else if (const EK::Segment_3 *q = boost::get<EK::Segment_3>(&*r)) {
          out.push_back(q->source());
          out.push_back(q->target());
        }
      }
  }

  bool full_dimensional(const std::vector<P3> &p)
  {
    if (p.size() < 4) return false;
    size_t j = 1;
    while (j < p.size() && p[j] == p[0]) ++j;
    if (j == p.size()) return false;
    size_t k = j + 1;
    while (k < p.size() && CGAL::collinear(p[0], p[j], p[k])) ++k;
    if (k >= p.size()) return false;
    for (size_t l = 0; l < p.size(); ++l)
      if (!CGAL::coplanar(p[0], p[j], p[k], p[l])) return true;
    return false;
  }

  // exact intersection hull; false if lower-dimensional or empty
  bool intersection_hull(const ExactHull &A, const ExactHull &B, Mesh &out, bool &nonempty)
  {
    std::vector<P3> cand;
    for (auto &p : A.pts)    // input points are doubles: exact containment by predicates
      if (contains(B, p)) cand.push_back(p);
    for (auto &p : B.pts)
      if (contains(A, p)) cand.push_back(p);
    add_crossings(A, B, cand);
    add_crossings(B, A, cand);
    nonempty = !cand.empty();
    if (!full_dimensional(cand)) return false;
    CGAL::convex_hull_3(cand.begin(), cand.end(), out);
    return true;
  }

  void integrate(const Mesh &m, double &vol, std::array<double, 3> &c)
  {
    const P3 o = m.point(*m.vertices().begin());
    EK::FT v6 = 0, cx = 0, cy = 0, cz = 0;
    for (auto f : m.faces()) {
      std::array<EK::Vector_3, 3> t;
      int k = 0;
      for (auto v : CGAL::vertices_around_face(m.halfedge(f), m)) t[k++] = m.point(v) - o;
      EK::FT d = CGAL::determinant(t[0], t[1], t[2]);
      v6 += d;
      EK::Vector_3 s = t[0] + t[1] + t[2];
      cx += d * s.x();
      cy += d * s.y();
      cz += d * s.z();
    }
    vol = CGAL::to_double(v6 / 6);
    c = {CGAL::to_double(o.x() + cx / (4 * v6)), CGAL::to_double(o.y() + cy / (4 * v6)),
         CGAL::to_double(o.z() + cz / (4 * v6))};
  }

}    // namespace

RefResult ref_intersection(const Pts &a, const Pts &b)
{
  ExactHull A, B;
  build(a, A);
  build(b, B);
  RefResult r;
  Mesh m;
  if (!intersection_hull(A, B, m, r.intersects)) return r;
  integrate(m, r.volume, r.centroid);
  return r;
}

RefResult ref_halfspaces(const std::vector<std::array<double, 4>> &planes)
{
  std::vector<EK::Plane_3> pl;    // a x + b y + c z + d = 0, inside: negative side
  for (auto &q : planes) pl.emplace_back(q[0], q[1], q[2], -EK::FT(q[3]));
  const size_t n = pl.size();
  std::vector<P3> cand;
  for (size_t i = 0; i < n; ++i)
    for (size_t j = i + 1; j < n; ++j)
      for (size_t k = j + 1; k < n; ++k) {
        // cheap double rejection of nearly dependent triples is not safe; exact
        auto r = CGAL::intersection(pl[i], pl[j], pl[k]);
        if (!r) continue;
        const P3 *p = boost::get<P3>(&*r);
        if (!p) continue;
        bool in = true;
        for (size_t l = 0; l < n && in; ++l)
          if (l != i && l != j && l != k && pl[l].oriented_side(*p) == CGAL::ON_POSITIVE_SIDE)
            in = false;
        if (in) cand.push_back(*p);
      }
  RefResult r;
  r.intersects = !cand.empty();
  if (!full_dimensional(cand)) return r;
  Mesh m;
  CGAL::convex_hull_3(cand.begin(), cand.end(), m);
  integrate(m, r.volume, r.centroid);
  return r;
}

RefClip ref_clip(const Pts &p, const std::array<double, 3> &t0, const std::array<double, 3> &t1,
                 const std::array<double, 3> &t2)
{
  ExactHull A, Q;
  build(p, A);
  const P3 a(t0[0], t0[1], t0[2]), b(t1[0], t1[1], t1[2]), c(t2[0], t2[1], t2[2]);
  const EK::Vector_3 n = CGAL::cross_product(b - a, c - a);
  // prism behind the triangle, deep enough to contain the polyhedron's far side
  double ext = 0;
  for (auto &q : p)
    for (int k = 0; k < 3; ++k) ext = std::max(ext, std::fabs(q[k] - t0[k]));
  const double nn = std::sqrt(CGAL::to_double(n.squared_length()));
  const EK::FT lam = 4 * (ext + 1) / nn;
  Pts qp;
  for (const P3 &v : {a, b, c, a - lam * n, b - lam * n, c - lam * n})
    qp.push_back({CGAL::to_double(v.x()), CGAL::to_double(v.y()), CGAL::to_double(v.z())});
  // the doubles above may round the deep vertices; that is harmless (far away)
  qp[0] = t0;
  qp[1] = t1;
  qp[2] = t2;
  build(qp, Q);
  RefClip r;
  Mesh m;
  bool ne;
  if (!intersection_hull(A, Q, m, ne)) return r;
  integrate(m, r.volume, r.vcentroid);
  // faces of the intersection lying in the triangle's plane = clipped section
  EK::Plane_3 pl(a, b, c);
  double ar = 0, cx = 0, cy = 0, cz = 0;
  for (auto f : m.faces()) {
    std::array<P3, 3> t;
    int k = 0;
    for (auto v : CGAL::vertices_around_face(m.halfedge(f), m)) t[k++] = m.point(v);
    if (!pl.has_on(t[0]) || !pl.has_on(t[1]) || !pl.has_on(t[2])) continue;
    double x[3][3];
    for (int i = 0; i < 3; ++i) {
      x[i][0] = CGAL::to_double(t[i].x());
      x[i][1] = CGAL::to_double(t[i].y());
      x[i][2] = CGAL::to_double(t[i].z());
    }
    double u[3], w[3];
    for (int i = 0; i < 3; ++i) {
      u[i] = x[1][i] - x[0][i];
      w[i] = x[2][i] - x[0][i];
    }
    double cr[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2],
                    u[0] * w[1] - u[1] * w[0]};
    double at = 0.5 * std::sqrt(cr[0] * cr[0] + cr[1] * cr[1] + cr[2] * cr[2]);
    ar += at;
    cx += at * (x[0][0] + x[1][0] + x[2][0]) / 3;
    cy += at * (x[0][1] + x[1][1] + x[2][1]) / 3;
    cz += at * (x[0][2] + x[1][2] + x[2][2]) / 3;
  }
  r.area = ar;
  if (ar > 0) r.acentroid = {cx / ar, cy / ar, cz / ar};
  return r;
}

double ref_distance(const Pts &a, const Pts &b)
{
  using K = CGAL::Simple_cartesian<double>;
  using Traits = CGAL::Polytope_distance_d_traits_3<K, CGAL::Gmpzf, double>;
  std::vector<K::Point_3> pa, pb;
  for (auto &q : a) pa.emplace_back(q[0], q[1], q[2]);
  for (auto &q : b) pb.emplace_back(q[0], q[1], q[2]);
  CGAL::Polytope_distance_d<Traits> pd(pa.begin(), pa.end(), pb.begin(), pb.end());
  return std::sqrt(CGAL::to_double(pd.squared_distance_numerator()) /
                   CGAL::to_double(pd.squared_distance_denominator()));
}

}    // namespace polydem_test
