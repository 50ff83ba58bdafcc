// fix wall/mesh through LAMMPS (issue 5): mesh independence against the
// analytic flat wall (seed §3.2, Table 2 cuboid), bad input, restart.
#include "polydem_lmp.h"
#include "wall_meshes.h"
#include "wall_scene.h"

#include "poly_shape_library.h"
#include "fix.h"
#include "polydem_shape_template.h"
#include "modify.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <vector>

using polydem_test::Lmp;
using polydem_test::num;
using polydem_test::potentials;
using namespace wall_test;

namespace {

constexpr double PI = 3.14159265358979323846;

// Seed Table 2: cuboid L = 2.5 cm, rho 1500, E 1e6, nu 0.1, mu 0.8 (e = 1
// here: the tangential spring is then undamped and the analytic force exact)
constexpr double L = 0.025, RHO = 1500.0, E = 1.0e6, NU = 0.1, MU = 0.8;
constexpr double DELTA = 2.5e-5;    // penetration 1e-3 L
constexpr double CORE = 1.0e-4;     // default core fraction

// analytic W'(V) of the contact model's doc (Feng, Eqs. 12-13, C2 core)
double wprime(double K, double V, double V0)
{
  if (V < V0) return K / std::cbrt(V0 * V0) * V * (5.0 / 3.0 - 2.0 / 3.0 * V / V0);
  return K * std::cbrt(V);
}

struct Sweep {
  double max_fn_err = 0, max_ft_err = 0;    // relative to the full-contact values
  int nsamples = 0;
  double ffull = 0;                         // full-contact normal force
  std::vector<double> fx, fz;               // force on the mesh, every step
};

// Cuboid face down on the wall z = 0 (wall x in [0, 3L], y in [-L, L]),
// moved by fix move at speed U along x from x = -0.4 L to 3.4 L.
// fixargs: extra fix wall/mesh keywords ("merge no": the triangulation as
// written, which is what the mesh-independence test is about)
Sweep sweep(const Tris &tris, const std::string &name, double U, double dt, int steps,
            const std::string &fixargs = "merge no")
{
  const std::string stl = tmpdir() + "/" + name + ".stl";
  write_ascii(stl, tris);
  const std::string out = tmpdir() + "/" + name + ".force";
  const double x0 = -0.4 * L;
  Lmp l;
  l.cmds({"units si", "atom_style polyhedron", "atom_modify map array", "boundary f f f",
          "comm_modify vel yes", "region box block -0.1 0.2 -0.1 0.1 -0.1 0.1",
          "create_box 1 box", "polyhedron_shape c " + potentials() + "/cuboid_2p5cm.shape",
          "create_atoms 1 single " + num(x0) + " 0.001 " + num(L / 2 - DELTA),
          "polyhedron_set group all scale 1 density " + num(RHO), "pair_style polyhedron",
          "pair_coeff * * " + num(E) + " " + num(NU) + " 1.0 " + num(MU),
          "fix w all wall/mesh " + stl + " " + fixargs, "fix m all move linear " + num(U) + " 0 0",
          "fix o all ave/time 1 1 1 f_w[1] f_w[3] file " + out + " format \" %.16g\"", "timestep " + num(dt),
          "thermo 1000", "run " + std::to_string(steps)});
  // analytic: V = A delta, A = L * (overlap of [x-L/2, x+L/2] with [0, 3L])
  const double Vp = L * L * L, m = RHO * Vp;
  const double R = std::cbrt(3.0 * Vp / (4.0 * PI));
  const double K = 2.0 * E / R, Kt = 2.0 * E / (2.0 * (1.0 + NU) * R);
  const double Afull = L * L, Ffull = wprime(K, Afull * DELTA, CORE * Vp) * Afull;
  (void) m;
  std::ifstream in(out);
  std::string line;
  Sweep s;
  s.ffull = Ffull;
  // analytic Cundall-Strack spring (flat wall, constant speed) in the
  // contact model's incremental form: a growing area keeps the stored force
  double shear = 0.0, Aold = 0.0;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ls(line);
    long step;
    double fx, fz;
    ls >> step >> fx >> fz;    // force on the mesh
    s.fx.push_back(fx);
    s.fz.push_back(fz);
    const double x = x0 + U * dt * step;
    const double ov = std::fmax(0.0, std::fmin(x + L / 2, 3 * L) - std::fmax(x - L / 2, 0.0));
    const double A = L * ov;
    double fn = 0.0, ft = 0.0;
    if (A > 0.0) {
      fn = wprime(K, A * DELTA, CORE * Vp) * A;
      if (A > Aold && Aold > 0.0) shear *= Aold / A;
      if (step > 0) shear += U * dt;
      ft = Kt * A * shear;
      if (ft > MU * fn) {
        ft = MU * fn;
        shear = ft / (Kt * A);
      }
    } else
      shear = 0.0;
    Aold = A;
    // force on the particle: +z (fn), -x (friction); on the mesh the opposite
    s.max_fn_err = std::fmax(s.max_fn_err, std::fabs(-fz - fn) / Ffull);
    s.max_ft_err = std::fmax(s.max_ft_err, std::fabs(fx - ft) / (MU * Ffull));
    s.nsamples++;
  }
  return s;
}

}    // namespace

// Acceptance 1 (short): six triangulations with lambda = L/L_m from 0.5 to 8,
// regular, alternating, jittered (irregular) and a fan of slivers; every
// step compared with the analytic flat wall (also while entering and leaving
// the mesh and crossing every triangle edge): 1% of the full-contact force.
TEST(WallMesh, MeshIndependenceFlatWall)
{
  struct Case {
    const char *name;
    Tris t;
  };
  const double W = 3 * L;
  std::vector<Case> cases = {
      {"lam0.5", flat(0, W, -L, L, 0, 2, 1)},    // L_m = 1.5 L, 2 L
      {"lam1", flat(0, W, -L, L, 0, 3, 2, true)},
      {"lam2", flat(0, W, -L, L, 0, 6, 4)},
      {"lam4_irregular", flat(0, W, -L, L, 0, 12, 8, true, 0.35, 11)},
      {"lam8", flat(0, W, -L, L, 0, 24, 16, true)},
      {"fan", fan(0, W, -L, L, 0, 7, 0.37 * W, 0.21 * L)},
  };
  for (auto &c : cases) {
    const Sweep s = sweep(c.t, c.name, 5.0, 1.0e-5, 1900);
    std::printf("[ wall     ] %-16s %5zu triangles: max |Fn - analytic| = %.3g, max |Ft - "
                "analytic| = %.3g (of full contact), %d steps\n",
                c.name, c.t.size() / 9, s.max_fn_err, s.max_ft_err, s.nsamples);
    EXPECT_EQ(s.nsamples, 1901);
    EXPECT_LT(s.max_fn_err, 0.01) << c.name;
    EXPECT_LT(s.max_ft_err, 0.01) << c.name;
  }
}

