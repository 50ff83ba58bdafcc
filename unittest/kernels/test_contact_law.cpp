// The parts of the contact law (polydem_contact_law.h, issue 16) against
// analytic results: continuity of Feng's law and its core (W, W', W''),
// the restitution of a flat contact (Feng and linear laws), the Coulomb cap,
// the incremental tangential stiffness on area growth and shrinkage, the
// twisting part (stiffness and Coulomb torque of the disk of the contact
// area), the rolling resistance (EPSD, Ai et al. 2011: spring, cap,
// dashpot, and a sphere rolling to rest on a flat against the closed form),
// and the history sign convention (swapping A and B).
#include "polydem_contact_law.h"
#include "polydem_damping.h"
#include "polydem_ellipsoid_force.h"

#include <gtest/gtest.h>

#include <cmath>

using polydem::ContactGeometry;
using polydem::ContactKinematics;
using polydem::ContactLaw;
using polydem::make_vec3;
using polydem::Vec3;

namespace {

const double PI = 3.14159265358979323846;
const int NR = polydem::CONTACT_HIST_ROLL;    // history values with rolling resistance

// a face contact of area A along +x (A towards B), overlap volume V
ContactGeometry<double> face(double V, double A, const Vec3<double> &c)
{
  ContactGeometry<double> g;
  g.volume = V;
  g.area = A;
  g.normal = make_vec3(1.0, 0.0, 0.0);
  g.centroid = c;
  g.S_A = A * g.normal;
  g.M_A = g.M_B = make_vec3(0.0, 0.0, 0.0);
  g.gradient_damping = 0;
  return g;
}

ContactKinematics<double> still(double meff, double dt)
{
  ContactKinematics<double> k;
  k.xA = make_vec3(0.0, 0.0, 0.0);
  k.xB = make_vec3(1.0, 0.0, 0.0);
  k.vA = k.vB = k.wA = k.wB = make_vec3(0.0, 0.0, 0.0);
  k.meff = meff;
  k.dt = dt;
  return k;
}

ContactLaw<double> feng(double e, double mu, int local, int twist, double core = 1e-4)
{
  return polydem::feng_law(1e7, 0.3, 1e-3, 1e7, 0.3, 1e-3, polydem::damping_law(e, local), mu,
                           core, twist);
}

}    // namespace

// W, W' and W'' A^2 are continuous at V0, W(0) = 0, W' = dW/dV and
// k = dW'/dV A^2 (central differences), and q = dlnW'/dlnV
TEST(ContactLaw, FengCoreIsC2AndConsistent)
{
  const auto L = feng(0.5, 0.0, 0, 0, 1e-2).normal;
  const double A = 0.02, V0 = L.V0;
  ASSERT_GT(V0, 0.0);
  const auto below = polydem::normal_value(L, V0 * (1 - 1e-12), A);
  const auto above = polydem::normal_value(L, V0, A);
  EXPECT_NEAR(below.W, above.W, 1e-9 * above.W);
  EXPECT_NEAR(below.Wp, above.Wp, 1e-9 * above.Wp);
  EXPECT_NEAR(below.k, above.k, 1e-9 * above.k);
  EXPECT_NEAR(below.q, above.q, 1e-9);
  EXPECT_EQ(polydem::normal_value(L, 0.0, A).W, 0.0);
  for (double V : {0.1 * V0, 0.7 * V0, 3.0 * V0, 100.0 * V0}) {
    const double h = 1e-5 * V;
    const auto m = polydem::normal_value(L, V - h, A), p = polydem::normal_value(L, V + h, A);
    const auto c = polydem::normal_value(L, V, A);
    EXPECT_NEAR((p.W - m.W) / (2 * h), c.Wp, 1e-7 * c.Wp) << V / V0;
    EXPECT_NEAR((p.Wp - m.Wp) / (2 * h) * A * A, c.k, 1e-6 * c.k) << V / V0;
    EXPECT_NEAR((std::log(p.Wp) - std::log(m.Wp)) / (std::log(V + h) - std::log(V - h)), c.q,
                1e-6)
        << V / V0;
  }
  // above the core: W' = K V^(1/3) (Eq. 12)
  EXPECT_NEAR(polydem::normal_value(L, 8.0 * V0, A).Wp, L.K * std::cbrt(8.0 * V0),
              1e-12 * L.K * std::cbrt(8.0 * V0));
}

