// Ellipsoids on fix wall/mesh (issue 16), through LAMMPS:
// 1. central impact on a flat mesh (the a, b or c axis normal to it, turned
//    about the normal; e = 0.5 and 0.9, from pair_coeff or the fix's
//    restitution keyword): v_out / v_in within 2 % of e, no spin; elastic
//    off-centre impacts keep the energy to 1e-4 (the exact gradient);
// 2. a flat square as 2, 8, 32 and 512 triangles (merge no): force and
//    torque of ellipsoids in contact (random and axis-aligned orientations,
//    the foot on vertices, internal edges and the diagonal, moving and
//    spinning: damping and friction act) equal to 1e-12 of the force;
// 3. an inclined mesh (mu = 0.5): sticks for tan(theta) < mu, slides with
//    the acceleration g (sin theta - mu cos theta) within 2 % otherwise;
// 4. fix insert/polyhedron places ellipsoids apart from a mesh crossing its
//    region (no wall contact), and bad input (a group of polyhedra and
//    ellipsoids, ellipsoids without pair_style ellipsoid) is an error.
#include "polydem_lmp.h"
#include "wall_meshes.h"

#include "fix.h"
#include "modify.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using polydem_test::Lmp;
using polydem_test::num;
using namespace wall_test;

namespace {

struct Q {
  double w, x, y, z;
};
Q qmul(const Q &a, const Q &b)
{
  return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z,
          a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
          a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
          a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}
Q axis_angle(double ax, double ay, double az, double deg)
{
  const double n = std::sqrt(ax * ax + ay * ay + az * az), h = 0.5 * deg * M_PI / 180.0;
  return {std::cos(h), std::sin(h) * ax / n, std::sin(h) * ay / n, std::sin(h) * az / n};
}
// polyhedron_set's "quat a b c theta" of a unit quaternion
std::string quat_words(Q q)
{
  if (q.w < 0) q = {-q.w, -q.x, -q.y, -q.z};
  const double s = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z);
  if (s < 1e-15) return "quat 0 0 1 0";
  const double th = 2.0 * std::atan2(s, q.w) * 180.0 / M_PI;
  return "quat " + num(q.x / s) + " " + num(q.y / s) + " " + num(q.z / s) + " " + num(th);
}
// rotation matrix of q (body -> lab)
void quat_matrix(const Q &q, double R[3][3])
{
  const double w = q.w, x = q.x, y = q.y, z = q.z;
  R[0][0] = 1 - 2 * (y * y + z * z), R[0][1] = 2 * (x * y - w * z), R[0][2] = 2 * (x * z + w * y);
  R[1][0] = 2 * (x * y + w * z), R[1][1] = 1 - 2 * (x * x + z * z), R[1][2] = 2 * (y * z - w * x);
  R[2][0] = 2 * (x * z - w * y), R[2][1] = 2 * (y * z + w * x), R[2][2] = 1 - 2 * (x * x + y * y);
}
// support sqrt(n^T M n) of semi-axes ax in orientation q along lab n
double support(const double ax[3], const Q &q, const double n[3])
{
  double R[3][3], s = 0.0;
  quat_matrix(q, R);
  for (int k = 0; k < 3; k++) {
    double nb = 0.0;
    for (int i = 0; i < 3; i++) nb += R[i][k] * n[i];
    s += ax[k] * ax[k] * nb * nb;
  }
  return std::sqrt(s);
}

std::vector<std::string> box(double L, const std::string &shape)
{
  return {"units si", "atom_style polyhedron", "atom_modify map array", "boundary f f f",
          "comm_modify vel yes", "region box block " + num(-L) + " " + num(L) + " " + num(-L) +
              " " + num(L) + " " + num(-L) + " " + num(L),
          "create_box 1 box", "polyhedron_shape e ellipsoid " + shape};
}

double fvec(Lmp &l, const std::string &id, int k)
{
  return l.lmp->modify->fix[l.lmp->modify->find_fix(id)]->compute_vector(k);
}

}    // namespace

