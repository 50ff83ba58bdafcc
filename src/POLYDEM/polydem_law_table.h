/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - the law table of a style: the coefficients of every type pair
   (pair styles) or particle type on the wall (fix wall/mesh) and the
   style's law settings, one plain struct built once on the host after the
   coefficients are mixed (init) and copied as it is to the device by the
   /kk style (polydem_law_table_kokkos.h), its entry array pointing into
   host or device memory. The entry points of polydem_contact_pipeline.h
   and polydem_wall_pipeline.h make each contact's ContactLaw (polydem_contact_law.h) from it.
   No LAMMPS includes; host and device.
------------------------------------------------------------------------- */

#ifndef POLYDEM_LAW_TABLE_H
#define POLYDEM_LAW_TABLE_H

#include "polydem_contact_law.h"
#include "polydem_ellipsoid_force.h"

namespace polydem {

// The coefficients of one type pair (pair styles) or of one particle type
// on the wall (fix wall/mesh).
template <typename T> struct LawEntry {
  T E1, nu1;                // Feng: first body's Young's modulus, Poisson's ratio (type i)
  T E2, nu2;                // Feng: second body's (type j; the wall's material on a wall)
  T kn;                     // linear: normal stiffness k_n [force/length]
  T mu;                     // Coulomb friction (0: frictionless, no history kept)
  DampingLaw<T> damping;    // restitution as a damping law (damping_law of e, host)
  T mu_r;                   // rolling friction (0: no rolling resistance)
  T cohesion;               // dry cohesion (ContactLaw::cohesion; 0: none)
  BridgeLaw<T> bridge;      // liquid bridge between spheres (volume 0: none; R unset)
};

template <typename T> struct LawTable {
  const LawEntry<T> *entry;    // pairs: (ntypes+1)^2, [i (ntypes+1) + j]; walls: ntypes+1, [t]
  int ntypes;
  int nentry;    // entries in entry
  // values kept per pair contact (CONTACT_HIST, ELLIPSOID_HIST, or
  // CONTACT_HIST_ROLL when a type pair has rolling resistance)
  int nhist;
  // composites in the scene: a pair keeps nslot keyed part contacts of
  // 1 + nhist values each (pair_history_stride); 0: one contact of nhist
  int nslot;
  // rolling resistance (RollingLaw): k_r factor and dashpot ratio eta_r
  T roll_kr, roll_eta;
  // Feng (polyhedra): polynomial core V0 = core x smaller volume; twisting friction
  T core;
  int twist;
  // linear (ellipsoids): k_t / k_n, gamma_t / gamma_n; overlap measure
  // (OVERLAP_CENTRE/CHORD); mass of the dashpot (DAMPING_REDUCED/CONTACT)
  T kt_ratio, gt_ratio;
  int overlap, damping_mass;
  // the largest rupture distance of a liquid bridge (0: no bridges); pairs
  // are candidates within their bounding radii plus this
  T bridge_reach;
  // counted as large overlaps: pairs beyond overlap_warn x the smaller
  // polyhedron volume / the smallest ellipsoid semi-axis
  T overlap_warn;

  POLYDEM_FN const LawEntry<T> &pair(int i, int j) const { return entry[i * (ntypes + 1) + j]; }
  POLYDEM_FN const LawEntry<T> &wall(int t) const { return entry[t]; }
};

// values a pair of the table keeps in the neighbor history
template <typename T> POLYDEM_FN int pair_history_stride(const LawTable<T> &t)
{
  return t.nslot > 0 ? t.nslot * (1 + t.nhist) : t.nhist;
}

// keyed part contacts a pair keeps when the largest template has maxparts
// parts: every pair of parts, at most cap (pair_style polyhedron part/slots,
// default 16; more are counted, without history). A fixed cap keeps the
// history's size when composites with more parts are defined between runs
// (and restart files readable).
inline int part_contact_slots(int maxparts, int cap = 16)
{
  return maxparts > 1 ? (maxparts * maxparts < cap ? maxparts * maxparts : cap) : 0;
}

// the table over nentry entries (zero: the caller fills them), its settings
// at their defaults
template <typename T> inline LawTable<T> law_table(const LawEntry<T> *entry, int ntypes, int nentry)
{
  LawTable<T> t;
  t.entry = entry;
  t.ntypes = ntypes;
  t.nentry = nentry;
  t.core = T(0);
  t.twist = 0;
  t.kt_ratio = T(1);    // finite zeta_t for a table that never sets them
  t.gt_ratio = T(0);
  t.overlap = OVERLAP_CENTRE;
  t.damping_mass = DAMPING_REDUCED;
  t.overlap_warn = T(1);
  t.nhist = CONTACT_HIST;
  t.nslot = 0;
  t.bridge_reach = T(0);
  const RollingLaw<T> r;
  t.roll_kr = r.kr;
  t.roll_eta = r.eta;
  return t;
}

// the rolling and cohesion parts of an entry's law
template <typename T>
POLYDEM_FN ContactLaw<T> with_rolling(ContactLaw<T> L, const LawTable<T> &tab, const LawEntry<T> &e)
{
  L.rolling.mu_r = e.mu_r;
  L.rolling.kr = tab.roll_kr;
  L.rolling.eta = tab.roll_eta;
  L.cohesion = e.cohesion;
  L.bridge = e.bridge;
  return L;
}

// Feng law of polyhedra of types i, j and (scaled) volumes Vi, Vj (Eqs. 13, 19, 20)
template <typename T>
POLYDEM_FN ContactLaw<T> polyhedron_pair_law(const LawTable<T> &tab, int i, int j, T Vi, T Vj)
{
  const LawEntry<T> &e = tab.pair(i, j);
  return with_rolling(
      feng_law(e.E1, e.nu1, Vi, e.E2, e.nu2, Vj, e.damping, e.mu, tab.core, tab.twist), tab, e);
}

// linear law of ellipsoids of types i, j (ellipsoid seed Eqs. 23-24)
template <typename T>
POLYDEM_FN ContactLaw<T> ellipsoid_pair_law(const LawTable<T> &tab, int i, int j)
{
  const LawEntry<T> &e = tab.pair(i, j);
  return with_rolling(ellipsoid_law(e.kn, e.damping, e.mu, tab.kt_ratio, tab.gt_ratio), tab, e);
}

// Wall law of a particle (volume V, material E, nu) on the wall (wE, wnu):
// the wall is a half-space sized like the particle (R_w = R_p) and of
// infinite mass; damping of restitution e at the contact's exponent
// (damping_law(e, 1) on the host).
template <typename T>
POLYDEM_FN ContactLaw<T> wall_law(T E, T nu, T wE, T wnu, T V, const DampingLaw<T> &d, T mu, T core,
                                  int twist)
{
  return feng_law(E, nu, V, wE, wnu, V, d, mu, core, twist);
}

// wall law of a polyhedron of type t and volume V (wall_law), or of an ellipsoid
template <typename T>
POLYDEM_FN ContactLaw<T> wall_polyhedron_law(const LawTable<T> &tab, int t, T V)
{
  const LawEntry<T> &e = tab.wall(t);
  return with_rolling(wall_law(e.E1, e.nu1, e.E2, e.nu2, V, e.damping, e.mu, tab.core, tab.twist),
                      tab, e);
}
template <typename T> POLYDEM_FN ContactLaw<T> wall_ellipsoid_law(const LawTable<T> &tab, int t)
{
  const LawEntry<T> &e = tab.wall(t);
  return with_rolling(ellipsoid_law(e.kn, e.damping, e.mu, tab.kt_ratio, tab.gt_ratio), tab, e);
}

}    // namespace polydem

#endif
