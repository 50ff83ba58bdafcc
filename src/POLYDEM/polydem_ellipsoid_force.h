/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - the geometry of a contact between two ellipsoids for the
   contact layer (polydem_contact_law.h), and the ellipsoid seed's law:
   a linear spring on an overlap delta with viscous damping from the
   restitution coefficient (ellipsoid seed §3.2 Eqs. 23-24, §4),
   frictionless as in the seed or with Cundall-Strack friction. Host/device.

   Two overlap measures (pair_style ellipsoid keyword 'overlap'):
   - chord:  the seed's force F_A = -(k_n delta + gamma_n v_n) n at C with
             delta the normal chord through C (polydem_ellipsoid.h). Not the
             gradient of 1/2 k_n delta^2: an elastic gas drifts in energy
             (about 1e-3 of the collision energy per collision, measured).
             As a ContactGeometry: the point Jacobian of C along n.
   - centre: delta = r (1/W0 - 1), r = |x_B - x_A|: how far the centres must
             separate along their line to touch (r/W0 is the contact distance,
             W0 being proportional to r at fixed direction and orientations).
             Equal to the chord for spheres. The force is the exact gradient of
             1/2 k_n delta^2 (W0^2 differentiated by the envelope theorem), so
             elastic contacts conserve energy; it acts at C along n plus a
             central part of relative size (1 - W0). Damping is the Rayleigh
             force -gamma_n (d delta/dt) grad delta (gradient_damping).
   gamma_n = 2 zeta sqrt(k_n m) with zeta = zeta(e, q = 1) of polydem_damping.h
   is the seed's sqrt(4 k_n m / (1 + (pi / ln e_n)^2)).
------------------------------------------------------------------------- */

#ifndef POLYDEM_ELLIPSOID_FORCE_H
#define POLYDEM_ELLIPSOID_FORCE_H

#include "polydem_contact_law.h"
#include "polydem_ellipsoid.h"
#include "polydem_rigid.h"    // ellipsoid_inverse_moments, point_inverse_mass

namespace polydem {

enum EllipsoidOverlap : int { OVERLAP_CENTRE = 0, OVERLAP_CHORD = 1 };

// the tangential spring and dashpot of the linear law by default:
// k_t / k_n = 2/7, gamma_t / gamma_n = 1/2 (pair_style ellipsoid's
// 'tangential', and pair_style polyhedron's ellipsoid pairs)
constexpr double ELLIPSOID_KT_RATIO = 2.0 / 7.0;
constexpr double ELLIPSOID_GT_RATIO = 0.5;
// pair_style ellipsoid keyword 'damping': the mass in gamma_n
enum EllipsoidDampingMass : int { DAMPING_REDUCED = 0, DAMPING_CONTACT = 1 };

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

// The contact as a ContactGeometry: measure delta, its gradient (centre:
// d delta/dx_A = -J, d/dtheta_A = -(C - x_A) x P, d/dtheta_B = (C - x_B) x P;
// chord: the point force at C along n), no area.
template <typename T>
POLYDEM_FN ContactGeometry<T> ellipsoid_geometry(const EllipsoidContact<T> &c, int overlap,
                                                 const Vec3<T> &xA, const Vec3<T> &xB)
{
  ContactGeometry<T> g;
  const Vec3<T> lA = c.c - xA, lB = c.c - xB;
  g.area = T(0);
  g.normal = c.n;
  g.centroid = c.c;
  if (overlap == OVERLAP_CHORD) {
    g.volume = c.delta;
    g.S_A = c.n;
    g.M_A = cross(lA, c.n);
    g.M_B = -cross(lB, c.n);
    g.gradient_damping = 0;
  } else {
    Vec3<T> J, P;
    centre_overlap(c, xA, xB, g.volume, J, P);
    g.S_A = -J;
    g.M_A = -cross(lA, P);
    g.M_B = cross(lB, P);
    g.gradient_damping = 1;
  }
  return g;
}

// The law of a type pair: spring k_n, damping d (damping_law(e, 1): zeta at
// q = 1), friction mu with k_t = kt_ratio k_n and gamma_t = gt_ratio gamma_n
// (zeta_t = gt_ratio / sqrt(kt_ratio) zeta), the cap mu max(F_n, 0) and the
// spring's 1/2 k_t |s|^2 in the pair energy.
template <typename T>
POLYDEM_FN ContactLaw<T> ellipsoid_law(T kn, const DampingLaw<T> &d, T mu, T kt_ratio, T gt_ratio)
{
  ContactLaw<T> L;
  L.normal.kind = NORMAL_LINEAR;
  L.normal.K = kn;
  L.normal.V0 = T(0);
  L.damping = d;
  L.tangential.mu = mu;
  L.tangential.Kt = kt_ratio * kn;
  L.tangential.zeta_ratio = gt_ratio / sqrt(kt_ratio);
  L.tangential.area_scaled = 0;
  L.tangential.incremental = 0;
  L.tangential.twist = 0;
  L.tangential.cap_abs = 0;
  L.tangential.spring_energy = 1;
  return L;
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
    im = point_inverse_mass(im, ellipsoid_inverse_moments(mass[k], e.axes), g);
  }
  return T(1) / im;
}

}    // namespace polydem

#endif
