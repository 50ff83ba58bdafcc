// Liquid bridges between spheres (pair_coeff ... bridge V_b gamma theta;
// polydem_contact_law.h bridge_force): two spheres of radii 1 and 1.5 mm
// joined by V_b = 1e-11 m^3 of water (gamma = 0.072 N/m, theta = 20 deg).
//  - the force on each sphere at gaps 0 .. s_c is Willett et al.'s closed
//    form, F = 2 pi R gamma cos(theta) / (1 + 1.05 s^ + 2.5 s^^2),
//    s^ = s sqrt(R / V_b), R = 2 r1 r2 / (r1 + r2), to 1e-12 (relative);
//  - the pair energy is -int_s^s_c F ds' (numerical quadrature here, against
//    the law's arctan form) to 1e-9;
//  - beyond s_c = (1 + theta/2) V_b^(1/3) the bridge is gone and does not
//    form again until the spheres touch (Lian et al. 1993);
//  - an elastic collision that forms and ruptures a bridge conserves
//    kinetic + pair energy from the bridge's formation on (2e-6) and loses
//    the bridge's energy at contact, |U(0)|, up to F(0) v dt;
//  - a stretched bridge continues bit for bit after write_restart /
//    read_restart;
//  - a sphere and a convex polyhedron (a cube): Willett's force with the
//    sphere-plane radius 2 r across the gap to the cube's nearest point, on
//    the sphere through its centre and on the cube at that point, to 1e-12;
//    an off-centre elastic impact that spins the cube keeps the energy
//    from the bridge's formation on (2e-6) and loses |U(0)|; a bridge
//    stretched between them continues bit for bit after a restart;
//  - the viscous part (pair_coeff ... viscous eta s_min): the force on each
//    sphere is Willett's plus Pitois et al.'s closed form (-c v_n along n,
//    c = 3/2 pi eta R^2 / D (1 - 1/sqrt(1 + 2 V_b / (pi R D^2)))^2,
//    D = max(s, s_min)) at gaps s_min / 2 .. s_c, to 1e-12, and none in
//    contact (the contact's dashpot acts there);
//    its coefficient is capped at m_eff / dt; a collision that forms and
//    stretches a viscous bridge loses from its formation on exactly the
//    viscous work, sum c v_n^2 dt (to 0.1 %), and a stretched viscous bridge
//    continues bit for bit after a restart;
//  - errors: pair_style ellipsoid, a skin below s_c, a bad angle, a viscous
//    part without a bridge.
#include "polydem_lmp.h"

#include "atom.h"
#include "force.h"
#include "pair.h"
#include "polydem_pair_counts.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

using polydem_test::Lmp;
using polydem_test::num;

