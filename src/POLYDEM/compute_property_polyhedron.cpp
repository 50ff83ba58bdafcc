/* ----------------------------------------------------------------------
   POLYDEM - compute property/polyhedron
   compute ID group property/polyhedron keyword ...
     keywords: shape scale density quatw quati quatj quatk
------------------------------------------------------------------------- */

#include "compute_property_polyhedron.h"

#include "accelerator_kokkos.h"
#include "atom.h"
#include "atom_masks.h"
#include "error.h"
#include "memory.h"
#include "poly_shape_library.h"
#include "update.h"

using namespace LAMMPS_NS;

ComputePropertyPolyhedron::ComputePropertyPolyhedron(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), avec(nullptr), nmax(0), vector(nullptr), array(nullptr)
{
  if (narg < 4)
    error->all(FLERR,
               "Illegal compute property/polyhedron command: expected at least one of "
               "shape scale density quatw quati quatj quatk");
  avec = PolyShapeLibrary::of(lmp, "compute property/polyhedron");
  for (int iarg = 3; iarg < narg; iarg++) {
    const int k = avec->property_atom(arg[iarg]);
    if (k < 0)
      error->all(FLERR,
                 "compute property/polyhedron: unknown keyword '{}' (shape scale density "
                 "quatw quati quatj quatk)",
                 arg[iarg]);
    index.push_back(k);
  }
  peratom_flag = 1;
  size_peratom_cols = index.size() == 1 ? 0 : (int) index.size();
}

ComputePropertyPolyhedron::~ComputePropertyPolyhedron()
{
  memory->destroy(vector);
  memory->destroy(array);
}

void ComputePropertyPolyhedron::init()
{
  avec = PolyShapeLibrary::of(lmp, "compute property/polyhedron");
}

void ComputePropertyPolyhedron::compute_peratom()
{
  invoked_peratom = update->ntimestep;
  if (atom->nmax > nmax) {
    nmax = atom->nmax;
    if (index.size() == 1) {
      memory->destroy(vector);
      memory->create(vector, nmax, "property/polyhedron:vector");
      vector_atom = vector;
    } else {
      memory->destroy(array);
      memory->create(array, nmax, (int) index.size(), "property/polyhedron:array");
      array_atom = array;
    }
  }
  // with KOKKOS the current values may live on the device
  if (lmp->kokkos) atomKK->sync(Host, ALL_MASK);
  const int n = (int) index.size();
  for (int k = 0; k < n; k++)
    avec->pack_property_atom(index[k], n == 1 ? vector : &array[0][k], n, groupbit);
}

double ComputePropertyPolyhedron::memory_usage()
{
  return (double) nmax * index.size() * sizeof(double);
}
