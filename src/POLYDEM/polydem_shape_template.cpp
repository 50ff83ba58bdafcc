/* ----------------------------------------------------------------------
   POLYDEM - host-side convex shape template (seed polyhedral 2.1).
   File format and conventions: doc/Howto_polyhedron_shapes.rst.

   Exactness: input coordinates are doubles, hence exact rationals. Hull
   predicates are exact (Epick filtered predicates); volume, first and
   second moments are summed over the hull's tetrahedra in exact rational
   arithmetic and rounded once. Only the principal-axis rotation (Jacobi,
   long double) and the final rounding of rotated vertices are inexact.
------------------------------------------------------------------------- */

#include "polydem_shape_template.h"

#include "polydem_dual_seed.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>

namespace polydem {

namespace {

  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using P3 = K::Point_3;
  using Mesh = CGAL::Surface_mesh<P3>;
  using Q = CGAL::Exact_rational;
  using Pt = PolyShapeTemplate::Point;

  // Relative tolerance (times the template diameter, length units) for
  // "this point lies in that plane" when exact coplanarity fails only
  // because irrational coordinates were rounded to double (e.g. the
  // dodecahedron's golden ratio). Rounding errors are ~1e-16.
  constexpr double PLANE_TOL = 1e-10;
  // Relative tolerance on principal moments below which two moments are
  // treated as equal (degenerate axes: see choose_axes()). Round-off splits
  // truly equal moments by ~1e-15; keeping input axes for a split below
  // 1e-11 leaves products of inertia below 1e-11 of the largest moment.
  constexpr double MOMENT_TOL = 1e-11;
  // Sizes (length units) a template may have: its volume ~ size^3 and moments
  // ~ size^5 must be normal doubles, and CGAL's exact arithmetic (GMP) dies
  // with SIGFPE on degree-5 products that overflow a double (coordinates
  // above ~1e61). Coordinates may lie at most SHAPE_OFFSET_MAX sizes from the
  // origin (beyond, the body frame loses every digit of the shape).
  constexpr double SHAPE_SIZE_MIN = 1e-50, SHAPE_SIZE_MAX = 1e50, SHAPE_OFFSET_MAX = 1e12;

  std::string fmt_num(double x)
  {
    std::ostringstream os;
    os.precision(17);
    os << x;
    return os.str();
  }

  // ---------------------------------------------------------------------
  // Exact mass properties of a closed, outward-oriented triangle surface:
  // sum over tetrahedra (0,a,b,c): det = a.(b x c), V = det/6,
  // int x_i = det/24 s_i, int x_i x_j = det/120 (sum_v v_i v_j + s_i s_j),
  // s = a+b+c (standard tetrahedron moment formulas).
  // ---------------------------------------------------------------------
  struct Moments {
    Q vol6, m1_24[3], m2_120[3][3];    // 6V, 24 int x, 120 int x x^T
  };

  Moments exact_moments(const std::vector<Pt> &v, const std::vector<std::array<int, 3>> &tris)
  {
    Moments m;
    m.vol6 = 0;
    for (int i = 0; i < 3; ++i) {
      m.m1_24[i] = 0;
      for (int j = 0; j < 3; ++j) m.m2_120[i][j] = 0;
    }
    for (const auto &t : tris) {
      Q a[3], b[3], c[3], s[3];
      for (int i = 0; i < 3; ++i) {
        a[i] = v[t[0]][i];
        b[i] = v[t[1]][i];
        c[i] = v[t[2]][i];
        s[i] = a[i] + b[i] + c[i];
      }
      Q det = a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
          a[2] * (b[0] * c[1] - b[1] * c[0]);
      m.vol6 += det;
      for (int i = 0; i < 3; ++i) {
        m.m1_24[i] += det * s[i];
        for (int j = i; j < 3; ++j)
          m.m2_120[i][j] += det * (a[i] * a[j] + b[i] * b[j] + c[i] * c[j] + s[i] * s[j]);
      }
    }
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < i; ++j) m.m2_120[i][j] = m.m2_120[j][i];
    return m;
  }

