/* ----------------------------------------------------------------------
   POLYDEM - fix insert/polyhedron (doc/fix_insert_polyhedron.rst):
   keywords, size and kind distributions, the insertion schedule, restart.
   Where particles go: fix_insert_polyhedron_place.cpp
------------------------------------------------------------------------- */

#include "fix_insert_polyhedron.h"

#include "accelerator_kokkos.h"
#include "atom.h"
#include "atom_masks.h"
#include "atom_vec.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "group.h"
#include "math_const.h"
#include "modify.h"
#include "pair.h"
#include "poly_shape_library.h"
#include "polydem_lammps_compat.h"
#include "polydem_parse.h"
#include "polydem_rigid.h"
#include "polydem_shape_template.h"
#include "region.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;
using MathConst::MY_PI;

namespace {
constexpr int RESTART_VERSION = 2;    // 2: the command's keywords follow the state

// text with every word that is a finite number rewritten as %.17g, so
// that 0.001 and 1e-3 compare equal
std::string canonical_numbers(const std::string &text)
{
  std::string out;
  for (const auto &w : utils::split_words(text)) {
    char *end = nullptr;
    const double v = strtod(w.c_str(), &end);
    const bool num = !w.empty() && end && *end == '\0' && std::isfinite(v);
    out += (out.empty() ? "" : " ") + (num ? fmt::format("{:.17g}", v) : w);
  }
  return out;
}
}    // namespace

/* ----------------------------------------------------------------------
   fix ID group insert/polyhedron N seed keyword values ...
------------------------------------------------------------------------- */

