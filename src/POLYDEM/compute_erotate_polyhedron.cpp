/* ----------------------------------------------------------------------
   POLYDEM - compute erotate/polyhedron
------------------------------------------------------------------------- */

#include "compute_erotate_polyhedron.h"

#include "atom.h"
#include "error.h"
#include "force.h"
#include "poly_shape_library.h"
#include "polydem_rigid.h"
#include "update.h"

using namespace LAMMPS_NS;

ComputeERotatePolyhedron::ComputeERotatePolyhedron(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), avec(nullptr)
{
  if (narg != 3)
    error->all(FLERR, "Illegal compute erotate/polyhedron command: no arguments expected");
  scalar_flag = 1;
  extscalar = 1;
  avec = PolyShapeLibrary::of(lmp, "Compute erotate/polyhedron");
}

void ComputeERotatePolyhedron::init()
{
  avec = PolyShapeLibrary::of(lmp, "Compute erotate/polyhedron");
}

double ComputeERotatePolyhedron::compute_scalar()
{
  invoked_scalar = update->ntimestep;
  double **angmom = atom->angmom, **quat = atom->quat;
  int *mask = atom->mask;
  double e = 0.0;
  for (int i = 0; i < atom->nlocal; i++)
    if (mask[i] & groupbit) {
      double inertia[3];
      avec->inertia(i, inertia);
      e += polydem::rotational_energy(inertia, angmom[i], quat[i]);
    }
  MPI_Allreduce(&e, &scalar, 1, MPI_DOUBLE, MPI_SUM, world);
  scalar *= force->mvv2e;
  return scalar;
}