// 1. Central impact at 1 m/s, no gravity: the contact point is the centre's
// foot, m_c = m, the linear spring-dashpot with zeta(e, 1) rebounds with e
// (to the time step's resolution, t_c / dt = 200).
TEST(WallEllipsoid, CentralImpactRestitution)
{
  const double ax[3] = {0.01, 0.006, 0.004};
  const std::string stl = tmpdir() + "/ell_floor.stl";
  write_ascii(stl, flat(-0.05, 0.05, -0.05, 0.05, 0.0, 3, 3));
  const double m = 2000.0 * 4.0 / 3.0 * M_PI * ax[0] * ax[1] * ax[2], kn = 1e4;
  const double tc = M_PI * std::sqrt(m / kn), dt = tc / 200.0;
  const Q orient[] = {{1, 0, 0, 0},                                        // c normal
                      axis_angle(0, 1, 0, 90),                             // a normal
                      qmul(axis_angle(0, 0, 1, 30), axis_angle(1, 0, 0, 90)),    // b normal, turned
                      qmul(axis_angle(0, 0, 1, -71), axis_angle(0, 1, 0, 90))};
  struct Case {
    std::string coeff, fixkw;
    double e;
  };
  const Case cases[] = {{"1e4 0.5 0.4", "", 0.5}, {"1e4 0.9 0.4", "", 0.9},
                        {"1e4 0.9", " restitution 0.5", 0.5}};
  double worst = 0.0;
  for (const auto &c : cases)
    for (const Q &q : orient) {
      Lmp l;
      l.cmds(box(0.1, num(ax[0]) + " " + num(ax[1]) + " " + num(ax[2])));
      const double n[3] = {0, 0, 1};
      const double z0 = support(ax, q, n) + 2e-4;
      l.cmds({"create_atoms 1 single 0.003 -0.002 " + num(z0),
              "polyhedron_set atom 1 density 2000 " + quat_words(q), "velocity all set 0 0 -1",
              "pair_style ellipsoid", "pair_coeff * * " + c.coeff, "neighbor 0.001 bin",
              "fix nve all nve/polyhedron", "fix w all wall/mesh " + stl + c.fixkw,
              "timestep " + num(dt)});
      l.cmd("run 100");    // approach: 2e-4 m at 1 m/s = 0.3 t_c
      EXPECT_GT(fvec(l, "w", 6), 0.0);    // in contact
      l.cmd("run 400");
      EXPECT_EQ(fvec(l, "w", 6), 0.0);    // rebounded
      auto *a = l.lmp->atom;
      const double e = a->v[0][2];
      double w = 0.0;
      for (int k = 0; k < 3; k++) w = std::fmax(w, std::fabs(a->omega[0][k]));
      std::printf("[ ell wall ] e %.2f%s, orientation (%.3f %.3f %.3f %.3f): v_out/v_in = %.5f, "
                  "|omega| %.2g rad/s\n", c.e, c.fixkw.c_str(), q.w, q.x, q.y, q.z, e, w);
      EXPECT_NEAR(e, c.e, 0.02 * c.e);
      EXPECT_LT(w, 1e-6);
      EXPECT_LT(std::fabs(a->v[0][0]) + std::fabs(a->v[0][1]), 1e-9);
      worst = std::fmax(worst, std::fabs(e / c.e - 1.0));
    }
  std::printf("[ ell wall ] central impact: largest |e_measured / e - 1| = %.3g\n", worst);
}

