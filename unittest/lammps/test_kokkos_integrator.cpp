// atom_style polyhedron/kk + fix nve/polyhedron/kk against the plain styles
// (issue 2, acceptance item 3): a few hundred randomly oriented, spinning
// polyhedra of two shapes in a periodic box, non-interacting, run with
// "-k on -sf kk" (1 thread, _threads: 2) and without; positions, image flags,
// quaternions, angular momenta, velocities and angular velocities must agree
// to 1e-12 relative after many steps with particles crossing periodic (and,
// on 2 ranks, subdomain) boundaries, for each Kokkos communication mode.
// Also: restart and data-file round trips under /kk, and /kk on 2 ranks
// against plain on 1 rank (run under mpirun -np 2).

#include "polydem_allgather.h"
#include "polydem_lmp.h"

#include "domain.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include <unistd.h>

using polydem_test::Lmp;
using polydem_test::potentials;

namespace {

const std::vector<std::string> KK = polydem_test::kk({"-sf", "kk"});

std::vector<std::string> with(std::vector<std::string> a, const std::vector<std::string> &b)
{
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

// n particles of each of two shapes; speeds ~ a few box lengths per 1000
// steps, spins of order 1 about random body axes
// ghosts: without a pair style the communication cutoff must be set for
// borders and forward communication to carry anything; spatial sorting
// exercises AtomVec::copy; ghost_vel adds velocities to ghosts
std::vector<std::string> setup(int n, bool ghost_vel = false)
{
  const std::string sn = std::to_string(n);
  return {"units lj",
          "atom_style polyhedron",
          "atom_modify map array sort 100 2.0",
          std::string("comm_modify cutoff 2.5 vel ") + (ghost_vel ? "yes" : "no"),
          "boundary p p p",
          "region box block 0 10 0 10 0 10",
          "create_box 2 box",
          "polyhedron_shape cube " + potentials() + "/cube.shape",
          "polyhedron_shape dode " + potentials() + "/dodecahedron.shape",
          "create_atoms 1 random " + sn + " 4711 NULL",
          "create_atoms 2 random " + sn + " 4712 NULL",
          "polyhedron_set type 2 shape dode scale 0.6 density 2.0 quat/random 5 omega -1.5 0.7 2.0",
          "polyhedron_set type 1 scale 0.8 quat/random 6 omega 1.0 2.0 -0.5",
          "velocity all create 20.0 999 loop geom",
          "neighbor 0.3 bin",
          "fix 1 all nve/polyhedron",
          "timestep 0.002",
          "thermo 100",
          "thermo_style custom step atoms"};
}

// the same system read from a data file: atom IDs independent of the number
// of ranks (create_atoms numbers atoms rank by rank)
std::vector<std::string> setup_from_data(const std::string &file, bool ghost_vel = false)
{
  return {"units lj",
          "atom_style polyhedron",
          "atom_modify map array sort 100 2.0",
          std::string("comm_modify cutoff 2.5 vel ") + (ghost_vel ? "yes" : "no"),
          "boundary p p p",
          "polyhedron_shape cube " + potentials() + "/cube.shape",
          "polyhedron_shape dode " + potentials() + "/dodecahedron.shape",
          "read_data " + file,
          "neighbor 0.3 bin",
          "fix 1 all nve/polyhedron",
          "timestep 0.002",
          "thermo 100",
          "thermo_style custom step atoms"};
}

// one record per atom, sorted by ID, gathered to every rank of comm:
// id, x, image, v, quat, angmom, omega
constexpr int REC = 1 + 3 + 3 + 3 + 4 + 3 + 3;

std::vector<double> gather(Lmp &l, MPI_Comm comm)
{
  auto *a = l.lmp->atom;
  std::vector<double> mine;
  for (int i = 0; i < a->nlocal; i++) {
    mine.push_back((double) a->tag[i]);
    for (int k = 0; k < 3; k++) mine.push_back(a->x[i][k]);
    const LAMMPS_NS::imageint im = a->image[i];
    mine.push_back((double) ((im & IMGMASK) - IMGMAX));
    mine.push_back((double) ((im >> IMGBITS & IMGMASK) - IMGMAX));
    mine.push_back((double) ((im >> IMG2BITS) - IMGMAX));
    for (int k = 0; k < 3; k++) mine.push_back(a->v[i][k]);
    for (int k = 0; k < 4; k++) mine.push_back(a->quat[i][k]);
    for (int k = 0; k < 3; k++) mine.push_back(a->angmom[i][k]);
    for (int k = 0; k < 3; k++) mine.push_back(a->omega[i][k]);
  }
  return polydem_test::allgather_by_tag(mine, REC, comm);
}

struct Diff {
  double x = 0, v = 0, q = 0, L = 0, w = 0;    // max relative difference per quantity
  long image = 0;                             // atoms whose image flags differ
  long ids = 0;                               // records whose IDs differ
  long crossed = 0;                           // atoms with non-zero image flags
  double max() const { return std::max({x, v, q, L, w}); }
};

// relative difference of two small vectors: |a - b|_inf / max(|a|_inf, |b|_inf)
double rel(const double *a, const double *b, int n)
{
  double d = 0, s = 0;
  for (int k = 0; k < n; k++) {
    d = std::max(d, std::fabs(a[k] - b[k]));
    s = std::max({s, std::fabs(a[k]), std::fabs(b[k])});
  }
  return s > 0 ? d / s : d;
}

Diff compare(const std::vector<double> &a, const std::vector<double> &b)
{
  Diff d;
  EXPECT_EQ(a.size(), b.size());
  const size_t n = std::min(a.size(), b.size()) / REC;
  for (size_t i = 0; i < n; i++) {
    const double *p = &a[i * REC], *q = &b[i * REC];
    if (p[0] != q[0]) d.ids++;
    // positions in a box [0,10): relative to the box length
    double dx = 0;
    for (int k = 0; k < 3; k++) dx = std::max(dx, std::fabs(p[1 + k] - q[1 + k]) / 10.0);
    d.x = std::max(d.x, dx);
    if (p[4] != q[4] || p[5] != q[5] || p[6] != q[6]) d.image++;
    if (p[4] != 0 || p[5] != 0 || p[6] != 0) d.crossed++;
    d.v = std::max(d.v, rel(p + 7, q + 7, 3));
    d.q = std::max(d.q, rel(p + 10, q + 10, 4));
    d.L = std::max(d.L, rel(p + 14, q + 14, 3));
    d.w = std::max(d.w, rel(p + 17, q + 17, 3));
  }
  return d;
}

std::string describe(const Diff &d)
{
  char buf[400];
  snprintf(buf, sizeof(buf),
           "max rel diff x %.3g v %.3g quat %.3g angmom %.3g omega %.3g; image mismatches %ld, "
           "atoms that crossed a periodic boundary %ld",
           d.x, d.v, d.q, d.L, d.w, d.image, d.crossed);
  return buf;
}

// every ghost atom must carry its owner's data: position up to a periodic
// image, quaternion, shape, scale, radius, mass (and with ghost velocities
// v, omega, angmom). Non-interacting particles: the final half step changes
// none of these, so ghosts and owners agree exactly at the end of a run.
// Returns the number of ghosts checked; counts mismatches in *bad.
long check_ghosts(Lmp &l, bool ghost_vel, long *bad)
{
  auto *a = l.lmp->atom;
  // owners' records from every rank: id, x, quat, v, omega, angmom, shape, scale, radius, mass
  const int R = 1 + 3 + 4 + 9 + 4;
  std::vector<double> mine;
  for (int i = 0; i < a->nlocal; i++) {
    mine.push_back((double) a->tag[i]);
    for (int k = 0; k < 3; k++) mine.push_back(a->x[i][k]);
    for (int k = 0; k < 4; k++) mine.push_back(a->quat[i][k]);
    for (int k = 0; k < 3; k++) mine.push_back(a->v[i][k]);
    for (int k = 0; k < 3; k++) mine.push_back(a->omega[i][k]);
    for (int k = 0; k < 3; k++) mine.push_back(a->angmom[i][k]);
    mine.push_back(a->pshape[i]);
    mine.push_back(a->pscale[i]);
    mine.push_back(a->radius[i]);
    mine.push_back(a->rmass[i]);
  }
  const std::vector<double> all = polydem_test::allgather(mine, l.lmp->world);
  std::map<long, const double *> owner;
  for (size_t i = 0; i < all.size(); i += R) owner[(long) all[i]] = &all[i];

  const double prd[3] = {l.lmp->domain->xprd, l.lmp->domain->yprd, l.lmp->domain->zprd};
  long checked = 0;
  *bad = 0;
  for (int i = a->nlocal; i < a->nlocal + a->nghost; i++) {
    auto it = owner.find((long) a->tag[i]);
    if (it == owner.end()) {
      (*bad)++;
      continue;
    }
    const double *o = it->second;
    bool ok = true;
    for (int k = 0; k < 3; k++) {
      const double d = a->x[i][k] - o[1 + k];
      const double img = std::round(d / prd[k]);
      if (std::fabs(d - img * prd[k]) > 1e-12 * prd[k]) ok = false;
    }
    for (int k = 0; k < 4; k++) ok = ok && a->quat[i][k] == o[4 + k];
    ok = ok && a->pshape[i] == (int) o[17] && a->pscale[i] == o[18] && a->radius[i] == o[19] &&
        a->rmass[i] == o[20];
    if (ghost_vel) {
      for (int k = 0; k < 3; k++) {
        ok = ok && a->v[i][k] == o[8 + k];
        ok = ok && a->omega[i][k] == o[11 + k];
        ok = ok && a->angmom[i][k] == o[14 + k];
      }
    }
    if (!ok) (*bad)++;
    checked++;
  }
  return checked;
}

// the same name on every rank (rank 0's process id)
std::string tmpfile(const std::string &name)
{
  long pid = (long) getpid();
  MPI_Bcast(&pid, 1, MPI_LONG, 0, MPI_COMM_WORLD);
  return "/tmp/polydem_kk_" + std::to_string(pid) + "_" + name;
}

}    // namespace

/* ---------------------------------------------------------------------- */

constexpr int NPER = 150;      // particles per shape: 300 in all
constexpr int NSTEPS = 2000;    // in 4 runs of 500 (re-neighboring, exchange, borders)

class KokkosVsPlain : public ::testing::TestWithParam<std::tuple<std::string, bool>> {};

// comm device (kernels of this style), comm host (the same functors on the
// host space), comm no (LAMMPS's classic host communication through the
// generic AtomVec code); with and without ghost velocities
TEST_P(KokkosVsPlain, TrajectoriesAgree)
{
  const std::string mode = std::get<0>(GetParam());
  const bool ghost_vel = std::get<1>(GetParam());
  std::vector<double> plain, kk;
  long nghost = 0;
  {
    Lmp l;
    l.cmds(setup(NPER, ghost_vel));
    for (int r = 0; r < NSTEPS / 500; r++) l.cmd("run 500");
    plain = gather(l, MPI_COMM_WORLD);
    long bad = 0;
    EXPECT_GT(check_ghosts(l, ghost_vel, &bad), 0);
    EXPECT_EQ(bad, 0) << "plain";
  }
  {
    Lmp l(with(KK, {"-pk", "kokkos", "comm", mode}));
    l.cmds(setup(NPER, ghost_vel));
    EXPECT_STREQ(l.lmp->atom->atom_style, "polyhedron/kk");
    for (int r = 0; r < NSTEPS / 500; r++) l.cmd("run 500");
    EXPECT_EQ(l.thermo("atoms"), 2 * NPER);
    kk = gather(l, MPI_COMM_WORLD);
    long bad = 0;
    nghost = check_ghosts(l, ghost_vel, &bad);
    EXPECT_GT(nghost, 0);
    EXPECT_EQ(bad, 0) << "ghosts whose data differ from their owner's";
  }
  const Diff d = compare(plain, kk);
  EXPECT_EQ(d.ids, 0);
  EXPECT_EQ(d.image, 0);
  EXPECT_LE(d.max(), 1e-12) << describe(d);
  // the test must exercise boundary crossings
  EXPECT_GT(d.crossed, NPER) << describe(d);
  int me = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &me);
  int nprocs = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &nprocs);
  if (me == 0)
    printf("[ measured ] %d rank(s), comm %s, ghost velocities %s: %d particles, %d steps: %s; "
           "%ld ghosts on rank 0 equal to their owners\n",
           nprocs, mode.c_str(), ghost_vel ? "yes" : "no", 2 * NPER, NSTEPS,
           describe(d).c_str(), nghost);
}

