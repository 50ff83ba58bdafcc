// Rolling resistance (EPSD, Ai, Chen, Rotter and Ooi, Powder Technol. 206
// (2011) 269, model C; polydem_contact_law.h) of a sphere (an ellipsoid with
// a = b = c, pair_style ellipsoid) on fix wall/mesh, through LAMMPS:
// 1. a sphere rolling on a flat mesh stops where the closed form says: the
//    rolling torque mu_r R m g against the rolling inertia 7/5 m R^2 gives
//    the deceleration 5/7 mu_r g, so d = 7 v0^2 / (10 mu_r g) (within 1 %),
//    with mu_r from pair_coeff or from the fix's rolling keyword; without
//    rolling resistance it keeps rolling;
// 2. on an incline it rolls down for tan(theta) > mu_r, at 5/7 g (sin theta
//    - mu_r cos theta) (within 2 %), and stays for tan(theta) < mu_r;
// 3. a restart in mid-roll continues bit for bit (the rolling torque is
//    in the wall history), and bad rolling input is an error.
#include "polydem_lmp.h"
#include "wall_meshes.h"

#include "atom.h"
#include "fix.h"
#include "modify.h"

#include <gtest/gtest.h>

#include <cmath>

using polydem_test::Lmp;
using polydem_test::num;
using namespace wall_test;

namespace {

const double R = 0.01, RHO = 2000.0, KN = 1e4, GRAV = 9.81;

// a sphere of radius R resting on the plane through the origin with normal
// (sin theta, 0, cos theta), x along the slope (down for theta > 0), its
// centre at s along the slope; the floor mesh, gravity, the pair style
// and coefficients, and the fix's extra keywords
void scene(Lmp &l, double theta_deg, double s, const std::string &coeff,
           const std::string &fixkw)
{
  const double th = theta_deg * M_PI / 180.0;
  const std::string stl = tmpdir() + "/rolling_floor.stl";
  write_ascii(stl, inclined(flat(-0.1, 0.1, -0.03, 0.03, 0.0, 6, 3), th));
  const double m = RHO * 4.0 / 3.0 * M_PI * R * R * R;
  const double p[3] = {s, 0.0, R - m * GRAV * std::cos(th) / KN};
  double x0[3];
  incline_to_lab(th, p, x0);
  l.cmds({"units si", "atom_style polyhedron", "atom_modify map array", "boundary f f f",
          "comm_modify vel yes", "region box block -0.2 0.2 -0.2 0.2 -0.2 0.2",
          "create_box 1 box", "polyhedron_shape s ellipsoid " + num(R) + " " + num(R) + " " + num(R),
          "create_atoms 1 single " + num(x0[0]) + " " + num(x0[1]) + " " + num(x0[2]),
          "polyhedron_set atom 1 density " + num(RHO), "pair_style ellipsoid",
          "pair_coeff * * " + coeff, "neighbor 0.001 bin", "fix nve all nve/polyhedron",
          "fix g all gravity 9.81 vector 0 0 -1", "fix w all wall/mesh " + stl + fixkw,
          "timestep 5e-5"});    // t_c = pi sqrt(m / k_n) = 2.9 ms
}

// roll at v0 along +x (without slip: omega_y = v0 / R) on the flat floor;
// the distance to the first stop (vx <= 0), -1 if none within nmax steps
double stop_distance(const std::string &coeff, const std::string &fixkw, double v0, int nmax)
{
  Lmp l;
  scene(l, 0.0, -0.05, coeff, fixkw);
  l.cmds({"velocity all set " + num(v0) + " 0 0",
          "polyhedron_set atom 1 omega 0 " + num(v0 / R) + " 0"});
  auto *a = l.lmp->atom;
  const double x0 = a->x[0][0];
  l.cmd("run 0");
  for (int n = 0; n < nmax; n += 10) {
    const double xp = a->x[0][0], vp = a->v[0][0];
    l.cmd("run 10 pre no post no");
    if (a->v[0][0] <= 0.0) {
      // the stop between the two samples (constant deceleration)
      const double dec = (vp - a->v[0][0]) / (10 * 5e-5);
      return xp + vp * vp / (2.0 * dec) - x0;
    }
  }
  return -1.0;
}

double fvec(Lmp &l, const std::string &id, int k)
{
  return l.lmp->modify->fix[l.lmp->modify->find_fix(id)]->compute_vector(k);
}

}    // namespace

