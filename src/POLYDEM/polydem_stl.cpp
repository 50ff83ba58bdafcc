/* ----------------------------------------------------------------------
   POLYDEM - STL reader and mesh bin grid (host only), see polydem_stl.h
------------------------------------------------------------------------- */

#include "polydem_stl.h"

#include "polydem_mesh_grid.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>

#include <sys/stat.h>

namespace polydem {

namespace {

  std::string fmt_line(const std::string &path, long line, const std::string &why)
  {
    return path + ":" + std::to_string(line) + ": " + why;
  }

  struct Collector {
    const std::string &path;
    const StlTransform &xf;
    StlMesh &mesh;
    std::set<std::array<double, 9>> seen;

    // raw triangle (9 values) -> transformed, checked, deduplicated; the
    // file's facet normal (nrm, may be zero) is only compared with the
    // vertex order
    void add(const double *raw, const double *nrm, const std::string &where)
    {
      mesh.nread++;
      for (int k = 0; k < 9; k++)
        if (!std::isfinite(raw[k]))
          throw StlError(where + ": non-finite coordinate (NaN or Inf) in a triangle vertex");
      double p[3][3];
      for (int v = 0; v < 3; v++) {
        const double *q = raw + 3 * v;
        for (int d = 0; d < 3; d++)
          p[v][d] =
              xf.offset[d] + xf.scale * (xf.R[d][0] * q[0] + xf.R[d][1] * q[1] + xf.R[d][2] * q[2]);
      }
      for (int v = 0; v < 3; v++)
        for (int d = 0; d < 3; d++)
          if (!std::isfinite(p[v][d]))
            throw StlError(where + ": coordinate not finite after scale, rotate and offset");
      if (xf.flip) std::swap(p[1], p[2]);
      double e1[3], e2[3], e3[3];
      for (int d = 0; d < 3; d++) {
        e1[d] = p[1][d] - p[0][d];
        e2[d] = p[2][d] - p[0][d];
        e3[d] = p[2][d] - p[1][d];
      }
      const double cx = e1[1] * e2[2] - e1[2] * e2[1];
      const double cy = e1[2] * e2[0] - e1[0] * e2[2];
      const double cz = e1[0] * e2[1] - e1[1] * e2[0];
      const double n2 = cx * cx + cy * cy + cz * cz;
      auto l2 = [](const double *e) {
        return e[0] * e[0] + e[1] * e[1] + e[2] * e[2];
      };
      const double lmax = std::max(l2(e1), std::max(l2(e2), l2(e3)));
      if (!std::isfinite(n2) || !std::isfinite(lmax))
        throw StlError(where +
                       ": triangle too large (its area overflows) after scale, rotate "
                       "and offset");
      // |cross| = 2 area; zero area relative to the longest edge squared
      if (!(std::sqrt(n2) > 1e-12 * lmax)) {
        mesh.ndegenerate++;
        return;
      }
      // stored normal (rotated like the vertices) against the vertex order
      double sn[3];
      for (int d = 0; d < 3; d++)
        sn[d] = xf.R[d][0] * nrm[0] + xf.R[d][1] * nrm[1] + xf.R[d][2] * nrm[2];
      const double sd = sn[0] * cx + sn[1] * cy + sn[2] * cz;
      const double sl = std::sqrt(sn[0] * sn[0] + sn[1] * sn[1] + sn[2] * sn[2]);
      if (std::isfinite(sd) && sl > 0.0) {
        if (sd < -0.5 * sl * std::sqrt(n2))
          mesh.nopposite++;
        else if (sd > 0.5 * sl * std::sqrt(n2))
          mesh.nalong++;
      }
      // duplicate: same vertex set, whatever the order or orientation
      std::array<std::array<double, 3>, 3> s = {
          {{p[0][0], p[0][1], p[0][2]}, {p[1][0], p[1][1], p[1][2]}, {p[2][0], p[2][1], p[2][2]}}};
      std::sort(s.begin(), s.end());
      std::array<double, 9> key;
      for (int v = 0; v < 3; v++)
        for (int d = 0; d < 3; d++) key[3 * v + d] = s[v][d];
      if (!seen.insert(key).second) {
        mesh.nduplicate++;
        return;
      }
      for (int v = 0; v < 3; v++)
        for (int d = 0; d < 3; d++) mesh.tri.push_back(p[v][d]);
    }
  };