// 1b. Elastic (e = 1), frictionless, off-centre impacts of tilted, spinning
// ellipsoids: a face contact's force is the exact gradient of 1/2 k_n
// delta^2 in translation and rotation, so translation + rotation + the
// wall's elastic energy stays constant (sampled every 10 steps over 1,000,
// t_c = 200 steps, within 2e-4) while the impact turns translation into spin.
TEST(WallEllipsoid, ElasticTiltedImpactKeepsEnergy)
{
  const double ax[3] = {0.01, 0.006, 0.004};
  const std::string stl = tmpdir() + "/ell_floor_el.stl";
  write_ascii(stl, flat(-0.05, 0.05, -0.05, 0.05, 0.0, 3, 3));
  const double m = 2000.0 * 4.0 / 3.0 * M_PI * ax[0] * ax[1] * ax[2], kn = 1e4;
  const double dt = M_PI * std::sqrt(m / kn) / 200.0;
  double worst = 0.0;
  for (const Q q : {axis_angle(1, 2, 0.3, 37), axis_angle(-0.4, 1, 1, 61), axis_angle(0, 1, 0, 20)}) {
    Lmp l;
    l.cmds(box(0.1, num(ax[0]) + " " + num(ax[1]) + " " + num(ax[2])));
    const double n[3] = {0, 0, 1};
    l.cmds({"create_atoms 1 single 0.003 -0.002 " + num(support(ax, q, n) + 2e-4),
            "polyhedron_set atom 1 density 2000 " + quat_words(q) + " omega 3 -5 2",
            "velocity all set 0.1 0 -1", "pair_style ellipsoid", "pair_coeff * * 1e4 1.0",
            "neighbor 0.001 bin", "fix nve all nve/polyhedron", "fix w all wall/mesh " + stl,
            "compute er all erotate/polyhedron", "thermo_style custom step c_er",
            "timestep " + num(dt), "run 0"});
    // translation (thermo ke removes the 3 dof of a single atom), rotation,
    // the wall's elastic energy
    auto energy = [&]() {
      l.cmd("run 0");    // c_er and the wall energy of this state
      const double *v = l.lmp->atom->v[0];
      return 0.5 * l.lmp->atom->rmass[0] * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) +
          l.thermo("c_er") + l.lmp->modify->fix[l.lmp->modify->find_fix("w")]->compute_scalar();
    };
    const double e0 = energy(), w0 = l.lmp->atom->omega[0][0];
    double dev = 0.0, touched = 0.0;
    for (int k = 0; k < 100; k++) {
      l.cmd("run 10");
      touched = std::fmax(touched, fvec(l, "w", 6));
      dev = std::fmax(dev, std::fabs(energy() / e0 - 1.0));
    }
    std::printf("[ ell wall ] elastic tilted impact (%.3f %.3f %.3f %.3f): max |E / E_0 - 1| = "
                "%.3g, v_z %.4f, omega_x %.3f -> %.3f rad/s\n", q.w, q.x, q.y, q.z, dev,
                l.lmp->atom->v[0][2], w0, l.lmp->atom->omega[0][0]);
    EXPECT_GT(touched, 0.0);
    EXPECT_LT(dev, 2e-4);
    EXPECT_GT(std::fabs(l.lmp->atom->omega[0][0] - w0), 1.0);    // the impact did torque it
    worst = std::fmax(worst, dev);
  }
  std::printf("[ ell wall ] elastic tilted impacts: largest energy deviation %.3g\n", worst);
}