INSTANTIATE_TEST_SUITE_P(CommModes, KokkosVsPlain,
                         ::testing::Combine(::testing::Values("device", "host", "no"),
                                            ::testing::Bool()));

/* ----------------------------------------------------------------------
   write_restart -> read_restart under /kk continues bit-identically
------------------------------------------------------------------------- */

TEST(KokkosIntegrator, RestartContinuesBitIdentically)
{
  const std::string rfile = tmpfile("restart.bin");
  std::vector<double> straight, restarted;
  {
    Lmp l(KK);
    l.cmds(setup(NPER));
    l.cmds({"run 300", "write_restart " + rfile, "run 300"});
    straight = gather(l, MPI_COMM_WORLD);
  }
  {
    Lmp l(KK);
    l.cmds({"read_restart " + rfile, "neighbor 0.3 bin", "fix 1 all nve/polyhedron",
            "timestep 0.002"});
    EXPECT_STREQ(l.lmp->atom->atom_style, "polyhedron/kk");
    l.cmd("run 300");
    restarted = gather(l, MPI_COMM_WORLD);
  }
  const Diff d = compare(straight, restarted);
  EXPECT_EQ(d.ids, 0);
  EXPECT_EQ(d.image, 0);
  EXPECT_EQ(d.max(), 0.0) << describe(d);
  int me = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &me);
  if (me == 0) remove(rfile.c_str());
}