// 1. the stop distance on a flat mesh against d = 7 v0^2 / (10 mu_r g)
TEST(WallRolling, SphereStopsAtTheClosedForm)
{
  struct Case {
    std::string coeff, fixkw;
    double mu_r, v0;
  };
  const Case cases[] = {{"1e4 0.5 0.5 rolling 0.1", "", 0.1, 0.1},
                        {"1e4 0.5 0.5 rolling 0.3", "", 0.3, 0.15},
                        {"1e4 0.5 0.5", " rolling 0.2", 0.2, 0.1}};
  for (const auto &c : cases) {
    const double d = stop_distance(c.coeff, c.fixkw, c.v0, 20000);
    const double expect = 7.0 * c.v0 * c.v0 / (10.0 * c.mu_r * GRAV);
    std::printf("[ rolling ] mu_r %.2f (%s%s), v0 %.2f m/s: stopped after %.6g m, closed form "
                "%.6g m (%+.3f %%)\n", c.mu_r, c.coeff.c_str(), c.fixkw.c_str(), c.v0, d, expect,
                100.0 * (d / expect - 1.0));
    EXPECT_NEAR(d, expect, 0.01 * expect);
  }
  // no rolling resistance: still rolling after 3x the stop time of mu_r = 0.1
  EXPECT_LT(stop_distance("1e4 0.5 0.5", "", 0.1, 9000), 0.0);
}

// 2. incline: rolls down for tan(theta) > mu_r at 5/7 g (sin - mu_r cos)
TEST(WallRolling, InclineRollsOnlyBeyondTheRollingAngle)
{
  const double mu_r = 0.1;
  for (double f : {0.7, 1.5}) {
    const double th = f * std::atan(mu_r);
    Lmp l;
    scene(l, th * 180.0 / M_PI, -0.05, "1e4 0.5 0.5 rolling " + num(mu_r), "");
    auto *a = l.lmp->atom;
    auto along = [&]() { return std::cos(th) * a->v[0][0] - std::sin(th) * a->v[0][2]; };
    l.cmd("run 1000");    // 50 ms: settled onto the slope, the spring loaded
    const double v1 = along();
    l.cmd("run 2000");
    const double v2 = along();
    const double acc = (v2 - v1) / (2000 * 5e-5);
    const double expect = f > 1.0 ? 5.0 / 7.0 * GRAV * (std::sin(th) - mu_r * std::cos(th)) : 0.0;
    std::printf("[ rolling ] incline tan %.4f (mu_r %.2f): acceleration %.5g m/s^2 (expected "
                "%.5g), v %.3g m/s, contacts %g\n", std::tan(th), mu_r, acc, expect, v2,
                fvec(l, "w", 6));
    EXPECT_EQ(fvec(l, "w", 6), 1.0);
    if (f > 1.0)
      EXPECT_NEAR(acc, expect, 0.02 * expect);
    else
      EXPECT_LT(std::fabs(v2), 1e-4);
  }
}

