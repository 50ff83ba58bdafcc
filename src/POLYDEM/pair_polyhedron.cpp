/* ----------------------------------------------------------------------
   POLYDEM - pair_style polyhedron
------------------------------------------------------------------------- */

#include "pair_polyhedron.h"

#include "atom.h"
#include "poly_roles.h"
#include "poly_shape_library.h"
#include "comm.h"
#include "error.h"
#include "fix_dummy.h"
#include "fix_neigh_history.h"
#include "force.h"
#include "math_const.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neigh_request.h"
#include "neighbor.h"
#include "update.h"

#include "compute.h"
#include "polydem_contact_pipeline.h"
#include "polydem_contact_record.h"
#include "polydem_damping.h"
#include "polydem_history.h"
#include "polydem_lammps_compat.h"
#include "polydem_overlap.h"
#include "polydem_parse.h"
#include "polydem_shape_template.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using MathConst::MY_PI;

static constexpr int SIZE_HISTORY = polydem::CONTACT_HIST;    // s, k_t, twist (polydem_contact_law.h)
static_assert(int(PairPolyhedron::CNT_OVERFLOW) == int(polydem::PP_OVERFLOW) &&
                  int(PairPolyhedron::CNT_DEGENERATE) == int(polydem::PP_DEGENERATE) &&
                  int(PairPolyhedron::CNT_NOCONV) == int(polydem::PP_NOCONV) &&
                  int(PairPolyhedron::CNT_BIGOVERLAP) == int(polydem::PP_BIGOVERLAP) &&
                  int(PairPolyhedron::CNT_CONTACTS) == int(polydem::PP_CONTACTS) &&
                  int(PairPolyhedron::NCOUNT) == int(polydem::PP_NCOUNT),
              "counters in the order of the pipeline's");
// first value of the restart settings since the history has 5 values (older
// files begin with overlap/warn, which is > 0)
static constexpr double RESTART_VERSION = -2.0;

/* ---------------------------------------------------------------------- */

PairPolyhedron::PairPolyhedron(LAMMPS *lmp) :
    Pair(lmp), youngs(nullptr), poisson(nullptr), matset(nullptr), restitution(nullptr),
    friction(nullptr), pairset(nullptr), twist(0), overlap_warn(0.05), core(1.0e-4), dt(0.0),
    avec(nullptr),
    fix_dummy(nullptr), fix_history(nullptr), contact_step(-1)
{
  single_enable = 0;
  restartinfo = 1;
  no_virial_fdotr_compute = 1;
  centroidstressflag = CENTROID_NOTAVAIL;
  finitecutflag = 1;
  // one history sign convention (polydem_contact_law.h): a pair's history is
  // that of its lower-tag atom, copied to the partner unchanged
  nondefault_history_transfer = 1;
  for (int k = 0; k < NCOUNT; k++) counters[k] = local_counts[k] = reported[k] = 0.0;

  ws = std::make_unique<polydem::OverlapWorkspace<double, 128>>();

  // placeholder so that the history fix keeps its place in the fix list
  history_id = 0;
  while (modify->find_fix("NEIGH_HISTORY_POLY_DUMMY" + std::to_string(history_id)) >= 0 ||
         modify->find_fix("NEIGH_HISTORY_POLY" + std::to_string(history_id)) >= 0)
    history_id++;
  fix_dummy = (FixDummy *) modify->add_fix("NEIGH_HISTORY_POLY_DUMMY" +
                                           std::to_string(history_id) + " all DUMMY");
}

PairPolyhedron::~PairPolyhedron()
{
  if (copymode) return;
  if (!fix_history)
    modify->delete_fix("NEIGH_HISTORY_POLY_DUMMY" + std::to_string(history_id));
  else
    modify->delete_fix("NEIGH_HISTORY_POLY" + std::to_string(history_id));
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
    memory->destroy(youngs);
    memory->destroy(poisson);
    memory->destroy(matset);
    memory->destroy(restitution);
    memory->destroy(friction);
    memory->destroy(pairset);
  }
}

/* ---------------------------------------------------------------------- */

