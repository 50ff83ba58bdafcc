/* ----------------------------------------------------------------------
   POLYDEM - host code shared by pair_style polyhedron and ellipsoid
------------------------------------------------------------------------- */

#include "pair_polydem.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_dummy.h"
#include "fix_neigh_history.h"
#include "force.h"
#include "math_const.h"
#include "memory.h"
#include "modify.h"
#include "neighbor.h"
#include "poly_roles.h"
#include "poly_shape_library.h"
#include "update.h"

#include "polydem_contact_law.h"
#include "polydem_history.h"
#include "polydem_parse.h"

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using MathConst::MY_PI;

// first value of the restart settings: the layout since the history
// convention of polydem_contact_law.h (older files begin with overlap/warn > 0);
// -3 adds rolling resistance (files of -2 are read with none), -4 liquid
// bridges (files of -3 are read with none), -5 the stiffness of ellipsoid
// pairs in pair_style polyhedron (files of -4 are read with none), -6 the
// viscous part of liquid bridges (files of -5 are read with none)
static constexpr double RESTART_VERSION = -7.0;
static constexpr double RESTART_VERSION_NO_PART_SLOTS = -6.0;
static constexpr double RESTART_VERSION_NO_VISCOUS = -5.0;
static constexpr double RESTART_VERSION_NO_ELLIPSOID_KN = -4.0;
static constexpr double RESTART_VERSION_NO_BRIDGE = -3.0;
static constexpr double RESTART_VERSION_NO_ROLLING = -2.0;

PairPolydem::PairPolydem(LAMMPS *lmp, const char *style, const char *tag, int nhist, int ncnt) :
    Pair(lmp), style_name(style), history_tag(tag), nhistory_base(nhist), nhistory(nhist), nhistory_contact(nhist),
    nhistory_restart(0), restart_format(3), nhistory_fix(0), ncount(ncnt), rolling(nullptr),
    cohesion(nullptr), bridge_vol(nullptr), bridge_gamma(nullptr), bridge_theta(nullptr),
    bridge_eta(nullptr), bridge_smin(nullptr),
    roll_kr(polydem::RollingLaw<double>().kr),
    roll_eta(polydem::RollingLaw<double>().eta), avec(nullptr), fix_dummy(nullptr),
    fix_history(nullptr), history_id(0), kk_binsize(0.0)
{
  if (ncount > MAXCOUNT) error->all(FLERR, "pair_style {}: too many counters", style_name);
  single_enable = 0;
  restartinfo = 1;
  no_virial_fdotr_compute = 1;
  centroidstressflag = CENTROID_NOTAVAIL;
  finitecutflag = 1;
  // one history sign convention (polydem_contact_law.h): a pair's history is
  // that of its lower-tag atom, copied to the partner unchanged
  nondefault_history_transfer = 1;
  for (int k = 0; k < MAXCOUNT; k++) counters[k] = local_counts[k] = reported[k] = 0.0;

  // placeholder so that a history fix keeps its place in the fix list
  while (modify->find_fix(dummy_fix_id()) >= 0 || modify->find_fix(history_fix_id()) >= 0)
    history_id++;
  fix_dummy = (FixDummy *) modify->add_fix(dummy_fix_id() + " all DUMMY");
}

PairPolydem::~PairPolydem()
{
  if (copymode) return;
  destroy_arrays(rolling, cohesion, bridge_vol, bridge_gamma, bridge_theta, bridge_eta,
                 bridge_smin);
  modify->delete_fix(fix_history ? history_fix_id() : dummy_fix_id());
  // the bin size a /kk style chose goes with it (kk_init_after); at the end
  // of LAMMPS the neighbor class is gone first
  if (kk_binsize > 0.0 && neighbor && neighbor->binsizeflag &&
      neighbor->binsize_user == kk_binsize)
    neighbor->binsizeflag = 0;
}

/* ----------------------------------------------------------------------
   rolling resistance: coefficients, settings, history size, restart
------------------------------------------------------------------------- */