// 3. restart in mid-roll: the same trajectory bit for bit; bad input
TEST(WallRolling, RestartContinuesExactlyAndErrors)
{
  const std::string rst = tmpdir() + "/rolling.restart";
  const std::string coeff = "1e4 0.5 0.5 rolling 0.2";
  double ref[6];
  {
    Lmp l;
    scene(l, 0.0, -0.05, coeff, "");
    l.cmds({"velocity all set 0.1 0 0", "polyhedron_set atom 1 omega 0 " + num(0.1 / R) + " 0"});
    l.cmd("run 300");
    l.cmd("write_restart " + rst);
    l.cmd("run 300");
    for (int k = 0; k < 3; k++) ref[k] = l.lmp->atom->x[0][k], ref[3 + k] = l.lmp->atom->omega[0][k];
  }
  {
    Lmp l;
    l.cmds({"read_restart " + rst, "comm_modify vel yes", "neighbor 0.001 bin",
            "fix nve all nve/polyhedron", "fix g all gravity 9.81 vector 0 0 -1",
            "fix w all wall/mesh " + tmpdir() + "/rolling_floor.stl", "timestep 5e-5"});
    l.cmd("run 300");
    for (int k = 0; k < 3; k++) {
      EXPECT_EQ(l.lmp->atom->x[0][k], ref[k]) << k;
      EXPECT_EQ(l.lmp->atom->omega[0][k], ref[3 + k]) << k;
    }
  }
  Lmp l;
  scene(l, 0.0, -0.05, "1e4 0.5 0.5", "");
  const struct {
    std::string cmd, says;
  } bad[] = {{"pair_coeff * * 1e4 0.5 0.5 rolling -0.1", "rolling friction mu_r must be >= 0"},
             {"pair_coeff * * 1e4 0.5 0.5 rolling 0.1 0.2", "unknown keyword '0.2'"},
             {"pair_coeff * * 1e4 0.5 0.5 cohesion -1", "cohesion must be >= 0"},
             {"fix w3 all wall/mesh " + tmpdir() + "/rolling_floor.stl cohesion -1",
              "cohesion must be >= 0"},
             {"pair_style ellipsoid rolling/stiffness 0", "rolling/stiffness must be > 0"},
             {"fix w2 all wall/mesh " + tmpdir() + "/rolling_floor.stl rolling -1",
              "rolling must be >= 0"}};
  for (const auto &b : bad) {
    const std::string err = l.error_of(b.cmd);
    EXPECT_NE(err.find(b.says), std::string::npos) << b.cmd << ": " << err;
  }
}

// Dry cohesion on a wall (DMT, issue 30): a sphere (r = 1 cm, k_n = 1e4 N/m,
// e = 0.5) touching the flat mesh with 1e-7 m overlap, no gravity, surface
// energy Gamma = 0.2 J/m^2 from pair_coeff or the fix's cohesion keyword,
// settles where k_n delta = 2 pi Gamma R_r, R_r = r - delta (the contact
// point on the wall's plane): delta = 2 pi Gamma r / (k_n + 2 pi Gamma),
// within 1e-6.
TEST(WallCohesion, SphereRestsAtTheDMTOverlap)
{
  const double Gamma = 0.2;
  const std::string stl = tmpdir() + "/cohesion_floor.stl";
  write_ascii(stl, flat(-0.1, 0.1, -0.1, 0.1, 0.0, 3, 3));
  for (const std::string c : {"1e4 0.5 0.5 cohesion 0.2|", "1e4 0.5 0.5| cohesion 0.2"}) {
    const size_t bar = c.find('|');
    Lmp l;
    l.cmds({"units si", "atom_style polyhedron", "atom_modify map array", "boundary f f f",
            "comm_modify vel yes", "region box block -0.2 0.2 -0.2 0.2 -0.2 0.2", "create_box 1 box",
            "polyhedron_shape s ellipsoid " + num(R) + " " + num(R) + " " + num(R),
            "create_atoms 1 single 0 0 " + num(R - 1e-7), "polyhedron_set atom 1 density " + num(RHO),
            "pair_style ellipsoid", "pair_coeff * * " + c.substr(0, bar), "neighbor 0.001 bin",
            "fix nve all nve/polyhedron", "fix w all wall/mesh " + stl + c.substr(bar + 1),
            "timestep 5e-5", "run 10000"});
    const double delta = R - l.lmp->atom->x[0][2];
    const double expect = 2.0 * M_PI * Gamma * R / (KN + 2.0 * M_PI * Gamma);
    std::printf("[ cohesion ] sphere on the wall (%s): overlap %.10g m, closed form %.10g m\n",
                c.c_str(), delta, expect);
    EXPECT_NEAR(delta, expect, 1e-6 * expect);
  }
}