void PairPolyhedron::allocate()
{
  allocated = 1;
  const int n = atom->ntypes;
  memory->create(setflag, n + 1, n + 1, "pair:setflag");
  memory->create(cutsq, n + 1, n + 1, "pair:cutsq");
  memory->create(youngs, n + 1, "pair:youngs");
  memory->create(poisson, n + 1, "pair:poisson");
  memory->create(matset, n + 1, "pair:matset");
  memory->create(restitution, n + 1, n + 1, "pair:restitution");
  memory->create(friction, n + 1, n + 1, "pair:friction");
  memory->create(pairset, n + 1, n + 1, "pair:pairset");
  for (int i = 0; i <= n; i++) {
    youngs[i] = poisson[i] = 0.0;
    matset[i] = 0;
    for (int j = 0; j <= n; j++) {
      setflag[i][j] = pairset[i][j] = 0;
      restitution[i][j] = friction[i][j] = 0.0;
    }
  }
}

/* ----------------------------------------------------------------------
   pair_style polyhedron [overlap/warn f] [core f] [twist yes|no]
------------------------------------------------------------------------- */

void PairPolyhedron::settings(int narg, char **arg)
{
  overlap_warn = 0.05;
  core = 1.0e-4;
  twist = 0;
  for (int iarg = 0; iarg < narg; iarg += 2) {
    if (strcmp(arg[iarg], "twist") == 0) {
      if (iarg + 1 >= narg || (strcmp(arg[iarg + 1], "yes") && strcmp(arg[iarg + 1], "no")))
        error->all(FLERR, "pair_style polyhedron: twist expects yes or no");
      twist = strcmp(arg[iarg + 1], "yes") == 0;
      continue;
    }
    if (strcmp(arg[iarg], "core") == 0) {
      if (iarg + 1 >= narg) error->all(FLERR, "pair_style polyhedron: core needs a value");
      core = polydem_parse::numeric(FLERR, arg[iarg + 1], lmp);
      if (!(core >= 0.0 && core < 1.0))
        error->all(FLERR, "pair_style polyhedron: core must be in [0, 1), got '{}'",
                   arg[iarg + 1]);
      continue;
    }
    if (strcmp(arg[iarg], "overlap/warn") == 0) {
      if (iarg + 1 >= narg) error->all(FLERR, "pair_style polyhedron: overlap/warn needs a value");
      overlap_warn = polydem_parse::numeric(FLERR, arg[iarg + 1], lmp);
      if (!(overlap_warn > 0.0) || !(overlap_warn <= 1.0))
        error->all(FLERR, "pair_style polyhedron: overlap/warn must be in (0, 1], got '{}'",
                   arg[iarg + 1]);
    } else
      error->all(FLERR, "pair_style polyhedron: unknown keyword '{}'", arg[iarg]);
  }
}

/* ----------------------------------------------------------------------
   pair_coeff I J E nu e mu : material (E, nu) of the types in I and J,
                              restitution e and friction mu of the pairs
   pair_coeff I J e mu      : e and mu of unlike pairs (I != J) only
------------------------------------------------------------------------- */

void PairPolyhedron::coeff(int narg, char **arg)
{
  if (narg != 4 && narg != 6)
    error->all(FLERR, "pair_coeff polyhedron: expected 'I J E nu e mu' or 'I J e mu', got {} "
               "values", narg);
  if (!allocated) allocate();
  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);

  double E = 0.0, nu = 0.0;
  int k = 2;
  if (narg == 6) {
    E = polydem_parse::numeric(FLERR, arg[2], lmp);
    nu = polydem_parse::numeric(FLERR, arg[3], lmp);
    if (!(E > 0.0) || !std::isfinite(E))
      error->all(FLERR, "pair_coeff polyhedron: Young's modulus E must be > 0, got '{}'", arg[2]);
    if (!(nu > -1.0 && nu < 0.5))
      error->all(FLERR, "pair_coeff polyhedron: Poisson's ratio must be in (-1, 0.5), got '{}'",
                 arg[3]);
    k = 4;
  }
  const double e = polydem_parse::numeric(FLERR, arg[k], lmp);
  const double mu = polydem_parse::numeric(FLERR, arg[k + 1], lmp);
  if (!(e > 0.0 && e <= 1.0))
    error->all(FLERR, "pair_coeff polyhedron: restitution e must be in (0, 1], got '{}'", arg[k]);
  if (!(mu >= 0.0) || !std::isfinite(mu))
    error->all(FLERR, "pair_coeff polyhedron: friction mu must be >= 0, got '{}'", arg[k + 1]);

  int count = 0;
  for (int i = ilo; i <= ihi; i++)
    for (int j = MAX(jlo, i); j <= jhi; j++) {
      if (narg == 4 && i == j)
        error->all(FLERR, "pair_coeff polyhedron: type {} needs its material: 'I I E nu e mu'", i);
      if (narg == 6) {
        youngs[i] = youngs[j] = E;
        poisson[i] = poisson[j] = nu;
        matset[i] = matset[j] = 1;
      }
      restitution[i][j] = e;
      friction[i][j] = mu;
      pairset[i][j] = 1;
      setflag[i][j] = 1;
      count++;
    }
  if (count == 0) error->all(FLERR, "Incorrect args for pair coefficients");
}