// A face contact V = A delta of a body (mass m) on a fixed one: the normal
// speed after the contact is e times that before (closed-form damping,
// polydem_damping.h), for the pair's zeta(e, 1/3) and the local zeta(e, q),
// and for the linear spring of the ellipsoid law.
namespace {
double bounce(const ContactLaw<double> &L, bool linear, double v0 = 5.0)
{
  const double m = 1.0, A = 0.01;    // a cube of side 0.1 (volume 1e-3), rho 1000
  // largest overlap from the energy (above the core: W = 3/4 K V^(4/3)),
  // time step t_c / ~4000
  const double dmax = linear ? v0 * std::sqrt(m / L.normal.K)
                             : std::pow(2.0 / 3.0 * m * v0 * v0 / L.normal.K, 0.75) / A;
  const double dt = dmax / v0 / 2000.0;
  double x = 0.0, v = v0;    // overlap delta, its rate
  auto force = [&](double d, double vd) {
    ContactGeometry<double> g = face(linear ? d : A * d, linear ? 0.0 : A,
                                     make_vec3(0.0, 0.0, 0.0));
    if (linear) g.S_A = g.normal;
    ContactKinematics<double> k = still(m, dt);
    k.vA = make_vec3(vd, 0.0, 0.0);
    double h[polydem::CONTACT_HIST] = {0, 0, 0, 0, 0};
    return polydem::contact_step(g, L, k, h, polydem::CONTACT_HIST).F_A.x;
  };
  double f = 0.0;
  for (int n = 0; n < 1000000 && x >= 0.0; n++) {    // velocity Verlet, as fix nve
    v += 0.5 * dt * f / m;
    x += dt * v;
    f = x > 0.0 ? force(x, v) : 0.0;
    v += 0.5 * dt * f / m;
  }
  return -v / v0;
}
}    // namespace

// Self-similar regimes, where the closed form is exact: above the core
// (core 1e-6, 5 m/s: W' ~ V^(1/3), q = 1/3) and deep in it (core 1e-2,
// 0.05 m/s: W' ~ V, q = 1). The contact-shape-aware law (local) is right in
// both; the face calibration zeta(e, 1/3) alone over-damps contacts in the
// core by sqrt(2) (e = 0.5 rebounds with 0.37). In the transition (V_max ~
// V0) the local law is within 7 % for e = 0.1 and 2 % for e >= 0.5
// (measured over core 1e-6..1e-2, 0.05..5 m/s).
TEST(ContactLaw, FlatContactRestitution)
{
  for (double e : {0.1, 0.5, 0.9}) {
    EXPECT_NEAR(bounce(feng(e, 0.0, 0, 0, 1e-6), false, 5.0), e, 0.002 * e) << "face zeta, e " << e;
    EXPECT_NEAR(bounce(feng(e, 0.0, 1, 0, 1e-6), false, 5.0), e, 0.015 * e) << "local, e " << e;
    EXPECT_NEAR(bounce(feng(e, 0.0, 1, 0, 1e-2), false, 0.05), e, 0.002 * e) << "local, core, e " << e;
    EXPECT_LT(bounce(feng(e, 0.0, 0, 0, 1e-2), false, 0.05), 0.97 * e) << "face zeta in the core";
    const auto lin = polydem::ellipsoid_law(1e4, polydem::damping_law(e, 1), 0.0, 2.0 / 7.0, 0.5);
    EXPECT_NEAR(bounce(lin, true), e, 0.002 * e) << "linear, e " << e;
  }
  EXPECT_NEAR(bounce(feng(1.0, 0.0, 1, 0, 1e-4), false, 0.5), 1.0, 1e-6);
}