/* ----------------------------------------------------------------------
   write_data -> read_data under /kk reproduces x, v, quat, angmom exactly
   (omega is recomputed from angmom by the fix: compared after "run 0")
------------------------------------------------------------------------- */

TEST(KokkosIntegrator, DataFileRoundTrip)
{
  const std::string dfile = tmpfile("data.txt");
  std::vector<double> before, after;
  {
    Lmp l(KK);
    l.cmds(setup(NPER));
    l.cmds({"run 100", "write_data " + dfile});
    before = gather(l, MPI_COMM_WORLD);
  }
  {
    Lmp l(KK);
    l.cmds({"units lj", "atom_style polyhedron", "atom_modify map array", "boundary p p p",
            "polyhedron_shape cube " + potentials() + "/cube.shape",
            "polyhedron_shape dode " + potentials() + "/dodecahedron.shape",
            "read_data " + dfile, "neighbor 0.3 bin", "fix 1 all nve/polyhedron",
            "timestep 0.002", "run 0"});
    after = gather(l, MPI_COMM_WORLD);
  }
  const Diff d = compare(before, after);
  EXPECT_EQ(d.ids, 0);
  EXPECT_EQ(d.image, 0);
  EXPECT_EQ(d.x, 0.0) << describe(d);
  EXPECT_EQ(d.v, 0.0) << describe(d);
  EXPECT_EQ(d.q, 0.0) << describe(d);
  EXPECT_EQ(d.L, 0.0) << describe(d);
  EXPECT_LE(d.w, 1e-15) << describe(d);
  int me = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &me);
  if (me == 0) remove(dfile.c_str());
}