FixInsertPolyhedron::FixInsertPolyhedron(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), avec(nullptr), region(nullptr), mode(MODE_RATE), ratestyle(RATE_NONE),
    massfrac(0), ntotal(0), masstotal(0.0), rate(0.0), every(100), phi_target(0.0), attempts(-1),
    misses(10), orientstyle(ORIENT_RANDOM), otheta(0.0), itype(1), allin(1), gap(0.0), seed(0),
    ninserted(0), nfailed(0), nattempts(0), nevents(0), nstart(0), next_event(0), massinserted(0.0),
    volinserted(0.0), packdone(0), nfailed_warned(0), region_volume(0.0), rmax_insert(0.0)
{
  const std::string me = "fix insert/polyhedron";
  if (narg < 5)
    error->all(FLERR, "{}: needs N and seed (fix ID group insert/polyhedron N seed ...)", me);
  avec = PolyShapeLibrary::of(lmp, me);
  if (domain->dimension != 3) error->all(FLERR, "{}: 3d simulations only", me);
  if (domain->triclinic) error->all(FLERR, "{}: triclinic boxes are not supported", me);

  ntotal = utils::bnumeric(FLERR, arg[3], false, lmp);
  if (ntotal < 0) error->all(FLERR, "{}: N must be >= 0, got {}", me, arg[3]);
  seed = utils::bnumeric(FLERR, arg[4], false, lmp);
  if (seed <= 0) error->all(FLERR, "{}: seed must be > 0, got {}", me, arg[4]);

  oaxis[0] = oaxis[1] = 0.0;
  oaxis[2] = 1.0;
  for (int k = 0; k < 3; k++) vlo[k] = vhi[k] = wlo[k] = whi[k] = 0.0;
  double density = 0.0;
  bool have_rate = false;

  auto num = [&](int i) {
    return polydem_parse::number(FLERR, arg[i], lmp, me);
  };
  settings = {{"N", arg[3]}, {"seed", arg[4]}};
  int iarg = 5;
  while (iarg < narg) {
    const std::string kw = arg[iarg];
    const int kw_start = iarg;
    auto need = [&](int n) {
      if (iarg + n >= narg) error->all(FLERR, "{}: keyword '{}' needs {} value(s)", me, kw, n);
    };
    // the keyword's one value, a number > 0 (>= 0 where zero_ok)
    auto positive = [&](bool zero_ok = false) {
      need(1);
      const double v = num(iarg + 1);
      if (!(zero_ok ? v >= 0.0 : v > 0.0))
        error->all(FLERR, "{}: {} must be {} 0, got {}", me, kw, zero_ok ? ">=" : ">",
                   arg[iarg + 1]);
      iarg += 2;
      return v;
    };
    // the keyword's one value, a whole number > 0
    auto count = [&]() {
      need(1);
      const int v = utils::inumeric(FLERR, arg[iarg + 1], false, lmp);
      if (v <= 0) error->all(FLERR, "{}: {} must be > 0, got {}", me, kw, arg[iarg + 1]);
      iarg += 2;
      return v;
    };
    if (kw == "region") {
      need(1);
      idregion = arg[iarg + 1];
      iarg += 2;
    } else if (kw == "shape") {
      need(2);
      Kind k;
      k.id = arg[iarg + 1];
      k.ishape = avec->find_shape(k.id);
      if (k.ishape < 0)
        error->all(FLERR, "{}: shape '{}' is not defined (use polyhedron_shape first)", me, k.id);
      k.frac = num(iarg + 2);
      if (!(k.frac >= 0.0)) error->all(FLERR, "{}: fraction of shape '{}' must be >= 0", me, k.id);
      k.density = 0.0;
      k.pnum = 0.0;
      iarg += 3;
      while (iarg < narg) {    // sub-keywords of this shape
        if (strcmp(arg[iarg], "scale") == 0) {
          iarg++;
          parse_scale(iarg, narg, arg, k.scale, k.id);
        } else if (strcmp(arg[iarg], "density") == 0) {
          if (iarg + 1 >= narg)
            error->all(FLERR, "{}: shape '{}': density needs a value", me, k.id);
          k.density = num(iarg + 1);
          if (!(k.density > 0.0))
            error->all(FLERR, "{}: shape '{}': density must be > 0, got {}", me, k.id,
                       arg[iarg + 1]);
          iarg += 2;
        } else
          break;
      }
      kinds.push_back(k);
    } else if (kw == "fractions") {
      need(1);
      massfrac = polydem_parse::choice(FLERR, lmp, me, "fractions", arg[iarg + 1], "mass", "number");
      iarg += 2;
    } else if (kw == "density") {
      density = positive();
    } else if (kw == "mode") {
      need(1);
      if (strcmp(arg[iarg + 1], "rate") == 0)
        mode = MODE_RATE;
      else if (strcmp(arg[iarg + 1], "pack") == 0)
        mode = MODE_PACK;
      else
        error->all(FLERR, "{}: mode must be 'rate' or 'pack', got '{}'", me, arg[iarg + 1]);
      iarg += 2;
    } else if (kw == "every") {
      every = count();
    } else if (kw == "rate" || kw == "rate/mass" || kw == "per") {
      need(1);
      if (have_rate) error->all(FLERR, "{}: give only one of rate, rate/mass and per", me);
      have_rate = true;
      rate = num(iarg + 1);
      if (!(rate > 0.0)) error->all(FLERR, "{}: {} must be > 0, got {}", me, kw, arg[iarg + 1]);
      ratestyle = kw == "rate" ? RATE_NUMBER : (kw == "rate/mass" ? RATE_MASS : RATE_PER);
      if (ratestyle == RATE_PER && rate != floor(rate))
        error->all(FLERR, "{}: per needs a whole number of particles, got {}", me, arg[iarg + 1]);
      iarg += 2;
    } else if (kw == "mass/total") {
      masstotal = positive();
    } else if (kw == "fraction") {
      need(1);
      phi_target = num(iarg + 1);
      if (!(phi_target > 0.0 && phi_target < 1.0))
        error->all(FLERR, "{}: fraction must be in (0, 1), got {}", me, arg[iarg + 1]);
      iarg += 2;
    } else if (kw == "attempts") {
      attempts = count();
    } else if (kw == "misses") {
      misses = count();
    } else if (kw == "orient") {
      need(1);
      const std::string st = arg[iarg + 1];
      if (st == "random") {
        orientstyle = ORIENT_RANDOM;
        iarg += 2;
      } else if (st == "fixed" || st == "axis") {
        const int nv = st == "fixed" ? 4 : 3;
        need(1 + nv);
        for (int k = 0; k < 3; k++) oaxis[k] = num(iarg + 2 + k);
        const double n = sqrt(oaxis[0] * oaxis[0] + oaxis[1] * oaxis[1] + oaxis[2] * oaxis[2]);
        if (!(n > 0.0)) error->all(FLERR, "{}: orient {} needs a non-zero axis", me, st);
        for (double &a : oaxis) a /= n;
        if (st == "fixed") otheta = num(iarg + 5) * MY_PI / 180.0;
        orientstyle = st == "fixed" ? ORIENT_FIXED : ORIENT_AXIS;
        iarg += 2 + nv;
      } else
        error->all(FLERR, "{}: orient must be random, fixed or axis, got '{}'", me, st);
    } else if (kw == "vel" || kw == "omega") {
      need(1);
      double *lo = kw == "vel" ? vlo : wlo, *hi = kw == "vel" ? vhi : whi;
      const std::string st = arg[iarg + 1];
      if (st == "constant") {
        need(4);
        for (int k = 0; k < 3; k++) lo[k] = hi[k] = num(iarg + 2 + k);
        iarg += 5;
      } else if (st == "uniform") {
        need(7);
        for (int k = 0; k < 3; k++) {
          lo[k] = num(iarg + 2 + 2 * k);
          hi[k] = num(iarg + 3 + 2 * k);
          if (hi[k] < lo[k]) error->all(FLERR, "{}: {} uniform needs lo <= hi", me, kw);
        }
        iarg += 8;
      } else
        error->all(FLERR, "{}: {} must be followed by constant or uniform, got '{}'", me, kw, st);
    } else if (kw == "type") {
      need(1);
      itype = utils::inumeric(FLERR, arg[iarg + 1], false, lmp);
      if (itype < 1 || itype > atom->ntypes)
        error->all(FLERR, "{}: type {} is out of range 1..{}", me, arg[iarg + 1], atom->ntypes);
      iarg += 2;
    } else if (kw == "all_in") {
      need(1);
      allin = polydem_parse::choice(FLERR, lmp, me, "all_in", arg[iarg + 1], "yes", "no");
      iarg += 2;
    } else if (kw == "gap") {
      gap = positive(true);
    } else
      error->all(FLERR, "{}: unknown keyword '{}'", me, kw);
    // the keyword's values as given (a shape by its ID): restart compares them
    std::string key = kw, val;
    int v0 = kw_start + 1;
    if (kw == "shape") key += " " + std::string(arg[v0++]);
    for (int i = v0; i < iarg; i++) val += (val.empty() ? "" : " ") + std::string(arg[i]);
    settings.emplace_back(key, val);
  }
  for (auto &kv : settings) kv.second = canonical_numbers(kv.second);

  // ---- consistency
  if (idregion.empty()) error->all(FLERR, "{}: keyword 'region' is required", me);
  if (kinds.empty()) error->all(FLERR, "{}: at least one 'shape ID fraction' is required", me);
  double fsum = 0.0;
  for (auto &k : kinds) {
    fsum += k.frac;
    if (k.density <= 0.0) {
      if (!(density > 0.0))
        error->all(FLERR,
                   "{}: shape '{}' has no density: give 'density rho' before the first "
                   "shape (a density right after a shape is that shape's own)",
                   me, k.id);
      k.density = density;
    }
  }
  if (fabs(fsum - 1.0) > 1.0e-6)
    error->all(FLERR, "{}: the shape fractions sum to {:.6g}, not 1", me, fsum);
  // the checks of polyhedron_set, at both ends of each scale range (mass
  // rho V s^3 and moments m s^2 J / V grow with s): density 1e308 or
  // 1e-320, scale 1e-300 gave an infinite or zero mass
  for (const auto &k : kinds)
    for (const double s : {k.scale.min(), k.scale.max()}) {
      const double m = polydem::scaled_mass(k.density, avec->shape(k.ishape).volume(), s);
      if (!avec->mass_is_normal(k.ishape, m, s))
        error->all(FLERR,
                   "{}: shape '{}': density {:.6g} and scale {:.6g} give a mass {:.6g} outside "
                   "(0, 1e250] or a moment of inertia that is zero or not finite",
                   me, k.id, k.density, s, m);
    }
  if (mode == MODE_RATE) {
    if (!have_rate)
      error->all(FLERR, "{}: mode rate needs one of the keywords rate, rate/mass or per", me);
    if (phi_target > 0.0) error->all(FLERR, "{}: keyword fraction is for mode pack", me);
  } else if (have_rate)
    error->all(FLERR, "{}: keywords rate, rate/mass and per are for mode rate", me);
  if (ntotal == 0 && masstotal == 0.0 && phi_target == 0.0)
    error->all(FLERR, "{}: N = 0 needs a limit (mass/total, or fraction in mode pack)", me);
  if (attempts < 0) attempts = 1000;
  number_probabilities();
  for (const auto &k : kinds)
    rmax_insert = std::max(rmax_insert, avec->shape(k.ishape).radius() * k.scale.max());
  double prev = 0.0;
  mean_mass = mean_volume = 0.0;
  for (const auto &k : kinds) {
    const double v = (k.pnum - prev) * avec->shape(k.ishape).volume() * k.scale.moment(3);
    mean_volume += v;
    mean_mass += k.density * v;
    prev = k.pnum;
  }

  rng.seed((uint64_t) seed);
  nstart = update->ntimestep;
  next_event = nstart;

  force_reneighbor = 1;
  next_reneighbor = next_event;
  restart_global = 1;
  scalar_flag = 1;
  vector_flag = 1;
  size_vector = 5;
  global_freq = 1;
  extscalar = 0;
  extvector = 0;
}

