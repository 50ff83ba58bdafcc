/* ----------------------------------------------------------------------
   POLYDEM - host-side convex shape template (seed polyhedral 2.1):
   PolyShapeTemplate::from_points and build(), whose phases check the input,
   take CGAL's convex hull, check convexity, number the hull corners and
   merge coplanar hull triangles into faces; mass properties are in
   polydem_shape_mass.cpp, faces and views in polydem_shape_faces.cpp.
   File format and conventions: doc/Howto_polyhedron_shapes.rst.

   Exactness: input coordinates are doubles, hence exact rationals. Hull
   predicates are exact (Epick filtered predicates).
------------------------------------------------------------------------- */

#include "polydem_shape_template.h"

#include "polydem_shape_template_impl.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace polydem {

using namespace shape_impl;

namespace {

  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using P3 = K::Point_3;
  using Mesh = CGAL::Surface_mesh<P3>;

  // Relative tolerance (times the template diameter, length units) for
  // "this point lies in that plane" when exact coplanarity fails only
  // because irrational coordinates were rounded to double (e.g. the
  // dodecahedron's golden ratio). Rounding errors are ~1e-16.
  constexpr double PLANE_TOL = 1e-10;
  // Sizes (length units) a template may have: its volume ~ size^3 and moments
  // ~ size^5 must be normal doubles, and CGAL's exact arithmetic (GMP) dies
  // with SIGFPE on degree-5 products that overflow a double (coordinates
  // above ~1e61). Coordinates may lie at most SHAPE_OFFSET_MAX sizes from the
  // origin (beyond, the body frame loses every digit of the shape).
  constexpr double SHAPE_SIZE_MIN = 1e-50, SHAPE_SIZE_MAX = 1e50, SHAPE_OFFSET_MAX = 1e12;

}    // namespace

PolyShapeTemplate PolyShapeTemplate::from_points(const std::vector<Point> &pts_in,
                                                 const std::vector<std::vector<int>> &faces,
                                                 const ShapeOptions &opt, const std::string &name)
{
  if (!(opt.scale > 0) || !std::isfinite(opt.scale))
    throw ShapeError(name + ": scale must be positive and finite");
  std::vector<Pt> pts = pts_in;
  for (size_t i = 0; i < pts.size(); ++i)
    for (double &x : pts[i]) {
      if (!std::isfinite(x))
        throw ShapeError(name + ": vertex " + std::to_string(i) + ": coordinate " + fmt_num(x) +
                         " is not finite");
      x *= opt.scale;
    }
  for (size_t f = 0; f < faces.size(); ++f) {
    if (faces[f].size() < 3)
      throw ShapeError(name + ": face " + std::to_string(f) + " has fewer than 3 vertices");
    for (int k : faces[f])
      if (k < 0 || k >= (int) pts.size())
        throw ShapeError(name + ": face " + std::to_string(f) + ": vertex index " +
                         std::to_string(k) + " out of range");
  }
  PolyShapeTemplate st;
  st.name_ = name;
  ShapeOptions o2 = opt;
  o2.scale = 1.0;
  st.build(pts, faces, {}, {}, 0, o2);
  return st;
}

// =====================================================================
// geometry processing: build() runs the phases below in order; each one
// throws ShapeError for the first problem it finds, so a bad input gets
// the same message whatever else is wrong with it.
// =====================================================================

namespace {

  // Where things came from, for messages: "file:line" when read from a
  // file, else the name (and "name: face f" for faces).
  struct Where {
    const std::string &src;                     // file path, or the name when built from points
    const std::string head;                     // line of the `vertices` keyword, or src
    const std::vector<int> &vlines, &flines;    // file line of each vertex / face (empty: points)
    std::string vat(int i) const
    {
      return vlines.empty() ? src : src + ":" + std::to_string(vlines[i]);
    }
    std::string fat(int f) const
    {
      return flines.empty() ? src + ": face " + std::to_string(f)
                            : src + ":" + std::to_string(flines[f]);
    }
  };

