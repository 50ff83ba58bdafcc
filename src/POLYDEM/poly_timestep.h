/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - the time-step check of pair polyhedron, pair ellipsoid and
   fix wall/mesh: one computation and one wording. Each style adds the
   contacts it can make (the lightest, stiffest particles, those present and
   those an insertion fix will add); report() takes the minimum over the
   ranks, logs it on rank 0 and warns:
   - contact time t_c = pi sqrt(m / k_n) of a linear spring (seed §4;
     Feng's law at a contact section of area R^2: k_n = 2 E R, Eq. 13):
     warning above t_c / 10;
   - the explicit stability limit 2 sqrt(m / k) of a largest face resting
     flat in the core, k = 5/3 K V0^(-2/3) A^2 (polydem_contact_law.h,
     face_contact_stable_dt): warning above half of it.
------------------------------------------------------------------------- */

#ifndef LMP_POLY_TIMESTEP_H
#define LMP_POLY_TIMESTEP_H

#include <string>

namespace LAMMPS_NS {

class LAMMPS;

struct TimestepCheck {
  double tc = 1e300;      // smallest contact time
  double face = 1e300;    // smallest flat-face stability limit

  // a contact of mass m (the pair's reduced mass) and stiffness k_n, both in
  // consistent units (k_n times force->ftm2v)
  void contact(double m, double kn);
  // a flat face's stability limit (0 or less: no bound, ignored)
  void flat_face(double dt);
  // Minimum over the ranks of world; on rank 0: log "who: contact time ..."
  // (what: how t_c was estimated) and "who: a face flat on `against` in the
  // core ..." where there is a bound, and warn where dt exceeds it.
  void report(LAMMPS *lmp, const std::string &who, const std::string &what,
              const std::string &against, double core);
};

}    // namespace LAMMPS_NS

#endif