// The normal dashpot g = 2 zeta sqrt(k m_eff) (seed Eq. 14) is capped at
// g dt = m_eff, beyond which the explicit step would reverse the approach
// instead of damping it; the force says when (ContactForce::capped, counted
// and warned about by the styles). Below the cap: g exactly, capped = 0.
TEST(ContactLaw, DashpotCapIsFlagged)
{
  const double A = 1e-4, V = 1e-7, meff = 0.01, v = 0.3;    // A approaches B along +x
  const auto L = feng(0.2, 0.0, 0, 0);
  const auto g = face(V, A, make_vec3(0.5, 0.0, 0.0));
  const auto nv = polydem::normal_value(L.normal, V, A);
  const double zeta = polydem::damping_zeta(L.damping, nv.q);
  const double gfull = 2.0 * zeta * std::sqrt(nv.k * meff), dt_cap = meff / gfull;
  for (double f : {0.5, 2.0}) {
    auto k = still(meff, f * dt_cap);
    k.vA = make_vec3(v, 0.0, 0.0);
    double h[polydem::CONTACT_HIST] = {0, 0, 0, 0, 0};
    const auto out = polydem::contact_step(g, L, k, h, polydem::CONTACT_HIST);
    const double gn = f < 1.0 ? gfull : meff / k.dt;
    // the elastic part pushes A along -x; the dashpot opposes the approach
    const double want = -nv.Wp * A - gn * v;
    EXPECT_NEAR(out.F_A.x, want, 1e-12 * std::fabs(want)) << "dt / dt_cap " << f;
    EXPECT_EQ(out.capped, f < 1.0 ? 0 : 1) << "dt / dt_cap " << f;
  }
}

// Sliding: |F_t| = mu F_n, opposite to the slip; sticking (small s): the
// spring and dashpot, below the cap
TEST(ContactLaw, CoulombCapAndStick)
{
  const double mu = 0.4, A = 1e-4, V = 1e-7, dt = 1e-4;
  const auto L = feng(0.5, mu, 0, 0);
  const auto g = face(V, A, make_vec3(0.5, 0.0, 0.0));
  auto k = still(0.01, dt);
  k.vA = make_vec3(0.0, 2.0, 0.0);    // slip along +y
  double h[polydem::CONTACT_HIST] = {0, 0, 0, 0, 0};
  auto f = polydem::contact_step(g, L, k, h, polydem::CONTACT_HIST);
  for (int n = 0; n < 100; n++) f = polydem::contact_step(g, L, k, h, polydem::CONTACT_HIST);
  EXPECT_NEAR(std::fabs(f.F_A.y), mu * f.fn, 1e-12 * mu * f.fn);
  EXPECT_LT(f.F_A.y, 0.0);
  EXPECT_NEAR(f.ft, mu * f.fn, 1e-12 * f.fn);
  // stick: a tiny stored displacement and no velocity
  double h2[polydem::CONTACT_HIST] = {0, 1e-9, 0, L.tangential.Kt * A, 0};
  const auto f2 = polydem::contact_step(g, L, still(0.01, 0.0), h2, polydem::CONTACT_HIST);
  EXPECT_NEAR(f2.F_A.y, -L.tangential.Kt * A * 1e-9, 1e-12 * L.tangential.Kt * A * 1e-9);
  EXPECT_LT(f2.ft, mu * f2.fn);
  // the cap uses |F_n| for the seed's polyhedra, max(F_n, 0) otherwise
  EXPECT_EQ(L.tangential.cap_abs, 1);
}

