// pair_style polyhedron/kk against the plain pair_style polyhedron (issue 4,
// acceptance item 5): a dense periodic packing of a few hundred randomly
// oriented, spinning, moving cubes and dodecahedra on a simple cubic lattice
// with small random displacements, so that most neighbours overlap a little;
// friction on, so that the contact history matters. Per-atom forces and
// torques after "run 0", and positions, velocities, forces and torques after
// 100 steps, of "-k on -sf kk" (1 thread, _threads: 2) must agree with the plain
// styles to 1e-12 relative; so must the potential energy, the pressure (virial)
// and the number of contacts. Run on 1 rank and under mpirun -np 2 (both
// instances then use the same 2-rank decomposition).

#include "polydem_allgather.h"
#include "pair_restart_case.h"
#include "polydem_lmp.h"

#include "atom_kokkos.h"
#include "atom_masks.h"
#include "fix_neigh_history_kokkos.h"
#include "force.h"
#include "kokkos.h"
#include "modify.h"
#include "neigh_list_kokkos.h"
#include "neighbor.h"
#include "pair_polyhedron.h"
#include "pair_polyhedron_kokkos.h"
#include "polydem_launch_kokkos.h"

#include <Kokkos_Core.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

using polydem_test::Lmp;
using polydem_test::potentials;