/* ----------------------------------------------------------------------
   scale constant s | uniform lo hi | normal mean sd lo hi |
         lognormal median sigma lo hi | list n s1 w1 ... sn wn | s
------------------------------------------------------------------------- */

void FixInsertPolyhedron::parse_scale(int &iarg, int narg, char **arg, polydem::ScaleDist &d,
                                      const std::string &id)
{
  const std::string me = "fix insert/polyhedron";
  auto need = [&](int n, const char *what) {
    if (iarg + n > narg)
      error->all(FLERR, "{}: shape '{}': scale {} needs {} value(s)", me, id, what, n);
  };
  auto num = [&](int i) {
    const double v = polydem_parse::number(FLERR, arg[i], lmp, me);
    if (!(v > 0.0))
      error->all(FLERR, "{}: shape '{}': scale values must be finite and > 0, got '{}'", me, id,
                 arg[i]);
    return v;
  };
  if (iarg >= narg) error->all(FLERR, "{}: shape '{}': scale needs a value", me, id);
  const std::string st = arg[iarg];
  using polydem::ScaleDist;
  if (st == "constant") {
    need(2, "constant");
    d.kind = ScaleDist::CONSTANT;
    d.a = num(iarg + 1);
    iarg += 2;
  } else if (st == "uniform") {
    need(3, "uniform");
    d.kind = ScaleDist::UNIFORM;
    d.a = num(iarg + 1);
    d.b = num(iarg + 2);
    if (d.b < d.a) error->all(FLERR, "{}: shape '{}': scale uniform needs lo <= hi", me, id);
    iarg += 3;
  } else if (st == "normal" || st == "lognormal") {
    need(5, st.c_str());
    d.kind = st == "normal" ? ScaleDist::NORMAL : ScaleDist::LOGNORMAL;
    d.a = num(iarg + 1);
    d.b = num(iarg + 2);
    d.lo = num(iarg + 3);
    d.hi = num(iarg + 4);
    if (!(d.hi > d.lo))
      error->all(FLERR, "{}: shape '{}': scale {} needs cut-offs lo < hi", me, id, st);
    if (!(d.truncated_mass() >= 1.0e-3))
      error->all(FLERR,
                 "{}: shape '{}': scale {} keeps only {:.3g} of its probability within "
                 "[{}, {}] (at least 1e-3 needed)",
                 me, id, st, d.truncated_mass(), d.lo, d.hi);
    iarg += 5;
  } else if (st == "list") {
    need(2, "list");
    const int n = utils::inumeric(FLERR, arg[iarg + 1], false, lmp);
    if (n < 1 || n > ScaleDist::MAXLIST)
      error->all(FLERR, "{}: shape '{}': scale list needs 1..{} entries, got {}", me, id,
                 ScaleDist::MAXLIST, arg[iarg + 1]);
    need(2 + 2 * n, "list");
    d.kind = ScaleDist::LIST;
    d.nlist = n;
    double wsum = 0.0;
    for (int i = 0; i < n; i++) {
      d.val[i] = num(iarg + 2 + 2 * i);
      wsum += num(iarg + 3 + 2 * i);
      d.cum[i] = wsum;
    }
    for (int i = 0; i < n; i++) d.cum[i] /= wsum;
    d.cum[n - 1] = 1.0;
    iarg += 2 + 2 * n;
  } else {    // a bare number: constant
    d.kind = ScaleDist::CONSTANT;
    d.a = num(iarg);
    iarg += 1;
  }
}

