/* ----------------------------------------------------------------------
   POLYDEM - fix wall/mesh/kk
------------------------------------------------------------------------- */

#include "fix_wall_mesh_kokkos.h"

#include "atom_kokkos.h"
#include "atom_masks.h"
#include "atom_vec_polyhedron_kokkos.h"
#include "error.h"
#include "memory_kokkos.h"
#include "neighbor.h"
#include "polydem_body_views_kokkos.h"
#include "polydem_kokkos_masks.h"
#include "polydem_law_table_kokkos.h"
#include "polydem_shape_template.h"
#include "polydem_tally_kokkos.h"
#include "update.h"

#include <algorithm>

using namespace LAMMPS_NS;


namespace {

typedef polydem::WallWorkspace<double> WallWorkspace;
typedef polydem::WallTally<double> WallTally;    // what the threads sum

// device copy of a host vector (at least one element)
template <class V, class S> void upload(V &d, const std::vector<S> &h, const char *name)
{
  d = V(std::string(name), std::max<size_t>(1, h.size()));
  auto m = Kokkos::create_mirror_view(d);
  for (size_t k = 0; k < h.size(); k++) m(k) = h[k];
  Kokkos::deep_copy(d, m);
}

/* ----------------------------------------------------------------------
   one particle per thread, as FixWallMesh::compute_forces: gather, the
   pipeline's wall_body_contact, scatter; sums reduced over threads. The
   workspace: on GPUs that of the particle's slot in the batch; on CPU
   back ends that of the thread (Kokkos's UniqueToken), all particles in
   one kernel, so that it stays in the thread's cache
------------------------------------------------------------------------- */

// the first near list of each local atom (exclusive prefix sum of the lists
// its template keeps, polydem::near_lists_of; none outside the group), and
// after the last atom the total
template <class DeviceType> struct NearFirstScan {
  typename ArrayTypes<DeviceType>::t_int_1d_randomread mask, pshape;
  Kokkos::View<polydem::ShapeView<double> *, DeviceType> shapes;
  Kokkos::View<size_t *, DeviceType> first;
  int groupbit, n;
  KOKKOS_INLINE_FUNCTION void operator()(const int i, size_t &sum, const bool final) const
  {
    if (final) first(i) = sum;
    if (mask(i) & groupbit) sum += polydem::near_lists_of(shapes(pshape(i)));
    if (final && i == n - 1) first(n) = sum;
  }
};

// pertriangle: shares of the patch forces go to their triangles (atomics:
// particles on different threads touch the same triangle)
template <class DeviceType> struct TriAdd {
  Kokkos::View<double *[3], DeviceType> trif;
  KOKKOS_INLINE_FUNCTION void operator()(int t, double fx, double fy, double fz) const
  {
    Kokkos::atomic_add(&trif(t, 0), fx);
    Kokkos::atomic_add(&trif(t, 1), fy);
    Kokkos::atomic_add(&trif(t, 2), fz);
  }
};

template <class DeviceType> struct WallMeshKernel : PolyBodyViews<DeviceType> {
  typedef DeviceType device_type;
  typedef ArrayTypes<DeviceType> AT;
  typedef WallTally value_type;
  typedef typename DeviceType::execution_space ExecSpace;
  typedef polydem_kk::WorkspaceSlot<ExecSpace> Slot;
  Slot slots;    // the workspace of a particle

  Kokkos::View<double **, Kokkos::LayoutRight, DeviceType> hist;
  Kokkos::View<polydem::ShapeView<double> *, DeviceType> shapes;
  Kokkos::View<double *[3], DeviceType> axes;    // ellipsoids' semi-axes (0: polyhedron)
  polydem::LawTable<double> laws;                // entries on the device
  Kokkos::View<char *, DeviceType> workspace;
  Kokkos::View<size_t *, DeviceType> near_first;    // atom i's first list
  Kokkos::View<double *, DeviceType> near_ref;
  Kokkos::View<int *, DeviceType> near_count, near_tri;
  Kokkos::View<float *, DeviceType> near_gap;
  int near_cap;    // entries per list
  Kokkos::View<double *[3], DeviceType> trif;    // pertriangle: force on each triangle
  int pertri;
  polydem::WallScene<double> sc;    // grid pointers into device memory
  double dt;
  int update, groupbit, ibase;

  KOKKOS_INLINE_FUNCTION void operator()(const int slot, value_type &sum) const
  {
    const int i = ibase + slot;
    if (!(this->mask(i) & groupbit)) return;
    // gather: atom i with its template and semi-axes (0: a polyhedron)
    const int ps = this->pshape(i);
    const auto b = polydem::gather_wall_body(
        *this, i, &shapes(ps), polydem::make_vec3(axes(ps, 0), axes(ps, 1), axes(ps, 2)));
    const int w = slots.acquire(slot);
    auto &ws = *reinterpret_cast<WallWorkspace *>(workspace.data() + w * sizeof(WallWorkspace));
    ws.record = pertri;
    polydem::WallNear<double> nl;
    polydem::WallNear<double> *pn = nullptr;
    if (near_cap > 0) {
      const size_t l0 = near_first(i);
      nl.ref = &near_ref(13 * l0);
      nl.count = &near_count(l0);
      nl.tri = &near_tri(near_cap * l0);
      nl.gap = &near_gap(near_cap * l0);
      nl.cap = near_cap;
      pn = &nl;
    }
    // the contact (polydem_wall_pipeline.h; a composite's parts one by
    // one; the history row in place), tally, then scatter
    polydem::WallPatches<double> P;
    auto tally = [&](const polydem::WallBody<double> &bb,
                     const polydem::WallContactResult<double> &rr,
                     const polydem::WallPatches<double> &PP) {
      polydem::wall_tally_add(sum, bb, rr, sc.mp, PP);
      if (pertri) {
        TriAdd<DeviceType> add{trif};
        polydem::wall_body_triangle_forces(bb, ws, PP, rr, add);
      }
    };
    const auto r = polydem::wall_particle_contact(b, laws, sc, dt, update != 0, &hist(i, 0), ws,
                                                  P, pn, tally);
    slots.release(w);
    const auto &f = this->f, &torque = this->torque;
    f(i, 0) += r.wf.f.x;
    f(i, 1) += r.wf.f.y;
    f(i, 2) += r.wf.f.z;
    torque(i, 0) += r.wf.tau.x;
    torque(i, 1) += r.wf.tau.y;
    torque(i, 2) += r.wf.tau.z;
  }
};

}    // namespace