namespace {

// newton off (the Kokkos default on GPUs); the NewtonOn tests run both
// styles with newton on
const std::vector<std::string> KK = polydem_test::kk_styles();

// sorting every 50 steps: atoms are permuted with their contact history.
// 8 x 8 x 6 lattice sites (spacing 1): half cubes (edge 0.95: in-radius
// 0.475, circumradius 0.82), half dodecahedra (edge 0.43: 0.48 / 0.60).
// Contact time (printed by the pair style) about 0.02, dt = 1e-4.
std::vector<std::string> setup(const std::string &newton = "off")
{
  return polydem_test::cube_dode_lattice(
      {
          "units lj",
          "atom_style polyhedron",
          "atom_modify map array sort 50 0.0",
          "comm_modify vel yes",
          "newton " + newton,
          "boundary p p p",
      },
      8, 8, 6,
      {
          "variable m0 atom id%4==0",
          "variable m1 atom id%4==1",
          "variable m2 atom id%4==2",
          "group g0 variable m0",
          "group g1 variable m1",
          "group g2 variable m2",
          "polyhedron_set group g0 omega 3.0 -1.0 2.0",
          "polyhedron_set group g1 omega -2.0 4.0 0.5",
          "polyhedron_set group g2 omega 0.7 1.5 -3.5",
          "velocity all create 2.0 5151 loop geom",
          "pair_style polyhedron overlap/warn 1.0",
          "pair_coeff * * 1.0e4 0.3 0.7 0.5",
          "pair_coeff 1 2 0.8 0.3",
          "neighbor 0.01 bin",
          "neigh_modify every 1 delay 0 check yes",
          "fix 1 all nve/polyhedron",
          "timestep 1.0e-4",
          "thermo_style custom step pe ke press",
          "thermo 50",
      });
}

// per atom, sorted by ID, gathered to every rank: id, x, v, f, torque
constexpr int REC = 1 + 3 + 3 + 3 + 3;

std::vector<double> gather(Lmp &l)
{
  auto *a = l.lmp->atom;
  if (l.lmp->kokkos) ((LAMMPS_NS::AtomKokkos *) a)->sync(LAMMPS_NS::Host, ALL_MASK);
  std::vector<double> mine;
  for (int i = 0; i < a->nlocal; i++) {
    mine.push_back((double) a->tag[i]);
    for (int k = 0; k < 3; k++) mine.push_back(a->x[i][k]);
    for (int k = 0; k < 3; k++) mine.push_back(a->v[i][k]);
    for (int k = 0; k < 3; k++) mine.push_back(a->f[i][k]);
    for (int k = 0; k < 3; k++) mine.push_back(a->torque[i][k]);
  }
  const std::vector<double> all = polydem_test::allgather(mine);
  const int total = (int) all.size();
  std::vector<std::vector<double>> recs;
  for (int i = 0; i < total; i += REC) recs.emplace_back(all.begin() + i, all.begin() + i + REC);
  std::sort(recs.begin(), recs.end());
  std::vector<double> out;
  for (auto &r : recs) out.insert(out.end(), r.begin(), r.end());
  return out;
}

// |a - b|^2 and |b|^2 of the 3-vectors at field offset off of record r
std::pair<double, double> diff2_norm2(const std::vector<double> &a, const std::vector<double> &b,
                                      size_t r, int off)
{
  double d2 = 0.0, b2 = 0.0;
  for (int k = 0; k < 3; k++) {
    const double d = a[r + off + k] - b[r + off + k];
    d2 += d * d;
    b2 += b[r + off + k] * b[r + off + k];
  }
  return {d2, b2};
}

// max over atoms of |a - b| (3-vector at field offset off) divided by the
// largest |b| of that field over all atoms
double normwise(const std::vector<double> &a, const std::vector<double> &b, int off)
{
  double dmax = 0.0, bmax = 0.0;
  for (size_t r = 0; r < b.size(); r += REC) {
    const auto [d2, b2] = diff2_norm2(a, b, r, off);
    dmax = std::max(dmax, std::sqrt(d2));
    bmax = std::max(bmax, std::sqrt(b2));
  }
  return bmax > 0.0 ? dmax / bmax : dmax;
}

// max over atoms with |b| > 1e-6 max|b| of |a - b| / |b|
double peratom(const std::vector<double> &a, const std::vector<double> &b, int off)
{
  double bmax = 0.0;
  for (size_t r = 0; r < b.size(); r += REC)
    bmax = std::max(bmax, std::sqrt(diff2_norm2(a, b, r, off).second));
  double worst = 0.0;
  for (size_t r = 0; r < b.size(); r += REC) {
    const auto [d2, b2] = diff2_norm2(a, b, r, off);
    if (std::sqrt(b2) > 1e-6 * bmax) worst = std::max(worst, std::sqrt(d2 / b2));
  }
  return worst;
}

double contacts(Lmp &l)
{
  auto *p = dynamic_cast<LAMMPS_NS::PairPolyhedron *>(l.lmp->force->pair);
  return p ? p->counters[polydem::PP_CONTACTS] : -1.0;
}

int me()
{
  int r;
  MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}

// loose: a factor on the force and torque tolerances
void compare(Lmp &plain, Lmp &kk, const char *when, bool positions, double loose = 1.0)
{
  const auto a = gather(kk), b = gather(plain);
  ASSERT_EQ(a.size(), b.size());
  ASSERT_GT(b.size(), 0u);
  for (size_t r = 0; r < b.size(); r += REC) ASSERT_EQ(a[r], b[r]) << "atom IDs differ";
  const double ef = normwise(a, b, 7), et = normwise(a, b, 10);
  const double pf = peratom(a, b, 7), pt = peratom(a, b, 10);
  const double ex = normwise(a, b, 1) / 8.0, ev = normwise(a, b, 4);
  const double pe_p = plain.thermo("pe"), pe_k = kk.thermo("pe");
  const double pr_p = plain.thermo("press"), pr_k = kk.thermo("press");
  if (me() == 0)
    std::printf("[%s] %zu atoms, contacts plain %.0f kk %.0f; max rel. diff kk vs plain: "
                "force %.3g (per atom %.3g), torque %.3g (per atom %.3g), x %.3g, v %.3g, "
                "pe %.3g, press %.3g\n",
                when, b.size() / REC, contacts(plain), contacts(kk), ef, pf, et, pt, ex, ev,
                std::fabs(pe_k - pe_p) / std::fabs(pe_p), std::fabs(pr_k - pr_p) / std::fabs(pr_p));
  EXPECT_LE(ef, 1e-12 * loose);
  EXPECT_LE(et, 1e-12 * loose);
  EXPECT_LE(pf, 1e-10 * loose);
  EXPECT_LE(pt, 1e-10 * loose);
  if (positions) {
    // with threads the force sums are reordered from run to run (atomics)
    // and their round-off grows over a run's 100 steps (up to 1.03e-12 in v
    // seen for the composites on 2 threads); one thread repeats exactly
    const double tol = polydem_test::kk_threads() > 1 ? 1e-11 : 1e-12;
    EXPECT_LE(ex, tol);
    EXPECT_LE(ev, tol);
  }
  EXPECT_GT(contacts(plain), 0.5 * b.size() / REC);
  EXPECT_EQ(contacts(plain), contacts(kk));
  EXPECT_NEAR(pe_k, pe_p, 1e-12 * std::fabs(pe_p));
  EXPECT_NEAR(pr_k, pr_p, 1e-12 * std::fabs(pr_p));
  // no kernel failures in either run
  for (Lmp *l : {&plain, &kk}) {
    auto *p = dynamic_cast<LAMMPS_NS::PairPolyhedron *>(l->lmp->force->pair);
    ASSERT_NE(p, nullptr);
    EXPECT_EQ(p->counters[polydem::PP_OVERFLOW], 0.0);
    EXPECT_EQ(p->counters[polydem::PP_DEGENERATE], 0.0);
  }
}

// the scene of setup() and `extra` in both styles, 100 steps on, compared
// (positions included)
void expect_run_alike(const std::vector<std::string> &extra, const char *when)
{
  Lmp plain, kk(KK);
  for (Lmp *l : {&plain, &kk}) {
    l->cmds(setup());
    l->cmds(extra);
  }
  plain.cmd("run 100");
  kk.cmd("run 100");
  compare(plain, kk, when, true);
}

}    // namespace