// 2. One flat square wall, four triangulations: the same contacts.
TEST(WallEllipsoid, TriangulationIndependence)
{
  const double L = 0.05;
  const double ax[3] = {0.005, 0.003, 0.002};
  // feet: the centre (vertex for n >= 2), the diagonal (an internal edge of
  // all), x = 0 and x = L/2 (grid lines), a vertex of the finest mesh, any
  const double feet[][2] = {{0.0, 0.0},       {0.0123, 0.0123}, {0.0, 0.0311},
                            {0.025, -0.0177}, {0.01875, -0.03125}, {-0.0213, 0.0377},
                            {-0.031, -0.012}, {0.037, 0.027}};
  const int nfeet = sizeof(feet) / sizeof(feet[0]);
  std::mt19937_64 rng(11);
  std::normal_distribution<double> g;
  std::vector<Q> qs;
  for (int k = 0; k < nfeet; k++) {
    if (k % 3 == 0) qs.push_back(axis_angle(0, 0, 1, 17.0 * k));    // an axis normal
    else {
      Q q = {g(rng), g(rng), g(rng), g(rng)};
      const double s = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
      qs.push_back({q.w / s, q.x / s, q.y / s, q.z / s});
    }
  }
  double worst0 = 0.0, worst1 = 0.0;
  // the square as written (z = 0: every triangle stores the same plane), and
  // tilted (its planes differ in the last bits)
  for (const Q tilt : {Q{1, 0, 0, 0}, axis_angle(1, 2, 0.5, 23)}) {
  double Rw[3][3];
  quat_matrix(tilt, Rw);
  auto rot = [&](double x, double y, double z, double *o) {
    for (int i = 0; i < 3; i++) o[i] = Rw[i][0] * x + Rw[i][1] * y + Rw[i][2] * z;
  };
  std::vector<std::vector<double>> ref0, ref1;
  for (int n : {1, 2, 4, 16}) {
    const std::string stl = tmpdir() + "/ell_square" + std::to_string(n) + ".stl";
    Tris t = flat(-L, L, -L, L, 0.0, n, n);
    for (size_t k = 0; k < t.size(); k += 3) rot(t[k], t[k + 1], t[k + 2], &t[k]);
    write_ascii(stl, t);
    Lmp l;
    l.cmds(box(0.1, num(ax[0]) + " " + num(ax[1]) + " " + num(ax[2])));
    double up[3];
    rot(0.0, 0.0, 1.0, up);
    for (int k = 0; k < nfeet; k++) {
      const Q q = qmul(tilt, qs[k]);
      const double z = (0.97 - 0.01 * k) * support(ax, q, up);    // overlap 3-10 %
      double c[3];
      rot(feet[k][0], feet[k][1], z, c);
      l.cmd("create_atoms 1 single " + num(c[0]) + " " + num(c[1]) + " " + num(c[2]));
      l.cmd("polyhedron_set atom " + std::to_string(k + 1) + " density 2000 " + quat_words(q) +
            " omega " + num(30.0 - 7 * k) + " " + num(5.0 * k - 11) + " " + num(13.0 + k));
    }
    l.cmds({"velocity all set 0.3 -0.2 -0.1", "pair_style ellipsoid", "pair_coeff * * 1e4 0.5 0.4",
            "neighbor 0.001 bin", "fix nve all nve/polyhedron",
            "fix w all wall/mesh " + stl + " merge no", "timestep 1e-6", "run 0"});
    EXPECT_EQ(fvec(l, "w", 6), nfeet);
    EXPECT_EQ(l.lmp->modify->fix[l.lmp->modify->find_fix("w")]->size_vector, 10);    // 8 + servo 2
    auto snap = [&]() {
      std::vector<std::vector<double>> s(nfeet);
      auto *a = l.lmp->atom;
      for (int i = 0; i < a->nlocal; i++) {
        auto &r = s[a->tag[i] - 1];
        for (int k = 0; k < 3; k++) r.push_back(a->f[i][k]);
        for (int k = 0; k < 3; k++) r.push_back(a->torque[i][k]);
      }
      return s;
    };
    auto compare = [&](const std::vector<std::vector<double>> &s,
                       const std::vector<std::vector<double>> &ref) {
      double worst = 0.0;
      for (int k = 0; k < nfeet; k++) {
        double fmax = 0.0, d = 0.0;
        for (int c = 0; c < 6; c++) {
          fmax = std::fmax(fmax, std::fabs(ref[k][c]));
          d = std::fmax(d, std::fabs(s[k][c] - ref[k][c]));
        }
        EXPECT_GT(fmax, 0.0);
        EXPECT_LE(d, 1e-12 * fmax) << "mesh " << n << " particle " << k;
        worst = std::fmax(worst, d / fmax);
      }
      return worst;
    };
    const auto s0 = snap();
    l.cmd("run 100");    // the friction springs load, the contacts move over edges
    const auto s1 = snap();
    EXPECT_EQ(fvec(l, "w", 6), nfeet);
    if (n == 1) {
      ref0 = s0;
      ref1 = s1;
      continue;
    }
    const double w0 = compare(s0, ref0), w1 = compare(s1, ref1);
    std::printf("[ ell wall ] %s square, %d triangles vs 2: largest |d(f, torque)| / "
                "|f, torque| %.3g at setup, %.3g after 100 steps\n",
                tilt.w == 1.0 ? "flat" : "tilted", 2 * n * n, w0, w1);
    worst0 = std::fmax(worst0, w0);
    worst1 = std::fmax(worst1, w1);
  }
  }
  // (flat: bit-identical; a face contact is computed from the plane and the
  // ellipsoid only, and the coplanar triangles store the same plane)
  std::printf("[ ell wall ] triangulations: largest relative difference %.3g (setup), %.3g "
              "(100 steps)\n", worst0, worst1);
}

