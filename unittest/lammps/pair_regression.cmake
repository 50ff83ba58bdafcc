# pair_style polyhedron force regression against pair_regression.ref (and
# its independent checks; issue 4) on 1 and 2 ranks: test_pair_regression.
# include()d from CMakeLists.txt.
polydem_lammps_test(test_pair_regression test_pair_regression.cpp)
target_compile_definitions(test_pair_regression PRIVATE
  POLYDEM_TEST_DIR="${CMAKE_CURRENT_SOURCE_DIR}")
# the /kk cases skip themselves where LAMMPS has no KOKKOS package
add_test(NAME lammps.pair_regression COMMAND test_pair_regression)
polydem_mpi_test(lammps.pair_regression_2_ranks 2 test_pair_regression)
if(POLYDEM_KOKKOS)
  polydem_kk_threads_test(lammps.pair_regression 5 test_pair_regression)
endif()