TEST(PairKokkos, DensePackingMatchesPlain)
{
  Lmp plain, kk(KK);
  plain.cmds(setup());
  kk.cmds(setup());
  EXPECT_EQ(std::string(kk.lmp->force->pair_style), "polyhedron/kk");
  auto both = [&](const std::string &run, const char *when) {
    plain.cmd(run);
    kk.cmd(run);
    compare(plain, kk, when, true);
  };
  both("run 0", "run 0");
  // the history crosses a run boundary (post_run -> setup_post_neighbor)
  both("run 5", "run 5");
  both("run 0", "run 5 + run 0");
  // and reneighborings inside the run (skin 0.01: every few tens of steps)
  both("run 100", "run 100");
  EXPECT_GE(kk.lmp->neighbor->ncalls, 2) << "no reneighboring during the run";
  if (me() == 0)
    std::printf("[run 100] neighbor list builds: plain %d kk %d\n", plain.lmp->neighbor->ncalls,
                kk.lmp->neighbor->ncalls);
}

// rolling resistance and cohesion (issue 30) on every pair: the rolling
// torque history (8 values per pair) follows the pairs through
// reneighborings alike
TEST(PairKokkos, RollingResistanceMatchesPlain)
{
  expect_run_alike({"pair_coeff * * 1.0e4 0.3 0.7 0.5 rolling 0.2 cohesion 50"},
                   "rolling, run 100");
}

// a quarter of the grains spheres (issue 29): sphere-polyhedron and
// sphere-sphere contacts by their overlap volume, alike in both styles
TEST(PairKokkos, SpheresAmongPolyhedraMatchPlain)
{
  expect_run_alike({"polyhedron_shape ball ellipsoid 0.47 0.47 0.47",
                    "polyhedron_set group g1 shape ball density 1.0"},
                   "spheres, run 100");
}

// ellipsoids of unequal semi-axes and spheres among the polyhedra (issue
// 29): ellipsoid pairs by the algebraic contact (pair_coeff ... ellipsoid
// k_n; the unlike type pair with a k_n of its own), the rest by their
// overlap volume, alike in both styles
TEST(PairKokkos, EllipsoidsAmongPolyhedraMatchPlain)
{
  expect_run_alike({"polyhedron_shape ball ellipsoid 0.47 0.47 0.47",
                    "polyhedron_shape egg ellipsoid 0.55 0.42 0.36",
                    "polyhedron_set group g1 shape egg density 1.0",
                    "polyhedron_set group g2 shape ball density 1.0",
                    "pair_coeff * * 1.0e4 0.3 0.7 0.5 ellipsoid 4000",
                    "pair_coeff 1 2 0.8 0.3 ellipsoid 3000"},
                   "ellipsoids, run 100");
}

// a third of the grains composites (issue 29): two cubes and a sphere, part
// contacts with keyed histories, the parts' views on the device
TEST(PairKokkos, CompositesMatchPlain)
{
  expect_run_alike({"polyhedron_shape ball ellipsoid 0.58 0.58 0.58",
                    "polyhedron_shape dumb composite part cube -0.4 0 0 part cube 0.4 0 0 quat "
                    "0.92 0.38 0 0 part ball 0 1.3 0",
                    "polyhedron_set group g1 shape dumb scale 0.4 density 1.0"},
                   "composites, run 100");
}

// all grains spheres (then a quarter spheres among polyhedra: sphere-
// polyhedron and polyhedron-polyhedron bridges, with a viscous part) joined by
// liquid bridges: the bridged pairs that no
// longer overlap are kept by their touch flags alike in both styles
TEST(PairKokkos, LiquidBridgesMatchPlain)
{
  // all spheres; a quarter spheres among the cubes and dodecahedra (group
  // g0): sphere-polyhedron and polyhedron-polyhedron bridges
  for (const std::string group : {"all", "g0"}) {
    Lmp plain, kk(KK), dry;
    for (Lmp *l : {&plain, &kk, &dry}) {
      l->cmds(setup());
      l->cmds({"polyhedron_shape ball ellipsoid 0.58 0.58 0.58",
               "polyhedron_set group " + group + " shape ball density 1.0", "neighbor 0.15 bin"});
    }
    // (the mixed scene's bridges with their viscous part)
    const std::string viscous = group == "g0" ? " viscous 0.05 0.01" : "";
    for (Lmp *l : {&plain, &kk})
      l->cmd("pair_coeff * * 1.0e4 0.3 0.7 0.5 bridge 1e-3 10 10" + viscous);
    for (Lmp *l : {&plain, &kk, &dry}) l->cmd("run 100");
    // (the polyhedron pairs' bridges act along GJK's and EPA's converged
    // simplices, whose round-off of 1e-16 of the size the dense lattice's
    // 100 steps amplify: torques up to 1.2e-12, forces 5e-13 here)
    compare(plain, kk, group == "all" ? "liquid bridges, run 100" :
                                        "liquid bridges of spheres and polyhedra, run 100", true,
            group == "all" ? 1.0 : 10.0);
    // the bridges act: the run differs from the one without
    EXPECT_NE(plain.thermo("pe"), dry.thermo("pe"));
  }
}

