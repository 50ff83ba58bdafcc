// pair_style ellipsoid/kk (Kokkos) against plain pair_style ellipsoid,
// and 1 vs 2 MPI ranks (issue 6, acceptance 4). A gas of 216 prolate
// ellipsoids (xi = 2, solid fraction 0.1, v_rms 5 m/s, e_n = 0.9) crossing
// periodic and subdomain boundaries; frictionless, with friction, and with
// rolling resistance and cohesion (issue 30).
// Run as: test_ellipsoid_kokkos (1 rank) or mpirun -np 2 test_ellipsoid_kokkos.

#include "polydem_allgather.h"
#include "polydem_lmp.h"

#include "atom_kokkos.h"
#include "atom_masks.h"
#include "ellipsoid_gas.h"
#include "force.h"
#include "kokkos_type.h"
#include "pair.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using polydem_test::Lmp;
using polydem_test::num;
using polydem_test::pair_contact_time;

namespace {

const std::vector<std::string> KK = polydem_test::kk_styles();

int me()
{
  int r;
  MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}

// mu: "" (frictionless) or " 0.5" (pair_coeff friction, per-pair history)
std::vector<std::string> setup(const std::string &overlap, const std::string &mu = "",
                               const std::string &newton = "off")
{
  const polydem_test::GasSpec g = polydem_test::gas(6, 0.1, 0.75, 5.0, 77);
  const std::string data =
      polydem_test::write_gas(::testing::TempDir() + "polydem_ellipsoid_kk.data", g);
  const double b = g.b();
  const double m = g.mass();
  const double tc = pair_contact_time(m, 1e8);
  return {"units si", "atom_style polyhedron", "atom_modify map array", "boundary p p p",
          "comm_modify vel yes", "newton " + newton,
          "polyhedron_shape e ellipsoid " + num(g.xi * b) + " " + num(b) + " " + num(b),
          "read_data " + data, "pair_style ellipsoid overlap " + overlap,
          "pair_coeff * * 1e8 0.9" + mu, "neighbor " + num(0.2 * b) + " bin",
          "neigh_modify every 1 delay 0 check yes", "fix 1 all nve/polyhedron",
          "compute cp all pair ellipsoid", "thermo_style custom step pe press c_cp[1] c_cp[2]",
          "thermo 50", "timestep " + num(tc / 50.0)};
}

// compute pair ellipsoid: k = 0 collisions, 1 pair-steps in contact (this run, all ranks)
double pairvec(Lmp &l, int k)
{
  auto *p = (double *) lammps_extract_compute(l.lmp, "cp", LMP_STYLE_GLOBAL, LMP_TYPE_VECTOR);
  return p ? p[k] : std::nan("");
}

// (tag, x, v, f, torque) of all atoms on every rank of comm, sorted by tag
constexpr int REC = 13;
std::vector<double> gather(Lmp &l, MPI_Comm comm)
{
  if (auto *ak = dynamic_cast<LAMMPS_NS::AtomKokkos *>(l.lmp->atom))
    ak->sync(LAMMPS_NS::Host, ALL_MASK);
  auto *a = l.lmp->atom;
  std::vector<double> mine;
  for (int i = 0; i < a->nlocal; i++) {
    mine.push_back((double) a->tag[i]);
    for (double **arr : {a->x, a->v, a->f, a->torque})
      for (int k = 0; k < 3; k++) mine.push_back(arr[i][k]);
  }
  return polydem_test::allgather_by_tag(mine, REC, comm);
}

// max over atoms of |a - b| / max over atoms |b|, field at offset off
double normwise(const std::vector<double> &a, const std::vector<double> &b, int off)
{
  double d = 0.0, s = 0.0;
  for (size_t r = 0; r < b.size(); r += REC)
    for (int k = 0; k < 3; k++) {
      d = std::max(d, std::fabs(a[r + off + k] - b[r + off + k]));
      s = std::max(s, std::fabs(b[r + off + k]));
    }
  return s > 0.0 ? d / s : d;
}

void compare(const std::vector<double> &a, const std::vector<double> &b, Lmp &la, Lmp &lb,
             const char *what)
{
  ASSERT_EQ(a.size(), b.size());
  for (size_t r = 0; r < b.size(); r += REC) ASSERT_EQ(a[r], b[r]);
  const double ex = normwise(a, b, 1), ev = normwise(a, b, 4), ef = normwise(a, b, 7),
               et = normwise(a, b, 10);
  const double pa = la.thermo("pe"), pb = lb.thermo("pe");
  const double ca = pairvec(la, 1), cb = pairvec(lb, 1);
  if (me() == 0)
    std::printf("[%s] %zu atoms, %.0f pair-steps in contact, %.0f collisions; max rel. diff: "
                "x %.3g v %.3g f %.3g torque %.3g pe %.3g\n",
                what, b.size() / REC, cb, pairvec(lb, 0), ex, ev, ef, et,
                std::fabs(pa - pb) / std::fmax(std::fabs(pb), 1e-300));
  EXPECT_LE(ex, 1e-12);
  EXPECT_LE(ev, 1e-12);
  EXPECT_LE(ef, 1e-12);
  EXPECT_LE(et, 1e-12);
  EXPECT_NEAR(pa, pb, 1e-12 * std::fabs(pb));
  EXPECT_EQ(ca, cb);
}

}    // namespace

