/* ----------------------------------------------------------------------
   POLYDEM - pair_style ellipsoid
------------------------------------------------------------------------- */

#include "pair_ellipsoid.h"

#include "atom.h"
#include "poly_roles.h"
#include "poly_timestep.h"
#include "poly_shape_library.h"
#include "comm.h"
#include "error.h"
#include "fix_neigh_history.h"
#include "force.h"
#include "math_const.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neigh_request.h"
#include "neighbor.h"
#include "update.h"

#include "polydem_contact_pipeline.h"
#include "polydem_damping.h"
#include "polydem_history.h"
#include "polydem_lammps_compat.h"
#include "polydem_parse.h"
#include "polydem_shape_template.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using MathConst::MY_PI;

static constexpr int SIZE_HISTORY = polydem::ELLIPSOID_HIST;    // s (polydem_contact_law.h)

/* ---------------------------------------------------------------------- */

PairEllipsoid::PairEllipsoid(LAMMPS *lmp) :
    PairPolydem(lmp, "ellipsoid", "NEIGH_HISTORY_ELL", SIZE_HISTORY, NCOUNT), kn(nullptr),
    restitution(nullptr), friction(nullptr), kt_ratio(polydem::ELLIPSOID_KT_RATIO),
    gt_ratio(polydem::ELLIPSOID_GT_RATIO), use_history(0),
    overlap_warn(0.05), overlap(polydem::OVERLAP_CENTRE), damping_mass(polydem::DAMPING_REDUCED)
{
  // compute pair ellipsoid: [1] collisions started, [2] pair-steps in contact (this run;
  // a pair with a ghost atom counts 1/2 on each rank when newton_pair is off)
  nextra = 2;
  pvector = new double[nextra];
  pvector[0] = pvector[1] = 0.0;
}

PairEllipsoid::~PairEllipsoid()
{
  if (copymode) return;
  delete[] pvector;
  if (allocated) destroy_arrays(setflag, cutsq, kn, restitution, friction);
}

void PairEllipsoid::allocate()
{
  allocated = 1;
  create_per_type_pair(setflag, "setflag");
  create_per_type_pair(cutsq, "cutsq");
  create_per_type_pair(kn, "kn");
  create_per_type_pair(restitution, "restitution");
  create_per_type_pair(friction, "friction");
  allocate_rolling();
}

/* ----------------------------------------------------------------------
   pair_style ellipsoid [overlap centre|chord] [damping reduced|contact] [overlap/warn f]
                        [tangential kt/kn gammat/gamman]
                        [rolling/stiffness f] [rolling/damping eta]
------------------------------------------------------------------------- */

