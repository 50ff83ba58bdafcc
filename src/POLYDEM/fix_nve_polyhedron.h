/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - fix nve/polyhedron: velocity-Verlet translation and symplectic
   free-rotor splitting for rigid polyhedra (polyhedral seed §2.5).
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(nve/polyhedron,FixNVEPolyhedron);
// clang-format on
#else

#ifndef LMP_FIX_NVE_POLYHEDRON_H
#define LMP_FIX_NVE_POLYHEDRON_H

#include "fix_nve.h"
#include "polydem_shape_view.h"

#include <vector>

namespace LAMMPS_NS {

class FixNVEPolyhedron : public FixNVE {
 public:
  FixNVEPolyhedron(class LAMMPS *, int, char **);
  void init() override;
  void initial_integrate(int) override;
  void final_integrate() override;

 protected:
  class PolyShapeLibrary *avec;
  std::vector<polydem::ShapeView<double>> views;    // the templates', per step
  void integrate(bool first);    // first: the step's first half
};

}    // namespace LAMMPS_NS

#endif
#endif
