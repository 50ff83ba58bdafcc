/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - fix wall/mesh/kk: fix wall/mesh with one Kokkos thread per
   particle (polyhedra and ellipsoids: the kernel branches on the shape).
   Mesh, bin grid, shape templates and per-type material live on
   the device; the per-atom wall history is a DualView (host rows alias it
   for exchange and restart). Calls the same kernels (polydem_wall_contact.h)
   with the same arithmetic as the plain fix.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(wall/mesh/kk,FixWallMeshKokkos<LMPDeviceType>);
FixStyle(wall/mesh/kk/device,FixWallMeshKokkos<LMPDeviceType>);
FixStyle(wall/mesh/kk/host,FixWallMeshKokkos<LMPHostType>);
// clang-format on
#else

#ifndef LMP_FIX_WALL_MESH_KOKKOS_H
#define LMP_FIX_WALL_MESH_KOKKOS_H

// Kokkos first: fix_wall_mesh.h includes the kernel headers, whose
// POLYDEM_FN must see KOKKOS_VERSION to become KOKKOS_INLINE_FUNCTION
#include "kokkos_type.h"
// clang-format off
#include "fix_wall_mesh.h"
// clang-format on
#include "polydem_shapes_kokkos.h"

namespace LAMMPS_NS {

template <class DeviceType> class FixWallMeshKokkos : public FixWallMesh {
 public:
  typedef DeviceType device_type;
  typedef Kokkos::DualView<double **, Kokkos::LayoutRight, LMPDeviceType> tdual_hist;

  FixWallMeshKokkos(class LAMMPS *, int, char **);
  ~FixWallMeshKokkos() override;
  void init() override;

  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;

  // memory for the clipping workspaces of one batch of particles on GPUs [bytes]
  static constexpr double WORKSPACE_BUDGET_DEVICE = 256.0 * 1024 * 1024;

 protected:
  class AtomVecPolyhedronKokkos *avecKK;
  tdual_hist k_hist;

  // mesh and grid (mesh frame)
  Kokkos::View<double *, DeviceType> d_tri, d_plane, d_box, d_sphere;
  Kokkos::View<int *, DeviceType> d_start, d_items, d_region;
  // shape templates with their semi-axes (0: a polyhedron), as the pair styles
  polydem_kk::DeviceShapes<DeviceType> shapes;
  // the law table's entries on the device, and the table pointing there
  Kokkos::View<polydem::LawEntry<double> *, DeviceType> d_laws;
  polydem::LawTable<double> d_laws_table;
  Kokkos::View<char *, DeviceType> d_workspace;
  // near lists (keyword cache): atom i's from d_near_first(i) on, one per
  // part of its template; d_near_first for near_first_n local atoms
  Kokkos::View<size_t *, DeviceType> d_near_first;
  int near_first_n = -1;
  Kokkos::View<double *, DeviceType> d_near_ref;
  Kokkos::View<int *, DeviceType> d_near_count, d_near_tri;
  Kokkos::View<float *, DeviceType> d_near_gap;
  Kokkos::View<double *[3], DeviceType> d_trif;    // pertriangle
  int nslots;

  void compute_forces(bool update) override;
  void fetch_triangle_forces() override;
  void update_shapes();
  void host_rows_current();    // sync the history to the host before host access
};

}    // namespace LAMMPS_NS

#endif
#endif
