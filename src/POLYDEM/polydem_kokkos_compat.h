/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - the differences of LAMMPS's KOKKOS package API between LAMMPS
   29 Sep 2021 (run here, Kokkos 3.4.01) and 4 Feb 2025 (compiled against
   Kokkos 4.5.1's headers: unittest/scripts/kokkos-compile-check.sh), for
   atom_style polyhedron/kk. Host API differences: polydem_lammps_compat.h.

   Since 2021 the device communication sends one swap's list (a 1-D view,
   no iswap argument), exchange packs without the dimension bounds and
   unpacks with an index list, the atom style sorts its own fields
   (sort_kokkos), CommKokkos is no longer the atom style's commKK, and
   AtomVecKokkos derives virtually from AtomVec.
------------------------------------------------------------------------- */

#ifndef LMP_POLYDEM_KOKKOS_COMPAT_H
#define LMP_POLYDEM_KOKKOS_COMPAT_H

#include "kokkos_type.h"
#include "polydem_lammps_compat.h"

namespace LAMMPS_NS {

#if POLYDEM_LAMMPS_NEW_API
// the send list of one swap
typedef DAT::tdual_int_1d polydem_tdual_sendlist;
template <class DeviceType>
using polydem_sendlist_view = typename ArrayTypes<DeviceType>::t_int_1d_const;
#define POLYDEM_KK_SEND(list, iswap, i) list(i)
// the iswap parameter of pack_comm_kokkos / pack_comm_vel_kokkos /
// pack_comm_self (REF) and pack_border_kokkos / pack_border_vel_kokkos (INT)
#define POLYDEM_KK_ISWAP_REF
#define POLYDEM_KK_ISWAP_INT
// a function body without the parameter: iswap is 0 for the functors
#define POLYDEM_KK_NO_ISWAP const int iswap = 0;
// pack_exchange_kokkos(..., ExecutionSpace space POLYDEM_KK_EXCHANGE_BOUNDS)
#define POLYDEM_KK_EXCHANGE_BOUNDS
// unpack_exchange_kokkos(..., ExecutionSpace space POLYDEM_KK_EXCHANGE_INDICES)
#define POLYDEM_KK_EXCHANGE_INDICES , DAT::tdual_int_1d &
// AtomVec is a virtual base: the most derived class constructs it
#define POLYDEM_KK_ATOMVEC_BASE(lmp) AtomVec(lmp),
#define POLYDEM_KK_FORWARD_COMM_ON_HOST (lmp->kokkos->forward_comm_on_host)
#else
typedef DAT::tdual_int_2d polydem_tdual_sendlist;
template <class DeviceType>
using polydem_sendlist_view = typename ArrayTypes<DeviceType>::t_int_2d_const;
#define POLYDEM_KK_SEND(list, iswap, i) list(iswap, i)
#define POLYDEM_KK_ISWAP_REF const int &iswap,
#define POLYDEM_KK_ISWAP_INT int iswap,
#define POLYDEM_KK_NO_ISWAP
#define POLYDEM_KK_EXCHANGE_BOUNDS , int /*dim*/, X_FLOAT /*lo*/, X_FLOAT /*hi*/
#define POLYDEM_KK_EXCHANGE_INDICES
#define POLYDEM_KK_ATOMVEC_BASE(lmp)
#define POLYDEM_KK_FORWARD_COMM_ON_HOST (commKK->forward_comm_on_host)
#endif

}    // namespace LAMMPS_NS

#endif
