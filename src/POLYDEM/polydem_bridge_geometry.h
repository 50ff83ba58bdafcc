/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - liquid bridges of non-spherical pairs (pair_coeff ... bridge):
   the gap, direction and point of application of Willett's force between
   a sphere and a convex polyhedron (the signed distance of the centre to
   the surface) and between two convex polyhedra (their signed distance,
   polydem_signed_distance.h), added to a contact's force by add_bridge
   (polydem_contact_law.h). Two spheres take theirs in the contact law.
   No LAMMPS includes; host and device.
------------------------------------------------------------------------- */

#ifndef POLYDEM_BRIDGE_GEOMETRY_H
#define POLYDEM_BRIDGE_GEOMETRY_H

#include "polydem_contact_law.h"
#include "polydem_signed_distance.h"

namespace polydem {

// the radius of a posed sphere (an ellipsoid template of equal semi-axes), 0 otherwise
template <typename T> POLYDEM_FN T posed_sphere_radius(const PosedShape<T> &A)
{
  const T *a = A.view->axes;
  return view_is_ellipsoid(*A.view) && a[0] == a[1] && a[0] == a[2] ? A.s * a[0] : T(0);
}

// a convex polyhedron template (not an ellipsoid, not a composite)
template <typename T> POLYDEM_FN bool view_is_convex_polyhedron(const ShapeView<T> &v)
{
  return !view_is_ellipsoid(v) && !view_is_composite(v);
}

// Signed distance from the point c to the surface of the posed convex
// polyhedron b: outside, |p - c| to its nearest point p (on a face, an edge
// or a vertex: the nearest of the closest points of the fan triangles of
// the faces c sees); inside (or on it), minus the distance to the nearest
// face plane, p the foot on it. n: the unit direction from c towards b at
// p ((p - c)/|p - c| outside, minus that face's normal inside). The
// distance's gradient is -n in c and (p - x_b) x n in b's rotation.
template <typename T>
POLYDEM_FN T point_polyhedron_distance(const Vec3<T> &c, const PosedShape<T> &b, Vec3<T> &n,
                                       Vec3<T> &p)
{
  const ShapeView<T> &v = *b.view;
  auto vertex = [&](int i) {
    const T *q = v.verts + 3 * i;
    return b.x + b.s * matvec(b.R, make_vec3(q[0], q[1], q[2]));
  };
  T dmax = T(-1e300);
  Vec3<T> nmax = make_vec3(T(0), T(0), T(1));
  T best = T(-1);
  for (int f = 0; f < v.nfaces; ++f) {
    const T *q = v.planes + 4 * f;
    const Vec3<T> nf = matvec(b.R, make_vec3(q[0], q[1], q[2]));
    const T d = dot(nf, c - b.x) - b.s * q[3];    // above the face's plane
    if (d > dmax) {
      dmax = d;
      nmax = nf;
    }
    if (!(d > T(0))) continue;
    // the face's convex polygon as a fan from its first vertex
    const int k0 = v.face_start[f], k1 = v.face_start[f + 1];
    const Vec3<T> p0 = vertex(v.face_verts[k0]);
    Vec3<T> pj = vertex(v.face_verts[k0 + 1]);
    for (int k = k0 + 2; k < k1; ++k) {
      const Vec3<T> pk = vertex(v.face_verts[k]);
      int face;
      const Vec3<T> y = triangle_closest_point(c, p0, pj, pk, face);
      const T d2 = norm2(y - c);
      if (best < T(0) || d2 < best) {
        best = d2;
        p = y;
      }
      pj = pk;
    }
  }
  if (!(dmax > T(0)) || !(best > T(0))) {    // inside or on the surface
    n = -nmax;
    p = c - dmax * nmax;
    return dmax;
  }
  const T dist = sqrt(best);
  n = (T(1) / dist) * (p - c);
  return dist;
}

// The liquid bridge of a sphere sph and a convex polyhedron poly (pair_coeff
// ... bridge): the gap s = d(c) - r from the sphere's centre c to the
// polyhedron's surface (point_polyhedron_distance; negative in overlap) and
// Willett's force with the sphere-plane radius R = 2 r, the pull F(s) n on
// the sphere through its centre and -F(s) n on the polyhedron at p: the
// exact gradient of U(s) (bridge_energy) in both bodies' positions and
// rotations. A is the sphere if sphere_first. Adds to out; false (nothing
// added) at or beyond the rupture distance.
template <typename T, typename Out>
POLYDEM_FN bool sphere_polyhedron_bridge(const PosedShape<T> &sph, const PosedShape<T> &poly,
                                         BridgeLaw<T> law, bool sphere_first,
                                         const ContactKinematics<T> &kin, Out &out)
{
  const T r = posed_sphere_radius(sph);
  Vec3<T> n, p;
  const T s = point_polyhedron_distance(sph.x, poly, n, p) - r;
  if (!(s < law.rupture)) return false;
  law.R = T(2) * r;
  ContactGeometry<T> g{};
  g.normal = sphere_first ? n : -n;
  g.centroid = p;
  g.has_gap = 1;
  g.gap = s;
  add_bridge(g, law, kin, out);
  return true;
}

// Willett's radius for a liquid bridge between two convex polyhedra: the
// Derjaguin mean 2 r_A r_B / (r_A + r_B) of their volume-equivalent sphere
// radii r = (3 V / 4 pi)^(1/3) (a flat face has no curvature of its own; the
// grains' size stands for it, as for clumps of spheres)
template <typename T>
POLYDEM_FN T polyhedron_bridge_radius(const PosedShape<T> &a, const PosedShape<T> &b)
{
  const T k = T(3) / (T(4) * T(3.14159265358979323846));
  const T ra = cbrt(k * posed_volume(a)), rb = cbrt(k * posed_volume(b));
  return T(2) * ra * rb / (ra + rb);
}

// The liquid bridge of two convex polyhedra a and b (pair_coeff ... bridge):
// Willett's force with R = polyhedron_bridge_radius at their signed distance
// s, the distance of their nearest points (gjk_witness) while apart, minus
// their penetration depth (epa_penetration) while they overlap, so that s is
// continuous through contact and U(s) (bridge_energy) has the pull F(s) n
// on A and -F(s) n on B along the line of the witness points as its exact
// gradient in both bodies' positions and rotations (where the nearest or
// deepest features are unique; else at the centre of the region they share,
// witness_region_centre). Touching within GJK's tolerance: s = 0
// along the line of centres. Adds to out (and the geometry to geo); false
// (nothing added) at or beyond the rupture distance.
template <typename T, typename Out>
POLYDEM_FN bool polyhedron_pair_bridge(const PosedShape<T> &a, const PosedShape<T> &b,
                                       BridgeLaw<T> law, const ContactKinematics<T> &kin,
                                       Out &out, ContactGeometry<T> *geo = nullptr)
{
  const GjkWitness<T> w = gjk_witness(a, b);
  ContactGeometry<T> g{};
  g.has_gap = 1;
  bool found = false;
  if (w.status == STATUS_SEPARATED) {
    if (!(w.distance < law.rupture)) return false;
    const Vec3<T> dw = w.pb - w.pa;
    g.normal = (T(1) / norm(dw)) * dw;
    // on the line of the force (the same torques); the region's centre
    // where the nearest features are not unique
    g.centroid = witness_region_centre(a, b, g.normal, T(0.5) * (w.pa + w.pb));
    g.gap = w.distance;
    found = true;
  } else if (w.status == STATUS_OK && w.nsimplex == 4) {
    const EpaResult<T> e = epa_penetration(a, b, w);
    if ((e.status == STATUS_OK || e.status == STATUS_NO_CONVERGENCE) && e.depth > T(0)) {
      g.normal = e.normal;
      g.centroid = witness_region_centre(a, b, g.normal, T(0.5) * (e.pa + e.pb));
      g.gap = -e.depth;
      found = true;
    }
  }
  if (!found) {    // touching
    const Vec3<T> dc = b.x - a.x;
    const T d = norm(dc);
    if (!(d > T(0))) return false;
    g.normal = (T(1) / d) * dc;
    g.centroid = a.x;
    g.gap = T(0);
  }
  law.R = polyhedron_bridge_radius(a, b);
  add_bridge(g, law, kin, out);
  if (geo) *geo = g;
  return true;
}

}    // namespace polydem

#endif