  // Volume, centroid and inertia tensor (per unit density, about the centroid).
  void mass_properties(const Moments &m, double &vol, Pt &cen, double inertia[3][3])
  {
    Q V = m.vol6 / 6;
    Q c[3], S[3][3];
    for (int i = 0; i < 3; ++i) c[i] = m.m1_24[i] / 24 / V;
    // central second moments S = int x x^T - V c c^T, then I = tr(S) 1 - S
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) S[i][j] = m.m2_120[i][j] / 120 - V * c[i] * c[j];
    Q tr = S[0][0] + S[1][1] + S[2][2];
    vol = CGAL::to_double(V);
    for (int i = 0; i < 3; ++i) {
      cen[i] = CGAL::to_double(c[i]);
      for (int j = 0; j < 3; ++j) inertia[i][j] = CGAL::to_double((i == j ? tr : Q(0)) - S[i][j]);
    }
  }

  // Cyclic Jacobi eigen-decomposition of a symmetric 3x3 matrix.
  // Columns of e are the eigenvectors.
  void jacobi3(const double a_in[3][3], long double w[3], long double e[3][3])
  {
    long double a[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        a[i][j] = a_in[i][j];
        e[i][j] = (i == j);
      }
    for (int sweep = 0; sweep < 60; ++sweep) {
      long double off = std::fabs(a[0][1]) + std::fabs(a[0][2]) + std::fabs(a[1][2]);
      if (off == 0.0L) break;
      for (int p = 0; p < 2; ++p)
        for (int q = p + 1; q < 3; ++q) {
          if (a[p][q] == 0.0L) continue;
          long double theta = (a[q][q] - a[p][p]) / (2.0L * a[p][q]);
          long double t =
              (theta >= 0 ? 1.0L : -1.0L) / (std::fabs(theta) + std::sqrt(theta * theta + 1.0L));
          long double c = 1.0L / std::sqrt(t * t + 1.0L), s = t * c;
          for (int k = 0; k < 3; ++k) {    // A <- A J
            long double akp = a[k][p], akq = a[k][q];
            a[k][p] = c * akp - s * akq;
            a[k][q] = s * akp + c * akq;
          }
          for (int k = 0; k < 3; ++k) {    // A <- J^T A
            long double apk = a[p][k], aqk = a[q][k];
            a[p][k] = c * apk - s * aqk;
            a[q][k] = s * apk + c * aqk;
          }
          for (int k = 0; k < 3; ++k) {
            long double ekp = e[k][p], ekq = e[k][q];
            e[k][p] = c * ekp - s * ekq;
            e[k][q] = s * ekp + c * ekq;
          }
        }
    }
    for (int i = 0; i < 3; ++i) w[i] = a[i][i];
  }

  using V3 = std::array<long double, 3>;
  V3 col(const long double e[3][3], int j)
  {
    return {e[0][j], e[1][j], e[2][j]};
  }
  V3 vcross(const V3 &a, const V3 &b)
  {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  }
  long double vdot(const V3 &a, const V3 &b)
  {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  }
  V3 vunit(const V3 &a)
  {
    long double n = std::sqrt(vdot(a, a));
    return {a[0] / n, a[1] / n, a[2] / n};
  }
  V3 sign_fix(V3 a)    // largest-magnitude component positive (first one on ties)
  {
    int k = 0;
    for (int i = 1; i < 3; ++i)
      if (std::fabs(a[i]) > std::fabs(a[k])) k = i;
    if (a[k] < 0) a = {-a[0], -a[1], -a[2]};
    return a;
  }
  // In the plane normal to u: the input axis most nearly in that plane
  // (lowest index on ties), projected. Keeps input axes where they are free.
  V3 plane_axis(const V3 &u)
  {
    int k = 0;
    for (int i = 1; i < 3; ++i)
      if (std::fabs(u[i]) < std::fabs(u[k]) - 1e-12L) k = i;
    V3 a = {0, 0, 0};
    a[k] = 1;
    long double d = u[k];
    return vunit({a[0] - d * u[0], a[1] - d * u[1], a[2] - d * u[2]});
  }

  // Principal axes as the columns of R (proper rotation), moments ascending.
  // Degenerate moments keep the input axes (see the Howto for the rules).
  void choose_axes(const double inertia[3][3], double rot[3][3])
  {
    long double w[3], e[3][3];
    jacobi3(inertia, w, e);
    int idx[3] = {0, 1, 2};
    std::sort(idx, idx + 3, [&](int a, int b) {
      return w[a] < w[b];
    });
    long double l0 = w[idx[0]], l1 = w[idx[1]], l2 = w[idx[2]];
    long double tol = MOMENT_TOL * std::fabs(l2);
    bool eq01 = l1 - l0 <= tol, eq12 = l2 - l1 <= tol;
    V3 c[3];
    if (eq01 && eq12) {
      c[0] = {1, 0, 0};
      c[1] = {0, 1, 0};
      c[2] = {0, 0, 1};
    } else if (eq01) {
      V3 u = sign_fix(col(e, idx[2]));
      c[0] = plane_axis(u);
      c[1] = vcross(u, c[0]);
      c[2] = u;
    } else if (eq12) {
      V3 u = sign_fix(col(e, idx[0]));
      c[0] = u;
      c[1] = plane_axis(u);
      c[2] = vcross(u, c[1]);
    } else {
      for (int j = 0; j < 3; ++j) c[j] = sign_fix(col(e, idx[j]));
      c[1] = vunit(c[1]);
      c[0] = vunit(c[0]);
      c[2] = vcross(c[0], c[1]);    // right-handed; agrees with e up to sign
    }
    // Snap to a signed permutation when that is what it is up to round-off,
    // so that axis-aligned input stays bit-exact.
    for (int j = 0; j < 3; ++j) {
      int k = 0;
      for (int i = 1; i < 3; ++i)
        if (std::fabs(c[j][i]) > std::fabs(c[j][k])) k = i;
      bool axis = true;
      for (int i = 0; i < 3; ++i)
        if (i != k && std::fabs(c[j][i]) > 1e-13L) axis = false;
      if (axis) {
        long double s = c[j][k] > 0 ? 1 : -1;
        c[j] = {0, 0, 0};
        c[j][k] = s;
      }
    }
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) rot[i][j] = (double) c[j][i];
  }

  V3 vsub(const Pt &a, const Pt &b)
  {
    return {(long double) a[0] - b[0], (long double) a[1] - b[1], (long double) a[2] - b[2]};
  }

  // Newell normal (area-weighted, not normalised) of a vertex loop.
  V3 newell(const std::vector<Pt> &v, const std::vector<int> &loop)
  {
    V3 n = {0, 0, 0};
    for (size_t i = 0; i < loop.size(); ++i) {
      const Pt &a = v[loop[i]], &b = v[loop[(i + 1) % loop.size()]];
      n[0] += ((long double) a[1] - b[1]) * ((long double) a[2] + b[2]);
      n[1] += ((long double) a[2] - b[2]) * ((long double) a[0] + b[0]);
      n[2] += ((long double) a[0] - b[0]) * ((long double) a[1] + b[1]);
    }
    return n;
  }

}    // namespace

