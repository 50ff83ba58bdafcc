/* ----------------------------------------------------------------------
   POLYDEM - shape-template library and per-atom semantics of
   atom_style polyhedron (and polyhedron/kk)
------------------------------------------------------------------------- */

#include "poly_shape_library.h"

#include "polydem_rigid.h"

#include "atom.h"
#include "atom_vec.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "modify.h"
#include "polydem_lammps_compat.h"
#include "polydem_shape_record.h"
#include "polydem_shape_template.h"


#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

using namespace LAMMPS_NS;

/* ---------------------------------------------------------------------- */

PolyShapeLibrary::PolyShapeLibrary(LAMMPS *lmp, AtomVec *owner_) :
    Pointers(lmp), owner(owner_), version(0), pshape_one(0), rmass_one(0.0)
{
}

PolyShapeLibrary::~PolyShapeLibrary() = default;

PolyShapeLibrary *PolyShapeLibrary::of(LAMMPS *lmp, const std::string &who)
{
  if (auto *o = dynamic_cast<ShapeLibraryOwner *>(lmp->atom->avec)) return o->shape_library();
  lmp->error->all(FLERR, "{} requires atom_style polyhedron", who);
  return nullptr;
}

/* ----------------------------------------------------------------------
   what the constructor of either atom style sets
------------------------------------------------------------------------- */

void PolyShapeLibrary::setup_style()
{
  owner->mass_type = AtomVec::PER_ATOM;
  owner->molecular = Atom::ATOMIC;
  owner->forceclearflag = 0;

  atom->radius_flag = atom->rmass_flag = atom->omega_flag = atom->torque_flag =
      atom->angmom_flag = 1;
  atom->quat_flag = atom->pshape_flag = 1;

  // LAMMPS 2021's main() answers error->one (LAMMPSAbortException) with
  // MPI_Abort and no flush: with the screen redirected to a file the message
  // and the log were lost (issue 17). Line buffering keeps both; glibc
  // allows it on a stream already in use (it changes only the flags).
  if (screen) setvbuf(screen, nullptr, _IOLBF, BUFSIZ);
  if (logfile) setvbuf(logfile, nullptr, _IOLBF, BUFSIZ);
  check_dimension();

  // ghosts get template index, scale, quaternion (+ radius and mass for the
  // neighbor cutoff and the effective mass), never vertices (seed §2.6)
  polydem_compat::set_fields(owner->fields_grow, "radius rmass omega angmom torque quat pshape pscale");
  polydem_compat::set_fields(owner->fields_copy, "radius rmass omega angmom quat pshape pscale");
  polydem_compat::set_fields(owner->fields_comm, "quat");
  polydem_compat::set_fields(owner->fields_comm_vel, "quat omega angmom");
  polydem_compat::set_fields(owner->fields_reverse, "torque");
  polydem_compat::set_fields(owner->fields_border, "radius rmass quat pshape pscale");
  polydem_compat::set_fields(owner->fields_border_vel, "radius rmass quat pshape pscale omega angmom");
  polydem_compat::set_fields(owner->fields_exchange, "radius rmass omega angmom quat pshape pscale");
  polydem_compat::set_fields(owner->fields_restart, "radius rmass omega angmom quat pshape pscale");
  polydem_compat::set_fields(owner->fields_create, "radius rmass omega angmom quat pshape pscale");
  // data file: atom-ID atom-type shape scale density x y z qw qx qy qz
  polydem_compat::set_fields(owner->fields_data_atom, "id type pshape pscale rmass x quat");
  polydem_compat::set_fields(owner->fields_data_vel, "id v angmom");
}

/* ----------------------------------------------------------------------
   arguments: none from the user. Restart files store the templates as
   "shape ID RECORD" triples here (AtomVec::argcopy is what write_restart
   saves and read_restart hands back), so a restart needs no shape files.
------------------------------------------------------------------------- */

void PolyShapeLibrary::process_args(int narg, char **arg)
{
  int iarg = 0;
  while (iarg < narg) {
    if (strcmp(arg[iarg], "shape") != 0 || iarg + 3 > narg)
      error->all(FLERR, "Illegal atom_style polyhedron command: unexpected argument '{}' "
                 "(define templates with polyhedron_shape)", arg[iarg]);
    std::string err;
    auto t = polydem::shape_from_record(arg[iarg + 2], err);
    if (!t) error->all(FLERR, "atom_style polyhedron: corrupt shape record for '{}': {}",
                       arg[iarg + 1], err);
    templates.push_back(std::move(t));
    template_ids.emplace_back(arg[iarg + 1]);
    template_records.emplace_back(arg[iarg + 2]);
    iarg += 3;
  }
  version++;
}

/* ----------------------------------------------------------------------
   3-d only: the rigid-body integration and contacts are three-dimensional
   (in 2-d particles left the plane)
------------------------------------------------------------------------- */

