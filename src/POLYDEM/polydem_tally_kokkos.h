/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - what the /kk pair styles share around contact_step
   (polydem_contact_law.h): the thread-reduced energy, virial and counters,
   LAMMPS's Pair::ev_tally_xyz with atomics for the per-atom arrays, and the
   atomic scatter of a contact's forces and torques to its two atoms.
------------------------------------------------------------------------- */

#ifndef POLYDEM_TALLY_KOKKOS_H
#define POLYDEM_TALLY_KOKKOS_H

#include "polydem_contact_law.h"
#include "polydem_launch_kokkos.h"

#include <Kokkos_Core.hpp>

#include <type_traits>

namespace polydem_kk {

// energy, virial and NCNT counters of one kernel, summed over threads
template <int NCNT> struct PairReduce {
  double evdwl;
  double v[6];
  double cnt[NCNT];
  KOKKOS_INLINE_FUNCTION PairReduce()
  {
    evdwl = 0.0;
    for (int k = 0; k < 6; k++) v[k] = 0.0;
    for (int k = 0; k < NCNT; k++) cnt[k] = 0.0;
  }
  KOKKOS_INLINE_FUNCTION void operator+=(const PairReduce &r)
  {
    evdwl += r.evdwl;
    for (int k = 0; k < 6; k++) v[k] += r.v[k];
    for (int k = 0; k < NCNT; k++) cnt[k] += r.cnt[k];
  }
#if defined(KOKKOS_VERSION) && KOKKOS_VERSION < 40000
  // Kokkos 3 joins through volatile references (Kokkos 4 rejects this form)
  KOKKOS_INLINE_FUNCTION void operator+=(const volatile PairReduce &r) volatile
  {
    evdwl += r.evdwl;
    for (int k = 0; k < 6; k++) v[k] += r.v[k];
    for (int k = 0; k < NCNT; k++) cnt[k] += r.cnt[k];
  }
#endif
};

// what ev_tally needs of the pair style on this step
struct TallyFlags {
  int nlocal, newton_pair;
  int eflag_global, eflag_atom, vflag_global, vflag_atom;
};

// Pair::ev_tally_xyz(i, j, nlocal, newton_pair, e, 0, F, del): global sums in
// red, per-atom sums with atomics (i and j are shared between threads)
template <class Red, class EAtom, class VAtom>
KOKKOS_INLINE_FUNCTION void ev_tally_xyz(Red &red, const TallyFlags &t, const EAtom &eatom,
                                         const VAtom &vatom, int i, int j, double e,
                                         const double F[3], double delx, double dely, double delz)
{
  const bool ti = t.newton_pair || i < t.nlocal, tj = t.newton_pair || j < t.nlocal;
  if (t.eflag_global) {
    if (t.newton_pair)
      red.evdwl += e;
    else {
      if (i < t.nlocal) red.evdwl += 0.5 * e;
      if (j < t.nlocal) red.evdwl += 0.5 * e;
    }
  }
  if (t.eflag_atom) {
    if (ti) Kokkos::atomic_add(&eatom(i), 0.5 * e);
    if (tj) Kokkos::atomic_add(&eatom(j), 0.5 * e);
  }
  if (!t.vflag_global && !t.vflag_atom) return;
  const double vv[6] = {delx * F[0], dely * F[1], delz * F[2],
                        delx * F[1], delx * F[2], dely * F[2]};
  if (t.vflag_global) {
    if (t.newton_pair)
      for (int k = 0; k < 6; k++) red.v[k] += vv[k];
    else {
      if (i < t.nlocal)
        for (int k = 0; k < 6; k++) red.v[k] += 0.5 * vv[k];
      if (j < t.nlocal)
        for (int k = 0; k < 6; k++) red.v[k] += 0.5 * vv[k];
    }
  }
  if (t.vflag_atom) {
    if (ti)
      for (int k = 0; k < 6; k++) Kokkos::atomic_add(&vatom(i, k), 0.5 * vv[k]);
    if (tj)
      for (int k = 0; k < 6; k++) Kokkos::atomic_add(&vatom(j, k), 0.5 * vv[k]);
  }
}

// whether the threads of ExecSpace can add to one atom at the same time: not
// on a CPU back end with one thread (Serial, OpenMP with t 1), where a plain
// add does what the atomic does without its locked read-modify-write (a
// compare-and-swap loop for doubles on x86: about 7 % of the dense
// dodecahedra's step with 12 per contact)
template <class ExecSpace> inline bool needs_atomics()
{
  return !one_host_thread<ExecSpace>();
}

// Which preallocated workspace a kernel's work item uses. CPU back ends (the
// execution space reaches host memory): the thread's (Kokkos's UniqueToken),
// so that all items run in one kernel with a workspace that stays in the
// thread's cache, and with one thread the first, without asking the token;
// GPUs: the item's slot in its batch. count() (on the host, before the
// kernel) is the number of workspaces to allocate (the batch size on GPUs).
template <class ExecSpace> struct WorkspaceSlot {
  static constexpr bool per_thread =
      Kokkos::SpaceAccessibility<ExecSpace, Kokkos::HostSpace>::accessible;
  typename std::conditional<per_thread, Kokkos::Experimental::UniqueToken<ExecSpace>, int>::type
      token{};
  bool alone = false;    // one host thread (one_host_thread)
  int count(int batch)
  {
    if constexpr (per_thread) {
      alone = one_host_thread<ExecSpace>();
      return token.size();
    } else
      return batch;
  }
  KOKKOS_INLINE_FUNCTION int acquire(int slot_in_batch) const
  {
    if constexpr (per_thread)
      return alone ? 0 : token.acquire();
    else
      return slot_in_batch;
  }
  KOKKOS_INLINE_FUNCTION void release(int w) const
  {
    if constexpr (per_thread)
      if (!alone) token.release(w);
    (void) w;
  }
};

// forces and torques of one contact to i and, if to_j, to j; with atomics
// unless the caller runs alone (needs_atomics)
template <class FView>
KOKKOS_INLINE_FUNCTION void scatter_contact(const FView &f, const FView &torque, int i, int j,
                                            bool to_j, const polydem::ContactForce<double> &cf,
                                            bool atomic = true)
{
  const double F[3] = {cf.F_A.x, cf.F_A.y, cf.F_A.z};
  const double tA[3] = {cf.tau_A.x, cf.tau_A.y, cf.tau_A.z};
  const double tB[3] = {cf.tau_B.x, cf.tau_B.y, cf.tau_B.z};
  if (!atomic) {
    for (int k = 0; k < 3; k++) {
      f(i, k) += F[k];
      torque(i, k) += tA[k];
    }
    if (to_j)
      for (int k = 0; k < 3; k++) {
        f(j, k) -= F[k];
        torque(j, k) += tB[k];
      }
    return;
  }
  for (int k = 0; k < 3; k++) {
    Kokkos::atomic_add(&f(i, k), F[k]);
    Kokkos::atomic_add(&torque(i, k), tA[k]);
  }
  if (to_j)
    for (int k = 0; k < 3; k++) {
      Kokkos::atomic_add(&f(j, k), -F[k]);
      Kokkos::atomic_add(&torque(j, k), tB[k]);
    }
}

// the global sums of a kernel into the pair style (eng_vdwl, virial, counters)
template <class PairT, class Red>
inline void add_reduced(PairT *pair, const TallyFlags &t, const Red &red, double *counts, int ncnt)
{
  if (t.eflag_global) pair->eng_vdwl += red.evdwl;
  if (t.vflag_global)
    for (int k = 0; k < 6; k++) pair->virial[k] += red.v[k];
  for (int k = 0; k < ncnt; k++) counts[k] += red.cnt[k];
}

}    // namespace polydem_kk

#endif