void PairPolydem::allocate_rolling()
{
  destroy_arrays(rolling, cohesion, bridge_vol, bridge_gamma, bridge_theta, bridge_eta,
                 bridge_smin);
  create_per_type_pair(rolling, "rolling");
  create_per_type_pair(cohesion, "cohesion");
  create_per_type_pair(bridge_vol, "bridge_vol");
  create_per_type_pair(bridge_gamma, "bridge_gamma");
  create_per_type_pair(bridge_theta, "bridge_theta");
  create_per_type_pair(bridge_eta, "bridge_eta");
  create_per_type_pair(bridge_smin, "bridge_smin");
}

// the law table (polydem_law_table.h) with the settings both styles have;
// its type pairs' entries zero until init_one fills them
void PairPolydem::begin_law_table(double overlap_warn)
{
  const int nt = atom->ntypes + 1;
  law_entries.assign((size_t) nt * nt, polydem::LawEntry<double>());
  laws = polydem::law_table(law_entries.data(), atom->ntypes, nt * nt);
  laws.overlap_warn = overlap_warn;
  laws.roll_kr = roll_kr;
  laws.roll_eta = roll_eta;
}

int PairPolydem::coeff_keywords(int narg, char **arg, double &mu_r, double &coh, double *bridge,
                                double *ellipsoid_kn)
{
  mu_r = coh = 0.0;
  if (bridge)
    for (int k = 0; k < 5; k++) bridge[k] = 0.0;
  if (ellipsoid_kn) *ellipsoid_kn = 0.0;
  // each keyword: its values, where they go (null: not a keyword of this
  // style), each value's name and range (> 0, >= 0, or an angle in [0, 90))
  enum Range { POSITIVE, NONNEGATIVE, WETTING_ANGLE };
  struct Keyword {
    const char *name;
    int n;
    double *dest;
    const char *what[3];
    Range range[3];
    const char *absent;    // why dest is null
  };
  const Keyword kws[5] = {
      {"rolling", 1, &mu_r, {"rolling friction mu_r"}, {NONNEGATIVE}, ""},
      {"cohesion", 1, &coh, {"cohesion"}, {NONNEGATIVE}, ""},
      {"bridge", 3, bridge,
       {"bridge liquid volume V_b", "bridge surface tension gamma", "bridge contact angle theta"},
       {POSITIVE, POSITIVE, WETTING_ANGLE},
       "liquid bridges ('bridge') are a part of pair_style polyhedron"},
      {"viscous", 2, bridge ? bridge + 3 : nullptr,
       {"viscous viscosity eta", "viscous smallest gap s_min"},
       {POSITIVE, POSITIVE},
       "viscous liquid bridges ('viscous') are a part of pair_style polyhedron"},
      {"ellipsoid", 1, ellipsoid_kn, {"ellipsoid stiffness k_n"}, {POSITIVE},
       "'ellipsoid k_n' is a keyword of pair_style polyhedron (here k_n is the pair's own "
       "coefficient)"}};
  auto keyword = [&](const char *a) -> const Keyword * {
    for (const auto &kw : kws)
      if (strcmp(a, kw.name) == 0) return &kw;
    return nullptr;
  };
  int first = 2;
  while (first < narg && !keyword(arg[first])) first++;
  for (int k = first; k < narg;) {
    const Keyword *kw = keyword(arg[k]);
    if (!kw)
      error->all(FLERR, "pair_coeff {}: unknown keyword '{}' (after the coefficients: "
                 "'rolling mu_r', 'cohesion c'{})", style_name, arg[k],
                 bridge ? ", 'bridge V_b gamma theta', 'viscous eta s_min', 'ellipsoid k_n'"
                        : "");
    if (!kw->dest) error->all(FLERR, "pair_coeff {}: {}", style_name, kw->absent);
    if (k + kw->n >= narg)
      error->all(FLERR, "pair_coeff {}: '{}' needs {}", style_name, kw->name,
                 kw->n == 1   ? "a value"
                     : kw->n == 2 ? "two values: the liquid's viscosity eta and the smallest "
                                    "gap s_min"
                                  : "three values: the liquid volume V_b, the surface "
                                    "tension gamma and the contact angle theta in degrees");
    for (int m = 0; m < kw->n; m++) {
      const char *word = arg[k + 1 + m];
      const double v = polydem_parse::numeric(FLERR, word, lmp);
      const Range r = kw->range[m];
      const bool ok = std::isfinite(v) &&
          (r == POSITIVE ? v > 0.0 : r == NONNEGATIVE ? v >= 0.0 : v >= 0.0 && v < 90.0);
      if (!ok)
        error->all(FLERR, "pair_coeff {}: {} must be {}, got '{}'", style_name, kw->what[m],
                   r == POSITIVE      ? "> 0"
                       : r == NONNEGATIVE ? ">= 0"
                                          : "in [0, 90) degrees (a wetting liquid)",
                   word);
      kw->dest[m] = v;
    }
    k += 1 + kw->n;
  }
  if (bridge && bridge[3] > 0.0 && !(bridge[0] > 0.0))
    error->all(FLERR, "pair_coeff {}: 'viscous eta s_min' is the viscous part of a liquid "
               "bridge; give 'bridge V_b gamma theta' with it", style_name);
  return first;
}

