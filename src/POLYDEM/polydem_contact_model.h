/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - contact force model for two polyhedra from their overlap
   polyhedron (polyhedral seed §2.5), shared by pair polyhedron and /kk.
   No LAMMPS includes; host and device.

   Normal, elastic (Feng's energy-conserving model, Eqs. 12-13):
     W'(V) = K V^{1/3},  K = E_A/R_A + E_B/R_B   (R: volume-equivalent radii)
     W(V)  = 3/4 K V^{4/3} - 5/36 K V0^{4/3}                for V >= V0
   with a polynomial core below V0 (W, W', W'' continuous, W(0) = 0):
     W'(V) = K V0^{-2/3} (5/3 V - 2/3 V^2/V0)
     W(V)  = K V0^{-2/3} (5/6 V^2 - 2/9 V^3/V0)              for V <  V0
   The pure V^{1/3} law (V0 = 0) has an unbounded stiffness W''(V) A_n^2 as
   V -> 0: a flat face resting under gravity then needs time steps far below
   any practical dt and chatters. The core bounds the stiffness of small
   overlaps by 5/3 K V0^{-2/3} A_n^2 (pair_style polyhedron keyword core,
   V0 = core * smaller particle volume); it is C2, so the integrator keeps
   its second order.
     F_A = -W'(V) S_A,  tau_A = -W'(V) M_A,  tau_B = -W'(V) M_B,  F_B = -F_A
   with S_A = dV/dx_A, M = dV/dtheta from polydem_overlap.h, so the elastic
   part is exactly the negative gradient of W(V) in translation and rotation
   (|F| = K V^{1/3} A_n as in Eq. 12 with A_n = |S_A|).
   Normal damping (Eq. 14): F_A^d = -g_n (v_r.n) n, g_n = 2 zeta sqrt(k m_eff).
     Eq. 15 takes k = K A_n, the stiffness of a linear spring; the V^(1/3)
     law is far stiffer near its maximum overlap, and with that k the
     measured restitution of face-to-face cubes is 0.99 for e = 0.85. So k is
     the local normal stiffness W''(V) A_n^2 = K A_n^2 / (3 V^(2/3)) and zeta
     is chosen so that a face-to-face contact (force ~ delta^(1/3)) gives
     exactly e, whatever the impact speed (damping_factor(e), closed form in
     polydem_damping.h).
     The dashpot is capped at g_n dt <= m_eff, the explicit stability limit
     (it binds only in the first steps of a flat contact, where k -> inf).
   Tangential (Cundall-Strack, Eqs. 17-20): accumulated displacement s kept
   in the tangent plane, F_t = -k_t s - g_t v_t, k_t = K_t A_n,
   K_t = sum E/(2(1+nu)R), capped by mu |F_n| (then s is reset to match).
   The contact point is the centroid of the overlap polyhedron; v_r is the
   velocity of A relative to B there, including both spins.
------------------------------------------------------------------------- */

#ifndef POLYDEM_CONTACT_MODEL_H
#define POLYDEM_CONTACT_MODEL_H

#include "polydem_damping.h"
#include "polydem_math.h"

#include <cmath>

namespace polydem {

using std::cbrt;
using std::log;

template <typename T> struct ContactParams {
  T K;        // E_A/R_A + E_B/R_B [pressure/length]
  T Kt;       // E_A/(2(1+nu_A)R_A) + E_B/(2(1+nu_B)R_B) [pressure/length]
  T damp;     // damping ratio zeta >= 0: damping_factor(e) on the host
  T mu;       // Coulomb friction coefficient
  T meff;     // m_A m_B / (m_A + m_B)
  T dt;       // time step (tangential displacement increment)
  T V0 = T(0);    // volume below which W is quadratic (0: pure V^{1/3} law)
};

// Parameters of one contact from the two particles' Young's moduli, Poisson
// ratios, volumes (already scaled) and masses (Eqs. 13, 19; R: radius of the
// sphere of equal volume), the pair's damping ratio and friction, the core
// fraction and the time step (0 during setup: no history update).
template <typename T>
POLYDEM_FN ContactParams<T> make_contact_params(T Ei, T nui, T Vi, T mi, T Ej, T nuj, T Vj, T mj,
                                                T damp, T mu, T core, T dt)
{
  const T f = T(3) / (T(4) * T(3.14159265358979323846));
  const T Ri = cbrt(f * Vi), Rj = cbrt(f * Vj);
  ContactParams<T> p;
  p.K = Ei / Ri + Ej / Rj;
  p.Kt = Ei / (T(2) * (T(1) + nui) * Ri) + Ej / (T(2) * (T(1) + nuj) * Rj);
  p.damp = damp;
  p.mu = mu;
  p.meff = mi * mj / (mi + mj);
  p.dt = dt;
  p.V0 = core * (Vi < Vj ? Vi : Vj);
  return p;
}

// Explicit stability limit of a flat face contact (area A, e.g. the largest
// face) resting in the core: its local stiffness W''(V) A^2 is largest at
// V -> 0, W''(0) A^2 = 5/3 K V0^(-2/3) A^2, and velocity Verlet is stable for
// dt < 2 sqrt(m_eff / k). 0 if there is no core (V0 = 0: no bound).
template <typename T> POLYDEM_FN T face_contact_stable_dt(const ContactParams<T> &p, T A)
{
  if (!(p.V0 > T(0)) || !(A > T(0))) return T(0);
  const T k = T(5) / T(3) * p.K / cbrt(p.V0 * p.V0) * A * A;
  return T(2) * sqrt(p.meff / k);
}

template <typename T> struct ContactForce {
  Vec3<T> F_A;      // force on A (B gets -F_A)
  Vec3<T> tau_A;    // torque on A about x_A
  Vec3<T> tau_B;    // torque on B about x_B
  T energy;         // W(V)
  T fn;             // normal force magnitude (elastic + damping) along -n on A
  T ft;             // tangential force magnitude
};

// Geometry of one contact, as computed by polydem_overlap.h.
template <typename T> struct ContactGeometry {
  T volume;
  T area;
  Vec3<T> normal;      // from A towards B
  Vec3<T> centroid;    // contact point
  Vec3<T> S_A, M_A, M_B;
};

// The fields of an overlap result (polydem_overlap.h OverlapResult) that the
// model uses.
template <typename T, typename Overlap>
POLYDEM_FN ContactGeometry<T> contact_geometry(const Overlap &ov)
{
  ContactGeometry<T> g;
  g.volume = ov.volume;
  g.area = ov.area;
  g.normal = ov.normal;
  g.centroid = ov.centroid;
  g.S_A = ov.S_A;
  g.M_A = ov.M_A;
  g.M_B = ov.M_B;
  return g;
}

// Values of tangential history per contact: displacement (3), stiffness of
// the previous step (1).
constexpr int CONTACT_HIST = 4;

// shear: tangential history (in/out, CONTACT_HIST values: accumulated
// displacement, previous k_t). With mu = 0 the tangential part is skipped
// and shear is zeroed.
template <typename T>
POLYDEM_FN ContactForce<T> contact_force(const ContactGeometry<T> &g, const ContactParams<T> &p,
                                         const Vec3<T> &xA, const Vec3<T> &xB,
                                         const Vec3<T> &vA, const Vec3<T> &vB,
                                         const Vec3<T> &wA, const Vec3<T> &wB, T *shear)
{
  ContactForce<T> out;
  const T V = g.volume;
  T Wp, kloc;    // W'(V) (Eq. 12-13) and the local normal stiffness W''(V) A_n^2
  if (V < p.V0) {
    const T c0 = cbrt(p.V0);
    const T c = p.K / (c0 * c0);
    const T u = V / p.V0;
    Wp = c * V * (T(5) / T(3) - T(2) / T(3) * u);
    out.energy = c * V * V * (T(5) / T(6) - T(2) / T(9) * u);
    kloc = c * (T(5) / T(3) - T(4) / T(3) * u) * g.area * g.area;
  } else {
    const T v13 = cbrt(V);
    Wp = p.K * v13;
    out.energy = T(0.75) * Wp * V - T(5) / T(36) * p.K * p.V0 * cbrt(p.V0);
    kloc = v13 > T(0) ? p.K * g.area * g.area / (T(3) * v13 * v13) : T(0);
  }
  out.F_A = -Wp * g.S_A;
  out.tau_A = -Wp * g.M_A;
  out.tau_B = -Wp * g.M_B;

  const Vec3<T> n = g.normal;
  const Vec3<T> rA = g.centroid - xA, rB = g.centroid - xB;
  const Vec3<T> vr = (vA + cross(wA, rA)) - (vB + cross(wB, rB));
  const T vn = dot(vr, n);

  // normal damping, Eq. 14, with the local stiffness W''(V) A_n^2
  T gn = T(2) * p.damp * sqrt(kloc * p.meff);
  if (p.dt > T(0) && gn * p.dt > p.meff) gn = p.meff / p.dt;
  const Vec3<T> Fd = (-gn * vn) * n;
  out.F_A += Fd;
  out.tau_A += cross(rA, Fd);
  out.tau_B -= cross(rB, Fd);
  out.fn = Wp * g.area + gn * vn;
  out.ft = T(0);

  if (!(p.mu > T(0))) {
    shear[0] = shear[1] = shear[2] = shear[3] = T(0);
    return out;
  }

  // tangential, Eqs. 17-20: keep s in the current tangent plane (same length)
  Vec3<T> s = make_vec3(shear[0], shear[1], shear[2]);
  const T s0 = norm(s);
  s -= dot(s, n) * n;
  const T s1 = norm(s);
  if (s1 > T(0)) s = (s0 / s1) * s;
  const Vec3<T> vt = vr - vn * n;
  const T kt = p.Kt * g.area;
  // The stiffness k_t = K_t A_n changes with the contact area. The spring is
  // carried in incremental form: a growing area does not scale up the force
  // already stored (-k_old s), only the new increment uses k_t; a shrinking
  // area scales the force down with k_t (Mindlin unloading). Scaling a loaded
  // spring up with the area pumped energy into dense frictional packings.
  // shear[3] = k_old (magnitude: LAMMPS's history fix negates every value
  // when it copies a pair's history to the partner).
  const T kold = fabs(shear[3]);
  if (kt > kold && kt > T(0)) s = (kold / kt) * s;
  s += p.dt * vt;
  const T gt = T(2) * p.damp * sqrt(kt * p.meff);
  Vec3<T> Ft = (-kt) * s - gt * vt;
  const T ftm = norm(Ft);
  const T fmax = p.mu * fabs(out.fn);
  if (ftm > fmax) {
    // slip: cap at mu|F_n| and reset the spring to the capped force
    Ft = (ftm > T(0) ? fmax / ftm : T(0)) * Ft;
    if (kt > T(0)) s = (T(-1) / kt) * (Ft + gt * vt);
  }
  shear[0] = s.x;
  shear[1] = s.y;
  shear[2] = s.z;
  shear[3] = kt;
  out.ft = norm(Ft);
  out.F_A += Ft;
  out.tau_A += cross(rA, Ft);
  out.tau_B -= cross(rB, Ft);
  return out;
}

}    // namespace polydem

#endif