/* ----------------------------------------------------------------------
   number probabilities of the kinds; mass fractions w_i give
   p_i ~ w_i / <m_i>, <m_i> = rho_i V_i <s^3>_i
------------------------------------------------------------------------- */

void FixInsertPolyhedron::number_probabilities()
{
  std::vector<double> p(kinds.size());
  double sum = 0.0;
  for (size_t i = 0; i < kinds.size(); i++) {
    const auto &k = kinds[i];
    p[i] = k.frac;
    if (massfrac) p[i] /= k.density * avec->shape(k.ishape).volume() * k.scale.moment(3);
    sum += p[i];
  }
  double cum = 0.0;
  for (size_t i = 0; i < kinds.size(); i++) {
    cum += p[i] / sum;
    kinds[i].pnum = cum;
  }
  kinds.back().pnum = 1.0;
}

/* ---------------------------------------------------------------------- */

int FixInsertPolyhedron::setmask()
{
  return PRE_EXCHANGE;
}

/* ---------------------------------------------------------------------- */

void FixInsertPolyhedron::init()
{
  const std::string me = "fix insert/polyhedron";
  region = polydem_compat::find_region(domain, idregion);
  if (!region) error->all(FLERR, "{}: region '{}' does not exist", me, idregion);
  if (!region->bboxflag)
    error->all(FLERR, "{}: region '{}' has no bounding box (an exterior or unbounded region)", me,
               idregion);
  if (domain->triclinic) error->all(FLERR, "{}: triclinic boxes are not supported", me);

  // the obstacles every candidate must clear (the pair styles refuse the
  // kinds of shape they do not take: ParticleSource::candidates)
  walls = InsertionObstacle::all(lmp);

  region->prematch();
  region_volume = estimate_region_volume();
  if (!(region_volume > 0.0)) error->all(FLERR, "{}: region '{}' has zero volume", me, idregion);
}