// =====================================================================
// file reader
// =====================================================================

namespace {

  std::vector<std::string> tokens_of(const std::string &line)
  {
    std::string s = line.substr(0, line.find('#'));
    std::istringstream is(s);
    std::vector<std::string> t;
    std::string w;
    while (is >> w) t.push_back(w);
    return t;
  }

  double to_number(const std::string &tok, const std::string &where, const char *what)
  {
    const char *b = tok.c_str();
    char *end = nullptr;
    errno = 0;
    double x = std::strtod(b, &end);
    if (end == b || *end != '\0')
      throw ShapeError(where + ": " + what + " '" + tok + "' is not a number");
    if (!std::isfinite(x)) throw ShapeError(where + ": " + what + " '" + tok + "' is not finite");
    return x;
  }

  long to_int(const std::string &tok, const std::string &where, const char *what)
  {
    const char *b = tok.c_str();
    char *end = nullptr;
    errno = 0;
    long x = std::strtol(b, &end, 10);
    if (end == b || *end != '\0' || errno == ERANGE)
      throw ShapeError(where + ": " + what + " '" + tok + "' is not an integer");
    return x;
  }

}    // namespace

PolyShapeTemplate PolyShapeTemplate::from_file(const std::string &path, const ShapeOptions &opt)
{
  std::ifstream in(path);
  if (!in) throw ShapeError(path + ": cannot open file: " + std::strerror(errno));

  std::vector<Pt> pts;
  std::vector<int> vlines;
  std::vector<std::vector<int>> faces;
  std::vector<int> flines;
  double scale = 1.0;
  int vkey = 0, fkey = 0, skey = 0;
  long nv_expect = -1, nf_expect = -1;

  std::string line;
  int lineno = 0;
  enum { KEY, VERTS, FACES } mode = KEY;
  long left = 0;
  while (std::getline(in, line)) {
    ++lineno;
    auto t = tokens_of(line);
    if (t.empty()) continue;
    const std::string where = path + ":" + std::to_string(lineno);
    if (mode == VERTS) {
      if (t.size() != 3)
        throw ShapeError(where + ": expected 3 numbers, got " + std::to_string(t.size()));
      Pt p;
      for (int i = 0; i < 3; ++i) p[i] = to_number(t[i], where, "coordinate");
      pts.push_back(p);
      vlines.push_back(lineno);
      if (--left == 0) mode = KEY;
      continue;
    }
    if (mode == FACES) {
      if (t.size() < 3)
        throw ShapeError(where + ": a face needs at least 3 vertex indices, got " +
                         std::to_string(t.size()));
      std::vector<int> f;
      for (const auto &w : t) {
        long k = to_int(w, where, "vertex index");
        if (k < 0 || k > 1000000000L)
          throw ShapeError(where + ": vertex index " + w + " out of range");
        f.push_back((int) k);
      }
      faces.push_back(f);
      flines.push_back(lineno);
      if (--left == 0) mode = KEY;
      continue;
    }
    // keyword lines
    const std::string &key = t[0];
    if (key == "vertices" || key == "faces") {
      if (t.size() != 2)
        throw ShapeError(where + ": expected '" + key + " N', got " + std::to_string(t.size()) +
                         " words");
      long n = to_int(t[1], where, "count");
      if (n < 1) throw ShapeError(where + ": '" + key + "' count must be positive, got " + t[1]);
      if (key == "vertices") {
        if (vkey)
          throw ShapeError(where + ": second 'vertices' section (first at line " +
                           std::to_string(vkey) + ")");
        vkey = lineno;
        nv_expect = n;
        mode = VERTS;
      } else {
        if (fkey)
          throw ShapeError(where + ": second 'faces' section (first at line " +
                           std::to_string(fkey) + ")");
        fkey = lineno;
        nf_expect = n;
        mode = FACES;
      }
      left = n;
    } else if (key == "scale") {
      if (t.size() != 2)
        throw ShapeError(where + ": expected 'scale s', got " + std::to_string(t.size()) +
                         " words");
      if (skey)
        throw ShapeError(where + ": second 'scale' line (first at line " + std::to_string(skey) +
                         ")");
      skey = lineno;
      scale = to_number(t[1], where, "scale");
      if (!(scale > 0)) throw ShapeError(where + ": scale must be positive, got " + t[1]);
    } else {
      throw ShapeError(where + ": unknown keyword '" + key + "'");
    }
  }
  const std::string end = lineno > 0 ? path + ":" + std::to_string(lineno) : path;
  if (mode == VERTS)
    throw ShapeError(end + ": end of file after " + std::to_string(pts.size()) + " of " +
                     std::to_string(nv_expect) + " vertex lines");
  if (mode == FACES)
    throw ShapeError(end + ": end of file after " + std::to_string(faces.size()) + " of " +
                     std::to_string(nf_expect) + " face lines");
  if (!vkey) throw ShapeError(end + ": no 'vertices' section");

  for (size_t f = 0; f < faces.size(); ++f)
    for (int k : faces[f])
      if (k >= (int) pts.size())
        throw ShapeError(path + ":" + std::to_string(flines[f]) + ": vertex index " +
                         std::to_string(k) + " out of range 0.." + std::to_string(pts.size() - 1));

  const double s = scale * opt.scale;
  if (!(s > 0) || !std::isfinite(s)) throw ShapeError(path + ": scale must be positive and finite");
  for (auto &p : pts)
    for (double &x : p) {
      x *= s;
      if (!std::isfinite(x)) throw ShapeError(path + ": coordinate overflow after scaling");
    }

  PolyShapeTemplate st;
  st.file_ = path;
  auto slash = path.find_last_of('/');
  st.name_ = slash == std::string::npos ? path : path.substr(slash + 1);
  ShapeOptions o2 = opt;
  o2.scale = 1.0;
  st.build(pts, faces, vlines, flines, vkey, o2);
  return st;
}

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