void PairEllipsoid::settings(int narg, char **arg)
{
  overlap_warn = 0.05;
  overlap = polydem::OVERLAP_CENTRE;
  damping_mass = polydem::DAMPING_REDUCED;
  kt_ratio = polydem::ELLIPSOID_KT_RATIO;
  gt_ratio = polydem::ELLIPSOID_GT_RATIO;
  roll_kr = polydem::RollingLaw<double>().kr;
  roll_eta = polydem::RollingLaw<double>().eta;
  for (int iarg = 0; iarg < narg; iarg += 2) {
    if (settings_rolling(narg, arg, iarg)) continue;
    if (strcmp(arg[iarg], "overlap") == 0) {
      const std::string v = iarg + 1 < narg ? arg[iarg + 1] : "";
      if (v == "centre") overlap = polydem::OVERLAP_CENTRE;
      else if (v == "chord") overlap = polydem::OVERLAP_CHORD;
      else error->all(FLERR, "pair_style ellipsoid: overlap needs 'centre' or 'chord', got '{}'", v);
    } else if (strcmp(arg[iarg], "damping") == 0) {
      const std::string v = iarg + 1 < narg ? arg[iarg + 1] : "";
      if (v == "reduced") damping_mass = polydem::DAMPING_REDUCED;
      else if (v == "contact") damping_mass = polydem::DAMPING_CONTACT;
      else error->all(FLERR, "pair_style ellipsoid: damping needs 'reduced' or 'contact', got '{}'", v);
    } else if (strcmp(arg[iarg], "overlap/warn") == 0) {
      if (iarg + 1 >= narg) error->all(FLERR, "pair_style ellipsoid: overlap/warn needs a value");
      overlap_warn = polydem_parse::numeric(FLERR, arg[iarg + 1], lmp);
      if (!(overlap_warn > 0.0) || !(overlap_warn <= 1.0))
        error->all(FLERR, "pair_style ellipsoid: overlap/warn must be in (0, 1], got '{}'",
                   arg[iarg + 1]);
    } else if (strcmp(arg[iarg], "tangential") == 0) {
      if (iarg + 2 >= narg)
        error->all(FLERR, "pair_style ellipsoid: tangential needs 2 values: kt/kn gammat/gamman");
      kt_ratio = polydem_parse::numeric(FLERR, arg[iarg + 1], lmp);
      gt_ratio = polydem_parse::numeric(FLERR, arg[iarg + 2], lmp);
      if (!(kt_ratio > 0.0) || !std::isfinite(kt_ratio))
        error->all(FLERR, "pair_style ellipsoid: tangential kt/kn must be > 0, got '{}'",
                   arg[iarg + 1]);
      if (!(gt_ratio >= 0.0) || !std::isfinite(gt_ratio))
        error->all(FLERR, "pair_style ellipsoid: tangential gammat/gamman must be >= 0, got '{}'",
                   arg[iarg + 2]);
      iarg++;
    } else
      error->all(FLERR, "pair_style ellipsoid: unknown keyword '{}'", arg[iarg]);
  }
}

/* ----------------------------------------------------------------------
   pair_coeff I J kn e [mu] [rolling mu_r] [cohesion Gamma] : normal
   stiffness (force/length), restitution, Coulomb friction (default 0:
   frictionless, the seed's model), rolling friction and DMT surface energy
   (default 0: none)
------------------------------------------------------------------------- */

void PairEllipsoid::coeff(int nargs, char **arg)
{
  if (!allocated) allocate();
  double mu_r = 0.0, coh = 0.0;
  const int narg = coeff_keywords(nargs, arg, mu_r, coh);
  if (narg != 4 && narg != 5)
    error->all(FLERR, "pair_coeff ellipsoid: expected 'I J kn e [mu] [rolling mu_r] "
               "[cohesion Gamma]', got {} values", nargs);
  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);
  const double k = polydem_parse::numeric(FLERR, arg[2], lmp);
  const double e = polydem_parse::numeric(FLERR, arg[3], lmp);
  if (!(k > 0.0) || !std::isfinite(k))
    error->all(FLERR, "pair_coeff ellipsoid: stiffness kn must be > 0, got '{}'", arg[2]);
  if (!(e > 0.0 && e <= 1.0))
    error->all(FLERR, "pair_coeff ellipsoid: restitution e must be in (0, 1], got '{}'", arg[3]);
  const double mu = narg == 5 ? polydem_parse::numeric(FLERR, arg[4], lmp) : 0.0;
  if (!(mu >= 0.0) || !std::isfinite(mu))
    error->all(FLERR, "pair_coeff ellipsoid: friction mu must be >= 0, got '{}'", arg[4]);
  int count = 0;
  for (int i = ilo; i <= ihi; i++)
    for (int j = MAX(jlo, i); j <= jhi; j++) {
      kn[i][j] = k;
      restitution[i][j] = e;
      friction[i][j] = mu;
      rolling[i][j] = mu_r;
      cohesion[i][j] = coh;
      setflag[i][j] = 1;
      count++;
    }
  if (count == 0) error->all(FLERR, "Incorrect args for pair coefficients");
}

/* ---------------------------------------------------------------------- */