// A servo-controlled lid (move servo, issue 30): nine spheres (r = 1 cm,
// k_n = 1e4 N/m, e = 0.5) resting on a floor mesh under gravity, a flat lid
// mesh 2 mm above them moving down (direction 0 0 -1) at up to 0.05 m/s
// with gain 0.02 m/s per N until the spheres push it back with the target
// force: in steady state (the last 1,000 of 6,000 steps) the mean force
// on the lid is the target within 1 %, its velocity below 1e-4 m/s; the
// vector's [9] and [10] give the lid's displacement and velocity, and a
// restart in mid-run continues bit for bit (the servo's state is in it).
namespace {
void servo_scene(Lmp &l, double target)
{
  const std::string floor = tmpdir() + "/servo_floor.stl", lid = tmpdir() + "/servo_lid.stl";
  write_ascii(floor, flat(-0.1, 0.1, -0.1, 0.1, 0.0, 2, 2));
  write_ascii(lid, flat(-0.1, 0.1, -0.1, 0.1, 2 * R + 0.002, 2, 2));
  l.cmds({"units si", "atom_style polyhedron", "atom_modify map array", "boundary f f f",
          "comm_modify vel yes", "region box block -0.2 0.2 -0.2 0.2 -0.2 0.2", "create_box 1 box",
          "polyhedron_shape s ellipsoid " + num(R) + " " + num(R) + " " + num(R)});
  for (int i = -1; i <= 1; i++)
    for (int j = -1; j <= 1; j++)
      l.cmd("create_atoms 1 single " + num(0.03 * i) + " " + num(0.03 * j) + " " + num(R - 1e-7));
  l.cmds({"polyhedron_set group all density " + num(RHO), "pair_style ellipsoid",
          "pair_coeff * * 1e4 0.5 0.5", "neighbor 0.001 bin", "fix nve all nve/polyhedron",
          "fix g all gravity 9.81 vector 0 0 -1", "fix floor all wall/mesh " + floor,
          "fix lid all wall/mesh " + lid + " move servo 0 0 -1 " + num(target) + " 0.05 0.02",
          "timestep 5e-5"});
}
}    // namespace

TEST(WallServo, LidHoldsTheTargetForce)
{
  for (double target : {2.0, 8.0}) {
    Lmp l;
    servo_scene(l, target);
    l.cmd("run 5000");
    double sum = 0.0;
    for (int k = 0; k < 100; k++) {
      l.cmd("run 10 pre no post no");
      sum += fvec(l, "lid", 2);
    }
    const double mean = sum / 100.0, s = fvec(l, "lid", 8), v = fvec(l, "lid", 9);
    std::printf("[ servo ] target %.1f N: mean lid force %.6f N (%+.4f %%), lid moved %.6g m, "
                "v %.3g m/s\n", target, mean, 100.0 * (mean / target - 1.0), s, v);
    EXPECT_NEAR(mean, target, 0.01 * target);
    EXPECT_LT(std::fabs(v), 1e-4);
    EXPECT_GT(s, 0.002);    // it came down onto the spheres
  }
  // restart in mid-approach
  const std::string rst = tmpdir() + "/servo.restart";
  double ref[2];
  {
    Lmp l;
    servo_scene(l, 5.0);
    l.cmd("run 600");
    l.cmd("write_restart " + rst);
    l.cmd("run 600");
    ref[0] = fvec(l, "lid", 8);
    ref[1] = l.lmp->atom->x[l.lmp->atom->map(5)][2];
  }
  Lmp l;
  l.cmds({"read_restart " + rst, "comm_modify vel yes", "neighbor 0.001 bin",
          "fix nve all nve/polyhedron", "fix g all gravity 9.81 vector 0 0 -1",
          "fix floor all wall/mesh " + tmpdir() + "/servo_floor.stl",
          "fix lid all wall/mesh " + tmpdir() + "/servo_lid.stl move servo 0 0 -1 5 0.05 0.02",
          "timestep 5e-5", "run 600"});
  EXPECT_EQ(fvec(l, "lid", 8), ref[0]);
  EXPECT_EQ(l.lmp->atom->x[l.lmp->atom->map(5)][2], ref[1]);
  l.expect_error("fix bad all wall/mesh " + tmpdir() + "/servo_lid.stl move servo 0 0 0 5 "
                       "0.05 0.02", "move servo direction must be non-zero");
}

