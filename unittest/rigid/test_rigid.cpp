// Free-rotor kernel (polydem_rigid.h) against the analytic torque-free
// asymmetric top (Landau & Lifshitz, Mechanics, section 37): conservation of
// energy and of the lab angular-momentum vector, and the period of the
// intermediate-axis (Dzhanibekov) flip from the complete elliptic integral K.

#include "polydem_rigid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

using namespace polydem;

namespace {

// complete elliptic integral of the first kind K(k), by the AGM
double ellipK(double k)
{
  double a = 1.0, b = std::sqrt(1.0 - k * k);
  for (int i = 0; i < 60 && std::fabs(a - b) > 1e-17 * a; i++) {
    const double an = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = an;
  }
  return M_PI / (2.0 * a);
}

// Half period (time between sign changes of the body-frame L_2) of the
// torque-free top with I1 < I2 < I3, from the Jacobi-elliptic solution.
double half_period(const double I[3], double L2, double twoE)
{
  const double I1 = I[0], I2 = I[1], I3 = I[2];
  double lambda, k2;
  if (L2 > twoE * I2) {    // precession about axis 3 (L^2 > 2 E I2)
    lambda = std::sqrt((I3 - I2) * (L2 - twoE * I1) / (I1 * I2 * I3));
    k2 = (I2 - I1) * (twoE * I3 - L2) / ((I3 - I2) * (L2 - twoE * I1));
  } else {    // about axis 1
    lambda = std::sqrt((I2 - I1) * (twoE * I3 - L2) / (I1 * I2 * I3));
    k2 = (I3 - I2) * (L2 - twoE * I1) / ((I2 - I1) * (twoE * I3 - L2));
  }
  return 2.0 * ellipK(std::sqrt(k2)) / lambda;
}

struct TopRun {
  double drift_energy, drift_L, measured_half_period, analytic_half_period;
  int flips;
};

TopRun run_top(const double I[3], const double wb0[3], double dt, long nsteps)
{
  double q[4] = {1, 0, 0, 0};
  // a generic initial orientation so that lab and body axes differ
  const double ang = 0.7, ax[3] = {0.3, -0.5, 0.8};
  const double n = std::sqrt(ax[0] * ax[0] + ax[1] * ax[1] + ax[2] * ax[2]);
  q[0] = std::cos(ang / 2);
  for (int k = 0; k < 3; k++) q[k + 1] = std::sin(ang / 2) * ax[k] / n;
  double L[3];
  {
    double Lb[3] = {I[0] * wb0[0], I[1] * wb0[1], I[2] * wb0[2]};
    auto r = quat_to_mat(make_quat(q[0], q[1], q[2], q[3]));
    auto l = matvec(r, make_vec3(Lb[0], Lb[1], Lb[2]));
    L[0] = l.x, L[1] = l.y, L[2] = l.z;
  }
  const double L0[3] = {L[0], L[1], L[2]};
  const double E0 = rotational_energy(I, L, q);
  const double Lmag = std::sqrt(L0[0] * L0[0] + L0[1] * L0[1] + L0[2] * L0[2]);

  double maxdE = 0.0, maxdL = 0.0;
  std::vector<double> crossings;
  double prev = 0.0;
  for (long s = 1; s <= nsteps; s++) {
    free_rotor_step(dt, I, L, q);
    const double E = rotational_energy(I, L, q);
    maxdE = std::fmax(maxdE, std::fabs(E - E0) / E0);
    for (int k = 0; k < 3; k++) maxdL = std::fmax(maxdL, std::fabs(L[k] - L0[k]) / Lmag);
    auto r = quat_to_mat(make_quat(q[0], q[1], q[2], q[3]));
    const double lb2 = matTvec(r, make_vec3(L[0], L[1], L[2])).y;
    if (s > 1 && (lb2 > 0) != (prev > 0)) {
      // linear interpolation of the crossing time
      const double t = dt * (s - 1 + prev / (prev - lb2));
      crossings.push_back(t);
    }
    prev = lb2;
  }
  TopRun out;
  out.drift_energy = maxdE;
  out.drift_L = maxdL;
  out.flips = (int) crossings.size();
  out.measured_half_period = crossings.size() > 1
      ? (crossings.back() - crossings.front()) / (crossings.size() - 1)
      : 0.0;
  out.analytic_half_period = half_period(I, Lmag * Lmag, 2.0 * E0);
  return out;
}

}    // namespace

// Acceptance (issue 2, item 2): I = 1:2:3, 1e6 steps, drift of kinetic energy
// and of the lab angular-momentum vector <= 1e-6, flip period within 1 %.
TEST(RigidKernel, AsymmetricTopIntermediateAxisFlip)
{
  const double I[3] = {1.0, 2.0, 3.0};
  const double wb0[3] = {0.01, 1.0, 0.01};    // close to the intermediate axis
  const TopRun r = run_top(I, wb0, 1.0e-3, 1000000);
  std::printf("1e6 steps: energy drift %.3g, L drift %.3g, %d flips, half period %.6f vs "
              "analytic %.6f\n", r.drift_energy, r.drift_L, r.flips, r.measured_half_period,
              r.analytic_half_period);
  EXPECT_LE(r.drift_energy, 1e-6);
  EXPECT_LE(r.drift_L, 1e-6);
  ASSERT_GE(r.flips, 6) << "the intermediate axis must flip several times in 1000 time units";
  EXPECT_NEAR(r.measured_half_period / r.analytic_half_period, 1.0, 0.01)
      << "measured " << r.measured_half_period << " analytic " << r.analytic_half_period;
}

