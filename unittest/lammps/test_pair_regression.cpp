// Force-style regression of pair_style polyhedron (issue 4, acceptance 6):
// per-atom forces and torques, energy and virial of a fixed configuration
// (pair_regression.data: 27 overlapping cubes, dodecahedra, cylinders and
// tetrahedra in a periodic box, moving and spinning, damping and friction)
// at step 0 and after 50 steps (friction history), against the reference
// pair_regression.ref, to 1e-10 relative: catches any change in the model.
//
// The reference is not merely the code checking itself: in this file the
// same configuration is also checked independently of it:
//  - forces and torques = minus the gradient of the pair energy, by central
//    finite differences of W in translation and rotation (elastic version);
//  - polyhedron/kk gives the reference values too (to 1e-12);
//  - 1 rank and 2 ranks (ctest runs this file under mpirun -np 2 as well).
// Regenerate (only after a deliberate model change, and say so in the commit):
//   POLYDEM_WRITE_REFERENCE=unittest/lammps/pair_regression.ref \
//   POLYDEM_REFERENCE_COMMIT=$(git rev-parse HEAD) \
//   build/unittest/lammps/test_pair_regression --gtest_filter=*MatchesReference

#include "polydem_allgather.h"
#include "polydem_lmp.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using polydem_test::Lmp;
using polydem_test::potentials;

namespace {

const std::string DIR = POLYDEM_TEST_DIR;
const std::vector<std::string> KK = polydem_test::kk_styles();

std::vector<std::string> setup(const std::string &coeff, const std::string &newton)
{
  return {"units lj",
          "atom_style polyhedron",
          "atom_modify map array",
          "comm_modify vel yes",
          "newton " + newton,
          "boundary p p p",
          "polyhedron_shape cube " + potentials() + "/cube.shape",
          "polyhedron_shape dode " + potentials() + "/dodecahedron.shape",
          "polyhedron_shape cyl " + potentials() + "/cylinder42.shape",
          "polyhedron_shape tet " + potentials() + "/tetrahedron.shape",
          "read_data " + DIR + "/pair_regression.data",
          "pair_style polyhedron overlap/warn 1.0",
          coeff,
          "neighbor 0.01 bin",
          "neigh_modify every 1 delay 0 check yes",
          "fix 1 all nve/polyhedron",
          "timestep 1.0e-4",
          "compute pf all property/atom fx fy fz tqx tqy tqz",
          "compute pv all pressure NULL virial",
          "thermo_style custom step pe c_pv[*]",
          "thermo_modify norm no",
          "thermo 50"};
}
const std::string COEFF = "pair_coeff * * 1.0e4 0.3 0.7 0.5";
const std::string COEFF12 = "pair_coeff 1 2 0.8 0.3";

// energy, virial (6) and, per atom ID, force and torque (6)
struct Snapshot {
  double energy;
  double virial[6];
  std::map<long, std::vector<double>> atoms;
};

Snapshot snapshot(Lmp &l)
{
  Snapshot s;
  s.energy = l.thermo("pe");
  auto *pv = (double *) lammps_extract_compute(l.lmp, "pv", LMP_STYLE_GLOBAL, LMP_TYPE_VECTOR);
  for (int k = 0; k < 6; k++) s.virial[k] = pv[k];
  auto **pf = (double **) lammps_extract_compute(l.lmp, "pf", LMP_STYLE_ATOM, LMP_TYPE_ARRAY);
  auto *a = l.lmp->atom;
  std::vector<double> mine;
  for (int i = 0; i < a->nlocal; i++) {
    mine.push_back((double) a->tag[i]);
    for (int k = 0; k < 6; k++) mine.push_back(pf[i][k]);
  }
  const std::vector<double> all = polydem_test::allgather(mine);
  const int total = (int) all.size();
  for (int k = 0; k < total; k += 7) s.atoms[(long) all[k]].assign(&all[k + 1], &all[k + 7]);
  return s;
}

// step 0 and step 50 of the regression run
std::vector<Snapshot> regression_run(const std::vector<std::string> &extra,
                                     const std::string &newton)
{
  Lmp l(extra);
  l.cmds(setup(COEFF, newton));
  l.cmd(COEFF12);
  l.cmd("run 0");
  std::vector<Snapshot> out{snapshot(l)};
  l.cmd("run 50");
  out.push_back(snapshot(l));
  return out;
}

void write_reference(const std::string &file, const std::vector<Snapshot> &s)
{
  std::ofstream o(file);
  const char *commit = std::getenv("POLYDEM_REFERENCE_COMMIT");
  o << "# pair_style polyhedron force regression reference (test_pair_regression.cpp)\n"
    << "# generated at commit " << (commit ? commit : "unknown") << "\n"
    << "# per snapshot: step, energy, virial (6), then per atom: atom ID fx fy fz tqx tqy tqz\n";
  o.precision(17);
  const int steps[2] = {0, 50};
  for (int k = 0; k < 2; k++) {
    o << "step " << steps[k] << "\nenergy " << s[k].energy << "\nvirial";
    for (double v : s[k].virial) o << " " << v;
    o << "\n";
    for (auto &kv : s[k].atoms) {
      o << "atom " << kv.first;
      for (double v : kv.second) o << " " << v;
      o << "\n";
    }
  }
}

std::vector<Snapshot> read_reference(const std::string &file)
{
  std::ifstream in(file);
  std::vector<Snapshot> out;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream w(line);
    std::string key;
    if (!(w >> key) || key[0] == '#') continue;
    if (key == "step") out.emplace_back();
    else if (key == "energy") w >> out.back().energy;
    else if (key == "virial")
      for (double &v : out.back().virial) w >> v;
    else if (key == "atom") {
      long id;
      w >> id;
      auto &a = out.back().atoms[id];
      a.resize(6);
      for (double &v : a) w >> v;
    }
  }
  return out;
}