// Phase 6, principal frame: exact volume, centroid and inertia of the hull
// in input coordinates; the centroid moves to the origin and the principal
// axes become the body axes (choose_axes). Sets centroid_ and rot_ and
// returns the body-frame corners p_body = R^T (p - c), rounded to double.
std::vector<PolyShapeTemplate::Point>
PolyShapeTemplate::principal_frame(const std::vector<Point> &hv,
                                   const std::vector<std::array<int, 3>> &tri,
                                   const std::string &head)
{
  double vol0, inertia0[3][3];
  Pt cen;
  mass_properties(exact_moments(hv, tri), vol0, cen, inertia0);
  if (!(vol0 > 0)) throw ShapeError(head + ": the hull has zero volume");
  centroid_ = cen;

  double R[3][3];
  choose_axes(inertia0, R);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) rot_[i][j] = R[i][j];

  std::vector<Pt> bv(hv.size());
  for (size_t k = 0; k < hv.size(); ++k) {
    V3 d = vsub(hv[k], cen);
    for (int j = 0; j < 3; ++j)
      bv[k][j] = (double) (R[0][j] * d[0] + R[1][j] * d[1] + R[2][j] * d[2]);
  }
  return bv;
}

// Phase 7, stored mass properties: volume and principal moments computed
// again, exactly, from the rounded body-frame vertices actually stored;
// the bounding radius about the centroid. Checked to be normal numbers.
void PolyShapeTemplate::set_mass_properties(const std::vector<Point> &bv,
                                            const std::vector<std::array<int, 3>> &tri,
                                            const std::string &head)
{
  double inertia[3][3];
  Pt c2;
  mass_properties(exact_moments(bv, tri), volume_, c2, inertia);
  for (int i = 0; i < 3; ++i) moments_[i] = inertia[i][i];

  verts_.clear();
  for (const auto &p : bv) verts_.insert(verts_.end(), p.begin(), p.end());
  radius_ = 0;
  for (const auto &p : bv)
    radius_ = std::max(radius_, std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]));

  check_mass_properties(head);
}

