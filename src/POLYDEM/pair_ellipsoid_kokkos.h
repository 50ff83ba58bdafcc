/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - pair_style ellipsoid/kk: pair ellipsoid on the device. One
   thread per entry of LAMMPS's Kokkos half "size" neighbor list runs the
   same kernels as the plain style (polydem_ellipsoid.h,
   polydem_ellipsoid_force.h) over its neighbors (bounded by the list);
   forces and torques are accumulated with atomics. No contact history.
------------------------------------------------------------------------- */

#ifdef PAIR_CLASS
// clang-format off
PairStyle(ellipsoid/kk,PairEllipsoidKokkos<LMPDeviceType>);
PairStyle(ellipsoid/kk/device,PairEllipsoidKokkos<LMPDeviceType>);
PairStyle(ellipsoid/kk/host,PairEllipsoidKokkos<LMPHostType>);
// clang-format on
#else

#ifndef LMP_PAIR_ELLIPSOID_KOKKOS_H
#define LMP_PAIR_ELLIPSOID_KOKKOS_H

#include "kokkos_type.h"
#include "pair_ellipsoid.h"
#include "polydem_shapes_kokkos.h"

namespace LAMMPS_NS {

template <class DeviceType> class PairEllipsoidKokkos : public PairEllipsoid {
 public:
  typedef DeviceType device_type;
  typedef ArrayTypes<DeviceType> AT;

  PairEllipsoidKokkos(class LAMMPS *);
  ~PairEllipsoidKokkos() override;
  void compute(int, int) override;
  void init_style() override;
  void init_list(int id, NeighList *ptr) override
  {
    PairEllipsoid::init_list(id, ptr);
    kk_init_list<DeviceType>(ptr);
  }

 protected:
  class AtomVecPolyhedronKokkos *avecKK;
  polydem_kk::DeviceShapes<DeviceType> shapes;    // .axes: semi-axes per template (unit scale)
  // the law table's entries on the device, and the table pointing there
  Kokkos::View<polydem::LawEntry<double> *, DeviceType> d_laws;
  polydem::LawTable<double> d_laws_table;
  // friction: partner counts for the history fix (polydem_history_kokkos.h)
  Kokkos::View<int *, DeviceType> d_npartner;    // list entries per local atom
  int params_dirty;
  DAT::tdual_efloat_1d k_eatom;
  DAT::tdual_virial_array k_vatom;

  void update_device_data();
};

}    // namespace LAMMPS_NS

#endif
#endif
