/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - the per-atom Views a /kk contact kernel reads of each body
   (position, velocities, mass, scale, type, shape, tag, mask, orientation)
   and writes (force, torque): one set for pair polyhedron/kk, pair
   ellipsoid/kk and fix wall/mesh/kk. A kernel functor derives from it, so
   that it is the `Atoms` of polydem_body_gather.h's gather_* (the
   functor itself is passed as *this).
------------------------------------------------------------------------- */

#ifndef POLYDEM_BODY_VIEWS_KOKKOS_H
#define POLYDEM_BODY_VIEWS_KOKKOS_H

#include "atom_kokkos.h"
#include "atom_vec_polyhedron_kokkos.h"
#include "kokkos_type.h"

// in LAMMPS_NS, ArrayTypes unqualified: LAMMPS 29 Sep 2021 declares it in the
// global namespace, so the name must resolve from either
namespace LAMMPS_NS {

template <class DeviceType> struct PolyBodyViews {
  typedef ArrayTypes<DeviceType> ATB;

  typename ATB::t_x_array_randomread x;
  typename ATB::t_v_array_randomread v, omega;
  typename ATB::t_f_array f, torque;
  typename ATB::t_float_1d_randomread rmass, pscale;
  typename ATB::t_int_1d_randomread type, pshape, mask;
  typename ATB::t_tagint_1d_randomread tag;
  polydem_view_t<tdual_quat_array, DeviceType> quat;

  // the Views on DeviceType (the caller syncs them first)
  void bind_bodies(AtomKokkos *atomKK, AtomVecPolyhedronKokkos *avecKK)
  {
    x = atomKK->k_x.view<DeviceType>();
    v = atomKK->k_v.view<DeviceType>();
    omega = atomKK->k_omega.view<DeviceType>();
    f = atomKK->k_f.view<DeviceType>();
    torque = atomKK->k_torque.view<DeviceType>();
    rmass = atomKK->k_rmass.view<DeviceType>();
    pscale = avecKK->k_pscale.view<DeviceType>();
    type = atomKK->k_type.view<DeviceType>();
    pshape = avecKK->k_pshape.view<DeviceType>();
    mask = atomKK->k_mask.view<DeviceType>();
    tag = atomKK->k_tag.view<DeviceType>();
    quat = avecKK->k_quat.view<DeviceType>();
  }
};

}    // namespace LAMMPS_NS

#endif
