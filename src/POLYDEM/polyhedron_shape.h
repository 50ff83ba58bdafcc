/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - command polyhedron_shape ID file [hull yes|no]
   Loads a shape template (potentials/*.shape), an ellipsoid or a composite
   of convex parts into atom_style polyhedron.
------------------------------------------------------------------------- */

#ifdef COMMAND_CLASS
// clang-format off
CommandStyle(polyhedron_shape,PolyhedronShape);
// clang-format on
#else

#ifndef LMP_POLYHEDRON_SHAPE_H
#define LMP_POLYHEDRON_SHAPE_H

#include "command.h"

#include <memory>
#include <string>

namespace polydem {
class PolyShapeTemplate;
}

namespace LAMMPS_NS {

class PolyhedronShape : public Command {
 public:
  PolyhedronShape(class LAMMPS *lmp) : Command(lmp) {}
  void command(int, char **) override;

 private:
  void composite(const std::string &id, int narg, char **arg);
  void add(const std::string &id, std::unique_ptr<polydem::PolyShapeTemplate> t,
           const std::string &record, const std::string &what);
  void add_composite(const std::string &id, std::unique_ptr<polydem::PolyShapeTemplate> t,
                     const std::string &record, const std::string &how);
};

}    // namespace LAMMPS_NS

#endif
#endif
