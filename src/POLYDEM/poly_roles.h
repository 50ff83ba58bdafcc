/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - the roles fixes play for other styles, so that no style includes
   another style's header (as LAMMPS's pair styles learn future radii from
   fix pour through Fix::extract, never through fix_pour.h):
   - InsertionObstacle: a fix whose geometry inserted particles must keep
     clear of (fix wall/mesh); fix insert/polyhedron collects them from
     modify.
   - ParticleSource: a fix that creates particles during a run (fix
     insert/polyhedron); pair styles and walls size their cutoffs and check
     the time step and material with the particles to come.
   - ContactRecordSource: a pair style that records its contacts (pair
     polyhedron, plain and /kk) for the contact computes.
------------------------------------------------------------------------- */

#ifndef LMP_POLY_ROLES_H
#define LMP_POLY_ROLES_H

#include "polydem_insert.h"

#include <vector>

namespace LAMMPS_NS {

class LAMMPS;

// The roles' destructors are protected and not virtual: a role is never
// deleted through it, and a virtual one would have to repeat the exception
// specification of the style's own base (Fix and Pair are noexcept(false)
// in some LAMMPS versions).
class InsertionObstacle {
 public:
  // true if body b (lab frame, orientation q) is certified farther than gap
  // from the obstacle at its current pose and has no contact with it
  virtual bool insertion_clear(const polydem::InsertBody<double> &b,
                               const polydem::Quat<double> &q, double gap) = 0;
  // every fix with this role, in the order of modify
  static std::vector<InsertionObstacle *> all(LAMMPS *);

 protected:
  ~InsertionObstacle() = default;
};

class ParticleSource {
 public:
  // the smallest particle of one kind a source may create
  struct Candidate {
    int ishape;           // shape template
    double scale, mass;
    int type;
    int mask;             // the group bits the created atoms get
    const char *source;   // the fix's ID (messages)
  };
  // largest bounding radius of a particle it may create (0: none)
  virtual double max_insert_radius() const = 0;
  virtual void add_candidates(std::vector<Candidate> &out) const = 0;

  // over every fix with this role
  static double max_radius(LAMMPS *);
  static std::vector<Candidate> candidates(LAMMPS *);

 protected:
  ~ParticleSource() = default;
};

class ContactRecordSource {
 public:
  // the per-contact records (polydem_contact_record.h) of the current
  // step's force evaluation, n records of stride doubles (CR_NFIELD, or
  // CR_NSUMMARY where no compute asks for whole records);
  // an error naming compute 'who' if there are none, or if full and the
  // step has summaries only
  virtual const double *contact_records(int &n, int &stride, bool full, const char *who) = 0;
  // the pair style of this LAMMPS if it has the role, else an error naming
  // compute 'who'
  static ContactRecordSource *require(LAMMPS *, const char *who);

 protected:
  ~ContactRecordSource() = default;
};

}    // namespace LAMMPS_NS

#endif
