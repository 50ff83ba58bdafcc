// POLYDEM kernel tests: shape builder (CGAL convex hull, merged coplanar faces).
#include "test_shapes.h"

#include "polydem_dual_seed.h"

#include "polydem_math.h"
#include "polydem_shape_template.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <functional>
#include <map>
#include <numeric>

namespace polydem_test {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;

ShapeData make_shape(const std::vector<std::array<double, 3>> &in)
{
  std::vector<K::Point_3> pts;
  for (auto &p : in) pts.emplace_back(p[0], p[1], p[2]);
  Mesh m;
  CGAL::convex_hull_3(pts.begin(), pts.end(), m);
  // compact vertex numbering
  std::map<Mesh::Vertex_index, int> vid;
  std::vector<std::array<double, 3>> V;
  for (auto v : m.vertices()) {
    vid[v] = (int) V.size();
    auto p = m.point(v);
    V.push_back({p.x(), p.y(), p.z()});
  }
  std::vector<std::array<int, 3>> tri;
  for (auto f : m.faces()) {
    std::array<int, 3> t;
    int k = 0;
    for (auto v : CGAL::vertices_around_face(m.halfedge(f), m)) t[k++] = vid[v];
    tri.push_back(t);
  }
  // volume and centroid (tetrahedra from vertex 0)
  double vol = 0, c[3] = {0, 0, 0};
  auto sub = [](const std::array<double, 3> &a, const std::array<double, 3> &b) {
    return std::array<double, 3>{a[0] - b[0], a[1] - b[1], a[2] - b[2]};
  };
  auto crs = [](const std::array<double, 3> &a, const std::array<double, 3> &b) {
    return std::array<double, 3>{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                                 a[0] * b[1] - a[1] * b[0]};
  };
  auto dt = [](const std::array<double, 3> &a, const std::array<double, 3> &b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  };
  for (auto &t : tri) {
    auto a = sub(V[t[0]], V[0]), b = sub(V[t[1]], V[0]), d = sub(V[t[2]], V[0]);
    double v6 = dt(a, crs(b, d));
    vol += v6 / 6;
    for (int k = 0; k < 3; ++k) c[k] += v6 / 6 * (a[k] + b[k] + d[k]) / 4;
  }
  for (int k = 0; k < 3; ++k) c[k] = c[k] / vol + V[0][k];
  for (auto &v : V)
    for (int k = 0; k < 3; ++k) v[k] -= c[k];
  ShapeData s;
  s.volume = vol;
  for (auto &v : V) {
    for (int k = 0; k < 3; ++k) s.verts.push_back(v[k]);
    s.radius = std::max(s.radius, std::sqrt(dt(v, v)));
  }
  // group triangles into planar faces (normals and offsets equal to 1e-10)
  const int nt = (int) tri.size();
  std::vector<std::array<double, 4>> tp(nt);
  for (int i = 0; i < nt; ++i) {
    auto n = crs(sub(V[tri[i][1]], V[tri[i][0]]), sub(V[tri[i][2]], V[tri[i][0]]));
    double l = std::sqrt(dt(n, n));
    for (int k = 0; k < 3; ++k) n[k] /= l;
    tp[i] = {n[0], n[1], n[2], dt(n, V[tri[i][0]])};
  }
  std::vector<int> grp(nt);
  std::iota(grp.begin(), grp.end(), 0);
  std::function<int(int)> find = [&](int i) { return grp[i] == i ? i : grp[i] = find(grp[i]); };
  std::map<std::pair<int, int>, int> he;    // directed edge -> triangle
  for (int i = 0; i < nt; ++i)
    for (int e = 0; e < 3; ++e) he[{tri[i][e], tri[i][(e + 1) % 3]}] = i;
  for (int i = 0; i < nt; ++i)
    for (int e = 0; e < 3; ++e) {
      int j = he[{tri[i][(e + 1) % 3], tri[i][e]}];
      double dn = 0;
      for (int k = 0; k < 3; ++k) dn += std::fabs(tp[i][k] - tp[j][k]);
      if (dn < 1e-10 && std::fabs(tp[i][3] - tp[j][3]) < 1e-10 * s.radius) grp[find(i)] = find(j);
    }
  std::map<int, int> gid;
  for (int i = 0; i < nt; ++i)
    if (!gid.count(find(i))) gid[find(i)] = (int) gid.size();
  const int nf = (int) gid.size();
  s.planes.assign(4 * nf, 0.0);
  std::vector<double> bestarea(nf, -1);
  s.face_start.assign(1, 0);
  std::vector<std::vector<int>> loops(nf);
  for (auto &g : gid) {
    int f = g.second;
    // boundary half-edges of the group, chained into a CCW loop
    std::map<int, int> next;
    for (int i = 0; i < nt; ++i) {
      if (find(i) != g.first) continue;
      auto n = crs(sub(V[tri[i][1]], V[tri[i][0]]), sub(V[tri[i][2]], V[tri[i][0]]));
      double a = std::sqrt(dt(n, n));
      if (a > bestarea[f]) {
        bestarea[f] = a;
        for (int k = 0; k < 3; ++k) s.planes[4 * f + k] = tp[i][k];
      }
      for (int e = 0; e < 3; ++e) {
        int u = tri[i][e], v = tri[i][(e + 1) % 3];
        if (find(he[{v, u}]) != g.first) next[u] = v;
      }
    }
    int start = next.begin()->first, u = start;
    do {
      loops[f].push_back(u);
      u = next[u];
    } while (u != start && loops[f].size() <= next.size());
  }
  for (int f = 0; f < nf; ++f) {
    double d = -1e300;
    std::array<double, 3> n = {s.planes[4 * f], s.planes[4 * f + 1], s.planes[4 * f + 2]};
    for (int v : loops[f]) d = std::max(d, dt(n, V[v]));
    s.planes[4 * f + 3] = d;
    for (int v : loops[f]) s.face_verts.push_back(v);
    s.face_start.push_back((int) s.face_verts.size());
  }
  // edges between different faces
  for (int i = 0; i < nt; ++i)
    for (int e = 0; e < 3; ++e) {
      int u = tri[i][e], v = tri[i][(e + 1) % 3];
      if (u < v && find(he[{v, u}]) != find(i)) {
        s.edges.push_back(u);
        s.edges.push_back(v);
      }
    }
  s.dual = polydem::build_dual_seed(s.nverts(), nf, s.planes.data(), s.face_start.data(),
                                    s.face_verts.data());
  s.vadj = polydem::build_vertex_adjacency(s.nverts(), (int) s.edges.size() / 2, s.edges.data());
  // as the templates (polydem_shape_faces.cpp): no adjacency where the fans disagree
  if (!s.dual.empty() && !s.vadj.empty() && !polydem::dual_fans_match(s.dual, s.vadj, s.nverts()))
    s.vadj.clear();
  return s;
}

std::vector<std::array<double, 3>> random_points(std::mt19937_64 &rng, int n, double aspect)
{
  std::normal_distribution<double> g(0, 1);
  std::uniform_real_distribution<double> u(0, 1);
  const double sy = 1.0 / (1.0 + (aspect - 1.0) * u(rng)), sz = 1.0 / aspect;
  std::vector<std::array<double, 3>> p;
  while ((int) p.size() < n) {
    double x = g(rng), y = g(rng), z = g(rng);
    double r = std::sqrt(x * x + y * y + z * z);
    double rad = 0.5 + 0.5 * u(rng);
    p.push_back({x / r * rad, y / r * rad * sy, z / r * rad * sz});
  }
  return p;
}

const char *const SHIPPED_SHAPES[6] = {"tetrahedron.shape", "octahedron.shape",
                                       "icosahedron.shape", "mineral18.shape",
                                       "catalyst_cylinder.shape", "cuboid_2p5cm.shape"};

std::vector<std::array<double, 3>> shipped_points(const std::string &file)
{
  const auto t = polydem::PolyShapeTemplate::from_file(std::string(POLYDEM_POTENTIALS_DIR) + "/" + file);
  std::vector<std::array<double, 3>> p;
  for (int i = 0; i < t.nverts(); ++i) {
    const auto v = t.vertex(i);
    p.push_back({v[0] / t.radius(), v[1] / t.radius(), v[2] / t.radius()});
  }
  return p;
}

std::vector<std::array<double, 3>> cube_points(double a)
{
  std::vector<std::array<double, 3>> p;
  for (int i = 0; i < 8; ++i)
    p.push_back({(i & 1 ? 0.5 : -0.5) * a, (i & 2 ? 0.5 : -0.5) * a, (i & 4 ? 0.5 : -0.5) * a});
  return p;
}

std::vector<std::array<double, 3>> dodecahedron_points(double R)
{
  const double phi = (1 + std::sqrt(5.0)) / 2, s = R / std::sqrt(3.0);
  std::vector<std::array<double, 3>> p;
  for (int i = 0; i < 8; ++i)
    p.push_back({(i & 1 ? 1 : -1) * s, (i & 2 ? 1 : -1) * s, (i & 4 ? 1 : -1) * s});
  for (int i = 0; i < 4; ++i) {
    double a = (i & 1 ? 1 : -1) * s / phi, b = (i & 2 ? 1 : -1) * s * phi;
    p.push_back({0, a, b});
    p.push_back({a, b, 0});
    p.push_back({b, 0, a});
  }
  return p;
}

std::vector<std::array<double, 3>> cylinder_points(double D, double L, int nrim)
{
  std::vector<std::array<double, 3>> p;
  for (int k = 0; k < nrim; ++k) {
    double t = 2 * M_PI * k / nrim;
    p.push_back({0.5 * D * std::cos(t), 0.5 * D * std::sin(t), -0.5 * L});
    p.push_back({0.5 * D * std::cos(t), 0.5 * D * std::sin(t), 0.5 * L});
  }
  p.push_back({0, 0, -0.5 * L});    // cap centres: 42 vertices in the point set
  p.push_back({0, 0, 0.5 * L});
  return p;
}

polydem::Quat<double> random_quat(std::mt19937_64 &rng)
{
  std::normal_distribution<double> g(0, 1);
  return polydem::qnormalize(polydem::make_quat(g(rng), g(rng), g(rng), g(rng)));
}

std::vector<std::array<double, 3>> posed_vertices(const ShapeData &s,
                                                  const polydem::Pose<double> &p)
{
  auto R = polydem::quat_to_mat(p.q);
  std::vector<std::array<double, 3>> out;
  for (int i = 0; i < s.nverts(); ++i) {
    auto v = polydem::make_vec3(s.verts[3 * i], s.verts[3 * i + 1], s.verts[3 * i + 2]);
    auto w = p.x + p.s * polydem::matvec(R, v);
    out.push_back({w.x, w.y, w.z});
  }
  return out;
}

}    // namespace polydem_test
