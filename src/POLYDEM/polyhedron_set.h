/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - command polyhedron_set style ID keyword value ...
   Per-atom properties of atom_style polyhedron (the core 'set' command
   does not know templates): shape, scale, density, mass, quat,
   quat/random, angmom, omega.
------------------------------------------------------------------------- */

#ifdef COMMAND_CLASS
// clang-format off
CommandStyle(polyhedron_set,PolyhedronSet);
// clang-format on
#else

#ifndef LMP_POLYHEDRON_SET_H
#define LMP_POLYHEDRON_SET_H

#include "command.h"

namespace LAMMPS_NS {

class PolyhedronSet : public Command {
 public:
  PolyhedronSet(class LAMMPS *lmp) : Command(lmp) {}
  void command(int, char **) override;
};

}    // namespace LAMMPS_NS

#endif
#endif
