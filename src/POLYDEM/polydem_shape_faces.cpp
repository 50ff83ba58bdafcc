/* ----------------------------------------------------------------------
   POLYDEM - host-side convex shape template (seed polyhedral 2.1): faces,
   planes and edges of the merged hull (build()'s last phase), the dual
   seed and vertex adjacency (polydem_dual_seed.h) and the float copy the
   kernels read through ShapeView<T>; face(), inradius(), max_face_area().
------------------------------------------------------------------------- */

#include "polydem_shape_template.h"

#include "polydem_dual_seed.h"
#include "polydem_shape_template_impl.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace polydem {

using namespace shape_impl;

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

void PolyShapeTemplate::make_float_copy()
{
  dual_ =
      build_dual_seed(nverts(), nfaces(), planes_.data(), face_start_.data(), face_verts_.data());
  vadj_ = build_vertex_adjacency(nverts(), nedges(), edges_.data());
  // the overlap kernel walks the dual triangulation by the vertices' fans
  // (dual_fan_first) where both exist: a template where they disagree (not
  // a closed convex polyhedron) keeps neither fast path's shortcut
  if (!dual_.empty() && !vadj_.empty() && !dual_fans_match(dual_, vadj_, nverts())) vadj_.clear();
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
  for (const auto &p : part_shapes_) r = std::min(r, p->inradius());    // the thinnest part
  for (int f = 0; f < nfaces(); f++) r = std::min(r, planes_[4 * f + 3]);
  return r;
}

double PolyShapeTemplate::max_face_area() const
{
  double amax = 0.0;
  for (const auto &p : part_shapes_) amax = std::max(amax, p->max_face_area());
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
                              const int *vadj, const std::array<double, 3> &axes)
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
  for (int i = 0; i < 3; ++i) s.axes[i] = (T) axes[i];
  return s;
}

ShapeView<double> PolyShapeTemplate::view() const
{
  ShapeView<double> v =
      make_view<double>(nverts(), nfaces(), nedges(), verts_.data(), planes_.data(),
                        face_start_.data(), face_verts_.data(), edges_.data(), radius_, volume_,
                        moments_, dual_.empty() ? nullptr : dual_.data(),
                        vadj_.empty() ? nullptr : vadj_.data(), axes_);
  if (parts_) {
    v.nparts = (int) parts_->size();
    v.parts = parts_->data();
  }
  return v;
}

ShapeView<float> PolyShapeTemplate::view_float() const
{
  return make_view<float>(nverts(), nfaces(), nedges(), verts_f_.data(), planes_f_.data(),
                          face_start_.data(), face_verts_.data(), edges_.data(), radius_, volume_,
                          moments_, dual_.empty() ? nullptr : dual_.data(),
                           vadj_.empty() ? nullptr : vadj_.data(), axes_);
}

}    // namespace polydem
