// Damping calibration (issue 17, item 6): the closed-form damping ratio of
// polydem_damping.h against an independent numerical integration of the
// self-similar contact x'' = -x^p - 2 zeta sqrt(q a x^(p-1)) x', p = a(q+1)-1
// (face, edge, vertex contacts, Feng's law and the quadratic core), and its
// cost for e down to 1e-300 (it used to integrate for seconds, or not end).
#include "polydem_damping.h"
#include "polydem_wall_contact.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>

namespace {

// Restitution of the contact (a, q) with damping ratio zeta: Dormand-Prince
// 5(4) with step-size control, started from the series x = t near x = 0
// (where the damping is singular for p < 1). 0 when it does not come back.
double restitution(double zeta, double a, double q)
{
  const double p = a * (q + 1.0) - 1.0, b = q * a;
  const double c = 2.0 * zeta * std::sqrt(b);
  auto acc = [&](double x, double v) {
    if (!(x > 0.0)) return 0.0;
    const double xp = std::pow(x, p);
    return -xp - c * std::sqrt(xp / x) * v;
  };
  // start at x = t0 from the series x = t, v = 1 - c t^((p+1)/2) / ((p+1)/2):
  // the damping x^((p-1)/2) is singular at x = 0 for p < 1
  const double t0 = 1e-9, s = 0.5 * (p + 1.0);
  double x = t0, v = 1.0 - c * std::pow(t0, s) / s;
  double h = 1e-6;
  const double rtol = 1e-10, atol = 1e-16;    // per step (x, v: impact units)
  // Dormand-Prince 5(4) tableau
  static const double A[7][6] = {
      {0, 0, 0, 0, 0, 0},
      {1.0 / 5, 0, 0, 0, 0, 0},
      {3.0 / 40, 9.0 / 40, 0, 0, 0, 0},
      {44.0 / 45, -56.0 / 15, 32.0 / 9, 0, 0, 0},
      {19372.0 / 6561, -25360.0 / 2187, 64448.0 / 6561, -212.0 / 729, 0, 0},
      {9017.0 / 3168, -355.0 / 33, 46732.0 / 5247, 49.0 / 176, -5103.0 / 18656, 0},
      {35.0 / 384, 0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84}};
  static const double E[7] = {71.0 / 57600,      0,          -71.0 / 16695, 71.0 / 1920,
                              -17253.0 / 339200, 22.0 / 525, -1.0 / 40};    // b5 - b4
  double kx[7], kv[7];
  kx[0] = v;
  kv[0] = acc(x, v);
  for (int n = 0; n < 200000; n++) {
    double xs = x, vs = v;
    for (int i = 1; i < 7; i++) {
      xs = x;
      vs = v;
      for (int j = 0; j < i; j++) {
        xs += h * A[i][j] * kx[j];
        vs += h * A[i][j] * kv[j];
      }
      kx[i] = vs;
      kv[i] = acc(xs, vs);
    }
    const double xn = xs, vn = vs;    // stage 7 is the 5th-order solution (FSAL)
    double ex = 0.0, ev = 0.0;
    for (int i = 0; i < 7; i++) {
      ex += h * E[i] * kx[i];
      ev += h * E[i] * kv[i];
    }
    const double err =
        std::fmax(std::fabs(ex) / (atol + rtol * std::fmax(std::fabs(x), std::fabs(xn))),
                  std::fabs(ev) / (atol + rtol * std::fmax(std::fabs(v), std::fabs(vn))));
    if (!(err <= 1.0)) {    // reject (also NaN)
      h *= std::fmax(0.2, 0.9 * std::pow(err, -0.2));
      continue;
    }
    if (xn <= 0.0) {
      // left the contact in this step: free flight after x = 0, so the exit
      // speed is reached when x crosses 0; shrink the step onto the crossing
      if (x < 1e-14) return -vn;
      h *= std::fmax(0.05, 0.99 * x / (x - xn));
      continue;
    }
    x = xn;
    v = vn;
    kx[0] = kx[6];
    kv[0] = kv[6];
    h *= std::fmin(5.0, 0.9 * std::pow(std::fmax(err, 1e-30), -0.2));
  }
  return 0.0;    // did not come back: fully damped
}

}    // namespace

// zeta(e, q) gives restitution e for every contact shape a and law q
TEST(Damping, ClosedFormGivesTheRestitution)
{
  for (double a : {1.0, 1.5, 2.0, 3.0})
    for (double q : {1.0 / 3.0, 0.5, 1.0})
      for (double e : {0.99, 0.9, 0.5, 0.1, 0.01, 1e-4}) {
        const double z = polydem::damping_ratio(e, q);
        EXPECT_NEAR(restitution(z, a, q), e, 1e-7 * e + 1e-12)
            << "a " << a << " q " << q << " e " << e;
      }
  // the pair's face contact with Feng's law; no damping for e = 1
  EXPECT_DOUBLE_EQ(polydem::damping_factor(0.5), polydem::damping_ratio(0.5, 1.0 / 3.0));
  EXPECT_EQ(polydem::damping_factor(1.0), 0.0);
  // the contact-shape-aware damping law (walls, ellipsoids) at its nodes
  // (a = 1, 2, 3; q = 1/3, 1)
  const polydem::DampingLaw<double> d = polydem::damping_law(0.3, 1);
  for (int k : {0, 4, 8}) {
    EXPECT_NEAR(restitution(polydem::damping_zeta(d, 1.0 / 3.0), 1.0 + 0.25 * k, 1.0 / 3.0), 0.3,
                1e-7);
    EXPECT_NEAR(restitution(polydem::damping_zeta(d, 1.0), 1.0 + 0.25 * k, 1.0), 0.3, 1e-7);
  }
}

// Tiny restitutions: finite, increasing towards the critical damping
// (zeta_l = 1), and the whole wall table in well under a second.
TEST(Damping, SmallRestitutionIsCheapAndFinite)
{
  const auto t0 = std::chrono::steady_clock::now();
  double last = 0.0;
  for (double e : {0.01, 1e-4, 1e-20, 1e-300}) {
    const polydem::DampingLaw<double> d = polydem::damping_law(e, 1);
    const double z = polydem::damping_factor(e);
    EXPECT_TRUE(std::isfinite(z) && z > last) << e;
    EXPECT_LT(z, std::sqrt(2.0)) << e;
    EXPECT_LT(polydem::damping_zeta(d, 1.0), 1.0) << e;
    last = z;
  }
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_LT(s, 0.01);
}
