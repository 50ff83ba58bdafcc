/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - compute property/polyhedron: per-atom shape index, scale,
   density and orientation quaternion of atom_style polyhedron.
   compute property/atom gives quatw..quatk too (LAMMPS 29 Sep 2021 through
   the copy of compute_property_atom.cpp cmake/PolydemLammps.cmake patches).
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(property/polyhedron,ComputePropertyPolyhedron);
// clang-format on
#else

#ifndef LMP_COMPUTE_PROPERTY_POLYHEDRON_H
#define LMP_COMPUTE_PROPERTY_POLYHEDRON_H

#include "compute.h"

#include <vector>

namespace LAMMPS_NS {

class ComputePropertyPolyhedron : public Compute {
 public:
  ComputePropertyPolyhedron(class LAMMPS *, int, char **);
  ~ComputePropertyPolyhedron() override;
  void init() override;
  void compute_peratom() override;
  double memory_usage() override;

 private:
  class PolyShapeLibrary *avec;
  std::vector<int> index;    // PolyShapeLibrary::property_atom of each keyword
  int nmax;
  double *vector;
  double **array;
};

}    // namespace LAMMPS_NS

#endif
#endif