/* ---------------------------------------------------------------------- */

template <class DeviceType>
FixWallMeshKokkos<DeviceType>::FixWallMeshKokkos(LAMMPS *lmp, int narg, char **arg) :
    FixWallMesh(lmp, narg, arg), avecKK(nullptr), nslots(0)
{
  kokkosable = 1;
  atomKK = (AtomKokkos *) atom;
  execution_space = ExecutionSpaceFromDevice<DeviceType>::space;
  datamask_read = X_MASK | V_MASK | OMEGA_MASK | F_MASK | TORQUE_MASK | MASK_MASK | TYPE_MASK |
      RMASS_MASK | POLYDEM_ALL_MASK;
  datamask_modify = F_MASK | TORQUE_MASK;
  // the base class allocated a plain history array: replace it by the DualView
  memory->destroy(hist);
  hist = nullptr;
  grow_arrays(atom->nmax);
  for (int i = 0; i < atom->nlocal; i++) set_arrays(i);
}

template <class DeviceType> FixWallMeshKokkos<DeviceType>::~FixWallMeshKokkos()
{
  if (copymode) return;
  memoryKK->destroy_kokkos(k_hist, hist);
  hist = nullptr;
}

/* ---------------------------------------------------------------------- */

template <class DeviceType> void FixWallMeshKokkos<DeviceType>::init()
{
  FixWallMesh::init();
  avecKK = AtomVecPolyhedronKokkos::of(atom);
  if (!avecKK) error->all(FLERR, "fix wall/mesh/kk requires atom_style polyhedron/kk");

  // mesh and grid (rebuilt by FixWallMesh::init only if the bin edge changed)
  upload(d_tri, geom.mesh.tri, "wall/mesh/kk:tri");
  upload(d_plane, geom.grid.plane, "wall/mesh/kk:plane");
  upload(d_box, geom.grid.box, "wall/mesh/kk:box");
  upload(d_start, geom.grid.start, "wall/mesh/kk:start");
  upload(d_items, geom.grid.items, "wall/mesh/kk:items");
  upload(d_sphere, geom.grid.sphere, "wall/mesh/kk:sphere");
  upload(d_region, geom.regions, "wall/mesh/kk:region");

  // the law table (FixWallMesh::init) on the device
  d_laws_table = polydem_kk::mirror_law_table<DeviceType>(laws, d_laws);
  shapes.version = -1;
  update_shapes();
}