// liquid bridges between the parts of composites (dumbbells of two spheres
// in group g1) and the other grains: the part slots of bridged part pairs
// that no longer overlap are kept alike in both styles
TEST(PairKokkos, CompositeBridgesMatchPlain)
{
  Lmp plain, kk(KK), dry;
  for (Lmp *l : {&plain, &kk, &dry}) {
    l->cmds(setup());
    l->cmds({"polyhedron_shape ball ellipsoid 0.58 0.58 0.58",
             "polyhedron_shape dumb composite part ball -0.7 0 0 part ball 0.7 0 0",
             "polyhedron_set group g0 shape ball density 1.0",
             "polyhedron_set group g1 shape dumb scale 0.6 density 1.0", "neighbor 0.15 bin"});
  }
  for (Lmp *l : {&plain, &kk}) l->cmd("pair_coeff * * 1.0e4 0.3 0.7 0.5 bridge 1e-3 10 10");
  for (Lmp *l : {&plain, &kk, &dry}) l->cmd("run 100");
  compare(plain, kk, "liquid bridges of composites' parts, run 100", true, 10.0);
  EXPECT_NE(plain.thermo("pe"), dry.thermo("pe"));
}

// two spheres collide, form a liquid bridge, separate with it stretched
// (no overlap: the pair is kept by its touch flag, which the history fix
// keeps over a reneighboring beyond the size list's reach) and rupture it:
// /kk equals plain bit for bit at every stage
TEST(PairKokkos, LiquidBridgeFormsStretchesAndRupturesAlike)
{
  Lmp plain, kk(KK);
  for (Lmp *l : {&plain, &kk})
    l->cmds({"units si", "atom_style polyhedron", "atom_modify map array", "boundary f f f",
             "newton off", "comm_modify vel yes",
             "region box block -0.01 0.01 -0.01 0.01 -0.01 0.01", "create_box 1 box",
             "polyhedron_shape s1 ellipsoid 0.001 0.001 0.001",
             "polyhedron_shape s2 ellipsoid 0.0015 0.0015 0.0015", "create_atoms 1 single 0 0 0",
             "create_atoms 1 single 0.00255 0 0", "polyhedron_set atom 1 shape s1",
             "polyhedron_set atom 2 shape s2", "polyhedron_set group all density 2500",
             "pair_style polyhedron", "pair_coeff * * 1e7 0.3 0.7 0.3 bridge 1e-11 0.072 20",
             "neighbor 3e-4 bin", "neigh_modify every 1 delay 0 check no",
             "velocity all set 0 0 0", "set atom 1 vx 0.1 vy 0.01", "set atom 2 vx -0.05",
             "fix 1 all nve/polyhedron", "timestep 1e-7", "run 0"});
  int stretched = 0;
  for (int k = 0; k < 40; k++) {
    plain.cmd("run 500 pre no post no");
    kk.cmd("run 500 pre no post no");
    auto *a = plain.lmp->atom;
    const double gap = a->x[a->map(2)][0] - a->x[a->map(1)][0] - 0.0025;
    if (gap > 0.0 && a->f[a->map(1)][0] > 0.0) stretched++;
    for (int id : {1, 2})
      for (int d = 0; d < 3; d++) {
        ASSERT_EQ(kk.lmp->atom->x[kk.lmp->atom->map(id)][d], a->x[a->map(id)][d]) << k;
        ASSERT_EQ(kk.lmp->atom->v[kk.lmp->atom->map(id)][d], a->v[a->map(id)][d]) << k;
      }
  }
  EXPECT_GT(stretched, 0) << "the bridge must act across a gap";
}

// the same style run as /kk/host must give the same numbers
TEST(PairKokkos, HostVariantMatchesPlain)
{
  Lmp plain, kk(polydem_test::kk({"-pk", "kokkos", "newton", "off"}));
  plain.cmds(setup());
  auto s = setup();
  for (auto &c : s) {
    if (c == "atom_style polyhedron") c = "atom_style polyhedron/kk";
    if (c == "pair_style polyhedron overlap/warn 1.0")
      c = "pair_style polyhedron/kk/host overlap/warn 1.0";
    if (c == "fix 1 all nve/polyhedron") c = "fix 1 all nve/polyhedron/kk";
  }
  s.push_back("run_style verlet/kk");
  kk.cmds(s);
  plain.cmd("run 20");
  kk.cmd("run 20");
  compare(plain, kk, "kk/host run 20", true);
}

