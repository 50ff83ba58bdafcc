# atom_style polyhedron/kk + fix nve/polyhedron/kk against the plain styles,
# on 1 and 2 ranks: test_kokkos_integrator. include()d from CMakeLists.txt after
# polydem_lammps_test is defined. Needs LAMMPS built with KOKKOS.
if(POLYDEM_KOKKOS)
  polydem_lammps_test(test_kokkos_integrator test_kokkos_integrator.cpp TEST lammps.kokkos_vs_plain)
  polydem_kk_threads_test(lammps.kokkos_vs_plain 3 test_kokkos_integrator)
  # /kk on 2 ranks: exchange and borders between ranks, against plain on 1 rank
  polydem_mpi_test(lammps.kokkos_2_ranks 2 test_kokkos_integrator
    --gtest_filter=KokkosIntegrator.KokkosOnAllRanksMatchesPlainOnOne:CommModes/*)
endif()
