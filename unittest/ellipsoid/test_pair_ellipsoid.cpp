// Ellipsoid templates and pair_style ellipsoid through LAMMPS (issue 6):
// analytic mass properties, restart, restitution of a binary collision,
// elastic energy and momentum conservation, bad input.

#include "polydem_lmp.h"

#include "poly_shape_library.h"
#include "force.h"
#include "pair.h"
#include "ellipsoid_gas.h"
#include "polydem_ellipsoid_force.h"
#include "polydem_pair_counts.h"
#include "polydem_shape_template.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using polydem_test::Lmp;
using polydem_test::num;
using polydem_test::ellipsoid_mass;
using polydem_test::pair_contact_time;

namespace {

LAMMPS_NS::PolyShapeLibrary *avec_of(Lmp &l)
{
  return LAMMPS_NS::PolyShapeLibrary::of(l.lmp, "test");
}

std::vector<std::string> box_cmds()
{
  return {"units si", "atom_style polyhedron", "atom_modify map array", "boundary p p p",
          "comm_modify vel yes", "region box block 0 1 0 1 0 1", "create_box 1 box"};
}

// box_cmds() and two ellipsoids of semi-axes (a, b, c), template e, at x1
// and x2 ("x y z"), density rho
std::vector<std::string> two_ellipsoids(double a, double b, double c, const std::string &x1,
                                        const std::string &x2, double rho)
{
  std::vector<std::string> cmds = box_cmds();
  cmds.insert(cmds.end(),
              {"polyhedron_shape e ellipsoid " + num(a) + " " + num(b) + " " + num(c),
               "create_atoms 1 single " + x1, "create_atoms 1 single " + x2,
               "polyhedron_set group all density " + num(rho)});
  return cmds;
}

double total_energy(Lmp &l)
{
  return l.thermo("c_kt") + l.thermo("c_er") + l.thermo("pe");
}

void total_momentum(Lmp &l, double *p)
{
  double mine[3] = {0, 0, 0};
  auto *a = l.lmp->atom;
  for (int i = 0; i < a->nlocal; i++)
    for (int k = 0; k < 3; k++) mine[k] += a->rmass[i] * a->v[i][k];
  MPI_Allreduce(mine, p, 3, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
}

}    // namespace

// Mass and principal moments of an ellipsoid template are the analytic ones:
// m = rho 4/3 pi abc s^3, I_x = m s^2 (b^2 + c^2) / 5, ...
TEST(EllipsoidTemplate, MassAndInertia)
{
  Lmp l;
  l.cmds(box_cmds());
  l.cmds({"polyhedron_shape e ellipsoid 0.03 0.02 0.01", "create_atoms 1 single 0.5 0.5 0.5",
          "polyhedron_set group all scale 1.5 density 2000"});
  auto *av = avec_of(l);
  ASSERT_TRUE(av->shape(0).is_ellipsoid());
  const double a = 0.045, b = 0.03, c = 0.015;
  const double m = 2000.0 * 4.0 / 3.0 * M_PI * a * b * c;
  EXPECT_NEAR(l.lmp->atom->rmass[0], m, 1e-14 * m);
  EXPECT_NEAR(l.lmp->atom->radius[0], a, 1e-16);
  double mom[3];
  av->inertia(0, mom);
  EXPECT_NEAR(mom[0], m * (b * b + c * c) / 5.0, 1e-14 * mom[0]);
  EXPECT_NEAR(mom[1], m * (a * a + c * c) / 5.0, 1e-14 * mom[1]);
  EXPECT_NEAR(mom[2], m * (a * a + b * b) / 5.0, 1e-14 * mom[2]);
}

// A restart carries the ellipsoid template: no shape command needed, the
// semi-axes are bit-identical and the continued run is bit-identical.
// Also with friction (mu 0.4): the per-pair tangential history of the contacts
// active at the restart is restored (bit-identical continuation).
TEST(EllipsoidTemplate, RestartIsExact)
{
 for (const std::string mu : {"", " 0.4"}) {
  const std::string file = ::testing::TempDir() + "polydem_ellipsoid.restart";
  const std::string data = ::testing::TempDir() + "polydem_ellipsoid_restart.data";
  const polydem_test::GasSpec g = polydem_test::gas(3, 0.2, 1.0, 2.0);
  polydem_test::write_gas(data, g);
  auto setup = [&](Lmp &l) {
    l.cmds({"pair_style ellipsoid", "pair_coeff * * 1e6 0.9" + mu, "neighbor 0.01 bin",
            "fix 1 all nve/polyhedron", "timestep 2e-5"});
  };
  std::vector<double> ref;
  {
    Lmp l;
    l.cmds({"units si", "atom_style polyhedron", "atom_modify map array", "boundary p p p",
            "comm_modify vel yes", "polyhedron_shape e ellipsoid " + num(g.xi * g.b()) + " " +
                num(g.b()) + " " + num(g.b()),
            "read_data " + data});
    setup(l);
    l.cmd("run 300");
    // restart while contacts (and their friction histories) are active
    for (int k = 0; k < 200 && !(l.thermo("pe") > 0.0); k++) l.cmd("run 5");
    EXPECT_GT(l.thermo("pe"), 0.0);
    l.cmds({"write_restart " + file, "run 300"});
    for (auto &kv : l.local_state())
      for (int k = 0; k < 3; k++) ref.push_back(kv.second.x[k]);
  }
  Lmp l;
  l.cmds({"read_restart " + file, "comm_modify vel yes"});
  auto *av = avec_of(l);
  ASSERT_EQ(av->ntemplates(), 1);
  ASSERT_TRUE(av->shape(0).is_ellipsoid());
  EXPECT_EQ(av->shape(0).semi_axes()[0], g.xi * g.b());
  EXPECT_EQ(av->shape(0).semi_axes()[1], g.b());
  setup(l);
  l.cmd("run 300");
  std::vector<double> got;
  for (auto &kv : l.local_state())
    for (int k = 0; k < 3; k++) got.push_back(kv.second.x[k]);
  ASSERT_EQ(got.size(), ref.size());
  for (size_t i = 0; i < got.size(); i++) EXPECT_EQ(got[i], ref[i]) << i << " mu '" << mu << "'";
 }
}

// Head-on collision of two equal spheres (a = b = c): the linear spring-
// dashpot with gamma_n from e_n and m12 (seed §4) gives exactly e_n as the
// velocity ratio; with dt = t_c/50 the discrete result is within 1e-3.
// Also: the contact lasts t_c = pi sqrt(m12/k_n) / sqrt(1 - zeta^2)... checked
// only through e here; elastic case: energy back to 1e-6.
TEST(PairEllipsoid, RestitutionOfSpheres)
{
  for (double e : {1.0, 0.9, 0.5}) {
    Lmp l;
    const double r = 0.02, rho = 2000.0, kn = 1e6;
    const double m = ellipsoid_mass(rho, r, r, r);
    const double tc = pair_contact_time(m, kn);
    l.cmds(two_ellipsoids(r, r, r, "0.45 0.5 0.5", "0.55 0.5 0.5", rho));
    l.cmds({"polyhedron_set atom 2 quat 1 2 3 40", "velocity all set 0 0 0",
            "set atom 1 vx 1.0", "set atom 2 vx -1.0", "pair_style ellipsoid",
            "pair_coeff * * " + num(kn) + " " + num(e), "neighbor 0.005 bin",
            "fix 1 all nve/polyhedron", "timestep " + num(tc / 50.0), "run 3000"});
    auto st = l.local_state();
    const double vrel = st[2].v[0] - st[1].v[0];
    // damping uses half-step velocities: first order in dt (0.0044 at e = 0.5)
    EXPECT_NEAR(vrel / 2.0, e, e > 0.8 ? 1e-3 : 1e-2) << "e = " << e;
    EXPECT_NEAR(st[1].v[1], 0.0, 1e-12);
    EXPECT_NEAR(st[1].w[2], 0.0, 1e-12);
  }
}

// Eccentric impact: ellipsoid B (xi = 3, axis along z) moves along -x and hits
// the side of ellipsoid A (xi = 3, axis along y, at rest) 2/3 of the way out
// from A's centre, so A's rotation makes the contact's effective mass about
// m/4 instead of m12 = m/2. The restitution of the collision is the ratio of
// the overlap rates d(delta)/dt after and before, evaluated (gamma 0) in the
// pose of maximum overlap with the velocities before and after. 'damping
// contact' (gamma_n from m_eff) must give e_n within 1 % (n and the lever arm
// turn slightly during the contact); 'damping reduced' (the seed's m12) gives
// visibly less (about 0.60 for e_n = 0.7).
namespace {
double eccentric_restitution(const std::string &damping, double e)
{
  Lmp l;
  const double a = 0.03, b = 0.01, rho = 2000.0, kn = 1e6;
  const double m = ellipsoid_mass(rho, a, b, b);
  const double tc = pair_contact_time(m, kn);
  l.cmds(two_ellipsoids(a, b, b, "0.5 0.5 0.5", "0.519 0.52 0.5", rho));
  l.cmds({"polyhedron_set atom 1 quat 0 0 1 90",
          "polyhedron_set atom 2 quat 0 1 0 90", "velocity all set 0 0 0", "set atom 2 vx -1.0",
          "pair_style ellipsoid damping " + damping, "pair_coeff * * " + num(kn) + " " + num(e),
          "neighbor 0.005 bin", "fix 1 all nve/polyhedron", "thermo_style custom step pe",
          "timestep " + num(tc / 100.0), "run 0"});
  auto pose = [&](const Lmp::State &s) {
    polydem::EllipsoidPose<double> p;
    p.x = polydem::make_vec3(s.x[0], s.x[1], s.x[2]);
    p.q = polydem::make_quat(s.q[0], s.q[1], s.q[2], s.q[3]);
    p.axes = polydem::make_vec3(a, b, b);
    return p;
  };
  auto vec = [](const double *u) { return polydem::make_vec3(u[0], u[1], u[2]); };
  const auto before = l.local_state();
  double pe_max = 0.0;
  std::map<long, Lmp::State> peak;
  for (int k = 0; k < 400; k++) {
    l.cmd("run 5 pre no post no");
    const double pe = l.thermo("pe");
    if (pe > pe_max) {
      pe_max = pe;
      peak = l.local_state();
    }
  }
  EXPECT_GT(pe_max, 0.0);
  EXPECT_EQ(l.thermo("pe"), 0.0);    // the contact has ended
  const auto after = l.local_state();
  const auto A = pose(peak.at(1)), B = pose(peak.at(2));
  const auto c = polydem::ellipsoid_contact(A, B);
  EXPECT_EQ(c.status, polydem::STATUS_OK);
  auto rate = [&](const std::map<long, Lmp::State> &s) {
    polydem::ContactKinematics<double> kin;
    kin.xA = A.x;
    kin.xB = B.x;
    kin.vA = vec(s.at(1).v);
    kin.vB = vec(s.at(2).v);
    kin.wA = vec(s.at(1).w);
    kin.wB = vec(s.at(2).w);
    // d delta / dt of the centre measure
    return polydem::contact_rate(polydem::ellipsoid_geometry(c, polydem::OVERLAP_CENTRE, A.x, B.x),
                                 kin);
  };
  const double lever = polydem::norm(polydem::cross(c.c - A.x, c.n));
  const double ratio = -rate(after) / rate(before);
  printf("eccentric impact, damping %s, e_n %g: lever arm on A %.4g m, m_eff/m %.3f, "
         "restitution %.4f\n", damping.c_str(), e, lever,
         polydem::ellipsoid_contact_mass(c, polydem::OVERLAP_CENTRE, A, B, m, m) / m, ratio);
  EXPECT_GT(lever, 0.01);
  return ratio;
}
}    // namespace

TEST(PairEllipsoid, RestitutionOfEccentricImpact)
{
  for (double e : {1.0, 0.9, 0.7}) {
    const double got = eccentric_restitution("contact", e);
    EXPECT_NEAR(got, e, 0.01 * e) << "damping contact, e_n = " << e;
  }
  // the seed's reduced-mass damping over-damps this impact
  EXPECT_LT(eccentric_restitution("reduced", 0.7), 0.7 - 0.05);
}

// Elastic gas (e_n = 1): total energy (translational + rotational + spring)
// and momentum. 64 prolate ellipsoids (xi = 2) at solid fraction 0.1, v_rms
// 5 m/s per component, k_n = 1e8: about 200 collisions in 20,000 steps of
// t_c/50. Energy is sampled when no contact is active. Measured (overlap
// centre): max |E - E0|/E0 1.1e-4 at t_c/50, 3e-5 at t_c/100 (second order in
// dt: integration error only); the seed's chord overlap (not a gradient)
// drifts by 2.4e-3 in the same run. Tolerances: 3e-4 and 1e-4; momentum 1e-12.
// The acceptance run (1e-5 over 1e5 steps, N = 4096, seed parameters) is
// examples/hcs/in.elastic.
namespace {
struct GasRun {
  double max_err, max_dp, max_er, contacts;
};
GasRun elastic_gas(const std::string &overlap, int refine)
{
  const std::string data = ::testing::TempDir() + "polydem_ellipsoid_gas.data";
  // phi 0.1: lattice spacing > 2a, no initial overlaps
  const polydem_test::GasSpec g = polydem_test::gas(4, 0.1, 0.5, 5.0);
  polydem_test::write_gas(data, g);
  const double b = g.b(), kn = 1e8;
  const double m = g.mass();
  const double tc = pair_contact_time(m, kn);
  Lmp l;
  l.cmds(g.scene(data));
  l.cmds({"pair_style ellipsoid overlap " + overlap,
          "pair_coeff * * " + num(kn) + " 1.0", "neighbor " + num(0.2 * b) + " bin",
          "fix 1 all nve/polyhedron", "compute kt all ke", "compute er all erotate/polyhedron",
          "thermo 100", "thermo_style custom step pe",
          "timestep " + num(tc / (50.0 * refine)), "run 0"});
  const double e0 = total_energy(l);
  double p0[3];
  total_momentum(l, p0);
  const double pscale = m * g.vrms * 64;
  GasRun r{0.0, 0.0, 0.0, 0.0};
  for (int s = 0; s < 200; s++) {
    l.cmd("run " + std::to_string(100 * refine) + " pre no post no");
    if (l.thermo("pe") == 0.0)
      r.max_err = std::fmax(r.max_err, std::fabs(total_energy(l) - e0) / e0);
    r.max_er = std::fmax(r.max_er, l.thermo("c_er") / e0);
    double p[3];
    total_momentum(l, p);
    for (int k = 0; k < 3; k++) r.max_dp = std::fmax(r.max_dp, std::fabs(p[k] - p0[k]) / pscale);
  }
  int dim = 0;
  r.contacts = ((double *) l.lmp->force->pair->extract("counters", dim))[polydem::EP_CONTACTS];
  printf("elastic gas, overlap %s, dt = t_c/%d: %.0f contact evaluations, max |E - E0|/E0 "
         "%.3g, max momentum error %.3g, max E_rot/E0 %.3g\n",
         overlap.c_str(), 50 * refine, r.contacts, r.max_err, r.max_dp, r.max_er);
  return r;
}
}    // namespace

TEST(PairEllipsoid, ElasticGasConservesEnergyAndMomentum)
{
  const auto a = elastic_gas("centre", 1);
  EXPECT_GT(a.contacts, 3000.0);    // collisions did happen
  EXPECT_GT(a.max_er, 0.05);        // and transferred energy into rotation
  EXPECT_LT(a.max_err, 3e-4);
  EXPECT_LT(a.max_dp, 1e-12);
  const auto b = elastic_gas("centre", 2);
  EXPECT_LT(b.max_err, 1e-4);
  EXPECT_LT(b.max_dp, 1e-12);
}

// Two ellipsoids of unequal semi-axes under pair_style polyhedron (issue 29:
// every shape meets every shape) meet by pair_style ellipsoid's algebraic
// contact and linear law, with the pair's 'ellipsoid k_n': a frictional,
// dissipative gas of 64 prolate ellipsoids runs the same trajectory under
// either style, bit for bit (the same kernel, law and history convention;
// pair_style polyhedron's E and nu do not enter these pairs).
TEST(PairEllipsoid, PolyhedronStyleRunsEllipsoidPairsAlike)
{
  const std::string data = ::testing::TempDir() + "polydem_ellipsoid_alike.data";
  const polydem_test::GasSpec g = polydem_test::gas(4, 0.2, 0.5, 3.0);
  polydem_test::write_gas(data, g);
  const double b = g.b(), kn = 1e6;
  const double m = g.mass();
  const double dt = pair_contact_time(m, kn) / 50.0;
  auto run = [&](const std::vector<std::string> &pair) {
    Lmp l;
    l.cmds(g.scene(data));
    l.cmds(pair);
    l.cmds({"neighbor " + num(0.2 * b) + " bin", "fix 1 all nve/polyhedron",
            "timestep " + num(dt), "run 1500"});
    int dim = 0;
    const bool ell = std::string(l.lmp->force->pair_style) == "ellipsoid";
    const double *counters = (double *) l.lmp->force->pair->extract("counters", dim);
    const double contacts = counters[ell ? (int) polydem::EP_CONTACTS : (int) polydem::PP_CONTACTS];
    return std::make_pair(l.local_state(), contacts);
  };
  const auto ell = run({"pair_style ellipsoid", "pair_coeff * * " + num(kn) + " 0.8 0.4"});
  const auto pol =
      run({"pair_style polyhedron", "pair_coeff * * 1e9 0.3 0.8 0.4 ellipsoid " + num(kn)});
  std::printf("64 ellipsoids, 1500 steps: %.0f contact-steps under pair_style ellipsoid, %.0f "
              "under pair_style polyhedron\n", ell.second, pol.second);
  EXPECT_GT(ell.second, 500.0);    // contact-steps: collisions did happen
  EXPECT_EQ(ell.second, pol.second);
  ASSERT_EQ(ell.first.size(), pol.first.size());
  for (const auto &kv : ell.first) {
    const auto &q = pol.first.at(kv.first);
    for (int k = 0; k < 3; k++) {
      EXPECT_EQ(kv.second.x[k], q.x[k]) << "atom " << kv.first;
      EXPECT_EQ(kv.second.v[k], q.v[k]) << "atom " << kv.first;
      EXPECT_EQ(kv.second.L[k], q.L[k]) << "atom " << kv.first;
    }
  }
}

// Bad input: clear errors naming the command and the bad value.
TEST(PairEllipsoid, BadInput)
{
  Lmp l;
  l.cmds(box_cmds());
  l.expect_error("polyhedron_shape e ellipsoid 0.1 0 0.1", "semi-axis b must be > 0");
  l.expect_error("polyhedron_shape e ellipsoid 0.1 0.1 -2", "semi-axis c must be > 0");
  l.expect_error("polyhedron_shape e ellipsoid 0.1 0.1", "expected 3 semi-axes");
  l.cmds({"polyhedron_shape e ellipsoid 0.03 0.02 0.02",
          "polyhedron_shape c " + polydem_test::potentials() + "/cube.shape",
          "create_atoms 1 single 0.5 0.5 0.5", "pair_style ellipsoid"});
  l.expect_error("pair_coeff * * 1e6 0", "restitution e must be in (0, 1]");
  l.expect_error("pair_coeff * * 1e6 1.5", "restitution e must be in (0, 1]");
  l.expect_error("pair_coeff * * -1 0.5", "stiffness kn must be > 0");
  l.expect_error("pair_coeff * * 1e6", "expected 'I J kn e [mu] [rolling mu_r] [cohesion Gamma]'");
  l.expect_error("pair_coeff * * 1e6 0.9 -0.1", "friction mu must be >= 0");
  l.expect_error("pair_style ellipsoid tangential 0 0.5", "tangential kt/kn must be > 0");
  l.expect_error("pair_style ellipsoid tangential 0.3", "tangential needs 2 values");
  l.cmd("pair_style ellipsoid");
  l.cmds({"pair_coeff * * 1e6 0.9", "timestep 1e-5"});
  // an ellipsoid pair style with a polyhedron atom, and vice versa
  l.cmd("create_atoms 1 single 0.2 0.2 0.2");
  l.cmd("polyhedron_set atom 2 shape c");
  l.expect_error("run 0", "1 atoms have a polyhedron or composite shape (e.g. 'c')");
  l.cmds({"polyhedron_set atom 2 shape e", "run 0", "pair_style polyhedron",
          "pair_coeff * * 1e7 0.3 0.9 0.0"});
  l.expect_error("run 0", "shape 'e' is an ellipsoid with unequal semi-axes");
  l.expect_error("run 0", "types 1 and 1 lack: add 'ellipsoid k_n'");
  // the stiffness of ellipsoid pairs (pair_style polyhedron only)
  l.expect_error("pair_coeff * * 1e7 0.3 0.9 0.0 ellipsoid 0",
                 "ellipsoid stiffness k_n must be > 0, got '0'");
  l.expect_error("pair_coeff * * 1e7 0.3 0.9 0.0 ellipsoid", "'ellipsoid' needs a value");
  l.cmds({"pair_coeff * * 1e7 0.3 0.9 0.0 ellipsoid 1e6", "run 0"});
  l.cmds({"pair_style ellipsoid"});
  l.expect_error("pair_coeff * * 1e6 0.9 ellipsoid 1e6",
                 "'ellipsoid k_n' is a keyword of pair_style polyhedron");
}

// Two types of ellipsoids under pair_style polyhedron: the error for a
// missing 'ellipsoid k_n' says which pair_coeff line it goes on (the unlike
// pair's own line when it has one, else both types' lines)
TEST(PairEllipsoid, MissingStiffnessNamesItsLine)
{
  auto scene = [](Lmp &l) {
    l.cmds({"units si", "atom_style polyhedron", "atom_modify map array", "boundary p p p",
            "comm_modify vel yes", "region box block 0 1 0 1 0 1", "create_box 2 box",
            "polyhedron_shape e ellipsoid 0.03 0.02 0.01", "create_atoms 1 single 0.3 0.3 0.3",
            "create_atoms 2 single 0.6 0.6 0.6", "polyhedron_set group all density 1000",
            "pair_style polyhedron", "timestep 1e-5"});
  };
  {
    Lmp l;
    scene(l);
    l.cmds({"pair_coeff * * 1e7 0.3 0.9 0.0 ellipsoid 1e6", "pair_coeff 1 2 0.9 0.0"});
    l.expect_error("run 0",
                   "types 1 and 2 lack: add 'ellipsoid k_n' to their own pair_coeff 1 2");
    l.cmds({"pair_coeff 1 2 0.9 0.0 ellipsoid 2e6", "run 0"});
  }
  Lmp l;
  scene(l);
  l.cmds({"pair_coeff 1 1 1e7 0.3 0.9 0.0 ellipsoid 1e6", "pair_coeff 2 2 1e7 0.3 0.9 0.0"});
  l.expect_error("run 0", "types 1 and 2 lack: add 'ellipsoid k_n' to pair_coeff 1 1 and "
                          "pair_coeff 2 2 (mixed by the geometric mean), or to a pair_coeff 1 2");
  l.cmds({"pair_coeff 2 2 1e7 0.3 0.9 0.0 ellipsoid 3e6", "run 0"});
}

// Friction (pair_coeff ... mu): two spheres (r = 2 cm) both spinning at
// omega_z = 100 rad/s collide head-on along x at 2 m/s closing speed: the
// contact points slip at 2 omega r = 4 m/s along y. Elastic normal contact
// (F_n >= 0 throughout), mu = 0.1. The contact slides the whole time (the slip
// speed falls by 7 mu J_n / m = 1.4 < 4), so the tangential impulse is mu J_n,
// J_n = m12 (1 + e) v_n = 2 m: the spheres leave with v_y = -/+ mu J_n / m =
// 0.2 m/s, and both spins drop by r mu J_n / I = 25 rad/s (I = 2/5 m r^2).
// Measured 0.7 % off in both, beyond the point-contact model: the lever arm is
// r - delta/2 (delta_max = 1.8 % of r) and the normal tilts as the spheres
// slide apart. Tolerance 1.5 %; the normal velocities are exchanged as
// without friction.
TEST(PairEllipsoid, FrictionSlidingImpactOfSpheres)
{
  Lmp l;
  const double r = 0.02, rho = 2000.0, kn = 1e6, mu = 0.1;
  const double m = ellipsoid_mass(rho, r, r, r);
  const double tc = pair_contact_time(m, kn);
  l.cmds(two_ellipsoids(r, r, r, "0.45 0.5 0.5", "0.55 0.5 0.5", rho));
  l.cmds({"velocity all set 0 0 0", "set atom 1 vx 1.0", "set atom 2 vx -1.0",
          "set group all angmom 0 0 " + num(0.4 * m * r * r * 100.0), "pair_style ellipsoid",
          "pair_coeff * * " + num(kn) + " 1.0 " + num(mu), "neighbor 0.005 bin",
          "fix 1 all nve/polyhedron", "thermo_style custom step pe",
          "timestep " + num(tc / 50.0), "run 3000"});
  auto st = l.local_state();
  EXPECT_EQ(l.thermo("pe"), 0.0);    // the contact has ended
  const double dv = mu * 2.0 * m / m, w = 100.0 - r * mu * 2.0 * m / (0.4 * m * r * r);
  std::printf("friction, sliding sphere impact: v_y %.5f %.5f (expected %.5f %.5f), omega_z "
              "%.4f %.4f (expected %.4f), v_x %.6f %.6f\n", st[1].v[1], st[2].v[1], -dv, dv,
              st[1].w[2], st[2].w[2], w, st[1].v[0], st[2].v[0]);
  EXPECT_NEAR(st[1].v[1], -dv, 0.015 * dv);
  EXPECT_NEAR(st[2].v[1], dv, 0.015 * dv);
  EXPECT_NEAR(st[1].w[2], w, 0.015 * (100.0 - w));
  EXPECT_NEAR(st[2].w[2], w, 0.015 * (100.0 - w));
  EXPECT_NEAR(st[1].v[0], -1.0, 2e-3);
  EXPECT_NEAR(st[2].v[0], 1.0, 2e-3);
}

// Rolling resistance between two particles (EPSD, issue 30): a sphere
// (r = 1 cm, k_n = 1e4 N/m) rolling over the top of a fixed sphere of radius
// 50 m stops where the closed form for a flat says, d = 7 v0^2 / (10 mu_r g)
// (the rolling torque mu_r R_r m g against 7/5 m r^2; R_r = r R / (r + R)
// and the slope reached, 1.4e-4 rad, change d by less than 0.1 %), within
// 1 %, with mu_r from the pair's own coefficients and from the mixing of
// unlike types.
TEST(PairEllipsoid, RollingSphereOnASphereStopsAtTheClosedForm)
{
  const double r = 0.01, RB = 50.0, rho = 2000.0, kn = 1e4, g = 9.81, v0 = 0.1;
  const double m = ellipsoid_mass(rho, r, r, r);
  for (const std::string coeff : {"* * 1e4 0.5 0.5 rolling 0.1", "1 1 1e4 0.5 0.5 rolling 0.1|2 2 "
                                   "1e4 0.5 0.5 rolling 0.1"}) {
    Lmp l;
    const double z = RB + r - m * g / kn;
    l.cmds({"units si", "atom_style polyhedron", "atom_modify map array", "boundary f f f",
            "comm_modify vel yes", "region box block -60 60 -60 60 -60 60", "create_box 2 box",
            "polyhedron_shape s ellipsoid " + num(r) + " " + num(r) + " " + num(r),
            "polyhedron_shape big ellipsoid " + num(RB) + " " + num(RB) + " " + num(RB),
            "create_atoms 1 single 0 0 " + num(z), "create_atoms 2 single 0 0 0",
            "polyhedron_set atom 1 density " + num(rho),
            "polyhedron_set atom 2 shape big density " + num(rho), "group a id 1",
            "velocity a set " + num(v0) + " 0 0", "polyhedron_set atom 1 omega 0 " + num(v0 / r) + " 0",
            "pair_style ellipsoid"});
    size_t from = 0;
    while (true) {    // '|' separates pair_coeff lines
      const size_t bar = coeff.find('|', from);
      l.cmd("pair_coeff " + coeff.substr(from, bar == std::string::npos ? bar : bar - from));
      if (bar == std::string::npos) break;
      from = bar + 1;
    }
    l.cmds({"neighbor 0.001 bin", "fix 1 a nve/polyhedron", "fix g a gravity 9.81 vector 0 0 -1",
            "timestep 5e-5", "run 0"});
    auto *a = l.lmp->atom;
    const int i = a->map(1);
    const double x0 = a->x[i][0];
    double d = -1.0;
    for (int n = 0; n < 10000 && d < 0.0; n += 10) {
      const double xp = a->x[i][0], vp = a->v[i][0];
      l.cmd("run 10 pre no post no");
      if (a->v[i][0] <= 0.0) d = xp + vp * vp / (2.0 * (vp - a->v[i][0]) / (10 * 5e-5)) - x0;
    }
    const double expect = 7.0 * v0 * v0 / (10.0 * 0.1 * g);
    std::printf("rolling sphere on a sphere (pair_coeff %s): stopped after %.6g m, closed form "
                "%.6g m (%+.3f %%)\n", coeff.c_str(), d, expect, 100.0 * (d / expect - 1.0));
    EXPECT_NEAR(d, expect, 0.01 * expect);
  }
}

// The rolling torque history (8 values per pair) and the rolling and
// cohesion coefficients are written to restart files: a sphere rolling over
// a fixed sphere (as above, with cohesion) continues bit for bit after
// write_restart / read_restart; a run that would read or keep a
// history of another size (rolling resistance switched off for all pairs
// after a restart, or between two runs) is an error that says so.
namespace {
std::vector<std::string> rolling_pair(const std::string &coeff)
{
  const double r = 0.01, RB = 50.0;
  return {"units si", "atom_style polyhedron", "atom_modify map array", "boundary f f f",
          "comm_modify vel yes", "region box block -60 60 -60 60 -60 60", "create_box 2 box",
          "polyhedron_shape s ellipsoid " + num(r) + " " + num(r) + " " + num(r),
          "polyhedron_shape big ellipsoid " + num(RB) + " " + num(RB) + " " + num(RB),
          "create_atoms 1 single 0 0 " + num(RB + r - 1e-6), "create_atoms 2 single 0 0 0",
          "polyhedron_set atom 1 density 2000 omega 0 10 0", "polyhedron_set atom 2 shape big density 2000",
          "group a id 1", "velocity a set 0.1 0 0", "pair_style ellipsoid", "pair_coeff * * " + coeff,
          "neighbor 0.001 bin", "fix 1 a nve/polyhedron", "fix g a gravity 9.81 vector 0 0 -1",
          "timestep 5e-5"};
}
}    // namespace

TEST(PairEllipsoid, RollingHistoryRestartsExactlyAndItsSizeIsChecked)
{
  const std::string rst = ::testing::TempDir() + "polydem_rolling_pair.restart";
  double ref[6];
  {
    Lmp l;
    l.cmds(rolling_pair("1e4 0.5 0.5 rolling 0.1 cohesion 0.05"));
    l.cmd("run 400");
    l.cmd("write_restart " + rst);
    l.cmd("run 400");
    auto *a = l.lmp->atom;
    const int i = a->map(1);
    for (int k = 0; k < 3; k++) ref[k] = a->x[i][k], ref[3 + k] = a->omega[i][k];
    // between runs: the history of 8 values cannot become one of 3
    l.cmd("pair_coeff * * 1e4 0.5 0.5");
    const std::string err = l.error_of("run 10");
    EXPECT_NE(err.find("the contact history of the previous run keeps 8 values per pair, this "
                       "run needs 3"), std::string::npos) << err;
  }
  const std::vector<std::string> again = {"comm_modify vel yes", "neighbor 0.001 bin",
                                          "group a id 1", "fix 1 a nve/polyhedron",
                                          "fix g a gravity 9.81 vector 0 0 -1", "timestep 5e-5"};
  {
    Lmp l;
    l.cmd("read_restart " + rst);
    l.cmds(again);
    l.cmd("run 400");
    auto *a = l.lmp->atom;
    const int i = a->map(1);
    for (int k = 0; k < 3; k++) {
      EXPECT_EQ(a->x[i][k], ref[k]) << k;
      EXPECT_EQ(a->omega[i][k], ref[3 + k]) << k;
    }
    // the coefficients came back with the restart file
    int dim = 0;
    auto **coh = (double **) l.lmp->force->pair->extract("cohesion", dim);
    auto **roll = (double **) l.lmp->force->pair->extract("rolling", dim);
    EXPECT_EQ(coh[1][1], 0.05);
    EXPECT_EQ(coh[1][2], 0.05);
    EXPECT_EQ(roll[2][2], 0.1);
  }
  Lmp l;
  l.cmd("read_restart " + rst);
  l.cmds(again);
  l.cmd("pair_coeff * * 1e4 0.5 0.5");
  const std::string err = l.error_of("run 10");
  EXPECT_NE(err.find("the restart file's contact history keeps 8 values per pair, this run "
                     "needs 3"), std::string::npos) << err;
}

// Dry cohesion between two spheres (DMT, issue 30): sphere 2 (r = 1 cm,
// k_n = 1e4 N/m, e = 0.5, surface energy Gamma = 0.2 J/m^2) touching a fixed
// sphere 1 of the same size (overlap 1e-7 m), no gravity, settles at the overlap where the
// spring balances the pull 2 pi Gamma R_r, R_r = (r - delta/2) / 2 (the
// contact point halfway): delta = pi Gamma r / (k_n + pi Gamma / 2), within
// 1e-6; pulled apart by a constant force, it holds 0.98 of the pull-off
// force 2 pi Gamma r / 2 and separates at 1.02 of it (the pull ramped up
// over 100 contact times).
namespace {
double cohesive_pair(double pull, double &delta)
{
  const double r = 0.01, rho = 2000.0, kn = 1e4, Gamma = 0.2;
  const double m = ellipsoid_mass(rho, r, r, r), tc = M_PI * std::sqrt(m / kn);
  Lmp l;
  l.cmds(box_cmds());
  l.cmds({"polyhedron_shape s ellipsoid " + num(r) + " " + num(r) + " " + num(r),
          "create_atoms 1 single 0.5 0.5 0.3", "create_atoms 1 single 0.5 0.5 " + num(0.3 + 2 * r - 1e-7),
          "polyhedron_set group all density " + num(rho), "group b id 2",
          "pair_style ellipsoid", "pair_coeff * * " + num(kn) + " 0.5 cohesion " + num(Gamma),
          "neighbor 0.005 bin", "fix 1 b nve/polyhedron",
          // the pull ramped over 100 t_c (quasi-static), then held
          "variable f equal " + num(pull) + "*(step/5000.0*(step<5000)+(step>=5000))",
          "fix pull b addforce 0 0 v_f", "timestep " + num(tc / 50.0), "run 10000"});
  auto *a = l.lmp->atom;
  delta = 2 * r - (a->x[a->map(2)][2] - a->x[a->map(1)][2]);
  return a->v[a->map(2)][2];
}
}    // namespace

TEST(PairEllipsoid, CohesionEquilibriumAndPullOff)
{
  const double r = 0.01, kn = 1e4, Gamma = 0.2;
  double delta = 0.0;
  const double v = cohesive_pair(0.0, delta);
  const double expect = M_PI * Gamma * r / (kn + M_PI * Gamma / 2.0);
  std::printf("cohesive spheres at rest: overlap %.10g m (closed form %.10g), v %.3g m/s\n", delta,
              expect, v);
  EXPECT_NEAR(delta, expect, 1e-6 * expect);
  const double Fpo = 2.0 * M_PI * Gamma * r / 2.0;
  double d_hold = 0.0, d_off = 0.0;
  cohesive_pair(0.98 * Fpo, d_hold);
  const double v_off = cohesive_pair(1.02 * Fpo, d_off);
  std::printf("pulled at 0.98 / 1.02 of the pull-off force %.6g N: overlap %.4g m / %.4g m "
              "(v %.3g m/s)\n", Fpo, d_hold, d_off, v_off);
  EXPECT_GT(d_hold, 0.0);
  EXPECT_LT(d_off, 0.0);    // separated
  EXPECT_GT(v_off, 0.0);
}

// The friction history survives a change of the atom that holds the pair in
// the neighbor list. Atom 2 slides along +y (5 m/s, mu = 0.8) on atom 1,
// their centres 0.0399 apart along x, while atom_modify sort (binsize 0.2)
// reorders them at every reneighboring: atom 2 starts in a lower sort bin
// (y < 0.4) and so first in memory, and moves above atom 1's bin during the
// contact, so the pair passes from atom 2's neighbor list to atom 1's.
// Reneighboring every step must give the run whose list is built once, to
// round-off (1e-12 relative): a pair's history is that of its lower-tag atom,
// copied to the partner unchanged (polydem_contact_law.h). Copied negated
// (LAMMPS's default transfer), the tangential spring flips sign at the swap
// and atom 2's final y differs by 2.7e-5 m.
namespace {
std::map<long, Lmp::State> sliding_contact(const std::string &neigh)
{
  Lmp l;
  l.cmds(box_cmds());
  const double r = 0.02, rho = 2000.0, kn = 1e6;
  const double m = ellipsoid_mass(rho, r, r, r);
  const double tc = pair_contact_time(m, kn);
  l.cmds({"atom_modify sort 1 0.2",
          "polyhedron_shape s ellipsoid " + num(r) + " " + num(r) + " " + num(r),
          "create_atoms 1 single 0.381 0.4005 0.5", "create_atoms 1 single 0.4209 0.3995 0.5",
          "polyhedron_set group all density " + num(rho), "velocity all set 0 0 0",
          "set atom 2 vy 5.0", "pair_style ellipsoid", "pair_coeff * * " + num(kn) + " 1.0 0.8",
          "neighbor 0.03 bin", "neigh_modify binsize 0.2 " + neigh, "fix 1 all nve/polyhedron",
          "thermo_style custom step pe", "timestep " + num(tc / 50.0), "run 40"});
  EXPECT_EQ(l.thermo("pe"), 0.0);    // the contact has ended
  return l.local_state();
}
}    // namespace

TEST(PairEllipsoid, FrictionHistoryFollowsThePairAcrossLists)
{
  const auto once = sliding_contact("every 100000 delay 0 check no");
  const auto every = sliding_contact("every 1 delay 0 check no");
  std::printf("sliding contact: atom 2 y %.9f, w_z %.6g (list built once); y %.9f, w_z %.6g "
              "(rebuilt every step)\n", once.at(2).x[1], once.at(2).w[2], every.at(2).x[1],
              every.at(2).w[2]);
  EXPECT_GT(std::fabs(once.at(2).w[2]), 1.0);    // friction acted
  for (long t : {1L, 2L})
    for (int k = 0; k < 3; k++) {
      EXPECT_NEAR(every.at(t).x[k], once.at(t).x[k], 1e-12) << "atom " << t << " x" << k;
      EXPECT_NEAR(every.at(t).v[k], once.at(t).v[k], 1e-12 * 5.0) << "atom " << t << " v" << k;
      EXPECT_NEAR(every.at(t).w[k], once.at(t).w[k], 1e-12 * std::fabs(once.at(t).w[2]))
          << "atom " << t << " w" << k;
    }
}

// Friction with eccentric contacts: a frictional elastic gas of 64 prolate
// ellipsoids (xi = 2, mu = 0.5, 'damping contact', e_n = 1) conserves linear
// momentum and total angular momentum (orbital about the origin plus spin)
// to round-off, the pair's forces and torques being exactly opposite about
// the contact point; friction only dissipates: the total energy does not grow
// beyond the integration error of the elastic gas (3e-4, as in
// ElasticGasConservesEnergyAndMomentum; measured 2.9e-5) and has dropped by
// the end (measured 7.5 %). A box without periodic
// images (boundary m: it follows the gas) so that the orbital angular momentum
// is defined; k_n = 1e6 N/m, dt = t_c/53, speeds ~ 1.7 m/s.
TEST(PairEllipsoid, FrictionConservesMomentaAndDissipates)
{
  Lmp l;
  l.cmds({"units si", "atom_style polyhedron", "atom_modify map array", "boundary m m m",
          "comm_modify vel yes", "region box block 0 0.4 0 0.4 0 0.4", "create_box 1 box",
          "polyhedron_shape e ellipsoid 0.03 0.015 0.015", "lattice sc 0.1 origin 0.5 0.5 0.5",
          "create_atoms 1 box", "polyhedron_set group all density 2000 quat/random 5",
          "velocity all create 4e21 17 dist gaussian mom yes rot yes",
          "pair_style ellipsoid damping contact", "pair_coeff * * 1e6 1.0 0.5",
          "neighbor 0.01 bin", "fix 1 all nve/polyhedron",
          "compute kt all ke", "compute er all erotate/polyhedron",
          "thermo_style custom step c_kt c_er pe", "timestep 1e-5"});
  auto momenta = [&](double *P, double *Lt) {
    auto *a = l.lmp->atom;
    for (int k = 0; k < 3; k++) P[k] = Lt[k] = 0.0;
    for (int i = 0; i < a->nlocal; i++) {
      const double *x = a->x[i], *v = a->v[i], m = a->rmass[i];
      P[0] += m * v[0], P[1] += m * v[1], P[2] += m * v[2];
      Lt[0] += m * (x[1] * v[2] - x[2] * v[1]) + a->angmom[i][0];
      Lt[1] += m * (x[2] * v[0] - x[0] * v[2]) + a->angmom[i][1];
      Lt[2] += m * (x[0] * v[1] - x[1] * v[0]) + a->angmom[i][2];
    }
  };
  l.cmd("run 0");
  double P0[3], L0[3];
  momenta(P0, L0);
  const double E0 = total_energy(l);
  double pscale = 0, lscale = 0;
  {
    auto *a = l.lmp->atom;
    for (int i = 0; i < a->nlocal; i++) {
      const double *v = a->v[i];
      pscale += a->rmass[i] * std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    }
    lscale = pscale * 0.4;
  }
  double maxE = E0, dP = 0, dL = 0;
  for (int k = 0; k < 40; k++) {
    l.cmd("run 250 pre no post no");
    double P[3], Lt[3];
    momenta(P, Lt);
    for (int d = 0; d < 3; d++) {
      dP = std::fmax(dP, std::fabs(P[d] - P0[d]));
      dL = std::fmax(dL, std::fabs(Lt[d] - L0[d]));
    }
    maxE = std::fmax(maxE, total_energy(l));
  }
  const double E1 = total_energy(l);
  const double contacts = l.lmp->force->pair->pvector[0];
  std::printf("frictional gas: energy %.6g -> %.6g (max %.6g), |dP| %.3g of %.3g, |dL| %.3g of "
              "%.3g, %g collisions in the last run\n", E0, E1, maxE, dP, pscale, dL, lscale,
              contacts);
  EXPECT_LT(dP, 1e-12 * pscale);
  EXPECT_LT(dL, 1e-10 * lscale);
  EXPECT_LT(maxE, E0 * (1 + 3e-4));    // integration error only (elastic gas: 1.1e-4)
  EXPECT_LT(E1, 0.99 * E0);
}

// Homogeneous cooling, shortened (issue 6, acceptance 3; the full runs are
// examples/hcs). N = 512 prolate ellipsoids, xi = 2, solid fraction 0.058,
// rho = 2000, k_n = 1e8, dt = t_c/50, v_rms 8 m/s: elastic warm-up (rotation
// equilibrates; the collision rate per particle Gamma0 is measured), then
// e_n = 0.9 with 'damping contact' (every collision has restitution e_n) up to
// tau = alpha Gamma0 t ~ 0.36, alpha = (1 - e_n^2)/10 (D = 5). Asserted, for
// tau in [0.1, end]: the kinetic energy E = E_tr + E_rot follows Haff's law
// 1/(1 + tau)^2 (seed Eq. 27) within 5% (measured 1.7%), and T_tr/T_rot stays
// within [0.8, 1.25] (equipartition for xi >= 2, seed Fig. 8). E rather than
// E_tr: with N = 512 the split between translation and rotation fluctuates by
// several % (E_tr(0) is one sample of it); examples/hcs uses E_tr with N = 4096
// over tau up to 5, and Gamma0 from Eq. 28.
TEST(PairEllipsoid, HomogeneousCoolingShort)
{
  const std::string data = ::testing::TempDir() + "polydem_ellipsoid_hcs.data";
  const polydem_test::GasSpec g = polydem_test::gas(8, 0.058, 1.0, 8.0, 4928);
  polydem_test::write_gas(data, g);
  const double b = g.b(), kn = 1e8, en = 0.9;
  const double m = g.mass();
  const double dt = pair_contact_time(m, kn) / 50.0;
  Lmp l;
  l.cmds(g.scene(data));
  l.cmds({"pair_style ellipsoid damping contact",
          "pair_coeff * * " + num(kn) + " 1.0",
          "neighbor " + num(b) + " bin", "fix 1 all nve/polyhedron",
          "compute er all erotate/polyhedron", "compute cp all pair ellipsoid",
          "compute kt all ke", "thermo_style custom step c_kt c_er c_cp[1]",
          "timestep " + num(dt), "run 10000"});
  const int nmeasure = 10000;
  l.cmd("run " + std::to_string(nmeasure));
  const double ncoll =
      ((double *) lammps_extract_compute(l.lmp, "cp", LMP_STYLE_GLOBAL, LMP_TYPE_VECTOR))[0];
  const double gamma0 = 2.0 * ncoll / (512.0 * nmeasure * dt);
  const double e0 = l.thermo("c_kt") + l.thermo("c_er");
  const double alpha = (1.0 - en * en) / 10.0;
  l.cmd("pair_coeff * * " + num(kn) + " " + num(en));
  double max_dev = 0.0, min_ratio = 1e30, max_ratio = 0.0, tau = 0.0;
  const int chunk = 5000;
  for (int k = 1; k <= 14; k++) {
    l.cmd("run " + std::to_string(chunk));
    tau = alpha * gamma0 * k * chunk * dt;
    const double etr = (l.thermo("c_kt") + l.thermo("c_er")) / e0;
    const double ttr_trot = (2.0 / 3.0) * l.thermo("c_kt") / l.thermo("c_er");
    min_ratio = std::fmin(min_ratio, ttr_trot);
    max_ratio = std::fmax(max_ratio, ttr_trot);
    if (tau >= 0.1) {
      const double haff = 1.0 / std::pow(1.0 + tau, 2);
      max_dev = std::fmax(max_dev, std::fabs(etr / haff - 1.0));
    }
  }
  printf("HCS short: Gamma0 %.4g /s from %.0f collisions, tau reached %.3g, max |E/E0 / "
         "Haff(tau) - 1| %.3g, T_tr/T_rot in [%.3f, %.3f]\n",
         gamma0, ncoll, tau, max_dev, min_ratio, max_ratio);
  EXPECT_GT(ncoll, 300.0);
  EXPECT_GT(tau, 0.3);
  EXPECT_LT(max_dev, 0.05);
  EXPECT_GT(min_ratio, 0.8);
  EXPECT_LT(max_ratio, 1.25);
}
