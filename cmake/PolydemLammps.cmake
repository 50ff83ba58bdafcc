# Builds LAMMPS with POLYDEM compiled in.
#
# LAMMPS's own CMake only builds packages that live in its src/ folder, so we
# stage a LAMMPS tree in the build directory: symbolic links to the pristine
# LAMMPS source, plus
#   src/POLYDEM        links to our non-Kokkos files
#   src/KOKKOS         LAMMPS's KOKKOS files plus links to our *_kokkos.* files
#   src/atom.{h,cpp}   copies with three per-atom fields added (quat, pshape,
#                      pscale), see "atom.h / atom.cpp" below
#   cmake/             a copy whose package list knows POLYDEM and that
#                      compiles as C++17
# and add that tree's cmake/ folder as a subdirectory.

# Which Debian lammps source package to fetch when LAMMPS_SOURCE_DIR is not
# given: POLYDEM_LAMMPS picks a LAMMPS version and the Debian suite that has it.
set(POLYDEM_LAMMPS "2021" CACHE STRING
    "LAMMPS fetched from Debian when LAMMPS_SOURCE_DIR is empty: 2021 (bookworm, 29 Sep 2021), 2025 (trixie, 4 Feb 2025), 2026 (sid, 4 Jul 2026)")
set_property(CACHE POLYDEM_LAMMPS PROPERTY STRINGS 2021 2025 2026)
if(POLYDEM_LAMMPS STREQUAL "2021")
  set(POLYDEM_LAMMPS_DEB_VERSION "20220106.git7586adbb6a+ds1-2")
  set(_lmp_suite bookworm)
elseif(POLYDEM_LAMMPS STREQUAL "2025")
  set(POLYDEM_LAMMPS_DEB_VERSION "20250204+dfsg.1-2")
  set(_lmp_suite trixie)
elseif(POLYDEM_LAMMPS STREQUAL "2026")
  set(POLYDEM_LAMMPS_DEB_VERSION "20260704+dfsg-2")
  set(_lmp_suite sid)
else()
  message(FATAL_ERROR "POLYDEM_LAMMPS must be 2021, 2025 or 2026 (got '${POLYDEM_LAMMPS}')")
endif()
set(LAMMPS_SOURCE_DIR "" CACHE PATH "A LAMMPS source tree (with src/ and cmake/); empty: fetch Debian's")

