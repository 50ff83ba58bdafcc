/* ----------------------------------------------------------------------
   POLYDEM - the roles fixes play for other styles (poly_roles.h)
------------------------------------------------------------------------- */

#include "poly_roles.h"

#include "error.h"
#include "fix.h"
#include "force.h"
#include "lammps.h"
#include "modify.h"
#include "pair.h"

#include <algorithm>

using namespace LAMMPS_NS;

std::vector<InsertionObstacle *> InsertionObstacle::all(LAMMPS *lmp)
{
  std::vector<InsertionObstacle *> out;
  for (int i = 0; i < lmp->modify->nfix; i++) {
    auto o = dynamic_cast<InsertionObstacle *>(lmp->modify->fix[i]);
    if (o) out.push_back(o);
  }
  return out;
}

double ParticleSource::max_radius(LAMMPS *lmp)
{
  double r = 0.0;
  for (int i = 0; i < lmp->modify->nfix; i++) {
    auto s = dynamic_cast<ParticleSource *>(lmp->modify->fix[i]);
    if (s) r = std::max(r, s->max_insert_radius());
  }
  return r;
}

std::vector<ParticleSource::Candidate> ParticleSource::candidates(LAMMPS *lmp)
{
  std::vector<Candidate> out;
  for (int i = 0; i < lmp->modify->nfix; i++) {
    auto s = dynamic_cast<ParticleSource *>(lmp->modify->fix[i]);
    if (s) s->add_candidates(out);
  }
  return out;
}

ContactRecordSource *ContactRecordSource::require(LAMMPS *lmp, const char *who)
{
  auto *p = dynamic_cast<ContactRecordSource *>(lmp->force->pair);
  if (!p)
    lmp->error->all(FLERR, "compute {} requires pair_style polyhedron or polyhedron/kk", who);
  return p;
}
