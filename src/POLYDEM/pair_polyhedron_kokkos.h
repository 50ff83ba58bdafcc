/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - pair_style polyhedron/kk: pair polyhedron on the device.
   Broad phase on LAMMPS's Kokkos half "size" neighbor list with history
   (FixNeighHistoryKokkos); narrow phase on the 1-D contact-pair array of
   the polyhedral seed §2.2: candidates per particle (bounding spheres
   overlap) -> exclusive prefix sum -> (i, jj) pair array -> one thread per
   pair running the same kernels as the plain style (GJK, overlap
   polyhedron, contact_step), forces and torques accumulated with atomics.
   Overlap workspaces (seed §2.3) are preallocated per pair slot and the
   pairs are processed in batches of at most as many slots as a memory
   budget allows; their size follows the largest face count present.
------------------------------------------------------------------------- */

#ifdef PAIR_CLASS
// clang-format off
PairStyle(polyhedron/kk,PairPolyhedronKokkos<LMPDeviceType>);
PairStyle(polyhedron/kk/device,PairPolyhedronKokkos<LMPDeviceType>);
PairStyle(polyhedron/kk/host,PairPolyhedronKokkos<LMPHostType>);
// clang-format on
#else

#ifndef LMP_PAIR_POLYHEDRON_KOKKOS_H
#define LMP_PAIR_POLYHEDRON_KOKKOS_H

#include "kokkos_type.h"
#include "pair_polyhedron.h"
#include "polydem_contact_record.h"
#include "polydem_shape_view.h"
#include "polydem_shapes_kokkos.h"

namespace LAMMPS_NS {

template <class DeviceType> class FixNeighHistoryKokkos;

template <class DeviceType> class PairPolyhedronKokkos : public PairPolyhedron {
 public:
  typedef DeviceType device_type;
  typedef ArrayTypes<DeviceType> AT;

  PairPolyhedronKokkos(class LAMMPS *);
  ~PairPolyhedronKokkos() override;
  void compute(int, int) override;
  void init_style() override;
  void init_list(int id, NeighList *ptr) override
  {
    PairPolyhedron::init_list(id, ptr);
    kk_init_list<DeviceType>(ptr);
  }
  double memory_usage() override;

  // device memory for the overlap workspaces of one batch on GPUs [bytes]
  static constexpr double WORKSPACE_BUDGET_DEVICE = 512.0 * 1024 * 1024;
  // on CPU back ends: one workspace per thread, all pairs in one kernel
  // (batches of this many pairs where a compute asks for contact records)
  static constexpr int RECORD_BATCH_CPU = 4096;

  // the MaxFaces instantiations of OverlapWorkspace the style dispatches on
  static int workspace_max_faces(int nfaces);
  static double workspace_bytes(int max_faces);

 protected:
  class AtomVecPolyhedronKokkos *avecKK;
  FixNeighHistoryKokkos<DeviceType> *fix_historyKK;

  // all shape templates, flat on the device, and one ShapeView per template
  // pointing into them
  polydem_kk::DeviceShapes<DeviceType> shapes;

  // the law table's entries on the device, and the table pointing there
  int params_dirty;
  Kokkos::View<polydem::LawEntry<double> *, DeviceType> d_laws;
  polydem::LawTable<double> d_laws_table;

  // contact-pair array: candidates per list entry, their exclusive prefix
  // sum, and (i, jj) per candidate
  Kokkos::View<int *, DeviceType> d_count, d_offset;
  Kokkos::View<int *[2], DeviceType> d_pairs;
  int npairs;
  Kokkos::View<int *, DeviceType> d_npartner;    // candidates per local atom

  // overlap workspaces (raw bytes, nslots * sizeof(workspace)): one per pair
  // of a batch on GPUs, one per thread on CPU back ends
  Kokkos::View<char *, DeviceType> d_workspace;
  int nslots;

  // per-contact records of one batch, on steps a contact compute is due
  Kokkos::View<double *[polydem::CR_NFIELD], Kokkos::LayoutRight, DeviceType> d_records;
  int store_contacts;

  DAT::tdual_efloat_1d k_eatom;
  DAT::tdual_virial_array k_vatom;

  void update_shapes();
  void update_params();
  void build_pairs();
  void ensure_partners(int nlocal);
  template <int MF> void run_pairs();
  void gather_records(int n);
};

}    // namespace LAMMPS_NS

#endif
#endif
