// POLYDEM kernel tests: exact reference geometry with CGAL's
// Exact_predicates_exact_constructions_kernel. Compiled without sanitizers
// (it is the reference, not the code under test).
#ifndef POLYDEM_CGAL_REF_H
#define POLYDEM_CGAL_REF_H

#include <array>
#include <vector>

namespace polydem_test {

using Pts = std::vector<std::array<double, 3>>;

struct RefResult {
  bool intersects = false;    // closed sets share a point
  double volume = 0;
  std::array<double, 3> centroid = {0, 0, 0};
};

// Intersection of conv(a) and conv(b), the points taken as exact rationals:
// convex hull (exact) of the vertices of a inside b, of b inside a and of
// all edge-triangle intersections; volume and centroid evaluated exactly.
RefResult ref_intersection(const Pts &a, const Pts &b);

// Intersection of the half-spaces n . p <= h, planes[i] = (nx, ny, nz, h),
// each double taken as an exact rational: every triple of planes meeting in
// one point gives a candidate vertex (exact), kept if it satisfies all
// half-spaces exactly; exact hull, volume and centroid. This is the exact
// answer for the very half-spaces the kernel receives, free of the round-off
// that turning vertices into planes adds (which alone moves the centroid of a
// 1e-9-thin sliver by ~1e-8 of the size).
RefResult ref_halfspaces(const std::vector<std::array<double, 4>> &planes);

// Polyhedron conv(p) against triangle (t0,t1,t2) with normal n = (t1-t0)x(t2-t0):
// section of conv(p) with the triangle (area, centroid), and the part of
// conv(p) behind the plane inside the triangle's prism (volume, centroid).
struct RefClip {
  double area = 0;
  std::array<double, 3> acentroid = {0, 0, 0};
  double volume = 0;
  std::array<double, 3> vcentroid = {0, 0, 0};
};
RefClip ref_clip(const Pts &p, const std::array<double, 3> &t0, const std::array<double, 3> &t1,
                 const std::array<double, 3> &t2);

// Distance between conv(a) and conv(b) (CGAL's Polytope_distance_d, the
// points taken as exact rationals, solved exactly; 0 if they intersect).
double ref_distance(const Pts &a, const Pts &b);

}    // namespace polydem_test

#endif