// 3. An ellipsoid (a = 1 cm along the slope, c = 5 mm normal to it) on a
// plane tilted by theta about y (mesh of 8 x 3 cells, merge no: it slides
// over internal edges), mu = 0.5, g = 9.81. Each starts in its steady pose:
// pitched so that the deepest point lies on the line of the total contact
// force through the centre (vertical when it sticks; atan(mu) from the
// normal when it slides), at the static overlap.
TEST(WallEllipsoid, FrictionOnIncline)
{
  const double a = 0.01, b = 0.006, c = 0.005, mu = 0.5, grav = 9.81, kn = 1e4;
  const double m = 2000.0 * 4.0 / 3.0 * M_PI * a * b * c;
  for (double theta : {15.0, 24.0, 30.0, 40.0}) {
    const double th = theta * M_PI / 180.0;
    const bool slides = std::tan(th) > mu;
    // pitch phi: tan psi = (a^2 - c^2) sin phi cos phi / (a^2 sin^2 phi + c^2 cos^2 phi)
    const double tpsi = slides ? mu : std::tan(th);
    double lo = 0.0, hi = std::atan(c / a);    // the ratio grows on [0, atan(c/a)]
    for (int it = 0; it < 100; it++) {
      const double p = 0.5 * (lo + hi), s = std::sin(p), co = std::cos(p);
      ((a * a - c * c) * s * co / (a * a * s * s + c * c * co * co) < tpsi ? lo : hi) = p;
    }
    const double phi = 0.5 * (lo + hi);
    const double sig = std::sqrt(a * a * std::sin(phi) * std::sin(phi) +
                                 c * c * std::cos(phi) * std::cos(phi));
    const double delta0 = m * grav * std::cos(th) / kn;
    // incline frame (x down the slope, z its normal) -> lab: R_y(theta)
    const std::string stl = tmpdir() + "/ell_incline.stl";
    write_ascii(stl, inclined(flat(-0.06, 0.1, -0.03, 0.03, 0.0, 8, 3), th));
    const double p[3] = {-0.04, 0.0, sig - delta0};
    double x0[3];
    incline_to_lab(th, p, x0);
    Lmp l;
    l.cmds(box(0.2, num(a) + " " + num(b) + " " + num(c)));
    l.cmds({"create_atoms 1 single " + num(x0[0]) + " " + num(x0[1]) + " " + num(x0[2]),
            "polyhedron_set atom 1 density 2000 quat 0 1 0 " + num(theta + phi * 180.0 / M_PI),
            "pair_style ellipsoid", "pair_coeff * * " + num(kn) + " 0.5 " + num(mu),
            "neighbor 0.001 bin", "fix nve all nve/polyhedron",
            "fix g all gravity 9.81 vector 0 0 -1", "fix w all wall/mesh " + stl + " merge no",
            "timestep 2e-5"});
    // velocity down the slope, sampled every 1 ms from 20 ms to 150 ms
    auto along = [&]() {
      auto *at = l.lmp->atom;
      return std::cos(th) * at->v[0][0] - std::sin(th) * at->v[0][2];
    };
    auto pos = [&]() {
      auto *at = l.lmp->atom;
      return std::cos(th) * at->x[0][0] - std::sin(th) * at->x[0][2];
    };
    l.cmd("run 1000");
    const double s0 = pos();
    double st = 0, sv = 0, stt = 0, stv = 0;
    int ns = 0, lost = 0;
    for (int k = 0; k <= 130; k++) {
      const double tk = 0.02 + 0.001 * k, vk = along();
      st += tk, sv += vk, stt += tk * tk, stv += tk * vk, ns++;
      lost += fvec(l, "w", 6) != 1.0;
      if (k < 130) l.cmd("run 50");
    }
    const double acc = (ns * stv - st * sv) / (ns * stt - st * st);
    const double expect = slides ? grav * (std::sin(th) - mu * std::cos(th)) : 0.0;
    std::printf("[ ell wall ] incline %.0f deg (tan %.3f, mu %.2f): pitch %.2f deg, acceleration "
                "%.5g m/s^2 (expected %.5g), v %.3g m/s, moved %.3g m after 20 ms\n", theta,
                std::tan(th), mu, phi * 180.0 / M_PI, acc, expect, along(), pos() - s0);
    EXPECT_EQ(lost, 0);    // one contact throughout
    if (slides) {
      EXPECT_NEAR(acc, expect, 0.02 * expect);
    } else {
      EXPECT_LT(std::fabs(along()), 1e-4);
      EXPECT_LT(std::fabs(pos() - s0), 1e-5);
    }
  }
}

