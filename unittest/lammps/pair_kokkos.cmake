# pair_style polyhedron/kk against the plain pair_style polyhedron (issue 4,
# acceptance item 5): test_pair_kokkos. include()d from CMakeLists.txt after
# polydem_lammps_test is defined. Needs LAMMPS built with KOKKOS.
if(POLYDEM_KOKKOS)
  # KOKKOS: the test reads Kokkos DualViews (AtomKokkos::sync)
  polydem_lammps_test(test_pair_kokkos test_pair_kokkos.cpp KOKKOS
                      TEST lammps.pair_kokkos_vs_plain)
  polydem_kk_threads_test(lammps.pair_kokkos_vs_plain 4 test_pair_kokkos)
  # both instances on the same 2-rank decomposition (atoms migrate between ranks)
  polydem_mpi_test(lammps.pair_kokkos_2_ranks 2 test_pair_kokkos
    --gtest_filter=PairKokkos.DensePackingMatchesPlain:PairKokkos.RestartKeepsContactHistory:PairKokkos.NewtonOn*)
endif()
