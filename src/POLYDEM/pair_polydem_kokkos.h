/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - what pair_style polyhedron/kk and ellipsoid/kk do around the
   plain styles' init_style (PairPolydem's member templates)
------------------------------------------------------------------------- */

#ifndef LMP_PAIR_POLYDEM_KOKKOS_H
#define LMP_PAIR_POLYDEM_KOKKOS_H

#include "atom_vec_polyhedron_kokkos.h"
#include "error.h"
#include "force.h"
#include "kokkos_type.h"
#include "pair_polydem.h"
#include "polydem_history_kokkos.h"
#include "polydem_lammps_compat.h"

#include <type_traits>

namespace LAMMPS_NS {

/* ----------------------------------------------------------------------
   before the plain init_style: atom_style polyhedron/kk; newton pair off
   (FixNeighHistoryKokkos keeps the history of a pair with a ghost atom only
   on the owner of i: its pre_exchange has no reverse communication, so with
   newton on a pair whose owner changes at reneighboring would lose it); and
   where a history is kept, the Kokkos history fix in the placeholder's
   place (the plain init_style would otherwise create a plain one)
------------------------------------------------------------------------- */

template <class DeviceType> AtomVecPolyhedronKokkos *PairPolydem::kk_init_before(bool history)
{
  auto *avecKK = AtomVecPolyhedronKokkos::of(atom);
  if (!avecKK)
    error->all(FLERR, "pair_style {}/kk requires atom_style polyhedron/kk", style_name);
  if (force->newton_pair)
    error->all(FLERR,
               "pair_style {}/kk requires newton pair off: use '-pk kokkos newton off' or "
               "'package kokkos newton off' (default on GPUs)", style_name);
  if (history && fix_history == nullptr) {
    fix_history = polydem_kk::create_history_fix<DeviceType>(
        modify, history_fix_id(), dummy_fix_id(), nhistory, execution_space == Device);
    fix_history->pair = this;
  }
  return avecKK;
}

/* ----------------------------------------------------------------------
   after it: its size request made a Kokkos half list whatever 'package
   kokkos neigh' says (each pair once, with one history slot; forces go to
   both atoms with atomics)
------------------------------------------------------------------------- */

template <class DeviceType> void PairPolydem::kk_init_after()
{
  polydem_compat::request_kokkos_half_list(
      neighbor, this,
      std::is_same<DeviceType, LMPHostType>::value &&
          !std::is_same<DeviceType, LMPDeviceType>::value,
      std::is_same<DeviceType, LMPDeviceType>::value);
}

}    // namespace LAMMPS_NS

#endif
