// fix wall/mesh/kk (Kokkos) against plain fix wall/mesh (acceptance
// 6): dodecahedra in a closed box mesh, translating or rotating (45 rpm),
// with friction and damping, 500 steps: per-atom forces and torques to 1e-12
// of the largest, positions and velocities to 1e-12, the mesh's global
// vector and energy to 1e-12 relative.
#include "wall_scene.h"

#include "fix.h"
#include "modify.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

using polydem_test::Lmp;
using namespace wall_test;

namespace {

const std::vector<std::string> KK =
    polydem_test::kk({"-sf", "kk", "-pk", "kokkos", "newton", "off"});

struct Snapshot {
  std::map<long, std::vector<double>> atoms;    // f, torque, x, v, wall history
  std::vector<double> vec;                      // the fix's global vector + scalar
  double max_contacts = 0.0;                    // wall contacts, most seen every 50 steps
  double max_contacts2 = 0.0;                   // same, second mesh
  std::vector<double> tri;                      // pertriangle array of w2 at its most contacts
};

Snapshot run(const std::vector<std::string> &extra, const std::string &fixargs,
             const std::string &fix2args = "")
{
  const std::string data = scene_data(tmpdir() + "/kk.data", 3, 0.06, 21);
  Lmp l(extra);
  auto cmds = scene_setup(data);
  if (!extra.empty())
    for (auto &c : cmds)
      if (c == "neighbor 0.002 bin") c = "newton off";    // with -pk newton off
  l.cmds(cmds);
  l.cmds({"neighbor 0.002 bin", "fix w all wall/mesh " + fixargs});
  if (!fix2args.empty()) l.cmd("fix w2 all wall/mesh " + fix2args);
  Snapshot s;
  auto *fix = l.lmp->modify->fix[l.lmp->modify->find_fix("w")];
  auto *fix2 = fix2args.empty() ? nullptr : l.lmp->modify->fix[l.lmp->modify->find_fix("w2")];
  for (int k = 0; k < 50; k++) {    // 500 steps; the most wall contacts seen at the ends
    l.cmd("run 10");
    s.max_contacts = std::fmax(s.max_contacts, fix->compute_vector(6));
    if (fix2) {
      const double c2 = fix2->compute_vector(6);
      if (c2 > s.max_contacts2 && fix2->array_flag) {    // pertriangle at the most contacts
        s.tri.clear();
        for (int t = 0; t < fix2->size_array_rows; t++)
          for (int c = 0; c < 4; c++) s.tri.push_back(fix2->compute_array(t, c));
      }
      s.max_contacts2 = std::fmax(s.max_contacts2, c2);
    }
  }
  auto *a = l.lmp->atom;
  for (int i = 0; i < a->nlocal; i++) {
    std::vector<double> r;
    for (int k = 0; k < 3; k++) r.push_back(a->f[i][k]);
    for (int k = 0; k < 3; k++) r.push_back(a->torque[i][k]);
    for (int k = 0; k < 3; k++) r.push_back(a->x[i][k]);
    for (int k = 0; k < 3; k++) r.push_back(a->v[i][k]);
    s.atoms[(long) a->tag[i]] = r;
  }
  for (int k = 0; k < fix->size_vector; k++) s.vec.push_back(fix->compute_vector(k));
  s.vec.push_back(fix->compute_scalar());
  return s;
}

void compare(const Snapshot &p, const Snapshot &k, const char *what)
{
  ASSERT_EQ(p.atoms.size(), k.atoms.size());
  double fmax = 0.0, dmax = 0.0;
  for (auto &kv : p.atoms) {
    const auto &q = k.atoms.at(kv.first);
    for (int c = 0; c < 6; c++) {
      fmax = std::fmax(fmax, std::fabs(kv.second[c]));
      dmax = std::fmax(dmax, std::fabs(kv.second[c] - q[c]));
    }
    for (int c = 6; c < 12; c++) EXPECT_NEAR(kv.second[c], q[c], 1e-12) << what;
  }
  std::printf("[ wall     ] %s: max |f,torque (kk - plain)| = %.3g (max |f| %.3g); mesh force "
              "%.6g %.6g %.6g, contacts %g\n", what, dmax, fmax, p.vec[0], p.vec[1], p.vec[2],
              p.vec[6]);
  EXPECT_GT(fmax, 0.0);
  EXPECT_LE(dmax, 1e-12 * fmax);
  for (size_t c = 0; c < p.vec.size(); c++)
    EXPECT_NEAR(p.vec[c], k.vec[c], 1e-12 * (1.0 + std::fabs(p.vec[c]))) << what << " " << c;
}

}    // namespace