/* ----------------------------------------------------------------------
   all shape templates flat on the device, one ShapeView per template
------------------------------------------------------------------------- */

template <class DeviceType> void FixWallMeshKokkos<DeviceType>::update_shapes()
{
  if (avec->ntemplates() == 0)
    error->all(FLERR, "fix wall/mesh/kk: no shape defined (polyhedron_shape)");
  shapes.update(*avec, true, "wall/mesh/kk");    // the clip marks faces through the dual
}

/* ---------------------------------------------------------------------- */

template <class DeviceType> void FixWallMeshKokkos<DeviceType>::compute_forces(bool stepping)
{
  for (int k = 0; k <= NVEC; k++) local[k] = 0.0;
  reduced = 0;
  update_shapes();
  atomKK->sync(execution_space, datamask_read);
  k_hist.template sync<DeviceType>();

  const int nlocal = atom->nlocal;
  typedef WallMeshKernel<DeviceType> Kernel;
  typename Kernel::Slot slots;
  const int want = slots.count(
      std::max(1, std::min(nlocal, (int) (WORKSPACE_BUDGET_DEVICE / sizeof(WallWorkspace)))));
  if (want > nslots) {
    nslots = want;
    d_workspace = Kokkos::View<char *, DeviceType>(
        Kokkos::view_alloc(Kokkos::WithoutInitializing, "wall/mesh/kk:workspace"),
        (size_t) nslots * sizeof(WallWorkspace));
  }

  // near lists of local atoms: stale after reneighboring and at setup; one
  // per composite part (polydem::wall_part_near), atom i's from
  // d_near_first(i) on
  const bool stale = !stepping || neighbor->ago == 0;
  if (near_cap > 0 && (stale || near_first_n != nlocal)) {
    if ((int) d_near_first.extent(0) < nlocal + 1)
      d_near_first = Kokkos::View<size_t *, DeviceType>("wall/mesh/kk:near_first", nlocal + 1);
    NearFirstScan<DeviceType> scan;
    scan.mask = atomKK->k_mask.view<DeviceType>();
    scan.pshape = avecKK->k_pshape.view<DeviceType>();
    scan.shapes = shapes.views;
    scan.first = d_near_first;
    scan.groupbit = groupbit;
    scan.n = nlocal;
    size_t n = 0;
    polydem_kk::scan_range<typename DeviceType::execution_space>(0, nlocal, scan, n);
    near_first_n = nlocal;
    near_lists_held = (bigint) n;
    if (d_near_count.extent(0) < std::max<size_t>(1, n)) {
      const size_t room = std::max<size_t>(1, n + n / 5);    // grows with the atoms
      d_near_ref = decltype(d_near_ref)(
          Kokkos::view_alloc(Kokkos::WithoutInitializing, "wall/mesh/kk:near_ref"), 13 * room);
      d_near_count = decltype(d_near_count)("wall/mesh/kk:near_count", room);
      d_near_tri = decltype(d_near_tri)(
          Kokkos::view_alloc(Kokkos::WithoutInitializing, "wall/mesh/kk:near_tri"),
          (size_t) near_cap * room);
      d_near_gap = decltype(d_near_gap)(
          Kokkos::view_alloc(Kokkos::WithoutInitializing, "wall/mesh/kk:near_gap"),
          (size_t) near_cap * room);
    }
    Kokkos::deep_copy(d_near_count, polydem::NEAR_REBUILD);
  }

  Kernel k;
  k.slots = slots;
  k.pertri = pertri;
  if (pertri) {
    if ((int) d_trif.extent(0) != geom.ntri())
      d_trif = Kokkos::View<double *[3], DeviceType>("wall/mesh/kk:trif", geom.ntri());
    else
      Kokkos::deep_copy(d_trif, 0.0);
    k.trif = d_trif;
  }
  tri_reduced = 0;
  k.near_first = d_near_first;
  k.near_ref = d_near_ref;
  k.near_count = d_near_count;
  k.near_tri = d_near_tri;
  k.near_gap = d_near_gap;
  k.near_cap = near_cap;
  k.bind_bodies(atomKK, avecKK);
  k.hist = k_hist.template view<DeviceType>();
  k.shapes = shapes.views;
  k.axes = shapes.axes;
  k.laws = d_laws_table;
  k.workspace = d_workspace;
  k.sc = scene();
  k.sc.grid.tri = d_tri.data();
  k.sc.grid.start = d_start.data();
  k.sc.grid.items = d_items.data();
  k.sc.grid.plane = d_plane.data();
  k.sc.grid.box = d_box.data();
  k.sc.grid.sphere = d_sphere.data();
  k.sc.grid.region = d_region.data();
  k.dt = update->dt;
  k.update = stepping ? 1 : 0;
  k.groupbit = groupbit;

  int batch = nslots;
  if constexpr (Kernel::Slot::per_thread) batch = std::max(1, nlocal);
  WallTally total;
  for (int i0 = 0; i0 < nlocal; i0 += batch) {
    k.ibase = i0;
    WallTally sum;
    polydem_kk::reduce_range<typename Kernel::ExecSpace>(0, std::min(batch, nlocal - i0), k, sum);
    total += sum;
  }
  atomKK->modified(execution_space, datamask_modify);
  k_hist.template modify<DeviceType>();

  absorb(total);
  if (stepping && neighbor->ago == 0) report_counts();
}