/* ---------------------------------------------------------------------- */

void PairPolyhedron::init_style()
{
  avec = PolyShapeLibrary::of(lmp, "pair_style polyhedron");
  if (comm->ghost_velocity == 0)
    error->all(FLERR, "pair_style polyhedron requires ghost velocities: use 'comm_modify vel yes'");
  for (int t = 0; t < avec->ntemplates(); t++)
    if (avec->shape(t).nfaces() > 128)
      error->all(FLERR, "pair_style polyhedron: shape '{}' has {} faces, more than 128",
                 avec->shape_id(t), avec->shape(t).nfaces());
  // ellipsoid templates belong to pair_style ellipsoid (mixed contacts not supported)
  int nell = 0;
  for (int i = 0; i < atom->nlocal; i++) nell += avec->shape(atom->pshape[i]).is_ellipsoid();
  MPI_Allreduce(MPI_IN_PLACE, &nell, 1, MPI_INT, MPI_SUM, world);
  if (nell) error->all(FLERR, "pair_style polyhedron: {} atoms have an ellipsoid shape; "
                       "use pair_style ellipsoid (mixed contacts are not supported)", nell);
  // and those an insertion fix will add
  for (const auto &c : ParticleSource::candidates(lmp))
    if (avec->shape(c.ishape).is_ellipsoid())
      error->all(FLERR, "fix {}: shape '{}' is an ellipsoid, but pair_style polyhedron takes "
                 "polyhedra only", c.source, avec->shape_id(c.ishape));

  polydem_compat::request_size_list(neighbor, this, instance_me, true);

  dt = update->dt;

  // the law table: settings now, the type pairs' entries in init_one
  const int nt = atom->ntypes + 1;
  law_entries.assign((size_t) nt * nt, polydem::LawEntry<double>());
  laws = polydem::law_table(law_entries.data(), atom->ntypes, nt * nt);
  laws.core = core;
  laws.twist = twist;
  laws.overlap_warn = overlap_warn;

  if (fix_history == nullptr) {
    fix_history = polydem_history::create_history_fix(
        modify, "NEIGH_HISTORY_POLY" + std::to_string(history_id),
        "NEIGH_HISTORY_POLY_DUMMY" + std::to_string(history_id), SIZE_HISTORY);
    fix_history->pair = this;
  }
  int ifix = modify->find_fix("NEIGH_HISTORY_POLY" + std::to_string(history_id));
  if (ifix < 0) error->all(FLERR, "pair_style polyhedron: history fix not found");
  fix_history = (FixNeighHistory *) modify->fix[ifix];

  for (int k = 0; k < NCOUNT; k++) counters[k] = local_counts[k] = reported[k] = 0.0;
  check_timestep();
}

/* ----------------------------------------------------------------------
   unlike pairs without explicit e, mu: geometric means of the like pairs.
   Cutoff: twice the largest bounding radius present (particles of any
   size interact; LAMMPS's size neighbor list uses radius_i + radius_j).
------------------------------------------------------------------------- */

double PairPolyhedron::init_one(int i, int j)
{
  if (!matset[i] || !matset[j])
    error->all(FLERR, "pair_coeff polyhedron: no material (E nu e mu) for type {}",
               matset[i] ? j : i);
  if (!pairset[i][j]) {
    restitution[i][j] = sqrt(restitution[i][i] * restitution[j][j]);
    friction[i][j] = sqrt(friction[i][i] * friction[j][j]);
  }
  restitution[j][i] = restitution[i][j];
  friction[j][i] = friction[i][j];
  // the law table's entries of the pair, damping in closed form (polydem_damping.h)
  const int nt = atom->ntypes + 1;
  const auto damp = polydem::damping_law(restitution[i][j], 1);
  auto fill = [&](int a, int b) {
    auto &e = law_entries[a * nt + b];
    e.E1 = youngs[a];
    e.nu1 = poisson[a];
    e.E2 = youngs[b];
    e.nu2 = poisson[b];
    e.kn = 0.0;
    e.mu = friction[i][j];
    e.damping = damp;
  };
  fill(i, j);
  fill(j, i);

  // particles present, and those an insertion fix may add later
  double rmax = ParticleSource::max_radius(lmp);
  for (int k = 0; k < atom->nlocal; k++) rmax = MAX(rmax, atom->radius[k]);
  double all;
  MPI_Allreduce(&rmax, &all, 1, MPI_DOUBLE, MPI_MAX, world);
  return 2.0 * all;
}

