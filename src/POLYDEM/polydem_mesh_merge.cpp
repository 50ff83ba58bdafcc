/* ----------------------------------------------------------------------
   POLYDEM - coplanar merging of a triangle mesh at load (host only), see
   polydem_stl.h (merge_coplanar).

   The wall contact sums the prisms of all triangles of a flat patch, and
   the prisms of any triangulation of a flat region partition the same
   space (polydem_clip.h), so V, S and M do not depend on how a flat region
   is triangulated. A region of edge-connected coplanar triangles can then be
   replaced by a coarser triangulation of its outline without changing any
   force (to round-off); the work per particle then follows the geometry,
   not the facet count of the file. Regions with holes, pinched outlines or
   a triangulation whose area does not match are kept as read.
------------------------------------------------------------------------- */

#include "polydem_stl.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <vector>

namespace polydem {

namespace {

  using V3 = std::array<double, 3>;

  V3 sub(const V3 &a, const V3 &b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
  V3 crs(const V3 &a, const V3 &b)
  {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  }
  double dt(const V3 &a, const V3 &b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

  // twice the signed area of (a, b, c) in 2-D
  double orient(const double *a, const double *b, const double *c)
  {
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
  }

  // Ear clipping of a simple counter-clockwise polygon (2-D points p, 3-D
  // points q); appends triangles (3-D) to out. False if no ear is found
  // (numerically degenerate outline).
  bool ear_clip(std::vector<std::array<double, 2>> p, std::vector<V3> q, double eps2,
                std::vector<double> &out)
  {
    std::vector<int> idx(p.size());
    for (size_t i = 0; i < idx.size(); i++) idx[i] = (int) i;
    while (idx.size() > 3) {
      const int n = (int) idx.size();
      bool found = false;
      for (int k = 0; k < n && !found; k++) {
        const int ia = idx[(k + n - 1) % n], ib = idx[k], ic = idx[(k + 1) % n];
        const double *a = p[ia].data(), *b = p[ib].data(), *c = p[ic].data();
        if (!(orient(a, b, c) > eps2)) continue;    // reflex or flat
        bool empty = true;
        for (int m = 0; m < n && empty; m++) {
          const int j = idx[m];
          if (j == ia || j == ib || j == ic) continue;
          const double *x = p[j].data();
          // inside or on the closed triangle: not an ear
          if (orient(a, b, x) >= -eps2 && orient(b, c, x) >= -eps2 && orient(c, a, x) >= -eps2)
            empty = false;
        }
        if (!empty) continue;
        for (const int v : {ia, ib, ic})
          for (int d = 0; d < 3; d++) out.push_back(q[v][d]);
        idx.erase(idx.begin() + k);
        found = true;
      }
      if (!found) return false;
    }
    for (const int v : idx)
      for (int d = 0; d < 3; d++) out.push_back(q[v][d]);
    return true;
  }

}    // namespace

MergeStats merge_coplanar(std::vector<double> &tri, double tol)
{
  MergeStats st;
  const int nt = (int) (tri.size() / 9);
  st.before = st.after = nt;
  if (nt < 2 || !(tol >= 0.0)) return st;

  // welded vertices (exact coordinates) and per-triangle planes
  std::map<V3, int> vid;
  std::vector<V3> vert;
  std::vector<std::array<int, 3>> tv(nt);
  std::vector<V3> nrm(nt);
  std::vector<double> area(nt);
  for (int t = 0; t < nt; t++) {
    for (int k = 0; k < 3; k++) {
      const V3 p = {tri[9 * t + 3 * k], tri[9 * t + 3 * k + 1], tri[9 * t + 3 * k + 2]};
      auto it = vid.find(p);
      if (it == vid.end()) {
        it = vid.emplace(p, (int) vert.size()).first;
        vert.push_back(p);
      }
      tv[t][k] = it->second;
    }
    const V3 c = crs(sub(vert[tv[t][1]], vert[tv[t][0]]), sub(vert[tv[t][2]], vert[tv[t][0]]));
    const double l = std::sqrt(dt(c, c));
    area[t] = 0.5 * l;
    nrm[t] = {c[0] / l, c[1] / l, c[2] / l};
  }
  // directed edges; an edge joins two triangles only if it is used once in
  // each direction (consistently oriented, manifold)
  std::map<std::pair<int, int>, std::vector<int>> edges;
  for (int t = 0; t < nt; t++)
    for (int k = 0; k < 3; k++) edges[{tv[t][k], tv[t][(k + 1) % 3]}].push_back(t);
  auto neighbour = [&](int t, int k) {
    const int a = tv[t][k], b = tv[t][(k + 1) % 3];
    const auto f = edges.find({a, b}), r = edges.find({b, a});
    if (r == edges.end() || f->second.size() != 1 || r->second.size() != 1) return -1;
    return r->second[0];
  };

  std::vector<int> region(nt, -1);
  std::vector<double> out;
  out.reserve(tri.size());
  std::vector<int> members, stack;
  for (int seed = 0; seed < nt; seed++) {
    if (region[seed] >= 0) continue;
    // grow the region: every vertex within tol of the seed's plane, same side
    const V3 n = nrm[seed];
    const double d0 = dt(n, vert[tv[seed][0]]);
    members.assign(1, seed);
    stack.assign(1, seed);
    region[seed] = seed;
    while (!stack.empty()) {
      const int t = stack.back();
      stack.pop_back();
      for (int k = 0; k < 3; k++) {
        const int u = neighbour(t, k);
        if (u < 0 || region[u] >= 0 || dt(nrm[u], n) < 0.5) continue;
        bool flat = true;
        for (int v = 0; v < 3 && flat; v++) flat = std::fabs(dt(n, vert[tv[u][v]]) - d0) <= tol;
        if (!flat) continue;
        region[u] = seed;
        members.push_back(u);
        stack.push_back(u);
      }
    }
    auto keep = [&]() {
      for (const int t : members)
        for (int k = 0; k < 9; k++) out.push_back(tri[9 * t + k]);
    };
    if (members.size() < 3) {
      keep();
      continue;
    }
    st.regions++;
    // outline: region edges whose reverse is not in the region
    std::map<int, int> next;    // vertex -> next vertex along the outline
    bool simple = true;
    double rarea = 0.0;
    for (const int t : members) {
      rarea += area[t];
      for (int k = 0; k < 3; k++) {
        const int u = neighbour(t, k);
        if (u >= 0 && region[u] == seed) continue;
        const int a = tv[t][k], b = tv[t][(k + 1) % 3];
        if (!next.emplace(a, b).second) simple = false;    // pinched outline
      }
    }
    std::vector<int> loop;
    if (simple && !next.empty()) {
      const int first = next.begin()->first;
      int v = first;
      do {
        loop.push_back(v);
        const auto it = next.find(v);
        if (it == next.end() || loop.size() > next.size()) {
          simple = false;
          break;
        }
        v = it->second;
      } while (v != first);
      if (loop.size() != next.size()) simple = false;    // holes: several loops
    }
    if (!simple || loop.size() < 3 || loop.size() > 4096) {    // ear clipping is O(n^2)
      st.kept_holes++;
      keep();
      continue;
    }
    // drop outline vertices on the line of their neighbours (within tol)
    bool changed = true;
    while (changed && loop.size() > 3) {
      changed = false;
      for (size_t i = 0; i < loop.size() && loop.size() > 3; i++) {
        const V3 &a = vert[loop[(i + loop.size() - 1) % loop.size()]], &b = vert[loop[i]],
                 &c = vert[loop[(i + 1) % loop.size()]];
        const V3 ac = sub(c, a), ab = sub(b, a);
        const double l2 = dt(ac, ac);
        const V3 x = crs(ab, ac);
        if (l2 > 0.0 && dt(x, x) <= tol * tol * l2 && dt(ab, ac) > 0.0 && dt(ab, ab) < l2) {
          loop.erase(loop.begin() + (long) i);
          changed = true;
        }
      }
    }
    // 2-D coordinates in the plane (e1, e2, n right-handed: outline counter-clockwise)
    V3 e1 = std::fabs(n[0]) < 0.9 ? crs(n, V3{1, 0, 0}) : crs(n, V3{0, 1, 0});
    const double l1 = std::sqrt(dt(e1, e1));
    e1 = {e1[0] / l1, e1[1] / l1, e1[2] / l1};
    const V3 e2 = crs(n, e1);
    std::vector<std::array<double, 2>> p;
    std::vector<V3> q;
    double ext = 0.0;
    for (const int v : loop) {
      q.push_back(vert[v]);
      p.push_back({dt(vert[v], e1), dt(vert[v], e2)});
    }
    for (const auto &a : p)
      for (const auto &b : p) ext = std::max(ext, std::fabs(a[0] - b[0]) + std::fabs(a[1] - b[1]));
    std::vector<double> tris;
    const bool ok = ear_clip(p, q, 1e-14 * ext * ext, tris);
    double narea = 0.0;
    for (size_t t = 0; ok && t < tris.size() / 9; t++) {
      const V3 a = {tris[9 * t], tris[9 * t + 1], tris[9 * t + 2]};
      const V3 b = {tris[9 * t + 3], tris[9 * t + 4], tris[9 * t + 5]};
      const V3 c = {tris[9 * t + 6], tris[9 * t + 7], tris[9 * t + 8]};
      const V3 x = crs(sub(b, a), sub(c, a));
      if (dt(x, n) <= 0.0) narea = -1e300;    // a flipped triangle: reject
      narea += 0.5 * std::sqrt(dt(x, x));
    }
    if (!ok || !(std::fabs(narea - rarea) <= 1e-9 * rarea)) {
      st.kept_failed++;
      keep();
      continue;
    }
    st.merged_regions++;
    out.insert(out.end(), tris.begin(), tris.end());
  }
  tri.swap(out);
  st.after = (int) (tri.size() / 9);
  return st;
}

}    // namespace polydem