/* ----------------------------------------------------------------------
   schedule of mode rate: insertion k (k = 0, 1, ...) at step
   nstart + k every brings the totals to those of the interval it opens
------------------------------------------------------------------------- */

bigint FixInsertPolyhedron::count_target(bigint k) const
{
  // in floating point, clamped to N (or, without N, to 4e18): rate 1e25
  // overflowed the integer target, which then asked for nothing
  const double t = ratestyle == RATE_PER ? (double) (k + 1) * rate
                                         : rate * (double) ((k + 1) * every) * update->dt;
  const double cap = ntotal > 0 ? (double) ntotal : 4.0e18;
  return t < cap ? (bigint) llround(t) : (bigint) cap;
}

double FixInsertPolyhedron::mass_target(bigint k) const
{
  return rate * (double) ((k + 1) * every) * update->dt;
}

bool FixInsertPolyhedron::finished() const
{
  if (mode == MODE_PACK) return packdone;
  return (ntotal > 0 && ninserted >= ntotal) ||
      (masstotal > 0.0 && massinserted + 0.5 * mean_mass >= masstotal);
}

void FixInsertPolyhedron::do_event()
{
  bigint nmax = -1;
  double mstop = masstotal;
  if (ratestyle == RATE_MASS) {
    const double m = mass_target(nevents);
    mstop = mstop > 0.0 ? std::min(mstop, m) : m;
  } else
    nmax = std::max<bigint>(0, count_target(nevents) - ninserted);
  if (ntotal > 0) nmax = nmax < 0 ? ntotal - ninserted : std::min(nmax, ntotal - ninserted);
  const bigint failed_before = nfailed;
  insert(nmax, mstop, 0.0);
  nevents++;
  next_event += every;
  if (nfailed > failed_before && nfailed > 2 * nfailed_warned) {
    nfailed_warned = nfailed;
    if (comm->me == 0)
      error->warning(FLERR,
                     "fix insert/polyhedron: {} particle(s) found no place in {} attempts "
                     "each so far (last at step {}): region '{}' is too full; the schedule "
                     "carries them to the next insertion",
                     nfailed, attempts, update->ntimestep, idregion);
  }
}

