/* ----------------------------------------------------------------------
   POLYDEM - coplanar merging of a triangle mesh at load (host only), see
   polydem_stl.h (merge_coplanar).

   The wall contact sums the prisms of all triangles of a flat patch, and
   the prisms of any triangulation of a flat region partition the same
   space (polydem_clip.h), so V, S and M do not depend on how a flat region
   is triangulated. A region of edge-connected coplanar triangles can then be
   replaced by a coarser triangulation of its outline without changing any
   force (to round-off); the work per particle then follows the geometry,
   not the facet count of the file. Holes are joined to the outer outline
   by bridge edges before ear clipping. Pinched outlines and triangulations
   whose area does not match are kept as read.
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

  V3 sub(const V3 &a, const V3 &b)
  {
    return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
  }
  V3 crs(const V3 &a, const V3 &b)
  {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  }
  double dt(const V3 &a, const V3 &b)
  {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  }

  // twice the signed area of (a, b, c) in 2-D
  double orient(const double *a, const double *b, const double *c)
  {
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
  }

  // Ear clipping of a counter-clockwise polygon (2-D points p, 3-D points q,
  // vertex ids id: a polygon with bridged holes visits some vertices twice,
  // and a copy of an ear's own vertex does not block the ear). Appends the
  // triangles (3-D) to out; false if no ear is found (degenerate outline).
  bool ear_clip(const std::vector<std::array<double, 2>> &p, const std::vector<V3> &q,
                const std::vector<int> &id, double eps2, std::vector<double> &out)
  {
    std::vector<int> idx(p.size());
    for (size_t i = 0; i < idx.size(); i++) idx[i] = (int) i;
    auto emit = [&](int a, int b, int c) {
      for (const int v : {a, b, c})
        for (int d = 0; d < 3; d++) out.push_back(q[v][d]);
    };
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
          if (id[j] == id[ia] || id[j] == id[ib] || id[j] == id[ic]) continue;
          const double *x = p[j].data();
          // inside or on the closed triangle: not an ear
          if (orient(a, b, x) >= -eps2 && orient(b, c, x) >= -eps2 && orient(c, a, x) >= -eps2)
            empty = false;
        }
        if (!empty) continue;
        emit(ia, ib, ic);
        idx.erase(idx.begin() + k);
        found = true;
      }
      if (!found) return false;
    }
    emit(idx[0], idx[1], idx[2]);
    return true;
  }

  // Do the closed segments pq and ab share a point? (exact orientation tests)
  bool segments_touch(const double *p, const double *q, const double *a, const double *b)
  {
    const double o1 = orient(p, q, a), o2 = orient(p, q, b), o3 = orient(a, b, p),
                 o4 = orient(a, b, q);
    auto on = [](const double *u, const double *v, const double *w) {    // w on segment uv
      return std::min(u[0], v[0]) <= w[0] && w[0] <= std::max(u[0], v[0]) &&
          std::min(u[1], v[1]) <= w[1] && w[1] <= std::max(u[1], v[1]);
    };
    if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0)))
      return true;
    return (o1 == 0 && on(p, q, a)) || (o2 == 0 && on(p, q, b)) || (o3 == 0 && on(a, b, p)) ||
        (o4 == 0 && on(a, b, q));
  }

  // Splice hole h (clockwise) into the counter-clockwise polygon outer by a
  // bridge from the hole's vertex M of largest u to the nearest vertex P of
  // outer that M sees: the segment MP touches no edge of outer, of h or of
  // the holes still to come, except at its own ends, and leaves P inside the
  // corner of that copy of P (a vertex used by an earlier bridge appears
  // several times). Lists hold indices into the 2-D points pt. O(n^2) per
  // hole. False if no vertex is visible (degenerate input).
  bool bridge_hole(std::vector<int> &outer, const std::vector<int> &h,
                   const std::vector<std::vector<int>> &later,
                   const std::vector<std::array<double, 2>> &pt)
  {
    size_t mi = 0;
    for (size_t i = 1; i < h.size(); i++)
      if (pt[h[i]][0] > pt[h[mi]][0] || (pt[h[i]][0] == pt[h[mi]][0] && pt[h[i]][1] > pt[h[mi]][1]))
        mi = i;
    const double *M = pt[h[mi]].data();
    const int no = (int) outer.size();
    std::vector<std::pair<double, int>> cand;
    for (int i = 0; i < no; i++) {
      const double du = pt[outer[i]][0] - M[0], dv = pt[outer[i]][1] - M[1];
      cand.emplace_back(du * du + dv * dv, i);
    }
    std::sort(cand.begin(), cand.end());
    auto blocked_by = [&](const std::vector<int> &loop, const double *P, int skipA, int skipB) {
      const int n = (int) loop.size();
      for (int e = 0; e < n; e++) {
        const int ia = loop[e], ib = loop[(e + 1) % n];
        if (ia == skipA || ib == skipA || ia == skipB || ib == skipB) continue;
        if (segments_touch(M, P, pt[ia].data(), pt[ib].data())) return true;
      }
      return false;
    };
    for (const auto &c : cand) {
      const int i = c.second;
      const double *a = pt[outer[(i + no - 1) % no]].data(), *P = pt[outer[i]].data(),
                   *b = pt[outer[(i + 1) % no]].data();
      const bool convex = orient(a, P, b) > 0;
      const bool l1 = orient(a, P, M) > 0, l2 = orient(P, b, M) > 0;
      if (!(convex ? (l1 && l2) : (l1 || l2))) continue;
      if (blocked_by(outer, P, outer[i], -1) || blocked_by(h, P, h[mi], -1)) continue;
      bool free = true;
      for (const auto &l : later) free = free && !blocked_by(l, P, -1, -1);
      if (!free) continue;
      std::vector<int> merged(outer.begin(), outer.begin() + i + 1);
      for (size_t k = 0; k <= h.size(); k++) merged.push_back(h[(mi + k) % h.size()]);
      merged.push_back(outer[i]);
      merged.insert(merged.end(), outer.begin() + i + 1, outer.end());
      outer.swap(merged);
      return true;
    }
    return false;
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
    // loops of the outline (one outer, counter-clockwise; holes clockwise)
    std::vector<std::vector<int>> loops;
    {
      std::map<int, int> rest = next;
      while (simple && !rest.empty()) {
        std::vector<int> loop;
        const int first = rest.begin()->first;
        int v = first;
        do {
          loop.push_back(v);
          const auto it = rest.find(v);
          if (it == rest.end()) {
            simple = false;
            break;
          }
          v = it->second;
          rest.erase(it);
        } while (v != first);
        loops.push_back(loop);
      }
    }
    size_t total = 0;
    for (const auto &l : loops) total += l.size();
    if (!simple || total > (1u << 20)) {    // pinched (or absurdly long)
      st.kept_holes++;
      keep();
      continue;
    }
    // drop outline vertices on the line of their neighbours (within tol), in
    // one sweep per loop (a stack) plus the wrap-around
    auto collinear = [&](int ia, int ib, int ic) {
      const V3 &a = vert[ia], &b = vert[ib], &c = vert[ic];
      const V3 ac = sub(c, a), ab = sub(b, a);
      const double l2 = dt(ac, ac);
      const V3 x = crs(ab, ac);
      return l2 > 0.0 && dt(x, x) <= tol * tol * l2 && dt(ab, ac) > 0.0 && dt(ab, ab) < l2;
    };
    total = 0;
    double perim = 0.0;    // outline length: dropping vertices within tol moves it by <= tol
    for (auto &loop : loops) {
      for (size_t k = 0; k < loop.size(); k++) {
        const V3 e = sub(vert[loop[(k + 1) % loop.size()]], vert[loop[k]]);
        perim += std::sqrt(dt(e, e));
      }
      std::vector<int> kept;
      for (const int v : loop) {
        kept.push_back(v);
        while (kept.size() >= 3 &&
               collinear(kept[kept.size() - 3], kept[kept.size() - 2], kept.back()))
          kept.erase(kept.end() - 2);
      }
      bool changed = true;
      while (changed && kept.size() > 3) {
        changed = false;
        const size_t m = kept.size();
        if (collinear(kept[m - 2], kept[m - 1], kept[0])) {
          kept.pop_back();
          changed = true;
        } else if (collinear(kept[m - 1], kept[0], kept[1])) {
          kept.erase(kept.begin());
          changed = true;
        }
      }
      loop.swap(kept);
      total += loop.size();
    }
    // ear clipping and bridging are O(n^2) (O(n^3) at worst): bounded
    if (total > 2048 || loops.size() > 256) {
      st.kept_holes++;
      keep();
      continue;
    }
    // 2-D coordinates in the plane (e1, e2, n right-handed: outline counter-clockwise)
    V3 e1 = std::fabs(n[0]) < 0.9 ? crs(n, V3{1, 0, 0}) : crs(n, V3{0, 1, 0});
    const double l1 = std::sqrt(dt(e1, e1));
    e1 = {e1[0] / l1, e1[1] / l1, e1[2] / l1};
    const V3 e2 = crs(n, e1);
    std::map<int, int> local;    // vertex id -> index into pt
    std::vector<std::array<double, 2>> pt;
    std::vector<int> ptid;
    for (const auto &loop : loops)
      for (const int v : loop)
        if (local.emplace(v, (int) pt.size()).second) {
          pt.push_back({dt(vert[v], e1), dt(vert[v], e2)});
          ptid.push_back(v);
        }
    // the outer loop has the largest signed area; the others must be holes
    int outer_k = -1;
    double amax = 0.0;
    std::vector<double> sarea(loops.size(), 0.0);
    for (size_t k = 0; k < loops.size(); k++) {
      const auto &l = loops[k];
      for (size_t i = 0; i < l.size(); i++) {
        const auto &a = pt[local[l[i]]], &b = pt[local[l[(i + 1) % l.size()]]];
        sarea[k] += 0.5 * (a[0] * b[1] - a[1] * b[0]);
      }
      if (sarea[k] > amax) {
        amax = sarea[k];
        outer_k = (int) k;
      }
    }
    bool ok = outer_k >= 0 && loops[outer_k].size() >= 3;
    std::vector<int> poly;    // indices into pt
    if (ok)
      for (const int v : loops[outer_k]) poly.push_back(local[v]);
    std::vector<std::pair<double, int>> holes;
    for (size_t k = 0; ok && k < loops.size(); k++) {
      if ((int) k == outer_k) continue;
      if (!(sarea[k] < 0.0) || loops[k].size() < 3) ok = false;
      double mx = -1e300;
      for (const int v : loops[k]) mx = std::max(mx, pt[local[v]][0]);
      holes.emplace_back(-mx, (int) k);
    }
    std::sort(holes.begin(), holes.end());    // largest u first
    std::vector<std::vector<int>> hl;
    for (const auto &hk : holes) {
      hl.emplace_back();
      for (const int v : loops[hk.second]) hl.back().push_back(local[v]);
    }
    for (size_t k = 0; ok && k < hl.size(); k++)
      ok = bridge_hole(poly, hl[k],
                       std::vector<std::vector<int>>(hl.begin() + (long) k + 1, hl.end()), pt);
    double ext = 0.0;
    for (const auto &a : pt)
      for (const auto &b : pt) ext = std::max(ext, std::fabs(a[0] - b[0]) + std::fabs(a[1] - b[1]));
    std::vector<std::array<double, 2>> p;
    std::vector<V3> q;
    std::vector<int> qid;
    for (const int i : poly) {
      p.push_back(pt[i]);
      q.push_back(vert[ptid[i]]);
      qid.push_back(ptid[i]);
    }
    std::vector<double> tris;
    ok = ok && ear_clip(p, q, qid, 1e-14 * ext * ext, tris);
    double narea = 0.0;
    for (size_t t = 0; ok && t < tris.size() / 9; t++) {
      const V3 a = {tris[9 * t], tris[9 * t + 1], tris[9 * t + 2]};
      const V3 b = {tris[9 * t + 3], tris[9 * t + 4], tris[9 * t + 5]};
      const V3 c = {tris[9 * t + 6], tris[9 * t + 7], tris[9 * t + 8]};
      const V3 x = crs(sub(b, a), sub(c, a));
      if (dt(x, n) <= 0.0) narea = -1e300;    // a flipped triangle: reject
      narea += 0.5 * std::sqrt(dt(x, x));
    }
    // the new triangulation covers the region: its area may differ only by
    // round-off and by the vertices dropped within tol (<= tol x outline)
    if (!ok || !(std::fabs(narea - rarea) <= 1e-9 * rarea + tol * perim)) {
      st.kept_failed++;
      keep();
      continue;
    }
    st.merged_regions++;
    st.bridged_holes += (int) loops.size() - 1;
    out.insert(out.end(), tris.begin(), tris.end());
  }
  tri.swap(out);
  st.after = (int) (tri.size() / 9);
  return st;
}

}    // namespace polydem

namespace polydem {

std::vector<int> mesh_regions(const std::vector<double> &tri, double cosmax, double tol)
{
  const int nt = (int) (tri.size() / 9);
  std::vector<int> region(nt, -1);
  if (nt == 0) return region;
  // unit normals
  std::vector<V3> nrm(nt);
  for (int t = 0; t < nt; t++) {
    const double *p = tri.data() + 9 * (size_t) t;
    const V3 a = {p[0], p[1], p[2]}, b = {p[3], p[4], p[5]}, c = {p[6], p[7], p[8]};
    V3 n = crs(sub(b, a), sub(c, a));
    const double l = std::sqrt(dt(n, n));
    for (double &x : n) x = l > 0.0 ? x / l : 0.0;
    nrm[t] = n;
  }
  // welded vertex ids, and the triangles at each vertex (CSR)
  const double q = tol > 0.0 ? tol : 1e-300;
  std::map<std::array<long long, 3>, int> ids;
  std::vector<int> vid(3 * (size_t) nt);
  for (size_t k = 0; k < vid.size(); k++) {
    std::array<long long, 3> key;
    for (int d = 0; d < 3; d++) key[d] = std::llround(tri[3 * k + d] / q);
    vid[k] = ids.emplace(key, (int) ids.size()).first->second;
  }
  std::vector<int> start(ids.size() + 1, 0), at(vid.size());
  for (const int v : vid) start[v + 1]++;
  for (size_t v = 0; v < ids.size(); v++) start[v + 1] += start[v];
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (size_t k = 0; k < vid.size(); k++) at[fill[vid[k]]++] = (int) (k / 3);
  // region growing (breadth first) from each unassigned triangle in order
  const double cmin = cosmax - 1e-12;    // patch angle 0: parallel to round-off
  std::vector<int> queue;
  for (int s = 0; s < nt; s++) {
    if (region[s] >= 0) continue;
    region[s] = 2 * s;
    queue.assign(1, s);
    for (size_t h = 0; h < queue.size(); h++) {
      const int t = queue[h];
      for (int c = 0; c < 3; c++) {
        const int v = vid[3 * (size_t) t + c];
        for (int k = start[v]; k < start[v + 1]; k++) {
          const int u = at[k];
          if (region[u] >= 0) continue;
          const double cs = dt(nrm[u], nrm[s]);
          if (cs >= cmin)
            region[u] = 2 * s;
          else if (-cs >= cmin)
            region[u] = 2 * s + 1;
          else
            continue;
          queue.push_back(u);
        }
      }
    }
  }
  return region;
}

}    // namespace polydem
