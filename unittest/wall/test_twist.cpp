// Twisting friction (polydem_contact_law.h): a cube resting flat on a floor
// (fix wall/mesh) or on a frozen plate (pair polyhedron), spun about the
// vertical axis, stops in the time its Coulomb torque predicts and stays
// flat. (Pairs apply friction at the centre of pressure, pressure_centre;
// at the centroid of the overlap volume, a thin wedge whose centroid moves
// by millimetres for a tilt of 1e-8 rad, the cube tipped onto an edge
// within ~60 steps and spun on.) A cube given a wobble as well (1e-4 rad/s
// about x) tips onto an edge on the mesh and on the plate alike: a face
// resting in the core overlaps by nanometres and has no tilting stiffness
// below a tilt of 2h/L (3e-7 rad here), and the rocking grows from the spin.
// For a uniform pressure on a square face of side L the Coulomb torque is
// mu m g L (sqrt(2) + ln(1 + sqrt(2))) / 6 = 0.38260 mu m g L, so the spin
// omega0 decays linearly to zero in t* = I omega0 / M, I = m L^2 / 6. The law
// takes the disk of the contact area (lever 2/3 sqrt(A/pi) = 0.37613 L:
// 1.7 % less); the measured stop time must be within 2 % of t*. Without the
// twisting part the cube keeps spinning (a point spring at the centroid of
// the contact resists no spin about the normal).
#include "polydem_lmp.h"
#include "wall_meshes.h"

#include "atom.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using polydem_test::Lmp;
using polydem_test::num;
using polydem_test::potentials;
using namespace wall_test;

namespace {

constexpr double L = 0.025, RHO = 1500.0, E = 1.0e6, NU = 0.1, MU = 0.5, G = 9.81;
constexpr double W0 = 30.0, DT = 2e-5;

// spin of the cube (atom 1) about z, sampled each 'every' steps; returns the
// time tstop the spin first falls below 1 % of omega0 (or -1), the spin at
// tstar and the largest tilt of the cube's axis from the vertical [rad]
void stop_time(bool on_mesh, bool twist, double &spin_at_tstar, double tstar, double &tstop,
               double &tilt)
{
  const std::string stl = tmpdir() + "/twist_floor.stl";
  write_ascii(stl, flat(-0.05, 0.05, -0.05, 0.05, 0.0, 4, 4, true));
  const std::string tw = twist ? "yes" : "no";
  Lmp l;
  l.cmds({"units si", "atom_style polyhedron", "atom_modify map array", "boundary f f f",
          "comm_modify vel yes", "region box block -0.1 0.1 -0.1 0.1 -0.1 0.1",
          "create_box 1 box", "polyhedron_shape c " + potentials() + "/cuboid_2p5cm.shape",
          "create_atoms 1 single 0.007 -0.004 " + num(L / 2 - 1e-9)});    // off-centre
  if (!on_mesh) {
    // a frozen plate (10 x 10 x 1 cm) under the cube: the contact area stays L^2
    const std::string plate = tmpdir() + "/twist_plate.shape";
    std::FILE *fp = std::fopen(plate.c_str(), "w");
    ASSERT_NE(fp, nullptr);
    std::fprintf(fp, "vertices 8\n");
    for (int k = 0; k < 8; k++)
      std::fprintf(fp, "%g %g %g\n", (k & 1) ? 0.05 : -0.05, (k & 2) ? 0.05 : -0.05,
                   (k & 4) ? 0.005 : -0.005);
    std::fclose(fp);
    l.cmds({"polyhedron_shape p " + plate, "create_atoms 1 single 0 0 " + num(-0.005 + 1e-9),
            "group bottom id 2", "polyhedron_set group bottom shape p"});
  }
  l.cmds({"polyhedron_set group all scale 1 density " + num(RHO),
          "pair_style polyhedron twist " + tw,
          "pair_coeff * * " + num(E) + " " + num(NU) + " 0.5 " + num(MU),
          "group top id 1"});
  if (on_mesh) l.cmd("fix w all wall/mesh " + stl + " twist " + tw);
  l.cmds({"fix g top gravity " + num(G) + " vector 0 0 -1", "fix nve top nve/polyhedron",
          "timestep " + num(DT), "thermo 0", "run 5000"});    // settle: normal force m g
  const double m = RHO * L * L * L, I = m * L * L / 6.0;
  l.cmd("set atom 1 angmom 0 0 " + num(I * W0));
  l.cmd("run 0");
  const int every = 25;
  double t = 0.0;
  tstop = -1.0;
  spin_at_tstar = -1.0;
  tilt = 0.0;
  for (int k = 0; k < 2000 && (tstop < 0.0 || spin_at_tstar < 0.0) && t < 2.0 * tstar; k++) {
    l.cmd("run " + std::to_string(every) + " pre no post no");
    t += every * DT;
    const double w = l.lmp->atom->omega[l.lmp->atom->map(1)][2];
    const double *q = l.lmp->atom->quat[l.lmp->atom->map(1)];
    tilt = std::max(tilt, std::acos(std::min(1.0, 1.0 - 2.0 * (q[1] * q[1] + q[2] * q[2]))));
    if (tstop < 0.0 && std::fabs(w) < 0.01 * W0) tstop = t;
    if (spin_at_tstar < 0.0 && t >= tstar) spin_at_tstar = w;
  }
}

}    // namespace

TEST(Twist, SpinningCubeStopsInTheCoulombTime)
{
  const double lever = (std::sqrt(2.0) + std::log(1.0 + std::sqrt(2.0))) / 6.0 * L;
  const double tstar = (L * L / 6.0) * W0 / (MU * G * lever);
  for (bool mesh : {true, false}) {
    double w_at = 0.0, ts = 0.0, tilt = 0.0;
    stop_time(mesh, true, w_at, tstar, ts, tilt);
    std::printf("[ twist    ] %s: spin %.0f rad/s stops after %.4g s, Coulomb time of the square "
                "%.4g s (ratio %.4f)\n", mesh ? "cube on a mesh floor" : "cube on a cube",
                W0, ts, tstar, ts / tstar);
    EXPECT_GT(ts, 0.0);
    // the square's Coulomb torque is 1.7 % above the disk's the law takes
    EXPECT_NEAR(ts / tstar, 1.0, 0.02) << (mesh ? "mesh" : "pair");
    std::printf("[ twist    ] largest tilt %.3g rad\n", tilt);
    EXPECT_LT(tilt, 1e-3) << (mesh ? "mesh" : "pair");
    double w_off = 0.0, ts_off = 0.0, tilt_off = 0.0;
    stop_time(mesh, false, w_off, tstar, ts_off, tilt_off);
    std::printf("[ twist    ] %s without twist: spin at t* %.3g rad/s\n", mesh ? "mesh" : "pair",
                w_off);
    EXPECT_GT(std::fabs(w_off), 0.5 * W0) << (mesh ? "mesh" : "pair");
  }
}
