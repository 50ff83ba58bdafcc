/* ----------------------------------------------------------------------
   POLYDEM - fix nve/polyhedron
------------------------------------------------------------------------- */

#include "fix_nve_polyhedron.h"

#include "atom.h"
#include "error.h"
#include "poly_shape_library.h"
#include "polydem_rigid.h"

using namespace LAMMPS_NS;
using namespace FixConst;

/* ---------------------------------------------------------------------- */

FixNVEPolyhedron::FixNVEPolyhedron(LAMMPS *lmp, int narg, char **arg) :
    FixNVE(lmp, narg, arg), avec(nullptr)
{
  if (narg != 3) error->all(FLERR, "Illegal fix nve/polyhedron command: no arguments expected");
  avec = PolyShapeLibrary::of(lmp, "Fix nve/polyhedron");
}

/* ----------------------------------------------------------------------
   omega follows from angmom, orientation and inertia (so that pair styles
   see consistent spins before the first step)
------------------------------------------------------------------------- */

void FixNVEPolyhedron::init()
{
  FixNVE::init();
  avec = PolyShapeLibrary::of(lmp, "Fix nve/polyhedron");

  double **angmom = atom->angmom, **omega = atom->omega, **quat = atom->quat;
  int *mask = atom->mask;
  for (int i = 0; i < atom->nlocal; i++)
    if (mask[i] & groupbit) {
      double inertia[3];
      avec->inertia(i, inertia);
      polydem::omega_from_angmom(inertia, angmom[i], quat[i], omega[i]);
    }
}

/* ----------------------------------------------------------------------
   first half (initial_integrate): kick (v, L by dt/2), drift (x by dt), free
   rotation (q, L by dt); second half (final_integrate): kick only. omega
   follows from L, q and the inertia after each half.
------------------------------------------------------------------------- */

void FixNVEPolyhedron::initial_integrate(int /*vflag*/)
{
  integrate(true);
}

void FixNVEPolyhedron::final_integrate()
{
  integrate(false);
}

void FixNVEPolyhedron::integrate(bool first)
{
  double **x = atom->x, **v = atom->v, **f = atom->f;
  double **angmom = atom->angmom, **torque = atom->torque, **omega = atom->omega;
  double **quat = atom->quat;
  double *rmass = atom->rmass;
  int *mask = atom->mask;
  int nlocal = atom->nlocal;
  if (igroup == atom->firstgroup) nlocal = atom->nfirst;
  const int *pshape = atom->pshape;
  const double *pscale = atom->pscale;
  avec->views(views);

  for (int i = 0; i < nlocal; i++)
    if (mask[i] & groupbit) {
      const double dtfm = dtf / rmass[i];
      for (int k = 0; k < 3; k++) {
        v[i][k] += dtfm * f[i][k];
        if (first) x[i][k] += dtv * v[i][k];
        angmom[i][k] += dtf * torque[i][k];
      }
      // principal moments (PolyShapeLibrary::inertia, the template's view
      // taken once per step)
      const auto &sv = views[pshape[i]];
      double inertia[3];
      polydem::scaled_moments(rmass[i], pscale[i], sv.volume, sv.inertia, inertia);
      if (first) polydem::free_rotor_step(dtv, inertia, angmom[i], quat[i]);
      polydem::omega_from_angmom(inertia, angmom[i], quat[i], omega[i]);
    }
}
