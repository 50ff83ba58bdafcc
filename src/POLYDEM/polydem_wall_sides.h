/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - which side of a mesh triangle acts on a particle (two-sided
   walls, issue 17; fix wall/mesh). Host and device, no LAMMPS includes.

   The seed's walls act from the front (the side n_w points to). Here both
   sides act by default: a triangle met from the back is clipped reversed,
   (t0, t2, t1), so the part of the particle in front of it is the overlap.
   The side is where the particle's centroid is when the contact begins, and
   it is kept while the contact lasts (WallSides).
------------------------------------------------------------------------- */

#ifndef POLYDEM_WALL_SIDES_H
#define POLYDEM_WALL_SIDES_H

#include "polydem_math.h"

#include <cmath>

namespace polydem {

constexpr int WALL_MAX_PATCH = 4;    // contacts per particle and mesh

// Which side of a triangle acts on a particle (two-sided walls). The side
// is where the centroid is when the contact begins, kept while it lasts:
// a contact kept from the previous step (normal n_c of its first facet, from
// the particle into the wall, e_c = n_c . (p_c - x) the distance from the
// centroid x to that facet's plane, p_c a vertex of it) claims a triangle whose plane,
// met on side s (normal -s n_t into the wall, distance e = s h, h the
// centroid's height above the front), agrees with it: normals within 45
// degrees, planes within WALL_SIDE_TOL x the bounding radius (the closest
// wins). Any other triangle is met on the centroid's side. A particle pushed
// beyond its centroid is then still pushed back, two parallel walls on
// either side of a particle are told apart by their planes, and a closed
// mesh acts alike with either normal convention.
constexpr double WALL_SIDE_COS = 0.70710678118654752;    // cos 45 degrees
constexpr double WALL_SIDE_TOL = 0.1;                    // x bounding radius

template <typename T> struct WallSides {
  int both;                      // 1: two-sided; 0: the front only (sides front)
  int n;                         // contacts kept from the previous step
  Vec3<T> nc[WALL_MAX_PATCH];    // their normals (mesh frame)
  T ec[WALL_MAX_PATCH];          // their plane distances [length]
};

// +1: front, -1: back, for the plane pl (unit normal, offset) of a triangle,
// centroid c and bounding radius r (mesh frame); s null: the front.
// claimed (if given): 1 when a kept contact chose the side, 0 when the
// centroid did.
template <typename T>
POLYDEM_FN int wall_side(const WallSides<T> *s, const T *pl, const Vec3<T> &c, T r,
                         int *claimed = nullptr)
{
  if (claimed) *claimed = 0;
  if (!s || !s->both) return 1;
  const T h = pl[0] * c.x + pl[1] * c.y + pl[2] * c.z - pl[3];
  int side = h >= T(0) ? 1 : -1;
  T best = T(WALL_SIDE_TOL) * r;
  for (int k = 0; k < s->n; ++k) {
    const T cn = s->nc[k].x * pl[0] + s->nc[k].y * pl[1] + s->nc[k].z * pl[2];
    const int sk = cn <= -T(WALL_SIDE_COS) ? 1 : (cn >= T(WALL_SIDE_COS) ? -1 : 0);
    if (!sk) continue;
    const T d = fabs(T(sk) * h - s->ec[k]);
    if (d <= best) {
      best = d;
      side = sk;
      if (claimed) *claimed = 1;
    }
  }
  return side;
}

// a kept contact whose centroid has crossed its plane (e_c < 0) may claim
// the back of a triangle the centroid is in front of: the near lists'
// side bound (wall_prism_gap) assumes there is none
template <typename T> POLYDEM_FN bool wall_sides_crossed(const WallSides<T> *s)
{
  if (!s || !s->both) return false;
  for (int k = 0; k < s->n; ++k)
    if (!(s->ec[k] >= T(0))) return true;
  return false;
}

}    // namespace polydem

#endif
