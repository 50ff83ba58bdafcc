/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - normal contact force between two ellipsoids (ellipsoid seed
   §3.2 Eqs. 23-24, §4): linear spring on an overlap delta plus viscous
   damping from the restitution coefficient and the reduced mass.
   Frictionless as in the seed, or with Cundall-Strack friction (below). Host/device.

   Two overlap measures (pair_style ellipsoid keyword 'overlap'):
   - chord:  the seed's force F_A = -(k_n delta + gamma_n v_n) n at C with
             delta the normal chord through C (polydem_ellipsoid.h). Not the
             gradient of 1/2 k_n delta^2: an elastic gas drifts in energy
             (about 1e-3 of the collision energy per collision, measured).
   - centre: delta = r (1/W0 - 1), r = |x_B - x_A|: how far the centres must
             separate along their line to touch (r/W0 is the contact distance,
             W0 being proportional to r at fixed direction and orientations).
             Equal to the chord for spheres. The force is the exact gradient of
             1/2 k_n delta^2 (W0^2 differentiated by the envelope theorem), so
             elastic contacts conserve energy; it acts at C along n plus a
             central part of relative size (1 - W0). Damping is the Rayleigh
             force -gamma_n (d delta/dt) grad delta.
------------------------------------------------------------------------- */

#ifndef POLYDEM_ELLIPSOID_FORCE_H
#define POLYDEM_ELLIPSOID_FORCE_H

#include "polydem_ellipsoid.h"