void PairPolydem::mix_keywords(int i, int j, bool own)
{
  if (!own) {
    rolling[i][j] = sqrt(rolling[i][i] * rolling[j][j]);
    cohesion[i][j] = sqrt(cohesion[i][i] * cohesion[j][j]);
    bridge_vol[i][j] = sqrt(bridge_vol[i][i] * bridge_vol[j][j]);
    bridge_gamma[i][j] = sqrt(bridge_gamma[i][i] * bridge_gamma[j][j]);
    bridge_theta[i][j] = 0.5 * (bridge_theta[i][i] + bridge_theta[j][j]);
    bridge_eta[i][j] = sqrt(bridge_eta[i][i] * bridge_eta[j][j]);
    bridge_smin[i][j] = sqrt(bridge_smin[i][i] * bridge_smin[j][j]);
  }
  rolling[j][i] = rolling[i][j];
  cohesion[j][i] = cohesion[i][j];
  bridge_vol[j][i] = bridge_vol[i][j];
  bridge_gamma[j][i] = bridge_gamma[i][j];
  bridge_theta[j][i] = bridge_theta[i][j];
  bridge_eta[j][i] = bridge_eta[i][j];
  bridge_smin[j][i] = bridge_smin[i][j];
}

void *PairPolydem::extract_models(const char *str, int &dim)
{
  dim = 2;
  if (strcmp(str, "rolling") == 0) return (void *) rolling;
  if (strcmp(str, "cohesion") == 0) return (void *) cohesion;
  dim = 1;
  if (strcmp(str, "counters") == 0) return (void *) counters;
  dim = 0;
  if (strcmp(str, "rolling_kr") == 0) return (void *) &roll_kr;
  if (strcmp(str, "rolling_eta") == 0) return (void *) &roll_eta;
  return nullptr;
}

polydem::BridgeLaw<double> PairPolydem::bridge_law(int i, int j) const
{
  return polydem::make_bridge_law(bridge_vol[i][j], bridge_gamma[i][j],
                                  bridge_theta[i][j] * MY_PI / 180.0, bridge_eta[i][j],
                                  bridge_smin[i][j]);
}

int PairPolydem::settings_rolling(int narg, char **arg, int iarg)
{
  const bool stiff = strcmp(arg[iarg], "rolling/stiffness") == 0;
  if (!stiff && strcmp(arg[iarg], "rolling/damping") != 0) return 0;
  if (iarg + 1 >= narg) error->all(FLERR, "pair_style {}: {} needs a value", style_name, arg[iarg]);
  const double v = polydem_parse::numeric(FLERR, arg[iarg + 1], lmp);
  if (!(stiff ? v > 0.0 : v >= 0.0) || !std::isfinite(v))
    error->all(FLERR, "pair_style {}: {} must be {} 0, got '{}'", style_name, arg[iarg],
               stiff ? ">" : ">=", arg[iarg + 1]);
  (stiff ? roll_kr : roll_eta) = v;
  return 1;
}

