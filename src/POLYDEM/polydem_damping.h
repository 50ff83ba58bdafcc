/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - normal damping ratio zeta for a restitution e (polyhedral seed
   Eqs. 14-15), shared by every contact (polydem_contact_law.h DampingLaw).
   No LAMMPS includes; host only.

   A self-similar contact with V ~ delta^a (a = 1 face, 2 edge, 3 vertex)
   and W' ~ V^q (q = 1/3 Feng's law, 1 in the quadratic core) is, in units
   where m = 1 and the impact speed is 1 (polydem_wall_contact.h),
     x'' = -x^p - c x^((p-1)/2) x',  p = a(q+1) - 1,  c = 2 zeta sqrt(q a),
   x(0) = 0, x'(0) = 1 (the dashpot 2 zeta sqrt(k m) on the local stiffness
   k = q a x^(p-1)). With y = x^((p+1)/2) and the time tau, dtau/dt =
   x^((p-1)/2), it is the linear oscillator
     y'' + c y' + (p+1)/2 y = 0  (' = d/dtau),  damping ratio
     zeta_l = zeta sqrt(2q/(q+1))   (independent of a),
   and y' = (p+1)/2 x'(t), so the restitution is
   the linear oscillator's, e = exp(-pi zeta_l / sqrt(1 - zeta_l^2)), and 0
   for zeta_l >= 1. Inverted:
     zeta(e, q) = sqrt((q+1)/(2q)) (-ln e) / sqrt(pi^2 + ln^2 e).
   Exact for every e in (0, 1] and constant cost (this replaced a numerical
   calibration whose integration took seconds, and did not end for e -> 0).
------------------------------------------------------------------------- */

#ifndef POLYDEM_DAMPING_H
#define POLYDEM_DAMPING_H

#include "polydem_contact_law.h"

#include <cmath>

namespace polydem {

// damping ratio of the contact with W' ~ V^q for restitution e (0: e >= 1)
inline double damping_ratio(double e, double q)
{
  if (!(e > 0.0) || !(e < 1.0)) return 0.0;
  const double l = std::log(e), pi = 3.14159265358979323846;
  return std::sqrt((q + 1.0) / (2.0 * q)) * (-l) / std::sqrt(pi * pi + l * l);
}

// Damping ratio of the face contact with Feng's law (q = 1/3), used by pair
// polyhedron: sqrt(2) times the linear oscillator's.
inline double damping_factor(double e)
{
  return damping_ratio(e, 1.0 / 3.0);
}

// The damping law of restitution e (polydem_contact_law.h): zeta at q = 1/3
// and q = 1; local: zeta at the contact's own exponent (walls, ellipsoids),
// else the face contact's zeta(e, 1/3) (pair polyhedron).
inline DampingLaw<double> damping_law(double e, int local)
{
  DampingLaw<double> d;
  d.z[0] = damping_ratio(e, 1.0 / 3.0);
  d.z[1] = damping_ratio(e, 1.0);
  d.local = local;
  return d;
}

}    // namespace polydem

#endif
