# pair_style polyhedron, second batch (issue 4): contact computes, force
# regression, cylinders, /kk restart. include()d at the end of CMakeLists.txt.
set(_polydem_mpi_env
  "OMPI_ALLOW_RUN_AS_ROOT=1;OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1;OMPI_MCA_rmaps_base_oversubscribe=1")

polydem_lammps_test(test_contact_computes test_contact_computes.cpp)
if(POLYDEM_KOKKOS)
  add_test(NAME lammps.contact_computes COMMAND test_contact_computes)
  add_test(NAME lammps.contact_computes_2_ranks
    COMMAND ${MPIEXEC_EXECUTABLE} --oversubscribe ${MPIEXEC_NUMPROC_FLAG} 2
            $<TARGET_FILE:test_contact_computes>)
  set_tests_properties(lammps.contact_computes_2_ranks PROPERTIES ENVIRONMENT "${_polydem_mpi_env}")
endif()

# force-style regression against pair_regression.ref (and its independent checks)
polydem_lammps_test(test_pair_regression test_pair_regression.cpp)
target_compile_definitions(test_pair_regression PRIVATE
  POLYDEM_TEST_DIR="${CMAKE_CURRENT_SOURCE_DIR}")
if(POLYDEM_KOKKOS)
  add_test(NAME lammps.pair_regression COMMAND test_pair_regression)
  add_test(NAME lammps.pair_regression_2_ranks
    COMMAND ${MPIEXEC_EXECUTABLE} --oversubscribe ${MPIEXEC_NUMPROC_FLAG} 2
            $<TARGET_FILE:test_pair_regression>)
  set_tests_properties(lammps.pair_regression_2_ranks PROPERTIES ENVIRONMENT "${_polydem_mpi_env}")
endif()