int PairPolydem::rolling_used() const
{
  if (!rolling) return 0;
  // j >= i: pair_coeff sets those (the lower half is init_one's copy of
  // the previous run)
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++)
      if (rolling[i][j] > 0.0) return 1;
  return 0;
}

void PairPolydem::choose_history_size()
{
  nhistory_contact = rolling_used() ? polydem::CONTACT_HIST_ROLL : nhistory_base;
  const int slots = history_slots();
  nhistory = slots > 0 ? slots * (1 + nhistory_contact) : nhistory_contact;
  const char *why = "rolling resistance (pair_coeff ... rolling mu_r) is on for some type pair "
                    "in one and off for all in the other, or composite shapes (part contacts "
                    "kept per pair) are defined in one and not in the other, or their number "
                    "(pair_style polyhedron part/slots) differs";
  if (fix_history && nhistory_fix != nhistory)
    error->all(FLERR, "pair_style {}: the contact history of the previous run keeps {} values "
               "per pair, this run needs {}: {}; define pair_style again to start without "
               "history", style_name, nhistory_fix, nhistory, why);
  if (!fix_history && nhistory_restart > 0 && nhistory_restart != nhistory)
    error->all(FLERR, "pair_style {}: the restart file's contact history keeps {} values per "
               "pair, this run needs {}: {}", style_name, nhistory_restart, nhistory, why);
}

void PairPolydem::rolling_settings_fields(RestartFields &io)
{
  if (!io.has_rolling()) {
    nhistory_restart = nhistory_base;
    return;
  }
  io(roll_kr);
  io(roll_eta);
  io(nhistory);
  nhistory_restart = nhistory;
}

void PairPolydem::rolling_coeff_fields(RestartFields &io, int i, int j)
{
  if (!io.has_rolling()) return;
  io(rolling[i][j]);
  io(cohesion[i][j]);
  if (!io.has_bridge()) return;
  io(bridge_vol[i][j]);
  io(bridge_gamma[i][j]);
  io(bridge_theta[i][j]);
  if (!io.has_bridge_viscous()) return;
  io(bridge_eta[i][j]);
  io(bridge_smin[i][j]);
}

std::string PairPolydem::history_fix_id() const
{
  return history_tag + std::to_string(history_id);
}

std::string PairPolydem::dummy_fix_id() const
{
  return history_tag + "_DUMMY" + std::to_string(history_id);
}

void PairPolydem::init_common(bool history)
{
  avec = PolyShapeLibrary::of(lmp, ("pair_style " + style_name).c_str());
  if (comm->ghost_velocity == 0)
    error->all(FLERR, "pair_style {} requires ghost velocities: use 'comm_modify vel yes'",
               style_name);
  polydem_compat::request_size_list(neighbor, this, instance_me, history);
  for (int k = 0; k < MAXCOUNT; k++) counters[k] = local_counts[k] = reported[k] = 0.0;
}

void PairPolydem::setup_history_fix()
{
  if (fix_history == nullptr) {
    fix_history = polydem_history::create_history_fix(modify, history_fix_id(), dummy_fix_id(),
                                                      nhistory);
    fix_history->pair = this;
    nhistory_fix = nhistory;
  }
  const int ifix = modify->find_fix(history_fix_id());
  if (ifix < 0) error->all(FLERR, "pair_style {}: history fix not found", style_name);
  fix_history = (FixNeighHistory *) modify->fix[ifix];
}

/* ----------------------------------------------------------------------
   kernel failures and large overlaps are counted on every rank and reported
   (collectively, at reneighboring and at a run's last step) as warnings
   with counts, never silently:
   the first one, then each time a count has doubled since its last warning
   (as fix wall/mesh does)
------------------------------------------------------------------------- */

bool PairPolydem::counters_due() const
{
  return neighbor->ago == 0 || update->ntimestep == update->laststep;
}