// 4a. fix insert/polyhedron puts ellipsoids apart from the mesh: a floor
// crosses the region (one-sided: an ellipsoid below it would be behind it,
// and none is placed there); random positions do touch it (the check can
// fail).
TEST(WallEllipsoid, InsertionApartFromTheMesh)
{
  const std::string stl = tmpdir() + "/ell_insert_floor.stl";
  write_ascii(stl, flat(-0.05, 0.05, -0.05, 0.05, 0.0, 4, 4));
  for (const std::string sides : {"both", "front"}) {
    Lmp l;
    l.cmds(box(0.05, "0.004 0.0025 0.0015"));
    l.cmds({"region feed block -0.04 0.04 -0.04 0.04 -0.01 0.01",
            "fix ins all insert/polyhedron 200 7 region feed mode pack density 2000 shape e 1",
            "pair_style ellipsoid", "pair_coeff * * 1e4 0.5 0.4", "neighbor 0.001 bin",
            "fix nve all nve/polyhedron", "fix w all wall/mesh " + stl + " sides " + sides,
            "timestep 1e-6", "run 0"});
    // one-sided, the half below the floor is refused (issue 32 item 3): the
    // thin layer above holds fewer
    const int n = (int) l.lmp->atom->natoms;
    if (sides == "both") {
      EXPECT_EQ(n, 200);
    } else {
      EXPECT_GT(n, 100);
      for (int i = 0; i < l.lmp->atom->nlocal; i++) EXPECT_GT(l.lmp->atom->x[i][2], 0.0);
    }
    EXPECT_EQ(fvec(l, "w", 6), 0.0) << sides;
    l.cmds({"unfix ins", "create_atoms 1 random 100 5 feed",
            "polyhedron_set atom " + std::to_string(n + 1) + "*" + std::to_string(n + 100) +
                " shape e density 2000 quat/random 3",
            "run 0"});
    EXPECT_GT(fvec(l, "w", 6), 10.0) << sides;
  }
}

// 4b. bad input
TEST(WallEllipsoid, Errors)
{
  const std::string stl = tmpdir() + "/ell_err_floor.stl";
  write_ascii(stl, flat(-0.05, 0.05, -0.05, 0.05, 0.0, 2, 2));
  {
    // ellipsoids without pair_style ellipsoid: no k_n (pair_style polyhedron
    // refuses them itself, before the fix's init)
    Lmp l;
    l.cmds(box(0.05, "0.004 0.0025 0.0015"));
    l.cmds({"create_atoms 1 single 0 0 0.01", "polyhedron_set atom 1 density 2000",
            "fix w all wall/mesh " + stl});
    const std::string err = l.error_of("run 0");
    EXPECT_NE(err.find("1 atoms of its group have an ellipsoid shape"), std::string::npos) << err;
  }
  {
    // polyhedra and ellipsoids in one group (no pair style: each pair style
    // refuses the other kind itself)
    Lmp l;
    l.cmds(box(0.05, "0.004 0.0025 0.0015"));
    l.cmds({"polyhedron_shape d " + polydem_test::potentials() + "/dodecahedron.shape",
            "create_atoms 1 single 0 0 0.01", "create_atoms 1 single 0.02 0 0.01",
            "polyhedron_set atom 1 density 2000", "polyhedron_set atom 2 shape d scale 0.003",
            "fix w all wall/mesh " + stl});
    const std::string err = l.error_of("run 0");
    EXPECT_NE(err.find("1 polyhedra and 1 ellipsoids"), std::string::npos) << err;
  }
}

