/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - compute contact/polyhedron/local: one row per polyhedron
   contact (force-chain analysis), from the records pair polyhedron (plain
   or /kk) stores on the steps this compute is due.
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(contact/polyhedron/local,ComputeContactPolyhedronLocal);
// clang-format on
#else

#ifndef LMP_COMPUTE_CONTACT_POLYHEDRON_LOCAL_H
#define LMP_COMPUTE_CONTACT_POLYHEDRON_LOCAL_H

#include "compute.h"

#include <vector>

namespace LAMMPS_NS {

class ComputeContactPolyhedronLocal : public Compute {
 public:
  ComputeContactPolyhedronLocal(class LAMMPS *, int, char **);
  ~ComputeContactPolyhedronLocal() override;
  void init() override;
  void compute_local() override;
  double memory_usage() override;

 private:
  std::vector<int> field;    // record field (polydem_contact_record.h) per column
  int nmax;
  class ContactRecordSource *pair;    // pair polyhedron (poly_roles.h)
};

}    // namespace LAMMPS_NS

#endif
#endif
