# pair_style polyhedron/kk against the plain pair_style polyhedron (issue 4,
# acceptance item 5): test_pair_kokkos. include()d from CMakeLists.txt after
# polydem_lammps_test is defined. Needs LAMMPS built with KOKKOS.
if(POLYDEM_KOKKOS)
  polydem_lammps_test(test_pair_kokkos test_pair_kokkos.cpp)
  # the test reads Kokkos DualViews (AtomKokkos::sync): Kokkos headers
  if(NOT TARGET Kokkos::kokkos)
    find_package(Kokkos REQUIRED)
  endif()
  target_link_libraries(test_pair_kokkos PRIVATE Kokkos::kokkos)
  add_test(NAME lammps.pair_kokkos_vs_plain COMMAND test_pair_kokkos)
  polydem_kk_threads_test(lammps.pair_kokkos_vs_plain 4 test_pair_kokkos)
  # both instances on the same 2-rank decomposition (atoms migrate between ranks)
  polydem_mpi_test(lammps.pair_kokkos_2_ranks 2 test_pair_kokkos
    --gtest_filter=PairKokkos.DensePackingMatchesPlain:PairKokkos.RestartKeepsContactHistory)
endif()
