/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - dump polyhedron/vtk: every particle as its true polyhedron,
   legacy-VTK polydata (ParaView reads it), one file per snapshot.
   Only id, type, shape, scale, position and quaternion travel to the
   writing rank; it rebuilds the faces from the templates.
------------------------------------------------------------------------- */

#ifdef DUMP_CLASS
// clang-format off
DumpStyle(polyhedron/vtk,DumpPolyhedronVTK);
// clang-format on
#else

#ifndef LMP_DUMP_POLYHEDRON_VTK_H
#define LMP_DUMP_POLYHEDRON_VTK_H

#include "dump.h"

#include <vector>

namespace LAMMPS_NS {

class DumpPolyhedronVTK : public Dump {
 public:
  DumpPolyhedronVTK(class LAMMPS *, int, char **);

  // what is drawn for each shape template (unit scale, body frame): the
  // polyhedron itself, a tessellation of an ellipsoid's surface, or the
  // parts of a composite placed in its frame
  struct DrawMesh {
    std::vector<double> verts;
    std::vector<int> face_start, face_verts;
    int nverts() const { return (int) verts.size() / 3; }
    int nfaces() const { return (int) face_start.size() - 1; }
  };

 protected:
  void init_style() override;
  void write_header(bigint) override;
  void pack(tagint *) override;
  void write_data(int, double *) override;

 private:
  class PolyShapeLibrary *avec;
  bigint nexpected;               // particles in this snapshot
  std::vector<double> records;    // gathered on the writing rank
  std::vector<DrawMesh> meshes;
  int meshes_version;
  const DrawMesh &mesh_of(int shape);
  void write_snapshot();
};

}    // namespace LAMMPS_NS

#endif
#endif