// Spheres under pair_style polyhedron (issue 29): the wall takes them by the
// volume law (the cap the patch's plane cuts off, sphere_cap_contacts), with
// the polyhedra's material, in one group with polyhedra. A sphere (r = 1 cm,
// E = 1 MPa) hits the floor centrally at 1 m/s: it rebounds with e (within
// 2 %, as a sphere on a polyhedron does under the pair style); elastic (e = 1)
// oblique impacts of a spinning sphere keep translation + rotation + W(V)
// within 1e-4 during the contact and 1e-6 after it.
TEST(WallEllipsoid, SphereByVolumeUnderPairPolyhedron)
{
  const std::string stl = tmpdir() + "/sphere_vol_floor.stl";
  write_ascii(stl, flat(-0.05, 0.05, -0.05, 0.05, 0.0, 3, 3));
  auto run_case = [&](double e, bool oblique, double *dev_contact, double *dev_after) {
    Lmp l;
    l.cmds(box(0.1, "0.01 0.01 0.01"));
    l.cmds({"polyhedron_shape c " + polydem_test::potentials() + "/cube.shape",
            "create_atoms 1 single 0.003 -0.002 0.0102",
            "create_atoms 1 single 0.05 0.05 0.05",    // a polyhedron in the wall's group, apart
            "polyhedron_set atom 1 density 2000", "polyhedron_set atom 2 shape c scale 0.005 density 2000",
            "velocity all set 0 0 0", std::string("set atom 1 vx ") + (oblique ? "0.3" : "0") + " vz -1",
            "pair_style polyhedron", "pair_coeff * * 1e6 0.3 " + num(e) + " 0.0",
            "neighbor 0.001 bin", "fix nve all nve/polyhedron", "fix w all wall/mesh " + stl,
            "compute er all erotate/polyhedron", "thermo_style custom step c_er",
            "timestep 2e-6"});
    if (oblique) l.cmd("polyhedron_set atom 1 omega 30 -50 20");
    l.cmd("run 0");
    auto energy = [&]() {
      l.cmd("run 0");
      const double *v = l.lmp->atom->v[l.lmp->atom->map(1)];
      return 0.5 * l.lmp->atom->rmass[l.lmp->atom->map(1)] *
          (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) +
          l.thermo("c_er") + l.lmp->modify->fix[l.lmp->modify->find_fix("w")]->compute_scalar();
    };
    const double e0 = energy();
    double touched = 0.0, steps_in = 0.0;
    *dev_contact = *dev_after = 0.0;
    for (int k = 0; k < 300; k++) {
      l.cmd("run 20");
      const double c = fvec(l, "w", 6);
      touched = std::fmax(touched, c);
      if (c > 0) steps_in += 20;
      const double d = std::fabs(energy() / e0 - 1.0);
      if (c > 0)
        *dev_contact = std::fmax(*dev_contact, d);
      else if (touched > 0)
        *dev_after = d;
    }
    EXPECT_GT(touched, 0.0);
    EXPECT_EQ(fvec(l, "w", 6), 0.0);    // rebounded
    std::printf("[ sphere wall ] e %.2f%s: contact %.0f steps, v_z out %.5f\n", e,
                oblique ? " oblique, spinning" : "", steps_in,
                l.lmp->atom->v[l.lmp->atom->map(1)][2]);
    return l.lmp->atom->v[l.lmp->atom->map(1)][2];
  };
  double dc, da;
  for (double e : {0.5, 0.9}) EXPECT_NEAR(run_case(e, false, &dc, &da), e, 0.02 * e);
  run_case(1.0, true, &dc, &da);
  std::printf("[ sphere wall ] elastic oblique impact: max |E / E_0 - 1| %.3g in contact, %.3g after\n",
              dc, da);
  EXPECT_LT(dc, 1e-4);
  EXPECT_LT(da, 1e-6);
}

