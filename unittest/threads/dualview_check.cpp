// Kokkos's DualView modify check (issue 19) fires on a missing sync.
//
// The check (KOKKOS_ENABLE_DEBUG_DUALVIEW_MODIFY_CHECK) lives in
// Kokkos_DualView.hpp; it is defined here before that header so that this
// test works against any Kokkos 3.4 build (the TSan build of unittest/scripts/tsan.sh
// also turns it on for the whole LAMMPS build). The check only acts on
// DualViews whose two sides are distinct (DualView::modify returns early when
// the device and host types are the same, as for every DualView of a CPU-only
// LAMMPS build). A CPU device that is not host-accessible is made from
// Kokkos's LogicalMemorySpace over HostSpace without shared access: host and
// device sides are then distinct types, as on a GPU.
//
//   dualview_check correct         modify device, sync host, modify host: exits 0
//   dualview_check missing-sync    modify device, modify host (no sync): Kokkos::abort
//   dualview_check single-device   the same missing sync on a single-space DualView:
//                                  exits 0 (the check cannot act there)
#ifndef KOKKOS_ENABLE_DEBUG_DUALVIEW_MODIFY_CHECK
#define KOKKOS_ENABLE_DEBUG_DUALVIEW_MODIFY_CHECK
#endif
#include <Kokkos_Core.hpp>
#include <Kokkos_DualView.hpp>

#include <cstdio>
#include <cstring>

namespace {

using Exec = Kokkos::DefaultExecutionSpace;
using FakeDeviceSpace = Kokkos::Experimental::LogicalMemorySpace<
    Kokkos::HostSpace, Kokkos::DefaultHostExecutionSpace,
    Kokkos::Experimental::DefaultMemorySpaceNamer,
    Kokkos::Experimental::LogicalSpaceSharesAccess::no_shared_access>;
using TwoSided = Kokkos::DualView<double *, Kokkos::Device<Exec, FakeDeviceSpace>>;
using OneSided = Kokkos::DualView<double *, Exec>;    // as LAMMPS's DAT types on the CPU

// the template arguments are memory spaces: with one execution space on both
// sides, DualView::modify<Device<Exec, Space>>() cannot tell the sides apart
template <class DV> int run(bool sync)
{
  DV dv("polydem_dv", 16);
  std::printf("dualview_check: single device: %d\n",
              (int) DV::impl_dualview_is_single_device::value);
  // (the fake device's data cannot be touched from the CPU: Kokkos refuses
  // host access to it, which is the point; only the flags matter here)
  dv.template modify<typename DV::t_dev::memory_space>();
  if (sync) dv.template sync<typename DV::t_host::memory_space>();
  dv.h_view(0) = -1.0;
  dv.template modify<typename DV::t_host::memory_space>();    // aborts without the sync
  std::printf("dualview_check: no abort\n");
  return 0;
}

}    // namespace

int main(int argc, char **argv)
{
  const char *mode = argc > 1 ? argv[1] : "correct";
  Kokkos::initialize(argc, argv);
  int rc = 2;
  if (!std::strcmp(mode, "correct"))
    rc = run<TwoSided>(true);
  else if (!std::strcmp(mode, "missing-sync"))
    rc = run<TwoSided>(false);
  else if (!std::strcmp(mode, "single-device"))
    rc = run<OneSided>(false);
  else
    std::fprintf(stderr, "dualview_check: unknown mode %s\n", mode);
  Kokkos::finalize();
  return rc;
}
