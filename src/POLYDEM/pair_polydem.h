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

#include "atom.h"
#include "memory.h"
#include "pair.h"
#include "polydem_contact_law.h"
#include "polydem_law_table.h"
#include "polydem_lammps_compat.h"

#include <cstdio>
#include <string>
#include <vector>

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

  static constexpr int MAXCOUNT = 12;
  double counters[MAXCOUNT];    // kernel counters summed over ranks (extract "counters")

  // one list of restart fields for writing (rank 0) and reading (rank 0,
  // then broadcast)
  class RestartFields {
   public:
    RestartFields(PairPolydem *p, FILE *f, bool r, int v) : pair(p), fp(f), reading(r), version(v)
    {
    }
    void operator()(double &v);
    void operator()(int &v);
    void flag_as_double(int &v);    // a 0/1 flag stored as a double
    // the file has the rolling-resistance fields (written since format 3)
    bool has_rolling() const { return version >= 3; }
    // ... and the liquid bridges' (since format 4)
    bool has_bridge() const { return version >= 4; }
    // ... and pair_style polyhedron's stiffness of ellipsoid pairs (since format 5)
    bool has_ellipsoid_kn() const { return version >= 5; }
    // ... and the viscous part of the liquid bridges (since format 6)
    bool has_bridge_viscous() const { return version >= 6; }
    // ... and pair_style polyhedron's part/slots (since format 7)
    bool has_part_slots() const { return version >= 7; }

   private:
    PairPolydem *pair;
    FILE *fp;
    bool reading;
    int version;
    // v written, or read on rank 0 and broadcast as `type`
    template <class V> void field(V &v, MPI_Datatype type);
  };

 protected:
  const std::string style_name;
  const std::string history_tag;
  const int nhistory_base;    // values per pair without rolling resistance
  int nhistory;               // values per pair (set in init_style: choose_history_size)
  int nhistory_contact;       // of them per contact (nhistory without part slots)
  int nhistory_restart;       // the restart file's (0: none read)
  int restart_format;         // the restart file's format (2 to 5) while it is read
  int nhistory_fix;           // values per pair of the history fix made (0: none yet)
  const int ncount;
  // rolling resistance (polydem_contact_law.h RollingLaw): mu_r per type
  // pair (pair_coeff ... rolling mu_r; 0: none), k_r factor, dashpot ratio;
  // dry cohesion per type pair (pair_coeff ... cohesion c; 0: none)
  double **rolling, **cohesion;
  // liquid bridges per type pair (pair_coeff ... bridge V_b gamma theta
  // [viscous eta s_min]; pair_style polyhedron): volume (0: none), surface
  // tension, contact angle [deg], viscosity (0: none), smallest viscous gap
  double **bridge_vol, **bridge_gamma, **bridge_theta, **bridge_eta, **bridge_smin;
  double roll_kr, roll_eta;
  // the law table (polydem_law_table.h) of the contacts: settings from
  // init_style, each type pair's entry from init_one (mixed coefficients)
  std::vector<polydem::LawEntry<double>> law_entries;
  polydem::LawTable<double> laws;
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
  void allocate_rolling();
  void begin_law_table(double overlap_warn);
  // a per-type array of ntypes + 1 zeros (a style's allocate()), named pair:NAME
  template <class T> void create_per_type(T *&a, const char *name)
  {
    memory->create(a, atom->ntypes + 1, (std::string("pair:") + name).c_str());
    for (int i = 0; i <= atom->ntypes; i++) a[i] = T(0);
  }
  // a per-type-pair array of (ntypes + 1)^2 zeros, named pair:NAME
  template <class T> void create_per_type_pair(T **&a, const char *name)
  {
    const int n = atom->ntypes + 1;
    memory->create(a, n, n, (std::string("pair:") + name).c_str());
    for (int i = 0; i < n; i++)
      for (int j = 0; j < n; j++) a[i][j] = T(0);
  }
  // memory->destroy of each array
  template <class... A> void destroy_arrays(A *&...a) { (memory->destroy(a), ...); }
  // pair_coeff's trailing keywords 'rolling mu_r' and 'cohesion c' (each
  // default 0), 'bridge V_b gamma theta' and 'viscous eta s_min' where
  // bridge (5 values) is given and
  // 'ellipsoid k_n' where ellipsoid_kn is (else errors): the count of the
  // values before them
  int coeff_keywords(int narg, char **arg, double &mu_r, double &coh, double *bridge = nullptr,
                     double *ellipsoid_kn = nullptr);
  // extract() of the fields every POLYDEM pair style has: rolling and
  // cohesion per type pair, the counters, the rolling k_r factor and
  // dashpot ratio (fix wall/mesh); null for any other name
  void *extract_models(const char *str, int &dim);
  // the liquid bridge law of type pair (i, j) (volume 0: none; R set per contact)
  polydem::BridgeLaw<double> bridge_law(int i, int j) const;
  // mixing of the keywords' values for an unlike pair without its own
  // (geometric means), and the symmetric copy
  void mix_keywords(int i, int j, bool own);
  // pair_style's rolling/stiffness and rolling/damping keywords at arg[iarg]:
  // the values taken (0: not one of them)
  int settings_rolling(int narg, char **arg, int iarg);
  // some type pair has rolling resistance (coefficients are global)
  int rolling_used() const;
  // nhistory for this run: per contact nhistory_base, or CONTACT_HIST_ROLL
  // with rolling resistance (nhistory_contact); times 1 + that per keyed
  // part contact where composites need history_slots(); an error where an
  // existing history (this run's fix or the restart file's) has another size
  void choose_history_size();
  // keyed part contacts per pair (composite templates), 0: one contact
  virtual int history_slots() { return 0; }
  // restart: the rolling settings, and the pair's mu_r and cohesion
  void rolling_settings_fields(RestartFields &io);
  void rolling_coeff_fields(RestartFields &io, int i, int j);
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
  // the counters are due at reneighboring and at a run's last step (so that
  // nothing counted after the last reneighboring goes unreported)
  bool counters_due() const;
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
  // init_list: a new Kokkos list starts narrow (its first build widens it
  // to 1.2 x the most neighbors an atom has), so that it and the history
  // arrays sized by its width follow the packing, not LAMMPS's 16
  template <class DeviceType> void kk_init_list(class NeighList *);
  double kk_binsize;    // the bin size kk_init_after chose (0: none)
};

}    // namespace LAMMPS_NS

#endif