// Coplanar merging at load (default 'merge 1e-9'): the irregular and the fan
// triangulations become a few large triangles, and the force on the sweeping
// cuboid is the same as with the file's triangulation at every step (to
// round-off: 1e-12 of the full-contact force).
TEST(WallMesh, MergedMeshGivesTheSameForces)
{
  const double W = 3 * L;
  for (auto &c : std::vector<std::pair<std::string, Tris>>{
           {"merge_irregular", flat(0, W, -L, L, 0, 12, 8, true, 0.35, 11)},
           {"merge_fan", fan(0, W, -L, L, 0, 7, 0.37 * W, 0.21 * L)}}) {
    const Sweep a = sweep(c.second, c.first, 5.0, 1.0e-5, 1900, "merge no");
    const Sweep b = sweep(c.second, c.first, 5.0, 1.0e-5, 1900, "");
    ASSERT_EQ(a.fx.size(), b.fx.size());
    double dmax = 0.0;
    for (size_t k = 0; k < a.fx.size(); k++)
      dmax = std::fmax(dmax, std::fmax(std::fabs(a.fx[k] - b.fx[k]), std::fabs(a.fz[k] - b.fz[k])));
    std::printf("[ wall     ] %-16s %zu triangles: merged vs as read, max |dF| = %.3g of full "
                "contact\n", c.first.c_str(), c.second.size() / 9, dmax / a.ffull);
    EXPECT_LT(dmax, 1e-12 * a.ffull) << c.first;
    EXPECT_LT(b.max_fn_err, 0.01);
  }
}

// Near lists (keyword cache, default on): particles tumbling on a curved,
// finely triangulated floor (3,200 facets, none coplanar) give the same
// forces, torques and trajectories as the grid query of every step
// (cache 0), also when lists overflow (cache 3: those particles query the
// grid) and when they are rebuilt often (small skin); and the lists are
// reused (far fewer builds than particle-steps). The same with every second
// grain a composite of two dodecahedra, whose parts keep a list each, and
// with every second grain a sphere (an ellipsoid's list: its bounding
// sphere's triangles).
TEST(WallMesh, NearListsGiveTheSameForces)
{
  for (const std::string mix : {"", "composites", "spheres"}) {
    const bool composites = mix == "composites";
    const double B = 0.06, Rc = 0.06, z0 = 0.002;
    const std::string stl = tmpdir() + "/near_bowl.stl";
    write_binary(stl, bowl(0, B, 0, B, z0, Rc, 40));
    const std::string data = tmpdir() + "/near_bowl.data";
    {
      std::mt19937_64 rng(8);
      std::uniform_real_distribution<double> g(-1.0, 1.0);
      std::ofstream o(data);
      o.precision(17);
      o << "near lists\n\n18 atoms\n1 atom types\n" << -0.5 * B << " " << 1.5 * B
        << " xlo xhi\n" << -0.5 * B << " " << 1.5 * B << " ylo yhi\n" << -0.5 * B << " " << B
        << " zlo zhi\n\nAtoms # polyhedron\n\n";
      int id = 0;
      for (int k = 0; k < 2; k++)
        for (int j = 0; j < 3; j++)
          for (int i = 0; i < 3; i++) {
            const double x = (i + 0.5) * B / 3, y = (j + 0.5) * B / 3;
            const double zb = z0 + ((x - B / 2) * (x - B / 2) + (y - B / 2) * (y - B / 2)) / (2 * Rc);
            double q[4], qn = 0;
            for (double &c : q) c = g(rng), qn += c * c;
            o << ++id << " 1 1 0.004 1500 " << x << " " << y << " " << zb + 0.0058 + 0.0115 * k;
            for (double c : q) o << " " << c / std::sqrt(qn);
            o << "\n";
          }
      o << "\nVelocities\n\n";
      for (int i = 1; i <= 18; i++)
        o << i << " " << 0.3 * g(rng) << " " << 0.3 * g(rng) << " -0.3 " << 3e-7 * g(rng) << " "
          << 3e-7 * g(rng) << " " << 3e-7 * g(rng) << "\n";
    }
    struct Out {
      std::map<long, std::vector<double>> atoms;
      double contacts = 0, builds = 0, overflows = 0;
    };
    auto run = [&](const std::string &cache) {
      Lmp l;
      std::vector<std::string> setup = scene_setup(data);
      if (composites)
        setup.insert(setup.begin() + 7,
                     {"polyhedron_shape comp composite part d -1.45 0 0 part d 1.45 0.3 0 quat "
                      "0.9 0.3 0.2 0.1",
                      "variable odd atom id%2", "group odd variable odd",
                      "polyhedron_set group odd shape comp scale 0.0018"});
      if (mix == "spheres")
        setup.insert(setup.begin() + 7,
                     {"polyhedron_shape ball ellipsoid 0.5 0.5 0.5", "variable odd atom id%2",
                      "group odd variable odd", "polyhedron_set group odd shape ball scale 0.009"});
      l.cmds(setup);
      l.cmds({"fix w all wall/mesh " + stl + " friction 0.5 restitution 0.5 " + cache,
              "thermo_modify lost error"});
      auto *fix = l.lmp->modify->fix[l.lmp->modify->find_fix("w")];
      Out o;
      for (int k = 0; k < 6; k++) {    // 1,200 steps; every run starts with fresh lists
        l.cmd(k == 5 ? "run 700" : "run 100");
        o.contacts = std::fmax(o.contacts, fix->compute_vector(6));
      }
      int dim;
      o.builds = (double) *(LAMMPS_NS::bigint *) fix->extract("near_builds", dim);
      o.overflows = (double) *(LAMMPS_NS::bigint *) fix->extract("near_overflows", dim);
      auto *a = l.lmp->atom;
      for (int i = 0; i < a->nlocal; i++) {
        std::vector<double> r;
        for (double *arr : {a->f[i], a->torque[i], a->x[i], a->v[i]})
          for (int c = 0; c < 3; c++) r.push_back(arr[c]);
        o.atoms[(long) a->tag[i]] = r;
      }
      return o;
    };
    const Out ref = run("cache 0");
    EXPECT_EQ(ref.builds, 0.0);
    EXPECT_GE(ref.contacts, 5.0);    // most of the lower layer lies on the floor
    for (const std::string c : {"", "cache 3", "cache/skin 0.005", "cache 200 cache/skin 0.5"}) {
      const Out o = run(c);
      ASSERT_EQ(o.atoms.size(), ref.atoms.size());
      const auto [fmax, df, dx] = record_diff(ref.atoms, o.atoms);
      std::printf("[ wall     ] near lists '%s'%s: %.0f builds in 21,600 particle-steps, %.0f "
                  "overflows; max |d f,torque| %.3g of %.3g, max |d x,v| %.3g\n", c.c_str(),
                  mix.empty() ? "" : (" (" + mix + ")").c_str(), o.builds, o.overflows, df, fmax, dx);
      EXPECT_LE(df, 1e-12 * fmax) << c;
      EXPECT_LE(dx, 1e-12) << c;
      EXPECT_GT(o.builds, 18.0) << c;
      if (c == "cache 3") EXPECT_GT(o.overflows, 0.0);
      if (c == "") EXPECT_LT(o.builds, 0.2 * 21600) << "lists are not reused";
    }
  }
}

