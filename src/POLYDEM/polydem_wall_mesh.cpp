/* ----------------------------------------------------------------------
   POLYDEM - a wall's mesh: loading, grid, motion, geometric queries
------------------------------------------------------------------------- */

#include "polydem_wall_mesh.h"

#include "polydem_wall_ellipsoid.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace polydem {

static constexpr double PI = 3.14159265358979323846;

MeshPose<double> MeshMotion::pose(double t) const
{
  MeshPose<double> mp;
  mp.o = make_vec3(origin[0], origin[1], origin[2]);
  mp.d = make_vec3(0.0, 0.0, 0.0);
  mp.vw = make_vec3(0.0, 0.0, 0.0);
  mp.w = make_vec3(0.0, 0.0, 0.0);
  mp.q = make_quat(1.0, 0.0, 0.0, 0.0);
  if (style == TRANSLATE) {
    mp.vw = make_vec3(vel[0], vel[1], vel[2]);
    mp.d = t * mp.vw;
  } else if (style == WIGGLE) {
    // d = A sin(2 pi t / T), v = A (2 pi / T) cos(2 pi t / T)
    const double w = 2.0 * PI / period;
    mp.d = sin(w * t) * make_vec3(amp[0], amp[1], amp[2]);
    mp.vw = (w * cos(w * t)) * make_vec3(amp[0], amp[1], amp[2]);
  } else if (style == SERVO) {
    const Vec3<double> a = make_vec3(dir[0], dir[1], dir[2]);
    mp.d = s * a;
    mp.vw = v * a;
  } else if (style == ROTATE) {
    const double ph = 0.5 * omega * t;
    mp.q = make_quat(cos(ph), sin(ph) * axis[0], sin(ph) * axis[1], sin(ph) * axis[2]);
    mp.w = omega * make_vec3(axis[0], axis[1], axis[2]);
  }
  mp.R = quat_to_mat(mp.q);
  return mp;
}

double MeshMotion::max_speed(const std::vector<double> &tri) const
{
  if (style == TRANSLATE) return sqrt(vel[0] * vel[0] + vel[1] * vel[1] + vel[2] * vel[2]);
  if (style == WIGGLE)
    return 2.0 * PI / period * sqrt(amp[0] * amp[0] + amp[1] * amp[1] + amp[2] * amp[2]);
  if (style == SERVO) return vmax;
  if (style != ROTATE) return 0.0;
  double r2 = 0.0;    // largest squared distance of a vertex from the axis
  for (size_t k = 0; k < tri.size(); k += 3) {
    const double d[3] = {tri[k] - origin[0], tri[k + 1] - origin[1], tri[k + 2] - origin[2]};
    const double a = d[0] * axis[0] + d[1] * axis[1] + d[2] * axis[2];
    r2 = std::max(r2, d[0] * d[0] + d[1] * d[1] + d[2] * d[2] - a * a);
  }
  return fabs(omega) * sqrt(r2);
}

void MeshMotion::servo_step(const double f[3])
{
  const double Fc = -(f[0] * dir[0] + f[1] * dir[1] + f[2] * dir[2]);
  v = std::max(-vmax, std::min(vmax, gain * (target - Fc)));
}

/* ---------------------------------------------------------------------- */