// Incremental k_t = K_t A_n: a growing area keeps the stored force
// (k_old s), a shrinking one scales it with the area
TEST(ContactLaw, IncrementalTangentialStiffness)
{
  const auto L = feng(0.5, 10.0, 0, 0);    // large mu: no slip
  const double A = 1e-4, s = 1e-8, kold = L.tangential.Kt * A;
  const Vec3<double> c = make_vec3(0.5, 0.0, 0.0);
  for (double grow : {2.0, 0.5}) {
    double h[polydem::CONTACT_HIST] = {0, s, 0, kold, 0};
    const auto f = polydem::contact_step(face(1e-7, grow * A, c), L, still(0.01, 0.0), h,
                                         polydem::CONTACT_HIST);
    const double expect = grow > 1.0 ? kold * s : grow * kold * s;
    EXPECT_NEAR(-f.F_A.y, expect, 1e-12 * expect) << grow;
    EXPECT_DOUBLE_EQ(h[3], grow * kold);
  }
  // without the incremental rule the stored force scales with the area
  auto L2 = L;
  L2.tangential.incremental = 0;
  double h[polydem::CONTACT_HIST] = {0, s, 0, kold, 0};
  const auto f = polydem::contact_step(face(1e-7, 2.0 * A, c), L2, still(0.01, 0.0), h,
                                       polydem::CONTACT_HIST);
  EXPECT_NEAR(-f.F_A.y, 2.0 * kold * s, 1e-12 * kold * s);
}

// Twisting: torque -k_r phi with k_r = k_t A / (2 pi) for a small twist;
// capped at mu F_n 2/3 sqrt(A / pi) when spinning; nothing without 'twist'
TEST(ContactLaw, TwistingStiffnessAndCoulombTorque)
{
  const double mu = 0.5, A = 1e-4, phi = 1e-6;
  const auto L = feng(0.5, mu, 0, 1);
  const auto g = face(1e-7, A, make_vec3(0.5, 0.0, 0.0));
  const double kt = L.tangential.Kt * A;
  double h[polydem::CONTACT_HIST] = {0, 0, 0, kt, phi};
  const auto f = polydem::contact_step(g, L, still(0.01, 0.0), h, polydem::CONTACT_HIST);
  const double kr = kt * A / (2.0 * PI);
  EXPECT_NEAR(f.tau_A.x, -kr * phi, 1e-12 * kr * phi);
  EXPECT_NEAR(f.tau_B.x, kr * phi, 1e-12 * kr * phi);
  auto k = still(0.01, 1e-6);
  k.wA = make_vec3(5000.0, 0.0, 0.0);    // spin about n
  double h2[polydem::CONTACT_HIST] = {0, 0, 0, kt, 0};
  double last = 0.0;
  for (int n = 0; n < 1000; n++) last = polydem::contact_step(g, L, k, h2, polydem::CONTACT_HIST).tau_A.x;
  const auto f2 = polydem::contact_step(g, L, k, h2, polydem::CONTACT_HIST);
  const double cap = mu * f2.fn * 2.0 / 3.0 * std::sqrt(A / PI);
  EXPECT_NEAR(last, -cap, 1e-12 * cap);
  auto L0 = L;
  L0.tangential.twist = 0;
  double h3[polydem::CONTACT_HIST] = {0, 0, 0, kt, phi};
  EXPECT_EQ(polydem::contact_step(g, L0, k, h3, polydem::CONTACT_HIST).tau_A.x, 0.0);
  EXPECT_EQ(h3[polydem::HIST_TWIST], 0.0);
}