// pertriangle yes: the seed's Table 2 cuboid pressed face-down by delta onto a
namespace {

// the cuboid pressed DELTA into a flat mesh (stl), its edges cutting cells;
// the fix with per-triangle forces
std::vector<std::string> pertri_scene(const std::string &stl)
{
  return {"units si", "atom_style polyhedron", "atom_modify map array", "boundary f f f",
          "comm_modify vel yes", "region box block -0.1 0.2 -0.1 0.1 -0.1 0.1",
          "create_box 1 box", "polyhedron_shape c " + potentials() + "/cuboid_2p5cm.shape",
          "create_atoms 1 single " + num(1.5 * L + 0.0013) + " 0.0021 " + num(L / 2 - DELTA),
          "polyhedron_set group all scale 1 density " + num(RHO), "pair_style polyhedron",
          "pair_coeff * * " + num(E) + " " + num(NU) + " 1.0 " + num(MU),
          "fix w all wall/mesh " + stl + " merge no pertriangle yes"};
}

// its normal force: the flat-wall contact of the face, W'(L^2 DELTA) L^2
double pertri_fn()
{
  const double Vp = L * L * L;
  const double R = std::cbrt(3.0 * Vp / (4.0 * PI));
  return wprime(2.0 * E / R, L * L * DELTA, CORE * Vp) * L * L;
}

}    // namespace

// regular flat mesh (merge no, cells of L/4, offset so that the cuboid's
// edges cut cells): the triangles' forces add up to the force on the mesh (to
// round-off), every triangle under the face carries the uniform pressure
// F_n / L^2 of the flat-wall contact (1e-9), partly covered ones in proportion
// to the covered area, and triangles away from the face nothing, also after
// the cuboid has moved to a place that overlaps the first in part. Rows
// follow the file's order, also when the file lists the triangles shuffled
// (the wall stores them in spatial order).
TEST(WallMesh, PerTriangleForces)
{
  for (const bool shuffle : {false, true}) {
    Tris tris = flat(0, 3 * L, -L, L, 0, 12, 8);
    if (shuffle) {
      const int n = (int) tris.size() / 9;
      std::vector<int> perm(n);
      for (int t = 0; t < n; t++) perm[t] = t;
      std::mt19937 rng(3);
      std::shuffle(perm.begin(), perm.end(), rng);
      const Tris in = tris;
      for (int t = 0; t < n; t++)
        for (int k = 0; k < 9; k++) tris[9 * t + k] = in[9 * perm[t] + k];
    }
    const std::string stl = tmpdir() + "/pertri.stl";
    write_ascii(stl, tris);
    Lmp l;
    l.cmds(pertri_scene(stl));
    auto *fix = l.lmp->modify->fix[l.lmp->modify->find_fix("w")];
    const double Fn = pertri_fn();
    // xc: the face's centre; each position after a run 0 (the second one
    // overlaps the first in part: rows of the first must be cleared)
    auto check = [&](double xc) {
      l.cmd("run 0");
      ASSERT_EQ(fix->size_array_rows, (int) tris.size() / 9);
      const double x0 = xc - L / 2, x1 = x0 + L, y0 = 0.0021 - L / 2, y1 = y0 + L;
      double sum[3] = {0, 0, 0}, pmax_err = 0, share_err = 0, outside = 0;
      int nfull = 0, npart = 0;
      for (int t = 0; t < fix->size_array_rows; t++) {
        for (int c = 0; c < 3; c++) sum[c] += fix->compute_array(t, c);
        const double *q = &tris[9 * t];
        const double area = 0.5 * std::fabs((q[3] - q[0]) * (q[7] - q[1]) - (q[6] - q[0]) * (q[4] - q[1]));
        // covered area: the triangle clipped to the face's rectangle (Sutherland-Hodgman in 2D)
        std::vector<std::array<double, 2>> poly = {{q[0], q[1]}, {q[3], q[4]}, {q[6], q[7]}};
        auto clip = [&](int axis, double v, bool keep_above) {
          std::vector<std::array<double, 2>> out;
          for (size_t i = 0; i < poly.size(); i++) {
            const auto &a = poly[i], &b = poly[(i + 1) % poly.size()];
            const bool ina = keep_above ? a[axis] >= v : a[axis] <= v;
            const bool inb = keep_above ? b[axis] >= v : b[axis] <= v;
            if (ina) out.push_back(a);
            if (ina != inb) {
              const double u = (v - a[axis]) / (b[axis] - a[axis]);
              out.push_back({a[0] + u * (b[0] - a[0]), a[1] + u * (b[1] - a[1])});
            }
          }
          poly = out;
        };
        clip(0, x0, true), clip(0, x1, false), clip(1, y0, true), clip(1, y1, false);
        double cov = 0.0;
        for (size_t i = 0; i < poly.size(); i++) {
          const auto &a = poly[i], &b = poly[(i + 1) % poly.size()];
          cov += 0.5 * (a[0] * b[1] - b[0] * a[1]);
        }
        cov = std::fabs(cov);
        const double p = fix->compute_array(t, 3);
        if (cov > (1 - 1e-12) * area) {
          nfull++;
          pmax_err = std::fmax(pmax_err, std::fabs(p / (Fn / (L * L)) - 1));
        } else if (cov > 1e-9 * area) {
          npart++;
          share_err = std::fmax(share_err, std::fabs(p * area - Fn * cov / (L * L)) / (Fn * area / (L * L)));
        } else
          outside = std::fmax(outside, std::fabs(p));
      }
      std::printf("[ wall     ] pertriangle: %d triangles under the face, %d partly: pressure %.4g "
                  "(max rel. error %.2g, partly covered %.2g of a full share), sum %.6g %.6g %.6g vs "
                  "mesh force %.6g %.6g %.6g\n", nfull, npart, Fn / (L * L), pmax_err, share_err,
                  sum[0], sum[1], sum[2], fix->compute_vector(0), fix->compute_vector(1),
                  fix->compute_vector(2));
      EXPECT_GT(nfull, 10);
      EXPECT_GT(npart, 10);
      EXPECT_LT(pmax_err, 1e-9);
      EXPECT_LT(share_err, 1e-9);
      EXPECT_EQ(outside, 0.0);
      for (int c = 0; c < 3; c++)
        EXPECT_NEAR(sum[c], fix->compute_vector(c), 1e-12 * Fn) << c;
      EXPECT_NEAR(sum[2], -Fn, 1e-9 * Fn);
    };
    check(1.5 * L + 0.0013);
    l.cmd("displace_atoms all move " + num(-0.6 * L) + " 0 0 units box");
    check(0.9 * L + 0.0013);
  }
}