namespace {

constexpr double R1 = 1e-3, R2 = 1.5e-3, VB = 1e-11, GAMMA = 0.072, THETA_DEG = 20.0;
const double THETA = THETA_DEG * M_PI / 180.0;
const double RSTAR = 2.0 * R1 * R2 / (R1 + R2);
const double SC = (1.0 + 0.5 * THETA) * std::cbrt(VB);

// Willett et al.'s force at gap s for the radius R
double willett_R(double s, double R)
{
  const double u = (s > 0.0 ? s : 0.0) * std::sqrt(R / VB);
  return 2.0 * M_PI * R * GAMMA * std::cos(THETA) / (1.0 + 1.05 * u + 2.5 * u * u);
}

// -int_s^s_c F ds' by Simpson's rule
double willett_R_energy(double s, double R)
{
  const int n = 20000;
  const double h = (SC - s) / n;
  double sum = willett_R(s, R) + willett_R(SC, R);
  for (int k = 1; k < n; k++) sum += (k % 2 ? 4.0 : 2.0) * willett_R(s + k * h, R);
  return -sum * h / 3.0;
}

// the two spheres' force and energy
double willett(double s)
{
  return willett_R(s, RSTAR);
}
double willett_energy(double s)
{
  return willett_R_energy(s, RSTAR);
}

const std::string BRIDGE =
    " bridge " + num(VB) + " " + num(GAMMA) + " " + num(THETA_DEG);

// the viscous part: water's viscosity, the smallest gap 1 um
constexpr double ETA = 1e-3, SMIN = 1e-6;
const std::string VISCOUS = BRIDGE + " viscous " + num(ETA) + " " + num(SMIN);

// Pitois et al.'s coefficient c at gap s (the force on the first sphere
// along the line of centres is -c v_n, v_n the approach speed), for the
// bridge radius R and the smallest gap s_min
double pitois(double s, double R = RSTAR, double eta = ETA, double smin = SMIN)
{
  const double D = std::fmax(s, smin);
  const double q = 1.0 - 1.0 / std::sqrt(1.0 + 2.0 * VB / (M_PI * R * D * D));
  return 1.5 * M_PI * eta * R * R / D * q * q;
}

// two spheres on the x axis, the second at x2, the bridge law on type 1
// (law: pair_coeff's keywords after the coefficients)
void two_spheres(Lmp &l, double x2, double e, const std::string &skin = "3e-4",
                 const std::string &law = BRIDGE)
{
  l.cmds({"units si", "atom_style polyhedron", "atom_modify map array", "boundary f f f",
          "comm_modify vel yes", "region box block -0.01 0.01 -0.01 0.01 -0.01 0.01",
          "create_box 1 box", "polyhedron_shape s1 ellipsoid " + num(R1) + " " + num(R1) + " " +
              num(R1),
          "polyhedron_shape s2 ellipsoid " + num(R2) + " " + num(R2) + " " + num(R2),
          "create_atoms 1 single 0 0 0", "create_atoms 1 single " + num(x2) + " 0 0",
          "polyhedron_set atom 1 shape s1", "polyhedron_set atom 2 shape s2",
          "polyhedron_set group all density 2500", "pair_style polyhedron",
          "pair_coeff * * 1e7 0.3 " + num(e) + " 0.0" + law, "neighbor " + skin + " bin",
          "thermo_style custom step pe ke", "thermo_modify norm no"});
}

double force_x(Lmp &l, int id)
{
  return l.lmp->atom->f[l.lmp->atom->map(id)][0];
}

// the translational kinetic energy of atoms 1 and 2
double two_body_kinetic(Lmp &l)
{
  auto *a = l.lmp->atom;
  double k = 0.0;
  for (int id : {1, 2}) {
    const int i = a->map(id);
    k += 0.5 * a->rmass[i] * (a->v[i][0] * a->v[i][0] + a->v[i][1] * a->v[i][1] +
                               a->v[i][2] * a->v[i][2]);
  }
  return k;
}

// that plus the rotational energy compute c_er of the scenes below
double two_body_energy(Lmp &l)
{
  return l.thermo("c_er") + two_body_kinetic(l);
}

// An impact that forms and ruptures a bridge, 100 steps at a time (at most
// `chunks` times): from the step the bridge forms (the pair energy turns
// negative) on, the largest deviation of energy() + pair energy from its
// value then; stops once done(pair energy) after the formation
struct BridgeEnergy {
  bool formed = false;
  double E_formed = 0.0, dev = 0.0;
};
template <class Energy, class Done>
BridgeEnergy track_bridge_energy(Lmp &l, int chunks, Energy energy, Done done)
{
  BridgeEnergy r;
  for (int k = 0; k < chunks; k++) {
    l.cmd("run 100 pre no post no");
    const double pe = l.lmp->force->pair->eng_vdwl, E = energy() + pe;
    if (!r.formed && pe < 0.0) {
      r.formed = true;
      r.E_formed = E;
    }
    if (r.formed) r.dev = std::fmax(r.dev, std::fabs(E - r.E_formed));
    if (r.formed && done(pe)) break;
  }
  return r;
}

// from the bridge's formation on, the energy stayed constant, and the
// bodies left with it (K1), to 2e-6 of the kinetic energy K0 they came with
void expect_energy_kept(const BridgeEnergy &b, double K0, double K1)
{
  EXPECT_LE(b.dev, 2e-6 * K0);
  EXPECT_NEAR(K1, b.E_formed, 2e-6 * K0);
}

// the same until the bodies are 1.2 s_c apart: gap() their distance
// across the bridge; the last gap in .gap
struct BridgeEnergyApart : BridgeEnergy {
  double gap = 0.0;
};
template <class Energy, class Gap>
BridgeEnergyApart track_bridge_until_apart(Lmp &l, int chunks, Energy energy, Gap gap)
{
  BridgeEnergyApart r;
  static_cast<BridgeEnergy &>(r) = track_bridge_energy(l, chunks, energy, [&](double) {
    r.gap = gap();
    return r.gap > 1.2 * SC;
  });
  return r;
}

// positions, velocities and spins of atoms 1 and 2
void two_body_state(Lmp &l, double out[6][3])
{
  auto *a = l.lmp->atom;
  for (int id : {1, 2}) {
    const int i = a->map(id);
    for (int d = 0; d < 3; d++) {
      out[3 * (id - 1)][d] = a->x[i][d];
      out[3 * (id - 1) + 1][d] = a->v[i][d];
      out[3 * (id - 1) + 2][d] = a->omega[i][d];
    }
  }
}

// atom `id` launched at v down along z and 0.2 v along x, the other at
// rest; then the commands `more`, and nve/polyhedron at the step dt
void launch(Lmp &l, int id, double v, double dt, const std::vector<std::string> &more = {})
{
  l.cmds({"velocity all set 0 0 0", "set atom " + std::to_string(id) + " vz " + num(-v) +
              " vx " + num(0.2 * v)});
  l.cmds(more);
  l.cmds({"fix 1 all nve/polyhedron", "timestep " + num(dt), "thermo 100", "run 0"});
}

// after `move` (beyond s_c): no force on local atom i's component k, no
// pair energy
void expect_no_bridge(Lmp &l, const std::string &move, int i, int k)
{
  l.cmd(move);
  l.cmd("run 0");
  EXPECT_EQ(l.lmp->atom->f[i][k], 0.0);
  EXPECT_EQ(l.lmp->force->pair->eng_vdwl, 0.0);
}

// a new run from the restart file, 3000 steps on
void run_from_restart(Lmp &l, const std::string &file)
{
  l.cmds({"read_restart " + file, "comm_modify vel yes", "neighbor 3e-4 bin",
          "fix 1 all nve/polyhedron", "timestep 1e-7", "run 3000"});
}

// l written to a restart file and run 3000 steps on, against a new run from
// that file: positions, velocities and spins of both bodies bit for bit
void expect_restart_exact(Lmp &l, const std::string &file)
{
  double ref[6][3], got[6][3];
  l.cmds({"write_restart " + file, "run 3000"});
  two_body_state(l, ref);
  Lmp r;
  run_from_restart(r, file);
  two_body_state(r, got);
  for (int k = 0; k < 6; k++)
    for (int d = 0; d < 3; d++) EXPECT_EQ(got[k][d], ref[k][d]) << k << " " << d;
}

}    // namespace

TEST(Bridge, ForceAndEnergyFollowWillettsClosedForm)
{
  Lmp l;
  two_spheres(l, R1 + R2 - 1e-9, 1.0);
  l.cmd("run 0");    // touching: the bridge forms
  int nchecked = 0;
  for (double f : {0.0, 0.01, 0.05, 0.1, 0.2, 0.4, 0.6, 0.8, 0.95, 0.999}) {
    const double s = f * SC;
    l.cmd("set atom 2 x " + num(R1 + R2 + s));
    l.cmd("run 0");
    const double F1 = force_x(l, 1), F2 = force_x(l, 2);
    const double U = l.lmp->force->pair->eng_vdwl;
    const double Fw = willett(s), Uw = willett_energy(s);
    std::printf("[ bridge   ] s/s_c %.3f: F %.9e N (Willett %.9e), U %.9e J (quadrature %.9e)\n",
                f, F1, Fw, U, Uw);
    EXPECT_NEAR(F1, Fw, 1e-12 * Fw) << f;
    EXPECT_NEAR(F2, -Fw, 1e-12 * Fw) << f;
    if (f < 0.999) EXPECT_NEAR(U, Uw, 1e-9 * std::fabs(willett_energy(0.0))) << f;
    nchecked++;
  }
  EXPECT_EQ(nchecked, 10);
  // ruptured beyond s_c, and not formed again on the way back without touching
  for (double f : {1.001, 0.5, 0.01}) {
    l.cmd("set atom 2 x " + num(R1 + R2 + f * SC));
    l.cmd("run 0");
    EXPECT_EQ(force_x(l, 1), 0.0) << f;
    EXPECT_EQ(l.lmp->force->pair->eng_vdwl, 0.0) << f;
  }
  // touching again forms it again
  l.cmd("set atom 2 x " + num(R1 + R2 - 1e-8));
  l.cmd("run 0");
  l.cmd("set atom 2 x " + num(R1 + R2 + 0.3 * SC));
  l.cmd("run 0");
  EXPECT_NEAR(force_x(l, 1), willett(0.3 * SC), 1e-12 * willett(0.3 * SC));
}

