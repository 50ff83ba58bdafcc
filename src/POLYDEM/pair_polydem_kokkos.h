/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - what pair_style polyhedron/kk and ellipsoid/kk do around the
   plain styles' init_style (PairPolydem's member templates)
------------------------------------------------------------------------- */

#ifndef LMP_PAIR_POLYDEM_KOKKOS_H
#define LMP_PAIR_POLYDEM_KOKKOS_H

#include "atom_kokkos.h"
#include "atom_masks.h"
#include "atom_vec_polyhedron_kokkos.h"
#include "error.h"
#include "force.h"
#include "kokkos_type.h"
#include "memory_kokkos.h"
#include "neigh_list_kokkos.h"
#include "neighbor.h"
#include "pair_polydem.h"
#include "polydem_history_kokkos.h"
#include "polydem_kokkos_masks.h"
#include "polydem_lammps_compat.h"

#include <type_traits>

namespace LAMMPS_NS {

/* ----------------------------------------------------------------------
   constructor: Kokkos-able on DeviceType's space, the fields read and
   modified; destructor: the per-atom energy and virial Views
------------------------------------------------------------------------- */

template <class DeviceType> void PairPolydem::kk_construct()
{
  kokkosable = 1;
  atomKK = (AtomKokkos *) atom;
  execution_space = ExecutionSpaceFromDevice<DeviceType>::space;
  datamask_read = X_MASK | V_MASK | OMEGA_MASK | F_MASK | TORQUE_MASK | TYPE_MASK | MASK_MASK |
      TAG_MASK | ENERGY_MASK | VIRIAL_MASK | RMASS_MASK | RADIUS_MASK | POLYDEM_ALL_MASK;
  datamask_modify = F_MASK | TORQUE_MASK | ENERGY_MASK | VIRIAL_MASK;
}

template <class KE, class KV> void PairPolydem::kk_destroy_tallies(KE &k_eatom, KV &k_vatom)
{
  memoryKK->destroy_kokkos(k_eatom, eatom);
  memoryKK->destroy_kokkos(k_vatom, vatom);
  eatom = nullptr;
  vatom = nullptr;
}

template <class KE, class KV> void PairPolydem::kk_tally_views(KE &k_eatom, KV &k_vatom)
{
  if (eflag_atom) {
    memoryKK->destroy_kokkos(k_eatom, eatom);
    memoryKK->create_kokkos(k_eatom, eatom, maxeatom, "pair:eatom");
  }
  if (vflag_atom) {
    memoryKK->destroy_kokkos(k_vatom, vatom);
    memoryKK->create_kokkos(k_vatom, vatom, maxvatom, "pair:vatom");
  }
}

// after the kernel: the per-atom tallies written on DeviceType, copied to the host
template <class DeviceType, class KE, class KV>
void PairPolydem::kk_tally_to_host(KE &k_eatom, KV &k_vatom)
{
  if (eflag_atom) {
    k_eatom.template modify<DeviceType>();
    k_eatom.template sync<LMPHostType>();
  }
  if (vflag_atom) {
    k_vatom.template modify<DeviceType>();
    k_vatom.template sync<LMPHostType>();
  }
}

inline void PairPolydem::kk_sync_atoms(int eflag, int vflag)
{
  atomKK->sync(execution_space, datamask_read);
  if (eflag || vflag)
    atomKK->modified(execution_space, datamask_modify);
  else
    atomKK->modified(execution_space, F_MASK | TORQUE_MASK);
}

/* ----------------------------------------------------------------------
   before the plain init_style: atom_style polyhedron/kk; and where a
   history is kept, the Kokkos history fix in the placeholder's place (the
   plain init_style would otherwise create a plain one). Newton pair on or
   off: with on, each pair is computed once and the ghosts' forces and
   torques go back to their owners; the history fix sends the ghosts'
   histories to their owners at reneighboring
   (FixNeighHistoryPolyhedronKokkos::pre_exchange_newton)
------------------------------------------------------------------------- */

template <class DeviceType> AtomVecPolyhedronKokkos *PairPolydem::kk_init_before(bool history)
{
  auto *avecKK = AtomVecPolyhedronKokkos::of(atom);
  if (!avecKK)
    error->all(FLERR, "pair_style {}/kk requires atom_style polyhedron/kk", style_name);
  choose_history_size();
  if (history && fix_history == nullptr) {
    fix_history = polydem_kk::create_history_fix<DeviceType>(
        modify, history_fix_id(), dummy_fix_id(), nhistory, execution_space == Device);
    fix_history->pair = this;
    nhistory_fix = nhistory;
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
  // Bins as wide as the neighbor cutoff (LAMMPS's own choice for Kokkos on
  // GPUs, NeighborKokkos::set_binsize_kokkos) on every back end, unless the
  // user chose a size (neigh_modify binsize, package kokkos binsize).
  // NBinKokkos keeps at least 16 slots per bin; half-cutoff bins hold about
  // one grain each, which costs 0.4 kB per particle of dense dodecahedra at
  // the same speed (bench/RESULTS.md). The size follows the cutoff (every
  // type pair's is size_cutoff()) at every init, a hair wider, so that the
  // stencil stays one bin wide: LAMMPS's Kokkos neighbor build does not
  // survive a stencil that grows between runs with unchanged requests.
  if (!neighbor->binsizeflag || (kk_binsize > 0.0 && neighbor->binsize_user == kk_binsize)) {
    kk_binsize = (size_cutoff() + neighbor->skin) * (1.0 + 1e-10);
    neighbor->binsize_user = kk_binsize;
    neighbor->binsizeflag = kk_binsize > 0.0 ? 1 : 0;
  }
}

/* ----------------------------------------------------------------------
   a list not yet built starts 2 neighbors wide instead of NeighListKokkos's
   16: its first build finds the widest row and widens it to 1.2 x that
   (npair_kokkos.cpp), which FixNeighHistoryKokkos's firstflag and
   firstvalue (maxatom x width x values) follow. A dense packing of
   polyhedra has 3-6 half-list neighbors per atom, so the padding to 16
   costs about 1 KB per particle of memory otherwise.
------------------------------------------------------------------------- */

template <class DeviceType> void PairPolydem::kk_init_list(NeighList *ptr)
{
  auto *l = dynamic_cast<NeighListKokkos<DeviceType> *>(ptr);
  if (l && l->d_neighbors.extent(0) == 0) l->maxneighs = 2;
}

}    // namespace LAMMPS_NS

#endif
