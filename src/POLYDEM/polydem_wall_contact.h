/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - contact of one convex polyhedron with a triangle mesh (fix
   wall/mesh and /kk), host and device. No LAMMPS includes.

   Seed §2.4 (Algorithm VII, Eqs. 10-11) weights a facet's force by the
   clipped section area. Here the facets a particle touches are grouped into
   patches, one per smooth region of the mesh (facets connected to the
   region's seed facet within the patch angle of its normal, fixed at load:
   mesh_regions, polydem_stl.h). Per patch the kernel's per-triangle results are summed:
     V = sum V_t,  S = sum S_t = -sum n_t A_t,  M = sum M_t
   (polydem_clip.h: prisms of a flat triangulated wall partition the space
   behind it, so V, S, M of a flat patch equal those of the infinite plane
   whatever the triangulation), and the patch is one contact of the pair
   model (polydem_contact_law.h, Eqs. 12-20):
     F = -W'(V) S,  tau = -W'(V) M   (+ damping, Cundall-Strack friction),
   so each patch force is the exact gradient of W(V_patch), with no double
   counting or spikes at shared edges and vertices. A sharp edge of the
   mesh (angle > patch angle) gives two contacts, each with its own
   tangential history.

   Wall material: a half-space of (E_w, nu_w) sized like the particle
   (R_w = R_p), so K = (E_p + E_w)/R_p, K_t likewise; m_eff = m_p.

   The file's parts: polydem_wall_sides.h (which side of a triangle acts),
   polydem_wall_patches.h (candidates, clipping, patches), this file (the
   patches' contacts through the contact layer, history, tallies);
   polydem_wall_ellipsoid.h (ellipsoids).
------------------------------------------------------------------------- */

#ifndef POLYDEM_WALL_CONTACT_H
#define POLYDEM_WALL_CONTACT_H

#include "polydem_contact_law.h"
#include "polydem_rigid.h"    // MeshPose, point_inverse_mass
#include "polydem_wall_patches.h"
#include "polydem_wall_sides.h"

#include <cmath>

namespace polydem {

// Normal damping of a wall contact. The pair's damping ratio is that of a
// face contact (V = A delta, W' ~ V^(1/3)) of a free particle. A corner or
// edge hitting a wall is a different self-similar contact: with V ~ delta^a
// (a = 1 face, 2 edge, 3 vertex) and W' ~ V^q (q = dlnW'/dlnV: 1/3 for
// Feng's law, 1 deep in the quadratic core V << V0), F = W'(V) A ~
// delta^(a(q+1) - 1) and the model's local stiffness W''(V) A^2 = q a F /
// delta. The damping ratio for restitution e then depends on q (exactly, not
// on a: polydem_damping.h), and the contact point sees the mass m_c = 1 /
// (1/m + (r x n).I^-1 (r x n)) (r: centre to contact point), not m. The wall
// contact uses m_c and zeta(e, q) (DampingLaw with local = 1), so that a
// corner impact reverses the contact point's normal velocity by e (the
// assumption of seed Eqs. 27-28).

template <typename T> struct WallForce {
  Vec3<T> f, tau;    // on the particle (torque about its centroid)
  T energy;          // sum of W(V) over patches
  int ncontact;
  int capped;                        // contacts whose normal damping was capped at m_eff / dt
  int fresh;                         // bit k: patch k has no kept history (its contact begins)
  Vec3<T> fpatch[WALL_MAX_PATCH];    // force of each patch of P on the particle (lab)
};

// The contacts of one particle with one mesh as the contact layer sees them
// (lab frame), indexed like the patches they come from: on[k] = 0 when
// patch k makes no contact. Polyhedron patches (wall_patch_contacts) and
// ellipsoid patches (polydem_wall_ellipsoid.h) both end here, and
// wall_contact_forces is the one loop of slot matching, contact_step and
// history for both.
// key[k]: the patch's first facet normal as met (lab, from the particle
// into the wall), which names the contact from step to step (history slot,
// kept side): the contact normal g.normal tilts where the prism's sides take
// part (open borders, sharp edges), the facet's normal does not.
// kpoint[k]: a vertex of that facet (lab): the kept side's plane is the
// facet's own (key, kpoint), whose distance from the centroid is continuous;
// the contact point, an area-weighted mean over the patch's sections, can
// jump off the facets' planes where a section ends (an open border) on a
// curved patch, and the plane through it then claimed no triangle.
template <typename T> struct WallContacts {
  int n;
  int on[WALL_MAX_PATCH];
  ContactGeometry<T> g[WALL_MAX_PATCH];
  Vec3<T> key[WALL_MAX_PATCH];
  Vec3<T> kpoint[WALL_MAX_PATCH];
};

// Polyhedron patches: V, S = -sum n_t A_t, M summed over the patch's
// triangles (mesh frame) -> one contact each, normal S / |S| from the
// particle into the wall, contact point the area-weighted section centroid
// (the volume centroid if the patch has no section area).
template <typename T>
POLYDEM_FN WallContacts<T> wall_patch_contacts(const WallPatches<T> &P, const MeshPose<T> &mp)
{
  WallContacts<T> C;
  C.n = P.n;
  const Vec3<T> xw = mesh_axis_point(mp);    // a point of the wall's rotation axis (lab)
  for (int k = 0; k < P.n; ++k) {
    const WallPatch<T> &q = P.p[k];
    const T an = norm(q.S);
    C.on[k] = q.volume > T(0) && an > T(0);
    if (!C.on[k]) continue;
    ContactGeometry<T> &g = C.g[k];
    g.volume = q.volume;
    g.area = an;
    g.S_A = matvec(mp.R, q.S);
    g.M_A = matvec(mp.R, q.M);
    g.M_B = make_vec3(T(0), T(0), T(0));
    g.normal = (T(1) / an) * g.S_A;    // from the particle into the wall
    C.key[k] = -matvec(mp.R, q.nseed);
    C.kpoint[k] = lab_point(mp, xw, q.p0);
    const Vec3<T> cm = q.area > T(0) ? (T(1) / q.area) * q.ac : (T(1) / q.volume) * q.vc;
    g.centroid = lab_point(mp, xw, cm);
    g.gradient_damping = 0;
  }
  return C;
}

// no force, no contact
template <typename T> POLYDEM_FN WallForce<T> wall_force_zero()
{
  WallForce<T> out;
  out.f = out.tau = make_vec3(T(0), T(0), T(0));
  out.energy = T(0);
  out.ncontact = 0;
  out.capped = 0;
  out.fresh = 0;
  for (int k = 0; k < WALL_MAX_PATCH; ++k) out.fpatch[k] = make_vec3(T(0), T(0), T(0));
  return out;
}

// Forces of all contacts on the particle (lab frame) and the update of its
// tangential history hist[WALL_HIST_SIZE] for this mesh: each contact takes
// the old slot whose key normal (C.key) is closest within the patch angle
// (else a fresh spring); unmatched slots are cleared. Each slot keeps that
// normal and its plane's distance from the centroid (WallSides). law: the particle's wall law
// (wall_law of polydem_law_table.h, or ellipsoid_law); m its mass, Iinv its inverse principal
// moments, R its rotation (body -> frame of the contact normals, for the
// contact point's mass); dt the time step (0: no history increment, setup).
template <typename T>
POLYDEM_FN WallForce<T> wall_contact_forces(const WallContacts<T> &C, const MeshPose<T> &mp,
                                            const ContactLaw<T> &law, T m, const Vec3<T> &Iinv,
                                            const Mat3<T> &R, T cosmax, const Vec3<T> &x,
                                            const Vec3<T> &v, const Vec3<T> &w, T dt, T *hist,
                                            bool update)
{
  WallForce<T> out = wall_force_zero<T>();
  T newh[WALL_HIST_SIZE];
  for (int i = 0; i < WALL_HIST_SIZE; ++i) newh[i] = T(0);
  bool used[WALL_MAX_PATCH] = {false, false, false, false};
  const Vec3<T> xw = mesh_axis_point(mp);    // a point of the wall's rotation axis (lab)
  ContactKinematics<T> kin;
  kin.xA = x;
  kin.xB = xw;
  kin.vA = v;
  kin.vB = mp.vw;
  kin.wA = w;
  kin.wB = mp.w;
  kin.dt = dt;
  kin.mA = m;
  kin.mB = T(0);    // the wall: no rolling inertia, R_r = r_A
  int nslot = 0;
  for (int k = 0; k < C.n; ++k) {
    if (!C.on[k]) continue;
    const ContactGeometry<T> &g = C.g[k];
    const Vec3<T> &key = C.key[k];
    // history slot with the closest key normal (lab frame)
    int best = -1;
    T bc = cosmax;
    for (int s = 0; s < WALL_MAX_PATCH; ++s) {
      const T *h = hist + WALL_HIST * s;
      const T c = h[0] * key.x + h[1] * key.y + h[2] * key.z;
      if (!used[s] && c >= bc) {
        bc = c;
        best = s;
      }
    }
    // a liquid bridge across a gap (on = 2) acts only where it formed in
    // contact, i.e. where a slot is kept; it clears the slot's friction and
    // rolling springs (as a pair's bridge_contact)
    const bool bridge = C.on[k] == 2;
    if (bridge && (best < 0 || !(law.bridge.volume > T(0)) || !(g.gap < law.bridge.rupture)))
      continue;
    T shear[CONTACT_HIST_ROLL];
    for (int i = 0; i < CONTACT_HIST_ROLL; ++i) shear[i] = T(0);
    if (best >= 0) {
      used[best] = true;
      if (!bridge)
        for (int i = 0; i < CONTACT_HIST_ROLL; ++i) shear[i] = hist[WALL_HIST * best + 4 + i];
    } else
      out.fresh |= 1 << k;
    ContactForce<T> cf{};
    // the mass the contact point sees
    const Vec3<T> rn = matTvec(R, cross(g.centroid - x, g.normal));
    kin.meff = T(1) / point_inverse_mass(T(1) / m, Iinv, rn);
    if (bridge) {
      add_bridge(g, law.bridge, kin, cf);
    } else {
      cf = contact_step(g, law, kin, shear, CONTACT_HIST_ROLL);
      out.ncontact++;
    }
    T *h = newh + WALL_HIST * nslot++;
    h[0] = key.x;
    h[1] = key.y;
    h[2] = key.z;
    h[3] = dot(key, C.kpoint[k] - x);
    for (int i = 0; i < CONTACT_HIST_ROLL; ++i) h[4 + i] = shear[i];
    out.capped += cf.capped;
    out.f += cf.F_A;
    out.fpatch[k] = cf.F_A;
    out.tau += cf.tau_A;
    out.energy += cf.energy;
  }
  if (update)    // setup (no time step yet) leaves the history as it was
    for (int i = 0; i < WALL_HIST_SIZE; ++i) hist[i] = newh[i];
  return out;
}

// Forces of the polyhedron patches P (wall_patch_contacts, wall_contact_forces).
template <typename T>
POLYDEM_FN WallForce<T> wall_forces(const WallPatches<T> &P, const MeshPose<T> &mp,
                                    const ContactLaw<T> &law, T m, const Vec3<T> &Iinv,
                                    const Mat3<T> &R, T cosmax, const Vec3<T> &x,
                                    const Vec3<T> &v, const Vec3<T> &w, T dt, T *hist, bool update)
{
  return wall_contact_forces(wall_patch_contacts(P, mp), mp, law, m, Iinv, R, cosmax, x, v, w, dt,
                             hist, update);
}

// Torque on the mesh about its axis point o + d balancing the particle's
// force f and torque tau (about x).
template <typename T>
POLYDEM_FN Vec3<T> wall_reaction_torque(const Vec3<T> &x, const WallForce<T> &wf,
                                        const MeshPose<T> &mp)
{
  return -(wf.tau + cross(x - mesh_axis_point(mp), wf.f));
}

// The sides the contacts kept in hist claim (mesh frame; WallSides)
template <typename T>
POLYDEM_FN WallSides<T> wall_kept_sides(const T *hist, const MeshPose<T> &mp, int both)
{
  WallSides<T> s;
  s.both = both;
  s.n = 0;
  for (int k = 0; k < WALL_MAX_PATCH && both; ++k) {
    const T *h = hist + WALL_HIST * k;
    if (h[0] == T(0) && h[1] == T(0) && h[2] == T(0)) continue;
    s.nc[s.n] = matTvec(mp.R, make_vec3(h[0], h[1], h[2]));
    s.ec[s.n++] = h[3];
  }
  return s;
}

// What wall_contact_forces gives for no contact: nothing, and a cleared
// history (if update).
template <typename T> POLYDEM_FN WallForce<T> wall_no_contact(T *hist, bool update)
{
  WallForce<T> out = wall_force_zero<T>();
  if (update)
    for (int i = 0; i < WALL_HIST_SIZE; ++i) hist[i] = T(0);
  return out;
}

// Everything for one particle (lab pose x, q, s; velocity v, spin w):
// pose into the mesh frame, patches, forces back in the lab frame.
// both: two-sided wall (else the front of each triangle only). law_of():
// the particle's ContactLaw, asked for only when it touches the wall.
template <typename T, int MF, int ME, typename LawOf>
POLYDEM_FN WallForce<T>
wall_particle(const ShapeView<T> &sv, const Pose<T> &lab, const MeshPose<T> &mp,
              const MeshGridView<T> &g, const LawOf &law_of, T m, T dt, T cosmax, int both,
              const Vec3<T> &v, const Vec3<T> &w, T *hist, bool update,
              WallWorkspace<T, MF, ME> &ws, WallPatches<T> &P, WallNear<T> *near = nullptr)
{
  Pose<T> pm;
  pm.x = mesh_point(mp, lab.x);
  pm.q = mesh_orientation(mp, lab.q);
  pm.s = lab.s;
  const PosedShape<T> a = make_posed(sv, pm);
  const WallSides<T> sides = wall_kept_sides(hist, mp, both);
  wall_patches(a, g, cosmax, ws, P, near, &sides);
  if (P.n == 0) return wall_no_contact<T>(hist, update);
  const ContactLaw<T> law = law_of();
  // inverse principal moments: I = rho s^5 I_unit, rho = m / (s^3 V_unit)
  const T rho = m / (lab.s * lab.s * lab.s * sv.volume), s5 = lab.s * lab.s * lab.s * lab.s * lab.s;
  const Vec3<T> Iinv = make_vec3(T(1) / (rho * s5 * sv.inertia[0]), T(1) / (rho * s5 * sv.inertia[1]),
                                 T(1) / (rho * s5 * sv.inertia[2]));
  // the contact-point mass needs the particle's lab rotation (a.R is in the
  // mesh frame: on a rotating mesh it used the wrong body axes until
  // December 2026)
  return wall_forces(P, mp, law, m, Iinv, quat_to_mat(lab.q), cosmax, lab.x, v, w, dt, hist,
                     update);
}

// What fix wall/mesh warns about, per particle (issue 17): contacts whose
// particle's centroid is behind the triangle it is met on (a one-sided wall
// met from behind, or a two-sided one pushed beyond the centroid), deeper
// than depth_warn x the bounding radius r, or with an overlap volume beyond
// overlap_warn x the particle's volume Vp; and contacts that begin (no kept
// history; at setup: particles created or moved into the mesh) with their
// largest V / Vp, depth / r, and the particle's wall energy per mass.
template <typename T> struct WallWarnings {
  int behind, deep, large, fresh;
  T fresh_v, fresh_d, fresh_em;
};

template <typename T>
POLYDEM_FN WallWarnings<T> wall_warnings(const WallPatches<T> &P, const WallForce<T> &wf, T Vp, T r,
                                         T m, T depth_warn, T overlap_warn)
{
  WallWarnings<T> w;
  w.behind = w.deep = w.large = w.fresh = 0;
  w.fresh_v = w.fresh_d = w.fresh_em = T(0);
  for (int k = 0; k < P.n; ++k) {
    const WallPatch<T> &q = P.p[k];
    if (!(q.volume > T(0))) continue;
    w.behind += q.behind;
    w.deep += q.depth > depth_warn * r ? 1 : 0;
    w.large += q.volume > overlap_warn * Vp ? 1 : 0;
    if (!((wf.fresh >> k) & 1)) continue;
    w.fresh++;
    w.fresh_v = q.volume / Vp > w.fresh_v ? q.volume / Vp : w.fresh_v;
    w.fresh_d = q.depth / r > w.fresh_d ? q.depth / r : w.fresh_d;
    w.fresh_em = wf.energy / m;
  }
  return w;
}

// d += s for two WallTally (either may be volatile: Kokkos 3 joins)
template <class D, class S> POLYDEM_FN void wall_tally_merge(D &d, const S &s)
{
  for (int k = 0; k < 3; ++k) {
    d.force[k] += s.force[k];
    d.torque[k] += s.torque[k];
  }
  d.ncontact += s.ncontact;
  d.ntri += s.ntri;
  d.energy += s.energy;
  d.noverflow += s.noverflow;
  d.ndegenerate += s.ndegenerate;
  d.nmerged += s.nmerged;
  d.near_overflow += s.near_overflow;
  d.near_builds += s.near_builds;
  d.nunrecorded += s.nunrecorded;
  d.ncapped += s.ncapped;
  d.behind += s.behind;
  d.deep += s.deep;
  d.large += s.large;
  d.fresh += s.fresh;
  if (s.fresh_v > d.fresh_v) d.fresh_v = s.fresh_v;
  if (s.fresh_d > d.fresh_d) d.fresh_d = s.fresh_d;
  if (s.fresh_em > d.fresh_em) d.fresh_em = s.fresh_em;
}

// What one call of fix wall/mesh sums over its particles (plain: a loop;
// /kk: a reduction over threads): the reaction on the mesh, contacts,
// energy, kernel counts and warnings; maxima for the contacts that begin.
template <typename T> struct WallTally {
  T force[3], torque[3];    // reaction on the mesh (lab; torque about its axis point)
  T ncontact, ntri, energy;
  T noverflow, ndegenerate, nmerged;    // kernel counts (WallPatches)
  T near_overflow, near_builds, nunrecorded;
  T ncapped;                            // contacts with their normal damping capped (WallForce)
  T behind, deep, large, fresh;         // WallWarnings: counts
  T fresh_v, fresh_d, fresh_em;         // WallWarnings: maxima
  POLYDEM_FN WallTally()
  {
    for (int k = 0; k < 3; ++k) force[k] = torque[k] = T(0);
    ncontact = ntri = energy = noverflow = ndegenerate = nmerged = T(0);
    near_overflow = near_builds = nunrecorded = behind = deep = large = fresh = T(0);
    ncapped = T(0);
    fresh_v = fresh_d = fresh_em = T(0);
  }
  // one particle at x (lab): its forces wf, patches P, warnings w
  POLYDEM_FN void add(const Vec3<T> &x, const WallForce<T> &wf, const MeshPose<T> &mp,
                      const WallPatches<T> &P, const WallWarnings<T> &w)
  {
    const Vec3<T> tm = wall_reaction_torque(x, wf, mp);
    force[0] -= wf.f.x;
    force[1] -= wf.f.y;
    force[2] -= wf.f.z;
    torque[0] += tm.x;
    torque[1] += tm.y;
    torque[2] += tm.z;
    ncontact += T(wf.ncontact);
    ntri += T(P.ntri);
    energy += wf.energy;
    noverflow += T(P.noverflow);
    ndegenerate += T(P.ndegenerate);
    nmerged += T(P.nmerged);
    nunrecorded += T(P.nunrecorded);
    ncapped += T(wf.capped);
    behind += T(w.behind);
    deep += T(w.deep);
    large += T(w.large);
    fresh += T(w.fresh);
    fresh_v = w.fresh_v > fresh_v ? w.fresh_v : fresh_v;
    fresh_d = w.fresh_d > fresh_d ? w.fresh_d : fresh_d;
    fresh_em = w.fresh_em > fresh_em ? w.fresh_em : fresh_em;
  }
  POLYDEM_FN void operator+=(const WallTally &o) { wall_tally_merge(*this, o); }
#if defined(KOKKOS_VERSION) && KOKKOS_VERSION < 40000
  // Kokkos 3 joins through volatile references (Kokkos 4 rejects this form)
  POLYDEM_FN void operator+=(const volatile WallTally &o) volatile { wall_tally_merge(*this, o); }
#endif
};

// Per-triangle forces (fix wall/mesh pertriangle yes): each patch's force on
// the wall (-F of the patch on the particle) shared among its clipped
// triangles in proportion to their section areas A_t (by volume if the patch
// has no section area), so the triangles' forces add up to the patch force;
// for a flat patch this is a uniform pressure over the contact section.
// The shares are of the patch's totals (P), so a triangle beyond the record
// (more than WALL_MAX_CAND under one particle, counted in P.nunrecorded)
// leaves its share out rather than inflating the others.
// add(t, fx, fy, fz) receives each share (lab frame).
template <typename T, int MF, int ME, typename F>
POLYDEM_FN void wall_triangle_forces(const WallWorkspace<T, MF, ME> &ws, const WallPatches<T> &P,
                                     const WallForce<T> &wf, F &add)
{
  T asum[WALL_MAX_PATCH], vsum[WALL_MAX_PATCH];
  for (int k = 0; k < WALL_MAX_PATCH; ++k) {
    asum[k] = k < P.n ? P.p[k].area : T(0);
    vsum[k] = k < P.n ? P.p[k].volume : T(0);
  }
  for (int e = 0; e < ws.nrec; ++e) {
    const int k = ws.rpatch[e];
    const T w = asum[k] > T(0) ? ws.rarea[e] / asum[k]
                               : (vsum[k] > T(0) ? ws.rvol[e] / vsum[k] : T(0));
    if (w != T(0)) add(ws.rtri[e], -w * wf.fpatch[k].x, -w * wf.fpatch[k].y, -w * wf.fpatch[k].z);
  }
}

}    // namespace polydem

#endif