// An elastic head-on collision (e = 1, no friction): the bridge forms at
// contact with the energy U < 0 and ruptures at s_c with U = 0. From the
// step it forms to long after it ruptured, kinetic + pair energy is
// constant (to 2e-6 of the kinetic energy); the spheres leave with the
// kinetic energy they came with less |U(0)|, up to the work of the pull
// over the one step in which the bridge appears (F(0) v dt).
TEST(Bridge, CollisionLosesTheBridgeEnergy)
{
  Lmp l;
  const double v = 0.15, dt = 1e-7;
  two_spheres(l, R1 + R2 + 5e-5, 1.0);
  l.cmds({"velocity all set 0 0 0", "set atom 1 vx " + num(v), "set atom 2 vx " + num(-v),
          "fix 1 all nve/polyhedron", "timestep " + num(dt), "thermo 100", "run 0"});
  auto *a = l.lmp->atom;
  auto kinetic = [&]() { return two_body_kinetic(l); };
  const double K0 = kinetic();
  const double U0 = willett_energy(0.0);
  const auto b = track_bridge_until_apart(
      l, 1000, kinetic, [&] { return a->x[a->map(2)][0] - a->x[a->map(1)][0] - R1 - R2; });
  ASSERT_TRUE(b.formed);
  ASSERT_GT(b.gap, SC) << "the spheres did not separate";
  const double K1 = kinetic();
  std::printf("[ bridge   ] collision: K0 %.9e J, K1 %.9e J, K0 - K1 %.9e J, |U(0)| %.9e J "
              "(ratio %.8f); energy from formation on constant to %.3g J\n", K0, K1, K0 - K1,
              -U0, (K0 - K1) / -U0, b.dev);
  expect_energy_kept(b, K0, K1);
  EXPECT_NEAR(K0 - K1, -U0, willett(0.0) * 2.0 * v * dt);
}

// A sphere (r = 1 mm) and a cube (edge 4 mm, scale of cube.shape), the
// sphere above the cube's top face at (x0, y0): the sphere and the cube in
// the pair's order `order` (1: sphere first)
namespace {
constexpr double CUBE = 4e-3;
void sphere_and_cube(Lmp &l, double x0, double y0, double z, double e, int order)
{
  const std::string sph = "create_atoms 1 single " + num(x0) + " " + num(y0) + " " + num(z);
  const std::string cube = "create_atoms 1 single 0 0 0";
  l.cmds({"units si", "atom_style polyhedron", "atom_modify map array", "boundary f f f",
          "comm_modify vel yes", "region box block -0.01 0.01 -0.01 0.01 -0.01 0.01",
          "create_box 1 box", "polyhedron_shape s ellipsoid " + num(R1) + " " + num(R1) + " " +
              num(R1),
          "polyhedron_shape c " + polydem_test::potentials() + "/cube.shape",
          order == 1 ? sph : cube, order == 1 ? cube : sph});
  const int is = order == 1 ? 1 : 2, ic = 3 - is;
  l.cmds({"polyhedron_set atom " + std::to_string(is) + " shape s",
          "polyhedron_set atom " + std::to_string(ic) + " shape c scale " + num(CUBE),
          "polyhedron_set group all density 2500", "pair_style polyhedron",
          "pair_coeff * * 1e7 0.3 " + num(e) + " 0.0" + BRIDGE, "neighbor 3e-4 bin",
          "compute er all erotate/polyhedron", "thermo_style custom step pe ke c_er",
          "thermo_modify norm no"});
}
// Willett's force with the sphere-plane radius 2 r (the sphere on a face)
double willett_plane(double s)
{
  return willett_R(s, 2.0 * R1);
}
}    // namespace

// Sphere and polyhedron: formed in contact, then across the gap Willett's
// force with R = 2 r to the nearest point of the cube (a face, then beyond
// an edge), on the sphere through its centre and on the cube at that point
// (its torque), in either pair order; nothing beyond s_c.
TEST(Bridge, SphereOnAPolyhedronFollowsWillett)
{
  const double h = 0.5 * CUBE;
  for (int order : {1, 2}) {
    Lmp l;
    sphere_and_cube(l, 0.3 * h, 0.0, h + R1 - 1e-9, 1.0, order);
    l.cmd("run 0");    // touching: the bridge forms
    auto *a = l.lmp->atom;
    const int is = a->map(order == 1 ? 1 : 2), ic = a->map(order == 1 ? 2 : 1);
    double worst = 0.0;
    for (double f : {0.0, 0.1, 0.4, 0.8, 0.999}) {
      const double s = f * SC;
      l.cmd("set atom " + std::to_string(order == 1 ? 1 : 2) + " z " + num(h + R1 + s));
      l.cmd("run 0");
      const double Fw = willett_plane(s);
      worst = std::fmax(worst, std::fabs(-a->f[is][2] / Fw - 1.0));
      EXPECT_NEAR(a->f[ic][2], Fw, 1e-12 * Fw) << f;
      EXPECT_NEAR(a->f[is][0], 0.0, 1e-12 * Fw) << f;
      // the cube's torque: the pull -F at the face point (0.3 h, 0, h)
      EXPECT_NEAR(a->torque[ic][1], -0.3 * h * Fw, 1e-12 * Fw * h) << f;
      EXPECT_NEAR(a->torque[is][1], 0.0, 1e-12 * Fw * h) << f;
    }
    // beyond the edge x = h: the pull towards the edge's nearest point
    const double ex = 0.3 * SC, ez = 0.4 * SC, dist = R1 + 0.5 * SC;
    l.cmd("set atom " + std::to_string(order == 1 ? 1 : 2) + " x " + num(h + ex * dist / (0.5 * SC)) +
          " z " + num(h + ez * dist / (0.5 * SC)));
    l.cmd("run 0");
    const double Fw = willett_plane(0.5 * SC);
    EXPECT_NEAR(a->f[is][0], -Fw * 0.6, 1e-12 * Fw);
    EXPECT_NEAR(a->f[is][2], -Fw * 0.8, 1e-12 * Fw);
    std::printf("[ bridge   ] sphere on a cube (order %d): F(s) against Willett with R = 2r: "
                "largest relative difference %.2g\n", order, worst);
    EXPECT_LT(worst, 1e-12);
    // beyond s_c: gone
    expect_no_bridge(l, "set atom " + std::to_string(order == 1 ? 1 : 2) + " x 0 z " +
                            num(h + R1 + 1.001 * SC), is, 2);
  }
}