// more triangles under one particle than the per-triangle record holds
// (WALL_MAX_CAND = 1024; cells of L/32: 2048 under the face): a warning
// with the count, and the recorded triangles keep their share of the
// patch's force (the uniform pressure, not inflated), so the per-triangle
// forces add up to less than the force on the mesh.
TEST(WallMesh, PerTriangleRecordFull)
{
  const Tris tris = flat(0, 3 * L, -L, L, 0, 96, 64);
  const std::string stl = tmpdir() + "/pertri_fine.stl";
  write_binary(stl, tris);
  const std::string log = tmpdir() + "/pertri_fine.log";
  double pmax = 0.0, sumz = 0.0, fz = 0.0;
  int nrec = 0;
  {
    Lmp l({"-log", log});
    l.cmds(pertri_scene(stl));
    l.cmd("run 1");
    auto *fix = l.lmp->modify->fix[l.lmp->modify->find_fix("w")];
    for (int t = 0; t < fix->size_array_rows; t++) {
      pmax = std::fmax(pmax, fix->compute_array(t, 3));
      sumz += fix->compute_array(t, 2);
      nrec += fix->compute_array(t, 3) != 0.0;
    }
    fz = fix->compute_vector(2);
  }
  const double Fn = pertri_fn();
  const std::string text = polydem_test::read_text(log);
  std::printf("[ wall     ] per-triangle record full: %d triangles recorded, sum %.6g of the mesh "
              "force %.6g, largest pressure %.6g (uniform %.6g)\n", nrec, sumz, fz, pmax,
              Fn / (L * L));
  EXPECT_NE(text.find("triangle contacts left out of the per-triangle forces"),
            std::string::npos);
  EXPECT_LE(nrec, 1024);
  EXPECT_LT(pmax, (1 + 1e-9) * Fn / (L * L));
  EXPECT_GT(pmax, (1 - 1e-9) * Fn / (L * L));
  EXPECT_LT(std::fabs(sumz), 0.9 * std::fabs(fz));
  EXPECT_NEAR(fz, -Fn, 1e-9 * Fn);
}

// move wiggle: a cube resting (gravity, friction 0.8) on a floor that
// oscillates along x with amplitude A = 1 mm and period 0.2 s (peak
// acceleration A (2 pi/T)^2 = 1 m/s^2 < mu g): the cube sticks and follows
// x_w(t) = A sin(2 pi t / T). It first slips by about v_w(0)^2/(2 mu g) =
// 0.06 mm while it catches up with the floor's initial velocity, so over the
// second period x - <x> is compared with x_w: within 2 % of A (the
// tangential spring's compliance is far smaller).
TEST(WallMesh, WiggleCarriesAStickingCube)
{
  const std::string stl = tmpdir() + "/wiggle_floor.stl";
  write_ascii(stl, flat(-0.05, 0.05, -0.05, 0.05, 0.0, 4, 4, true));
  const double A = 1e-3, T = 0.2, dt = 2e-5;
  Lmp l;
  l.cmds({"units si", "atom_style polyhedron", "atom_modify map array", "boundary f f f",
          "comm_modify vel yes", "region box block -0.1 0.1 -0.1 0.1 -0.1 0.1",
          "create_box 1 box", "polyhedron_shape c " + potentials() + "/cuboid_2p5cm.shape",
          "create_atoms 1 single 0 0 " + num(L / 2 - 1e-9),
          "polyhedron_set group all scale 1 density " + num(RHO), "pair_style polyhedron",
          "pair_coeff * * " + num(E) + " " + num(NU) + " 0.5 " + num(MU),
          "fix w all wall/mesh " + stl + " move wiggle " + num(A) + " 0 0 " + num(T),
          "fix g all gravity 9.81 vector 0 0 -1", "fix nve all nve/polyhedron",
          "timestep " + num(dt), "thermo 0", "run 0"});
  const int per = (int) std::lround(T / dt);
  l.cmd("run " + std::to_string(per));
  std::vector<double> x, xw;
  for (int k = 1; k <= 20; k++) {
    l.cmd("run " + std::to_string(per / 20) + " pre no post no");
    const double t = (per + k * (per / 20)) * dt;
    x.push_back(l.lmp->atom->x[0][0]);
    xw.push_back(A * std::sin(2 * PI * t / T));
  }
  double mean = 0.0, worst = 0.0;
  for (double v : x) mean += v / x.size();
  for (size_t k = 0; k < x.size(); k++) worst = std::fmax(worst, std::fabs(x[k] - mean - xw[k]));
  std::printf("[ wall     ] wiggle: max |x - <x> - A sin(2 pi t/T)| = %.3g A over the second "
              "period (offset <x> - x0 = %.3g A)\n", worst / A, mean / A);
  EXPECT_LT(worst, 0.02 * A);
  EXPECT_NEAR(l.lmp->atom->x[0][2], L / 2, 1e-6);    // still resting on the floor
  // bad input
  Lmp b;
  b.cmds({"units si", "atom_style polyhedron", "region box block -1 1 -1 1 -1 1", "create_box 1 box"});
  b.expect_error("fix w all wall/mesh " + stl + " move wiggle 1 0 0 0",
                 "move wiggle period must be > 0");
}

