/* ----------------------------------------------------------------------
   POLYDEM - pair_style polyhedron
------------------------------------------------------------------------- */

#include "pair_polyhedron.h"

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

#include "compute.h"
#include "polydem_contact_pipeline.h"
#include "polydem_contact_record.h"
#include "polydem_damping.h"
#include "polydem_history.h"
#include "polydem_lammps_compat.h"
#include "polydem_overlap.h"
#include "polydem_parse.h"
#include "polydem_shape_template.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

using namespace LAMMPS_NS;
using MathConst::MY_PI;

static constexpr int SIZE_HISTORY = polydem::CONTACT_HIST;    // s, k_t, twist (polydem_contact_law.h)

/* ---------------------------------------------------------------------- */

PairPolyhedron::PairPolyhedron(LAMMPS *lmp) :
    PairPolydem(lmp, "polyhedron", "NEIGH_HISTORY_POLY", SIZE_HISTORY, NCOUNT), youngs(nullptr),
    poisson(nullptr), matset(nullptr), restitution(nullptr), friction(nullptr),
    ellipsoid_kn(nullptr), twist(1),
    pairset(nullptr), overlap_warn(0.05), core(1.0e-4), part_slots(16), dt(0.0),
    record_stride(polydem::CR_NFIELD), contact_step(-1)
{
  ws = std::make_unique<polydem::OverlapWorkspace<double, 128>>();
}

PairPolyhedron::~PairPolyhedron()
{
  if (copymode) return;
  if (allocated)
    destroy_arrays(setflag, cutsq, youngs, poisson, matset, restitution, friction, ellipsoid_kn,
                   pairset);
}

/* ---------------------------------------------------------------------- */

void PairPolyhedron::allocate()
{
  allocated = 1;
  create_per_type_pair(setflag, "setflag");
  create_per_type_pair(cutsq, "cutsq");
  create_per_type(youngs, "youngs");
  create_per_type(poisson, "poisson");
  create_per_type(matset, "matset");
  create_per_type_pair(restitution, "restitution");
  create_per_type_pair(friction, "friction");
  create_per_type_pair(ellipsoid_kn, "ellipsoid_kn");
  create_per_type_pair(pairset, "pairset");
  allocate_rolling();
}

/* ----------------------------------------------------------------------
   pair_style polyhedron [overlap/warn f] [core f] [twist yes|no]
                         [rolling/stiffness f] [rolling/damping eta]
------------------------------------------------------------------------- */

