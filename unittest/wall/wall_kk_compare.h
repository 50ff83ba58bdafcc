// fix wall/mesh/kk against plain fix wall/mesh in a scene of wall_scene.h
// (dodecahedra) or wall_ellipsoid_scene.h (ellipsoids): the same run with and
// without -sf kk, then per-atom forces and torques to 1e-12 of the largest,
// positions and velocities to 1e-12, the mesh's global vector and energy and
// a second mesh's per-triangle array to 1e-12 relative, the wall contacts
// seen equal.
#ifndef POLYDEM_TEST_WALL_KK_COMPARE_H
#define POLYDEM_TEST_WALL_KK_COMPARE_H

#include "wall_scene.h"

#include "fix.h"
#include "modify.h"

#include <gtest/gtest.h>

#include <cmath>

namespace wall_test {

// a scene: its data file, set-up commands, the neighbor command that
// follows them, the samples (run 10 each) and the tag of the printed lines
struct KkScene {
  std::vector<std::string> setup;
  std::string neighbor;
  int samples;
  const char *tag;
};

struct KkSnapshot {
  std::map<long, std::vector<double>> atoms;    // f, torque, x, v
  std::vector<double> vec;                      // the fix's global vector + scalar
  double contacts = 0.0;                        // wall contacts of w and w2, summed over samples
  double max_contacts = 0.0;                    // most wall contacts of w in a sample
  double max_contacts2 = 0.0;                   // same, w2
  std::string style;                            // of the fix (wall/mesh or wall/mesh/kk)
  std::vector<double> tri;                      // pertriangle array of w2 at its most contacts
};

inline KkSnapshot kk_run(const KkScene &sc, const std::vector<std::string> &extra,
                         const std::string &fixargs, const std::string &fix2args = "")
{
  polydem_test::Lmp l(extra);
  auto cmds = sc.setup;
  if (!extra.empty())
    for (auto &c : cmds)
      if (c == sc.neighbor) c = "newton off";    // with -pk newton off
  l.cmds(cmds);
  l.cmds({sc.neighbor, "fix w all wall/mesh " + fixargs});
  if (!fix2args.empty()) l.cmd("fix w2 all wall/mesh " + fix2args);
  KkSnapshot s;
  auto *fix = l.lmp->modify->fix[l.lmp->modify->find_fix("w")];
  auto *fix2 = fix2args.empty() ? nullptr : l.lmp->modify->fix[l.lmp->modify->find_fix("w2")];
  s.style = fix->style;
  for (int k = 0; k < sc.samples; k++) {
    l.cmd("run 10");
    const double c1 = fix->compute_vector(6);
    s.contacts += c1;
    s.max_contacts = std::fmax(s.max_contacts, c1);
    if (fix2) {
      const double c2 = fix2->compute_vector(6);
      if (c2 > s.max_contacts2 && fix2->array_flag) {
        s.tri.clear();
        for (int t = 0; t < fix2->size_array_rows; t++)
          for (int c = 0; c < 4; c++) s.tri.push_back(fix2->compute_array(t, c));
      }
      s.max_contacts2 = std::fmax(s.max_contacts2, c2);
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

inline void kk_compare(const KkScene &sc, const KkSnapshot &p, const KkSnapshot &k,
                       const char *what)
{
  EXPECT_EQ(p.style, "wall/mesh");
  EXPECT_EQ(k.style, "wall/mesh/kk");
  ASSERT_EQ(p.atoms.size(), k.atoms.size());
  const auto [fmax, dmax, xmax] = record_diff(p.atoms, k.atoms);
  EXPECT_LE(xmax, 1e-12) << what;
  std::printf("[ %s ] %s: max |f,torque (kk - plain)| = %.3g (max |f| %.3g), max |x,v| "
              "difference %.3g; mesh force %.6g %.6g %.6g; contacts seen %g (most %g, %g)\n",
              sc.tag, what, dmax, fmax, xmax, p.vec[0], p.vec[1], p.vec[2], p.contacts,
              p.max_contacts, p.max_contacts2);
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
    std::printf("[ %s ] %s: pertriangle max |kk - plain| %.3g of %.3g\n", sc.tag, what, tdiff,
                tmax);
    EXPECT_GT(tmax, 0.0);
  }
}

}    // namespace wall_test

#endif