/* ----------------------------------------------------------------------
   /kk on all ranks of the run (2 under mpirun -np 2: exchange and borders
   between ranks) against plain LAMMPS on one rank
------------------------------------------------------------------------- */

TEST(KokkosIntegrator, KokkosOnAllRanksMatchesPlainOnOne)
{
  int me, nprocs;
  MPI_Comm_rank(MPI_COMM_WORLD, &me);
  MPI_Comm_size(MPI_COMM_WORLD, &nprocs);
  MPI_Comm self;
  MPI_Comm_split(MPI_COMM_WORLD, me, 0, &self);
  const std::string dfile = tmpfile("initial.data");
  if (me == 0) {
    Lmp l({}, self);
    l.cmds(setup(NPER));
    l.cmd("write_data " + dfile);
  }
  MPI_Barrier(MPI_COMM_WORLD);
  std::vector<double> multi;
  double natoms_min = 1e30, natoms_max = -1;
  {
    Lmp l(KK, MPI_COMM_WORLD);
    l.cmds(setup_from_data(dfile, true));
    for (int r = 0; r < NSTEPS / 500; r++) {
      l.cmd("run 500");
      natoms_min = std::min(natoms_min, l.thermo("atoms"));
      natoms_max = std::max(natoms_max, l.thermo("atoms"));
    }
    multi = gather(l, MPI_COMM_WORLD);
    long bad = 0;
    EXPECT_GT(check_ghosts(l, true, &bad), 0);
    EXPECT_EQ(bad, 0) << "ghosts whose data differ from their owner's";
  }
  EXPECT_EQ(natoms_min, 2 * NPER);
  EXPECT_EQ(natoms_max, 2 * NPER);
  if (me == 0) {
    Lmp l({}, self);
    l.cmds(setup_from_data(dfile, true));
    for (int r = 0; r < NSTEPS / 500; r++) l.cmd("run 500");
    const std::vector<double> single = gather(l, self);
    const Diff d = compare(single, multi);
    EXPECT_EQ(d.ids, 0);
    EXPECT_EQ(d.image, 0);
    EXPECT_LE(d.max(), 1e-12) << describe(d);
    printf("[ measured ] /kk on %d rank(s) vs plain on 1: %d particles, %d steps: %s\n", nprocs,
           2 * NPER, NSTEPS, describe(d).c_str());
    remove(dfile.c_str());
  }
  MPI_Comm_free(&self);
}