namespace {

// Seed §3.1, Table 1: the 42-vertex cylinder (D 8 mm, L 5.3 mm, rho 1245,
// E 1.15e9, nu 0.35, mu 0, e 0.85, dt 5e-7) falls at V on a flat wall with
// its bottom face tilted by theta; corner C = (R, 0, -L/2) touches first.
struct Impact {
  double wy, vz;      // after the impact
  double wy_a, vz_a;  // Eqs. 27-28
};

Impact cylinder_impact(double theta_deg, double V = 0.5, const std::string &extra = "", double EPS = 0.85)
{
  const double D = 8e-3, LC = 5.3e-3, RHO_C = 1245.0;
  const std::string stl = tmpdir() + "/impact_wall.stl";
  write_ascii(stl, flat(-0.02, 0.02, -0.02, 0.02, 0.0, 4, 4, true));
  Lmp l;
  l.cmds({"units si", "atom_style polyhedron", "atom_modify map array", "boundary f f f",
          "comm_modify vel yes", "region box block -0.03 0.03 -0.03 0.03 -0.03 0.03",
          "create_box 1 box", "polyhedron_shape c " + potentials() + "/cylinder42.shape",
          "create_atoms 1 single 0 0 0.01", "polyhedron_set group all scale 1 density " +
          num(RHO_C), "pair_style polyhedron", "pair_coeff * * 1.15e9 0.35 " + num(EPS) + " 0.0",
          "fix w all wall/mesh " + stl + " " + extra, "fix nve all nve/polyhedron",
          "timestep 5e-7"});
  // orientation: the file's frame (axis z, C on +x), then tilted about y
  auto *avec = LAMMPS_NS::PolyShapeLibrary::of(l.lmp, "test");
  const auto &tp = avec->shape(0);
  const auto qi = tp.input_orientation();
  const double th = theta_deg * PI / 180.0;
  const double qt[4] = {std::cos(th / 2), 0.0, std::sin(th / 2), 0.0};
  const double qa[4] = {qi.w, qi.x, qi.y, qi.z};
  double q[4] = {qt[0] * qa[0] - qt[1] * qa[1] - qt[2] * qa[2] - qt[3] * qa[3],
                 qt[0] * qa[1] + qt[1] * qa[0] + qt[2] * qa[3] - qt[3] * qa[2],
                 qt[0] * qa[2] - qt[1] * qa[3] + qt[2] * qa[0] + qt[3] * qa[1],
                 qt[0] * qa[3] + qt[1] * qa[2] - qt[2] * qa[1] + qt[3] * qa[0]};
  // lowest vertex: C in the file frame, (R, 0, -L/2) -> tilted
  const double R = D / 2, x_c = R * std::cos(th) - LC / 2 * std::sin(th);
  const double z_c = -R * std::sin(th) - LC / 2 * std::cos(th);
  auto *a = l.lmp->atom;
  for (int k = 0; k < 4; k++) a->quat[0][k] = q[k];
  const double gap = 2e-6;
  a->x[0][0] = -x_c;    // C above the origin of the wall
  a->x[0][1] = 0.0;
  a->x[0][2] = -z_c + gap;
  a->v[0][2] = -V;
  // contact lasts well under 1 ms: run until the particle is 0.1 mm above
  // Eqs. 27-28 describe one impact: stop when the first contact ends (a
  // second one follows at small angles, when the far rim swings down)
  l.cmd("run 0");
  auto *fix = l.lmp->modify->fix[l.lmp->modify->find_fix("w")];
  bool touched = false;
  for (int chunk = 0; chunk < 4000; chunk++) {
    l.cmd("run 5 pre no post no");
    const bool c = fix->compute_vector(6) > 0.0;
    if (touched && !c) break;
    touched = touched || c;
  }
  EXPECT_TRUE(touched);
  // analytic: mass and I_yy of the faceted 20-gon prism (fan of the ring)
  const int n = 20;
  double A = 0.0, Ix = 0.0;
  for (int k = 0; k < n; k++) {
    const double p1[2] = {R * std::cos(2 * PI * k / n), R * std::sin(2 * PI * k / n)};
    const double p2[2] = {R * std::cos(2 * PI * (k + 1) / n), R * std::sin(2 * PI * (k + 1) / n)};
    const double ar = 0.5 * (p1[0] * p2[1] - p1[1] * p2[0]);
    A += ar;
    // second moment of the triangle (0, p1, p2) about the x axis: int y^2
    Ix += ar / 6.0 * (p1[1] * p1[1] + p2[1] * p2[1] + p1[1] * p2[1]);
  }
  const double m = RHO_C * A * LC, Iyy = RHO_C * (LC * Ix + A * LC * LC * LC / 12.0);
  const double arm = x_c;    // r cos(alpha + theta)
  Impact out;
  out.wy_a = -m * V * (1 + EPS) * arm / (Iyy + m * arm * arm);    // Eq. 27 (sign: -y)
  out.vz_a = EPS * V + out.wy_a * arm;                               // Eq. 28 (z up)
  out.wy = a->omega[0][1];
  out.vz = a->v[0][2];
  EXPECT_NEAR(m, a->rmass[0], 1e-9 * m);
  return out;
}

}    // namespace

