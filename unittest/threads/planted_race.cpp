// A planted race for ThreadSanitizer (issue 19, unittest/scripts/tsan.sh): shows that
// the TSan build (Kokkos Threads backend, everything built with
// -fsanitize=thread) reports a race of the kind a /kk kernel could have:
// every thread adds into one slot of a View.
//
//   planted_race racy     sum(0) += 1 without an atomic: TSan must report a data race
//   planted_race atomic   Kokkos::atomic_add: no report, sum exact
#include <Kokkos_Core.hpp>

#include <cstdio>
#include <cstring>

int main(int argc, char **argv)
{
  const bool racy = argc > 1 && !std::strcmp(argv[1], "racy");
  Kokkos::initialize(argc, argv);
  int rc = 0;
  {
    using Exec = Kokkos::DefaultExecutionSpace;
    const int n = 1 << 16;
    Kokkos::View<double[1], Exec> sum("sum");
    Kokkos::parallel_for(
        "polydem_planted_race", Kokkos::RangePolicy<Exec>(0, n), KOKKOS_LAMBDA(const int) {
          if (racy)
            sum(0) += 1.0;    // the planted race
          else
            Kokkos::atomic_add(&sum(0), 1.0);
        });
    Kokkos::fence();
    auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sum);
    std::printf("planted_race: %s on %s with %d threads: sum %.0f of %d\n",
                racy ? "racy" : "atomic", Exec::name(), Exec::concurrency(), h(0), n);
    if (!racy && h(0) != n) rc = 1;
  }
  Kokkos::finalize();
  return rc;
}