// /kk (Serial) equals plain to 1e-12 over 2200 steps (both on the same ranks)
TEST(EllipsoidKokkos, MatchesPlain)
{
  // overlap (and damping) settings of pair_style ellipsoid
  for (std::string ovmu : {"centre", "chord", "centre damping contact", "chord damping contact",
                           "centre damping contact| 0.5", "chord| 0.3",
                           "centre damping contact| 0.5 rolling 0.1", "centre| 0 rolling 0.2 cohesion 5"}) {
    const size_t bar = ovmu.find('|');
    const std::string ov = ovmu.substr(0, bar), mu = bar == std::string::npos ? "" : ovmu.substr(bar + 1);
    Lmp plain, kk(KK);
    plain.cmds(setup(ov, mu));
    kk.cmds(setup(ov, mu));
    ASSERT_EQ(std::string(kk.lmp->force->pair_style), "ellipsoid/kk");
    // the lattice needs about 1500 steps before the first collisions
    for (int r = 0; r < 3; r++) {
      plain.cmd(r == 0 ? "run 2000" : "run 100");
      kk.cmd(r == 0 ? "run 2000" : "run 100");
      const auto a = gather(kk, MPI_COMM_WORLD), b = gather(plain, MPI_COMM_WORLD);
      compare(a, b, kk, plain, ("kk vs plain, overlap " + ov + ", mu" + mu).c_str());
    }
    EXPECT_GT(pairvec(plain, 1), 20.0) << "no contacts: the test tests nothing";
  }
}

// newton on: each pair once, the ghosts' forces, torques and histories sent
// to their owners; /kk against plain with newton on (with friction and
// rolling resistance, whose histories cross reneighborings)
TEST(EllipsoidKokkos, NewtonOnMatchesPlain)
{
  for (std::string mu : {" 0.5", " 0.5 rolling 0.1 cohesion 5"}) {
    Lmp plain, kk(polydem_test::kk_styles("on"));
    plain.cmds(setup("centre damping contact", mu, "on"));
    kk.cmds(setup("centre damping contact", mu, "on"));
    ASSERT_EQ(kk.lmp->force->newton_pair, 1);
    plain.cmd("run 2100");
    kk.cmd("run 2100");
    const auto a = gather(kk, MPI_COMM_WORLD), b = gather(plain, MPI_COMM_WORLD);
    compare(a, b, kk, plain, ("newton on, kk vs plain, mu" + mu).c_str());
    EXPECT_GT(pairvec(plain, 1), 20.0) << "no contacts: the test tests nothing";
  }
}

// all ranks of MPI_COMM_WORLD against one rank (MPI_COMM_SELF on each rank),
// plain and /kk, 2100 steps (collisions from about step 1500)
TEST(EllipsoidKokkos, RanksAgree)
{
  for (int variant = 0; variant < 6; variant++) {
    const bool usekk = variant % 2;
    // friction, rolling resistance: histories migrate
    const std::string mu = variant < 2 ? "" : variant < 4 ? " 0.5" : " 0.5 rolling 0.1 cohesion 5";
    Lmp multi(usekk ? KK : std::vector<std::string>{}, MPI_COMM_WORLD);
    Lmp single(usekk ? KK : std::vector<std::string>{}, MPI_COMM_SELF);
    multi.cmds(setup("centre damping contact", mu));
    single.cmds(setup("centre damping contact", mu));
    multi.cmd("run 2100");
    single.cmd("run 2100");
    const auto a = gather(multi, MPI_COMM_WORLD), b = gather(single, MPI_COMM_SELF);
    int np;
    MPI_Comm_size(MPI_COMM_WORLD, &np);
    compare(a, b, multi, single,
            (std::string(usekk ? "kk" : "plain") + ", mu" + mu + ", " + std::to_string(np) + " vs 1 rank")
                .c_str());
    EXPECT_GT(pairvec(single, 1), 20.0);
  }
}