// Phase 8, faces, planes and edges: the loops as CSR face lists, each
// face's plane n.p = d (Newell normal of the body-frame loop, d the
// largest n.p over its vertices), edges sorted (a < b). Euler's formula
// V - E + F = 2 catches a merge that went wrong.
void PolyShapeTemplate::set_faces(const std::vector<Point> &bv,
                                  const std::vector<std::vector<int>> &loops,
                                  const std::string &src)
{
  face_start_.assign(1, 0);
  face_verts_.clear();
  planes_.clear();
  edges_.clear();
  for (const auto &loop : loops) {
    face_verts_.insert(face_verts_.end(), loop.begin(), loop.end());
    face_start_.push_back((int) face_verts_.size());
    V3 nn = vunit(newell(bv, loop));
    long double d = -1e300L;
    for (int k : loop) d = std::max(d, nn[0] * bv[k][0] + nn[1] * bv[k][1] + nn[2] * bv[k][2]);
    planes_.insert(planes_.end(), {(double) nn[0], (double) nn[1], (double) nn[2], (double) d});
    for (size_t k = 0; k < loop.size(); ++k) {
      int a = loop[k], b = loop[(k + 1) % loop.size()];
      if (a < b) edges_.insert(edges_.end(), {a, b});
    }
  }
  std::vector<std::array<int, 2>> es;
  for (size_t k = 0; k < edges_.size(); k += 2) es.push_back({edges_[k], edges_[k + 1]});
  std::sort(es.begin(), es.end());
  edges_.clear();
  for (const auto &e : es) edges_.insert(edges_.end(), {e[0], e[1]});
  if (nverts() - nedges() + nfaces() != 2)
    throw ShapeError(
        src + ": face merging failed: V - E + F != 2 (features below the coplanarity tolerance?)");
}

