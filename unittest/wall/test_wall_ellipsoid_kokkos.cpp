// fix wall/mesh/kk (Kokkos) against plain fix wall/mesh for
// ellipsoids (issue 16): 18 ellipsoids in a closed box mesh, translating or
// rotating (45 rpm), a curved floor with per-triangle forces, friction and
// damping, 1,500 steps (30 or more wall contacts summed over 150 samples):
// per-atom forces and torques to 1e-12 of the largest, positions and
// velocities to 1e-12, the mesh's global vector, energy and per-triangle
// array to 1e-12 relative (measured: bit-identical on Kokkos Serial).
#include "wall_ellipsoid_scene.h"

#include "fix.h"
#include "modify.h"

#include <gtest/gtest.h>

#include <cmath>

using polydem_test::Lmp;
using namespace wall_test;

namespace {

const std::vector<std::string> KK =
    polydem_test::kk({"-sf", "kk", "-pk", "kokkos", "newton", "off"});

struct Snapshot {
  std::map<long, std::vector<double>> atoms;    // f, torque, x, v
  std::vector<double> vec;                      // the fix's global vector + scalar
  double contacts = 0.0;                        // wall contacts, summed every 10 steps
  std::string style;                            // of the fix (wall/mesh or wall/mesh/kk)
  std::vector<double> tri;                      // pertriangle array of w2 at its most contacts
};

Snapshot run(const std::vector<std::string> &extra, const std::string &fixargs,
             const std::string &fix2args = "")
{
  const std::string data = ellipsoid_scene_data(tmpdir() + "/ell_kk.data", 21);
  Lmp l(extra);
  auto cmds = ellipsoid_scene_setup(data);
  if (!extra.empty())
    for (auto &c : cmds)
      if (c == "neighbor 0.0006 bin") c = "newton off";    // with -pk newton off
  l.cmds(cmds);
  l.cmds({"neighbor 0.0006 bin", "fix w all wall/mesh " + fixargs});
  if (!fix2args.empty()) l.cmd("fix w2 all wall/mesh " + fix2args);
  Snapshot s;
  auto *fix = l.lmp->modify->fix[l.lmp->modify->find_fix("w")];
  auto *fix2 = fix2args.empty() ? nullptr : l.lmp->modify->fix[l.lmp->modify->find_fix("w2")];
  double most2 = 0.0;
  s.style = fix->style;
  for (int k = 0; k < 150; k++) {
    l.cmd("run 10");
    s.contacts += fix->compute_vector(6);
    if (fix2) {
      const double c2 = fix2->compute_vector(6);
      if (c2 > most2) {
        s.tri.clear();
        for (int t = 0; t < fix2->size_array_rows; t++)
          for (int c = 0; c < 4; c++) s.tri.push_back(fix2->compute_array(t, c));
        most2 = c2;
      }
      s.contacts += c2;
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
  EXPECT_EQ(p.style, "wall/mesh");
  EXPECT_EQ(k.style, "wall/mesh/kk");
  ASSERT_EQ(p.atoms.size(), k.atoms.size());
  double fmax = 0.0, dmax = 0.0, xmax = 0.0;
  for (auto &kv : p.atoms) {
    const auto &q = k.atoms.at(kv.first);
    for (int c = 0; c < 6; c++) {
      fmax = std::fmax(fmax, std::fabs(kv.second[c]));
      dmax = std::fmax(dmax, std::fabs(kv.second[c] - q[c]));
    }
    for (int c = 6; c < 12; c++) {
      EXPECT_NEAR(kv.second[c], q[c], 1e-12) << what;
      xmax = std::fmax(xmax, std::fabs(kv.second[c] - q[c]));
    }
  }
  std::printf("[ ell wall ] %s: max |f,torque (kk - plain)| = %.3g (max |f| %.3g), max |x,v| "
              "difference %.3g; contacts seen %g\n", what, dmax, fmax, xmax, p.contacts);
  EXPECT_GT(fmax, 0.0);
  EXPECT_LE(dmax, 1e-12 * fmax);
  EXPECT_EQ(p.contacts, k.contacts);
  for (size_t c = 0; c < p.vec.size(); c++)
    EXPECT_NEAR(p.vec[c], k.vec[c], 1e-12 * (1.0 + std::fabs(p.vec[c]))) << what << " " << c;
  ASSERT_EQ(p.tri.size(), k.tri.size());
  double tmax = 0.0, tdiff = 0.0;
  for (size_t c = 0; c < p.tri.size(); c++) {
    tmax = std::fmax(tmax, std::fabs(p.tri[c]));
    tdiff = std::fmax(tdiff, std::fabs(p.tri[c] - k.tri[c]));
  }
  EXPECT_LE(tdiff, 1e-12 * tmax);
  if (!p.tri.empty()) {
    std::printf("[ ell wall ] %s: pertriangle max |kk - plain| %.3g of %.3g\n", what, tdiff, tmax);
    EXPECT_GT(tmax, 0.0);
  }
}

}    // namespace

TEST(WallEllipsoidKokkos, KkEqualsPlain)
{
  const std::string box = tmpdir() + "/ell_kk_box.stl";
  write_binary(box, closed_box(EB, 4));
  const std::string curved = tmpdir() + "/ell_kk_bowl.stl";
  write_binary(curved, bowl(0, EB, 0, EB, 0.0004, 0.1, 24));
  for (const std::string move :
       {" move translate 0.05 0 0", " move rotate 0.015 0.015 0.015 1 0.3 0.2 rpm 45"}) {
    const std::string args = box + " friction 0.5 restitution 0.5" + move;
    const Snapshot p = run({}, args), k = run(KK, args);
    compare(p, k, move.c_str());
    EXPECT_GE(p.contacts, 30.0);    // the walls were touched
  }
  // the box reversed (every contact met from its back) and a curved floor
  // inside it (pertriangle)
  const std::string args = box + " friction 0.5 flip yes";
  const std::string args2 = curved + " friction 0.4 restitution 0.7 pertriangle yes";
  const Snapshot p = run({}, args, args2), k = run(KK, args, args2);
  compare(p, k, "reversed box and curved floor");
  EXPECT_GE(p.contacts, 30.0);
}
