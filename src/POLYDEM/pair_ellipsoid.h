/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - pair_style ellipsoid: exact algebraic contact between rigid
   ellipsoids of atom_style polyhedron (ellipsoid seed §2-4): characteristic
   quartic classification, shrink-to-touch contact point and normal, overlap
   chord, linear spring + restitution damping, optional Cundall-Strack
   friction with per-pair history. Physics in
   polydem_ellipsoid.h and polydem_ellipsoid_force.h.
------------------------------------------------------------------------- */

#ifdef PAIR_CLASS
// clang-format off
PairStyle(ellipsoid,PairEllipsoid);
// clang-format on
#else

#ifndef LMP_PAIR_ELLIPSOID_H
#define LMP_PAIR_ELLIPSOID_H

#include "pair_polydem.h"
#include "polydem_law_table.h"
#include "polydem_pair_counts.h"

#include <vector>

namespace LAMMPS_NS {

class PairEllipsoid : public PairPolydem {
 public:
  PairEllipsoid(class LAMMPS *);
  ~PairEllipsoid() override;
  void compute(int, int) override;
  void settings(int, char **) override;
  void coeff(int, char **) override;
  void init_style() override;
  double init_one(int, int) override;
  void *extract(const char *, int &) override;

  // counters since the start of the run (global after report_counters),
  // indexed by polydem::EllipsoidPairCount (polydem_pair_counts.h);
  // EP_COLLISIONS: contacts in their first step (delta < (d delta/dt) dt),
  // i.e. collisions started; EP_CONTACTS: pair-steps in contact
  static constexpr int NCOUNT = polydem::EP_NCOUNT;

 protected:
  double **kn, **restitution;    // per type pair
  double **friction;             // per type pair: Coulomb mu (0: frictionless)
  double kt_ratio, gt_ratio;     // k_t / k_n, gamma_t / gamma_n (keyword tangential)
  int use_history;               // some mu > 0: per-pair tangential history
  double overlap_warn;           // warn for delta > overlap_warn * smallest semi-axis
  int overlap;                   // polydem::OVERLAP_CENTRE or OVERLAP_CHORD
  int damping_mass;              // polydem::DAMPING_REDUCED or DAMPING_CONTACT

  void allocate() override;
  void settings_fields(RestartFields &) override;
  void coeff_fields(RestartFields &) override;
  const char *restart_version_text() const override;
  int friction_used() const;
  void report_counters();
  void check_timestep();
};

}    // namespace LAMMPS_NS

#endif
#endif
