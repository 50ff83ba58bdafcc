/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - fix wall/mesh's per-contact entry point, called alike by its
   plain and /kk loop (gather, call, scatter):

     wall_body_contact      a polyhedron's clipped patches
                            (polydem_wall_contact.h) or an ellipsoid's
                            (polydem_wall_ellipsoid.h) -> the type's wall
                            law (polydem_law_table.h)
     wall_particle_contact  the same, a composite part by part

   The kernel counters are in WallPatches and WallWarnings. No LAMMPS
   includes; host and device (no allocation, bounded loops).
------------------------------------------------------------------------- */

#ifndef POLYDEM_WALL_PIPELINE_H
#define POLYDEM_WALL_PIPELINE_H

#include "polydem_body_gather.h"
#include "polydem_law_table.h"
#include "polydem_wall_contact.h"
#include "polydem_wall_ellipsoid.h"

namespace polydem {

// ---------------------------------------------------------------------------
// particle - wall

// A particle on a wall: its template (unit scale; volume, radius, inertia),
// ellipsoid semi-axes at unit scale (all 0: a polyhedron), pose, motion.
template <typename T> struct WallBody : BodyMotion<T> {
  const ShapeView<T> *shape;
  Vec3<T> axes;
  Pose<T> pose;
};

// atom k with its template (unit scale) and the template's semi-axes (0: a polyhedron)
template <typename T, class Atoms>
POLYDEM_FN WallBody<T> gather_wall_body(const Atoms &atoms, int k, const ShapeView<T> *shape,
                                        const Vec3<T> &axes)
{
  WallBody<T> b;
  b.shape = shape;
  b.axes = axes;
  b.pose = gather_pose<T>(atoms, k);
  gather_motion<T>(atoms, k, b);
  return b;
}

// The mesh as every particle sees it this step: pose and grid, patch angle
// (cosine), sides, warning thresholds (x bounding radius, x particle
// volume), near-list skin (x bounding radius).
template <typename T> struct WallScene {
  MeshPose<T> mp;
  MeshGridView<T> grid;
  T cosmax;
  int both;
  T depth_warn, overlap_warn;
  T near_skin;
  int sphere_volume;    // the wall takes pair polyhedron's material: spheres by their cap volume
};

// What a particle's wall contact returns: forces on it (and per patch),
// energy, contacts; its warnings; near-list statistics.
template <typename T> struct WallContactResult {
  WallForce<T> wf;
  WallWarnings<T> warn;
  int near_built, near_overflow;
};

// One particle on the mesh: hist its WALL_HIST_SIZE values (updated if
// update; dt counts only then); ws the clipping workspace (polyhedra), P the
// patches (out: kernel counts), near its near list or null.
template <typename T, int MF, int ME>
POLYDEM_FN WallContactResult<T> wall_body_contact(const WallBody<T> &b, const LawTable<T> &tab,
                                                  const WallScene<T> &sc, T dt, bool update,
                                                  T *hist, WallWorkspace<T, MF, ME> &ws,
                                                  WallPatches<T> &P, WallNear<T> *near)
{
  WallContactResult<T> r;
  const ShapeView<T> &sv = *b.shape;
  const T s = b.pose.s;
  const T V = sv.volume * s * s * s;
  const T dts = update ? dt : T(0);
  r.near_built = r.near_overflow = 0;
  if (b.axes.x > T(0)) {    // an ellipsoid: its bounding sphere's near list (no workspace)
    const Vec3<T> ax = make_vec3(s * b.axes.x, s * b.axes.y, s * b.axes.z);
    // spheres of a volume-law scene by their cap volume; other ellipsoids
    // by the linear law (LawEntry::kn)
    const bool cap = sc.sphere_volume && ax.x == ax.y && ax.y == ax.z;
    ContactLaw<T> law = cap ? wall_polyhedron_law(tab, b.type, V) : wall_ellipsoid_law(tab, b.type);
    // a liquid bridge on the wall: spheres only, of radius R = 2 r (the
    // sphere-plane limit of Derjaguin's 2 r_A r_B / (r_A + r_B))
    if (ax.x == ax.y && ax.y == ax.z)
      law.bridge.R = T(2) * ax.x;
    else
      law.bridge.volume = T(0);
    if (near) {
      T rb = ax.x > ax.y ? ax.x : ax.y;
      rb = ax.z > rb ? ax.z : rb;
      near->skin = sc.near_skin * rb;
      near->built = 0;
    }
    r.wf = wall_ellipsoid_particle(ax, b.pose, sc.mp, sc.grid, law, b.m, dts, sc.cosmax, sc.both,
                                   b.v, b.w, hist, update, P, cap, near);
    if (near) {
      r.near_built = near->built;
      r.near_overflow = near->built && *near->count == NEAR_OVERFLOW;
    }
  } else {
    if (near) {
      near->skin = sc.near_skin * sv.radius * s;
      near->built = 0;
    }
    r.wf = wall_particle(
        sv, b.pose, sc.mp, sc.grid,
        [&] {
          return wall_polyhedron_law(tab, b.type, V);
        },
        b.m, dts, sc.cosmax, sc.both, b.v, b.w, hist, update, ws, P, near);
    if (near) {
      r.near_built = near->built;
      r.near_overflow = near->built && *near->count == NEAR_OVERFLOW;
    }
  }
  r.warn = wall_warnings(P, r.wf, V, sv.radius * s, b.m, sc.depth_warn, sc.overlap_warn);
  return r;
}

// part k of a composite particle as a wall body of its own: the part's
// template and semi-axes, its pose (x + s R x_k, q q_k), the velocity of
// its centre v + w x (x_part - x); the grain's spin, mass and type
template <typename T> POLYDEM_FN WallBody<T> wall_part_body(const WallBody<T> &b, int k)
{
  const ShapePart<T> &p = b.shape->parts[k];
  WallBody<T> r = b;
  r.shape = p.view;
  r.axes = make_vec3(p.view->axes[0], p.view->axes[1], p.view->axes[2]);
  const Quat<T> qk = make_quat(p.q[0], p.q[1], p.q[2], p.q[3]);
  r.pose.q = qmul(b.pose.q, qk);
  r.pose.x = b.pose.x + b.pose.s * qrotate(b.pose.q, make_vec3(p.x[0], p.x[1], p.x[2]));
  r.v = b.v + cross(b.w, r.pose.x - b.pose.x);
  return r;
}

// the near lists a particle of this template keeps: one per part of a
// composite, else one
template <typename T> POLYDEM_FN int near_lists_of(const ShapeView<T> &v)
{
  return v.nparts > 0 ? v.nparts : 1;
}

// part k's near list: a particle's lists lie one after the other (the
// caller gives each particle room for near_lists_of(its template) lists)
template <typename T> POLYDEM_FN WallNear<T> wall_part_near(const WallNear<T> &n, int k)
{
  WallNear<T> r = n;
  r.ref += 13 * k;
  r.count += k;
  r.tri += n.cap * k;
  r.gap += n.cap * k;
  return r;
}

// One particle on the mesh, convex or composite: a composite's parts are
// particles of their own on the wall (each with WALL_HIST_SIZE values of
// hist, part k at k WALL_HIST_SIZE, and near list k, wall_part_near), their
// forces summed and their torques moved to the grain's centre. after(body, result, P) is
// called for each convex body with its own result (the caller's tally and
// per-triangle forces); the returned force and torque act on the grain.
template <typename T, int MF, int ME, typename After>
POLYDEM_FN WallContactResult<T>
wall_particle_contact(const WallBody<T> &b, const LawTable<T> &tab, const WallScene<T> &sc, T dt,
                      bool update, T *hist, WallWorkspace<T, MF, ME> &ws, WallPatches<T> &P,
                      WallNear<T> *near, After &&after)
{
  if (!view_is_composite(*b.shape)) {
    const WallContactResult<T> r = wall_body_contact(b, tab, sc, dt, update, hist, ws, P, near);
    after(b, r, P);
    return r;
  }
  WallContactResult<T> sum;
  sum.wf.f = sum.wf.tau = make_vec3(T(0), T(0), T(0));
  sum.wf.energy = T(0);
  sum.wf.ncontact = 0;
  sum.near_built = sum.near_overflow = 0;
  for (int k = 0; k < b.shape->nparts; ++k) {
    const WallBody<T> bp = wall_part_body(b, k);
    WallNear<T> nk;
    if (near) nk = wall_part_near(*near, k);
    const WallContactResult<T> r = wall_body_contact(bp, tab, sc, dt, update,
                                                     hist + k * WALL_HIST_SIZE, ws, P,
                                                     near ? &nk : (WallNear<T> *) nullptr);
    after(bp, r, P);
    sum.near_built += r.near_built;
    sum.near_overflow += r.near_overflow;
    sum.wf.f += r.wf.f;
    sum.wf.tau += r.wf.tau + cross(bp.pose.x - b.pose.x, r.wf.f);
    sum.wf.energy += r.wf.energy;
    sum.wf.ncontact += r.wf.ncontact;
  }
  return sum;
}

// the particle's part of the call's sums (reaction on the mesh, counts)
template <typename T>
POLYDEM_FN void wall_tally_add(WallTally<T> &sum, const WallBody<T> &b,
                               const WallContactResult<T> &r, const MeshPose<T> &mp,
                               const WallPatches<T> &P)
{
  sum.add(b.pose.x, r.wf, mp, P, r.warn);
  sum.near_builds += T(r.near_built);
  sum.near_overflow += T(r.near_overflow);
}

// per-triangle forces (pertriangle yes) of the particle's patches to add(t, fx, fy, fz)
template <typename T, int MF, int ME, typename F>
POLYDEM_FN void wall_body_triangle_forces(const WallBody<T> &b, const WallWorkspace<T, MF, ME> &ws,
                                          const WallPatches<T> &P, const WallContactResult<T> &r,
                                          F &add)
{
  if (b.axes.x > T(0))
    wall_ellipsoid_triangle_forces(P, r.wf, add);
  else
    wall_triangle_forces(ws, P, r.wf, add);
}

}    // namespace polydem

#endif