/* ---------------------------------------------------------------------- */

void FixInsertPolyhedron::setup_pre_exchange()
{
  time_run = 0.0;
  time_start = MPI_Wtime();
  if (mode == MODE_PACK) {
    if (!packdone) {
      const bigint n0 = ninserted;
      const bigint a0 = nattempts;
      const int r = insert(ntotal > 0 ? ntotal - ninserted : -1, masstotal, phi_target);
      packdone = 1;
      const bigint n = ninserted - n0;
      if (comm->me == 0) {
        utils::logmesg(lmp,
                       "fix insert/polyhedron: packed {} particle(s) into region '{}': "
                       "solid fraction {:.4f}, {} attempts ({:.1f} per particle)\n",
                       n, idregion, last_phi, nattempts - a0,
                       n ? (double) (nattempts - a0) / n : 0.0);
        if (r < 0)
          error->warning(FLERR,
                         "fix insert/polyhedron: pack stopped at {} of the requested "
                         "particles (solid fraction {:.4f}{}): a particle found no place in {} "
                         "attempts",
                         n, last_phi,
                         phi_target > 0.0 ? fmt::format(", target {}", phi_target) : "", attempts);
      }
    }
    next_reneighbor = 0;
    return;
  }
  // a schedule left behind (reset_timestep): skip the missed insertions
  if (next_event < update->ntimestep) {
    const bigint miss = (update->ntimestep - next_event + every - 1) / every;
    next_event += miss * every;
    nevents += miss;
  }
  if (!finished() && next_event == update->ntimestep) do_event();
  next_reneighbor = finished() ? 0 : next_event;
}

void FixInsertPolyhedron::pre_exchange()
{
  if (mode == MODE_PACK || next_reneighbor != update->ntimestep) return;
  do_event();
  next_reneighbor = finished() ? 0 : next_event;
}

void FixInsertPolyhedron::post_run()
{
  if (comm->me == 0)
    utils::logmesg(lmp,
                   "fix insert/polyhedron {}: {} particle(s) inserted (mass {:.6g}), {} not "
                   "placed, {} attempts; insertion took {:.3g} s of this run ({:.2g} %)\n",
                   id, ninserted, massinserted, nfailed, nattempts, time_run,
                   100.0 * time_run / std::max(1e-30, MPI_Wtime() - time_start));
}

double FixInsertPolyhedron::max_insert_radius() const
{
  return rmax_insert;
}

void FixInsertPolyhedron::add_candidates(std::vector<Candidate> &out) const
{
  for (const auto &k : kinds) {
    const double s = k.scale.min();
    const double m = polydem::scaled_mass(k.density, avec->shape(k.ishape).volume(), s);
    out.push_back({k.ishape, s, m, itype, 1 | groupbit, id});
  }
}

double FixInsertPolyhedron::compute_scalar()
{
  return (double) ninserted;
}