// pertriangle: the device sums of this step into the host array
template <class DeviceType> void FixWallMeshKokkos<DeviceType>::fetch_triangle_forces()
{
  if (!pertri || d_trif.extent(0) == 0) return;
  auto h = Kokkos::create_mirror_view(d_trif);
  Kokkos::deep_copy(h, d_trif);
  for (size_t t = 0; t < h.extent(0); t++)
    for (int c = 0; c < 3; c++) tri_local[3 * t + c] = h(t, c);
}

/* ----------------------------------------------------------------------
   per-atom history: host rows alias the DualView's host view; host
   access (exchange, sort, restart) syncs first and marks the host modified
------------------------------------------------------------------------- */

template <class DeviceType> void FixWallMeshKokkos<DeviceType>::host_rows_current()
{
  k_hist.sync_host();
  k_hist.modify_host();
}

// DualView::resize keeps only the side marked newer, and after a sync it
// counts the device as newer (keeping the device rows and giving the host a
// fresh copy): mark the synced host modified first so that the host rows are
// the ones kept (on a GPU the device rows would otherwise be replaced by the
// fresh host copy at the next sync)
template <class DeviceType> void FixWallMeshKokkos<DeviceType>::grow_arrays(int nmax)
{
  if (hist) host_rows_current();
  memoryKK->grow_kokkos(k_hist, hist, nmax, nh, "wall/mesh/kk:hist");
  k_hist.modify_host();
}

template <class DeviceType> void FixWallMeshKokkos<DeviceType>::copy_arrays(int i, int j, int d)
{
  host_rows_current();
  FixWallMesh::copy_arrays(i, j, d);
}

template <class DeviceType> void FixWallMeshKokkos<DeviceType>::set_arrays(int i)
{
  host_rows_current();
  FixWallMesh::set_arrays(i);
}

template <class DeviceType> int FixWallMeshKokkos<DeviceType>::pack_exchange(int i, double *buf)
{
  k_hist.sync_host();
  return FixWallMesh::pack_exchange(i, buf);
}

template <class DeviceType> int FixWallMeshKokkos<DeviceType>::unpack_exchange(int n, double *buf)
{
  host_rows_current();
  return FixWallMesh::unpack_exchange(n, buf);
}

template <class DeviceType> int FixWallMeshKokkos<DeviceType>::pack_restart(int i, double *buf)
{
  k_hist.sync_host();
  return FixWallMesh::pack_restart(i, buf);
}

template <class DeviceType> void FixWallMeshKokkos<DeviceType>::unpack_restart(int n, int nth)
{
  host_rows_current();
  FixWallMesh::unpack_restart(n, nth);
}

namespace LAMMPS_NS {
template class FixWallMeshKokkos<LMPDeviceType>;
#ifdef LMP_KOKKOS_GPU
template class FixWallMeshKokkos<LMPHostType>;
#endif
}    // namespace LAMMPS_NS