/* ----------------------------------------------------------------------
   printed estimate of the contact time: a like pair of the stiffest, lightest
   particle with a contact patch of area R^2 (R: volume-equivalent radius),
   k_n = K R^2 = 2 E R (Eq. 13), t_c = pi sqrt(m_eff / k_n)
------------------------------------------------------------------------- */

void PairPolyhedron::check_timestep()
{
  double tc[2] = {1e300, 1e300};    // contact time, face-contact stability limit
  auto consider = [&](int ishape, double s, double m, int type) {
    const auto &shape = avec->shape(ishape);
    const double V = shape.volume();
    const double R = s * cbrt(3.0 * V / (4.0 * MY_PI));
    const double kn = 2.0 * youngs[type] * R;
    tc[0] = MIN(tc[0], MY_PI * sqrt(0.5 * m / (kn * force->ftm2v)));
    // like pair of this particle, its largest face flat on another's
    const double Vs = V * s * s * s, ms = m / force->ftm2v;
    const auto law = polydem::feng_law(youngs[type], 0.0, Vs, youngs[type], 0.0, Vs,
                                       polydem::damping_law(1.0, 0), 0.0, core, 0);
    const double dtf = polydem::face_contact_stable_dt(law.normal, ms * ms / (ms + ms),
                                                       shape.max_face_area() * s * s);
    if (dtf > 0.0) tc[1] = MIN(tc[1], dtf);
  };
  for (int i = 0; i < atom->nlocal; i++)
    consider(atom->pshape[i], atom->pscale[i], atom->rmass[i], atom->type[i]);
  // and the smallest of each kind an insertion fix will add
  for (const auto &c : ParticleSource::candidates(lmp))
    if (!avec->shape(c.ishape).is_ellipsoid()) consider(c.ishape, c.scale, c.mass, c.type);
  double all[2];
  MPI_Allreduce(tc, all, 2, MPI_DOUBLE, MPI_MIN, world);
  if (all[0] >= 1e300 || comm->me != 0) return;
  utils::logmesg(lmp, "pair polyhedron: estimated contact time {:.4g}, timestep {:.4g} = t_c/{:.3g}\n",
                 all[0], update->dt, all[0] / update->dt);
  if (update->dt > all[0] / 10.0)
    error->warning(FLERR, "pair polyhedron: timestep {:.4g} exceeds t_c/10 = {:.4g} (estimated "
                   "contact time {:.4g}): contacts will be poorly resolved",
                   update->dt, all[0] / 10.0, all[0]);
  if (all[1] < 1e300) {
    utils::logmesg(lmp, "pair polyhedron: a flat face contact in the core (core {}) is stable "
                   "for timesteps below {:.4g}, resolved below about {:.4g}\n", core, all[1],
                   all[1] / 20.0);
    if (update->dt > 0.5 * all[1])
      error->warning(FLERR, "pair polyhedron: timestep {:.4g} exceeds half of {:.4g}, the "
                     "stability limit of a largest face resting flat in the core (stiffness 5/3 K "
                     "V0^(-2/3) A^2): flat contacts may stick or gain energy; lower the timestep "
                     "or raise core", update->dt, all[1]);
  }
}

/* ---------------------------------------------------------------------- */