// newton on: each pair once, the ghosts' forces and torques sent back, the
// histories of pairs with a ghost partner sent to its owner at each
// reneighboring (FixNeighHistoryPolyhedronKokkos::pre_exchange_newton);
// against plain with newton on, through runs, reneighborings and sorting.
// Also on 2 ranks (ctest), where pairs cross the subdomain boundary.
TEST(PairKokkos, NewtonOnMatchesPlain)
{
  Lmp plain, kk(polydem_test::kk_styles("on"));
  plain.cmds(setup("on"));
  kk.cmds(setup("on"));
  ASSERT_EQ(kk.lmp->force->newton_pair, 1);
  auto both = [&](const std::string &run, const char *when) {
    plain.cmd(run);
    kk.cmd(run);
    compare(plain, kk, when, true);
  };
  both("run 0", "newton on, run 0");
  both("run 5", "newton on, run 5");
  both("run 300", "newton on, run 300");
  EXPECT_GE(kk.lmp->neighbor->ncalls, 4) << "no reneighboring during the run";
}

// rolling resistance (8 history values per pair) with newton on
TEST(PairKokkos, NewtonOnRollingMatchesPlain)
{
  Lmp plain, kk(polydem_test::kk_styles("on"));
  for (Lmp *l : {&plain, &kk}) {
    l->cmds(setup("on"));
    l->cmd("pair_coeff * * 1.0e4 0.3 0.7 0.5 rolling 0.2 cohesion 50");
  }
  plain.cmd("run 200");
  kk.cmd("run 200");
  compare(plain, kk, "newton on, rolling, run 200", true);
}

// overlap workspaces per pair slot: sized by the largest face count present
TEST(PairKokkos, WorkspaceFollowsFaceCount)
{
  using PK = LAMMPS_NS::PairPolyhedronKokkos<LMPDeviceType>;
  EXPECT_EQ(PK::workspace_max_faces(6), 16);
  EXPECT_EQ(PK::workspace_max_faces(12), 16);
  EXPECT_EQ(PK::workspace_max_faces(17), 32);
  EXPECT_EQ(PK::workspace_max_faces(40), 64);
  EXPECT_EQ(PK::workspace_max_faces(128), 128);
  double last = 0.0;
  for (int mf : {16, 32, 64, 128}) {
    const double b = PK::workspace_bytes(mf);
    if (me() == 0) std::printf("[workspace] MaxFaces %3d: %.0f bytes per pair slot\n", mf, b);
    EXPECT_GT(b, last);
    last = b;
  }
}

// the Kokkos list and the history arrays sized by it follow the packing: a
// list not yet built starts 2 wide, its first build widens it to 1.2 x the
// widest row (LAMMPS's npair_kokkos.cpp), not to LAMMPS's 16
TEST(PairKokkos, NeighborListAndHistoryWidthFollowThePacking)
{
  // dodecahedra on a simple cubic lattice (bench/in.dodeca_dense, 6^3):
  // 3 half-list neighbors per atom, a few more where displaced
  Lmp kk(KK);
  kk.cmds({"units lj", "atom_style polyhedron", "atom_modify map array", "comm_modify vel yes",
           "newton off", "boundary p p p", "lattice sc 1.0", "region box block 0 6 0 6 0 6",
           "create_box 1 box", "polyhedron_shape dode " + polydem_test::potentials() +
               "/dodecahedron.shape",
           "create_atoms 1 box", "displace_atoms all random 0.04 0.04 0.04 4242 units box",
           "polyhedron_set type 1 shape dode scale 0.4 density 1.0 quat/random 18",
           "pair_style polyhedron", "pair_coeff * * 1.0e4 0.3 0.7 0.5", "neighbor 0.02 bin",
           "fix 1 all nve/polyhedron", "timestep 1.0e-4"});
  kk.cmd("run 0");
  auto *list = dynamic_cast<LAMMPS_NS::NeighListKokkos<LMPDeviceType> *>(kk.lmp->force->pair->list);
  ASSERT_NE(list, nullptr);
  auto ilist = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), list->d_ilist);
  auto numneigh = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), list->d_numneigh);
  int widest = 0;
  for (int ii = 0; ii < list->inum; ii++) widest = std::max(widest, numneigh(ilist(ii)));
  const int width = (int) list->d_neighbors.extent(1);
  if (me() == 0)
    std::printf("[list] widest row %d, list width %d (LAMMPS's default 16)\n", widest, width);
  ASSERT_GT(widest, 2) << "the scene must outgrow the initial width";
  EXPECT_EQ(width, (int) (1.2 * widest));
  ASSERT_LT(widest, 13) << "the scene must show a width below LAMMPS's 16";
  LAMMPS_NS::FixNeighHistoryKokkos<LMPDeviceType> *hist = nullptr;
  for (int f = 0; f < kk.lmp->modify->nfix; f++)
    if (!hist)
      hist = dynamic_cast<LAMMPS_NS::FixNeighHistoryKokkos<LMPDeviceType> *>(kk.lmp->modify->fix[f]);
  ASSERT_NE(hist, nullptr);
  EXPECT_EQ((int) hist->k_firstflag.extent(1), width);
  EXPECT_EQ((int) hist->k_firstvalue.extent(1), width * polydem::CONTACT_HIST);
  // and the run continues to match plain (DensePackingMatchesPlain)
}

