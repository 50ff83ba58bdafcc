// compute contact/polyhedron/local and compute contact/polyhedron (issue 4):
// per-contact records of pair polyhedron and /kk against known geometry (two
// cubes face to face: overlap box, its centroid, S_A, the analytic force)
// and against the pair's own per-atom forces and energy in a dense periodic
// packing (each contact exactly once over all ranks, newton on and off),
// plain vs /kk to 1e-12. Also run under mpirun -np 2.

#include "polydem_allgather.h"
#include "polydem_contact_record.h"
#include "polydem_lmp.h"

#include "force.h"
#include "pair.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

using polydem_test::allgather;
using polydem_test::Lmp;
using polydem_test::potentials;

namespace {

const std::vector<std::string> KK = polydem_test::kk_styles();

// the columns requested from the local compute, in this order
const char *COLUMNS = "id1 id2 vol volfrac area fx fy fz nx ny nz cx cy cz fn ft energy";
enum { ID1, ID2, VOL, VOLFRAC, AREA, FX, FY, FZ, NX, NY, NZ, CX, CY, CZ, FN, FT, ENERGY, NCOL };

std::string num(double x)
{
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.17g", x);
  return buf;
}

// rows of the local compute on this rank
std::vector<std::vector<double>> local_rows(Lmp &l, const std::string &id)
{
  auto *rows = (int *) lammps_extract_compute(l.lmp, id.c_str(), LMP_STYLE_LOCAL, LMP_SIZE_ROWS);
  auto *arr = (double **) lammps_extract_compute(l.lmp, id.c_str(), LMP_STYLE_LOCAL,
                                                 LMP_TYPE_ARRAY);
  std::vector<std::vector<double>> out;
  for (int r = 0; rows && r < *rows; r++) out.emplace_back(arr[r], arr[r] + NCOL);
  return out;
}

// all ranks' rows, each normalised to id1 < id2 (force and normal flipped),
// sorted by (id1, id2)
std::vector<std::vector<double>> all_rows(Lmp &l, const std::string &id)
{
  std::vector<double> mine;
  for (auto r : local_rows(l, id)) {
    if (r[ID1] > r[ID2]) {
      std::swap(r[ID1], r[ID2]);
      for (int k = 0; k < 3; k++) r[FX + k] = -r[FX + k], r[NX + k] = -r[NX + k];
    }
    mine.insert(mine.end(), r.begin(), r.end());
  }
  const std::vector<double> all = allgather(mine);
  const int total = (int) all.size();
  std::vector<std::vector<double>> out;
  for (int i = 0; i < total; i += NCOL) out.emplace_back(all.begin() + i, all.begin() + i + NCOL);
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<double> stats(Lmp &l, const std::string &id)
{
  std::vector<double> v;
  for (int k = 0; k < 4; k++) {
    auto *p = (double *) lammps_extract_compute(l.lmp, id.c_str(), LMP_STYLE_GLOBAL,
                                                LMP_TYPE_VECTOR);
    v.push_back(p ? p[k] : std::nan(""));
  }
  return v;
}

// Two aligned cubes (edge a) overlapping face to face by delta, the second
// shifted by dy: the overlap is the box a (a-dy) delta centred at
// ((a-delta)/2, dy/2, 0), S_A = (a(a-dy), a delta, 0) (test_pair_polyhedron),
// F_A = -W'(V) S_A with W' = K V^(1/3), K = 2E/R (core 0).
void face_to_face(const std::vector<std::string> &extra)
{
  const double a = 0.01, delta = 2e-4, dy = 3e-3, E = 5e7;
  Lmp l(extra);
  l.cmds(polydem_test::cube_faces(a, delta, dy, E, "0"));
  l.cmds({"group one id 1",
          std::string("compute cl all contact/polyhedron/local ") + COLUMNS,
          std::string("compute cl1 one contact/polyhedron/local ") + COLUMNS,
          "compute cs all contact/polyhedron", "compute cs1 one contact/polyhedron",
          "thermo_style custom step pe", "run 0"});
  const double A = a * (a - dy), V = A * delta, An = std::hypot(A, a * delta);
  const double R = a * std::cbrt(3.0 / (4.0 * M_PI)), K = 2.0 * E / R, Wp = K * std::cbrt(V);
  const auto rows = all_rows(l, "cl");
  ASSERT_EQ(rows.size(), 1u);
  const auto &r = rows[0];
  const double F = Wp * A, L = a;
  EXPECT_EQ(r[ID1], 1.0);
  EXPECT_EQ(r[ID2], 2.0);
  EXPECT_NEAR(r[VOL], V, 1e-10 * V);
  EXPECT_NEAR(r[VOLFRAC], V / (a * a * a), 1e-10 * V / (a * a * a));
  EXPECT_NEAR(r[AREA], An, 1e-10 * An);
  EXPECT_NEAR(r[FX], -Wp * A, 1e-10 * F);
  EXPECT_NEAR(r[FY], -Wp * a * delta, 1e-9 * F);
  EXPECT_NEAR(r[FZ], 0.0, 1e-10 * F);
  EXPECT_NEAR(r[NX], A / An, 1e-10);
  EXPECT_NEAR(r[NY], a * delta / An, 1e-9);
  EXPECT_NEAR(r[NZ], 0.0, 1e-10);
  EXPECT_NEAR(r[CX], 0.5 * (a - delta), 1e-10 * L);
  EXPECT_NEAR(r[CY], 0.5 * dy, 1e-10 * L);
  EXPECT_NEAR(r[CZ], 0.0, 1e-10 * L);
  EXPECT_NEAR(r[FN], Wp * An, 1e-10 * F);    // at rest: no damping
  EXPECT_EQ(r[FT], 0.0);                     // mu = 0
  const double W = 0.75 * K * std::pow(V, 4.0 / 3.0);
  EXPECT_NEAR(r[ENERGY], W, 1e-10 * W);
  EXPECT_NEAR(l.thermo("pe"), W, 1e-10 * W);
  const auto s = stats(l, "cs");
  EXPECT_EQ(s[0], 1.0);
  EXPECT_NEAR(s[1], V / (a * a * a), 1e-10 * V / (a * a * a));
  EXPECT_EQ(s[2], s[1]);
  EXPECT_EQ(s[3], 1.0);    // 2 contacts-ends / 2 atoms
  // group 'one' holds only atom 1: the contact is not between two members
  EXPECT_EQ(all_rows(l, "cl1").size(), 0u);
  const auto s1 = stats(l, "cs1");
  EXPECT_EQ(s1[0], 0.0);
  EXPECT_EQ(s1[3], 0.0);
}

}    // namespace

TEST(ContactComputes, FaceToFaceCubesPlain)
{
  face_to_face({});
}

TEST(ContactComputes, FaceToFaceCubesKokkos)
{
  if (!polydem_test::has_kokkos()) GTEST_SKIP() << "LAMMPS without the KOKKOS package";
  face_to_face(KK);
}

namespace {

// a dense periodic packing of cubes and dodecahedra (as test_pair_kokkos, 5x5x4
// sites), with friction, moving and spinning
std::vector<std::string> dense(const std::string &newton)
{
  return polydem_test::cube_dode_lattice(
      {
          "units lj",
          "atom_style polyhedron",
          "atom_modify map array",
          "comm_modify vel yes",
          "newton " + newton,
          "boundary p p p",
      },
      5, 5, 4,
      {
          "polyhedron_set group all omega 3.0 -1.0 2.0",
          "velocity all create 2.0 5151 loop geom",
          "pair_style polyhedron overlap/warn 1.0",
          "pair_coeff * * 1.0e4 0.3 0.7 0.5",
          "neighbor 0.01 bin",
          "neigh_modify every 1 delay 0 check yes",
          "fix 1 all nve/polyhedron",
          "timestep 1.0e-4",
          std::string("compute cl all contact/polyhedron/local ") + COLUMNS,
          "compute cs all contact/polyhedron",
          "thermo_style custom step pe c_cs[1] c_cs[3]",
          "thermo_modify norm no",
          "thermo 10",
      });
}

struct Dense {
  std::vector<std::vector<double>> rows;
  std::vector<double> stats;
  std::map<long, std::vector<double>> f;    // pair force per atom ID (plain only)
  double pe;
};

Dense run_dense(const std::vector<std::string> &extra, const std::string &newton, int steps)
{
  Lmp l(extra);
  l.cmds(dense(newton));
  l.cmd("run " + std::to_string(steps));
  Dense d;
  d.rows = all_rows(l, "cl");
  d.stats = stats(l, "cs");
  d.pe = l.thermo("pe");
  if (extra.empty()) {
    std::vector<double> mine;
    auto *a = l.lmp->atom;
    for (int i = 0; i < a->nlocal; i++)
      mine.insert(mine.end(), {(double) a->tag[i], a->f[i][0], a->f[i][1], a->f[i][2]});
    const std::vector<double> all = allgather(mine);
    for (size_t k = 0; k < all.size(); k += 4)
      d.f[(long) all[k]] = {all[k + 1], all[k + 2], all[k + 3]};
  }
  return d;
}

// the records account for the pair's per-atom forces, energy and statistics
void check_against_pair(const Dense &d)
{
  ASSERT_GT(d.rows.size(), 50u) << "the packing must be in contact";
  std::map<long, std::vector<double>> sum;
  double fmax = 0.0, W = 0.0, frac = 0.0, fracmax = 0.0;
  for (const auto &r : d.rows) {
    auto &a = sum[(long) r[ID1]], &b = sum[(long) r[ID2]];
    a.resize(3), b.resize(3);
    for (int k = 0; k < 3; k++) a[k] += r[FX + k], b[k] -= r[FX + k];
    W += r[ENERGY];
    frac += r[VOLFRAC];
    fracmax = std::max(fracmax, r[VOLFRAC]);
    EXPECT_LT(r[ID1], r[ID2]) << "a contact appears twice or with itself";
    EXPECT_NEAR(std::hypot(r[NX], r[NY], r[NZ]), 1.0, 1e-12);
  }
  for (auto &kv : d.f) fmax = std::max(fmax, std::hypot(kv.second[0], kv.second[1], kv.second[2]));
  for (size_t c = 1; c < d.rows.size(); c++)
    EXPECT_FALSE(d.rows[c][ID1] == d.rows[c - 1][ID1] && d.rows[c][ID2] == d.rows[c - 1][ID2])
        << "duplicate contact " << d.rows[c][ID1] << " " << d.rows[c][ID2];
  double worst = 0.0;
  for (auto &kv : d.f) {
    auto it = sum.find(kv.first);
    const std::vector<double> s = it == sum.end() ? std::vector<double>(3, 0.0) : it->second;
    for (int k = 0; k < 3; k++) worst = std::max(worst, std::fabs(s[k] - kv.second[k]));
  }
  std::printf("%zu contacts, max |sum of contact forces - pair force| / max|f| = %.3g\n",
              d.rows.size(), worst / fmax);
  EXPECT_LE(worst, 1e-12 * fmax);
  EXPECT_NEAR(W, d.pe, 1e-12 * d.pe);
  EXPECT_EQ(d.stats[0], (double) d.rows.size());
  EXPECT_NEAR(d.stats[1], frac / d.rows.size(), 1e-12 * d.stats[1]);
  EXPECT_EQ(d.stats[2], fracmax);
  EXPECT_NEAR(d.stats[3], 2.0 * d.rows.size() / 100.0, 1e-12);
}

}    // namespace

// each contact once over all ranks, and the pair's own forces and energy
TEST(ContactComputes, DensePackingNewtonOnAndOff)
{
  for (const char *newton : {"on", "off"}) {
    SCOPED_TRACE(std::string("newton ") + newton);
    const Dense d0 = run_dense({}, newton, 0);
    check_against_pair(d0);
    const Dense d = run_dense({}, newton, 20);
    check_against_pair(d);
  }
}

// /kk stores the same contacts with the same values (1e-12) as plain
TEST(ContactComputes, KokkosEqualsPlain)
{
  if (!polydem_test::has_kokkos()) GTEST_SKIP() << "LAMMPS without the KOKKOS package";
  const Dense p = run_dense({}, "off", 20), k = run_dense(KK, "off", 20);
  ASSERT_EQ(p.rows.size(), k.rows.size());
  double worst = 0.0, ftmax = 0.0;
  for (size_t c = 0; c < p.rows.size(); c++) {
    ASSERT_EQ(p.rows[c][ID1], k.rows[c][ID1]);
    ASSERT_EQ(p.rows[c][ID2], k.rows[c][ID2]);
    for (int col = VOL; col < NCOL; col++) {
      const double scale = std::max(std::fabs(p.rows[c][col]), 1e-300);
      worst = std::max(worst, std::fabs(p.rows[c][col] - k.rows[c][col]) / scale);
    }
    ftmax = std::max(ftmax, p.rows[c][FT]);
  }
  std::printf("/kk vs plain: %zu contacts, largest relative difference %.3g\n", p.rows.size(),
              worst);
  EXPECT_GT(ftmax, 0.0) << "friction must be active";
  EXPECT_LE(worst, 1e-12);
  for (int s = 0; s < 4; s++) EXPECT_NEAR(p.stats[s], k.stats[s], 1e-12 * std::fabs(p.stats[s]));
}

// without a compute contact/polyhedron/local the pair keeps summaries (the
// first CR_NSUMMARY fields of each record), and compute contact/polyhedron
// reports exactly what it reports from whole records (plain and /kk)
TEST(ContactComputes, SummariesGiveTheSameStatistics)
{
  std::vector<std::vector<std::string>> variants = {{}};
  if (polydem_test::has_kokkos()) variants.push_back(KK);
  for (const auto &extra : variants) {
    SCOPED_TRACE(extra.empty() ? "plain" : "kk");
    auto summary_only = dense("off");
    const auto cl = std::find_if(summary_only.begin(), summary_only.end(), [](const std::string &c) {
      return c.rfind("compute cl ", 0) == 0;
    });
    ASSERT_NE(cl, summary_only.end());
    summary_only.erase(cl);
    Lmp whole(extra), summary(extra);
    whole.cmds(dense("off"));
    summary.cmds(summary_only);
    whole.cmd("run 20");
    summary.cmd("run 20");
    const auto a = stats(whole, "cs"), b = stats(summary, "cs");
    ASSERT_GT(a[0], 50.0) << "the packing must be in contact";
    for (int k = 0; k < 4; k++) EXPECT_EQ(a[k], b[k]) << "statistic " << k + 1;
    // the records' memory: 4 doubles per contact instead of 19 (a margin for
    // the vectors' growth and this rank's share of the contacts on 2 ranks)
    const double saved =
        whole.lmp->force->pair->memory_usage() - summary.lmp->force->pair->memory_usage();
    EXPECT_GE(saved, 0.1 * a[0] * (polydem::CR_NFIELD - polydem::CR_NSUMMARY) * sizeof(double));
  }
}

// on a step no output asked for, the compute errors instead of reporting stale contacts
TEST(ContactComputes, StaleStepIsAnError)
{
  Lmp l;
  auto c = dense("on");
  c.resize(c.size() - 4);    // keep compute cl; no compute cs, no thermo using it
  ASSERT_NE(c.back().find("compute cl"), std::string::npos);
  l.cmds(c);
  l.cmds({"thermo_style custom step pe", "thermo 1000", "run 5"});
  void *p = lammps_extract_compute(l.lmp, "cl", LMP_STYLE_LOCAL, LMP_TYPE_ARRAY);
  char msg[512] = "";
  lammps_get_last_error_message(l.lmp, msg, sizeof(msg));
  if (lammps_version(l.lmp) > 20250204) {
    // LAMMPS 4 Jul 2026's Modify::addstep_compute schedules every
    // time-flagged compute on each output step, invoked before or not: the
    // pair stored the contacts of step 5 (the run's last, a thermo step),
    // which are current, so there is no stale step to refuse here
    EXPECT_NE(p, nullptr) << msg;
    EXPECT_EQ(std::string(msg), "") << msg;
    return;
  }
  EXPECT_EQ(p, nullptr);
  EXPECT_NE(std::string(msg).find("stored no contacts on step 5"), std::string::npos) << msg;
}

TEST(ContactComputes, BadInput)
{
  Lmp l;
  l.cmds(polydem_test::unit_box(1, {"polyhedron_shape c " + potentials() + "/cube.shape",
                                     "create_atoms 1 single 0.5 0.5 0.5", "comm_modify vel yes",
                                     "polyhedron_set atom 1 scale 0.01",
                                     "fix 1 all nve/polyhedron"}));
  l.expect_error("compute a all contact/polyhedron/local", "expected at least one keyword");
  l.expect_error("compute a all contact/polyhedron/local id1 bogus", "unknown keyword 'bogus'");
  l.expect_error("compute a all contact/polyhedron 1", "expected no arguments");
  l.cmds({"compute b all contact/polyhedron", "pair_style zero 0.1", "pair_coeff * *"});
  l.expect_error("run 0", "requires pair_style polyhedron");
}