PolyShapeTemplate PolyShapeTemplate::ellipsoid(double a, double b, double c,
                                               const std::string &name)
{
  for (double v : {a, b, c})
    if (!(v > 0.0) || !std::isfinite(v))
      throw ShapeError(name + ": ellipsoid semi-axes must be positive and finite, got " +
                       std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(c));
  PolyShapeTemplate t;
  t.name_ = name;
  t.ellipsoid_ = true;
  t.axes_ = {a, b, c};
  t.face_start_ = {0};    // no faces, no vertices
  t.volume_ = 4.0 / 3.0 * M_PI * a * b * c;
  t.radius_ = std::max(a, std::max(b, c));
  t.moments_ = {t.volume_ * (b * b + c * c) / 5.0, t.volume_ * (a * a + c * c) / 5.0,
                t.volume_ * (a * a + b * b) / 5.0};
  t.check_mass_properties(name + ": ellipsoid " + fmt_num(a) + " " + fmt_num(b) + " " + fmt_num(c));
  return t;
}

// volume and principal moments must be finite, normal numbers (issue 17: a
// zero volume or moment gave NaN kinetic energy or silently dropped rotation)
void PolyShapeTemplate::check_mass_properties(const std::string &what) const
{
  bool ok = std::isnormal(volume_) && volume_ > 0.0 && std::isnormal(radius_);
  for (double m : moments_) ok = ok && std::isnormal(m) && m > 0.0;
  if (!ok)
    throw ShapeError(what + ": volume " + fmt_num(volume_) + " or principal moments " +
                     fmt_num(moments_[0]) + " " + fmt_num(moments_[1]) + " " +
                     fmt_num(moments_[2]) +
                     " are zero or not finite (size outside [1e-50, 1e50]?)");
}

void PolyShapeTemplate::make_float_copy()
{
  dual_ =
      build_dual_seed(nverts(), nfaces(), planes_.data(), face_start_.data(), face_verts_.data());
  vadj_ = build_vertex_adjacency(nverts(), nedges(), edges_.data());
  verts_f_.assign(verts_.begin(), verts_.end());
  planes_f_.assign(planes_.begin(), planes_.end());
}

std::vector<int> PolyShapeTemplate::face(int i) const
{
  return std::vector<int>(face_verts_.begin() + face_start_[i],
                          face_verts_.begin() + face_start_[i + 1]);
}

double PolyShapeTemplate::inradius() const
{
  if (ellipsoid_) return std::min(axes_[0], std::min(axes_[1], axes_[2]));
  double r = 1e300;
  for (int f = 0; f < nfaces(); f++) r = std::min(r, planes_[4 * f + 3]);
  return r;
}