// The same contact seen as (A, B) and as (B, A), with the history oriented
// by tags: opposite forces, the same stored history
TEST(ContactLaw, HistorySignConventionIsSymmetric)
{
  auto L = feng(0.5, 0.3, 0, 1);
  L.rolling.mu_r = 0.05;
  const double A = 1e-4;
  ContactGeometry<double> g = face(1e-7, A, make_vec3(0.5, 0.1, 0.0));
  g.M_A = make_vec3(0.0, 0.0, 1e-6);
  g.M_B = make_vec3(0.0, 0.0, -1e-6);
  ContactGeometry<double> r = g;    // B as A
  r.normal = -g.normal;
  r.S_A = -g.S_A;
  r.M_A = g.M_B;
  r.M_B = g.M_A;
  ContactKinematics<double> k = still(0.01, 1e-6);
  k.vA = make_vec3(0.1, 0.3, -0.2);
  k.wA = make_vec3(3.0, 1.0, 0.0);
  k.mA = 0.01;
  k.mB = 0.02;
  ContactKinematics<double> kr = k;
  kr.mA = k.mB;
  kr.mB = k.mA;
  kr.xA = k.xB;
  kr.xB = k.xA;
  kr.vA = k.vB;
  kr.vB = k.vA;
  kr.wA = k.wB;
  kr.wB = k.wA;
  double stored[NR] = {0, 2e-9, -1e-9, L.tangential.Kt * A, 1e-7, 0, 3e-9, -2e-9};
  double h1[NR], h2[NR];
  for (int i = 0; i < NR; i++) h1[i] = h2[i] = stored[i];
  // tag(A) = 1 < tag(B) = 2: A's history as stored; listed as (B, A): sign -1
  const double s1 = polydem::contact_history_sign(1, 2), s2 = polydem::contact_history_sign(2, 1);
  polydem::history_orient(h1, NR, s1);
  polydem::history_orient(h2, NR, s2);
  const auto f1 = polydem::contact_step(g, L, k, h1, NR);
  const auto f2 = polydem::contact_step(r, L, kr, h2, NR);
  polydem::history_orient(h1, NR, s1);
  polydem::history_orient(h2, NR, s2);
  const double F = polydem::norm(f1.F_A), T = polydem::norm(f1.tau_A);
  EXPECT_NEAR(polydem::norm(f1.F_A + f2.F_A), 0.0, 1e-12 * F);
  EXPECT_NEAR(polydem::norm(f1.tau_A - f2.tau_B), 0.0, 1e-12 * T);
  EXPECT_NEAR(polydem::norm(f1.tau_B - f2.tau_A), 0.0, 1e-12 * T);
  for (int i = 0; i < NR; i++) EXPECT_NEAR(h1[i], h2[i], 1e-12 * std::fabs(h1[i]) + 1e-30) << i;
}

// ---------------------------------------------------------------------------
// rolling resistance (EPSD, Ai, Chen, Rotter and Ooi, Powder Technol. 206
// (2011) 269, model C)

namespace {


// a sphere of radius R (centre x_A) on a wall below it: point contact at the
// sphere's lowest point, overlap delta, normal -z (A towards B)
ContactGeometry<double> on_floor(const Vec3<double> &x, double R)
{
  ContactGeometry<double> g;
  g.normal = make_vec3(0.0, 0.0, -1.0);
  g.volume = R - x.z;
  g.area = 0.0;
  g.centroid = make_vec3(x.x, x.y, 0.0);
  g.S_A = g.normal;
  g.M_A = g.M_B = make_vec3(0.0, 0.0, 0.0);
  g.gradient_damping = 0;
  return g;
}

ContactLaw<double> linear_rolling(double kn, double e, double mu, double mu_r)
{
  auto L = polydem::ellipsoid_law(kn, polydem::damping_law(e, 1), mu, 2.0 / 7.0, 0.5);
  L.rolling.mu_r = mu_r;
  return L;
}

}    // namespace