void WallMesh::load(const std::string &file, const StlTransform &xf, double merge_tol,
                    double patch_angle_deg)
{
  mesh = read_stl(file, xf);
  // the bounding-box diagonal: the tolerances below are relative to it
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for (size_t k = 0; k < mesh.tri.size(); k++) {
    lo[k % 3] = std::min(lo[k % 3], mesh.tri[k]);
    hi[k % 3] = std::max(hi[k % 3], mesh.tri[k]);
  }
  diag = 0.0;
  for (int d = 0; d < 3; d++) diag += (hi[d] - lo[d]) * (hi[d] - lo[d]);
  diag = sqrt(diag);
  // coplanar merging (deterministic: the same on every rank)
  merged = MergeStats();
  if (merge_tol >= 0.0) merged = merge_coplanar(mesh.tri, merge_tol * diag);
  // smooth regions, the patches' keys (after merging: its triangles; merging
  // keeps the outline's vertices, so the bounding box too)
  cosmax = cos(patch_angle_deg * PI / 180.0);
  regions = mesh_regions(mesh.tri, cosmax, 1e-9 * diag);
  nregions = 0;
  for (size_t t = 0; t < regions.size(); t++) nregions += regions[t] >> 1 == (int) t;
  // spatial order, in cells of the smallest automatic bin; the regions keep
  // their values (keys of the patches and their history, as before)
  row = spatial_order(mesh.tri, 2.0 * median_edge());
  tri_of_row.assign(row.size(), 0);
  std::vector<double> tri(mesh.tri.size());
  std::vector<int> reg(regions.size());
  for (size_t t = 0; t < row.size(); t++) {
    const size_t o = (size_t) row[t];
    tri_of_row[o] = (int) t;
    std::copy(mesh.tri.begin() + 9 * o, mesh.tri.begin() + 9 * o + 9, tri.begin() + 9 * t);
    reg[t] = regions[o];
  }
  mesh.tri.swap(tri);
  regions.swap(reg);
  grid = MeshGrid();
}

std::vector<int> spatial_order(const std::vector<double> &tri, double cell)
{
  const size_t n = tri.size() / 9;
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for (size_t k = 0; k < tri.size(); k++) {
    lo[k % 3] = std::min(lo[k % 3], tri[k]);
    hi[k % 3] = std::max(hi[k % 3], tri[k]);
  }
  // at most 2^20 cells along each direction: the key is 3 x 20 bits
  constexpr double CELLS = 1048575.0;
  double h = cell;
  for (int d = 0; d < 3; d++) h = std::max(h, (hi[d] - lo[d]) / CELLS);
  if (!(h > 0.0)) h = 1.0;    // a single point (no zero-area triangles reach here)
  std::vector<std::pair<unsigned long long, int>> key(n);
  for (size_t t = 0; t < n; t++) {
    unsigned long long k = 0;
    for (int d = 2; d >= 0; d--) {
      const double *p = &tri[9 * t + d];
      const double m = std::min(p[0], std::min(p[3], p[6]));
      const double u = std::min(CELLS, std::max(0.0, std::floor((m - lo[d]) / h)));
      k = (k << 20) | (unsigned long long) u;
    }
    key[t] = {k, (int) t};
  }
  std::sort(key.begin(), key.end());    // ties: the order as given
  std::vector<int> order(n);
  for (size_t t = 0; t < n; t++) order[t] = key[t].second;
  return order;
}

double WallMesh::median_edge() const
{
  // robust when merged regions make a few very large triangles
  std::vector<double> edges;
  for (int t = 0; t < ntri(); t++)
    for (int e = 0; e < 3; e++) {
      const double *p = &mesh.tri[9 * t + 3 * e], *q = &mesh.tri[9 * t + 3 * ((e + 1) % 3)];
      edges.push_back(sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                           (p[2] - q[2]) * (p[2] - q[2])));
    }
  if (edges.empty()) return 0.0;
  std::nth_element(edges.begin(), edges.begin() + edges.size() / 2, edges.end());
  return edges[edges.size() / 2];
}

double WallMesh::automatic_bin(double rmax) const
{
  return std::max(0.5 * rmax, 2.0 * median_edge());
}

bool WallMesh::set_grid(double h)
{
  if (!grid.start.empty() && grid.h == h) return false;
  grid = build_mesh_grid(mesh.tri, h);
  return true;
}

MeshGridView<double> WallMesh::grid_view() const
{
  MeshGridView<double> g;
  g.tri = mesh.tri.data();
  g.ntri = mesh.ntri();
  for (int d = 0; d < 3; d++) {
    g.lo[d] = grid.lo[d];
    g.n[d] = grid.n[d];
  }
  g.h = grid.h;
  g.start = grid.start.data();
  g.items = grid.items.data();
  g.plane = grid.plane.data();
  g.box = grid.box.data();
  g.region = regions.data();
  g.sphere = grid.sphere.data();
  return g;
}

