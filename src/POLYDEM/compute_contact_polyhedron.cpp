/* ----------------------------------------------------------------------
   POLYDEM - compute contact/polyhedron
------------------------------------------------------------------------- */

#include "compute_contact_polyhedron.h"

#include "error.h"
#include "group.h"
#include "poly_roles.h"
#include "update.h"

#include "polydem_contact_record.h"

using namespace LAMMPS_NS;
using namespace polydem;

/* ----------------------------------------------------------------------
   compute ID group contact/polyhedron
   vector: [1] contacts, [2] mean V/V_min, [3] max V/V_min, [4] 2 contacts / atoms
------------------------------------------------------------------------- */

ComputeContactPolyhedron::ComputeContactPolyhedron(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), pair(nullptr)
{
  if (narg != 3)
    error->all(FLERR, "compute contact/polyhedron: expected no arguments after the style, got {}",
               narg - 3);
  vector_flag = 1;
  size_vector = 4;
  timeflag = 1;    // the pair stores its contacts on the steps this compute is due
  extvector = -1;
  extlist = new int[4]{1, 0, 0, 0};
  vector = new double[4];
}

ComputeContactPolyhedron::~ComputeContactPolyhedron()
{
  delete[] vector;
  delete[] extlist;
}

void ComputeContactPolyhedron::init()
{
  pair = ContactRecordSource::require(lmp, "contact/polyhedron");
}

void ComputeContactPolyhedron::compute_vector()
{
  invoked_vector = update->ntimestep;
  int n, stride;
  const double *rec = pair->contact_records(n, stride, false, "contact/polyhedron");
  double sum[2] = {0.0, 0.0}, all[2], fmax = 0.0, allmax;    // count, sum of V/V_min
  for (int c = 0; c < n; c++) {
    const double *r = rec + c * stride;
    if (!contact_in_group(r, groupbit)) continue;
    const double frac = r[CR_VOL] / r[CR_VMIN];
    sum[0] += 1.0;
    sum[1] += frac;
    if (frac > fmax) fmax = frac;
  }
  MPI_Allreduce(sum, all, 2, MPI_DOUBLE, MPI_SUM, world);
  MPI_Allreduce(&fmax, &allmax, 1, MPI_DOUBLE, MPI_MAX, world);
  const double natoms = (double) group->count(igroup);
  vector[0] = all[0];
  vector[1] = all[0] > 0.0 ? all[1] / all[0] : 0.0;
  vector[2] = allmax;
  vector[3] = natoms > 0.0 ? 2.0 * all[0] / natoms : 0.0;
}