// Kokkos bins span the neighbor cutoff (LAMMPS's own choice on GPUs) unless
// the user chose a bin size; the choice follows a changed skin (and the run
// goes on) and goes with the /kk pair style
TEST(PairKokkos, BinsSpanTheNeighborCutoff)
{
  const std::vector<std::string> scene = {
      "units lj", "atom_style polyhedron", "atom_modify map array", "comm_modify vel yes",
      "newton off", "boundary p p p", "lattice sc 1.0", "region box block 0 6 0 6 0 6",
      "create_box 1 box", "polyhedron_shape dode " + polydem_test::potentials() +
          "/dodecahedron.shape",
      "create_atoms 1 box", "polyhedron_set type 1 shape dode scale 0.4 density 1.0",
      "pair_style polyhedron", "pair_coeff * * 1.0e4 0.3 0.7 0.5", "neighbor 0.02 bin",
      "fix 1 all nve/polyhedron", "timestep 1.0e-4"};
  Lmp kk(KK);
  kk.cmds(scene);
  kk.cmd("run 0");
  LAMMPS_NS::Neighbor *nb = kk.lmp->neighbor;
  const double cut1 = nb->cutneighmax;
  ASSERT_GT(cut1, 0.0);
  EXPECT_EQ(nb->binsizeflag, 1);
  EXPECT_GE(nb->binsize_user, cut1);
  EXPECT_NEAR(nb->binsize_user, cut1, 1e-9 * cut1);
  // a larger skin: the bins follow on the next run (with bins left at the
  // old cutoff, LAMMPS's Kokkos build would overrun its grown stencil)
  kk.cmd("neighbor 0.1 bin");
  kk.cmd("run 0");
  EXPECT_NEAR(nb->cutneighmax - cut1, 0.08, 1e-12);
  EXPECT_GE(nb->binsize_user, nb->cutneighmax);
  EXPECT_NEAR(nb->binsize_user, nb->cutneighmax, 1e-9 * cut1);
  // a /kk style's choice goes with it
  kk.cmd("pair_style none");
  EXPECT_EQ(nb->binsizeflag, 0);
  // the user's bin size is kept (set before the first run: LAMMPS's Kokkos
  // neighbor build does not survive a stencil grown between runs)
  Lmp kk2(KK);
  kk2.cmds(scene);
  kk2.cmd("neigh_modify binsize 0.3");
  kk2.cmd("run 0");
  EXPECT_DOUBLE_EQ(kk2.lmp->neighbor->binsize_user, 0.3);
  EXPECT_EQ(kk2.lmp->neighbor->binsizeflag, 1);
}

// per-atom energy and virial (eflag_atom, vflag_atom paths): sums and maxima
TEST(PairKokkos, PerAtomEnergyAndVirialMatchPlain)
{
  Lmp plain, kk(KK);
  const std::vector<std::string> extra = {
      "compute pa all pe/atom pair",
      "compute sa all stress/atom NULL pair",
      "compute r all reduce sum c_pa c_sa[1] c_sa[2] c_sa[3] c_sa[4] c_sa[5] c_sa[6]",
      "compute m all reduce max c_pa c_sa[1] c_sa[2] c_sa[3] c_sa[4] c_sa[5] c_sa[6]",
      "thermo_style custom step pe press c_r[*] c_m[*]",
      "thermo 10"};
  for (Lmp *l : {&plain, &kk}) {
    l->cmds(setup());
    l->cmds(extra);
  }
  for (int n : {0, 10}) {
    plain.cmd("run " + std::to_string(n));
    kk.cmd("run " + std::to_string(n));
    for (const char *id : {"r", "m"}) {
      auto *a = (double *) lammps_extract_compute(plain.lmp, id, LMP_STYLE_GLOBAL, LMP_TYPE_VECTOR);
      auto *b = (double *) lammps_extract_compute(kk.lmp, id, LMP_STYLE_GLOBAL, LMP_TYPE_VECTOR);
      ASSERT_NE(a, nullptr);
      ASSERT_NE(b, nullptr);
      double worst = 0.0;
      for (int k = 0; k < 7; k++) {
        EXPECT_NEAR(b[k], a[k], 1e-12 * std::fabs(a[k]) + 1e-300) << id << "[" << k + 1 << "]";
        worst = std::max(worst, std::fabs(b[k] - a[k]) / std::fabs(a[k]));
      }
      if (me() == 0)
        std::printf("[per-atom] run %d, reduce %s of pe/atom, stress/atom: max rel. diff %.3g\n", n,
                    std::strcmp(id, "r") == 0 ? "sum" : "max", worst);
    }
    // the sum of pe/atom is the pair energy
    auto *a = (double *) lammps_extract_compute(kk.lmp, "r", LMP_STYLE_GLOBAL, LMP_TYPE_VECTOR);
    const double natoms = (double) kk.lmp->atom->natoms;
    EXPECT_NEAR(a[0] / natoms, kk.thermo("pe"), 1e-12 * std::fabs(kk.thermo("pe")));
  }
}

