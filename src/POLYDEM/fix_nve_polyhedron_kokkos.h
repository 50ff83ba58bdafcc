/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - fix nve/polyhedron/kk: fix nve/polyhedron as one Kokkos kernel
   per half step. Calls the same kernels (polydem_rigid.h) with the same
   arithmetic as the plain fix, so trajectories agree to round-off (bit for
   bit on a CPU backend).
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(nve/polyhedron/kk,FixNVEPolyhedronKokkos<LMPDeviceType>);
FixStyle(nve/polyhedron/kk/device,FixNVEPolyhedronKokkos<LMPDeviceType>);
FixStyle(nve/polyhedron/kk/host,FixNVEPolyhedronKokkos<LMPHostType>);
// clang-format on
#else

#ifndef LMP_FIX_NVE_POLYHEDRON_KOKKOS_H
#define LMP_FIX_NVE_POLYHEDRON_KOKKOS_H

#include "fix_nve.h"
#include "kokkos_type.h"

namespace LAMMPS_NS {

// per shape template: volume, principal moments J0 J1 J2 (unit density and scale)
typedef Kokkos::DualView<double *[4], Kokkos::LayoutRight, LMPDeviceType> tdual_shape_props;

template <class DeviceType> class FixNVEPolyhedronKokkos : public FixNVE {
 public:
  FixNVEPolyhedronKokkos(class LAMMPS *, int, char **);
  void init() override;
  void initial_integrate(int) override;
  void final_integrate() override;

  // what a half step does
  enum { OMEGA_ONLY = 0, INITIAL = 1, FINAL = 2 };

 private:
  class PolyShapeLibrary *avec;
  class AtomVecPolyhedronKokkos *avecKK;
  int table_version;    // PolyShapeLibrary::shape_version() of k_props
  tdual_shape_props k_props;

  void find_style();
  void update_table();
  template <int MODE> void integrate(int nlocal);
};

}    // namespace LAMMPS_NS

#endif
#endif