namespace polydem {

enum EllipsoidOverlap : int { OVERLAP_CENTRE = 0, OVERLAP_CHORD = 1 };
// pair_style ellipsoid keyword 'damping': the mass in gamma_n
enum EllipsoidDampingMass : int { DAMPING_REDUCED = 0, DAMPING_CONTACT = 1 };

// gamma_n = sqrt(4 k_n m12 / (1 + (pi / ln e_n)^2)) (seed §4); 0 for e_n = 1.
template <typename T> POLYDEM_FN T ellipsoid_damping(T kn, T m12, T en)
{
  if (!(en < T(1))) return T(0);
  const T r = T(3.14159265358979323846) / log(en);
  return sqrt(T(4) * kn * m12 / (T(1) + r * r));
}

template <typename T> struct EllipsoidForce {
  Vec3<T> F_A;      // force on A (B gets -F_A)
  Vec3<T> tau_A;    // torque on A about its centre
  Vec3<T> tau_B;    // torque on B about its centre
  T energy;         // elastic energy 1/2 k_n delta^2
  T delta;          // overlap used
  T rate;           // d delta / dt (chord: approach speed along n)
};

// Gradient of delta = r (1/W0 - 1) with respect to x_B: J = (1/W0 - 1) u + P,
// with P = -(r / (2 W0^3)) gB acting at C (rotation of B: (C - x_B) x P).
template <typename T>
POLYDEM_FN void centre_overlap(const EllipsoidContact<T> &c, const Vec3<T> &xA,
                               const Vec3<T> &xB, T &delta, Vec3<T> &J, Vec3<T> &P)
{
  const Vec3<T> d = xB - xA;
  const T r = norm(d);
  const T iw = T(1) / c.W0;
  delta = r * (iw - T(1));
  P = (-T(0.5) * r * iw * iw * iw) * c.gB;
  J = ((iw - T(1)) / r) * d + P;
}

// Effective mass of the contact, m_eff = 1 / (grad(delta)^T M^-1 grad(delta)),
// M the mass matrix of both bodies (inertia of a solid ellipsoid of mass m:
// I_x = m (b^2 + c^2) / 5 and cyclic). The contact is a 1-D oscillator
// m_eff delta'' = -(k_n delta + gamma_n delta'), so gamma_n from m_eff gives every
// collision the restitution e_n; gamma_n from m12 over-damps eccentric impacts
// (m_eff < m12 when the force has a lever arm). Equals m12 for spheres.
template <typename T>
POLYDEM_FN T ellipsoid_contact_mass(const EllipsoidContact<T> &c, int overlap,
                                    const EllipsoidPose<T> &A, const EllipsoidPose<T> &B,
                                    T mA, T mB)
{
  Vec3<T> J = c.n, P = c.n;    // translational and lever (force at C) parts
  if (overlap != OVERLAP_CHORD) {
    T delta;
    centre_overlap(c, A.x, B.x, delta, J, P);
  }
  T im = norm2(J) * (T(1) / mA + T(1) / mB);
  const EllipsoidPose<T> *body[2] = {&A, &B};
  const T mass[2] = {mA, mB};
  for (int k = 0; k < 2; ++k) {
    const EllipsoidPose<T> &e = *body[k];
    const Vec3<T> g = qrotate_inv(e.q, cross(c.c - e.x, P));    // body frame
    const T a2 = e.axes.x * e.axes.x, b2 = e.axes.y * e.axes.y, c2 = e.axes.z * e.axes.z;
    const T f = T(5) / mass[k];
    im += f * (g.x * g.x / (b2 + c2) + g.y * g.y / (a2 + c2) + g.z * g.z / (a2 + b2));
  }
  return T(1) / im;
}

// F_A = -k_n delta n - gamma_n v_n n (Eq. 23) or its conservative form (see
// header); torques l x F with l = C - x (Eq. 24).
template <typename T>
POLYDEM_FN EllipsoidForce<T> ellipsoid_force(const EllipsoidContact<T> &c, int overlap, T kn,
                                            T gamma, const Vec3<T> &xA, const Vec3<T> &xB,
                                            const Vec3<T> &vA, const Vec3<T> &vB,
                                            const Vec3<T> &wA, const Vec3<T> &wB)
{
  const Vec3<T> lA = c.c - xA, lB = c.c - xB;
  // velocity of B's material point at C relative to A's
  const Vec3<T> vrel = (vB + cross(wB, lB)) - (vA + cross(wA, lA));
  EllipsoidForce<T> f;
  if (overlap == OVERLAP_CHORD) {
    const T vn = -dot(vrel, c.n);    // approach speed
    f.delta = c.delta;
    f.rate = vn;
    f.F_A = (-(kn * c.delta + gamma * vn)) * c.n;
    f.tau_A = cross(lA, f.F_A);
    f.tau_B = cross(lB, -f.F_A);
  } else {
    T delta;
    Vec3<T> J, P;
    centre_overlap(c, xA, xB, delta, J, P);
    // d delta/dt = J.(v_B - v_A) + P.(omega terms at C)
    const Vec3<T> d = xB - xA;
    const T rate = ((T(1) / c.W0 - T(1)) / norm(d)) * dot(d, vB - vA) + dot(P, vrel);
    const T s = -(kn * delta + gamma * rate);    // force on B = s J
    f.delta = delta;
    f.rate = rate;
    f.F_A = (-s) * J;
    f.tau_B = cross(lB, s * P);
    f.tau_A = cross(lA, (-s) * P);
  }
  f.energy = T(0.5) * kn * f.delta * f.delta;
  return f;
}

// Tangential friction (pair_coeff ... mu > 0; off in the seed): a Cundall-Strack
// spring on the tangential displacement s of B's material point at C relative to
// A's, kept per pair (neighbor history, antisymmetric in A and B). Each step s is
// turned into the current tangent plane (its length kept) and, when update,
// incremented by v_t dt; F_t (on B) = -k_t s - gamma_t v_t, capped at mu F_n with
// F_n = max(0, F_B . n) the normal force; on slip s = -(F_t + gamma_t v_t) / k_t.
// Torques l x F_t (Eq. 24); the spring's 1/2 k_t |s|^2 joins the pair energy.
template <typename T>
POLYDEM_FN void ellipsoid_friction(const EllipsoidContact<T> &c, EllipsoidForce<T> &f, T kt,
                                   T gammat, T mu, const Vec3<T> &xA, const Vec3<T> &xB,
                                   const Vec3<T> &vA, const Vec3<T> &vB, const Vec3<T> &wA,
                                   const Vec3<T> &wB, T dt, T *hist, bool update)
{
  const Vec3<T> n = c.n, lA = c.c - xA, lB = c.c - xB;
  const Vec3<T> vrel = (vB + cross(wB, lB)) - (vA + cross(wA, lA));
  const Vec3<T> vt = vrel - dot(vrel, n) * n;
  Vec3<T> s = make_vec3(hist[0], hist[1], hist[2]);
  const T s2 = norm2(s);
  s = s - dot(s, n) * n;
  const T p2 = norm2(s);
  s = p2 > T(0) ? sqrt(s2 / p2) * s : make_vec3(T(0), T(0), T(0));
  if (update) s = s + dt * vt;
  Vec3<T> Ft = (-kt) * s - gammat * vt;
  const T Fn = -dot(f.F_A, n);
  const T cap = mu * (Fn > T(0) ? Fn : T(0));
  const T ft = norm(Ft);
  if (ft > cap) {
    Ft = ft > T(0) ? (cap / ft) * Ft : Ft;
    s = (T(-1) / kt) * (Ft + gammat * vt);
  }
  f.F_A = f.F_A - Ft;
  f.tau_A = f.tau_A + cross(lA, -Ft);
  f.tau_B = f.tau_B + cross(lB, Ft);
  f.energy += T(0.5) * kt * norm2(s);
  if (update) {
    hist[0] = s.x;
    hist[1] = s.y;
    hist[2] = s.z;
  }
}

}    // namespace polydem

#endif
