/* ----------------------------------------------------------------------
   POLYDEM - command polyhedron_set
------------------------------------------------------------------------- */

#include "polyhedron_set.h"

#include "accelerator_kokkos.h"
#include "atom.h"
#include "atom_masks.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "group.h"
#include "math_const.h"
#include "poly_shape_library.h"
#include "polydem_lammps_compat.h"
#include "polydem_parse.h"
#include "polydem_rigid.h"
#include "polydem_shape_template.h"
#include "random_park.h"
#include "region.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

using namespace LAMMPS_NS;
using MathConst::MY_PI;

/* ----------------------------------------------------------------------
   polyhedron_set atom|type|group|region ID keyword value ...
   keywords (applied in the order given):
     shape ID            template (keeps the density)
     scale s             scale factor (keeps the density)
     density rho         mass = rho V s^3
     mass m
     quat a b c theta    rotation by theta degrees about axis (a,b,c)
     quat/random seed    uniformly random orientation (reproducible on any
                         number of ranks: seeded by seed and position)
     angmom Lx Ly Lz     lab-frame angular momentum
     omega wx wy wz      lab-frame angular velocity (sets angmom = R I R^T w)
------------------------------------------------------------------------- */

void PolyhedronSet::command(int narg, char **arg)
{
  if (domain->box_exist == 0)
    error->all(FLERR, "polyhedron_set command before simulation box is defined");
  if (atom->natoms == 0) error->all(FLERR, "polyhedron_set command with no atoms existing");
  if (narg < 4) error->all(FLERR, "Illegal polyhedron_set command: too few arguments");
  auto avec = PolyShapeLibrary::of(lmp, "polyhedron_set");

  // ---- selection
  const int nlocal = atom->nlocal;
  std::vector<char> select(nlocal, 0);
  const std::string style = arg[0];
  if (style == "atom" || style == "type") {
    bigint lo, hi;
    if (style == "atom") {
      utils::bounds(FLERR, arg[1], 1, MAXTAGINT, lo, hi, error);
      for (int i = 0; i < nlocal; i++)
        select[i] = (atom->tag[i] >= lo && atom->tag[i] <= hi);
    } else {
      utils::bounds(FLERR, arg[1], 1, atom->ntypes, lo, hi, error);
      for (int i = 0; i < nlocal; i++)
        select[i] = (atom->type[i] >= lo && atom->type[i] <= hi);
    }
  } else if (style == "group") {
    const int igroup = group->find(arg[1]);
    if (igroup < 0) error->all(FLERR, "polyhedron_set: group '{}' does not exist", arg[1]);
    const int bit = group->bitmask[igroup];
    for (int i = 0; i < nlocal; i++) select[i] = (atom->mask[i] & bit) ? 1 : 0;
  } else if (style == "region") {
    Region *region = polydem_compat::find_region(domain, arg[1]);
    if (!region) error->all(FLERR, "polyhedron_set: region '{}' does not exist", arg[1]);
    region->prematch();
    double **x = atom->x;
    for (int i = 0; i < nlocal; i++) select[i] = region->match(x[i][0], x[i][1], x[i][2]);
  } else
    error->all(FLERR, "polyhedron_set: unknown style '{}' (atom, type, group or region)", style);

  // with KOKKOS the current values may live on the device
  if (lmp->kokkos) atomKK->sync(Host, ALL_MASK);

  double **quat = atom->quat;
  double **angmom = atom->angmom;
  double **omega = atom->omega;
  double *rmass = atom->rmass;

  // ---- keywords
  int iarg = 2;
  while (iarg < narg) {
    const std::string kw = arg[iarg];
    auto need = [&](int n) {
      if (iarg + n >= narg)
        error->all(FLERR, "polyhedron_set: keyword '{}' needs {} value(s)", kw, n);
    };
    if (kw == "shape") {
      need(1);
      const int ishape = avec->find_shape(arg[iarg + 1]);
      if (ishape < 0) error->all(FLERR, "polyhedron_set: unknown shape ID '{}'", arg[iarg + 1]);
      for (int i = 0; i < nlocal; i++)
        if (select[i]) avec->set_shape_scale(i, ishape, atom->pscale[i]);
      iarg += 2;
    } else if (kw == "scale") {
      need(1);
      const double s = polydem_parse::number(FLERR, arg[iarg + 1], lmp, "polyhedron_set");
      if (!(s > 0.0) || !std::isfinite(s))
        error->all(FLERR, "polyhedron_set: scale must be > 0, got '{}'", arg[iarg + 1]);
      for (int i = 0; i < nlocal; i++)
        if (select[i]) avec->set_shape_scale(i, atom->pshape[i], s);
      iarg += 2;
    } else if (kw == "density" || kw == "mass") {
      need(1);
      const double val = polydem_parse::number(FLERR, arg[iarg + 1], lmp, "polyhedron_set");
      if (!(val > 0.0) || !std::isfinite(val))
        error->all(FLERR, "polyhedron_set: {} must be > 0, got '{}'", kw, arg[iarg + 1]);
      for (int i = 0; i < nlocal; i++)
        if (select[i]) {
          if (kw == "mass") rmass[i] = val;
          else {
            const double s = atom->pscale[i];
            rmass[i] = polydem::scaled_mass(val, avec->shape(atom->pshape[i]).view().volume, s);
          }
        }
      iarg += 2;
    } else if (kw == "quat") {
      need(4);
      double a[3];
      for (int k = 0; k < 3; k++) a[k] = polydem_parse::number(FLERR, arg[iarg + 1 + k], lmp, "polyhedron_set");
      const double theta = polydem_parse::number(FLERR, arg[iarg + 4], lmp, "polyhedron_set") * MY_PI / 180.0;
      const double n = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
      if (!(n > 0.0) || !std::isfinite(n) || !std::isfinite(theta))
        error->all(FLERR, "polyhedron_set: quat needs a finite non-zero axis and angle");
      const double c = cos(0.5 * theta), s = sin(0.5 * theta) / n;
      for (int i = 0; i < nlocal; i++)
        if (select[i]) {
          quat[i][0] = c;
          quat[i][1] = s * a[0];
          quat[i][2] = s * a[1];
          quat[i][3] = s * a[2];
        }
      iarg += 5;
    } else if (kw == "quat/random") {
      need(1);
      const int seed = utils::inumeric(FLERR, arg[iarg + 1], false, lmp);
      if (seed <= 0) error->all(FLERR, "polyhedron_set: quat/random seed must be > 0");
      RanPark ran(lmp, seed);
      for (int i = 0; i < nlocal; i++)
        if (select[i]) {
          // uniform on SO(3) (Shoemake's subgroup algorithm)
          ran.reset(seed, atom->x[i]);
          const double u = ran.uniform();
          const double t1 = sqrt(1.0 - u), t2 = sqrt(u);
          const double th1 = 2.0 * MY_PI * ran.uniform(), th2 = 2.0 * MY_PI * ran.uniform();
          quat[i][0] = cos(th2) * t2;
          quat[i][1] = sin(th1) * t1;
          quat[i][2] = cos(th1) * t1;
          quat[i][3] = sin(th2) * t2;
        }
      iarg += 2;
    } else if (kw == "angmom" || kw == "omega") {
      need(3);
      double w[3];
      for (int k = 0; k < 3; k++) w[k] = polydem_parse::number(FLERR, arg[iarg + 1 + k], lmp, "polyhedron_set");
      for (int i = 0; i < nlocal; i++)
        if (select[i]) {
          if (kw == "angmom") {
            for (int k = 0; k < 3; k++) angmom[i][k] = w[k];
          } else {
            double inertia[3];
            avec->inertia(i, inertia);
            polydem::angmom_from_omega(inertia, w, quat[i], angmom[i]);
          }
        }
      iarg += 4;
    } else
      error->all(FLERR, "polyhedron_set: unknown keyword '{}'", kw);
  }

  // mass and moments must stay finite and non-zero (density 1e308, scale 1e-300)
  bigint nbad = 0;
  tagint first = MAXTAGINT;
  for (int i = 0; i < nlocal; i++)
    if (select[i] && !avec->mass_is_normal(i)) {
      nbad++;
      first = std::min(first, atom->tag[i]);
    }
  bigint allbad;
  tagint allfirst;
  MPI_Allreduce(&nbad, &allbad, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  MPI_Allreduce(&first, &allfirst, 1, MPI_LMP_TAGINT, MPI_MIN, world);
  if (allbad)
    error->all(FLERR,
               "polyhedron_set: {} atom(s) (first: ID {}) get a mass outside (0, 1e250] or "
               "a moment of inertia that is zero or not finite: check density, mass and scale",
               allbad, allfirst);
  if (lmp->kokkos) atomKK->modified(Host, ALL_MASK);

  // keep omega consistent with angmom, orientation and inertia
  bigint count = 0;
  for (int i = 0; i < nlocal; i++)
    if (select[i]) {
      double inertia[3];
      avec->inertia(i, inertia);
      polydem::omega_from_angmom(inertia, angmom[i], quat[i], omega[i]);
      count++;
    }
  bigint all;
  MPI_Allreduce(&count, &all, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (comm->me == 0) utils::logmesg(lmp, "  polyhedron_set: {} atom(s) changed\n", all);
}
