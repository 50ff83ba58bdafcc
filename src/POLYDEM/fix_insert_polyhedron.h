/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - fix insert/polyhedron: shape-aware insertion of polyhedra and
   ellipsoids into a LAMMPS region, at a rate (number, mass, or N every M
   steps) or all at once (random sequential addition to a count or solid
   fraction). Every candidate is tested exactly against the particles near
   it and the mesh walls (certified GJK distance, polydem_insert.h); every
   rank runs the same candidate sequence on the same gathered data, so the
   inserted particles do not depend on the number of ranks.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(insert/polyhedron,FixInsertPolyhedron);
// clang-format on
#else

#ifndef LMP_FIX_INSERT_POLYHEDRON_H
#define LMP_FIX_INSERT_POLYHEDRON_H

#include "fix.h"
#include "poly_roles.h"

#include "polydem_insert_space.h"

#include <string>
#include <utility>
#include <vector>

namespace LAMMPS_NS {

class FixInsertPolyhedron : public Fix, public ParticleSource {
 public:
  FixInsertPolyhedron(class LAMMPS *, int, char **);
  int setmask() override;
  void init() override;
  void setup_pre_exchange() override;
  void pre_exchange() override;
  void post_run() override;
  double compute_scalar() override;
  double compute_vector(int) override;
  void write_restart(FILE *) override;
  void restart(char *) override;
  // ParticleSource: the largest bounding radius it may insert (the pair
  // styles size their cutoff with it, as with atoms present) and the
  // smallest particle of each kind (the time-step and material checks)
  double max_insert_radius() const override;
  void add_candidates(std::vector<Candidate> &out) const override;

  enum { MODE_RATE, MODE_PACK };
  enum { RATE_NONE, RATE_NUMBER, RATE_MASS, RATE_PER };
  enum { ORIENT_RANDOM, ORIENT_FIXED, ORIENT_AXIS };

 private:
  struct Kind {    // one shape template of the mixture
    std::string id;
    int ishape;
    double frac;       // as given (number or mass fraction)
    double density;    // <= 0: the global density
    polydem::ScaleDist scale;
    double pnum;    // number probability (cumulative over kinds)
  };

  class PolyShapeLibrary *avec;
  std::vector<Kind> kinds;
  std::string idregion;
  class Region *region;
  int mode, ratestyle, massfrac;
  bigint ntotal;        // particles in total (0: no count limit)
  double masstotal;     // mass in total (0: no mass limit)
  double rate;          // particles or mass per time unit, or per insertion
  int every;            // steps between insertions (rate mode)
  double phi_target;    // pack: solid fraction of the region (0: none)
  int attempts;         // per particle
  int misses;           // pack: stop after this many particles in a row found no place
  int orientstyle;
  double oaxis[3], otheta;
  double vlo[3], vhi[3], wlo[3], whi[3];
  int itype, allin;
  double gap;
  bigint seed;
  // the keywords as given (key, values; numbers canonical): a restart
  // warns about each one that changed
  std::vector<std::pair<std::string, std::string>> settings;

  // state (restart)
  polydem::InsertRng rng;
  bigint ninserted, nfailed, nattempts, nevents, nstart, next_event;
  double massinserted, volinserted;
  int packdone;
  bigint nfailed_warned;

  // log
  double last_phi = 0.0;                      // solid fraction after the last insertion
  double time_run = 0.0, time_start = 0.0;    // wall time of insertion this run, run start

  // per insertion
  double region_volume;
  polydem::InsertGrid grid;      // the particles a candidate is tested against
  polydem::InsertVoids space;    // the void cells of mode pack
  double rmax_insert;            // largest bounding radius of a candidate
  double mean_mass;              // mean particle mass of the mixture
  double mean_volume;            // and its mean particle volume
  std::vector<InsertionObstacle *> walls;    // fix wall/mesh and any other obstacle
  std::vector<polydem::ShapeView<double>> views;    // of every template (polyhedra)
  std::vector<double> inradius;                     // of every template at unit scale
  double slo[3], shi[3];    // box of the region now, within the simulation box

  struct Placed {
    int kind;
    double s, rho, x[3], q[4], v[3], w[3];
  };

  void parse_scale(int &iarg, int narg, char **arg, polydem::ScaleDist &d, const std::string &id);
  void number_probabilities();
  double estimate_region_volume();
  void region_bbox(double *lo, double *hi);
  bool sample_in_region(double *x);
  bool region_contains(const polydem::InsertBody<double> &b, const double *xc);
  std::vector<polydem::InsertBody<double>> gather(const double *lo, const double *hi, double rcand,
                                                  double &vol_in_region);
  void grid_add(const polydem::InsertBody<double> &b);
  void refresh_views();
  // the convex bodies of a posed particle (a composite: its parts) into
  // out, their orientations into qs (if given)
  void bodies_of(int ishape, double s, const double *x, const polydem::Quat<double> &q,
                 std::vector<polydem::InsertBody<double>> &out,
                 std::vector<polydem::Quat<double>> *qs = nullptr) const;
  polydem::InsertBody<double> body_of(int ishape, double s, const double *x,
                                      const polydem::Quat<double> &q) const;
  polydem::Quat<double> draw_orientation(int ishape);
  void draw_range(const double *lo, const double *hi, double *out);
  int insert(bigint nmax, double mmax, double phimax);
  void create(const std::vector<Placed> &placed);
  double pack_estimate(bigint nmax, double dm, double phistop, double vol);
  static bigint next_milestone(bigint n);
  bigint count_target(bigint k) const;
  double mass_target(bigint k) const;
  void do_event();
  bool finished() const;
};

}    // namespace LAMMPS_NS

#endif
#endif
