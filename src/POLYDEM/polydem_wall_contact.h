/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - contact of one convex polyhedron with a triangle mesh (fix
   wall/mesh and /kk), host and device. No LAMMPS includes.

   Seed §2.4 (Algorithm VII, Eqs. 10-11) weights a facet's force by the
   clipped section area. Here the facets a particle touches are grouped into
   patches of near-coplanar normals (|angle| < patch angle to the patch's
   first facet). Per patch the kernel's per-triangle results are summed:
     V = sum V_t,  S = sum S_t = -sum n_t A_t,  M = sum M_t
   (polydem_clip.h: prisms of a flat triangulated wall partition the space
   behind it, so V, S, M of a flat patch equal those of the infinite plane
   whatever the triangulation), and the patch is one contact of the pair
   model (polydem_contact_model.h, Eqs. 12-20):
     F = -W'(V) S,  tau = -W'(V) M   (+ damping, Cundall-Strack friction),
   so each patch force is the exact gradient of W(V_patch), with no double
   counting or spikes at shared edges and vertices. A sharp edge of the
   mesh (angle > patch angle) gives two contacts, each with its own
   tangential history.

   Wall material: a half-space of (E_w, nu_w) sized like the particle
   (R_w = R_p), so K = (E_p + E_w)/R_p, K_t likewise; m_eff = m_p.
------------------------------------------------------------------------- */

#ifndef POLYDEM_WALL_CONTACT_H
#define POLYDEM_WALL_CONTACT_H

#include "polydem_clip.h"
#include "polydem_contact_model.h"
#include "polydem_mesh_grid.h"