// Restart of a /kk run with loaded contacts (tangential history on the
// device), newton pair "off" or "on": write_restart from a -sf kk run,
// read_restart with -sf kk, continue == uninterrupted /kk run, bit for bit;
// and the /kk run equals the plain one (same newton setting) to 1e-12.
//
// With threads (POLYDEM_KK_THREADS > 1) the atomics add each contact's force
// and torque in an order that changes from run to run, so two runs agree
// only to round-off: the angular momentum is compared norm-wise. The cube
// sticks: its in-plane components (1e-9 of |L| = 1.7e-6) are what is left of
// cancelling contact torques, and a relative tolerance on them would measure
// the cancellation. Each step's torque differs by ~1e-16 of the contact
// torques; over the 5000 stick-slip steps this grew to at most 1.3e-9 |L|
// (2 threads, 40 runs); the bound is 1e-7 |L|. Serially the order is fixed:
// bit for bit, and 1e-12 of each component against plain.
static void expect_restart_keeps_history(const std::string &newton)
{
  auto sync = [](Lmp &l) {
    ((LAMMPS_NS::AtomKokkos *) l.lmp->atom)->sync(LAMMPS_NS::Host, ALL_MASK);
  };
  const std::string tmp = ::testing::TempDir() + "polydem_pair_kk_restart_" + newton;
  const auto kk =
      polydem_test::pair_restart_case(polydem_test::kk_styles(newton), tmp + ".bin", sync, newton);
  const bool threads = polydem_test::kk_threads() > 1;
  const double lnorm =
      std::sqrt(kk.ref[3] * kk.ref[3] + kk.ref[4] * kk.ref[4] + kk.ref[5] * kk.ref[5]);
  for (int k = 0; k < 6; k++) {
    if (!threads)
      EXPECT_EQ(kk.got[k], kk.ref[k]) << "component " << k;
    else
      EXPECT_NEAR(kk.got[k], kk.ref[k], k < 3 ? 1e-12 * 0.3 : 1e-7 * lnorm) << "component " << k;
  }
  // plain with the same newton setting (newton on sums in another order and,
  // over these 5000 stick-slip steps, differs by 1e-14 in angular momenta of
  // 1e-11 on 2 ranks)
  const auto plain =
      polydem_test::pair_restart_case({}, tmp + "_plain.bin", [](Lmp &) {}, newton);
  double worst = 0.0;
  for (int k = 0; k < 3; k++) {
    EXPECT_NEAR(kk.ref[k], plain.ref[k], 1e-12 * 0.3) << "position " << k;
    const double tol = threads ? 1e-7 * lnorm : 1e-12 * (std::fabs(plain.ref[3 + k]) + 1e-30);
    EXPECT_NEAR(kk.ref[3 + k], plain.ref[3 + k], tol) << "angular momentum " << k;
    worst = std::max(worst, std::fabs(kk.ref[3 + k] - plain.ref[3 + k]));
  }
  if (me() == 0)
    std::printf("[restart, newton %s] |L| %.3g, max |L_k(kk) - L_k(plain)| %.3g = %.3g |L|\n",
                newton.c_str(), lnorm, worst, worst / lnorm);
}

// Also run on 2 ranks (ctest), where the cube's contact partners lie on both
// sides of the subdomain boundary.
TEST(PairKokkos, RestartKeepsContactHistory)
{
  expect_restart_keeps_history("off");
}

// the same with newton on: the cube's contact histories reach their owners
// by reverse communication at each reneighboring (on 2 ranks from the other
// side of the subdomain boundary), and the restart file keeps them
TEST(PairKokkos, NewtonOnRestartKeepsContactHistory)
{
  expect_restart_keeps_history("on");
}

// A plain run's restart file continued by /kk keeps the contact history:
// the stick-slip history of RestartKeepsContactHistory decides where the cube
// ends, so the /kk continuation must equal the uninterrupted plain run as
// closely as /kk equals plain there (1e-12 serially; threads: 1e-7 |L|).
TEST(PairKokkos, PlainRestartFileContinuedByKokkos)
{
  auto sync = [](Lmp &l) {
    if (l.lmp->kokkos) ((LAMMPS_NS::AtomKokkos *) l.lmp->atom)->sync(LAMMPS_NS::Host, ALL_MASK);
  };
  const std::vector<std::string> kk_args = KK;
  const auto mixed = polydem_test::pair_restart_case(
      {}, ::testing::TempDir() + "polydem_pair_plain_to_kk.bin", sync, "off", &kk_args);
  const bool threads = polydem_test::kk_threads() > 1;
  const double lnorm = std::sqrt(mixed.ref[3] * mixed.ref[3] + mixed.ref[4] * mixed.ref[4] +
                                 mixed.ref[5] * mixed.ref[5]);
  for (int k = 0; k < 3; k++) {
    EXPECT_NEAR(mixed.got[k], mixed.ref[k], 1e-12 * 0.3) << "position " << k;
    const double tol = threads ? 1e-7 * lnorm : 1e-12 * (std::fabs(mixed.ref[3 + k]) + 1e-30);
    EXPECT_NEAR(mixed.got[3 + k], mixed.ref[3 + k], tol) << "angular momentum " << k;
  }
}

