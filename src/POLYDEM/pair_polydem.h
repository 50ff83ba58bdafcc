/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - what pair_style polyhedron and pair_style ellipsoid share on
   the host (not a style of its own): the per-pair history fix and its
   placeholder, the kernel counters and their warnings, the restart of
   settings and coefficients (one field list for writing and reading, with
   a format version), the history transfer of the pair sign convention, and
   the cutoff from the particle sizes present and to come.
------------------------------------------------------------------------- */

#ifndef LMP_PAIR_POLYDEM_H
#define LMP_PAIR_POLYDEM_H

#include "pair.h"
#include "polydem_lammps_compat.h"

#include <cstdio>
#include <string>

namespace LAMMPS_NS {

class PairPolydem : public Pair {
 public:
  // style: "polyhedron"; history_tag: ID stem of its history fix;
  // nhistory: values per pair
  PairPolydem(class LAMMPS *, const char *style, const char *history_tag, int nhistory,
              int ncount);
  ~PairPolydem() override;

  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  void write_restart_settings(FILE *) override;
  void read_restart_settings(FILE *) override;

  static constexpr int MAXCOUNT = 8;
  double counters[MAXCOUNT];    // kernel counters summed over ranks (extract "counters")

  // one list of restart fields for writing (rank 0) and reading (rank 0,
  // then broadcast)
  class RestartFields {
   public:
    RestartFields(PairPolydem *p, FILE *f, bool r) : pair(p), fp(f), reading(r) {}
    void operator()(double &v);
    void operator()(int &v);
    void flag_as_double(int &v);    // a 0/1 flag stored as a double

   private:
    PairPolydem *pair;
    FILE *fp;
    bool reading;
    // v written, or read on rank 0 and broadcast as `type`
    template <class V> void field(V &v, MPI_Datatype type);
  };

 protected:
  const std::string style_name;
  const std::string history_tag;
  const int nhistory;
  const int ncount;
  class PolyShapeLibrary *avec;
  class FixDummy *fix_dummy;
  class FixNeighHistory *fix_history;
  // suffix of the history fix ID: counts this style's pair styles of this
  // LAMMPS instance (Pair::instance_me counts all instances of the process,
  // so with several LAMMPS objects a restart would not find its history)
  int history_id;
  double local_counts[MAXCOUNT];
  double reported[MAXCOUNT];

  virtual void allocate() = 0;
  // the style's settings and per-type coefficients, in file order
  virtual void settings_fields(RestartFields &) = 0;
  virtual void coeff_fields(RestartFields &) = 0;
  // why a restart file of another settings version is refused
  virtual const char *restart_version_text() const = 0;

  std::string history_fix_id() const;
  std::string dummy_fix_id() const;
  // init_style: the atom style, ghost velocities, the size neighbor list,
  // counters reset
  void init_common(bool history);
  // the history fix in the placeholder's place (created once), found again
  void setup_history_fix();
  // warn (collectively) about counters[k], k < nwarn, that grew since the last report
  void report_counters(const char *const *what, int nwarn);
  // twice the largest bounding radius present or announced by an insertion fix
  double size_cutoff();
  void transfer_history(double *, double * POLYDEM_TRANSFER_HISTORY_TYPES) override;

  // the /kk styles' constructor settings and destructor (the per-atom
  // tallies), and their init_style around the plain one (pair_polydem_kokkos.h)
  template <class DeviceType> void kk_construct();
  template <class KE, class KV> void kk_destroy_tallies(KE &k_eatom, KV &k_vatom);
  // compute: the per-atom tally Views as ev_init asked for them; the atoms
  // synced to the execution space and marked modified there
  template <class KE, class KV> void kk_tally_views(KE &k_eatom, KV &k_vatom);
  template <class DeviceType, class KE, class KV> void kk_tally_to_host(KE &k_eatom, KV &k_vatom);
  void kk_sync_atoms(int eflag, int vflag);
  template <class DeviceType> class AtomVecPolyhedronKokkos *kk_init_before(bool history);
  template <class DeviceType> void kk_init_after();
};

}    // namespace LAMMPS_NS

#endif