  // CGAL's hull of the input points and what the later phases read of it.
  struct Hull {
    std::vector<P3> P;    // the input points as CGAL points (exact predicates)
    Mesh sm;
    Mesh::Property_map<Mesh::Vertex_index, int> vid;    // hull vertex -> input index
    std::vector<char> on_hull;                          // input point is a hull corner
    std::vector<std::array<int, 3>> tri_in;             // hull triangles, input indices, outward
    std::vector<Mesh::Face_index> fidx;                 // their mesh faces
    std::map<Mesh::Face_index, int> tri_of;             // mesh face -> triangle
    std::vector<V3> tnorm;                              // their unit normals (long double)
  };

  // Hull corners renumbered in input order, and the hull triangles in that numbering.
  struct Corners {
    std::vector<int> newid;    // input index -> corner index (-1: not a corner)
    std::vector<Pt> hv;        // corners, input coordinates
    std::vector<std::array<int, 3>> tri;
  };

  // Phase 1, input validation: at least 4 points, no exact duplicates (they
  // usually mean a typo in the file), size and distance from the origin
  // within bounds. Returns the coplanarity tolerance PLANE_TOL * diameter
  // (length units).
  long double check_points(const std::vector<Pt> &pts, const Where &w)
  {
    const int n = (int) pts.size();
    if (n < 4)
      throw ShapeError(w.head + ": a polyhedron needs at least 4 vertices, got " +
                       std::to_string(n));

    std::vector<int> ord(n);
    for (int i = 0; i < n; ++i) ord[i] = i;
    std::sort(ord.begin(), ord.end(), [&](int a, int b) {
      return pts[a] != pts[b] ? pts[a] < pts[b] : a < b;
    });
    for (int k = 1; k < n; ++k)
      if (pts[ord[k]] == pts[ord[k - 1]]) {
        int a = std::min(ord[k], ord[k - 1]), b = std::max(ord[k], ord[k - 1]);
        throw ShapeError(
            w.vat(b) + ": vertex " + std::to_string(b) + " duplicates vertex " + std::to_string(a) +
            (w.vlines.empty() ? std::string() : " (line " + std::to_string(w.vlines[a]) + ")"));
      }

    double lo[3], hi[3];
    for (int i = 0; i < 3; ++i) lo[i] = hi[i] = pts[0][i];
    for (const auto &p : pts)
      for (int i = 0; i < 3; ++i) {
        lo[i] = std::min(lo[i], p[i]);
        hi[i] = std::max(hi[i], p[i]);
      }
    double diam = std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                            (hi[2] - lo[2]) * (hi[2] - lo[2]));
    double cmax = 0.0;
    for (int i = 0; i < 3; ++i) cmax = std::max(cmax, std::max(std::fabs(lo[i]), std::fabs(hi[i])));
    if (!(diam >= SHAPE_SIZE_MIN && diam <= SHAPE_SIZE_MAX) || !(cmax <= SHAPE_SIZE_MAX))
      throw ShapeError(w.head + ": the shape's size " + fmt_num(diam) + " (largest coordinate " +
                       fmt_num(cmax) +
                       ") is outside [1e-50, 1e50]: its volume and moments would not "
                       "be normal numbers (use the file's or the command's scale)");
    if (cmax > SHAPE_OFFSET_MAX * diam)
      throw ShapeError(w.head + ": the shape (size " + fmt_num(diam) + ") lies " + fmt_num(cmax) +
                       " from the origin, more than 1e12 times its size: translate it");
    return PLANE_TOL * diam;
  }

  // Phase 2, hull: full dimensionality decided exactly, then CGAL's convex
  // hull, its triangles in input indices and their unit normals.
  void convex_hull(const std::vector<Pt> &pts, const Where &w, Hull &h)
  {
    const int n = (int) pts.size();
    std::vector<P3> &P = h.P;
    P.reserve(n);
    for (const auto &p : pts) P.emplace_back(p[0], p[1], p[2]);
    int i2 = -1, i3 = -1;
    for (int i = 2; i < n && i2 < 0; ++i)
      if (!CGAL::collinear(P[0], P[1], P[i])) i2 = i;
    if (i2 < 0)
      throw ShapeError(w.head + ": all " + std::to_string(n) +
                       " vertices are collinear (zero volume)");
    for (int i = 2; i < n && i3 < 0; ++i)
      if (CGAL::orientation(P[0], P[1], P[i2], P[i]) != CGAL::COPLANAR) i3 = i;
    if (i3 < 0)
      throw ShapeError(w.head + ": all " + std::to_string(n) +
                       " vertices are coplanar (zero volume)");

    Mesh &sm = h.sm;
    try {
      CGAL::convex_hull_3(P.begin(), P.end(), sm);
    } catch (const std::exception &e) {
      throw ShapeError(w.src + ": convex hull failed: " + e.what());
    }
    std::map<Pt, int> index_of;
    for (int i = 0; i < n; ++i) index_of[pts[i]] = i;
    h.vid = sm.add_property_map<Mesh::Vertex_index, int>("v:input", -1).first;
    h.on_hull.assign(n, 0);
    for (auto v : sm.vertices()) {
      const P3 &p = sm.point(v);
      auto it = index_of.find(Pt{p.x(), p.y(), p.z()});
      if (it == index_of.end())
        throw ShapeError(w.src + ": internal error: hull vertex not in input");
      h.vid[v] = it->second;
      h.on_hull[it->second] = 1;
    }
    for (auto f : sm.faces()) {
      std::array<int, 3> t;
      int k = 0;
      for (auto v : CGAL::vertices_around_face(sm.halfedge(f), sm)) {
        if (k == 3) throw ShapeError(w.src + ": internal error: hull face is not a triangle");
        t[k++] = h.vid[v];
      }
      h.tri_in.push_back(t);
      h.fidx.push_back(f);
    }
    for (size_t k = 0; k < h.fidx.size(); ++k) h.tri_of[h.fidx[k]] = (int) k;
    for (const auto &t : h.tri_in)
      h.tnorm.push_back(vunit(vcross(vsub(pts[t[1]], pts[t[0]]), vsub(pts[t[2]], pts[t[0]]))));
  }

  // Phase 3a, convexity of the points: input points that are not hull
  // corners, on the surface (e.g. a fan centre of a triangulated cap), are
  // simply not corners; strictly inside, the input was not convex (an
  // error, or a warning with the 'hull' option).
  void check_interior(const std::vector<Pt> &pts, const Hull &h, long double tol, bool hull,
                      const Where &w, std::vector<std::string> &warnings)
  {
    const int n = (int) pts.size();
    int ninterior = 0, first_interior = -1;
    for (int i = 0; i < n; ++i) {
      if (h.on_hull[i]) continue;
      long double dmax = -1e300L;
      for (size_t f = 0; f < h.tri_in.size(); ++f)
        dmax = std::max(dmax, vdot(h.tnorm[f], vsub(pts[i], pts[h.tri_in[f][0]])));
      if (dmax < -tol) {
        if (first_interior < 0) first_interior = i;
        ++ninterior;
      }
    }
    if (ninterior > 0) {
      std::string what = w.vat(first_interior) + ": vertex " + std::to_string(first_interior) +
          " lies inside the convex hull of the other vertices";
      if (!hull)
        throw ShapeError(what +
                         ": the shape is not convex (the 'hull' option uses its convex hull)");
      warnings.push_back(what + "; using the convex hull (" + std::to_string(ninterior) +
                         " interior vertices dropped)");
    }
  }

  // Phase 3b, the optional faces of the input: each must be a planar
  // polygon with all vertices on one side. They are only validated; the
  // stored faces are rebuilt from the hull.
  void check_faces(const std::vector<Pt> &pts, const std::vector<std::vector<int>> &faces,
                   long double tol, bool hull, const Where &w, std::vector<std::string> &warnings)
  {
    const int n = (int) pts.size();
    bool face_warned = false;
    for (size_t f = 0; f < faces.size(); ++f) {
      const auto &loop = faces[f];
      std::vector<int> s = loop;
      std::sort(s.begin(), s.end());
      if (std::adjacent_find(s.begin(), s.end()) != s.end())
        throw ShapeError(w.fat((int) f) + ": face repeats a vertex index");
      V3 nn = newell(pts, loop);
      long double len = std::sqrt(vdot(nn, nn));
      if (!(len > 0)) throw ShapeError(w.fat((int) f) + ": face has zero area");
      nn = vunit(nn);
      long double d0 = vdot(nn, vsub(pts[loop[0]], pts[0]));
      for (int k : loop)
        if (std::fabs(vdot(nn, vsub(pts[k], pts[0])) - d0) > tol)
          throw ShapeError(w.fat((int) f) + ": face is not planar (vertex " + std::to_string(k) +
                           ")");
      long double smin = 0, smax = 0;
      for (int i = 0; i < n; ++i) {
        long double sd = vdot(nn, vsub(pts[i], pts[0])) - d0;
        smin = std::min(smin, sd);
        smax = std::max(smax, sd);
      }
      if (smax > tol && smin < -tol) {
        std::string what = w.fat((int) f) + ": vertices lie on both sides of this face";
        if (!hull)
          throw ShapeError(what +
                           ": the shape is not convex (the 'hull' option uses its convex hull)");
        if (!face_warned) warnings.push_back(what + "; faces ignored, using the convex hull");
        face_warned = true;
      }
    }
  }

  // Phase 4, corners: hull corners renumbered in input order, at most
  // MAX_TEMPLATE_VERTS. Corners closer than the coplanarity tolerance would
  // make face merging ambiguous: reported rather than left to produce
  // sliver faces.
  Corners hull_corners(const std::vector<Pt> &pts, const Hull &h, long double tol, const Where &w)
  {
    const int n = (int) pts.size();
    Corners c;
    c.newid.assign(n, -1);
    for (int i = 0; i < n; ++i)
      if (h.on_hull[i]) {
        c.newid[i] = (int) c.hv.size();
        c.hv.push_back(pts[i]);
      }
    const int nh = (int) c.hv.size();
    if (nh > MAX_TEMPLATE_VERTS)
      throw ShapeError(w.src + ": the hull has " + std::to_string(nh) + " vertices, more than " +
                       "MAX_TEMPLATE_VERTS = " + std::to_string(MAX_TEMPLATE_VERTS));
    for (int a = 0; a < nh; ++a)
      for (int b = a + 1; b < nh; ++b) {
        V3 d = vsub(c.hv[a], c.hv[b]);
        if (std::sqrt(vdot(d, d)) <= tol) {
          int ia = -1, ib = -1;
          for (int i = 0; i < n; ++i) {
            if (c.newid[i] == a) ia = i;
            if (c.newid[i] == b) ib = i;
          }
          throw ShapeError(w.vat(ib) + ": vertex " + std::to_string(ib) + " is within " +
                           fmt_num((double) std::sqrt(vdot(d, d))) + " of vertex " +
                           std::to_string(ia) + ", closer than " + fmt_num(PLANE_TOL) +
                           " times the size of the shape");
        }
      }
    for (const auto &t : h.tri_in) c.tri.push_back({c.newid[t[0]], c.newid[t[1]], c.newid[t[2]]});
    return c;
  }

  // Phase 5a, coplanar hull triangles grouped into faces by a flood fill
  // over shared edges, before any rotation: exact coplanarity test first,
  // the tolerance only for rounded irrational coordinates. Returns the
  // number of groups, at most MAX_TEMPLATE_FACES; group[t] is triangle t's.
  int coplanar_groups(const std::vector<Pt> &pts, const Hull &h, long double tol, const Where &w,
                      std::vector<int> &group)
  {
    const Mesh &sm = h.sm;
    group.assign(h.tri_in.size(), -1);
    int ngroups = 0;
    for (size_t seed = 0; seed < h.tri_in.size(); ++seed) {
      if (group[seed] >= 0) continue;
      group[seed] = ngroups;
      std::vector<int> stack = {(int) seed};
      while (!stack.empty()) {
        int t = stack.back();
        stack.pop_back();
        const auto &a = h.tri_in[t];
        for (auto he : CGAL::halfedges_around_face(sm.halfedge(h.fidx[t]), sm)) {
          auto ho = sm.opposite(he);
          int u = h.tri_of.at(sm.face(ho));
          if (group[u] >= 0) continue;
          int v = h.vid[sm.target(sm.next(ho))];    // vertex of u not on the shared edge
          bool flat =
              CGAL::orientation(h.P[a[0]], h.P[a[1]], h.P[a[2]], h.P[v]) == CGAL::COPLANAR ||
              std::fabs(vdot(h.tnorm[t], vsub(pts[v], pts[a[0]]))) <= tol;
          if (flat) {
            group[u] = ngroups;
            stack.push_back(u);
          }
        }
      }
      ++ngroups;
    }
    if (ngroups > MAX_TEMPLATE_FACES)
      throw ShapeError(w.src + ": the hull has " + std::to_string(ngroups) + " faces, more than " +
                       "MAX_TEMPLATE_FACES = " + std::to_string(MAX_TEMPLATE_FACES));
    return ngroups;
  }

  // Phase 5b, face loops: the boundary half-edges of each group, walked in
  // mesh order (CGAL's hull faces are counter-clockwise seen from outside),
  // in corner numbering. Canonical order (CGAL's face order is not
  // guaranteed reproducible): each loop starts at its smallest vertex,
  // loops sorted lexicographically.
  std::vector<std::vector<int>> face_loops(const Hull &h, const std::vector<int> &group,
                                           int ngroups, const std::vector<int> &newid,
                                           const Where &w)
  {
    const Mesh &sm = h.sm;
    std::vector<std::vector<int>> loops(ngroups);
    std::vector<std::map<int, int>> next_of(ngroups);
    for (size_t t = 0; t < h.tri_in.size(); ++t)
      for (auto he : CGAL::halfedges_around_face(sm.halfedge(h.fidx[t]), sm)) {
        int u = h.tri_of.at(sm.face(sm.opposite(he)));
        if (group[u] == group[t]) continue;
        int a = newid[h.vid[sm.source(he)]], b = newid[h.vid[sm.target(he)]];
        if (!next_of[group[t]].emplace(a, b).second)
          throw ShapeError(w.src +
                           ": face merging failed: a merged face is not a simple polygon "
                           "(features below the coplanarity tolerance?)");
      }
    for (int g = 0; g < ngroups; ++g) {
      auto &nx = next_of[g];
      int start = nx.begin()->first, v = start;    // smallest vertex index first
      do {
        loops[g].push_back(v);
        const auto it = nx.find(v);
        if (it == nx.end())
          throw ShapeError(w.src +
                           ": degenerate hull: a merged face boundary is open (the shape is "
                           "thinner than the coplanarity tolerance " +
                           fmt_num(PLANE_TOL) + " times its size: a sliver?)");
        v = it->second;
      } while (v != start && loops[g].size() <= nx.size());
      if (loops[g].size() != nx.size())
        throw ShapeError(w.src +
                         ": face merging failed: a merged face boundary is not one loop "
                         "(features below the coplanarity tolerance?)");
    }
    std::sort(loops.begin(), loops.end());
    return loops;
  }

}    // namespace

void PolyShapeTemplate::build(const std::vector<Point> &pts,
                              const std::vector<std::vector<int>> &faces,
                              const std::vector<int> &vlines, const std::vector<int> &flines,
                              int vkey, const ShapeOptions &opt)
{
  const std::string src = file_.empty() ? name_ : file_;
  const Where w{src, vkey > 0 ? src + ":" + std::to_string(vkey) : src, vlines, flines};
  warnings_.clear();
  input_ = pts;

  const long double tol = check_points(pts, w);
  Hull h;
  convex_hull(pts, w, h);
  ntri_ = (int) h.tri_in.size();
  check_interior(pts, h, tol, opt.hull, w, warnings_);
  check_faces(pts, faces, tol, opt.hull, w, warnings_);
  const Corners c = hull_corners(pts, h, tol, w);
  std::vector<int> group;
  const int ngroups = coplanar_groups(pts, h, tol, w, group);
  const std::vector<std::vector<int>> loops = face_loops(h, group, ngroups, c.newid, w);

  const std::vector<Point> bv = principal_frame(c.hv, c.tri, w.head);
  set_mass_properties(bv, c.tri, w.head);
  set_faces(bv, loops, src);
  make_float_copy();
}

}    // namespace polydem