// An elastic oblique impact of the sphere on the cube off its centre (e =
// 1, no friction): the cube is pushed and spun. From the step the bridge
// forms to after it ruptured, kinetic (both) + rotational + pair energy is
// constant (2e-6 of the kinetic energy), and the bodies leave with the
// energy they came with less |U(0)| (up to F(0) v dt).
TEST(Bridge, SphereOnAPolyhedronKeepsTheEnergy)
{
  const double h = 0.5 * CUBE, v = 0.15, dt = 1e-7;
  Lmp l;
  sphere_and_cube(l, 0.5 * h, 0.2 * h, h + R1 + 5e-5, 1.0, 1);
  launch(l, 1, v, dt);
  auto *a = l.lmp->atom;
  auto energy = [&]() { return two_body_energy(l); };
  const double K0 = energy();
  const double U0 = willett_R_energy(0.0, 2.0 * R1);
  const auto b = track_bridge_until_apart(
      l, 2000, energy, [&] { return a->x[a->map(1)][2] - a->x[a->map(2)][2] - h - R1; });
  ASSERT_TRUE(b.formed);
  ASSERT_GT(b.gap, SC) << "the sphere did not leave";
  const double K1 = energy();
  std::printf("[ bridge   ] sphere on a cube: K0 %.9e J, K1 %.9e J, K0 - K1 %.9e J, |U(0)| %.9e J, "
              "cube spin energy %.3g J; energy from formation on constant to %.3g J\n", K0, K1,
              K0 - K1, -U0, l.thermo("c_er"), b.dev);
  EXPECT_GT(l.thermo("c_er"), 1e-3 * K0);    // the cube was spun
  expect_energy_kept(b, K0, K1);
  EXPECT_NEAR(K0 - K1, -U0, willett_plane(0.0) * 2.0 * v * dt);
}

// A stretched bridge (separated spheres, the pair kept by its touch flag)
// continues bit for bit after a restart
TEST(Bridge, StretchedBridgeRestartsExactly)
{
  const std::string file = ::testing::TempDir() + "polydem_bridge_restart.bin";
  double ref[2], got[2];
  {
    Lmp l;
    two_spheres(l, R1 + R2 + 5e-5, 0.7);
    l.cmds({"velocity all set 0 0 0", "set atom 1 vx 0.1", "set atom 2 vx -0.05",
            "fix 1 all nve/polyhedron", "timestep 1e-7", "run 6000"});
    auto *a = l.lmp->atom;
    const double gap = a->x[a->map(2)][0] - a->x[a->map(1)][0] - R1 - R2;
    std::printf("[ bridge   ] gap at the restart %.4g m (s_c %.4g m)\n", gap, SC);
    EXPECT_GT(gap, 0.0);
    EXPECT_LT(gap, SC);
    EXPECT_NE(force_x(l, 1), 0.0);
    l.cmds({"write_restart " + file, "run 3000"});
    ref[0] = a->x[a->map(1)][0];
    ref[1] = a->v[a->map(2)][0];
  }
  Lmp l;
  run_from_restart(l, file);
  auto *a = l.lmp->atom;
  got[0] = a->x[a->map(1)][0];
  got[1] = a->v[a->map(2)][0];
  EXPECT_EQ(got[0], ref[0]);
  EXPECT_EQ(got[1], ref[1]);
}

// A bridge stretched between a sphere and a spun cube (the oblique impact
// above, e = 0.7) continues bit for bit after a restart: positions,
// velocities and spins of both bodies 3000 steps on
TEST(Bridge, SphereCubeBridgeRestartsExactly)
{
  const std::string file = ::testing::TempDir() + "polydem_sphere_cube_bridge.bin";
  const double h = 0.5 * CUBE, v = 0.15;
  {
    Lmp l;
    sphere_and_cube(l, 0.5 * h, 0.2 * h, h + R1 + 5e-5, 0.7, 1);
    launch(l, 1, v, 1e-7);
    auto *a = l.lmp->atom;
    bool formed = false;
    double gap = 0.0;
    for (int k = 0; k < 400; k++) {
      l.cmd("run 500 pre no post no");
      formed = formed || l.lmp->force->pair->eng_vdwl < 0.0;
      gap = a->x[a->map(1)][2] - a->x[a->map(2)][2] - h - R1;
      if (formed && gap > 0.3 * SC) break;
    }
    std::printf("[ bridge   ] sphere-cube gap at the restart %.4g m (s_c %.4g m), cube spin %.3g rad/s\n",
                gap, SC, a->omega[a->map(2)][0]);
    ASSERT_TRUE(formed);
    ASSERT_GT(gap, 0.3 * SC);
    ASSERT_LT(gap, SC);
    ASSERT_LT(l.lmp->force->pair->eng_vdwl, 0.0);    // stretched, not ruptured
    EXPECT_NE(a->omega[a->map(2)][0], 0.0);
    expect_restart_exact(l, file);
  }
}

// Two convex polyhedra (cube.shape of edge 4 mm, and dodecahedron.shape):
// Willett's force with the Derjaguin mean of their volume-equivalent radii,
// across their distance along the line of their nearest points
namespace {
double equivalent_radius(double volume)
{
  return std::cbrt(3.0 * volume / (4.0 * M_PI));
}
// a cube (atom 1, edge CUBE) at the origin and a polyhedron of shape file
// `other` at scale `scale` (atom 2) at (x2, 0, z2)
void cube_and_polyhedron(Lmp &l, const std::string &other, double scale, double x2, double z2,
                         double e)
{
  l.cmds({"units si", "atom_style polyhedron", "atom_modify map array", "boundary f f f",
          "comm_modify vel yes", "region box block -0.02 0.02 -0.02 0.02 -0.02 0.02",
          "create_box 1 box", "polyhedron_shape c " + polydem_test::potentials() + "/cube.shape",
          "polyhedron_shape o " + polydem_test::potentials() + "/" + other,
          "create_atoms 1 single 0 0 0", "create_atoms 1 single " + num(x2) + " 0 " + num(z2),
          "polyhedron_set atom 1 shape c scale " + num(CUBE),
          "polyhedron_set atom 2 shape o scale " + num(scale),
          "polyhedron_set group all density 2500", "pair_style polyhedron",
          "pair_coeff * * 1e7 0.3 " + num(e) + " 0.0" + BRIDGE, "neighbor 3e-4 bin",
          "compute er all erotate/polyhedron", "thermo_style custom step pe ke c_er",
          "thermo_modify norm no"});
}
}    // namespace

