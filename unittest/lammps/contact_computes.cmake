# compute contact/polyhedron/local and compute contact/polyhedron (issue 4)
# on 1 and 2 ranks: test_contact_computes. include()d from CMakeLists.txt.
polydem_lammps_test(test_contact_computes test_contact_computes.cpp)
# the /kk cases skip themselves where LAMMPS has no KOKKOS package
add_test(NAME lammps.contact_computes COMMAND test_contact_computes)
polydem_mpi_test(lammps.contact_computes_2_ranks 2 test_contact_computes)
if(POLYDEM_KOKKOS)
  polydem_kk_threads_test(lammps.contact_computes 5 test_contact_computes)
endif()