  bool parse_double(const std::string &tok, double &out)
  {
    if (tok.empty()) return false;
    errno = 0;
    char *end = nullptr;
    out = std::strtod(tok.c_str(), &end);
    return end && *end == '\0';
  }

  void read_ascii(const std::string &path, const std::string &data, Collector &col)
  {
    std::istringstream in(data);
    std::string line;
    long lineno = 0;
    // states: 0 outside solid, 1 in solid, 2 after facet, 3 in loop (nv vertices)
    int state = 0, nv = 0;
    double raw[9], nrm[3] = {0.0, 0.0, 0.0};
    long facet_line = 0;
    auto bad = [&](const std::string &why) {
      throw StlError(fmt_line(path, lineno, why));
    };
    while (std::getline(in, line)) {
      lineno++;
      std::istringstream ls(line);
      std::vector<std::string> w;
      std::string t;
      while (ls >> t) {    // keywords in any case (SOLID, Facet, ...)
        if (!t.empty() && std::isalpha((unsigned char) t[0]))
          for (char &c : t) c = (char) std::tolower((unsigned char) c);
        w.push_back(t);
      }
      if (w.empty()) continue;
      const std::string &k = w[0];
      if (state == 0) {
        if (k != "solid")
          bad(col.mesh.nread == 0 ? "expected 'solid', got '" + k + "'"
                                  : "expected 'solid' or the end of the file, got '" + k + "'");
        state = 1;
      } else if (state == 1) {
        if (k == "endsolid") {
          state = 0;
        } else if (k == "facet") {
          if (w.size() != 5 || w[1] != "normal") bad("expected 'facet normal nx ny nz'");
          for (int i = 2; i < 5; i++)
            if (!parse_double(w[i], nrm[i - 2])) bad("bad number '" + w[i] + "' in facet normal");
          state = 2;
          facet_line = lineno;
        } else
          bad("expected 'facet' or 'endsolid', got '" + k + "'");
      } else if (state == 2) {
        if (k != "outer" || w.size() != 2 || w[1] != "loop") bad("expected 'outer loop'");
        state = 3;
        nv = 0;
      } else if (state == 3) {
        if (k == "vertex") {
          if (w.size() != 4) bad("expected 'vertex x y z'");
          if (nv >= 3) bad("more than 3 vertices in a facet");
          for (int i = 0; i < 3; i++)
            if (!parse_double(w[i + 1], raw[3 * nv + i]))
              bad("bad number '" + w[i + 1] + "' in vertex");
          nv++;
        } else if (k == "endloop") {
          if (nv != 3) bad("facet has " + std::to_string(nv) + " vertices, expected 3");
          state = 4;
        } else
          bad("expected 'vertex' or 'endloop', got '" + k + "'");
      } else if (state == 4) {
        if (k != "endfacet") bad("expected 'endfacet', got '" + k + "'");
        col.add(raw, nrm, fmt_line(path, facet_line, "facet"));
        state = 1;
      }
    }
    if (state != 0 && !(state == 1 && col.mesh.nread > 0))
      throw StlError(fmt_line(path, lineno,
                              "unexpected end of file (missing 'endfacet' or "
                              "'endsolid')"));
    col.mesh.no_endsolid = state == 1;    // complete facets, then the end: warned
  }