// Two aligned cubes: formed on contact, then across the gap between their
// facing faces the force is Willett's with R = r_eq (equal cubes: the mean
// of r_eq and r_eq) to 1e-12; beyond their parallel edges (the second cube
// moved diagonally) it pulls along the line between the edges, with the
// torque about the edges' direction that the pull at the edge gives; nothing
// beyond s_c
TEST(Bridge, TwoCubesFollowWillett)
{
  const double h = 0.5 * CUBE, R = equivalent_radius(CUBE * CUBE * CUBE);
  Lmp l;
  cube_and_polyhedron(l, "cube.shape", CUBE, CUBE - 1e-9, 0.0, 1.0);
  l.cmd("run 0");    // touching: the bridge forms
  auto *a = l.lmp->atom;
  const int i1 = a->map(1), i2 = a->map(2);
  double worst = 0.0;
  for (double f : {0.0, 0.1, 0.4, 0.8, 0.999}) {
    const double s = f * SC;
    l.cmd("set atom 2 x " + num(CUBE + s));
    l.cmd("run 0");
    const double Fw = willett_R(s, R);
    worst = std::fmax(worst, std::fabs(a->f[i1][0] / Fw - 1.0));
    EXPECT_NEAR(a->f[i2][0], -Fw, 1e-12 * Fw) << f;
    EXPECT_NEAR(a->f[i1][2], 0.0, 1e-12 * Fw) << f;
    if (f > 0.0)
      EXPECT_NEAR(l.lmp->force->pair->eng_vdwl, willett_R_energy(s, R),
                  1e-9 * std::fabs(willett_R_energy(0.0, R))) << f;
  }
  std::printf("[ bridge   ] two cubes, face to face: F(s) against Willett with R = r_eq = %.6g m: "
              "largest relative difference %.2g\n", R, worst);
  EXPECT_LT(worst, 1e-12);
  // beyond the parallel edges (along y) at x = z = h of the first cube
  const double gx = 0.3 * SC, gz = 0.4 * SC, d = 0.5 * SC;
  l.cmd("set atom 2 x " + num(CUBE + gx) + " z " + num(CUBE + gz));
  l.cmd("run 0");
  const double Fw = willett_R(d, R);
  EXPECT_NEAR(a->f[i1][0], Fw * gx / d, 1e-12 * Fw);
  EXPECT_NEAR(a->f[i1][2], Fw * gz / d, 1e-12 * Fw);
  EXPECT_NEAR(a->f[i1][1], 0.0, 1e-12 * Fw);
  // about y: the pull F at A's edge point (h, y, h) from A's centre and -F
  // at B's (-h, y, -h) from B's give h (F_x - F_z) on both
  EXPECT_NEAR(a->torque[i1][1], h * Fw * (gx - gz) / d, 1e-12 * Fw * h);
  EXPECT_NEAR(a->torque[i2][1], h * Fw * (gx - gz) / d, 1e-12 * Fw * h);
  // beyond s_c: gone
  expect_no_bridge(l, "set atom 2 x " + num(CUBE + 1.001 * SC) + " z 0", i1, 0);
}

// An elastic oblique impact of a dodecahedron on a cube off its centre (e =
// 1, no friction): both are spun. The pull is the exact gradient of U(s)
// with s their signed distance (the nearest points' distance apart, minus
// the penetration depth in contact): from the bridge's formation on,
// kinetic + rotational + pair energy is constant (2e-6 of the kinetic
// energy), and the bodies leave with the energy they came with less |U(0)|
// up to F(0) v dt (the step in which the bridge appears)
TEST(Bridge, TwoPolyhedraKeepTheEnergy)
{
  const double h = 0.5 * CUBE, v = 0.15, dt = 1e-7;
  Lmp l;
  cube_and_polyhedron(l, "dodecahedron.shape", 0.002, 0.4 * h, h + 0.0029, 1.0);
  launch(l, 2, v, dt, {"polyhedron_set atom 2 quat 0.3 0.5 0.8 40"});
  auto *a = l.lmp->atom;
  auto energy = [&]() { return two_body_energy(l); };
  const double K0 = energy();
  double U0 = 0.0;
  bool gone = false;
  const BridgeEnergy b = track_bridge_energy(l, 3000, energy, [&](double pe) {
    gone = pe == 0.0;
    return gone;
  });
  ASSERT_TRUE(b.formed);
  ASSERT_TRUE(gone) << "the bridge did not rupture";
  {
    const double R = 2.0 * equivalent_radius(CUBE * CUBE * CUBE) *
        equivalent_radius(a->rmass[a->map(2)] / 2500.0) /
        (equivalent_radius(CUBE * CUBE * CUBE) + equivalent_radius(a->rmass[a->map(2)] / 2500.0));
    U0 = willett_R_energy(0.0, R);
  }
  const double K1 = energy();
  std::printf("[ bridge   ] dodecahedron on a cube: K0 %.9e J, K1 %.9e J, K0 - K1 %.9e J, |U(0)| "
              "%.9e J (ratio %.6f), spin energy %.3g J; energy from formation on constant to "
              "%.3g J\n", K0, K1, K0 - K1, -U0, (K0 - K1) / -U0, l.thermo("c_er"),
              b.dev);
  EXPECT_GT(l.thermo("c_er"), 1e-3 * K0);    // spun
  expect_energy_kept(b, K0, K1);
  const double R = 2.0 * equivalent_radius(CUBE * CUBE * CUBE);    // a bound of F(0): R <= 2 r_cube
  EXPECT_NEAR(K0 - K1, -U0, 2.0 * M_PI * R * GAMMA * std::cos(THETA) * 2.0 * v * dt);
}