# ---------------------------------------------------------------------------
# 1. the pristine LAMMPS source
if(NOT LAMMPS_SOURCE_DIR)
  set(_lmp_cache ${POLYDEM_CACHE_DIR}/lammps-${POLYDEM_LAMMPS_DEB_VERSION})
  set(_lmp_stamp ${_lmp_cache}/.extracted)
  if(NOT EXISTS ${_lmp_stamp})
    message(STATUS "POLYDEM: fetching Debian's lammps ${POLYDEM_LAMMPS_DEB_VERSION} source (${_lmp_suite}) with apt")
    execute_process(
      COMMAND ${CMAKE_COMMAND} -E env POLYDEM_DEBIAN_SUITE=${_lmp_suite}
              bash ${CMAKE_SOURCE_DIR}/cmake/scripts/fetch-debian-source.sh lammps
              ${POLYDEM_LAMMPS_DEB_VERSION} ${_lmp_cache}/download
      RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
    if(NOT _rc EQUAL 0)
      message(FATAL_ERROR "POLYDEM: could not fetch the LAMMPS source:\n${_out}\n${_err}\n"
                          "Run tools/install-deps.sh first, or pass -DLAMMPS_SOURCE_DIR=...")
    endif()
    file(GLOB _tarball ${_lmp_cache}/download/lammps_*.orig.tar.*)
    list(FILTER _tarball EXCLUDE REGEX "\\.asc$")
    if(NOT _tarball)
      message(FATAL_ERROR "POLYDEM: no lammps orig tarball in ${_lmp_cache}/download")
    endif()
    message(STATUS "POLYDEM: extracting ${_tarball}")
    file(REMOVE_RECURSE ${_lmp_cache}/src)
    file(ARCHIVE_EXTRACT INPUT ${_tarball} DESTINATION ${_lmp_cache}/src)
    file(TOUCH ${_lmp_stamp})
  endif()
  if(EXISTS ${_lmp_cache}/src/src/atom.cpp)
    # sid's 4 Jul 2026 tarball has no top-level folder
    set(_lammps_pristine ${_lmp_cache}/src)
  else()
    file(GLOB _lmp_top LIST_DIRECTORIES true ${_lmp_cache}/src/*)
    list(GET _lmp_top 0 _lmp_top)
    set(_lammps_pristine ${_lmp_top})
  endif()
else()
  set(_lammps_pristine ${LAMMPS_SOURCE_DIR})
endif()
if(NOT EXISTS ${_lammps_pristine}/src/atom.cpp OR NOT EXISTS ${_lammps_pristine}/cmake/CMakeLists.txt)
  message(FATAL_ERROR "POLYDEM: ${_lammps_pristine} is not a LAMMPS source tree (no src/atom.cpp, cmake/CMakeLists.txt)")
endif()
message(STATUS "POLYDEM: LAMMPS source: ${_lammps_pristine}")

# the LAMMPS version, from src/version.h ("4 Feb 2025"), as YYYYMMDD for
# src/POLYDEM/polydem_lammps_compat.h
file(STRINGS ${_lammps_pristine}/src/version.h _lmp_vline REGEX "define LAMMPS_VERSION ")
string(REGEX MATCH "\"([0-9]+) ([A-Za-z]+) ([0-9]+)\"" _m "${_lmp_vline}")
if(NOT _m)
  message(FATAL_ERROR "POLYDEM: cannot read the LAMMPS version from ${_lammps_pristine}/src/version.h")
endif()
set(_lmp_months Jan Feb Mar Apr May Jun Jul Aug Sep Oct Nov Dec)
list(FIND _lmp_months "${CMAKE_MATCH_2}" _mon)
if(_mon EQUAL -1)
  message(FATAL_ERROR "POLYDEM: unknown month in LAMMPS version '${_lmp_vline}'")
endif()
math(EXPR _mon "${_mon} + 1")
math(EXPR POLYDEM_LAMMPS_VERSION "${CMAKE_MATCH_3} * 10000 + ${_mon} * 100 + ${CMAKE_MATCH_1}")
set(POLYDEM_LAMMPS_VERSION_TEXT "${CMAKE_MATCH_1} ${CMAKE_MATCH_2} ${CMAKE_MATCH_3}")
message(STATUS "POLYDEM: LAMMPS version ${POLYDEM_LAMMPS_VERSION_TEXT} (${POLYDEM_LAMMPS_VERSION})")
if(POLYDEM_LAMMPS_VERSION LESS 20210929)
  message(WARNING "POLYDEM: LAMMPS ${POLYDEM_LAMMPS_VERSION_TEXT} is older than the oldest tested (29 Sep 2021)")
endif()

# ---------------------------------------------------------------------------
# 2. the staged tree
set(POLYDEM_STAGE ${CMAKE_BINARY_DIR}/lammps-stage)
file(MAKE_DIRECTORY ${POLYDEM_STAGE}/src)

function(polydem_link target link)
  if(NOT EXISTS ${link} AND NOT IS_SYMLINK ${link})
    file(CREATE_LINK ${target} ${link} SYMBOLIC)
  endif()
endfunction()

# replace FROM by FROM+TO in the string VAR, failing loudly if FROM is absent
function(polydem_insert_after var from what file)
  string(FIND "${${var}}" "${from}" _pos)
  if(_pos EQUAL -1)
    message(FATAL_ERROR "POLYDEM: cannot patch ${file}: anchor '${from}' not found. "
                        "LAMMPS ${POLYDEM_LAMMPS_VERSION_TEXT} is not supported (tested: 29 Sep 2021, 4 Feb 2025, 4 Jul 2026).")
  endif()
  string(REPLACE "${from}" "${from}${what}" _new "${${var}}")
  set(${var} "${_new}" PARENT_SCOPE)
endfunction()

# top level: everything but src/ and cmake/
file(GLOB _entries RELATIVE ${_lammps_pristine} ${_lammps_pristine}/*)
foreach(e ${_entries})
  if(NOT e STREQUAL "src" AND NOT e STREQUAL "cmake")
    polydem_link(${_lammps_pristine}/${e} ${POLYDEM_STAGE}/${e})
  endif()
endforeach()

# src/: links, except KOKKOS, atom.h, atom.cpp and (where LAMMPS's reads no
# Atom::quat, 29 Sep 2021) compute_property_atom.cpp, patched copies below
file(READ ${_lammps_pristine}/src/compute_property_atom.cpp _cpa)
string(FIND "${_cpa}" "quat_flag" _cpa_has_quat)
if(_cpa_has_quat EQUAL -1)
  set(_patched "compute_property_atom\\.cpp")
else()
  set(_patched "")
endif()
file(GLOB _entries RELATIVE ${_lammps_pristine}/src ${_lammps_pristine}/src/*)
foreach(e ${_entries})
  if(NOT e MATCHES "^(KOKKOS|atom\\.h|atom\\.cpp|POLYDEM)$" AND
     (NOT _patched OR NOT e MATCHES "^${_patched}$"))
    polydem_link(${_lammps_pristine}/src/${e} ${POLYDEM_STAGE}/src/${e})
  endif()
endforeach()
file(MAKE_DIRECTORY ${POLYDEM_STAGE}/src/KOKKOS ${POLYDEM_STAGE}/src/POLYDEM)
# POLYDEM_KOKKOS_OTHER_PAIRS=OFF leaves out the KOKKOS package's pair styles of
# other fields (LJ, Coulomb, table, granular Hooke, ...; pair hybrid stays):
# with CUDA they are two thirds of lmp's device code (the GPU kit's prebuilt
# run, tools/gpu/, must fit in 60 MiB) and of its build time
option(POLYDEM_KOKKOS_OTHER_PAIRS "Build the KOKKOS package's pair styles of other fields" ON)
file(GLOB _entries RELATIVE ${_lammps_pristine}/src/KOKKOS ${_lammps_pristine}/src/KOKKOS/*)
foreach(e ${_entries})
  if(NOT POLYDEM_KOKKOS_OTHER_PAIRS AND e MATCHES "^pair_.*_kokkos\\.(h|cpp)$" AND
     NOT e MATCHES "^pair_hybrid")
    file(REMOVE ${POLYDEM_STAGE}/src/KOKKOS/${e})
  else()
    polydem_link(${_lammps_pristine}/src/KOKKOS/${e} ${POLYDEM_STAGE}/src/KOKKOS/${e})
  endif()
endforeach()

# our package: *_kokkos.* files go to KOKKOS (LAMMPS pairs them with their base
# style there), everything else to POLYDEM. Links are refreshed on every configure.
file(GLOB _ours CONFIGURE_DEPENDS RELATIVE ${POLYDEM_SOURCE_DIR}
     ${POLYDEM_SOURCE_DIR}/*.h ${POLYDEM_SOURCE_DIR}/*.cpp)
file(GLOB _old ${POLYDEM_STAGE}/src/POLYDEM/*)
if(_old)
  file(REMOVE ${_old})
endif()
foreach(f ${_ours})
  if(f MATCHES "^polydem_.*\\.cpp$")
    # host-only helpers that need CGAL: built as the library polydem_shapes so
    # that CGAL's flags (-frounding-math) stay out of LAMMPS's own files
  elseif(f MATCHES "_kokkos\\.(h|cpp)$")
    polydem_link(${POLYDEM_SOURCE_DIR}/${f} ${POLYDEM_STAGE}/src/KOKKOS/${f})
  else()
    polydem_link(${POLYDEM_SOURCE_DIR}/${f} ${POLYDEM_STAGE}/src/POLYDEM/${f})
  endif()
endforeach()

# atom.h / atom.cpp: add the per-atom fields pshape, pscale (and quat[4] where
# LAMMPS lacks it) to LAMMPS's Atom class so that the generic AtomVec machinery
# grows, copies, communicates, restarts and reads/writes them. LAMMPS 29 Sep
# 2021 predates Atom::quat; later versions have it (with quat_flag) already.
file(READ ${_lammps_pristine}/src/atom.h _ah)
file(READ ${_lammps_pristine}/src/atom.cpp _ac)
string(FIND "${_ah}" "double **quat;" _has_quat)
if(_has_quat EQUAL -1)
  polydem_insert_after(_ah "double **omega, **angmom, **torque;"
    "\n  double **quat;     // POLYDEM: orientation (w,x,y,z)\n  int *pshape;       // POLYDEM: shape-template index\n  double *pscale;    // POLYDEM: scale factor\n" atom.h)
  polydem_insert_after(_ah "int rmass_flag, radius_flag, omega_flag, torque_flag, angmom_flag;"
    "\n  int quat_flag, pshape_flag;    // POLYDEM\n" atom.h)
  polydem_insert_after(_ac "omega = angmom = torque = nullptr;"
    "\n  quat = nullptr;\n  pshape = nullptr;\n  pscale = nullptr;\n" atom.cpp)
  polydem_insert_after(_ac "add_peratom(\"angmom\",&angmom,DOUBLE,3);"
    "\n  add_peratom(\"quat\",&quat,DOUBLE,4);\n  add_peratom(\"pshape\",&pshape,INT,0);\n  add_peratom(\"pscale\",&pscale,DOUBLE,0);\n" atom.cpp)
  polydem_insert_after(_ac "rmass_flag = radius_flag = omega_flag = torque_flag = angmom_flag = 0;"
    "\n  quat_flag = pshape_flag = 0;\n" atom.cpp)
  polydem_insert_after(_ac "if (strcmp(name,\"angmom\") == 0) return (void *) angmom;"
    "\n  if (strcmp(name,\"quat\") == 0) return (void *) quat;\n  if (strcmp(name,\"pshape\") == 0) return (void *) pshape;\n  if (strcmp(name,\"pscale\") == 0) return (void *) pscale;\n" atom.cpp)
  polydem_insert_after(_ac "if (strcmp(name,\"angmom\") == 0) return LAMMPS_DOUBLE_2D;"
    "\n  if (strcmp(name,\"quat\") == 0) return LAMMPS_DOUBLE_2D;\n  if (strcmp(name,\"pshape\") == 0) return LAMMPS_INT;\n  if (strcmp(name,\"pscale\") == 0) return LAMMPS_DOUBLE;\n" atom.cpp)
else()
  # quat, quat_flag and their add_peratom/extract entries are LAMMPS's own
  polydem_insert_after(_ah "double **quat;"
    "\n  int *pshape;       // POLYDEM: shape-template index\n  double *pscale;    // POLYDEM: scale factor\n  int pshape_flag;   // POLYDEM\n" atom.h)
  polydem_insert_after(_ac "omega = angmom = torque = nullptr;"
    "\n  pshape = nullptr;\n  pscale = nullptr;\n" atom.cpp)
  polydem_insert_after(_ac "add_peratom(\"quat\",&quat,DOUBLE,4);"
    "\n  add_peratom(\"pshape\",&pshape,INT,0);\n  add_peratom(\"pscale\",&pscale,DOUBLE,0);\n" atom.cpp)
  polydem_insert_after(_ac "rmass_flag = radius_flag = omega_flag = torque_flag = angmom_flag = 0;"
    "\n  pshape_flag = 0;\n" atom.cpp)
  polydem_insert_after(_ac "if (strcmp(name,\"quat\") == 0) return (void *) quat;"
    "\n  if (strcmp(name,\"pshape\") == 0) return (void *) pshape;\n  if (strcmp(name,\"pscale\") == 0) return (void *) pscale;\n" atom.cpp)
  polydem_insert_after(_ac "if (strcmp(name,\"quat\") == 0) return LAMMPS_DOUBLE_2D;"
    "\n  if (strcmp(name,\"pshape\") == 0) return LAMMPS_INT;\n  if (strcmp(name,\"pscale\") == 0) return LAMMPS_DOUBLE;\n" atom.cpp)
endif()
foreach(f atom.h atom.cpp)
  if(f STREQUAL "atom.h")
    set(_content "${_ah}")
  else()
    set(_content "${_ac}")
  endif()
  file(WRITE ${POLYDEM_STAGE}/src/${f}.tmp "${_content}")
  file(COPY_FILE ${POLYDEM_STAGE}/src/${f}.tmp ${POLYDEM_STAGE}/src/${f} ONLY_IF_DIFFERENT)
  file(REMOVE ${POLYDEM_STAGE}/src/${f}.tmp)
endforeach()

# compute_property_atom.cpp (29 Sep 2021): quatw ... quatk read Atom::quat
# when neither an ellipsoid nor a body style is present and the atom style
# sets quat_flag (atom_style polyhedron), as LAMMPS does from 4 Feb 2025 on;
# before, they stopped with "atom property that isn't allocated"
set(_cpa_file ${POLYDEM_STAGE}/src/compute_property_atom.cpp)
if(_patched)
  string(REPLACE "if (!avec_ellipsoid && !avec_body)\n"
                 "if (!avec_ellipsoid && !avec_body && !atom->quat_flag)    // POLYDEM\n" _new "${_cpa}")
  string(REGEX MATCHALL "atom->quat_flag\\)    // POLYDEM" _hits "${_new}")
  list(LENGTH _hits _nhits)
  if(NOT _nhits EQUAL 4)
    message(FATAL_ERROR "POLYDEM: cannot patch compute_property_atom.cpp: found ${_nhits} of the 4 "
                        "quatw..quatk checks. LAMMPS ${POLYDEM_LAMMPS_VERSION_TEXT} is not supported.")
  endif()
  set(_cpa "${_new}")
  set(_k 0)
  foreach(c w i j k)
    polydem_insert_after(_cpa "void ComputePropertyAtom::pack_quat${c}(int n)\n{\n"
      "  if (!avec_ellipsoid && !avec_body) {    // POLYDEM: Atom::quat\n    double **quat = atom->quat;\n    int *mask = atom->mask;\n    int nlocal = atom->nlocal;\n    for (int i = 0; i < nlocal; i++) {\n      buf[n] = (mask[i] & groupbit) ? quat[i][${_k}] : 0.0;\n      n += nvalues;\n    }\n    return;\n  }\n"
      compute_property_atom.cpp)
    math(EXPR _k "${_k} + 1")
  endforeach()
  # a link left by an earlier configure would carry the write to the pristine file
  if(IS_SYMLINK ${_cpa_file})
    file(REMOVE ${_cpa_file})
  endif()
  file(WRITE ${_cpa_file}.tmp "${_cpa}")
  file(COPY_FILE ${_cpa_file}.tmp ${_cpa_file} ONLY_IF_DIFFERENT)
  file(REMOVE ${_cpa_file}.tmp)
endif()

# the LAMMPS version for src/POLYDEM/polydem_lammps_compat.h, in a header of
# the staged src/ (a compile definition would change, and so recompile, every
# LAMMPS file)
file(WRITE ${POLYDEM_STAGE}/src/polydem_lammps_version.h.tmp
  "// generated by cmake/PolydemLammps.cmake from src/version.h\n"
  "#define POLYDEM_LAMMPS_VERSION ${POLYDEM_LAMMPS_VERSION}    // ${POLYDEM_LAMMPS_VERSION_TEXT}\n")
file(COPY_FILE ${POLYDEM_STAGE}/src/polydem_lammps_version.h.tmp
     ${POLYDEM_STAGE}/src/polydem_lammps_version.h ONLY_IF_DIFFERENT)
file(REMOVE ${POLYDEM_STAGE}/src/polydem_lammps_version.h.tmp)

# cmake/: copy, then add POLYDEM to the package list and raise C++11 to C++17
if(NOT EXISTS ${POLYDEM_STAGE}/cmake/.copied)
  file(COPY ${_lammps_pristine}/cmake DESTINATION ${POLYDEM_STAGE})
  file(TOUCH ${POLYDEM_STAGE}/cmake/.copied)
endif()
file(READ ${_lammps_pristine}/cmake/CMakeLists.txt _cm)
polydem_insert_after(_cm "set(STANDARD_PACKAGES\n" "  POLYDEM\n" cmake/CMakeLists.txt)
string(REPLACE "set(CMAKE_CXX_STANDARD 11)" "set(CMAKE_CXX_STANDARD 17)" _cm "${_cm}")
file(WRITE ${POLYDEM_STAGE}/cmake/CMakeLists.txt.tmp "${_cm}")
file(COPY_FILE ${POLYDEM_STAGE}/cmake/CMakeLists.txt.tmp ${POLYDEM_STAGE}/cmake/CMakeLists.txt ONLY_IF_DIFFERENT)
file(REMOVE ${POLYDEM_STAGE}/cmake/CMakeLists.txt.tmp)

# ---------------------------------------------------------------------------
# 3. Kokkos. POLYDEM_KOKKOS_BACKEND (unless Kokkos_DIR is given):
#   openmp  (default) Kokkos 3.4.01 Serial + OpenMP, built from Debian's trilinos
#           source package into POLYDEM_CACHE_DIR/kokkos-openmp at configure time
#           (cmake/scripts/build-kokkos-host.sh; the source is fetched with apt once, as
#           for the CUDA compile check): `lmp -k on t N` runs N threads
#   tsan    Serial + Threads, ThreadSanitizer, Kokkos debug checks (unittest/scripts/tsan.sh)
#   debian  Debian's libtrilinos-kokkos-dev (Serial only: `t N` runs serially).
#           Its KokkosConfig.cmake points its include directory at
#           /usr/lib/include (it forgets the multiarch level); a corrected copy
#           is used (DESIGN.md section 5).
# Kokkos 3.4.01 suits LAMMPS 29 Sep 2021 only: later LAMMPS needs Kokkos 4, so
# there the default is no KOKKOS package unless Kokkos_DIR is given.
if(POLYDEM_LAMMPS_VERSION LESS 20220000 OR
   (Kokkos_DIR AND NOT Kokkos_DIR STREQUAL "${_POLYDEM_KOKKOS_AUTO_DIR}"))
  set(_kk_default ON)
else()
  set(_kk_default OFF)
endif()
option(POLYDEM_KOKKOS "Build the KOKKOS package and the /kk styles" ${_kk_default})
set(POLYDEM_KOKKOS_BACKEND openmp CACHE STRING "Kokkos for the KOKKOS package: openmp, tsan or debian")
set_property(CACHE POLYDEM_KOKKOS_BACKEND PROPERTY STRINGS openmp tsan debian)
# Kokkos_DIR chosen here on an earlier configure is chosen again (the backend may have changed)
if(POLYDEM_KOKKOS AND (NOT Kokkos_DIR OR Kokkos_DIR STREQUAL "${_POLYDEM_KOKKOS_AUTO_DIR}"))
  if(POLYDEM_KOKKOS_BACKEND STREQUAL "debian")
    set(_deb_kokkos /usr/lib/${CMAKE_LIBRARY_ARCHITECTURE}/cmake)
    if(NOT EXISTS ${_deb_kokkos}/Kokkos/KokkosConfig.cmake)
      message(FATAL_ERROR "POLYDEM: Kokkos not found: install libtrilinos-kokkos-dev (tools/install-deps.sh) "
                          "or pass -DKokkos_DIR=..., or -DPOLYDEM_KOKKOS=OFF")
    endif()
    set(_fixed ${CMAKE_BINARY_DIR}/kokkos-config)
    file(READ ${_deb_kokkos}/Kokkos/KokkosConfig.cmake _kc)
    string(REPLACE "\${CMAKE_CURRENT_LIST_DIR}/../" "${_deb_kokkos}/" _kc "${_kc}")
    string(REPLACE "\${CMAKE_CURRENT_LIST_DIR}/../../../../include/trilinos" "/usr/include/trilinos" _kc "${_kc}")
    string(REPLACE "\${KOKKOS_IMPORT_PREFIX}/include" "/usr/include/trilinos" _kc "${_kc}")
    file(WRITE ${_fixed}/KokkosConfig.cmake "${_kc}")
    file(COPY_FILE ${_deb_kokkos}/Kokkos/KokkosConfigVersion.cmake ${_fixed}/KokkosConfigVersion.cmake)
    set(_kdir ${_fixed})
  elseif(POLYDEM_KOKKOS_BACKEND MATCHES "^(openmp|tsan)$")
    message(STATUS "POLYDEM: Kokkos 3.4.01 (${POLYDEM_KOKKOS_BACKEND}) in ${POLYDEM_CACHE_DIR}/kokkos-${POLYDEM_KOKKOS_BACKEND}")
    execute_process(
      COMMAND ${CMAKE_COMMAND} -E env CMAKE=${CMAKE_COMMAND} CXX=${CMAKE_CXX_COMPILER}
              bash ${CMAKE_SOURCE_DIR}/cmake/scripts/build-kokkos-host.sh ${POLYDEM_CACHE_DIR} ${POLYDEM_KOKKOS_BACKEND}
      RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
    if(NOT _rc EQUAL 0)
      message(FATAL_ERROR "POLYDEM: building Kokkos (${POLYDEM_KOKKOS_BACKEND}) failed:\n${_out}\n${_err}\n"
                          "Run tools/install-deps.sh first, or -DPOLYDEM_KOKKOS_BACKEND=debian, or -DKokkos_DIR=...")
    endif()
    string(STRIP "${_out}" _out)
    string(REGEX REPLACE ".*\n" "" _prefix "${_out}")
    set(_kdir ${_prefix}/lib/cmake/Kokkos)
  else()
    message(FATAL_ERROR "POLYDEM_KOKKOS_BACKEND must be openmp, tsan or debian (got '${POLYDEM_KOKKOS_BACKEND}')")
  endif()
  set(Kokkos_DIR ${_kdir} CACHE PATH "Kokkos CMake config directory" FORCE)
  set(_POLYDEM_KOKKOS_AUTO_DIR ${_kdir} CACHE INTERNAL "Kokkos_DIR chosen by POLYDEM_KOKKOS_BACKEND")
endif()

# ---------------------------------------------------------------------------
# 4. LAMMPS options and the subdirectory
set(PKG_POLYDEM ON CACHE BOOL "" FORCE)
set(PKG_ASPHERE ON CACHE BOOL "")
set(PKG_GRANULAR ON CACHE BOOL "")
set(PKG_KOKKOS ${POLYDEM_KOKKOS} CACHE BOOL "" FORCE)
set(EXTERNAL_KOKKOS ON CACHE BOOL "" FORCE)
set(BUILD_MPI ON CACHE BOOL "")
set(LAMMPS_EXCEPTIONS ON CACHE BOOL "" FORCE)
set(BUILD_TOOLS OFF CACHE BOOL "")
set(BUILD_DOC OFF CACHE BOOL "")
set(ENABLE_TESTING OFF CACHE BOOL "LAMMPS's own tests" FORCE)
add_subdirectory(${POLYDEM_STAGE}/cmake ${CMAKE_BINARY_DIR}/lammps)
# lmp goes to the top of the build tree: build/lmp
set_target_properties(lmp PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR})
target_link_libraries(lammps PRIVATE polydem_shapes)