void PairPolydem::report_counters(const char *const *what, int nwarn)
{
  MPI_Allreduce(local_counts, counters, ncount, MPI_DOUBLE, MPI_SUM, world);
  if (comm->me != 0) return;
  for (int k = 0; k < nwarn; k++)
    if (counters[k] > 0.0 && counters[k] >= 2.0 * reported[k]) {
      error->warning(FLERR, "pair {}: {:.0f} {} by step {}", style_name, counters[k], what[k],
                     update->ntimestep);
      reported[k] = counters[k];
    }
}

/* ----------------------------------------------------------------------
   particles present, and those an insertion fix may add later: LAMMPS's
   size neighbor list uses radius_i + radius_j, so particles of any size
   interact within twice the largest bounding radius
------------------------------------------------------------------------- */

double PairPolydem::size_cutoff()
{
  double rmax = ParticleSource::max_radius(lmp);
  for (int k = 0; k < atom->nlocal; k++) rmax = std::max(rmax, atom->radius[k]);
  double all;
  MPI_Allreduce(&rmax, &all, 1, MPI_DOUBLE, MPI_MAX, world);
  return 2.0 * all;
}

// the history is that of the lower-tag atom of the pair (polydem_contact_law.h):
// the partner's copy is the same numbers
void PairPolydem::transfer_history(double *source, double *target POLYDEM_TRANSFER_HISTORY_TYPES)
{
  for (int k = 0; k < nhistory; k++) target[k] = source[k];
}

/* ---------------------------------------------------------------------- */

template <class V> void PairPolydem::RestartFields::field(V &v, MPI_Datatype type)
{
  if (!reading) {
    fwrite(&v, sizeof(V), 1, fp);
    return;
  }
  if (pair->comm->me == 0) utils::sfread(FLERR, &v, sizeof(V), 1, fp, nullptr, pair->error);
  MPI_Bcast(&v, 1, type, 0, pair->world);
}

void PairPolydem::RestartFields::operator()(double &v)
{
  field(v, MPI_DOUBLE);
}

void PairPolydem::RestartFields::operator()(int &v)
{
  field(v, MPI_INT);
}

void PairPolydem::RestartFields::flag_as_double(int &v)
{
  double d = v;
  (*this)(d);
  v = d != 0.0;
}

void PairPolydem::write_restart_settings(FILE *fp)
{
  double version = RESTART_VERSION;
  RestartFields io(this, fp, false, 7);
  io(version);
  settings_fields(io);
  rolling_settings_fields(io);
}

void PairPolydem::read_restart_settings(FILE *fp)
{
  double version = 0.0;
  RestartFields head(this, fp, true, 0);
  head(version);
  if (version != RESTART_VERSION && version != RESTART_VERSION_NO_PART_SLOTS &&
      version != RESTART_VERSION_NO_VISCOUS &&
      version != RESTART_VERSION_NO_ELLIPSOID_KN &&
      version != RESTART_VERSION_NO_BRIDGE && version != RESTART_VERSION_NO_ROLLING)
    error->all(FLERR, "pair_style {}: this restart file was written by an older POLYDEM ({}); "
               "restart it with that version, or write a data file there and start from it",
               style_name, restart_version_text());
  restart_format = version == RESTART_VERSION                  ? 7
      : version == RESTART_VERSION_NO_PART_SLOTS                 ? 6
      : version == RESTART_VERSION_NO_VISCOUS                    ? 5
      : version == RESTART_VERSION_NO_ELLIPSOID_KN               ? 4
      : version == RESTART_VERSION_NO_BRIDGE                     ? 3
                                                                 : 2;
  RestartFields io(this, fp, true, restart_format);
  settings_fields(io);
  rolling_settings_fields(io);
}

void PairPolydem::write_restart(FILE *fp)
{
  write_restart_settings(fp);
  RestartFields io(this, fp, false, 7);
  coeff_fields(io);
}

void PairPolydem::read_restart(FILE *fp)
{
  read_restart_settings(fp);
  allocate();
  RestartFields io(this, fp, true, restart_format);
  coeff_fields(io);
}