void PairPolyhedron::settings(int narg, char **arg)
{
  overlap_warn = 0.05;
  core = 1.0e-4;
  twist = 1;
  part_slots = 16;
  roll_kr = polydem::RollingLaw<double>().kr;
  roll_eta = polydem::RollingLaw<double>().eta;
  for (int iarg = 0; iarg < narg; iarg += 2) {
    if (settings_rolling(narg, arg, iarg)) continue;
    if (strcmp(arg[iarg], "twist") == 0) {
      twist = polydem_parse::choice(FLERR, lmp, "pair_style polyhedron", "twist",
                                    iarg + 1 < narg ? arg[iarg + 1] : nullptr, "yes", "no");
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
    if (strcmp(arg[iarg], "part/slots") == 0) {
      if (iarg + 1 >= narg) error->all(FLERR, "pair_style polyhedron: part/slots needs a value");
      const double v = polydem_parse::numeric(FLERR, arg[iarg + 1], lmp);
      constexpr int most = polydem::MAX_COMPOSITE_PARTS * polydem::MAX_COMPOSITE_PARTS;
      if (!(v >= 1.0 && v <= most) || v != (int) v)
        error->all(FLERR, "pair_style polyhedron: part/slots must be an integer from 1 to {}, "
                   "got '{}'", most, arg[iarg + 1]);
      part_slots = (int) v;
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
   either ending in 'rolling mu_r' (rolling resistance), 'cohesion k_c'
   (adhesive stress), 'bridge V_b gamma theta' (liquid bridge) and/or
   'ellipsoid k_n' (stiffness of two ellipsoids, one with unequal semi-axes)
------------------------------------------------------------------------- */

void PairPolyhedron::coeff(int nargs, char **arg)
{
  if (!allocated) allocate();
  double mu_r = 0.0, coh = 0.0, bridge[5], kn = 0.0;
  const int narg = coeff_keywords(nargs, arg, mu_r, coh, bridge, &kn);
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
      rolling[i][j] = mu_r;
      cohesion[i][j] = coh;
      bridge_vol[i][j] = bridge[0];
      bridge_gamma[i][j] = bridge[1];
      bridge_theta[i][j] = bridge[2];
      bridge_eta[i][j] = bridge[3];
      bridge_smin[i][j] = bridge[4];
      ellipsoid_kn[i][j] = kn;
      pairset[i][j] = 1;
      setflag[i][j] = 1;
      count++;
    }
  if (count == 0) error->all(FLERR, "Incorrect args for pair coefficients");
}

/* ---------------------------------------------------------------------- */

void PairPolyhedron::init_style()
{
  init_common(true);
  for (int t = 0; t < avec->ntemplates(); t++) {
    const auto &sh = avec->shape(t);
    for (int k = 0; k < std::max(1, sh.nparts()); k++) {
      const int nf = sh.is_composite() ? sh.part_shape(k).nfaces() : sh.nfaces();
      if (nf > 128)
        error->all(FLERR, "pair_style polyhedron: shape '{}' has {} faces, more than 128",
                   avec->shape_id(t), nf);
    }
  }
  // spheres and ellipsoids meet polyhedra and spheres by their exact overlap
  // volume; two ellipsoids of which one has unequal semi-axes have no volume
  // kernel and meet by the algebraic contact of pair_style ellipsoid, with
  // the type pair's 'ellipsoid k_n' (composites: by their parts)
  auto parts_any = [&](int ishape, bool aniso_only) {
    const auto &sh = avec->shape(ishape);
    auto one = [&](const polydem::PolyShapeTemplate &p) {
      return p.is_ellipsoid() && (!aniso_only || !p.is_sphere());
    };
    if (!sh.is_composite()) return one(sh);
    for (int k = 0; k < sh.nparts(); k++)
      if (one(sh.part_shape(k))) return true;
    return false;
  };
  // per type: it holds ellipsoids ([0]), of them with unequal semi-axes ([1])
  const int ntp = atom->ntypes + 1;
  std::vector<int> ell_type(2 * ntp, 0), first_shape(ntp, -1);
  int nell[2] = {0, 0};    // ellipsoid atoms, of them with unequal axes
  auto consider = [&](int ishape, int type, int natoms) {
    if (!parts_any(ishape, false)) return;
    nell[0] += natoms;
    ell_type[type] = 1;
    if (parts_any(ishape, true)) {
      nell[1] += natoms;
      ell_type[ntp + type] = 1;
      first_shape[type] = ishape;
    }
  };
  for (int i = 0; i < atom->nlocal; i++) consider(atom->pshape[i], atom->type[i], 1);
  MPI_Allreduce(MPI_IN_PLACE, nell, 2, MPI_INT, MPI_SUM, world);
  MPI_Allreduce(MPI_IN_PLACE, ell_type.data(), 2 * ntp, MPI_INT, MPI_MAX, world);
  MPI_Allreduce(MPI_IN_PLACE, first_shape.data(), ntp, MPI_INT, MPI_MAX, world);
  // an insertion fix adds many of each candidate
  for (const auto &c : ParticleSource::candidates(lmp)) consider(c.ishape, c.type, 2);
  if (nell[1] > 0 && nell[0] > 1)
    for (int i = 1; i < ntp; i++)
      for (int j = 1; j < ntp; j++) {
        if (!ell_type[ntp + i] || !ell_type[j]) continue;
        const int lo = std::min(i, j), hi = std::max(i, j);
        const bool given = pairset[lo][hi] ? ellipsoid_kn[lo][hi] > 0.0
                                           : ellipsoid_kn[lo][lo] > 0.0 && ellipsoid_kn[hi][hi] > 0.0;
        const double coh = pairset[lo][hi] ? cohesion[lo][hi]
                                           : sqrt(cohesion[lo][lo] * cohesion[hi][hi]);
        if (coh > 0.0 && (i <= j || !ell_type[ntp + j]) && comm->me == 0)
          error->warning(FLERR, "pair_style polyhedron: the cohesion of types {} and {} does "
                         "not act between two ellipsoids of which one has unequal semi-axes "
                         "(their algebraic contact has no adhesive stress)", lo, hi);
        if (!given) {
          // where the stiffness goes: the like pair's line, the unlike pair's own line,
          // or both types' lines (mixed) unless the unlike pair gets one of its own
          const std::string where = lo == hi ? fmt::format("pair_coeff {} {}", lo, lo)
              : pairset[lo][hi]
              ? fmt::format("their own pair_coeff {} {}", lo, hi)
              : fmt::format("pair_coeff {} {} and pair_coeff {} {} (mixed by the geometric "
                            "mean), or to a pair_coeff {} {} of their own",
                            lo, lo, hi, hi, lo, hi);
          error->all(FLERR, "pair_style polyhedron: shape '{}' is an ellipsoid with unequal "
                     "semi-axes; two ellipsoids meet by overlap volume only if both are spheres "
                     "(equal semi-axes), others by the algebraic contact of pair_style "
                     "ellipsoid, whose normal stiffness types {} and {} lack: add 'ellipsoid "
                     "k_n' to {}",
                     avec->shape_id(first_shape[i]), lo, hi, where);
        }
      }

  dt = update->dt;

  // the law table: settings now, the type pairs' entries in init_one
  begin_law_table(overlap_warn);
  laws.core = core;
  laws.twist = twist;
  // the algebraic contact of ellipsoid pairs: pair_style ellipsoid's defaults
  laws.kt_ratio = polydem::ELLIPSOID_KT_RATIO;
  laws.gt_ratio = polydem::ELLIPSOID_GT_RATIO;
  laws.overlap = polydem::OVERLAP_CENTRE;
  laws.damping_mass = polydem::DAMPING_REDUCED;
  beyond_contact = 0;    // init_one: 1 with liquid bridges
  choose_history_size();
  laws.nhist = nhistory_contact;
  laws.nslot = history_slots();
  setup_history_fix();
  check_timestep();
}

int PairPolyhedron::history_slots()
{
  return polydem::part_contact_slots(PolyShapeLibrary::of(lmp, "pair_style polyhedron")->max_parts(),
                                     part_slots);
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
  mix_keywords(i, j, pairset[i][j]);
  if (!pairset[i][j]) ellipsoid_kn[i][j] = sqrt(ellipsoid_kn[i][i] * ellipsoid_kn[j][j]);
  ellipsoid_kn[j][i] = ellipsoid_kn[i][j];
  // the law table's entries of the pair, damping in closed form (polydem_damping.h)
  const int nt = atom->ntypes + 1;
  const auto damp = polydem::damping_law(restitution[i][j], 1);
  auto fill = [&](int a, int b) {
    auto &e = law_entries[a * nt + b];
    e.E1 = youngs[a];
    e.nu1 = poisson[a];
    e.E2 = youngs[b];
    e.nu2 = poisson[b];
    e.kn = ellipsoid_kn[i][j];
    e.mu = friction[i][j];
    e.damping = damp;
    e.mu_r = rolling[i][j];
    e.cohesion = cohesion[i][j];
    e.bridge = bridge_law(i, j);
  };
  fill(i, j);
  fill(j, i);
  // a bridged pair must stay in the neighbor list until it ruptures: it was
  // within the skin at the last build if its gap is below s_c <= skin now
  const double sc = law_entries[i * nt + j].bridge.rupture;
  if (sc > neighbor->skin)
    error->all(FLERR, "pair_coeff polyhedron {} {}: the liquid bridge ruptures at a gap of "
               "s_c = (1 + theta/2) V_b^(1/3) = {:.6g}, beyond the neighbor skin {:.6g}: set "
               "the skin to at least s_c (neighbor {:.6g} bin)", i, j, sc, neighbor->skin, sc);
  laws.bridge_reach = std::max(laws.bridge_reach, sc);
  // the history fix keeps the flags of listed pairs beyond contact (a
  // bridge of separated spheres); LAMMPS's size list marks only overlapping ones
  if (sc > 0.0) beyond_contact = 1;

  return size_cutoff();
}

/* ----------------------------------------------------------------------
   printed estimate of the contact time: a like pair of the stiffest, lightest
   particle with a contact patch of area R^2 (R: volume-equivalent radius),
   k_n = K R^2 = 2 E R (Eq. 13), t_c = pi sqrt(m_eff / k_n)
------------------------------------------------------------------------- */

void PairPolyhedron::check_timestep()
{
  TimestepCheck check;
  auto consider = [&](int ishape, double s, double m, int type) {
    const auto &shape = avec->shape(ishape);
    const double V = shape.volume();
    const double R = s * cbrt(3.0 * V / (4.0 * MY_PI));
    const double kn = 2.0 * youngs[type] * R;
    check.contact(0.5 * m, kn * force->ftm2v);
    if (shape.is_ellipsoid()) {
      // and the algebraic contact of ellipsoid pairs, at the stiffest k_n of its type
      double kmax = 0.0;
      for (int u = 1; u <= atom->ntypes; u++)
        kmax = std::max(kmax, ellipsoid_kn[std::min(type, u)][std::max(type, u)]);
      if (kmax > 0.0) check.contact(0.5 * m, kmax * force->ftm2v);
      return;
    }
    // like pair of this particle, its largest face flat on another's
    const double Vs = V * s * s * s, ms = m / force->ftm2v;
    const auto law = polydem::feng_law(youngs[type], 0.0, Vs, youngs[type], 0.0, Vs,
                                       polydem::damping_law(1.0, 0), 0.0, core, 0);
    check.flat_face(polydem::face_contact_stable_dt(law.normal, ms * ms / (ms + ms),
                                                    shape.max_face_area() * s * s));
  };
  for (int i = 0; i < atom->nlocal; i++)
    consider(atom->pshape[i], atom->pscale[i], atom->rmass[i], atom->type[i]);
  // and the smallest of each kind an insertion fix will add
  for (const auto &c : ParticleSource::candidates(lmp)) consider(c.ishape, c.scale, c.mass, c.type);
  check.report(lmp, "pair polyhedron", "like pair, contact area R^2", "a like grain", core);
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
  avec->views(views);

  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    int *touch = firsttouch[i];
    double *allshear = firstshear[i];
    int *jlist = firstneigh[i];
    const int jnum = numneigh[i];
    const auto &vi = views[pshape[i]];
    const auto A = polydem::gather_polyhedron_body(atoms, i, vi);

    for (int jj = 0; jj < jnum; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      double *shear = &allshear[nhistory * jj];
      const double delx = x[i][0] - x[j][0], dely = x[i][1] - x[j][1],
                   delz = x[i][2] - x[j][2];
      const double radsum = radius[i] + radius[j] + laws.bridge_reach;
      if (delx * delx + dely * dely + delz * delz >= radsum * radsum) {
        touch[jj] = 0;
        polydem::history_release(shear, nhistory);
        continue;
      }
      const auto &vj = views[pshape[j]];
      const auto B = polydem::gather_polyhedron_body(atoms, j, vj);
      const auto c =
          polydem::polyhedron_pair_contact(A, B, laws, dt, shearupdate, shear, *ws, local_counts,
                                           touch[jj] != 0);
      touch[jj] = c.contact;
      if (!c.contact) continue;
      polydem::scatter_contact_host(f, torque, i, j, newton_pair || j < nlocal, c.cf);
      if (evflag)
        ev_tally_xyz(i, j, nlocal, newton_pair, c.cf.energy, 0.0, c.cf.F_A.x, c.cf.F_A.y,
                     c.cf.F_A.z, delx, dely, delz);
      if (store && c.contact == 1 &&
          polydem::contact_owned(newton_pair, j < nlocal, tag[i], tag[j], x[i], x[j])) {
        double rec[polydem::CR_NFIELD];
        polydem::fill_contact_record(rec, tag[i], tag[j], mask[i], mask[j], c.vmin, c.geo, c.cf);
        contact_data.insert(contact_data.end(), rec, rec + record_stride);
      }
    }
  }
  if (store) contact_step = update->ntimestep;
  if (counters_due()) report_counters();
}

/* ----------------------------------------------------------------------
   store per-contact records this step if a contact compute is due now
   (same mechanism as compute pe: Compute::timeflag and matchstep)
------------------------------------------------------------------------- */

bool PairPolyhedron::store_contacts_now()
{
  // whole records wherever a per-contact compute exists (it may also be
  // invoked on a step only a summary compute was due for, e.g. by the
  // library after a run); summaries where there is none
  bool due = false, full = false;
  for (int k = 0; k < modify->ncompute; k++) {
    Compute *c = modify->compute[k];
    const bool local = strcmp(c->style, "contact/polyhedron/local") == 0;
    full = full || local;
    if ((local || strcmp(c->style, "contact/polyhedron") == 0) && c->matchstep(update->ntimestep))
      due = true;
  }
  if (due) {
    contact_data.clear();
    record_stride = full ? polydem::CR_NFIELD : polydem::CR_NSUMMARY;
  }
  return due;
}

const double *PairPolyhedron::contact_records(int &n, int &stride, bool full, const char *who)
{
  if (contact_step != update->ntimestep || (full && record_stride != polydem::CR_NFIELD))
    error->all(FLERR,
               "compute {}: pair polyhedron stored no {}contacts on step {} (the compute can be "
               "used only on steps known in advance: thermo, dump, fix ave/*, run 0)",
               who, contact_step == update->ntimestep ? "whole records of " : "",
               update->ntimestep);
  stride = record_stride;
  n = (int) (contact_data.size() / record_stride);
  return contact_data.data();
}

/* ----------------------------------------------------------------------
   kernel failures and large overlaps, reported as warnings with counts
------------------------------------------------------------------------- */

void PairPolyhedron::report_counters()
{
  const char *what[] = {"overlap workspace overflows (contact skipped)",
                        "degenerate contacts (NaN or zero size; contact skipped)",
                        "GJK non-convergences (overlap computed anyway)",
                        "overlaps beyond overlap/warn of the smaller particle volume",
                        "part contacts of composites beyond the pair's history slots (friction "
                        "without history; pair_style polyhedron part/slots raises the number)",
                        "contact-steps under a liquid bridge law of grains that get no bridge "
                        "(bridges act between spheres and convex polyhedra, also as parts of "
                        "composites, not on ellipsoids of unequal semi-axes)",
                        "contact-steps whose normal damping (dashpot or a liquid bridge's "
                        "viscosity) was capped at m_eff/dt, less than asked: the time step is "
                        "too long for these contacts"};
  PairPolydem::report_counters(what, polydem::PP_CONTACTS);
}

/* ----------------------------------------------------------------------
   restart: the settings, then per type its material and per type pair
   (j >= i) its coefficients
------------------------------------------------------------------------- */

void PairPolyhedron::settings_fields(RestartFields &io)
{
  io(overlap_warn);
  io(core);
  io.flag_as_double(twist);
  if (io.has_part_slots())
    io(part_slots);
  else
    part_slots = 16;    // the fixed number of older files
}

const char *PairPolyhedron::restart_version_text() const
{
  return "contact history of 4 values, another sign convention";
}

void PairPolyhedron::coeff_fields(RestartFields &io)
{
  const int n = atom->ntypes;
  for (int i = 1; i <= n; i++) {
    io(matset[i]);
    io(youngs[i]);
    io(poisson[i]);
    for (int j = i; j <= n; j++) {
      io(setflag[i][j]);
      io(pairset[i][j]);
      io(restitution[i][j]);
      io(friction[i][j]);
      rolling_coeff_fields(io, i, j);
      if (io.has_ellipsoid_kn()) io(ellipsoid_kn[i][j]);
    }
  }
}

/* ---------------------------------------------------------------------- */

void *PairPolyhedron::extract(const char *str, int &dim)
{
  dim = 2;
  if (strcmp(str, "restitution") == 0) return (void *) restitution;
  if (strcmp(str, "friction") == 0) return (void *) friction;
  if (strcmp(str, "ellipsoid_kn") == 0) return (void *) ellipsoid_kn;
  dim = 1;
  if (strcmp(str, "youngs") == 0) return (void *) youngs;
  if (strcmp(str, "poisson") == 0) return (void *) poisson;
  return extract_models(str, dim);
}

double PairPolyhedron::memory_usage()
{
  return Pair::memory_usage() + (double) sizeof(polydem::OverlapWorkspace<double, 128>) +
         (double) contact_data.capacity() * sizeof(double);
}