namespace polydem {

constexpr int WALL_MAX_PATCH = 4;    // contacts per particle and mesh
constexpr int WALL_HIST = 6;         // per patch: normal (3), shear (3)
constexpr int WALL_HIST_SIZE = WALL_MAX_PATCH * WALL_HIST;

template <typename T> struct WallPatch {
  Vec3<T> nseed;    // first facet's normal n_w (mesh frame)
  T volume, area;
  Vec3<T> S, M;     // sums (mesh frame)
  Vec3<T> ac;       // area-weighted sum of section centroids
  Vec3<T> vc;       // volume-weighted sum of volume centroids
};

template <typename T> struct WallPatches {
  int n;
  int noverflow, ndegenerate, nmerged, ntri;    // counts for the host's warnings
  WallPatch<T> p[WALL_MAX_PATCH];
};

template <typename T, int MF, int ME> struct WallAccumulate {
  const PosedShape<T> *a;
  const MeshGridView<T> *g;
  ClipWorkspace<T, MF, ME> *ws;
  WallPatches<T> *out;
  T cosmax;    // cos(patch angle)

  POLYDEM_FN void operator()(int t)
  {
    Triangle<T> tri;
    const T *q = g->tri + 9 * t;
    for (int v = 0; v < 3; ++v) tri.v[v] = make_vec3(q[3 * v], q[3 * v + 1], q[3 * v + 2]);
    const ClipResult<T> r = polyhedron_triangle(*a, tri, *ws);
    if (r.status == STATUS_SEPARATED) return;
    if (r.status == STATUS_OVERFLOW) {
      out->noverflow++;
      return;
    }
    if (r.status != STATUS_OK) {
      out->ndegenerate++;
      return;
    }
    out->ntri++;
    int k = -1;
    T best = T(-2);
    for (int i = 0; i < out->n; ++i) {
      const T c = dot(out->p[i].nseed, r.normal);
      if (c > best) {
        best = c;
        k = i;
      }
    }
    if (k < 0 || best < cosmax) {
      if (out->n < WALL_MAX_PATCH) {
        k = out->n++;
        WallPatch<T> &p = out->p[k];
        const Vec3<T> z = make_vec3(T(0), T(0), T(0));
        p.nseed = r.normal;
        p.volume = p.area = T(0);
        p.S = p.M = p.ac = p.vc = z;
      } else
        out->nmerged++;    // more facet orientations than patches: join the closest
    }
    WallPatch<T> &p = out->p[k];
    p.volume += r.volume;
    p.area += r.area;
    p.S += r.S;
    p.M += r.M;
    p.ac += r.area * r.acentroid;
    p.vc += r.volume * r.vcentroid;
  }
};

// Patches of posed particle a (mesh frame) against the mesh; r: bounding radius.
template <typename T, int MF, int ME>
POLYDEM_FN void wall_patches(const PosedShape<T> &a, const MeshGridView<T> &g, T cosmax,
                             ClipWorkspace<T, MF, ME> &ws, WallPatches<T> &out)
{
  out.n = out.noverflow = out.ndegenerate = out.nmerged = out.ntri = 0;
  WallAccumulate<T, MF, ME> acc;
  acc.a = &a;
  acc.g = &g;
  acc.ws = &ws;
  acc.out = &out;
  acc.cosmax = cosmax;
  mesh_for_each_near(g, a.x, posed_radius(a), acc);
}

// Rigid motion of the mesh: p_lab = o + d + Rm (p_mesh - o); wall velocity
// at p_lab: vw + w x (p_lab - o - d).
template <typename T> struct MeshPose {
  Vec3<T> o, d;    // rotation origin (mesh frame = lab at t=0), displacement
  Mat3<T> R;       // rotation
  Quat<T> q;       // same rotation as a quaternion
  Vec3<T> vw, w;   // translation velocity, angular velocity (lab)
};

template <typename T> struct WallForce {
  Vec3<T> f, tau;    // on the particle (torque about its centroid)
  T energy;          // sum of W(V) over patches
  int ncontact;
};

// Forces of all patches on the particle (lab frame) and the update of its
// tangential history hist[WALL_HIST_SIZE] for this mesh: each patch takes
// the old slot whose normal is closest within the patch angle (else a fresh
// spring); unmatched slots are cleared. p: contact parameters (meff = m_p).
template <typename T>
POLYDEM_FN WallForce<T> wall_forces(const WallPatches<T> &P, const MeshPose<T> &mp,
                                    const ContactParams<T> &p, T cosmax, const Vec3<T> &x,
                                    const Vec3<T> &v, const Vec3<T> &w, T *hist, bool update)
{
  WallForce<T> out;
  out.f = out.tau = make_vec3(T(0), T(0), T(0));
  out.energy = T(0);
  out.ncontact = 0;
  T newh[WALL_HIST_SIZE];
  for (int i = 0; i < WALL_HIST_SIZE; ++i) newh[i] = T(0);
  bool used[WALL_MAX_PATCH] = {false, false, false, false};
  const Vec3<T> xw = mp.o + mp.d;    // a point of the wall's rotation axis (lab)
  for (int k = 0; k < P.n; ++k) {
    const WallPatch<T> &q = P.p[k];
    const T an = norm(q.S);
    if (!(q.volume > T(0)) || !(an > T(0))) continue;
    ContactGeometry<T> g;
    g.volume = q.volume;
    g.area = an;
    g.S_A = matvec(mp.R, q.S);
    g.M_A = matvec(mp.R, q.M);
    g.M_B = make_vec3(T(0), T(0), T(0));
    g.normal = (T(1) / an) * g.S_A;    // from the particle into the wall
    const Vec3<T> cm = q.area > T(0) ? (T(1) / q.area) * q.ac : (T(1) / q.volume) * q.vc;
    g.centroid = xw + matvec(mp.R, cm - mp.o);
    // history slot with the closest normal (lab frame)
    int best = -1;
    T bc = cosmax;
    for (int s = 0; s < WALL_MAX_PATCH; ++s) {
      const T *h = hist + WALL_HIST * s;
      const T c = h[0] * g.normal.x + h[1] * g.normal.y + h[2] * g.normal.z;
      if (!used[s] && c >= bc) {
        bc = c;
        best = s;
      }
    }
    T shear[3] = {T(0), T(0), T(0)};
    if (best >= 0) {
      used[best] = true;
      for (int i = 0; i < 3; ++i) shear[i] = hist[WALL_HIST * best + 3 + i];
    }
    const ContactForce<T> cf = contact_force(g, p, x, xw, v, mp.vw, w, mp.w, shear);
    T *h = newh + WALL_HIST * out.ncontact;
    h[0] = g.normal.x;
    h[1] = g.normal.y;
    h[2] = g.normal.z;
    for (int i = 0; i < 3; ++i) h[3 + i] = shear[i];
    out.f += cf.F_A;
    out.tau += cf.tau_A;
    out.energy += cf.energy;
    out.ncontact++;
  }
  if (update)    // setup (no time step yet) leaves the history as it was
    for (int i = 0; i < WALL_HIST_SIZE; ++i) hist[i] = newh[i];
  return out;
}

// Everything for one particle (lab pose x, q, s; velocity v, spin w):
// pose into the mesh frame, patches, forces back in the lab frame.
template <typename T, int MF, int ME>
POLYDEM_FN WallForce<T> wall_particle(const ShapeView<T> &sv, const Pose<T> &lab,
                                      const MeshPose<T> &mp, const MeshGridView<T> &g,
                                      const ContactParams<T> &p, T cosmax, const Vec3<T> &v,
                                      const Vec3<T> &w, T *hist, bool update,
                                      ClipWorkspace<T, MF, ME> &ws, WallPatches<T> &P)
{
  Pose<T> pm;
  pm.x = mp.o + matTvec(mp.R, lab.x - mp.o - mp.d);
  pm.q = qmul(qconj(mp.q), lab.q);
  pm.s = lab.s;
  const PosedShape<T> a = make_posed(sv, pm);
  wall_patches(a, g, cosmax, ws, P);
  return wall_forces(P, mp, p, cosmax, lab.x, v, w, hist, update);
}

}    // namespace polydem

#endif