// A load program: the target from an equal-style variable, evaluated every
// step (2 N, then 6 N from step 4,000): each step's mean force within 1 %.
TEST(WallServo, TargetFromAVariable)
{
  Lmp l;
  servo_scene(l, 1.0);
  l.cmds({"unfix lid", "variable load equal 2.0+4.0*(step>=4000)",
          "fix lid all wall/mesh " + tmpdir() + "/servo_lid.stl move servo 0 0 -1 v_load 0.05 0.02"});
  for (double target : {2.0, 6.0}) {
    l.cmd("run 3000");
    double sum = 0.0;
    for (int k = 0; k < 100; k++) {
      l.cmd("run 10 pre no post no");
      sum += fvec(l, "lid", 2);
    }
    std::printf("[ servo ] variable target %.1f N: mean lid force %.6f N\n", target, sum / 100.0);
    EXPECT_NEAR(sum / 100.0, target, 0.01 * target);
  }
  Lmp bad;
  servo_scene(bad, 1.0);
  bad.cmds({"unfix lid", "fix lid all wall/mesh " + tmpdir() +
                             "/servo_lid.stl move servo 0 0 -1 v_nothing 0.05 0.02"});
  bad.expect_error("run 0", "variable 'nothing' does not exist");
}

// Liquid bridges on a mesh (fix wall/mesh bridge, issue 30): a sphere (r =
// 1 cm, no gravity) touching a floor mesh gets its bridge, then is lifted
// at v0. Across the gap only the bridge acts, Willett et al.'s F(s) with
// the sphere-plane radius 2r (Langmuir 16 (2000) 9396): kinetic energy +
// the wall's energy stay constant (to 1e-5 of |U(0)|, the time step's
// error); below the escape speed the sphere stops at the gap where
// U(s_max) = U(s_1) + K_1, U integrated here by Simpson's rule from
// Willett's formula (within 1e-4 s_c); above it the bridge ruptures at s_c
// = (1 + theta/2) V^(1/3) (Lian et al. 1993) and the sphere leaves with
// K_1 + U(s_1), up to the work F(s_c) v dt the step across s_c misses.
// Bad bridge input is an error.
namespace {
const double BV = 1e-9, BGAMMA = 0.072, BTHETA = 20.0;

double willett_wall(double s)
{
  const double Rb = 2.0 * R, u = (s > 0.0 ? s : 0.0) * std::sqrt(Rb / BV);
  return 2.0 * M_PI * Rb * BGAMMA * std::cos(BTHETA * M_PI / 180.0) / (1.0 + 1.05 * u + 2.5 * u * u);
}
double rupture_gap() { return (1.0 + 0.5 * BTHETA * M_PI / 180.0) * std::cbrt(BV); }
// the floor mesh (its file name)
std::string bridge_floor()
{
  const std::string stl = tmpdir() + "/bridge_floor.stl";
  write_ascii(stl, flat(-0.1, 0.1, -0.1, 0.1, 0.0, 3, 3));
  return stl;
}
std::string bridge_fix(const std::string &stl)
{
  return "fix w all wall/mesh " + stl + " bridge " + num(BV) + " " + num(BGAMMA) + " " + num(BTHETA);
}
// a sphere touching the floor (overlap 1e-8 m), no gravity, the wall with
// the bridge; one step forms the bridge, then the sphere is given the
// upward velocity v0 (more: fix wall/mesh keywords after the bridge's)
void bridge_scene(Lmp &l, const std::string &stl, double v0, const std::string &more = "")
{
  l.cmds({"units si", "atom_style polyhedron", "atom_modify map array", "boundary f f f",
          "comm_modify vel yes", "region box block -0.2 0.2 -0.2 0.2 -0.2 0.2", "create_box 1 box",
          "polyhedron_shape s ellipsoid " + num(R) + " " + num(R) + " " + num(R),
          "create_atoms 1 single 0 0 " + num(R - 1e-8), "polyhedron_set atom 1 density " + num(RHO),
          "pair_style ellipsoid", "pair_coeff * * 1e4 0.5 0.5", "neighbor 0.001 bin",
          "fix nve all nve/polyhedron", bridge_fix(stl) + more, "timestep 5e-5", "run 1",
          "velocity all set 0 0 " + num(v0)});
}
// U(s) = -int_s^s_c F (Simpson, 4,000 intervals)
double willett_energy(double s)
{
  const int n = 4000;
  const double sc = rupture_gap(), h = (sc - s) / n;
  double sum = willett_wall(s) + willett_wall(sc);
  for (int k = 1; k < n; k++) sum += (k % 2 ? 4.0 : 2.0) * willett_wall(s + k * h);
  return -sum * h / 3.0;
}
}    // namespace