void PolyShapeLibrary::init()
{
  check_dimension();
  check_inserting_fixes();
}

void PolyShapeLibrary::check_dimension()
{
  if (domain->dimension != 3)
    error->all(FLERR, "atom_style polyhedron: 3-d only, got 'dimension {}'", domain->dimension);
}

/* ----------------------------------------------------------------------
   LAMMPS's inserting fixes give their atoms a sphere's radius and mass and
   no shape, scale or orientation of ours (fix pour then segfaulted at its
   first insertion): refused before the run starts
------------------------------------------------------------------------- */

void PolyShapeLibrary::check_inserting_fixes()
{
  for (int i = 0; i < modify->nfix; i++) {
    const std::string style = modify->fix[i]->style;
    if (style == "pour" || style == "deposit")
      error->all(FLERR,
                 "fix {} cannot insert atom_style polyhedron particles (it creates atoms "
                 "without a polyhedron's shape, scale, orientation and mass): use fix "
                 "insert/polyhedron",
                 style);
  }
}

/* ---------------------------------------------------------------------- */

int PolyShapeLibrary::find_shape(const std::string &id) const
{
  for (int i = 0; i < (int) template_ids.size(); i++)
    if (template_ids[i] == id) return i;
  return -1;
}

int PolyShapeLibrary::add_shape(const std::string &id,
                                std::unique_ptr<polydem::PolyShapeTemplate> t,
                                const std::string &record)
{
  if (find_shape(id) >= 0)
    error->all(FLERR, "polyhedron_shape: shape ID '{}' is already defined", id);
  templates.push_back(std::move(t));
  template_ids.push_back(id);
  template_records.push_back(record);
  version++;

  // append "shape ID RECORD" to the owner's stored arguments
  char **newargs = new char *[owner->nargcopy + 3];
  for (int i = 0; i < owner->nargcopy; i++) newargs[i] = owner->argcopy[i];
  newargs[owner->nargcopy] = utils::strdup("shape");
  newargs[owner->nargcopy + 1] = utils::strdup(id);
  newargs[owner->nargcopy + 2] = utils::strdup(record);
  delete[] owner->argcopy;
  owner->argcopy = newargs;
  owner->nargcopy += 3;
  return (int) templates.size() - 1;
}

int PolyShapeLibrary::max_parts() const
{
  int m = 1;
  for (const auto &t : templates) m = std::max(m, t->nparts());
  return m;
}

/* ---------------------------------------------------------------------- */

double PolyShapeLibrary::density(int i) const
{
  return polydem::scaled_density(atom->rmass[i], templates[atom->pshape[i]]->view().volume,
                                 atom->pscale[i]);
}

void PolyShapeLibrary::set_shape_scale(int i, int ishape, double scale)
{
  const double rho = density(i);
  atom->pshape[i] = ishape;
  atom->pscale[i] = scale;
  const auto v = templates[ishape]->view();
  atom->rmass[i] = polydem::scaled_mass(rho, v.volume, scale);
  atom->radius[i] = v.radius * scale;
}

void PolyShapeLibrary::views(std::vector<polydem::ShapeView<double>> &out) const
{
  out.resize(templates.size());
  for (size_t k = 0; k < templates.size(); ++k) out[k] = templates[k]->view();
}

void PolyShapeLibrary::inertia(int i, double *moments) const
{
  const auto v = templates[atom->pshape[i]]->view();
  polydem::scaled_moments(atom->rmass[i], atom->pscale[i], v.volume, v.inertia, moments);
}

// mass and moments of inertia of atom i are normal numbers, the mass at
// most MASS_MAX (a zero mass gave NaN energies, a zero moment no rotation,
// density 1e308 an infinite kinetic energy: m v^2 must not overflow)
static constexpr double MASS_MAX = 1e250;
bool PolyShapeLibrary::mass_is_normal(int i) const
{
  return mass_is_normal(atom->pshape[i], atom->rmass[i], atom->pscale[i]);
}

bool PolyShapeLibrary::mass_is_normal(int ishape, double mass, double scale) const
{
  const auto v = templates[ishape]->view();
  double I[3];
  polydem::scaled_moments(mass, scale, v.volume, v.inertia, I);
  bool ok = std::isnormal(mass) && mass > 0.0 && mass <= MASS_MAX;
  for (int k = 0; k < 3; k++) ok = ok && std::isnormal(I[k]) && I[k] > 0.0;
  return ok;
}

/* ----------------------------------------------------------------------
   create_atoms: first template, scale 1, density 1, identity orientation
------------------------------------------------------------------------- */