// A bridge stretched between a cube and a spun dodecahedron (the oblique
// impact above, e = 0.7) continues bit for bit after a restart
TEST(Bridge, TwoPolyhedraBridgeRestartsExactly)
{
  const std::string file = ::testing::TempDir() + "polydem_poly_bridge.bin";
  const double h = 0.5 * CUBE, v = 0.15;
  {
    Lmp l;
    cube_and_polyhedron(l, "dodecahedron.shape", 0.002, 0.4 * h, h + 0.0029, 0.7);
    launch(l, 2, v, 1e-7, {"polyhedron_set atom 2 quat 0.3 0.5 0.8 40"});
    // the pair energy: U(0) on touching, up with the elastic energy in
    // contact, down to about U(0) as they part, then up towards 0 across the
    // gap: stretched once it is back at half its lowest value after contact
    bool elastic = false, stretched = false;
    double low = 0.0;
    for (int k = 0; k < 3000 && !stretched; k++) {
      l.cmd("run 100 pre no post no");
      const double pe = l.lmp->force->pair->eng_vdwl;
      elastic = elastic || pe > 0.0;
      if (elastic) low = std::fmin(low, pe);
      stretched = elastic && pe < 0.0 && pe > 0.5 * low;
    }
    ASSERT_TRUE(stretched) << "no stretched bridge";
    expect_restart_exact(l, file);
  }
}

// A composite grain (a dumbbell of two spheres of radius r1, centres
// +-1.5 r1 on its x axis: the principal axis of the smallest moment, so
// the body frame keeps it) and a sphere of radius r2 at (x2, y2, 0): the
// bridge forms between the sphere and the dumbbell's part at +1.5 r1.
namespace {
constexpr double DB = 1.5 * R1;    // the parts' offset
void dumbbell_and_sphere(Lmp &l, double x2, double y2, double e)
{
  l.cmds({"units si", "atom_style polyhedron", "atom_modify map array", "boundary f f f",
          "comm_modify vel yes", "region box block -0.01 0.01 -0.01 0.01 -0.01 0.01",
          "create_box 1 box",
          "polyhedron_shape s1 ellipsoid " + num(R1) + " " + num(R1) + " " + num(R1),
          "polyhedron_shape s2 ellipsoid " + num(R2) + " " + num(R2) + " " + num(R2),
          "polyhedron_shape db composite part s1 " + num(DB) + " 0 0 part s1 " + num(-DB) +
              " 0 0",
          "create_atoms 1 single 0 0 0", "create_atoms 1 single " + num(x2) + " " + num(y2) + " 0",
          "polyhedron_set atom 1 shape db", "polyhedron_set atom 2 shape s2",
          "polyhedron_set group all density 2500", "pair_style polyhedron",
          "pair_coeff * * 1e7 0.3 " + num(e) + " 0.0" + BRIDGE, "neighbor 3e-4 bin",
          "compute er all erotate/polyhedron", "thermo_style custom step pe ke c_er",
          "thermo_modify norm no"});
}
}    // namespace

// The part of a composite bridges like a sphere: Willett's force for
// R = 2 r1 r2 / (r1 + r2) across the gap from the part, to 1e-12, on both
// grains, and the law's energy, to 1e-9; no torque on the dumbbell (the pull
// acts along its axis); ruptured beyond s_c, and not formed again without
// touching
TEST(Bridge, CompositePartFollowsWillett)
{
  Lmp l;
  const double x0 = DB + R1 + R2;    // touching
  dumbbell_and_sphere(l, x0 - 1e-9, 0.0, 1.0);
  // touching: the bridge forms (a part pair takes its history slot in a
  // step, not at a run's setup)
  l.cmds({"run 1", "set atom 1 x 0 y 0 z 0", "velocity all set 0 0 0"});
  auto *a = l.lmp->atom;
  for (double f : {0.0, 0.1, 0.4, 0.8, 0.999}) {
    const double s = f * SC;
    l.cmd("set atom 2 x " + num(x0 + s));
    l.cmd("run 0");
    const double F1 = force_x(l, 1), F2 = force_x(l, 2), Fw = willett(s);
    const double U = l.lmp->force->pair->eng_vdwl, Uw = willett_energy(s);
    std::printf("[ bridge   ] composite part, s/s_c %.3f: F %.9e N (Willett %.9e), U %.9e J "
                "(quadrature %.9e)\n", f, F1, Fw, U, Uw);
    EXPECT_NEAR(F1, Fw, 1e-12 * Fw) << f;
    EXPECT_NEAR(F2, -Fw, 1e-12 * Fw) << f;
    if (f < 0.999) EXPECT_NEAR(U, Uw, 1e-9 * std::fabs(willett_energy(0.0))) << f;
    const double *t = a->torque[a->map(1)];
    EXPECT_LE(std::fabs(t[0]) + std::fabs(t[1]) + std::fabs(t[2]), 1e-12 * Fw * R1) << f;
  }
  for (double f : {1.001, 0.5}) {
    l.cmd("set atom 2 x " + num(x0 + f * SC));
    l.cmd("run 0");
    EXPECT_EQ(force_x(l, 1), 0.0) << f;
    EXPECT_EQ(l.lmp->force->pair->eng_vdwl, 0.0) << f;
  }
}

// An elastic oblique impact of the sphere on the dumbbell's part (e = 1, no
// friction): the bridge spins the dumbbell; from its formation until the
// bodies are apart, kinetic + rotational + pair energy is constant (2e-6 of
// the kinetic energy), and they leave with |U(0)| less, up to F(0) v dt
TEST(Bridge, CompositeBridgeKeepsTheEnergy)
{
  const double v = 0.15, dt = 1e-7;
  Lmp l;
  dumbbell_and_sphere(l, DB + R1 + R2 + 5e-5, 0.4 * R1, 1.0);
  l.cmds({"velocity all set 0 0 0", "set atom 2 vx " + num(-v), "fix 1 all nve/polyhedron",
          "timestep " + num(dt), "thermo 100", "run 0"});
  auto *a = l.lmp->atom;
  auto energy = [&]() { return two_body_energy(l); };
  const double K0 = energy();
  const double U0 = willett_energy(0.0);
  // a lower bound of the gap to the part: the centres' distance less the
  // part's offset and both radii
  auto gap = [&] {
    const double *x1 = a->x[a->map(1)], *x2 = a->x[a->map(2)];
    return std::sqrt(std::pow(x2[0] - x1[0], 2) + std::pow(x2[1] - x1[1], 2) +
                     std::pow(x2[2] - x1[2], 2)) - DB - R1 - R2;
  };
  const auto b = track_bridge_until_apart(l, 3000, energy, gap);
  ASSERT_TRUE(b.formed);
  ASSERT_GT(b.gap, SC) << "the sphere did not leave";
  const double K1 = energy();
  std::printf("[ bridge   ] sphere on a composite: K0 %.9e J, K1 %.9e J, K0 - K1 %.9e J, "
              "|U(0)| %.9e J, dumbbell spin energy %.3g J; energy from formation on constant "
              "to %.3g J\n", K0, K1, K0 - K1, -U0, l.thermo("c_er"), b.dev);
  EXPECT_GT(l.thermo("c_er"), 1e-3 * K0);    // the dumbbell was spun
  expect_energy_kept(b, K0, K1);
  EXPECT_NEAR(K0 - K1, -U0, willett(0.0) * 2.0 * v * dt);
}