// Among the triangles whose prism (the triangle swept along its normal,
// both ways) holds c, the one whose plane is nearest decides: c behind it
// (the side opposite its normal) is behind the wall. A grain placed there,
// apart from the wall, is thrown through it when it reaches a triangle from
// behind. Every triangle is tested (prisms are unbounded): a cost
// proportional to the mesh size, paid only by poses that passed every
// other test.
bool WallMesh::behind(const Vec3<double> &c) const
{
  double best = 1e300;
  bool back = false;
  for (int t = 0; t < ntri(); t++) {
    const double *pl = grid.plane.data() + 4 * t, *p = mesh.tri.data() + 9 * t;
    const double h = pl[0] * c.x + pl[1] * c.y + pl[2] * c.z - pl[3];
    if (!(fabs(h) < best)) continue;
    bool in = true;
    for (int e = 0; e < 3 && in; e++) {
      const double *a = p + 3 * e, *b = p + 3 * ((e + 1) % 3);
      const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
      const double w[3] = {c.x - a[0], c.y - a[1], c.z - a[2]};
      // (b - a) x (c - a) . n: c's offset along n drops out of it
      const double turn = (u[1] * w[2] - u[2] * w[1]) * pl[0] +
          (u[2] * w[0] - u[0] * w[2]) * pl[1] + (u[0] * w[1] - u[1] * w[0]) * pl[2];
      in = turn >= 0.0;
    }
    if (!in) continue;
    best = fabs(h);
    back = h < 0.0;
  }
  return back;
}

bool WallMesh::insertion_clear(const MeshPose<double> &mp, const InsertBody<double> &lab,
                               const Quat<double> &q, double gap, int twosided) const
{
  const auto g = grid_view();
  InsertBody<double> b = lab;    // into the mesh frame
  b.x = mesh_point(mp, lab.x);
  const Quat<double> qm = mesh_orientation(mp, q);
  b.R = quat_to_mat(qm);
  struct Visit {
    const MeshGridView<double> *g;
    const InsertBody<double> *b;
    double gap;
    bool clear;
    void operator()(int t)
    {
      if (!clear) return;
      TriangleSupport<double> ts;
      for (int k = 0; k < 9; k++) ts.p[k] = g->tri[9 * t + k];
      clear = body_triangle_apart(*b, ts, gap);
    }
  } visit{&g, &b, gap, true};
  mesh_for_each_near(g, b.x, b.radius + gap, visit);
  if (!visit.clear) return false;
  auto behind_it = [&] { return !twosided && behind(b.x); };    // last: the costliest
  WallPatches<double> P;
  WallSides<double> sides;    // no history: each triangle met on the centroid's side
  sides.both = twosided;
  sides.n = 0;
  if (!b.view) {
    // apart from every triangle: an ellipsoid can still be behind one of a
    // one-sided wall (sides front), which its forces would act on
    WallEllipsoid<double> e;
    e.c = b.x;
    e.R = b.R;
    e.ax = b.ax;
    wall_ellipsoid_patches(e, g, cosmax, P, &sides);
    return P.n == 0 && P.ndegenerate == 0 && !behind_it();
  }
  // apart from every triangle, but possibly behind one: the wall's own
  // contact volume decides (what its forces would act on)
  if (!ws) ws = std::make_unique<WallWorkspace<double>>();
  ws->record = 0;
  Pose<double> pm;
  pm.x = b.x;
  pm.q = qm;
  pm.s = b.s;
  const PosedShape<double> a = make_posed(*b.view, pm);
  wall_patches(a, g, cosmax, *ws, P, (WallNear<double> *) nullptr, &sides);
  for (int k = 0; k < P.n; k++)
    if (P.p[k].volume > 0.0 || !(P.p[k].volume == P.p[k].volume)) return false;
  return P.noverflow == 0 && P.ndegenerate == 0 && !behind_it();
}

}    // namespace polydem
