/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - the dual triangulation of a convex template, precomputed on the
   host once per template, so that the overlap kernel can start its dual
   Quickhull from particle A itself (its planes are all hull faces, its
   vertices the hull's vertices) and insert only B's cutting planes, instead
   of inserting every plane into a bounding tetrahedron (seed Algorithms
   III-V; same result, fewer insertions).

   Each primal vertex v of degree k is k-2 dual triangles (a fan over the
   faces around v); every triangle is oriented counter-clockwise seen from
   outside in dual space (as polydem_dual_hull.h requires) and knows its
   neighbour across each edge. Packed layout (ints):
     dual[0] = ntri,  then per triangle t (7 ints at 1 + 7 t):
     face[3], neighbour[3] (across edge face[e] -> face[e+1]), vertex.
   Host only (std containers); the result is plain data for the device.
   Also the vertex adjacency that the support search climbs along.
------------------------------------------------------------------------- */

#ifndef POLYDEM_DUAL_SEED_H
#define POLYDEM_DUAL_SEED_H

#include "polydem_shape_view.h"

#include <map>
#include <utility>
#include <vector>

namespace polydem {

constexpr int DUAL_SEED_STRIDE = DUAL_SEED_STRIDE_K;

// planes: 4*nfaces (n, d) with the origin strictly inside (d > 0);
// face loops counter-clockwise seen from outside. Returns an empty vector if
// the combinatorics are not those of a closed convex polyhedron.
inline std::vector<int> build_dual_seed(int nverts, int nfaces, const double *planes,
                                        const int *face_start, const int *face_verts)
{
  if (nverts < 4 || nfaces < 4) return {};    // not a polyhedron (e.g. an ellipsoid template)
  // directed edge (u -> w) of face loops -> face
  std::map<std::pair<int, int>, int> edge_face;
  for (int f = 0; f < nfaces; ++f) {
    const int b = face_start[f], k = face_start[f + 1] - b;
    for (int i = 0; i < k; ++i)
      edge_face[{face_verts[b + i], face_verts[b + (i + 1) % k]}] = f;
  }
  // faces around each vertex, in cyclic order: after face f (which has the
  // edge v -> w) comes the face with the reversed edge w -> v
  std::vector<std::vector<int>> around(nverts);
  std::vector<int> first_face(nverts, -1);
  for (int f = 0; f < nfaces; ++f)
    for (int i = face_start[f]; i < face_start[f + 1]; ++i)
      if (first_face[face_verts[i]] < 0) first_face[face_verts[i]] = f;
  for (int v = 0; v < nverts; ++v) {
    if (first_face[v] < 0) return {};
    int f = first_face[v];
    bool closed = false;
    for (int guard = 0; guard <= nfaces && !closed; ++guard) {
      around[v].push_back(f);
      int w = -1;    // v's successor in face f
      const int b = face_start[f], k = face_start[f + 1] - b;
      for (int i = 0; i < k; ++i)
        if (face_verts[b + i] == v) w = face_verts[b + (i + 1) % k];
      const auto it = edge_face.find({w, v});
      if (it == edge_face.end()) return {};
      f = it->second;
      closed = f == first_face[v];
    }
    if (!closed || around[v].size() < 3) return {};
  }
  auto y = [&](int f, int c) { return planes[4 * f + c] / planes[4 * f + 3]; };
  std::vector<int> out(1, 0);
  std::map<std::pair<int, int>, int> dedge;    // dual directed edge -> triangle
  int nt = 0;
  for (int v = 0; v < nverts; ++v) {
    const auto &a = around[v];
    for (size_t i = 1; i + 1 < a.size(); ++i) {
      int f[3] = {a[0], a[i], a[i + 1]};
      // orientation: ((y1 - y0) x (y2 - y0)) . y0 > 0
      double d1[3], d2[3];
      for (int c = 0; c < 3; ++c) {
        d1[c] = y(f[1], c) - y(f[0], c);
        d2[c] = y(f[2], c) - y(f[0], c);
      }
      const double cr[3] = {d1[1] * d2[2] - d1[2] * d2[1], d1[2] * d2[0] - d1[0] * d2[2],
                            d1[0] * d2[1] - d1[1] * d2[0]};
      if (cr[0] * y(f[0], 0) + cr[1] * y(f[0], 1) + cr[2] * y(f[0], 2) < 0) std::swap(f[1], f[2]);
      out.insert(out.end(), {f[0], f[1], f[2], -1, -1, -1, v});
      for (int e = 0; e < 3; ++e)
        if (!dedge.emplace(std::make_pair(f[e], f[(e + 1) % 3]), nt).second) return {};
      ++nt;
    }
  }
  for (int t = 0; t < nt; ++t)
    for (int e = 0; e < 3; ++e) {
      int *q = out.data() + 1 + DUAL_SEED_STRIDE * t;
      const auto it = dedge.find({q[(e + 1) % 3], q[e]});
      if (it == dedge.end()) return {};
      q[3 + e] = it->second;
    }
  out[0] = nt;
  return out;
}

// Vertex adjacency of a convex template for the support search's hill climb
// (polydem_gjk.h): vadj[v] .. vadj[v+1]-1 index v's neighbours within the
// same array (vadj[0] = nverts + 1, vadj[nverts] = total length). Empty if
// some vertex has no edge (not a closed polyhedron).
inline std::vector<int> build_vertex_adjacency(int nverts, int nedges, const int *edges)
{
  if (nverts < 4) return {};
  std::vector<std::vector<int>> nb(nverts);
  for (int e = 0; e < nedges; ++e) {
    const int u = edges[2 * e], w = edges[2 * e + 1];
    if (u < 0 || w < 0 || u >= nverts || w >= nverts || u == w) return {};
    nb[u].push_back(w);
    nb[w].push_back(u);
  }
  std::vector<int> out(nverts + 1, 0);
  out[0] = nverts + 1;
  for (int v = 0; v < nverts; ++v) {
    if (nb[v].empty()) return {};
    out.insert(out.end(), nb[v].begin(), nb[v].end());
    out[v + 1] = (int) out.size();
  }
  return out;
}

// Do dual's triangles come as the fans of the vertices in vertex order,
// vertex v's (degree - 2) long with the degree of vadj (dual_fan_first)?
// True for the two built from one closed convex template.
inline bool dual_fans_match(const std::vector<int> &dual, const std::vector<int> &vadj,
                            int nverts)
{
  if (dual.empty() || (int) vadj.size() < nverts + 1 || vadj[0] != nverts + 1) return false;
  int t = 0;
  for (int v = 0; v < nverts; ++v)
    for (int k = 0; k < vadj[v + 1] - vadj[v] - 2; ++k, ++t)
      if (t >= dual[0] || dual[1 + DUAL_SEED_STRIDE * t + 6] != v) return false;
  return t == dual[0];
}

}    // namespace polydem

#endif