// A bridge stretched between the sphere and the spun dumbbell (the impact
// above, e = 0.7) continues bit for bit after a restart: positions,
// velocities and spins of both bodies 3000 steps on
TEST(Bridge, CompositeBridgeRestartsExactly)
{
  const std::string file = ::testing::TempDir() + "polydem_bridge_composite_restart.bin";
  {
    Lmp l;
    dumbbell_and_sphere(l, DB + R1 + R2 + 5e-5, 0.4 * R1, 0.7);
    l.cmds({"velocity all set 0 0 0", "set atom 2 vx -0.1", "fix 1 all nve/polyhedron",
            "timestep 1e-7", "run 15000"});
    const double U = l.lmp->force->pair->eng_vdwl;
    std::printf("[ bridge   ] composite: pair energy at the restart %.4g J\n", U);
    ASSERT_LT(U, 0.0);    // bridged
    auto *a = l.lmp->atom;
    const double *x1 = a->x[a->map(1)], *x2 = a->x[a->map(2)];
    ASSERT_GT(std::hypot(x2[0] - x1[0], x2[1] - x1[1]) - DB - R1 - R2, 0.0);    // apart
    expect_restart_exact(l, file);
  }
}

// The viscous part: at gaps from s_min / 2 to s_c, the spheres moving
// apart and together, the force on each is Willett's plus Pitois et al.'s
// -c v_n (at setup: no cap), to 1e-12; in contact (e = 1, no dashpot) the
// velocity adds nothing (the contact's own dashpot damps it there); without
// 'viscous' the velocity adds nothing across the gap either.
TEST(Bridge, ViscousPartFollowsPitois)
{
  Lmp l;
  two_spheres(l, R1 + R2 - 1e-9, 1.0, "3e-4", VISCOUS);
  l.cmd("run 0");    // touching: the bridge forms
  int nchecked = 0;
  for (double s : {0.5 * SMIN, SMIN, 3.0 * SMIN, 0.01 * SC, 0.1 * SC, 0.4 * SC, 0.8 * SC,
                   0.999 * SC})
    for (double v : {0.02, -0.05}) {
      // sphere 2 moves away at v, sphere 1 towards it at v / 3
      l.cmds({"set atom 2 x " + num(R1 + R2 + s), "set atom 2 vx " + num(v),
              "set atom 1 vx " + num(v / 3.0), "run 0"});
      const double vn = v / 3.0 - v;    // approach speed (v_1 - v_2).n
      const double F = willett(s) - pitois(s) * vn;
      std::printf("[ bridge   ] viscous, s %.4g m, v_n %+.3f m/s: F %.9e N (Willett %.9e, "
                  "Pitois %+.9e)\n", s, vn, force_x(l, 1), willett(s), -pitois(s) * vn);
      EXPECT_NEAR(force_x(l, 1), F, 1e-12 * std::fabs(F)) << s << " " << v;
      EXPECT_NEAR(force_x(l, 2), -F, 1e-12 * std::fabs(F)) << s << " " << v;
      nchecked++;
    }
  EXPECT_EQ(nchecked, 16);
  // in contact (e = 1: no dashpot) the velocity changes nothing
  l.cmds({"set atom 2 x " + num(R1 + R2 - 2e-7), "set atom 2 vx 0", "set atom 1 vx 0", "run 0"});
  const double F0 = force_x(l, 1);
  l.cmds({"set atom 2 vx 0.03", "run 0"});
  EXPECT_EQ(force_x(l, 1), F0);
  // the capillary bridge alone does not see the velocity
  Lmp d;
  two_spheres(d, R1 + R2 - 1e-9, 1.0);
  d.cmds({"run 0", "set atom 2 x " + num(R1 + R2 + 0.1 * SC), "set atom 2 vx 0.05", "run 0"});
  EXPECT_NEAR(force_x(d, 1), willett(0.1 * SC), 1e-12 * willett(0.1 * SC));
}

// Above setup, the viscous coefficient is capped at m_eff / dt (as the
// normal dashpot): with eta 1e4 times water's the force in a step is
// Willett's plus (m_eff / dt) times the half-step velocities' approach
TEST(Bridge, ViscousPartIsCappedAtTheStableStep)
{
  Lmp l;
  const double dt = 1e-6;
  two_spheres(l, R1 + R2 - 1e-9, 1.0, "3e-4",
              BRIDGE + " viscous " + num(1e4 * ETA) + " " + num(SMIN));
  l.cmds({"run 0", "set atom 2 x " + num(R1 + R2 + 0.01 * SC), "velocity all set 0 0 0",
          "set atom 2 vx 0.02", "fix 1 all nve/polyhedron", "timestep " + num(dt), "run 1"});
  auto *a = l.lmp->atom;
  const int i1 = a->map(1), i2 = a->map(2);
  const double m1 = a->rmass[i1], m2 = a->rmass[i2], meff = m1 * m2 / (m1 + m2);
  // the velocities the step's force saw: v(n + 1/2) = v(n + 1) - f dt / (2 m)
  const double v1 = a->v[i1][0] - 0.5 * dt * a->f[i1][0] / m1;
  const double v2 = a->v[i2][0] - 0.5 * dt * a->f[i2][0] / m2;
  const double s = a->x[i2][0] - a->x[i1][0] - R1 - R2;
  const double c = 1e4 * pitois(s);
  ASSERT_GT(c * dt, meff) << "the case must hit the cap";
  const double F = willett(s) - meff / dt * (v1 - v2);
  std::printf("[ bridge   ] viscous cap: c dt / m_eff %.3g, F %.9e N (expected %.9e)\n",
              c * dt / meff, force_x(l, 1), F);
  EXPECT_NEAR(force_x(l, 1), F, 1e-9 * std::fabs(F));
  // and counted (once: the step's own contact; setup has no time step),
  // reported at the run's last step
  int dim;
  EXPECT_EQ(((double *) l.lmp->force->pair->extract("counters", dim))[polydem::PP_DAMPCAP], 1.0);
}

