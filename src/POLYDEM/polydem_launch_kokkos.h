/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - how the /kk styles launch their kernels over a range of items
   (atoms, pairs, list entries): Kokkos's parallel_for / parallel_reduce /
   parallel_scan, except on a host back end with one thread (Serial, or
   OpenMP with `-k on t 1`, the usual setting with one MPI rank per core),
   where the loop runs in place. There the OpenMP back end still opens a
   parallel region per kernel: about 2,000 instructions and a few
   microseconds per launch, several launches per step, which on a few
   hundred grains is a few per cent of the step. In place, the items run
   in the order in which the back end's one thread runs them, so results
   are the same bit for bit. GPUs and host back ends with more threads
   launch as before.
------------------------------------------------------------------------- */

#ifndef POLYDEM_LAUNCH_KOKKOS_H
#define POLYDEM_LAUNCH_KOKKOS_H

#include <Kokkos_Core.hpp>

namespace polydem_kk {

// whether ExecSpace is a host back end running one thread: one thread does
// every item, and no other thread shares its targets
template <class ExecSpace> inline bool one_host_thread()
{
  if constexpr (Kokkos::SpaceAccessibility<ExecSpace, Kokkos::HostSpace>::accessible)
    return ExecSpace::concurrency() == 1;
  else
    return false;
}

// f(i) for i in [begin, end)
template <class ExecSpace, class F> inline void for_range(int begin, int end, const F &f)
{
  if constexpr (Kokkos::SpaceAccessibility<ExecSpace, Kokkos::HostSpace>::accessible) {
    if (one_host_thread<ExecSpace>()) {
      for (int i = begin; i < end; i++) f(i);
      return;
    }
  }
  Kokkos::parallel_for(Kokkos::RangePolicy<ExecSpace>(begin, end), f);
}

// f(i, sum) for i in [begin, end), sum from V's default constructor (the
// functors launched this way have no init()), its total in result
template <class ExecSpace, class F, class V>
inline void reduce_range(int begin, int end, const F &f, V &result)
{
  if constexpr (Kokkos::SpaceAccessibility<ExecSpace, Kokkos::HostSpace>::accessible) {
    if (one_host_thread<ExecSpace>()) {
      V sum{};
      for (int i = begin; i < end; i++) f(i, sum);
      result = sum;
      return;
    }
  }
  Kokkos::parallel_reduce(Kokkos::RangePolicy<ExecSpace>(begin, end), f, result);
}

// exclusive scan f(i, partial, final) for i in [begin, end), partial from
// zero; the total in result
template <class ExecSpace, class F, class V>
inline void scan_range(int begin, int end, const F &f, V &result)
{
  if constexpr (Kokkos::SpaceAccessibility<ExecSpace, Kokkos::HostSpace>::accessible) {
    if (one_host_thread<ExecSpace>()) {
      V partial{};
      for (int i = begin; i < end; i++) f(i, partial, true);
      result = partial;
      return;
    }
  }
  Kokkos::parallel_scan(Kokkos::RangePolicy<ExecSpace>(begin, end), f, result);
}

}    // namespace polydem_kk

#endif
