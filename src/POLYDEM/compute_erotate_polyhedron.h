/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - compute erotate/polyhedron: rotational kinetic energy of a
   group of polyhedra, 1/2 sum_k Lb_k^2 / I_k (global scalar, energy units)
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(erotate/polyhedron,ComputeERotatePolyhedron);
// clang-format on
#else

#ifndef LMP_COMPUTE_EROTATE_POLYHEDRON_H
#define LMP_COMPUTE_EROTATE_POLYHEDRON_H

#include "compute.h"

namespace LAMMPS_NS {

class ComputeERotatePolyhedron : public Compute {
 public:
  ComputeERotatePolyhedron(class LAMMPS *, int, char **);
  void init() override;
  double compute_scalar() override;

 private:
  class PolyShapeLibrary *avec;
};

}    // namespace LAMMPS_NS

#endif
#endif