// Under pair_style polyhedron (issue 29: every shape meets every shape) an
// ellipsoid of unequal semi-axes takes the wall with pair_style ellipsoid's
// linear law and the like pair's 'ellipsoid k_n', in the same group as
// polyhedra and spheres: a tilted, spinning ellipsoid dropped obliquely on a
// floor with friction follows, bit for bit, its path under pair_style
// ellipsoid with the same k_n, e and mu (a cube and a sphere fall beside it
// under pair_style polyhedron, apart from it). A type of such ellipsoids
// without k_n is an error naming it.
TEST(WallEllipsoid, UnequalAxesUnderPairPolyhedronAsUnderPairEllipsoid)
{
  const std::string stl = tmpdir() + "/ell_mixed_floor.stl";
  write_ascii(stl, flat(-0.05, 0.05, -0.05, 0.05, 0.0, 3, 3));
  auto run = [&](bool poly) {
    Lmp l;
    l.cmds(box(0.1, "0.01 0.006 0.004"));
    l.cmds({"create_atoms 1 single 0.003 -0.002 0.012",
            "polyhedron_set atom 1 density 2000 quat 1 2 0.5 35 omega 20 -40 10"});
    if (poly)
      l.cmds({"polyhedron_shape c " + polydem_test::potentials() + "/cube.shape",
              "polyhedron_shape ball ellipsoid 0.005 0.005 0.005",
              "create_atoms 1 single -0.035 0.035 0.012", "create_atoms 1 single 0.035 0.035 0.012",
              "polyhedron_set atom 2 shape c scale 0.008 density 2000",
              "polyhedron_set atom 3 shape ball density 2000"});
    l.cmds({"velocity all set 0.2 0 -0.5", "neighbor 0.001 bin",
            poly ? "pair_style polyhedron" : "pair_style ellipsoid",
            poly ? "pair_coeff * * 1e7 0.3 0.6 0.4 ellipsoid 1e4" : "pair_coeff * * 1e4 0.6 0.4",
            "fix nve all nve/polyhedron", "fix w all wall/mesh " + stl, "timestep 2e-6"});
    double touched = 0.0;
    for (int k = 0; k < 200; k++) {
      l.cmd("run 100");
      touched = std::fmax(touched, fvec(l, "w", 6));
    }
    EXPECT_GT(touched, 0.0);
    return l.local_state();
  };
  const auto ell = run(false), pol = run(true);
  const auto &a = ell.at(1), &b = pol.at(1);
  std::printf("[ ell wall ] under pair ellipsoid: z %.6g vx %.6g wy %.6g; under pair polyhedron: "
              "z %.6g vx %.6g wy %.6g; v_z after the bounce: cube %.4g, sphere %.4g\n",
              a.x[2], a.v[0], a.w[1], b.x[2], b.v[0], b.w[1], pol.at(2).v[2], pol.at(3).v[2]);
  for (int k = 0; k < 3; k++) {
    EXPECT_EQ(a.x[k], b.x[k]) << k;
    EXPECT_EQ(a.v[k], b.v[k]) << k;
    EXPECT_EQ(a.L[k], b.L[k]) << k;
  }
  // the ellipsoid, the cube and the sphere bounced off the floor
  for (long id : {1, 2, 3}) EXPECT_GT(pol.at(id).v[2], 0.0) << id;

  Lmp l;
  l.cmds(box(0.1, "0.01 0.006 0.004"));
  l.cmds({"create_atoms 1 single 0.003 -0.002 0.012", "polyhedron_set atom 1 density 2000",
          "pair_style polyhedron", "pair_coeff * * 1e7 0.3 0.6 0.4", "fix w all wall/mesh " + stl});
  l.expect_error("run 0", "particle type 1 has ellipsoids of unequal semi-axes, which "
                                     "meet the wall by the linear law of pair_style ellipsoid: "
                                     "add 'ellipsoid k_n' to pair_coeff 1 1");
}
