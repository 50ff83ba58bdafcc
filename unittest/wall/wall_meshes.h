// Test meshes for fix wall/mesh, written as STL files (ASCII or binary).
#ifndef POLYDEM_TEST_WALL_MESHES_H
#define POLYDEM_TEST_WALL_MESHES_H

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

namespace wall_test {

using Tris = std::vector<double>;    // 9 per triangle

inline void write_ascii(const std::string &path, const Tris &t)
{
  FILE *f = std::fopen(path.c_str(), "w");
  std::fprintf(f, "solid test\n");
  for (size_t k = 0; k + 8 < t.size(); k += 9) {
    std::fprintf(f, "  facet normal 0 0 0\n    outer loop\n");
    for (int v = 0; v < 3; v++)
      std::fprintf(f, "      vertex %.17g %.17g %.17g\n", t[k + 3 * v], t[k + 3 * v + 1],
                   t[k + 3 * v + 2]);
    std::fprintf(f, "    endloop\n  endfacet\n");
  }
  std::fprintf(f, "endsolid test\n");
  std::fclose(f);
}

inline void write_binary(const std::string &path, const Tris &t, long truncate_to = -1)
{
  std::string data(80, ' ');
  const uint32_t n = (uint32_t) (t.size() / 9);
  data.append((const char *) &n, 4);
  for (uint32_t i = 0; i < n; i++) {
    float rec[12] = {0, 0, 0};
    for (int k = 0; k < 9; k++) rec[3 + k] = (float) t[9 * i + k];
    data.append((const char *) rec, 48);
    data.append(2, '\0');
  }
  if (truncate_to >= 0) data.resize(truncate_to);
  FILE *f = std::fopen(path.c_str(), "wb");
  std::fwrite(data.data(), 1, data.size(), f);
  std::fclose(f);
}

// Flat rectangle [x0,x1] x [y0,y1] at z, facing +z, nx by ny cells split
// into two triangles each (diagonal alternating if alt); jitter moves the
// interior vertices by up to jitter * cell size (an irregular mesh).
inline Tris flat(double x0, double x1, double y0, double y1, double z, int nx, int ny,
                 bool alt = false, double jitter = 0.0, unsigned seed = 1)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double hx = (x1 - x0) / nx, hy = (y1 - y0) / ny;
  std::vector<double> px((nx + 1) * (ny + 1)), py(px.size());
  for (int j = 0; j <= ny; j++)
    for (int i = 0; i <= nx; i++) {
      double x = x0 + i * hx, y = y0 + j * hy;
      if (i > 0 && i < nx) x += jitter * hx * u(rng);
      if (j > 0 && j < ny) y += jitter * hy * u(rng);
      px[j * (nx + 1) + i] = x;
      py[j * (nx + 1) + i] = y;
    }
  Tris t;
  auto add = [&](int a, int b, int c) {
    for (int v : {a, b, c}) {
      t.push_back(px[v]);
      t.push_back(py[v]);
      t.push_back(z);
    }
  };
  for (int j = 0; j < ny; j++)
    for (int i = 0; i < nx; i++) {
      const int a = j * (nx + 1) + i, b = a + 1, c = a + nx + 1, d = c + 1;
      if (alt && ((i + j) % 2)) {
        add(a, b, c);
        add(b, d, c);
      } else {
        add(a, b, d);
        add(a, d, c);
      }
    }
  return t;
}

// Curved floor: the jittered flat mesh lifted onto the paraboloid
// z = z0 + ((x - cx)^2 + (y - cy)^2) / (2 Rc), facing up (no two facets coplanar).
inline Tris bowl(double x0, double x1, double y0, double y1, double z0, double Rc, int n,
                 unsigned seed = 5)
{
  Tris t = flat(x0, x1, y0, y1, 0.0, n, n, true, 0.2, seed);
  const double cx = 0.5 * (x0 + x1), cy = 0.5 * (y0 + y1);
  for (size_t k = 0; k < t.size(); k += 3)
    t[k + 2] = z0 + ((t[k] - cx) * (t[k] - cx) + (t[k + 1] - cy) * (t[k + 1] - cy)) / (2.0 * Rc);
  return t;
}

// An incline of theta (radians) about y: the point (x, y, z) of the
// incline's frame (x down the slope, z its normal) in the lab frame
inline void incline_to_lab(double theta, const double p[3], double out[3])
{
  out[0] = std::cos(theta) * p[0] + std::sin(theta) * p[2];
  out[1] = p[1];
  out[2] = -std::sin(theta) * p[0] + std::cos(theta) * p[2];
}

// the mesh t of the incline's frame in the lab frame
inline Tris inclined(Tris t, double theta)
{
  for (size_t k = 0; k < t.size(); k += 3) {
    const double p[3] = {t[k], t[k + 1], t[k + 2]};
    incline_to_lab(theta, p, &t[k]);
  }
  return t;
}

// Fan triangulation of the same rectangle around an off-centre point:
// long thin triangles meeting at one vertex (a strongly irregular mesh).
inline Tris fan(double x0, double x1, double y0, double y1, double z, int nside, double cx,
                double cy)
{
  std::vector<double> bx, by;
  for (int k = 0; k < nside; k++) {
    bx.push_back(x0 + (x1 - x0) * k / nside);
    by.push_back(y0);
  }
  for (int k = 0; k < nside; k++) {
    bx.push_back(x1);
    by.push_back(y0 + (y1 - y0) * k / nside);
  }
  for (int k = 0; k < nside; k++) {
    bx.push_back(x1 - (x1 - x0) * k / nside);
    by.push_back(y1);
  }
  for (int k = 0; k < nside; k++) {
    bx.push_back(x0);
    by.push_back(y1 - (y1 - y0) * k / nside);
  }
  Tris t;
  const size_t n = bx.size();
  for (size_t k = 0; k < n; k++) {
    const size_t l = (k + 1) % n;
    for (double v : {cx, cy, z, bx[k], by[k], z, bx[l], by[l], z}) t.push_back(v);
  }
  return t;
}

inline std::string tmpdir()
{
  static std::string d;
  if (d.empty()) {
    char tmpl[] = "/tmp/polydem_wall_XXXXXX";
    d = mkdtemp(tmpl);
  }
  return d;
}

}    // namespace wall_test

#endif