// largest difference of forces (cols 0-2) and torques (3-5) relative to the
// largest reference force / torque; energy and virial relative
struct Diff {
  double force, torque, energy, virial;
};

Diff compare(const Snapshot &got, const Snapshot &ref)
{
  Diff d{0, 0, 0, 0};
  double fmax = 0, tmax = 0, vmax = 0;
  for (auto &kv : ref.atoms) {
    const auto &r = kv.second;
    fmax = std::max(fmax, std::hypot(r[0], r[1], r[2]));
    tmax = std::max(tmax, std::hypot(r[3], r[4], r[5]));
    auto it = got.atoms.find(kv.first);
    if (it == got.atoms.end()) return Diff{1e300, 1e300, 1e300, 1e300};
    const auto &g = it->second;
    d.force = std::max(d.force, std::hypot(g[0] - r[0], g[1] - r[1], g[2] - r[2]));
    d.torque = std::max(d.torque, std::hypot(g[3] - r[3], g[4] - r[4], g[5] - r[5]));
  }
  for (int k = 0; k < 6; k++) vmax = std::max(vmax, std::fabs(ref.virial[k]));
  for (int k = 0; k < 6; k++) d.virial = std::max(d.virial, std::fabs(got.virial[k] - ref.virial[k]));
  d.force /= fmax;
  d.torque /= tmax;
  d.virial /= vmax;
  d.energy = std::fabs(got.energy - ref.energy) / std::fabs(ref.energy);
  if (got.atoms.size() != ref.atoms.size()) d.force = 1e300;
  return d;
}

void expect_close(const Snapshot &got, const Snapshot &ref, double tol, const std::string &what)
{
  const Diff d = compare(got, ref);
  std::printf("%s: force %.3g torque %.3g energy %.3g virial %.3g\n", what.c_str(), d.force,
              d.torque, d.energy, d.virial);
  EXPECT_LE(d.force, tol) << what;
  EXPECT_LE(d.torque, tol) << what;
  EXPECT_LE(d.energy, tol) << what;
  EXPECT_LE(d.virial, tol) << what;
}

}    // namespace

TEST(PairRegression, MatchesReference)
{
  const auto got = regression_run({}, "on");
  if (const char *file = std::getenv("POLYDEM_WRITE_REFERENCE")) {
    int me;
    MPI_Comm_rank(MPI_COMM_WORLD, &me);
    if (me == 0) write_reference(file, got);
    GTEST_SKIP() << "reference written to " << file;
  }
  const auto ref = read_reference(DIR + "/pair_regression.ref");
  ASSERT_EQ(ref.size(), 2u);
  ASSERT_EQ(ref[0].atoms.size(), 27u);
  // sanity of the configuration: contacts with friction and damping present
  ASSERT_GT(ref[0].energy, 0.0);
  expect_close(got[0], ref[0], 1e-10, "plain newton on, step 0");
  expect_close(got[1], ref[1], 1e-10, "plain newton on, step 50");
  const auto off = regression_run({}, "off");
  expect_close(off[0], ref[0], 1e-10, "plain newton off, step 0");
  expect_close(off[1], ref[1], 1e-10, "plain newton off, step 50");
}

