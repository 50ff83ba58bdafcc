/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - polyhedral and ellipsoidal DEM for LAMMPS
   Shared definitions for the header-only kernels (host and device).
   This header includes nothing from LAMMPS (DESIGN.md section 4.1).
------------------------------------------------------------------------- */

#ifndef POLYDEM_DEFS_H
#define POLYDEM_DEFS_H

// Kokkos translation units (the /kk styles) include a Kokkos header first,
// which defines KOKKOS_VERSION; others may ask with -DPOLYDEM_USE_KOKKOS.
// Plain LAMMPS files and the host tests get plain inline functions.
#if defined(POLYDEM_USE_KOKKOS) || defined(KOKKOS_VERSION)
#include <Kokkos_Macros.hpp>
#define POLYDEM_FN KOKKOS_INLINE_FUNCTION
#define POLYDEM_FORCE_FN KOKKOS_FORCEINLINE_FUNCTION
#else
#define POLYDEM_FN inline
#if defined(__GNUC__)
#define POLYDEM_FORCE_FN inline __attribute__((always_inline))
#else
#define POLYDEM_FORCE_FN inline
#endif
#endif
// POLYDEM_FORCE_FN: small per-contact functions on the hot path (the contact
// step), inlined into each caller so that the parts a caller does not use
// (e.g. the wall's torque on B) are dropped by the compiler.

#include <cfloat>

namespace polydem {

// Kernel status codes (DESIGN.md section 4.3). The host turns them into
// warnings/errors; device code counts them.
enum Status : int {
  STATUS_OK = 0,           // result valid
  STATUS_SEPARATED = 1,    // no overlap (result valid: zero)
  STATUS_OVERFLOW = 2,     // fixed-size workspace too small; result invalid
  STATUS_NO_CONVERGENCE = 3,    // iteration cap hit; result invalid
  STATUS_DEGENERATE = 4,   // input degenerate (NaN, zero size...); result invalid
  STATUS_UNSUPPORTED = 5   // no kernel for this pair of shapes; result invalid
};

template <typename T> struct Eps;
template <> struct Eps<double> {
  static constexpr double value = DBL_EPSILON;
};
template <> struct Eps<float> {
  static constexpr float value = FLT_EPSILON;
};

}    // namespace polydem

#endif