// The spring: M = -k_r theta with k_r = 2.25 k_n mu_r^2 R_r^2 (Eq. 13) for a
// small relative rotation, R_r = r_A on a wall and r_A r_B / (r_A + r_B) on a
// pair; the cap mu_r R_r F_n (Eq. 14) when spinning on; the spring's energy
// |M|^2 / (2 k_r); rolling about n (spin) is not resisted; mu_r = 0 clears it.
TEST(ContactLaw, RollingSpringCapAndEnergy)
{
  const double kn = 1e5, R = 0.01, mu_r = 0.1, dt = 1e-6, w = 0.5, delta = 1e-5;
  const auto L = linear_rolling(kn, 0.5, 0.0, mu_r);    // frictionless: rolling alone
  const Vec3<double> x = make_vec3(0.0, 0.0, R - delta);
  const auto g = on_floor(x, R);
  const double rA = R - delta;    // centre to contact point: R_r on a wall
  const double kr = 2.25 * kn * mu_r * mu_r * rA * rA;
  auto k = still(0.01, dt);
  k.xA = x;
  k.xB = make_vec3(0.0, 0.0, -1.0);
  k.mA = 0.01;    // mB = 0: a wall
  k.wA = make_vec3(0.0, w, 0.0);
  double h[NR] = {0, 0, 0, 0, 0, 0, 0, 0};
  auto f = polydem::contact_step(g, L, k, h, NR);
  // one step: the spring's torque -k_r w dt, the dashpot -C_r w below the cap
  const double Ir = 7.0 / 5.0 * 0.01 * rA * rA;
  const double Cr = 2.0 * 0.3 * std::sqrt(Ir * kr);
  EXPECT_NEAR(h[polydem::HIST_ROLL + 1], -kr * w * dt, 1e-12 * kr * w * dt);
  EXPECT_NEAR(f.tau_A.y, -kr * w * dt - Cr * w, 1e-10 * Cr * w);
  EXPECT_NEAR(f.tau_B.y, -f.tau_A.y, 1e-15);
  // spinning on: the torque capped at mu_r R_r F_n, the spring at the cap
  // less the dashpot's torque
  for (int n = 0; n < 20000; n++) f = polydem::contact_step(g, L, k, h, NR);
  const double cap = mu_r * rA * f.fn;
  EXPECT_NEAR(f.fn, kn * delta, 1e-9 * kn * delta);
  EXPECT_NEAR(f.tau_A.y, -cap, 1e-12 * cap);
  const double Mk = -cap + Cr * w;
  EXPECT_NEAR(h[polydem::HIST_ROLL + 1], Mk, 1e-12 * cap);
  EXPECT_NEAR(f.energy, 0.5 * kn * delta * delta + 0.5 * Mk * Mk / kr, 1e-12 * f.energy);
  // spin about n: no rolling torque
  double h2[NR] = {0, 0, 0, 0, 0, 0, 0, 0};
  auto ks = k;
  ks.wA = make_vec3(0.0, 0.0, w);
  EXPECT_EQ(polydem::norm(polydem::contact_step(g, L, ks, h2, NR).tau_A), 0.0);
  // a pair (mB > 0): R_r = r_A r_B / (r_A + r_B)
  auto kp = k;
  kp.mB = 0.02;
  kp.xB = make_vec3(0.0, 0.0, -3.0 * R);
  const double rB = 3.0 * R, Rr = rA * rB / (rA + rB);
  const double kr_pair = 2.25 * kn * mu_r * mu_r * Rr * Rr;
  double h3[NR] = {0, 0, 0, 0, 0, 0, 0, 0};
  const auto fp = polydem::contact_step(g, L, kp, h3, NR);
  EXPECT_NEAR(h3[polydem::HIST_ROLL + 1], -kr_pair * w * dt, 1e-12 * kr_pair * w * dt);
  // the pair's dashpot: I_r^-1 = sum 5 / (7 m_k r_k^2)
  const double Ir_pair = 1.0 / (5.0 / (7.0 * 0.01 * rA * rA) + 5.0 / (7.0 * 0.02 * rB * rB));
  EXPECT_NEAR(fp.tau_A.y, -kr_pair * w * dt - 0.6 * std::sqrt(Ir_pair * kr_pair) * w,
              1e-10 * std::fabs(fp.tau_A.y));
  // mu_r = 0: no torque, the rolling history cleared
  auto L0 = L;
  L0.rolling.mu_r = 0.0;
  double h4[NR] = {0, 0, 0, 0, 0, 1e-9, 2e-9, 0};
  EXPECT_EQ(polydem::norm(polydem::contact_step(g, L0, kp, h4, NR).tau_A), 0.0);
  EXPECT_EQ(h4[polydem::HIST_ROLL], 0.0);
  EXPECT_EQ(h4[polydem::HIST_ROLL + 1], 0.0);
}