double PolyShapeTemplate::max_face_area() const
{
  double amax = 0.0;
  for (int f = 0; f < nfaces(); f++) {
    double a[3] = {0.0, 0.0, 0.0};    // sum of p_k x p_k+1 = 2 area n
    for (int k = face_start_[f]; k < face_start_[f + 1]; k++) {
      const int next = k + 1 < face_start_[f + 1] ? k + 1 : face_start_[f];
      const double *p = &verts_[3 * face_verts_[k]], *q = &verts_[3 * face_verts_[next]];
      a[0] += p[1] * q[2] - p[2] * q[1];
      a[1] += p[2] * q[0] - p[0] * q[2];
      a[2] += p[0] * q[1] - p[1] * q[0];
    }
    amax = std::max(amax, 0.5 * std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]));
  }
  return amax;
}

template <typename T>
static ShapeView<T> make_view(int nv, int nf, int ne, const T *v, const T *pl, const int *fs,
                              const int *fv, const int *ed, double r, double vol,
                              const std::array<double, 3> &mom, const int *dual,
                              const int *vadj)
{
  ShapeView<T> s;
  s.nverts = nv;
  s.nfaces = nf;
  s.nedges = ne;
  s.verts = v;
  s.planes = pl;
  s.face_start = fs;
  s.face_verts = fv;
  s.edges = ed;
  s.radius = (T) r;
  s.volume = (T) vol;
  for (int i = 0; i < 3; ++i) s.inertia[i] = (T) mom[i];
  s.dual = dual;
  s.vadj = vadj;
  return s;
}

ShapeView<double> PolyShapeTemplate::view() const
{
  return make_view<double>(nverts(), nfaces(), nedges(), verts_.data(), planes_.data(),
                           face_start_.data(), face_verts_.data(), edges_.data(), radius_, volume_,
                           moments_, dual_.empty() ? nullptr : dual_.data(),
                           vadj_.empty() ? nullptr : vadj_.data());
}

ShapeView<float> PolyShapeTemplate::view_float() const
{
  return make_view<float>(nverts(), nfaces(), nedges(), verts_f_.data(), planes_f_.data(),
                          face_start_.data(), face_verts_.data(), edges_.data(), radius_, volume_,
                          moments_, dual_.empty() ? nullptr : dual_.data(),
                           vadj_.empty() ? nullptr : vadj_.data());
}

// rotation matrix -> unit quaternion (Shepperd's method: largest pivot)
Quat<double> PolyShapeTemplate::input_orientation() const
{
  const auto &m = rot_;
  double tr = m[0][0] + m[1][1] + m[2][2];
  double w, x, y, z;
  if (tr >= m[0][0] && tr >= m[1][1] && tr >= m[2][2]) {
    double s = 2.0 * std::sqrt(1.0 + tr);
    w = 0.25 * s;
    x = (m[2][1] - m[1][2]) / s;
    y = (m[0][2] - m[2][0]) / s;
    z = (m[1][0] - m[0][1]) / s;
  } else if (m[0][0] >= m[1][1] && m[0][0] >= m[2][2]) {
    double s = 2.0 * std::sqrt(1.0 + m[0][0] - m[1][1] - m[2][2]);
    w = (m[2][1] - m[1][2]) / s;
    x = 0.25 * s;
    y = (m[0][1] + m[1][0]) / s;
    z = (m[0][2] + m[2][0]) / s;
  } else if (m[1][1] >= m[2][2]) {
    double s = 2.0 * std::sqrt(1.0 + m[1][1] - m[0][0] - m[2][2]);
    w = (m[0][2] - m[2][0]) / s;
    x = (m[0][1] + m[1][0]) / s;
    y = 0.25 * s;
    z = (m[1][2] + m[2][1]) / s;
  } else {
    double s = 2.0 * std::sqrt(1.0 + m[2][2] - m[0][0] - m[1][1]);
    w = (m[1][0] - m[0][1]) / s;
    x = (m[0][2] + m[2][0]) / s;
    y = (m[1][2] + m[2][1]) / s;
    z = 0.25 * s;
  }
  if (w < 0) {
    w = -w;
    x = -x;
    y = -y;
    z = -z;
  }
  return qnormalize(make_quat(w, x, y, z));
}

}    // namespace polydem