TEST(WallBridge, LiftedSphereKeepsItsEnergyAndRuptures)
{
  const std::string stl = bridge_floor();
  const double m = RHO * 4.0 / 3.0 * M_PI * R * R * R, sc = rupture_gap();
  const double U0 = willett_energy(0.0);
  for (double v0 : {0.015, 0.03}) {
    Lmp l;
    bridge_scene(l, stl, v0);
    auto *a = l.lmp->atom;
    LAMMPS_NS::Fix *w = l.lmp->modify->fix[l.lmp->modify->find_fix("w")];
    double E1 = 0.0, s1 = -1.0, drift = 0.0, smax = 0.0, vfinal = 0.0;
    bool returned = false;
    for (int n = 0; n < 6000; n++) {
      l.cmd(n == 0 ? "run 1" : "run 1 pre no post no");
      const double s = a->x[0][2] - R, vz = a->v[0][2];
      const double E = 0.5 * m * vz * vz + w->compute_scalar();
      if (s <= 0.0) continue;
      if (s1 < 0.0) {
        s1 = s;
        E1 = E;
      }
      if (s < sc) drift = std::fmax(drift, std::fabs(E - E1));
      smax = std::fmax(smax, s);
      if (vz < 0.0) {
        returned = true;
        break;
      }
      if (s > 2.0 * sc) {
        vfinal = vz;
        break;
      }
    }
    std::printf("[ wall bridge ] v0 %.3g m/s: E drift %.3g of |U(0)| = %.4g J, ", v0,
                drift / std::fabs(U0), std::fabs(U0));
    EXPECT_LT(drift, 1e-5 * std::fabs(U0));
    ASSERT_GT(s1, 0.0);
    if (v0 < 0.02) {
      // U(s_max) = E1: bisection on the test's own U
      double lo = s1, hi = sc;
      for (int k = 0; k < 60; k++) {
        const double mid = 0.5 * (lo + hi);
        (willett_energy(mid) < E1 ? lo : hi) = mid;
      }
      std::printf("stopped at s %.6g m, expected %.6g m (s_c %.4g m)\n", smax, lo, sc);
      EXPECT_TRUE(returned);
      EXPECT_NEAR(smax, lo, 1e-4 * sc);
    } else {
      // the step across s_c misses at most the work F(s_c) v dt of the pull
      const double expect = std::sqrt(2.0 * E1 / m), jump = willett_wall(sc) * v0 * 5e-5;
      std::printf("ruptured, leaves at %.8g m/s, expected %.8g m/s (kinetic energy %+.3g of "
                  "F(s_c) v dt)\n", vfinal, expect, (0.5 * m * vfinal * vfinal - E1) / jump);
      EXPECT_FALSE(returned);
      EXPECT_NEAR(0.5 * m * vfinal * vfinal, E1, jump);
      EXPECT_EQ(w->compute_scalar(), 0.0);
    }
  }
  // errors
  Lmp l;
  l.cmds({"units si", "atom_style polyhedron", "region box block -0.2 0.2 -0.2 0.2 -0.2 0.2",
          "create_box 1 box"});
  for (const std::string kw : {" bridge 1e-9 0 10", " bridge -1 0.07 10", " bridge 1e-9 0.07 90",
                               " bridge 1e-9 0.07"}) {
    const std::string err = l.error_of("fix w all wall/mesh " + stl + kw);
    EXPECT_NE(err.find("bridge"), std::string::npos) << kw << ": " << err;
  }
}

