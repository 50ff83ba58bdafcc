// Free-rotor kernel (polydem_rigid.h) against the analytic torque-free
// asymmetric top (Landau & Lifshitz, Mechanics, section 37): conservation of
// energy and of the lab angular-momentum vector, and the period of the
// intermediate-axis (Dzhanibekov) flip from the complete elliptic integral K.

#include "polydem_rigid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <initializer_list>
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

// rotor_sincos: the series for |x| <= 1/16 against libm's sin and cos at
// 20,000 angles from 1e-12 to 0.0625 (both signs) and beyond: within one
// unit in the last place everywhere, equal at >= 99 % of them (the
// comment in polydem_rigid.h: one unit apart only next to a rounding
// boundary); libm's values themselves past 1/16.
TEST(RigidKernel, RotorSincosIsLibmWithinOneUnit)
{
  int n = 0, equal = 0;
  for (int i = 0; i < 10000; i++) {
    const double mag = std::exp(std::log(1e-12) + (std::log(0.0625) - std::log(1e-12)) * i / 9999.0);
    for (double x : {mag, -mag}) {
      double s, c;
      rotor_sincos(x, s, c);
      const double rs = std::sin(x), rc = std::cos(x);
      EXPECT_LE(std::fabs(s - rs), std::fabs(std::nextafter(rs, 2.0) - rs)) << x;
      EXPECT_LE(std::fabs(c - rc), std::fabs(rc - std::nextafter(rc, 0.0))) << x;
      n += 2;
      equal += (s == rs) + (c == rc);
    }
  }
  EXPECT_GE(equal, 0.99 * n) << equal << " of " << n;
  for (double x : {0.0625001, -0.07, 0.5, 1.0, -3.0}) {
    double s, c;
    rotor_sincos(x, s, c);
    EXPECT_EQ(s, std::sin(x));
    EXPECT_EQ(c, std::cos(x));
  }
}

// free_rotor_substep's quaternion update (the product with the zero
// components left out) equals qmul(q, (cos(phi/2), sin(phi/2) e_K)) value
// for value, for each axis K.
template <int K> void substep_against_qmul(const double I[3], const double Lb0[3], const double q0[4])
{
  double Lb[3] = {Lb0[0], Lb0[1], Lb0[2]}, q[4] = {q0[0], q0[1], q0[2], q0[3]};
  const double h = 0.37;
  free_rotor_substep<K>(h, I, Lb, q);
  double sh, ch;
  rotor_sincos(0.5 * h * Lb0[K] / I[K], sh, ch);
  const Quat<double> e = make_quat(ch, K == 0 ? sh : 0.0, K == 1 ? sh : 0.0, K == 2 ? sh : 0.0);
  const Quat<double> r = qmul(make_quat(q0[0], q0[1], q0[2], q0[3]), e);
  EXPECT_EQ(q[0], r.w) << K;
  EXPECT_EQ(q[1], r.x) << K;
  EXPECT_EQ(q[2], r.y) << K;
  EXPECT_EQ(q[3], r.z) << K;
}