void PairPolyhedron::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  const bool shearupdate = !update->setupflag;
  dt = update->dt;

  double **x = atom->x, **f = atom->f, **torque = atom->torque;
  double *radius = atom->radius;
  int *pshape = atom->pshape;
  const int nlocal = atom->nlocal;
  const int newton_pair = force->newton_pair;

  const bool store = store_contacts_now();
  tagint *tag = atom->tag;
  int *mask = atom->mask;

  const int inum = list->inum;
  int *ilist = list->ilist, *numneigh = list->numneigh, **firstneigh = list->firstneigh;
  int **firsttouch = fix_history->firstflag;
  double **firstshear = fix_history->firstvalue;

  const auto atoms = polydem::host_atoms(atom);

  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    int *touch = firsttouch[i];
    double *allshear = firstshear[i];
    int *jlist = firstneigh[i];
    const int jnum = numneigh[i];
    const auto vi = avec->shape(pshape[i]).view();
    const auto A = polydem::gather_polyhedron_body(atoms, i, vi);

    for (int jj = 0; jj < jnum; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      double *shear = &allshear[SIZE_HISTORY * jj];
      const double delx = x[i][0] - x[j][0], dely = x[i][1] - x[j][1],
                   delz = x[i][2] - x[j][2];
      const double radsum = radius[i] + radius[j];
      if (delx * delx + dely * dely + delz * delz >= radsum * radsum) {
        touch[jj] = 0;
        polydem::history_release(shear, SIZE_HISTORY);
        continue;
      }
      const auto vj = avec->shape(pshape[j]).view();
      const auto B = polydem::gather_polyhedron_body(atoms, j, vj);
      const auto c =
          polydem::polyhedron_pair_contact(A, B, laws, dt, shearupdate, shear, *ws, local_counts);
      touch[jj] = c.contact;
      if (!c.contact) continue;
      polydem::scatter_contact_host(f, torque, i, j, newton_pair || j < nlocal, c.cf);
      if (evflag)
        ev_tally_xyz(i, j, nlocal, newton_pair, c.cf.energy, 0.0, c.cf.F_A.x, c.cf.F_A.y,
                     c.cf.F_A.z, delx, dely, delz);
      if (store && polydem::contact_owned(newton_pair, j < nlocal, tag[i], tag[j], x[i], x[j])) {
        contact_data.resize(contact_data.size() + polydem::CR_NFIELD);
        polydem::fill_contact_record(&contact_data[contact_data.size() - polydem::CR_NFIELD],
                                     tag[i], tag[j], mask[i], mask[j], c.vmin, c.geo, c.cf);
      }
    }
  }
  if (store) contact_step = update->ntimestep;
  if (neighbor->ago == 0) report_counters(false);
}

/* ----------------------------------------------------------------------
   store per-contact records this step if a contact compute is due now
   (same mechanism as compute pe: Compute::timeflag and matchstep)
------------------------------------------------------------------------- */

bool PairPolyhedron::store_contacts_now()
{
  bool due = false;
  for (int k = 0; k < modify->ncompute; k++) {
    Compute *c = modify->compute[k];
    if ((strcmp(c->style, "contact/polyhedron/local") == 0 ||
         strcmp(c->style, "contact/polyhedron") == 0) &&
        c->matchstep(update->ntimestep))
      due = true;
  }
  if (due) contact_data.clear();
  return due;
}

const double *PairPolyhedron::contact_records(int &n, const char *who)
{
  if (contact_step != update->ntimestep)
    error->all(FLERR,
               "compute {}: pair polyhedron stored no contacts on step {} (the compute can be "
               "used only on steps known in advance: thermo, dump, fix ave/*, run 0)",
               who, update->ntimestep);
  n = (int) (contact_data.size() / polydem::CR_NFIELD);
  return contact_data.data();
}

/* ----------------------------------------------------------------------
   kernel failures and large overlaps are counted on every rank and reported
   (collectively, at reneighboring) as warnings with counts, never silently
------------------------------------------------------------------------- */

void PairPolyhedron::report_counters(bool /*final*/)
{
  MPI_Allreduce(local_counts, counters, NCOUNT, MPI_DOUBLE, MPI_SUM, world);
  if (comm->me != 0) return;
  const char *what[NCOUNT] = {"overlap workspace overflows (contact skipped)",
                              "degenerate contacts (NaN or zero size; contact skipped)",
                              "GJK non-convergences (overlap computed anyway)",
                              "overlaps beyond overlap/warn of the smaller particle volume",
                              nullptr};
  for (int k = 0; k < CNT_CONTACTS; k++)
    if (counters[k] > reported[k]) {
      error->warning(FLERR, "pair polyhedron: {:.0f} {} by step {}", counters[k], what[k],
                     update->ntimestep);
      reported[k] = counters[k];
    }
}

/* ---------------------------------------------------------------------- */

void PairPolyhedron::write_restart_settings(FILE *fp)
{
  const double version = RESTART_VERSION, tw = twist;
  fwrite(&version, sizeof(double), 1, fp);
  fwrite(&overlap_warn, sizeof(double), 1, fp);
  fwrite(&core, sizeof(double), 1, fp);
  fwrite(&tw, sizeof(double), 1, fp);
}