// Precession about the largest axis (other branch of the analytic solution).
TEST(RigidKernel, AsymmetricTopAboutMajorAxis)
{
  const double I[3] = {1.0, 2.0, 3.0};
  const double wb0[3] = {0.2, 0.6, 1.0};
  const TopRun r = run_top(I, wb0, 1.0e-3, 200000);
  EXPECT_LE(r.drift_energy, 1e-6);
  EXPECT_LE(r.drift_L, 1e-6);
  ASSERT_GE(r.flips, 4);
  EXPECT_NEAR(r.measured_half_period / r.analytic_half_period, 1.0, 0.01);
}

// Energy error is second order in dt (the splitting is symmetric), and
// bounded, not drifting.
TEST(RigidKernel, SecondOrderEnergyError)
{
  const double I[3] = {1.0, 2.0, 3.0};
  const double wb0[3] = {0.5, 0.9, 0.3};
  const double e1 = run_top(I, wb0, 0.02, 5000).drift_energy;
  const double e2 = run_top(I, wb0, 0.01, 10000).drift_energy;
  EXPECT_GT(e1, 0.0);
  EXPECT_NEAR(std::log2(e1 / e2), 2.0, 0.3) << e1 << " " << e2;
}

// Time reversibility: forward n steps, negate L, forward n steps, negate L:
// back to the start to round-off.
TEST(RigidKernel, TimeReversible)
{
  const double I[3] = {1.0, 2.5, 4.0};
  double q[4] = {0.9, 0.1, -0.3, 0.2};
  const double n = std::sqrt(0.81 + 0.01 + 0.09 + 0.04);
  for (double &c : q) c /= n;
  double L[3] = {0.3, -1.2, 0.7};
  const double q0[4] = {q[0], q[1], q[2], q[3]}, L0[3] = {L[0], L[1], L[2]};
  for (int s = 0; s < 1000; s++) free_rotor_step(0.01, I, L, q);
  for (double &c : L) c = -c;
  for (int s = 0; s < 1000; s++) free_rotor_step(0.01, I, L, q);
  for (double &c : L) c = -c;
  // q and -q are the same rotation
  const double sgn = (q[0] * q0[0] + q[1] * q0[1] + q[2] * q0[2] + q[3] * q0[3]) < 0 ? -1 : 1;
  for (int k = 0; k < 4; k++) EXPECT_NEAR(sgn * q[k], q0[k], 1e-12);
  for (int k = 0; k < 3; k++) EXPECT_NEAR(L[k], L0[k], 1e-12);
}

// omega_from_angmom and angmom_from_omega are inverses; a sphere-like body
// (equal moments) spins about L with |w| = |L|/I.
TEST(RigidKernel, OmegaAngmomRoundTrip)
{
  const double I[3] = {0.7, 1.3, 2.9};
  double q[4] = {0.5, 0.5, -0.5, 0.5};
  const double w[3] = {0.4, -2.0, 1.1};
  double L[3], w2[3];
  angmom_from_omega(I, w, q, L);
  omega_from_angmom(I, L, q, w2);
  for (int k = 0; k < 3; k++) EXPECT_NEAR(w2[k], w[k], 1e-14);
  const double Is[3] = {2.0, 2.0, 2.0};
  omega_from_angmom(Is, L, q, w2);
  for (int k = 0; k < 3; k++) EXPECT_NEAR(w2[k], L[k] / 2.0, 1e-14);
}

// A particle from its template: a template of volume V and unit-density
// moments J at scale s and density rho has m = rho V s^3 and I = m s^2 J / V.
// Against the analytic solids: a cube of edge 2 (template edge 1, s = 2,
// rho = 3: m = 24, I = m a^2 / 6 = 16) and an ellipsoid of semi-axes
// s (a, b, c) (I_x = m s^2 (b^2 + c^2) / 5), to 1e-14.
TEST(RigidKernel, ParticleFromTemplateTimesScale)
{
  const double Jcube[3] = {1.0 / 6.0, 1.0 / 6.0, 1.0 / 6.0};
  const double m = scaled_mass(3.0, 1.0, 2.0);
  EXPECT_DOUBLE_EQ(m, 24.0);
  EXPECT_DOUBLE_EQ(scaled_density(m, 1.0, 2.0), 3.0);
  double I[3];
  scaled_moments(m, 2.0, 1.0, Jcube, I);
  for (int k = 0; k < 3; k++) EXPECT_NEAR(I[k], 16.0, 1e-14 * 16.0);

  const double a = 0.3, b = 0.2, c = 0.1, s = 1.7, rho = 2500.0;
  const double V = 4.0 / 3.0 * M_PI * a * b * c;
  const double J[3] = {V * (b * b + c * c) / 5.0, V * (a * a + c * c) / 5.0,
                       V * (a * a + b * b) / 5.0};
  const double me = scaled_mass(rho, V, s);
  EXPECT_NEAR(me, rho * 4.0 / 3.0 * M_PI * (s * a) * (s * b) * (s * c), 1e-14 * me);
  scaled_moments(me, s, V, J, I);
  const double ax[3] = {s * a, s * b, s * c};
  for (int k = 0; k < 3; k++) {
    const double p = ax[(k + 1) % 3], q = ax[(k + 2) % 3];
    EXPECT_NEAR(I[k], me * (p * p + q * q) / 5.0, 1e-14 * I[k]) << "axis " << k;
  }
}