  void read_binary(const std::string &path, const std::string &data, Collector &col)
  {
    if (data.size() < 84)
      throw StlError(path + ": truncated binary STL: " + std::to_string(data.size()) +
                     " bytes, the header alone has 84");
    uint32_t n = 0;
    std::memcpy(&n, data.data() + 80, 4);    // little-endian hosts (x86, arm64)
    const unsigned long long need = 84ULL + 50ULL * n;
    if (data.size() < need)
      throw StlError(path + ": truncated binary STL: header announces " + std::to_string(n) +
                     " triangles (" + std::to_string(need) + " bytes), file has " +
                     std::to_string(data.size()) + " bytes");
    col.mesh.trailing = (long) (data.size() - need);
    for (uint32_t t = 0; t < n; t++) {
      const char *rec = data.data() + 84 + 50ULL * t;
      float f[12];
      std::memcpy(f, rec, 48);
      double nrm[3], raw[9];
      for (int k = 0; k < 3; k++) nrm[k] = f[k];
      for (int k = 0; k < 9; k++) raw[k] = f[3 + k];
      col.add(raw, nrm, path + ": triangle " + std::to_string(t + 1));
    }
  }

}    // namespace

// does the text begin (after white space) with "solid", in any case?
static bool starts_solid(const std::string &data)
{
  const size_t p = data.find_first_not_of(" \t\r\n");
  if (p == std::string::npos || data.size() < p + 5) return false;
  for (int k = 0; k < 5; k++)
    if (std::tolower((unsigned char) data[p + k]) != "solid"[k]) return false;
  return true;
}

StlMesh read_stl(const std::string &path, const StlTransform &xf)
{
  // a directory opens as a stream and then fails while being read (an
  // uncaught std::ios_failure); devices and FIFOs may never end
  struct stat st;
  if (stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode))
    throw StlError(
        path + ": cannot read: " + (S_ISDIR(st.st_mode) ? "is a directory" : "not a regular file"));
  std::ifstream f(path, std::ios::binary);
  if (!f) throw StlError(path + ": cannot open file: " + std::strerror(errno));
  std::string data;
  try {
    data.assign(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
  } catch (std::exception &e) {
    throw StlError(path + ": cannot read: " + e.what());
  }
  if (data.empty()) throw StlError(path + ": empty file");
  if (!(xf.scale > 0.0) || !std::isfinite(xf.scale)) throw StlError(path + ": scale must be > 0");

  StlMesh mesh;
  Collector col{path, xf, mesh, {}};
  // Binary files may also begin with "solid": binary if the size matches the
  // announced triangle count exactly; ASCII if it starts with "solid".
  bool binary = true;
  if (data.size() >= 84) {
    uint32_t n = 0;
    std::memcpy(&n, data.data() + 80, 4);
    const bool size_ok = data.size() == 84ULL + 50ULL * n;
    // a text file has no NUL bytes; a binary one whose header says "solid"
    // and that has trailing bytes does
    const bool nul = data.find('\0') != std::string::npos;
    binary = size_ok || !starts_solid(data) || nul;
  } else {
    binary = !starts_solid(data);
  }
  mesh.binary = binary;
  if (binary)
    read_binary(path, data, col);
  else
    read_ascii(path, data, col);
  if (mesh.ntri() == 0)
    throw StlError(path + ": empty mesh (" + std::to_string(mesh.nread) + " triangles read, " +
                   std::to_string(mesh.ndegenerate) + " zero-area and " +
                   std::to_string(mesh.nduplicate) + " duplicates dropped)");
  if (mesh.ntri() > MESH_MAX_TRIANGLES)
    throw StlError(path + ": " + std::to_string(mesh.ntri()) + " triangles, more than the " +
                   std::to_string(MESH_MAX_TRIANGLES) + " a mesh may have");
  return mesh;
}

MeshGrid build_mesh_grid(const std::vector<double> &tri, double h, long max_bins)
{
  MeshGrid g;
  const int nt = (int) (tri.size() / 9);
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for (size_t k = 0; k < tri.size(); k++) {
    lo[k % 3] = std::min(lo[k % 3], tri[k]);
    hi[k % 3] = std::max(hi[k % 3], tri[k]);
  }
  if (!(h > 0.0) || !std::isfinite(h)) h = 1.0;
  // at most max_bins bins and max_entries list entries (each triangle in
  // every bin of its box), counted in double so that a tiny h cannot overflow
  const double max_entries = double(1L << 28);
  for (;;) {
    double nb = 1.0, n[3];
    for (int d = 0; d < 3; d++) {
      n[d] = std::max(1.0, std::ceil((hi[d] - lo[d]) / h));
      nb *= n[d];
    }
    if (nb <= double(max_bins)) {
      double entries = 0.0;
      for (int t = 0; t < nt && entries <= max_entries; t++) {
        double nt_bins = 1.0;
        for (int d = 0; d < 3; d++) {
          const double *p = tri.data() + 9 * (size_t) t;
          const double a = std::min(p[d], std::min(p[3 + d], p[6 + d]));
          const double b = std::max(p[d], std::max(p[3 + d], p[6 + d]));
          nt_bins *= std::floor((b - lo[d]) / h) - std::floor((a - lo[d]) / h) + 1.0;
        }
        entries += nt_bins;
      }
      if (entries <= max_entries) {
        for (int d = 0; d < 3; d++) g.n[d] = (int) n[d];
        break;
      }
    }
    h *= 1.25;
  }
  for (int d = 0; d < 3; d++) g.lo[d] = lo[d];
  g.h = h;
  const long nbins = (long) g.n[0] * g.n[1] * g.n[2];
  MeshGridView<double> v;
  v.tri = tri.data();
  v.ntri = nt;
  for (int d = 0; d < 3; d++) {
    v.lo[d] = g.lo[d];
    v.n[d] = g.n[d];
  }
  v.h = g.h;
  g.plane.resize(4 * (size_t) nt);
  g.box.resize(6 * (size_t) nt);
  g.sphere.resize(4 * (size_t) nt);
  for (int t = 0; t < nt; t++) {
    const double *p = tri.data() + 9 * (size_t) t;
    const double e1[3] = {p[3] - p[0], p[4] - p[1], p[5] - p[2]};
    const double e2[3] = {p[6] - p[0], p[7] - p[1], p[8] - p[2]};
    double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                   e1[0] * e2[1] - e1[1] * e2[0]};
    const double l = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (int d = 0; d < 3; d++) n[d] /= l;
    for (int d = 0; d < 3; d++) g.plane[4 * t + d] = n[d];
    g.plane[4 * t + 3] = n[0] * p[0] + n[1] * p[1] + n[2] * p[2];
    for (int d = 0; d < 3; d++) {
      g.box[6 * t + d] = std::min(p[d], std::min(p[3 + d], p[6 + d]));
      g.box[6 * t + 3 + d] = std::max(p[d], std::max(p[3 + d], p[6 + d]));
    }
    // bounding sphere: the centroid and its largest distance to a vertex
    double *sp = &g.sphere[4 * (size_t) t], r2 = 0.0;
    for (int d = 0; d < 3; d++) sp[d] = (p[d] + p[3 + d] + p[6 + d]) / 3.0;
    for (int v = 0; v < 3; v++) {
      double q = 0.0;
      for (int d = 0; d < 3; d++) q += (p[3 * v + d] - sp[d]) * (p[3 * v + d] - sp[d]);
      r2 = std::max(r2, q);
    }
    sp[3] = std::sqrt(r2);
  }
  v.plane = g.plane.data();
  v.box = g.box.data();
  std::vector<int> count(nbins + 1, 0);
  for (int pass = 0; pass < 2; pass++) {
    for (int t = 0; t < nt; t++) {
      int blo[3], bhi[3];
      mesh_tri_bins(v, t, blo, bhi);
      for (int k = blo[2]; k <= bhi[2]; k++)
        for (int j = blo[1]; j <= bhi[1]; j++)
          for (int i = blo[0]; i <= bhi[0]; i++) {
            const int b = mesh_bin_id<double>(g.n, i, j, k);
            if (pass == 0)
              count[b + 1]++;
            else
              g.items[g.start[b] + count[b]++] =
                  mesh_item(t, (i == blo[0]) | (j == blo[1]) << 1 | (k == blo[2]) << 2);
          }
    }
    if (pass == 0) {
      g.start.assign(nbins + 1, 0);
      for (long b = 0; b < nbins; b++) g.start[b + 1] = g.start[b] + count[b + 1];
      g.items.assign(g.start[nbins], 0);
      std::fill(count.begin(), count.end(), 0);
    }
  }
  return g;
}

}    // namespace polydem