// Acceptance 2 (short): a few angles of the seed's 10-80 degree sweep, at
// V = 0.1 m/s. omega_y within 2% of Eq. 27; V_z within 2% of V (Eq. 28 is a
// difference of two terms that nearly cancel at 30 and 80 degrees, where the
// finite contact patch, whose force point sits a few microns from C, shows).
TEST(WallMesh, CylinderImpact)
{
  const double V = 0.1;
  for (double th : {10.0, 30.0, 45.0, 60.0, 80.0}) {
    const Impact r = cylinder_impact(th, V);
    std::printf("[ wall     ] theta %4.0f: omega_y %.5g (Eq. 27: %.5g, %+.2f%%), V_z %.5g (Eq. "
                "28: %.5g, %+.2f%%)\n",
                th, r.wy, r.wy_a, 100 * (r.wy / r.wy_a - 1), r.vz, r.vz_a,
                100 * (r.vz / r.vz_a - 1));
    EXPECT_NEAR(r.wy, r.wy_a, 0.02 * std::fabs(r.wy_a)) << th;
    EXPECT_NEAR(r.vz, r.vz_a, 0.02 * V) << th;
  }
}

namespace {

std::string write_file(const std::string &name, const std::string &text)
{
  const std::string p = tmpdir() + "/" + name;
  std::ofstream(p) << text;
  return p;
}

std::vector<std::string> one_particle()
{
  return {"units si", "atom_style polyhedron", "atom_modify map array", "boundary f f f",
          "comm_modify vel yes", "region box block -0.1 0.1 -0.1 0.1 -0.1 0.1",
          "create_box 1 box", "polyhedron_shape c " + potentials() + "/cuboid_2p5cm.shape",
          "create_atoms 1 single 0 0 0.05", "polyhedron_set group all density 1500",
          "pair_style polyhedron", "pair_coeff * * 1e6 0.1 0.5 0.5"};
}

// the log of a one-particle LAMMPS instance running cmds (the last one may fail)
std::string one_particle_log(const std::string &name, const std::vector<std::string> &cmds)
{
  const std::string log = tmpdir() + "/" + name + ".log";
  {
    Lmp l({"-log", log});
    l.cmds(one_particle());
    for (size_t k = 0; k + 1 < cmds.size(); k++) l.cmd(cmds[k]);
    if (!cmds.empty()) l.error_of(cmds.back());
  }
  return polydem_test::read_text(log);
}

}    // namespace

// Acceptance 5: each bad input a clear LAMMPS error naming the command and
// the file (and line), or a warning with a count.
TEST(WallMesh, BadInput)
{
  const std::string good = tmpdir() + "/good.stl";
  write_ascii(good, flat(-0.05, 0.05, -0.05, 0.05, 0, 2, 2));
  Tris t = flat(-0.05, 0.05, -0.05, 0.05, 0, 2, 2);
  const std::string trunc = tmpdir() + "/trunc_lmp.stl";
  write_binary(trunc, t, 84 + 50 * 8 - 20);
  const std::string bad = write_file("bad_lmp.stl", "solid s\n facet normal 0 0 1\n  outer loop\n"
                                                    "   vertex 0 0 0\n   vertex 1 0\n");
  const std::string nan = write_file("nan_lmp.stl", "solid s\n facet normal 0 0 1\n  outer loop\n"
                                                    "   vertex 0 0 0\n   vertex 1 0 0\n"
                                                    "   vertex 0 NaN 0\n  endloop\n endfacet\n"
                                                    "endsolid s\n");
  const std::string empty = write_file("empty_lmp.stl", "solid s\nendsolid s\n");
  struct Case {
    std::string args, expect;
  };
  const std::vector<Case> cases = {
      {"/nonexistent/wall.stl", "fix wall/mesh: /nonexistent/wall.stl: cannot open file"},
      {tmpdir(), "fix wall/mesh: " + tmpdir() + ": cannot read: is a directory"},    // issue 17
      {trunc, "truncated binary STL"},
      {bad, "bad_lmp.stl:5: expected 'vertex x y z'"},
      {nan, "nan_lmp.stl:2: facet: non-finite coordinate"},
      {empty, "empty mesh"},
      {good + " bogus 1", "fix wall/mesh: unknown keyword 'bogus'"},
      {good + " scale -1", "fix wall/mesh: scale must be > 0"},
      {good + " offset 1 2", "keyword 'offset' needs 3 value(s)"},
      {good + " move rotate 0 0 0 0 0 1 speed 3", "'omega' or 'rpm', got 'speed'"},
      {good + " move rotate 0 0 0 0 0 0 rpm 3", "move rotate axis must be non-zero"},
      {good + " move spin", "unknown move style 'spin'"},
      {good + " friction -0.1", "friction must be >= 0"},
      {good + " restitution 0", "restitution must be in (0, 1]"},
      {good + " poisson 0.5", "poisson must be in (-1, 0.5)"},
      {good + " patch/angle 95", "patch/angle must be in [0, 90)"},
      {good + " flip maybe", "flip expects yes or no"},
      {good + " scale abc", "Expected floating point parameter"},
      {good + " offset 1e400 0 0", "'1e400' (argument 6) is not a finite number"},
      {good + " move rotate 0 0 0 0 0 1 rpm 1e400", "is not a finite number"},
      {good + " move wiggle 0 0 1e-3 1e-320", "move wiggle period must be > 0"},
      {good + " scale 1e305", "too large (its area overflows) after scale, rotate and offset"},
  };
  for (const auto &c : cases) {
    Lmp l;
    l.cmds(one_particle());
    const std::string msg = l.error_of("fix w all wall/mesh " + c.args);
    EXPECT_NE(msg.find(c.expect), std::string::npos) << c.args << " -> '" << msg << "'";
  }
  {    // an unreadable file: the error reaches the log (error->all)
    const std::string text = one_particle_log("badinput", {"fix w all wall/mesh /nonexistent/wall.stl"});
    EXPECT_NE(text.find("ERROR: fix wall/mesh: /nonexistent/wall.stl: cannot open file"),
              std::string::npos) << text;
  }
  {    // facet normals stored against the vertex order: a warning
    const std::string down = write_file("down_lmp.stl", "solid s\n facet normal 0 0 -1\n  outer loop\n"
                                        "   vertex -1 -1 0\n   vertex 1 -1 0\n   vertex 1 1 0\n"
                                        "  endloop\n endfacet\nendsolid s\n");
    const std::string text = one_particle_log("down", {"fix w all wall/mesh " + down});
    EXPECT_NE(text.find("point against the vertex order for 1 of 1 triangles"),
              std::string::npos) << text;
  }
  {    // a bin edge far too small for the mesh: enlarged, with a warning
    const std::string text =
        one_particle_log("tinybin", {"fix w all wall/mesh " + good + " bin 1e-12", "run 0"});
    EXPECT_NE(text.find("bin 1e-12 enlarged to"), std::string::npos) << text;
  }
  {    // without pair_style polyhedron the particles have no material
    Lmp l;
    l.cmds({"units si", "atom_style polyhedron", "region box block -1 1 -1 1 -1 1",
            "create_box 1 box", "fix w all wall/mesh " + good});
    const std::string msg = l.error_of("run 0");
    EXPECT_NE(msg.find("requires pair_style polyhedron"), std::string::npos) << msg;
  }
}