void PairEllipsoid::init_style()
{
  // friction: per-pair tangential history (kept once created, e.g. from a restart)
  use_history = friction_used() || rolling_used() || fix_history != nullptr;
  init_common(use_history);
  choose_history_size();
  // mixed polyhedron-ellipsoid contacts are not supported
  int npoly = 0, first = -1;
  for (int i = 0; i < atom->nlocal; i++)
    if (!avec->shape(atom->pshape[i]).is_ellipsoid()) {
      if (first < 0) first = atom->pshape[i];
      npoly++;
    }
  // and those an insertion fix will add
  for (const auto &c : ParticleSource::candidates(lmp))
    if (!avec->shape(c.ishape).is_ellipsoid())
      error->all(FLERR, "fix {}: shape '{}' is a polyhedron, but pair_style ellipsoid takes "
                 "ellipsoids only", c.source, avec->shape_id(c.ishape));
  int all;
  MPI_Allreduce(&npoly, &all, 1, MPI_INT, MPI_SUM, world);
  if (all) {
    int f = first, gf;
    MPI_Allreduce(&f, &gf, 1, MPI_INT, MPI_MAX, world);
    error->all(FLERR, "pair_style ellipsoid: {} atoms have a polyhedron or composite shape "
               "(e.g. '{}'); define their shape with 'polyhedron_shape ID ellipsoid a b c' or "
               "use pair_style polyhedron, which takes polyhedra together with spheres and "
               "composites", all, avec->shape_id(gf));
  }

  if (use_history) setup_history_fix();

  // the law table: settings now, the type pairs' entries in init_one
  begin_law_table(overlap_warn);
  laws.kt_ratio = kt_ratio;
  laws.gt_ratio = gt_ratio;
  laws.overlap = overlap;
  laws.damping_mass = damping_mass;
  laws.nhist = nhistory;

  check_timestep();
}

// some type pair has friction (all ranks agree: coefficients are global)
int PairEllipsoid::friction_used() const
{
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++)
      if (setflag[i][j] && friction[i][j] > 0.0) return 1;
  return 0;
}

/* ----------------------------------------------------------------------
   unlike pairs without explicit coefficients: geometric means.
   Cutoff: twice the largest bounding radius present (size neighbor list).
------------------------------------------------------------------------- */

double PairEllipsoid::init_one(int i, int j)
{
  if (!setflag[i][j]) {
    if (!setflag[i][i] || !setflag[j][j])
      error->all(FLERR, "pair_coeff ellipsoid: no coefficients for type {}",
                 setflag[i][i] ? j : i);
    kn[i][j] = sqrt(kn[i][i] * kn[j][j]);
    restitution[i][j] = sqrt(restitution[i][i] * restitution[j][j]);
    friction[i][j] = sqrt(friction[i][i] * friction[j][j]);
  }
  kn[j][i] = kn[i][j];
  restitution[j][i] = restitution[i][j];
  friction[j][i] = friction[i][j];
  mix_keywords(i, j, setflag[i][j]);
  // the law table's entries of the pair (friction only with a history)
  const int nt = atom->ntypes + 1;
  polydem::LawEntry<double> e = polydem::LawEntry<double>();
  e.kn = kn[i][j];
  e.mu = use_history ? friction[i][j] : 0.0;
  e.mu_r = use_history ? rolling[i][j] : 0.0;
  e.cohesion = cohesion[i][j];
  e.damping = polydem::damping_law(restitution[i][j], 1);
  law_entries[i * nt + j] = law_entries[j * nt + i] = e;
  return size_cutoff();
}

/* ----------------------------------------------------------------------
   contact time of the lightest like pair: t_c = pi sqrt(m12 / k_n) (seed §4)
------------------------------------------------------------------------- */

void PairEllipsoid::check_timestep()
{
  TimestepCheck check;
  for (int i = 0; i < atom->nlocal; i++) {
    const int t = atom->type[i];
    check.contact(0.5 * atom->rmass[i], kn[t][t] * force->ftm2v);
  }
  check.report(lmp, "pair ellipsoid", "lightest like pair", "", 0.0);
}

/* ---------------------------------------------------------------------- */