TEST(RigidKernel, SubstepQuaternionIsTheProduct)
{
  const double I[3] = {1.0, 2.5, 4.0};
  const double q0[4] = {0.61, -0.23, 0.47, 0.59};
  for (double scale : {1e-3, 0.1, 1.0, 7.0}) {
    const double Lb[3] = {0.31 * scale, -0.17 * scale, 0.23 * scale};
    substep_against_qmul<0>(I, Lb, q0);
    substep_against_qmul<1>(I, Lb, q0);
    substep_against_qmul<2>(I, Lb, q0);
  }
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

// ellipsoid_moments against an independent quadrature: the second moments of
// a solid ellipsoid of semi-axes (0.9, 0.5, 0.3) and mass 2 summed over the
// cells of a 240^3 grid whose centres lie inside (midpoint rule; the mass is
// rescaled to m, so the boundary's O(h) error mostly cancels: measured 3.3e-5
// relative here; tolerance 3e-4); the inverse moments are their reciprocals
// to 1e-15.
TEST(RigidKernel, EllipsoidMomentsAgainstQuadrature)
{
  const double a = 0.9, b = 0.5, c = 0.3, m = 2.0;
  const int n = 240;
  double vol = 0.0, sxx = 0.0, syy = 0.0, szz = 0.0;
  const double hx = 2 * a / n, hy = 2 * b / n, hz = 2 * c / n, dv = hx * hy * hz;
  for (int i = 0; i < n; i++)
    for (int j = 0; j < n; j++)
      for (int k = 0; k < n; k++) {
        const double x = -a + (i + 0.5) * hx, y = -b + (j + 0.5) * hy, z = -c + (k + 0.5) * hz;
        if (x * x / (a * a) + y * y / (b * b) + z * z / (c * c) > 1.0) continue;
        vol += dv;
        sxx += x * x * dv;
        syy += y * y * dv;
        szz += z * z * dv;
      }
  const double rho = m / vol;
  const double Iq[3] = {rho * (syy + szz), rho * (sxx + szz), rho * (sxx + syy)};
  const Vec3<double> I = ellipsoid_moments(m, make_vec3(a, b, c));
  const Vec3<double> Ii = ellipsoid_inverse_moments(m, make_vec3(a, b, c));
  const double Ik[3] = {I.x, I.y, I.z}, Iik[3] = {Ii.x, Ii.y, Ii.z};
  for (int k = 0; k < 3; k++) {
    EXPECT_NEAR(Ik[k], Iq[k], 3e-4 * Iq[k]) << "axis " << k;
    EXPECT_NEAR(Iik[k] * Ik[k], 1.0, 1e-15) << "axis " << k;
  }
}

// point_inverse_mass against the impulse it stands for: an impulse J n at
// r (lab) on a body of mass m, moments I, orientation q changes the point's
// velocity by dv = J n / m + dw x r, dw = R I^-1 R^T (r x J n)
// (omega_from_angmom); n . dv = J / m_c. To 1e-13, for a pair too (the sum
// of the two bodies' parts, as for an impulse +J n on A and -J n on B).
TEST(RigidKernel, ContactPointMassIsTheImpulseResponse)
{
  const double I[3] = {0.7, 1.3, 2.9}, m = 3.5, Jimp = 0.8;
  const double q[4] = {0.5, 0.5, -0.5, 0.5};
  const Vec3<double> n0 = make_vec3(0.3, -0.4, 0.87), n = (1.0 / norm(n0)) * n0, r = make_vec3(0.6, 0.2, -0.45);
  auto response = [&](const Vec3<double> &rr) {    // n . dv per unit impulse along n
    const Vec3<double> dL = Jimp * cross(rr, n);
    const double L[3] = {dL.x, dL.y, dL.z};
    double dw[3];
    omega_from_angmom(I, L, q, dw);
    const Vec3<double> dv = (Jimp / m) * n + cross(make_vec3(dw[0], dw[1], dw[2]), rr);
    return dot(n, dv) / Jimp;
  };
  const Mat3<double> R = quat_to_mat(make_quat(q[0], q[1], q[2], q[3]));
  const Vec3<double> Iinv = make_vec3(1.0 / I[0], 1.0 / I[1], 1.0 / I[2]);
  const double im = point_inverse_mass(1.0 / m, Iinv, matTvec(R, cross(r, n)));
  EXPECT_NEAR(im, response(r), 1e-13);
  // two bodies (the same one at r and at r2): relative normal velocity
  const Vec3<double> r2 = make_vec3(-0.1, 0.5, 0.3);
  const double im2 = point_inverse_mass(point_inverse_mass(2.0 / m, Iinv, matTvec(R, cross(r, n))),
                                        Iinv, matTvec(R, cross(r2, n)));
  EXPECT_NEAR(im2, response(r) + response(r2), 1e-13);
}

// lab <-> mesh frame of a moving mesh: a point mapped into the mesh frame and
// back is itself (1e-14); the mesh-frame orientation's matrix is R^T R(q);
// a point of the mesh frame at its origin o maps to the axis point o + d.
TEST(RigidKernel, MeshFrameRoundTrip)
{
  MeshPose<double> mp;
  mp.o = make_vec3(0.2, -0.1, 0.4);
  mp.d = make_vec3(1.0, 0.5, -0.3);
  mp.q = qnormalize(make_quat(0.9, 0.1, -0.3, 0.2));
  mp.R = quat_to_mat(mp.q);
  const Vec3<double> x = make_vec3(0.7, -1.2, 2.5);
  const Vec3<double> xm = mesh_point(mp, x);
  const Vec3<double> back = lab_point(mp, mesh_axis_point(mp), xm);
  EXPECT_NEAR(norm(back - x), 0.0, 1e-14);
  EXPECT_NEAR(norm(lab_point(mp, mesh_axis_point(mp), mp.o) - (mp.o + mp.d)), 0.0, 1e-15);
  const Quat<double> q = qnormalize(make_quat(0.3, -0.5, 0.1, 0.8));
  const Mat3<double> Rq = quat_to_mat(mesh_orientation(mp, q)), Rl = quat_to_mat(q);
  for (int i = 0; i < 3; i++)    // (R^T Rl) e_i
  {
    const Vec3<double> e = make_vec3(i == 0 ? 1.0 : 0.0, i == 1 ? 1.0 : 0.0, i == 2 ? 1.0 : 0.0);
    EXPECT_NEAR(norm(matvec(Rq, e) - matTvec(mp.R, matvec(Rl, e))), 0.0, 1e-14) << "column " << i;
  }
}