// the stability limit of a face resting flat on the wall in the core,
// 2 sqrt(m / (5/3 K V0^(-2/3) A^2)) for the 2.5 cm cuboid (E 1e6 Pa on a wall
// of the same E, core 1e-4): printed, and a warning above half of it
TEST(WallMesh, TimestepWarning)
{
  const std::string good = tmpdir() + "/dt.stl";
  write_ascii(good, flat(-0.05, 0.05, -0.05, 0.05, 0, 2, 2));
  const double Vp = L * L * L, m = 1500 * Vp;
  const double R = std::cbrt(3.0 * Vp / (4.0 * PI)), K = 2.0 * 1e6 / R, V0 = 1e-4 * Vp;
  const double limit = 2.0 * std::sqrt(m / (5.0 / 3.0 * K / std::cbrt(V0 * V0) * L * L * L * L));
  for (double f : {0.4, 0.6}) {
    const std::string text = one_particle_log(
        "dt", {"fix w all wall/mesh " + good, "timestep " + num(f * limit), "run 0"});
    const size_t at = text.find("a face flat on the wall in the core (core 0.0001) is stable for "
                                "timesteps below ");
    ASSERT_NE(at, std::string::npos) << text;
    const double printed = std::atof(text.c_str() + text.find("below ", at) + 6);
    EXPECT_NEAR(printed, limit, 1e-3 * limit);
    EXPECT_EQ(text.find("WARNING: fix wall/mesh w: timestep") != std::string::npos, f > 0.5) << text;
  }
}

// a dashpot capped at m_eff / dt (the cube dropped face down at 0.5 m/s with
// e = 0.05 and a time step near the flat contact's stability limit) damps
// less than asked: counted and warned about; at dt = 1e-6 s it is not
TEST(WallMesh, CappedDashpotWarns)
{
  const std::string floor = tmpdir() + "/cap.stl";
  write_ascii(floor, flat(-0.05, 0.05, -0.05, 0.05, 0, 2, 2));
  for (double dt : {1e-6, 3e-5}) {
    const std::string text = one_particle_log(
        "cap",
        {"pair_coeff * * 1e6 0.1 0.05 0.5", "set atom 1 z 0.0126", "velocity all set 0 0 -0.5",
         "fix w all wall/mesh " + floor, "fix 1 all nve/polyhedron", "timestep " + num(dt),
         "run " + std::to_string((int) std::lround(0.01 / dt))});
    const bool warned =
        text.find("contact-steps whose normal damping (dashpot or a liquid "
                  "bridge's viscosity) was capped at m_eff/dt") != std::string::npos;
    EXPECT_EQ(warned, dt > 1e-5) << "dt " << dt << "\n" << text;
  }
}

// zero-area and duplicate triangles: dropped, counted in a warning
TEST(WallMesh, DroppedTrianglesWarn)
{
  Tris t = flat(-0.05, 0.05, -0.05, 0.05, 0, 2, 2);
  const Tris dup(t.begin(), t.begin() + 9);
  t.insert(t.end(), dup.begin(), dup.end());
  for (double v : {0.0, 0.0, 0.0, 0.01, 0.0, 0.0, 0.02, 0.0, 0.0}) t.push_back(v);
  const std::string f = tmpdir() + "/dropped.stl";
  write_binary(f, t);
  const std::string text = one_particle_log("dropped", {"fix w all wall/mesh " + f});
  EXPECT_NE(text.find("10 triangles read, 8 kept"), std::string::npos) << text;
  EXPECT_NE(text.find("WARNING: fix wall/mesh: " + f + ": 1 zero-area triangles dropped"),
            std::string::npos);
  EXPECT_NE(text.find("WARNING: fix wall/mesh: " + f + ": 1 duplicate triangles dropped"),
            std::string::npos);
}

// Restart: the wall history of every atom and the mesh's displacement (a
// translating box) survive write_restart / read_restart bit for bit; with
// a fix of another ID (history and displacement lost) the run differs.
TEST(WallMesh, Restart)
{
  const double B = 0.06;
  const std::string data = scene_data(tmpdir() + "/restart.data", 3, B, 11);
  const std::string stl = tmpdir() + "/restart_box.stl";
  write_binary(stl, closed_box(B, 4));
  const std::string rst = tmpdir() + "/wall.restart";
  const std::string fix = " all wall/mesh " + stl + " friction 0.6 move translate 0.02 0 0";
  std::map<long, Lmp::State> ref, again, lost;
  double wref[3];
  {
    Lmp l;
    l.cmds(scene_setup(data));
    l.cmds({"fix w" + fix, "run 400", "write_restart " + rst, "run 300"});
    ref = l.local_state();
    auto *w = l.lmp->modify->fix[l.lmp->modify->find_fix("w")];
    for (int k = 0; k < 3; k++) wref[k] = w->compute_vector(k);
    ASSERT_GT(w->compute_vector(6), 0.0);    // contacts at the restart time and after
  }
  auto restarted = [&](const std::string &id) {
    Lmp l;
    l.cmds({"read_restart " + rst, "comm_modify vel yes", "neighbor 0.002 bin",
            "neigh_modify every 1 delay 0 check yes", "fix nve all nve/polyhedron",
            "fix g all gravity 9.81 vector 0 0 -1", "fix " + id + fix, "run 300"});
    if (id == "w") {
      auto *w = l.lmp->modify->fix[l.lmp->modify->find_fix("w")];
      for (int k = 0; k < 3; k++) EXPECT_EQ(w->compute_vector(k), wref[k]);
    }
    return l.local_state();
  };
  again = restarted("w");
  lost = restarted("other");
  ASSERT_EQ(again.size(), ref.size());
  double same = 0.0, diff = 0.0;
  for (auto &kv : ref)
    for (int k = 0; k < 3; k++) {
      same = std::fmax(same, std::fabs(kv.second.x[k] - again[kv.first].x[k]));
      same = std::fmax(same, std::fabs(kv.second.v[k] - again[kv.first].v[k]));
      diff = std::fmax(diff, std::fabs(kv.second.v[k] - lost[kv.first].v[k]));
    }
  std::printf("[ wall     ] restart: max |difference| %.3g; without history %.3g\n", same, diff);
  EXPECT_EQ(same, 0.0);
  EXPECT_GT(diff, 1e-6);
}