// The bridge's viscous part on the wall (fix wall/mesh ... viscous eta
// s_min): at gaps s_min / 2 .. s_c, the sphere rising and sinking, the
// wall's force on it is Willett's pull plus Pitois et al.'s -c v_n with the
// sphere-plane radius 2 r, c = 3/2 pi eta (2r)^2 / D (1 - 1/sqrt(1 + 2 V /
// (pi 2r D^2)))^2, D = max(s, s_min) (J. Colloid Interface Sci. 231 (2000)
// 26; Reynolds' 6 pi eta r^2 v / D for a wide bridge), to 1e-12 (at setup:
// no cap). 'viscous' without 'bridge' is an error.
TEST(WallBridge, ViscousPartFollowsPitois)
{
  const std::string stl = bridge_floor();
  const double eta = 1e-3, smin = 1e-6, Rb = 2.0 * R;
  Lmp l;
  bridge_scene(l, stl, 0.0, " viscous " + num(eta) + " " + num(smin));
  int nchecked = 0;
  for (double s : {0.5 * smin, smin, 4.0 * smin, 0.01 * rupture_gap(), 0.3 * rupture_gap(),
                   0.9 * rupture_gap()})
    for (double vz : {0.01, -0.004}) {
      l.cmds({"set atom 1 z " + num(R + s), "set atom 1 vz " + num(vz), "run 0"});
      const double D = std::fmax(s, smin);
      const double q = 1.0 - 1.0 / std::sqrt(1.0 + 2.0 * BV / (M_PI * Rb * D * D));
      const double c = 1.5 * M_PI * eta * Rb * Rb / D * q * q;
      // n points down, to the wall: the approach speed is -vz
      const double fz = -(willett_wall(s) + c * vz);
      std::printf("[ wall bridge ] viscous, s %.4g m, vz %+.3f m/s: f_z %.9e N (expected %.9e)\n",
                  s, vz, l.lmp->atom->f[0][2], fz);
      EXPECT_NEAR(l.lmp->atom->f[0][2], fz, 1e-12 * std::fabs(fz)) << s << " " << vz;
      nchecked++;
    }
  EXPECT_EQ(nchecked, 12);
  Lmp e;
  e.cmds({"units si", "atom_style polyhedron", "region box block -0.2 0.2 -0.2 0.2 -0.2 0.2",
          "create_box 1 box"});
  EXPECT_NE(e.error_of("fix w all wall/mesh " + stl + " viscous 1e-3 1e-6").find("give 'bridge"),
            std::string::npos);
  EXPECT_NE(e.error_of("fix w all wall/mesh " + stl + " bridge 1e-9 0.07 10 viscous 0 1e-6")
                .find("viscosity eta > 0"),
            std::string::npos);
}

// a bridge stretched across the gap (the sphere 0.2 mm above the mesh,
// still rising) is in the restart file: the run continues bit for bit
TEST(WallBridge, StretchedBridgeRestartsExactly)
{
  const std::string stl = bridge_floor(), rst = tmpdir() + "/bridge_wall.restart";
  double ref[2], gap = 0.0;
  {
    Lmp l;
    bridge_scene(l, stl, 0.02);
    l.cmd("run 200");
    gap = l.lmp->atom->x[0][2] - R;
    l.cmds({"write_restart " + rst, "run 400"});
    ref[0] = l.lmp->atom->x[0][2];
    ref[1] = l.lmp->atom->v[0][2];
  }
  Lmp l;
  l.cmds({"read_restart " + rst, "comm_modify vel yes", "neighbor 0.001 bin",
          "fix nve all nve/polyhedron", bridge_fix(stl), "timestep 5e-5", "run 400"});
  std::printf("[ wall bridge ] restart at a gap of %.4g m (s_c %.4g m): z %.17g / %.17g\n", gap,
              rupture_gap(), l.lmp->atom->x[0][2], ref[0]);
  EXPECT_GT(gap, 0.0);
  EXPECT_LT(gap, rupture_gap());
  EXPECT_LT(ref[1], 0.02);    // the bridge pulled
  EXPECT_EQ(l.lmp->atom->x[0][2], ref[0]);
  EXPECT_EQ(l.lmp->atom->v[0][2], ref[1]);
}
