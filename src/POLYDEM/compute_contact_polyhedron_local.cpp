/* ----------------------------------------------------------------------
   POLYDEM - compute contact/polyhedron/local
------------------------------------------------------------------------- */

#include "compute_contact_polyhedron_local.h"

#include "error.h"
#include "memory.h"
#include "poly_roles.h"
#include "update.h"

#include "polydem_contact_record.h"

#include <cstring>

using namespace LAMMPS_NS;
using namespace polydem;

namespace {
struct Keyword {
  const char *name;
  int field;
};
constexpr Keyword KEYWORDS[] = {
    {"id1", CR_ID1},  {"id2", CR_ID2},      {"vol", CR_VOL},  {"volfrac", -1},  {"area", CR_AREA},
    {"fx", CR_F},     {"fy", CR_F + 1},     {"fz", CR_F + 2}, {"nx", CR_N},     {"ny", CR_N + 1},
    {"nz", CR_N + 2}, {"cx", CR_C},         {"cy", CR_C + 1}, {"cz", CR_C + 2}, {"fn", CR_FN},
    {"ft", CR_FT},    {"energy", CR_ENERGY}};
}    // namespace

/* ----------------------------------------------------------------------
   compute ID group contact/polyhedron/local keyword ...
------------------------------------------------------------------------- */

ComputeContactPolyhedronLocal::ComputeContactPolyhedronLocal(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), nmax(0), pair(nullptr)
{
  if (narg < 4)
    error->all(FLERR,
               "compute contact/polyhedron/local: expected at least one keyword "
               "(id1 id2 vol volfrac area fx fy fz nx ny nz cx cy cz fn ft energy)");
  for (int iarg = 3; iarg < narg; iarg++) {
    int found = -2;
    for (const auto &k : KEYWORDS)
      if (strcmp(arg[iarg], k.name) == 0) found = k.field;
    if (found == -2)
      error->all(FLERR, "compute contact/polyhedron/local: unknown keyword '{}'", arg[iarg]);
    field.push_back(found);
  }
  local_flag = 1;
  timeflag = 1;    // the pair stores its contacts on the steps this compute is due
  size_local_rows = 0;
  size_local_cols = field.size() == 1 ? 0 : (int) field.size();
  vector_local = nullptr;
  array_local = nullptr;
}

ComputeContactPolyhedronLocal::~ComputeContactPolyhedronLocal()
{
  memory->destroy(vector_local);
  memory->destroy(array_local);
}

void ComputeContactPolyhedronLocal::init()
{
  pair = ContactRecordSource::require(lmp, "contact/polyhedron/local");
}

/* ----------------------------------------------------------------------
   rows: the contacts owned by this rank whose two atoms are in the group
------------------------------------------------------------------------- */

void ComputeContactPolyhedronLocal::compute_local()
{
  invoked_local = update->ntimestep;
  int n, stride;
  const double *rec = pair->contact_records(n, stride, true, "contact/polyhedron/local");
  int rows = 0;
  for (int c = 0; c < n; c++) {
    const double *r = rec + c * stride;
    if (contact_in_group(r, groupbit)) rows++;
  }
  if (rows > nmax) {
    nmax = rows;
    memory->destroy(vector_local);
    memory->destroy(array_local);
    if (field.size() == 1)
      memory->create(vector_local, nmax, "contact/polyhedron/local:vector");
    else
      memory->create(array_local, nmax, (int) field.size(), "contact/polyhedron/local:array");
  }
  size_local_rows = rows;
  int row = 0;
  for (int c = 0; c < n; c++) {
    const double *r = rec + c * stride;
    if (!contact_in_group(r, groupbit)) continue;
    for (size_t k = 0; k < field.size(); k++) {
      const double value = field[k] < 0 ? r[CR_VOL] / r[CR_VMIN] : r[field[k]];
      if (field.size() == 1)
        vector_local[row] = value;
      else
        array_local[row][k] = value;
    }
    row++;
  }
}

double ComputeContactPolyhedronLocal::memory_usage()
{
  return (double) nmax * field.size() * sizeof(double);
}
