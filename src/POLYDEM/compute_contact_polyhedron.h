/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - compute contact/polyhedron: global contact statistics (number
   of contacts, mean and largest overlap volume relative to the smaller
   particle, coordination number) from the records pair polyhedron (plain
   or /kk) stores on the steps this compute is due.
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(contact/polyhedron,ComputeContactPolyhedron);
// clang-format on
#else

#ifndef LMP_COMPUTE_CONTACT_POLYHEDRON_H
#define LMP_COMPUTE_CONTACT_POLYHEDRON_H

#include "compute.h"

namespace LAMMPS_NS {

class ComputeContactPolyhedron : public Compute {
 public:
  ComputeContactPolyhedron(class LAMMPS *, int, char **);
  ~ComputeContactPolyhedron() override;
  void init() override;
  void compute_vector() override;

 private:
  class ContactRecordSource *pair;    // pair polyhedron (poly_roles.h)
};

}    // namespace LAMMPS_NS

#endif
#endif