namespace {

// A sphere (mass m, radius R, I = 2/5 m R^2) rolling on the floor z = 0
// along +x, started rolling without slip at v0, gravity g at an angle alpha
// of the floor (pulling along -x for alpha > 0), integrated by velocity
// Verlet with the law of the contact. Returns the distance to the first
// stop (vx <= 0), or the speed at t_end if it has not stopped by then.
struct RollResult {
  double stop_x, stop_t, v_end;
  bool stopped;
};

RollResult roll(double v0, double alpha, double mu_r, double t_end)
{
  const double R = 0.01, rho = 2500.0, grav = 9.81, kn = 1e5;
  const double m = 4.0 / 3.0 * PI * R * R * R * rho, I = 0.4 * m * R * R;
  const double dt = 1e-5;    // t_c = pi sqrt(m / k_n) = 1e-3
  const auto L = linear_rolling(kn, 0.5, 0.5, mu_r);
  const Vec3<double> gvec = make_vec3(-grav * std::sin(alpha), 0.0, -grav * std::cos(alpha));
  Vec3<double> x = make_vec3(0.0, 0.0, R + m * gvec.z / kn);
  Vec3<double> v = make_vec3(v0, 0.0, 0.0), w = make_vec3(0.0, v0 / R, 0.0);
  double h[NR] = {0, 0, 0, 0, 0, 0, 0, 0};
  auto force = [&](Vec3<double> &F, Vec3<double> &T) {
    ContactKinematics<double> k;
    k.xA = x;
    k.xB = make_vec3(x.x, x.y, -1.0);
    k.vA = v;
    k.wA = w;
    k.vB = k.wB = make_vec3(0.0, 0.0, 0.0);
    k.meff = m;
    k.dt = dt;
    k.mA = m;
    k.mB = 0.0;
    const auto cf = polydem::contact_step(on_floor(x, R), L, k, h, NR);
    F = cf.F_A + m * gvec;
    T = cf.tau_A;
  };
  Vec3<double> F, T;
  force(F, T);
  RollResult r{0.0, 0.0, 0.0, false};
  const int nsteps = static_cast<int>(t_end / dt);
  for (int n = 1; n <= nsteps; n++) {
    v += (0.5 * dt / m) * F;
    w += (0.5 * dt / I) * T;
    x += dt * v;
    force(F, T);
    v += (0.5 * dt / m) * F;
    w += (0.5 * dt / I) * T;
    if (v.x <= 0.0 && !r.stopped) {
      r.stopped = true;
      r.stop_x = x.x;
      r.stop_t = n * dt;
    }
  }
  r.v_end = v.x;
  return r;
}

}    // namespace

// A rolling sphere on a flat stops where the model's closed form says: the
// full rolling torque mu_r R m g against the rolling inertia 7/5 m R^2
// decelerates it at 5/7 mu_r g, d = 7 v0^2 / (10 mu_r g), t = 7 v0 / (5 mu_r g)
// (within 1 %); on an incline it rolls down if tan(alpha) > mu_r and stays
// if tan(alpha) < mu_r (Ai et al. 2011, section 2.3).
TEST(ContactLaw, RollingSphereStopsAtTheClosedForm)
{
  const double g = 9.81;
  for (double mu_r : {0.05, 0.2}) {
    const double v0 = 0.1;
    const auto r = roll(v0, 0.0, mu_r, 0.5);
    ASSERT_TRUE(r.stopped) << mu_r;
    const double d = 7.0 * v0 * v0 / (10.0 * mu_r * g), t = 7.0 * v0 / (5.0 * mu_r * g);
    EXPECT_NEAR(r.stop_x, d, 0.01 * d) << mu_r;
    EXPECT_NEAR(r.stop_t, t, 0.01 * t) << mu_r;
  }
  // incline: at rest, released on slopes of 0.8 and 1.25 times atan(mu_r)
  const double mu_r = 0.1;
  const auto steep = roll(0.0, 1.25 * std::atan(mu_r), mu_r, 0.2);
  const auto shallow = roll(0.0, 0.8 * std::atan(mu_r), mu_r, 0.2);
  // rolls down (-x) at (5/7) g (sin a - mu_r cos a) once mobilised
  const double a = 1.25 * std::atan(mu_r);
  const double vexp = -5.0 / 7.0 * g * (std::sin(a) - mu_r * std::cos(a)) * 0.2;
  EXPECT_NEAR(steep.v_end, vexp, 0.05 * std::fabs(vexp));
  EXPECT_LT(std::fabs(shallow.v_end), 1e-3 * std::fabs(vexp));
}