// polydem_launch_kokkos.h: on one host thread the kernels run in place, with
// the results of Kokkos's own launch bit for bit (the same items in the same
// order: a sum of 10,000 terms of mixed magnitude, whose value depends on
// the order); with N threads they are Kokkos's launches, on N threads.
namespace {
struct LaunchSum {
  typedef double value_type;
  KOKKOS_INLINE_FUNCTION void operator()(const int i, double &s) const
  {
    s += 1.0 / (1.0 + i) + ((i % 7) ? 1e-9 * i : 1e3);
  }
};
struct LaunchScan {
  typedef long value_type;
  Kokkos::View<long *, Kokkos::DefaultExecutionSpace> first;
  KOKKOS_INLINE_FUNCTION void operator()(const int i, long &partial, const bool final) const
  {
    if (final) first(i) = partial;
    partial += i % 5;
  }
};

// how many distinct threads run the items of launch(n, item) (UniqueToken
// ids; each id is held by one thread at a time, so the stores into seen()
// do not race), and whether each item ran once
template <class Launch> int distinct_threads(const Launch &launch, int n, bool &each_once)
{
  using Exec = Kokkos::DefaultExecutionSpace;
  Kokkos::Experimental::UniqueToken<Exec> token;
  Kokkos::View<int *, Exec> seen("seen", token.size()), done("done", n);
  launch(n, KOKKOS_LAMBDA(const int i) {
    const int id = token.acquire();
    seen(id) = 1;
    done(i) += 1;
    token.release(id);
  });
  Kokkos::fence();
  auto hs = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), seen);
  auto hd = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), done);
  int distinct = 0, once = 0;
  for (int i = 0; i < (int) hs.extent(0); i++) distinct += hs(i);
  for (int i = 0; i < n; i++) once += hd(i) == 1;
  each_once = once == n;
  return distinct;
}
}    // namespace

// The *_threads entries (POLYDEM_KK_THREADS=N, issue 19) must really run N
// threads: Kokkos's concurrency is N, and a parallel_for hands its work to N
// distinct threads; so does polydem_kk::for_range, and the launch helpers
// give Kokkos's results.
TEST(PairKokkos, RunsTheRequestedThreads)
{
  Lmp kk(KK);
  kk.cmds(setup());
  kk.cmd("run 0");
  using Exec = Kokkos::DefaultExecutionSpace;
  const int want = polydem_test::kk_threads();
  EXPECT_EQ(Exec::concurrency(), want) << Exec::name();
  EXPECT_EQ(polydem_kk::one_host_thread<Exec>(), want == 1);
  bool once = false;
  const int distinct = distinct_threads(
      [](int n, const auto &item) { Kokkos::parallel_for(Kokkos::RangePolicy<Exec>(0, n), item); },
      1 << 20, once);
  EXPECT_TRUE(once);
  if (me() == 0)
    std::printf("[threads] %s: concurrency %d, %d distinct threads ran\n", Exec::name(),
                Exec::concurrency(), distinct);
  EXPECT_EQ(distinct, want);
  EXPECT_EQ(distinct_threads([](int n, const auto &item) { polydem_kk::for_range<Exec>(0, n, item); },
                             10000, once),
            want);
  EXPECT_TRUE(once);

  const int n = 10000;
  double in_place = -1.0, kokkos = -2.0;
  polydem_kk::reduce_range<Exec>(0, n, LaunchSum(), in_place);
  Kokkos::parallel_reduce(Kokkos::RangePolicy<Exec>(0, n), LaunchSum(), kokkos);
  if (want == 1)
    EXPECT_EQ(in_place, kokkos);    // the same sum in the same order
  else
    EXPECT_NEAR(in_place, kokkos, 1e-12 * std::fabs(kokkos));

  LaunchScan scan;
  scan.first = Kokkos::View<long *, Exec>("first", n);
  long total = -1;
  polydem_kk::scan_range<Exec>(0, n, scan, total);
  auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), scan.first);
  long expect = 0;
  int wrong = 0;
  for (int i = 0; i < n; i++) {
    wrong += h(i) != expect;
    expect += i % 5;
  }
  EXPECT_EQ(wrong, 0);
  EXPECT_EQ(total, expect);
}
