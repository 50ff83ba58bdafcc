/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - pair_style polyhedron: energy-conserving overlap-volume contact
   between rigid convex polyhedra (polyhedral seed §2.2-2.5): bounding-sphere
   broad phase on LAMMPS's neighbor list, GJK, overlap polyhedron by dual
   Quickhull, Feng's normal force from W(V), damping, Cundall-Strack friction
   with history. Physics in polydem_overlap.h and polydem_contact_law.h.
------------------------------------------------------------------------- */

#ifdef PAIR_CLASS
// clang-format off
PairStyle(polyhedron,PairPolyhedron);
// clang-format on
#else

#ifndef LMP_PAIR_POLYHEDRON_H
#define LMP_PAIR_POLYHEDRON_H

#include "pair_polydem.h"
#include "poly_roles.h"
#include "polydem_law_table.h"
#include "polydem_pair_counts.h"
#include "polydem_shape_view.h"

#include <memory>
#include <vector>

namespace polydem {
template <typename T, int MF> struct OverlapWorkspace;
}

namespace LAMMPS_NS {

class PairPolyhedron : public PairPolydem, public ContactRecordSource {
 public:
  PairPolyhedron(class LAMMPS *);
  ~PairPolyhedron() override;
  void compute(int, int) override;
  void settings(int, char **) override;
  void coeff(int, char **) override;
  void init_style() override;
  double init_one(int, int) override;
  void *extract(const char *, int &) override;
  double memory_usage() override;

  // counters since the start of the run (global after report_counters),
  // indexed by polydem::PolyhedronPairCount (polydem_pair_counts.h)
  static constexpr int NCOUNT = polydem::PP_NCOUNT;

  // Per-contact records (polydem_contact_record.h) of the force evaluation of
  // the current step, each contact once over all ranks, for the contact
  // computes. Stored only on the steps such a compute is due (Compute
  // timeflag/matchstep, as for compute pe); errors naming 'who' otherwise.
  const double *contact_records(int &n, int &stride, bool full, const char *who) override;

 protected:
  double *youngs, *poisson;    // per type
  int *matset;                 // per type: material given
  double **restitution, **friction;
  // per type pair: k_n of the algebraic contact of two ellipsoids of which
  // one has unequal semi-axes (pair_coeff ... ellipsoid k_n; 0: none given)
  double **ellipsoid_kn;
  int twist;                   // torsional friction of the contact area (polydem_contact_law.h)
  int **pairset;               // explicit e, mu for an unlike pair
  double overlap_warn;         // warn for V > overlap_warn * smaller particle volume
  double core;                 // quadratic W below V0 = core * smaller particle volume
  int part_slots;              // part/slots: keyed part contacts per pair of composites
  double dt;

  std::unique_ptr<polydem::OverlapWorkspace<double, 128>> ws;
  std::vector<double> contact_data;    // record_stride doubles per stored contact
  int record_stride;                   // CR_NFIELD, or CR_NSUMMARY (summaries only)
  std::vector<polydem::ShapeView<double>> views;    // the templates', per compute
  bigint contact_step;                 // step of contact_data, -1: none

  bool store_contacts_now();
  void allocate() override;
  void settings_fields(RestartFields &) override;
  void coeff_fields(RestartFields &) override;
  const char *restart_version_text() const override;
  void report_counters();
  void check_timestep();
  // composites: every pair of parts of a pair keeps its history (up to 16)
  int history_slots() override;
};

}    // namespace LAMMPS_NS

#endif
#endif