void PolyShapeLibrary::create_atom_post(int ilocal)
{
  if (templates.empty())
    error->one(FLERR, "atom_style polyhedron: define a shape with polyhedron_shape "
               "before creating atoms");
  const auto v = templates[0]->view();
  atom->pshape[ilocal] = 0;
  atom->pscale[ilocal] = 1.0;
  atom->rmass[ilocal] = v.volume;
  atom->radius[ilocal] = v.radius;
  double *q = atom->quat[ilocal];
  q[0] = 1.0;
  q[1] = q[2] = q[3] = 0.0;
}

/* ----------------------------------------------------------------------
   read_data: shape index is 1-based (order of polyhedron_shape commands),
   the mass column holds the density
------------------------------------------------------------------------- */

void PolyShapeLibrary::data_atom_post(int ilocal)
{
  int *pshape = atom->pshape;
  double *rmass = atom->rmass;
  const int ishape = pshape[ilocal];
  if (ishape < 1 || ishape > ntemplates())
    error->one(FLERR, "Invalid shape index {} in Atoms section of data file: {} shape(s) "
               "defined with polyhedron_shape", ishape, ntemplates());
  pshape[ilocal] = ishape - 1;
  const double s = atom->pscale[ilocal];
  if (!(s > 0.0) || !std::isfinite(s))
    error->one(FLERR, "Invalid scale {} in Atoms section of data file", s);
  const double rho = rmass[ilocal];
  if (!(rho > 0.0) || !std::isfinite(rho))
    error->one(FLERR, "Invalid density {} in Atoms section of data file", rho);
  const auto v = templates[ishape - 1]->view();
  rmass[ilocal] = polydem::scaled_mass(rho, v.volume, s);
  atom->radius[ilocal] = v.radius * s;
  if (!mass_is_normal(ilocal))
    error->one(FLERR,
               "Invalid density {} or scale {} in Atoms section of data file: the mass "
               "{} must be in (0, 1e250] and the moments of inertia non-zero and finite",
               rho, s, rmass[ilocal]);

  double *q = atom->quat[ilocal];
  const double n = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (!(n > 0.0) || !std::isfinite(n))
    error->one(FLERR, "Invalid quaternion in Atoms section of data file");
  // accept slightly unnormalised input (e.g. printed with few digits)
  if (fabs(n - 1.0) > 1.0e-12)
    for (int k = 0; k < 4; k++) q[k] /= n;

  double *angmom = atom->angmom[ilocal], *omega = atom->omega[ilocal];
  angmom[0] = angmom[1] = angmom[2] = 0.0;
  omega[0] = omega[1] = omega[2] = 0.0;
}

/* ----------------------------------------------------------------------
   Velocities section: v and angmom of atom i must be finite (an
   overflowing number such as 1e999 parses as inf)
------------------------------------------------------------------------- */

void PolyShapeLibrary::check_data_vel(int ilocal)
{
  const double *v = atom->v[ilocal], *angmom = atom->angmom[ilocal];
  for (int k = 0; k < 3; k++)
    if (!std::isfinite(v[k]) || !std::isfinite(angmom[k]))
      error->one(FLERR,
                 "Invalid velocity ({} {} {}) or angular momentum ({} {} {}) in "
                 "Velocities section of data file: not finite",
                 v[0], v[1], v[2], angmom[0], angmom[1], angmom[2]);
}

/* ----------------------------------------------------------------------
   write_data: 1-based shape index, density in the mass column
------------------------------------------------------------------------- */

void PolyShapeLibrary::pack_data_pre(int ilocal)
{
  pshape_one = atom->pshape[ilocal];
  rmass_one = atom->rmass[ilocal];
  atom->rmass[ilocal] = density(ilocal);
  atom->pshape[ilocal] = pshape_one + 1;
}

void PolyShapeLibrary::pack_data_post(int ilocal)
{
  atom->pshape[ilocal] = pshape_one;
  atom->rmass[ilocal] = rmass_one;
}

/* ----------------------------------------------------------------------
   compute property/atom names: shape scale density quatw quati quatj quatk
------------------------------------------------------------------------- */

int PolyShapeLibrary::property_atom(const std::string &name)
{
  if (name == "shape") return 0;
  if (name == "scale") return 1;
  if (name == "density") return 2;
  if (name == "quatw") return 3;
  if (name == "quati") return 4;
  if (name == "quatj") return 5;
  if (name == "quatk") return 6;
  return -1;
}

void PolyShapeLibrary::pack_property_atom(int index, double *buf, int nvalues, int groupbit)
{
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  int n = 0;
  for (int i = 0; i < nlocal; i++) {
    double value = 0.0;
    if (mask[i] & groupbit) {
      if (index == 0) value = atom->pshape[i] + 1;
      else if (index == 1) value = atom->pscale[i];
      else if (index == 2) value = density(i);
      else value = atom->quat[i][index - 3];
    }
    buf[n] = value;
    n += nvalues;
  }
}