// 1 inserted, 2 mass inserted, 3 not placed, 4 inserted volume / region
// volume, 5 attempts
double FixInsertPolyhedron::compute_vector(int i)
{
  switch (i) {
    case 0:
      return (double) ninserted;
    case 1:
      return massinserted;
    case 2:
      return (double) nfailed;
    case 3:
      return region_volume > 0.0 ? volinserted / region_volume : 0.0;
    default:
      return (double) nattempts;
  }
}

/* ----------------------------------------------------------------------
   restart: counts, schedule and the generator's state (exact: 32-bit
   halves of its words), so insertion continues as if uninterrupted
------------------------------------------------------------------------- */

void FixInsertPolyhedron::write_restart(FILE *fp)
{
  std::vector<double> list = {(double) RESTART_VERSION,
                              (double) seed,
                              (double) ninserted,
                              (double) nfailed,
                              (double) nattempts,
                              (double) nevents,
                              (double) nstart,
                              (double) next_event,
                              massinserted,
                              volinserted,
                              (double) packdone,
                              (double) nfailed_warned};
  for (uint64_t w : rng.s) {
    list.push_back((double) (w >> 32));
    list.push_back((double) (w & 0xffffffffULL));
  }
  // then the keywords: their text's length, and the text (key TAB values NL)
  std::string text;
  for (const auto &kv : settings) text += kv.first + "\t" + kv.second + "\n";
  list.push_back((double) text.size());
  if (comm->me == 0) {
    int size = (int) (list.size() * sizeof(double) + text.size());
    fwrite(&size, sizeof(int), 1, fp);
    fwrite(list.data(), sizeof(double), list.size(), fp);
    fwrite(text.data(), 1, text.size(), fp);
  }
}

void FixInsertPolyhedron::restart(char *buf)
{
  auto list = (double *) buf;
  const int version = (int) list[0];
  if (version != 1 && version != RESTART_VERSION)
    error->all(FLERR, "fix insert/polyhedron: restart data of an unknown version {}", list[0]);
  // a changed command: the stored state continues, with a warning for each
  // keyword that differs (version 1 kept only the seed)
  std::vector<std::pair<std::string, std::string>> stored;
  if (version == 1) {
    stored = {{"seed", canonical_numbers(std::to_string((bigint) list[1]))}};
  } else {
    const size_t len = (size_t) list[20];
    const std::string text((const char *) (list + 21), len);
    for (const auto &line : utils::split_lines(text)) {
      const size_t tab = line.find('\t');
      if (tab != std::string::npos) stored.emplace_back(line.substr(0, tab), line.substr(tab + 1));
    }
  }
  auto value_of = [](const std::vector<std::pair<std::string, std::string>> &l,
                     const std::string &key, bool &found) {
    found = false;
    std::string v;
    for (const auto &kv : l)
      if (kv.first == key) {
        found = true;
        v = kv.second;
      }
    return v;
  };
  std::vector<std::string> keys;
  for (const auto &l : {stored, settings})
    for (const auto &kv : l)
      if (std::find(keys.begin(), keys.end(), kv.first) == keys.end()) keys.push_back(kv.first);
  for (const auto &key : keys) {
    if (version == 1 && key != "seed") continue;
    bool was, is;
    const std::string a = value_of(stored, key, was), b = value_of(settings, key, is);
    if (was == is && a == b) continue;
    if (comm->me == 0)
      error->warning(FLERR,
                     "fix insert/polyhedron {}: keyword '{}' was {} when the restart file was "
                     "written, now {}: the stored counts, schedule and generator state continue",
                     id, key, was ? "'" + a + "'" : "not given", is ? "'" + b + "'" : "not given");
  }
  ninserted = (bigint) list[2];
  nfailed = (bigint) list[3];
  nattempts = (bigint) list[4];
  nevents = (bigint) list[5];
  nstart = (bigint) list[6];
  next_event = (bigint) list[7];
  massinserted = list[8];
  volinserted = list[9];
  packdone = (int) list[10];
  nfailed_warned = (bigint) list[11];
  for (int k = 0; k < 4; k++)
    rng.s[k] = ((uint64_t) list[12 + 2 * k] << 32) | (uint64_t) list[13 + 2 * k];
  next_reneighbor = finished() ? 0 : next_event;
}