TEST(PairRegression, KokkosMatchesReference)
{
  if (!polydem_test::has_kokkos()) GTEST_SKIP() << "LAMMPS without the KOKKOS package";
  const auto ref = read_reference(DIR + "/pair_regression.ref");
  ASSERT_EQ(ref.size(), 2u);
  const auto kk = regression_run(KK, "off");
  expect_close(kk[0], ref[0], 1e-12, "/kk, step 0");
  expect_close(kk[1], ref[1], 1e-10, "/kk, step 50");
}

// Independent of the reference: with e = 1, mu = 0 and no velocities the pair
// force and torque on an atom are minus the gradient of the total pair energy
// in its position and orientation (central differences, step h).
TEST(PairRegression, ForcesAreMinusEnergyGradient)
{
  int nprocs;
  MPI_Comm_size(MPI_COMM_WORLD, &nprocs);
  if (nprocs > 1) GTEST_SKIP() << "moves atoms through the host arrays: 1 rank";
  Lmp l;
  l.cmds(setup("pair_coeff * * 1.0e4 0.3 1.0 0.0", "on"));
  l.cmds({"velocity all set 0 0 0", "polyhedron_set group all omega 0 0 0", "run 0"});
  const Snapshot s0 = snapshot(l);
  auto *a = l.lmp->atom;
  double fmax = 0, tmax = 0, worst_f = 0, worst_t = 0;
  for (auto &kv : s0.atoms) {
    fmax = std::max(fmax, std::hypot(kv.second[0], kv.second[1], kv.second[2]));
    tmax = std::max(tmax, std::hypot(kv.second[3], kv.second[4], kv.second[5]));
  }
  const double h = 1e-6;    // length (particles ~1) and radians
  auto energy_after = [&](long id, int kind, int axis, double step) {
    const int i = a->map(id);
    double x0[3], q0[4];
    for (int k = 0; k < 3; k++) x0[k] = a->x[i][k];
    for (int k = 0; k < 4; k++) q0[k] = a->quat[i][k];
    if (kind == 0)
      a->x[i][axis] += step;
    else {
      // lab-frame rotation by 'step' about axis: q <- (cos, sin e) * q
      double r[4] = {std::cos(0.5 * step), 0, 0, 0};
      r[1 + axis] = std::sin(0.5 * step);
      const double *q = q0;
      a->quat[i][0] = r[0] * q[0] - r[1] * q[1] - r[2] * q[2] - r[3] * q[3];
      a->quat[i][1] = r[0] * q[1] + r[1] * q[0] + r[2] * q[3] - r[3] * q[2];
      a->quat[i][2] = r[0] * q[2] - r[1] * q[3] + r[2] * q[0] + r[3] * q[1];
      a->quat[i][3] = r[0] * q[3] + r[1] * q[2] - r[2] * q[1] + r[3] * q[0];
    }
    l.cmd("run 0");
    const double e = l.thermo("pe");
    const int j = a->map(id);
    for (int k = 0; k < 3; k++) a->x[j][k] = x0[k];
    for (int k = 0; k < 4; k++) a->quat[j][k] = q0[k];
    return e;
  };
  int checked = 0;
  for (auto &kv : s0.atoms) {
    const long id = kv.first;
    if (std::hypot(kv.second[0], kv.second[1], kv.second[2]) < 1e-3 * fmax) continue;
    for (int kind = 0; kind < 2; kind++)
      for (int axis = 0; axis < 3; axis++) {
        const double ep = energy_after(id, kind, axis, h), em = energy_after(id, kind, axis, -h);
        const double grad = (ep - em) / (2.0 * h);
        const double got = kv.second[3 * kind + axis];
        if (kind == 0)
          worst_f = std::max(worst_f, std::fabs(got + grad) / fmax);
        else
          worst_t = std::max(worst_t, std::fabs(got + grad) / tmax);
      }
    checked++;
  }
  std::printf("%d atoms in contact: |f + dW/dx| / max|f| = %.3g, |tq + dW/dtheta| / max|tq| = "
              "%.3g\n", checked, worst_f, worst_t);
  EXPECT_GE(checked, 20);
  EXPECT_LE(worst_f, 1e-6);
  EXPECT_LE(worst_t, 1e-6);
}