void PairEllipsoid::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  double **x = atom->x, **f = atom->f, **torque = atom->torque;
  double *radius = atom->radius;
  int *pshape = atom->pshape;
  const int nlocal = atom->nlocal;
  const int newton_pair = force->newton_pair;
  const int inum = list->inum;
  int *ilist = list->ilist, *numneigh = list->numneigh, **firstneigh = list->firstneigh;
  int **firsttouch = use_history ? fix_history->firstflag : nullptr;
  double **firstshear = use_history ? fix_history->firstvalue : nullptr;
  const bool update_history = update->setupflag == 0;

  // gather: atom k with its template's semi-axes
  const auto atoms = polydem::host_atoms(atom);
  auto body = [&](int k) {
    const auto &ax = avec->shape(pshape[k]).semi_axes();
    return polydem::gather_ellipsoid_body(atoms, k, polydem::make_vec3(ax[0], ax[1], ax[2]));
  };

  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    const auto A = body(i);
    const int *jlist = firstneigh[i];
    const int jnum = numneigh[i];
    for (int jj = 0; jj < jnum; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      double *shear = use_history ? &firstshear[i][nhistory * jj] : nullptr;
      const double delx = x[i][0] - x[j][0], dely = x[i][1] - x[j][1], delz = x[i][2] - x[j][2];
      const double radsum = radius[i] + radius[j];
      // a pair with a ghost j is seen on two ranks when newton_pair is off
      const bool to_j = newton_pair || j < nlocal;
      polydem::PairContactResult<double> c;
      c.contact = 0;
      if (delx * delx + dely * dely + delz * delz >= radsum * radsum)
        polydem::history_release(shear, nhistory);
      else
        c = polydem::ellipsoid_pair_contact(A, body(j), laws, update->dt, update_history, shear,
                                            to_j ? 1.0 : 0.5, local_counts);
      if (use_history) firsttouch[i][jj] = c.contact;
      if (!c.contact) continue;
      polydem::scatter_contact_host(f, torque, i, j, to_j, c.cf);
      if (evflag)
        ev_tally_xyz(i, j, nlocal, newton_pair, c.cf.energy, 0.0, c.cf.F_A.x, c.cf.F_A.y,
                     c.cf.F_A.z, delx, dely, delz);
    }
  }
  pvector[0] = local_counts[polydem::EP_COLLISIONS];
  pvector[1] = local_counts[polydem::EP_CONTACTS];
  if (counters_due()) report_counters();
}

/* ----------------------------------------------------------------------
   kernel failures and large overlaps: counted, reported as warnings
------------------------------------------------------------------------- */

void PairEllipsoid::report_counters()
{
  const char *what[] = {"degenerate contacts (coincident centres or NaN; skipped)",
                        "contact searches without convergence (skipped)",
                        "overlaps beyond overlap/warn of the smallest semi-axis",
                        "contact-steps whose normal dashpot was capped at m_eff/dt, less "
                        "damping than asked: the time step is too long for these contacts"};
  PairPolydem::report_counters(what, polydem::EP_CONTACTS);
}

/* ----------------------------------------------------------------------
   restart: the settings, then per type pair (j >= i) whether it was set
   and its coefficients
------------------------------------------------------------------------- */

void PairEllipsoid::settings_fields(RestartFields &io)
{
  io(overlap_warn);
  io(overlap);
  io(damping_mass);
  io(kt_ratio);
  io(gt_ratio);
}

const char *PairEllipsoid::restart_version_text() const
{
  return "another sign convention of the friction history";
}

void PairEllipsoid::coeff_fields(RestartFields &io)
{
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      io(setflag[i][j]);
      if (setflag[i][j]) {
        io(kn[i][j]);
        io(restitution[i][j]);
        io(friction[i][j]);
        rolling_coeff_fields(io, i, j);
      }
    }
}

void *PairEllipsoid::extract(const char *str, int &dim)
{
  dim = 2;
  if (strcmp(str, "kn") == 0) return (void *) kn;
  if (strcmp(str, "restitution") == 0) return (void *) restitution;
  if (strcmp(str, "friction") == 0) return (void *) friction;
  dim = 0;    // tangential k_t / k_n and gamma_t / gamma_n (fix wall/mesh)
  if (strcmp(str, "kt_ratio") == 0) return (void *) &kt_ratio;
  if (strcmp(str, "gt_ratio") == 0) return (void *) &gt_ratio;
  return extract_models(str, dim);
}
