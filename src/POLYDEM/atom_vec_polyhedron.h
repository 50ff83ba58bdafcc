/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - atom_style polyhedron: rigid convex polyhedra built from shape
   templates (polyhedral seed §2.1, §2.6). Per atom: template index, scale,
   quaternion, angular momentum/velocity, mass and bounding radius. Ghosts
   carry template index, scale, quaternion (and velocities), never vertices.
   The templates and the per-atom semantics are the PolyShapeLibrary this
   style owns (shared with atom_style polyhedron/kk); other styles find it
   with PolyShapeLibrary::of.
------------------------------------------------------------------------- */

#ifdef ATOM_CLASS
// clang-format off
AtomStyle(polyhedron,AtomVecPolyhedron);
// clang-format on
#else

#ifndef LMP_ATOM_VEC_POLYHEDRON_H
#define LMP_ATOM_VEC_POLYHEDRON_H

#include "atom_vec.h"
#include "poly_shape_library.h"
#include "polydem_lammps_compat.h"

namespace LAMMPS_NS {

class AtomVecPolyhedron : public AtomVec, public ShapeLibraryOwner {
 public:
  AtomVecPolyhedron(class LAMMPS *);
  void process_args(int, char **) override;
  void init() override;

  void create_atom_post(int) override;
  void data_atom_post(int) override;
  void data_vel(int, polydem_compat::data_values) override;
  void pack_data_pre(int) override;
  void pack_data_post(int) override;
  int property_atom(polydem_compat::property_name) override;
  void pack_property_atom(int, double *, int, int) override;

  PolyShapeLibrary *shape_library() override { return &shapes; }

 private:
  PolyShapeLibrary shapes;
};

}    // namespace LAMMPS_NS

#endif
#endif