TEST(WallKokkos, KkEqualsPlain)
{
  const std::string box = tmpdir() + "/kk_box.stl";
  write_binary(box, closed_box(0.06, 5));
  for (const std::string move :
       {" move translate 0.05 0 0", " move rotate 0.03 0.03 0.03 1 0.3 0.2 rpm 45"}) {
    const std::string args = box + " friction 0.6 restitution 0.4" + move;
    const Snapshot p = run({}, args), k = run(KK, args);
    compare(p, k, move.c_str());
    EXPECT_GE(p.max_contacts, 1.0);    // the wall was touched during the run
  }
  // and a curved floor (4,608 facets, none coplanar, near lists on by
  // default) under the particles, inside the box
  const std::string curved = tmpdir() + "/kk_bowl.stl";
  write_binary(curved, bowl(0, 0.06, 0, 0.06, 0.0003, 0.3, 48));
  const std::string args = box + " friction 0.6 restitution 0.4";
  const std::string args2 = curved + " friction 0.5 restitution 0.5 pertriangle yes";
  const Snapshot p = run({}, args, args2), k = run(KK, args, args2);
  compare(p, k, "box and curved floor");
  ASSERT_EQ(p.tri.size(), k.tri.size());
  double tmax = 0.0, tdiff = 0.0;
  for (size_t c = 0; c < p.tri.size(); c++) {
    tmax = std::fmax(tmax, std::fabs(p.tri[c]));
    tdiff = std::fmax(tdiff, std::fabs(p.tri[c] - k.tri[c]));
  }
  std::printf("[ wall     ] curved floor: up to %g contacts; pertriangle: max |kk - plain| %.3g of "
              "%.3g\n", p.max_contacts2, tdiff, tmax);
  EXPECT_GT(tmax, 0.0);
  EXPECT_LE(tdiff, 1e-12 * tmax);
  EXPECT_GE(p.max_contacts2, 5.0);    // the curved floor was touched
}

// Two-sided walls (issue 17): the same box and curved floor with their
// normals reversed (flip yes: every contact is met from the back, through
// the kept sides of the wall history, near lists on), and the box one-sided
// (sides front): /kk equals plain.
TEST(WallKokkos, TwoSidedKkEqualsPlain)
{
  const std::string box = tmpdir() + "/kk2_box.stl", curved = tmpdir() + "/kk2_bowl.stl";
  write_binary(box, closed_box(0.06, 5));
  write_binary(curved, bowl(0, 0.06, 0, 0.06, 0.0003, 0.3, 48));
  const std::string args = box + " friction 0.6 restitution 0.4 flip yes move translate 0.05 0 0";
  const std::string args2 = curved + " friction 0.5 restitution 0.5 pertriangle yes flip yes";
  const Snapshot p = run({}, args, args2), k = run(KK, args, args2);
  compare(p, k, "reversed box and curved floor");
  EXPECT_GE(p.max_contacts, 1.0);
  EXPECT_GE(p.max_contacts2, 5.0);
  const std::string front = box + " friction 0.6 sides front";
  const Snapshot pf = run({}, front), kf = run(KK, front);
  compare(pf, kf, "box, one-sided");
}

// The warnings' counts and maxima reduced over /kk threads: the initial
// overlap of a 6 mm cube created 0.5 mm into a floor (issue 17 item 2), and
// the overlap/warn and depth/warn counts of its run, as the plain fix.
TEST(WallKokkos, WarningsAsPlain)
{
  const std::string stl = tmpdir() + "/kk_floor.stl";
  write_ascii(stl, flat(-0.05, 0.05, -0.05, 0.05, 0.0, 2, 2));
  auto warnings = [&](const std::vector<std::string> &extra, const std::string &name) {
    const std::string log = tmpdir() + "/" + name + ".log";
    {
      std::vector<std::string> args = {"-log", log};
      args.insert(args.end(), extra.begin(), extra.end());
      Lmp l(args);
      l.cmds({"units si", "atom_style polyhedron", "atom_modify map array", "boundary f f f",
              "comm_modify vel yes", "newton off",
              "region box block -0.05 0.05 -0.05 0.05 -0.05 0.05", "create_box 1 box",
              "polyhedron_shape c " + polydem_test::potentials() + "/cuboid_2p5cm.shape",
              "create_atoms 1 single 0 0 0.0025", "create_atoms 1 single 0.02 0 0.0026",
              "polyhedron_set group all scale 0.24 density 1500", "pair_style polyhedron",
              "pair_coeff * * 1e6 0.1 0.5 0.5", "fix nve all nve/polyhedron",
              "fix w all wall/mesh " + stl + " depth/warn 0.05", "timestep 2e-6", "run 200"});
    }
    std::ifstream in(log);
    std::string line, out;
    while (std::getline(in, line))
      if (line.find("WARNING: fix wall/mesh w:") != std::string::npos &&
          line.find("timestep") == std::string::npos)
        out += line.substr(0, line.find(" (src/")) + "\n";
    return out;
  };
  const std::string p = warnings({}, "warn_plain"), k = warnings(KK, "warn_kk");
  std::printf("%s", p.c_str());
  EXPECT_NE(p.find("2 contact(s) overlap the mesh at the start of the run"), std::string::npos);
  EXPECT_NE(p.find("depth/warn"), std::string::npos);
  EXPECT_NE(p.find("overlap/warn"), std::string::npos);
  EXPECT_EQ(p, k);
}