// Dry cohesion: the pull is the exact gradient of U = -c m (Feng: c = k_c,
// the pull k_c A_n; linear: the DMT pull-off force 2 pi Gamma R_r), so W'
// shifts by c and the energy by -c m; an elastic (e = 1) cohesive face
// contact gives back all its energy (it leaves with v0).
TEST(ContactLaw, CohesionIsTheGradientOfItsEnergy)
{
  const double A = 0.01, kc = 3e3;
  auto L = feng(1.0, 0.0, 0, 0, 1e-2);
  L.cohesion = kc;
  const auto g0 = face(0.0, A, make_vec3(0.5, 0.0, 0.0));
  for (double f : {0.1, 0.7, 3.0, 100.0}) {
    const double V = f * L.normal.V0;
    const auto nv = polydem::normal_value(L.normal, V, A);
    auto g = g0;
    g.volume = V;
    double h[polydem::CONTACT_HIST] = {0, 0, 0, 0, 0};
    const auto cf = polydem::contact_step(g, L, still(1.0, 0.0), h, polydem::CONTACT_HIST);
    EXPECT_NEAR(cf.F_A.x, -(nv.Wp - kc) * A, 1e-12 * (nv.Wp + kc) * A) << f;
    EXPECT_NEAR(cf.energy, nv.W - kc * V, 1e-12 * (nv.W + kc * V)) << f;
    EXPECT_NEAR(cf.fn, (nv.Wp - kc) * A, 1e-12 * (nv.Wp + kc) * A) << f;
  }
  // the DMT pull of a sphere on a wall (R_r = r_A): 2 pi Gamma R_r at any delta
  const double R = 0.01, Gamma = 0.05, kn = 1e4, delta = 2e-6;
  auto Ll = linear_rolling(kn, 1.0, 0.0, 0.0);
  Ll.cohesion = Gamma;
  const Vec3<double> x = make_vec3(0.0, 0.0, R - delta);
  auto k = still(0.01, 0.0);
  k.xA = x;
  k.xB = make_vec3(0.0, 0.0, -1.0);
  double h[polydem::CONTACT_HIST] = {0, 0, 0, 0, 0};
  const auto cf = polydem::contact_step(on_floor(x, R), Ll, k, h, polydem::CONTACT_HIST);
  const double Fpo = 2.0 * PI * Gamma * (R - delta);
  EXPECT_NEAR(cf.F_A.z, kn * delta - Fpo, 1e-12 * Fpo);
  EXPECT_NEAR(cf.energy, 0.5 * kn * delta * delta - Fpo * delta, 1e-12 * Fpo * delta);
  // elastic cohesive bounces: all the energy comes back (above and in the core)
  for (double v0 : {5.0, 0.05}) {
    auto Lb = feng(1.0, 0.0, 0, 0, v0 > 1.0 ? 1e-6 : 1e-2);
    Lb.cohesion = kc;
    EXPECT_NEAR(bounce(Lb, false, v0), 1.0, 1e-5) << v0;
  }
}