// A head-on collision (e = 1, no friction) that forms a viscous bridge and
// pulls it apart: from the bridge's formation on, kinetic + pair energy
// falls by the viscous work alone, the trapezoidal sum over the steps of
// c v_n^2 dt (v_n of the half-step velocities each force saw), to 0.1 %; it
// rises in no step by more than the elastic collision's round-off (2e-6 of
// the kinetic energy, as without the viscous part).
TEST(Bridge, ViscousBridgeDissipatesItsWork)
{
  Lmp l;
  const double v = 0.15, dt = 1e-7;
  two_spheres(l, R1 + R2 + 5e-5, 1.0, "3e-4", VISCOUS);
  l.cmds({"velocity all set 0 0 0", "set atom 1 vx " + num(v), "set atom 2 vx " + num(-v),
          "fix 1 all nve/polyhedron", "timestep " + num(dt), "thermo 100", "run 0"});
  auto *a = l.lmp->atom;
  auto energy = [&]() { return two_body_kinetic(l) + l.lmp->force->pair->eng_vdwl; };
  const double K0 = two_body_kinetic(l);
  bool formed = false;
  double E_formed = 0.0, work = 0.0, rise = 0.0, E_last = 0.0, gap = 0.0;
  for (int k = 0; k < 100000 && !(formed && gap > 1.2 * SC); k++) {
    l.cmd("run 1 pre no post no");
    const int i1 = a->map(1), i2 = a->map(2);
    gap = a->x[i2][0] - a->x[i1][0] - R1 - R2;
    const double pe = l.lmp->force->pair->eng_vdwl, E = energy();
    if (!formed && !(pe < 0.0)) continue;
    // the viscous power of this step's force (0 in contact and once
    // ruptured), half of it in the step it forms (its first half-kick came
    // before E_formed)
    const double v1 = a->v[i1][0] - 0.5 * dt * a->f[i1][0] / a->rmass[i1];
    const double v2 = a->v[i2][0] - 0.5 * dt * a->f[i2][0] / a->rmass[i2];
    const double P = gap > 0.0 && gap < SC ? pitois(gap) * (v1 - v2) * (v1 - v2) : 0.0;
    if (!formed) {
      formed = true;
      E_formed = E_last = E;
      work = 0.5 * P * dt;
      continue;
    }
    work += P * dt;
    rise = std::fmax(rise, E - E_last);
    E_last = E;
  }
  ASSERT_TRUE(formed);
  ASSERT_GT(gap, SC) << "the spheres did not separate";
  const double loss = E_formed - energy();
  std::printf("[ bridge   ] viscous collision: energy lost from formation on %.9e J, viscous "
              "work %.9e J (ratio %.6f); largest rise in a step %.3g J\n", loss, work,
              loss / work, rise);
  EXPECT_GT(work, 0.0);
  EXPECT_NEAR(loss, work, 1e-3 * work);
  EXPECT_LE(rise, 2e-6 * K0);
}

// A stretched viscous bridge continues bit for bit after a restart (its
// eta and s_min are in the restart file)
TEST(Bridge, ViscousBridgeRestartsExactly)
{
  Lmp l;
  two_spheres(l, R1 + R2 + 5e-5, 0.7, "3e-4", VISCOUS);
  l.cmds({"velocity all set 0 0 0", "set atom 1 vx 0.1", "set atom 2 vx -0.05",
          "fix 1 all nve/polyhedron", "timestep 1e-7", "run 6000"});
  auto *a = l.lmp->atom;
  const double gap = a->x[a->map(2)][0] - a->x[a->map(1)][0] - R1 - R2;
  EXPECT_GT(gap, 0.0);
  EXPECT_LT(gap, SC);
  expect_restart_exact(l, ::testing::TempDir() + "polydem_viscous_restart.bin");
}

TEST(Bridge, Errors)
{
  {
    Lmp l;
    two_spheres(l, 0.005, 1.0, "1e-4");
    const std::string e = l.error_of("run 0");
    EXPECT_NE(e.find("beyond the neighbor skin"), std::string::npos) << e;
  }
  Lmp l;
  l.cmds(polydem_test::unit_box(1, {"pair_style polyhedron"}));
  l.expect_error("pair_coeff * * 1e7 0.3 0.9 0.5 bridge 1e-11 0.07", "needs three values");
  l.expect_error("pair_coeff * * 1e7 0.3 0.9 0.5 bridge 1e-11 0.07 95", "contact angle theta must be in [0, 90)");
  l.expect_error("pair_coeff * * 1e7 0.3 0.9 0.5 bridge 0 0.07 10", "liquid volume V_b must be > 0");
  l.expect_error("pair_coeff * * 1e7 0.3 0.9 0.5 bridge 1e-11 -1 10", "surface tension gamma must be > 0");
  l.expect_error("pair_coeff * * 1e7 0.3 0.9 0.5 viscous 1e-3 1e-6", "give 'bridge V_b gamma theta' with it");
  l.expect_error("pair_coeff * * 1e7 0.3 0.9 0.5 bridge 1e-11 0.07 10 viscous 1e-3", "needs two values");
  l.expect_error("pair_coeff * * 1e7 0.3 0.9 0.5 bridge 1e-11 0.07 10 viscous 0 1e-6", "viscosity eta must be > 0");
  l.expect_error("pair_coeff * * 1e7 0.3 0.9 0.5 bridge 1e-11 0.07 10 viscous 1e-3 -1", "smallest gap s_min must be > 0");
  Lmp e;
  e.cmds(polydem_test::unit_box(1, {"pair_style ellipsoid"}));
  e.expect_error("pair_coeff * * 1e4 0.9 0.5 bridge 1e-11 0.07 10", "part of pair_style polyhedron");
}
