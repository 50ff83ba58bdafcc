/* ----------------------------------------------------------------------
   POLYDEM - host-side convex shape template (seed polyhedral 2.1):
   reading shape files (PolyShapeTemplate::from_file). File format and
   conventions: doc/Howto_polyhedron_shapes.rst. The points and faces read
   go to build() (polydem_shape_hull.cpp) with their line numbers.
------------------------------------------------------------------------- */

#include "polydem_shape_template.h"

#include "polydem_shape_template_impl.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace polydem {

using namespace shape_impl;

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
      const bool verts = key == "vertices";
      int &first = verts ? vkey : fkey;
      if (first)
        throw ShapeError(where + ": second '" + key + "' section (first at line " +
                         std::to_string(first) + ")");
      first = lineno;
      (verts ? nv_expect : nf_expect) = n;
      mode = verts ? VERTS : FACES;
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

}    // namespace polydem