void PairPolyhedron::read_restart_settings(FILE *fp)
{
  double version = 0.0, tw = 0.0;
  if (comm->me == 0) utils::sfread(FLERR, &version, sizeof(double), 1, fp, nullptr, error);
  MPI_Bcast(&version, 1, MPI_DOUBLE, 0, world);
  if (version != RESTART_VERSION)
    error->all(FLERR, "pair_style polyhedron: this restart file was written by an older POLYDEM "
               "(contact history of 4 values, another sign convention); restart it with that "
               "version, or write a data file there and start from it");
  if (comm->me == 0) {
    utils::sfread(FLERR, &overlap_warn, sizeof(double), 1, fp, nullptr, error);
    utils::sfread(FLERR, &core, sizeof(double), 1, fp, nullptr, error);
    utils::sfread(FLERR, &tw, sizeof(double), 1, fp, nullptr, error);
  }
  MPI_Bcast(&overlap_warn, 1, MPI_DOUBLE, 0, world);
  MPI_Bcast(&core, 1, MPI_DOUBLE, 0, world);
  MPI_Bcast(&tw, 1, MPI_DOUBLE, 0, world);
  twist = tw != 0.0;
}

/* ----------------------------------------------------------------------
   the history is that of the lower-tag atom of the pair
   (polydem_contact_law.h): the partner's copy is the same numbers
------------------------------------------------------------------------- */

void PairPolyhedron::transfer_history(double *source, double *target POLYDEM_TRANSFER_HISTORY_TYPES)
{
  for (int k = 0; k < SIZE_HISTORY; k++) target[k] = source[k];
}

void PairPolyhedron::write_restart(FILE *fp)
{
  write_restart_settings(fp);
  const int n = atom->ntypes;
  for (int i = 1; i <= n; i++) {
    fwrite(&matset[i], sizeof(int), 1, fp);
    fwrite(&youngs[i], sizeof(double), 1, fp);
    fwrite(&poisson[i], sizeof(double), 1, fp);
    for (int j = i; j <= n; j++) {
      fwrite(&setflag[i][j], sizeof(int), 1, fp);
      fwrite(&pairset[i][j], sizeof(int), 1, fp);
      fwrite(&restitution[i][j], sizeof(double), 1, fp);
      fwrite(&friction[i][j], sizeof(double), 1, fp);
    }
  }
}

void PairPolyhedron::read_restart(FILE *fp)
{
  read_restart_settings(fp);
  allocate();
  const int n = atom->ntypes, me = comm->me;
  for (int i = 1; i <= n; i++) {
    if (me == 0) {
      utils::sfread(FLERR, &matset[i], sizeof(int), 1, fp, nullptr, error);
      utils::sfread(FLERR, &youngs[i], sizeof(double), 1, fp, nullptr, error);
      utils::sfread(FLERR, &poisson[i], sizeof(double), 1, fp, nullptr, error);
    }
    MPI_Bcast(&matset[i], 1, MPI_INT, 0, world);
    MPI_Bcast(&youngs[i], 1, MPI_DOUBLE, 0, world);
    MPI_Bcast(&poisson[i], 1, MPI_DOUBLE, 0, world);
    for (int j = i; j <= n; j++) {
      if (me == 0) {
        utils::sfread(FLERR, &setflag[i][j], sizeof(int), 1, fp, nullptr, error);
        utils::sfread(FLERR, &pairset[i][j], sizeof(int), 1, fp, nullptr, error);
        utils::sfread(FLERR, &restitution[i][j], sizeof(double), 1, fp, nullptr, error);
        utils::sfread(FLERR, &friction[i][j], sizeof(double), 1, fp, nullptr, error);
      }
      MPI_Bcast(&setflag[i][j], 1, MPI_INT, 0, world);
      MPI_Bcast(&pairset[i][j], 1, MPI_INT, 0, world);
      MPI_Bcast(&restitution[i][j], 1, MPI_DOUBLE, 0, world);
      MPI_Bcast(&friction[i][j], 1, MPI_DOUBLE, 0, world);
    }
  }
}

/* ---------------------------------------------------------------------- */

void *PairPolyhedron::extract(const char *str, int &dim)
{
  dim = 2;
  if (strcmp(str, "restitution") == 0) return (void *) restitution;
  if (strcmp(str, "friction") == 0) return (void *) friction;
  dim = 1;
  if (strcmp(str, "youngs") == 0) return (void *) youngs;
  if (strcmp(str, "poisson") == 0) return (void *) poisson;
  if (strcmp(str, "counters") == 0) return (void *) counters;
  return nullptr;
}

double PairPolyhedron::memory_usage()
{
  return Pair::memory_usage() + (double) sizeof(polydem::OverlapWorkspace<double, 128>);
}