// Issue 17 item 6: the damping ratio for a small restitution used to take
// seconds (e = 0.01) or not end (e = 1e-20) at init; now a closed form
TEST(WallMesh, SmallRestitutionSetsUpQuickly)
{
  const std::string good = tmpdir() + "/good_e.stl";
  write_ascii(good, flat(-0.05, 0.05, -0.05, 0.05, 0, 2, 2));
  for (const char *e : {"0.01", "1e-20"}) {
    Lmp l;
    l.cmds(one_particle());
    const auto t0 = std::chrono::steady_clock::now();
    l.cmds({std::string("pair_coeff * * 1e6 0.1 ") + e + " 0.5",
            "fix w all wall/mesh " + good + " restitution " + e, "run 0"});
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    EXPECT_LT(s, 1.0) << "e = " << e;
  }
}

// Issue 17 item 8: youngs 1e300 made every wall contact NaN; the overflowing
// stiffness is now an error at init
TEST(WallMesh, OverflowingStiffnessRefused)
{
  const std::string good = tmpdir() + "/good_y.stl";
  write_ascii(good, flat(-0.05, 0.05, -0.05, 0.05, 0, 2, 2));
  {
    Lmp l;
    l.cmds(one_particle());
    l.cmd("polyhedron_set group all scale 0.24");    // a 6 mm cube, as in the issue
    l.cmd("fix w all wall/mesh " + good + " youngs 1e300");
    const std::string msg = l.error_of("run 0");
    EXPECT_NE(msg.find("fix wall/mesh w: the contact stiffness of 1 atom(s) overflows (youngs "
                       "1e+300"),
              std::string::npos)
        << msg;
  }
  Lmp l;
  l.cmds(one_particle());
  l.cmds({"fix w all wall/mesh " + good + " youngs 1e12", "run 0"});    // stiff, finite: fine
}

// Composites on a wall (issue 29): three grains of two overlapping cubes
// and a sphere land on a floor and slide with friction (each contact part
// keeps its own wall history, WALL_HIST_SIZE per part and atom); the run
// continues bit for bit from write_restart/read_restart, and a composite
// defined after the fix is refused (its history would not fit).
TEST(WallMesh, CompositesRestartExactly)
{
  const std::string stl = tmpdir() + "/composite_floor.stl";
  const std::string rst = tmpdir() + "/composite_wall.restart";
  write_ascii(stl, flat(-0.05, 0.05, -0.05, 0.05, 0.0, 4, 4));
  const std::vector<std::string> run = {"comm_modify vel yes", "neighbor 0.002 bin",
                                        "fix nve all nve/polyhedron",
                                        "fix g all gravity 9.81 vector 0 0 -1",
                                        "fix w all wall/mesh " + stl + " friction 0.6",
                                        "timestep 2e-6"};
  auto state = [](Lmp &l) {
    std::vector<double> s;
    auto *a = l.lmp->atom;
    for (int tag = 1; tag <= 3; tag++) {
      const int i = a->map(tag);
      for (int k = 0; k < 3; k++) s.insert(s.end(), {a->x[i][k], a->v[i][k], a->angmom[i][k]});
    }
    return s;
  };
  std::vector<double> ref;
  double contacts = 0.0;
  {
    Lmp l;
    l.cmds({"units si", "atom_style polyhedron", "atom_modify map array", "boundary f f f",
            "region box block -0.05 0.05 -0.05 0.05 -0.05 0.05", "create_box 1 box",
            "polyhedron_shape cube " + potentials() + "/cube.shape",
            "polyhedron_shape ball ellipsoid 0.5 0.5 0.5",
            "polyhedron_shape dumb composite part cube -0.4 0 0 part cube 0.4 0 0 quat 0.92 "
            "0.38 0 0 part ball 0 1.3 0",
            "create_atoms 1 single 0 0 0.0062", "create_atoms 1 single 0.02 0.004 0.0065",
            "create_atoms 1 single -0.018 0.01 0.007",
            "polyhedron_set group all shape dumb scale 0.004 density 2500 quat/random 5",
            "velocity all set 0.3 0.1 -0.4", "pair_style polyhedron",
            "pair_coeff * * 1e7 0.3 0.5 0.5"});
    l.cmds(run);
    l.cmd("run 4000");
    contacts = l.lmp->modify->fix[l.lmp->modify->find_fix("w")]->compute_vector(6);
    l.cmd("write_restart " + rst);
    l.cmd("run 2000");
    ref = state(l);
    // 16 parts (the fix was sized for dumb's contact parts): defining it is
    // fine, using it on this wall is not
    std::string late = "polyhedron_shape late composite";
    for (int k = 0; k < 16; k++) late += " part cube " + std::to_string(2 * k) + " 0 0";
    EXPECT_EQ(l.error_of(late), "");
    l.cmds({"polyhedron_set atom 1 shape late"});
    l.expect_error("run 1", "defined after the fix");
  }
  {
    Lmp l;
    l.cmd("read_restart " + rst);
    l.cmds(run);
    l.cmd("run 2000");
    const auto got = state(l);
    ASSERT_EQ(got.size(), ref.size());
    double diff = 0.0;
    for (size_t k = 0; k < got.size(); k++) diff = std::fmax(diff, std::fabs(got[k] - ref[k]));
    std::printf("[ wall     ] composites: %.0f wall contacts at the restart; largest difference "
                "after it %.3g\n", contacts, diff);
    EXPECT_EQ(diff, 0.0);
  }
  EXPECT_GE(contacts, 2.0);    // wall contacts (with friction history) at the restart
  std::remove(rst.c_str());
}
