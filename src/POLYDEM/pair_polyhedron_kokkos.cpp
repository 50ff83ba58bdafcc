/* ----------------------------------------------------------------------
   POLYDEM - pair_style polyhedron/kk
------------------------------------------------------------------------- */

#include "pair_polyhedron_kokkos.h"
#include "pair_polydem_kokkos.h"

#include "atom_kokkos.h"
#include "atom_masks.h"
#include "atom_vec_polyhedron_kokkos.h"
#include "comm.h"
#include "error.h"
#include "fix_neigh_history_kokkos.h"
#include "force.h"
#include "kokkos.h"
#include "memory_kokkos.h"
#include "modify.h"
#include "neigh_list_kokkos.h"
#include "neigh_request.h"
#include "polydem_lammps_compat.h"
#include "neighbor.h"
#include "update.h"

#include "polydem_body_views_kokkos.h"
#include "polydem_contact_pipeline.h"
#include "polydem_contact_record.h"
#include "polydem_history_kokkos.h"
#include "polydem_law_table_kokkos.h"
#include "polydem_shape_template.h"
#include "polydem_tally_kokkos.h"

#include <algorithm>
#include <cmath>
#include <vector>

using namespace LAMMPS_NS;

namespace {


template <class DeviceType> struct PolyKK {
  typedef ArrayTypes<DeviceType> AT;
  typedef typename AT::t_neighbors_2d t_neighbors;
  typedef typename AT::t_int_1d_randomread t_int_ro;
};

/* ----------------------------------------------------------------------
   step 1 of the contact-pair array (seed §2.2): candidates of list entry ii
   = neighbors whose bounding spheres overlap; the others lose their contact
   history here, exactly as in the plain style
------------------------------------------------------------------------- */

template <class DeviceType> struct PolyCandidateFunctor {
  typedef DeviceType device_type;
  typedef ArrayTypes<DeviceType> AT;
  polydem_kk::SizeListViews<DeviceType> nl;
  typename AT::t_int_2d firsttouch;
  typename AT::t_float_2d firstshear;
  Kokkos::View<int *, DeviceType> count, offset;
  Kokkos::View<int *[2], DeviceType> pairs;
  Kokkos::View<int *, DeviceType> npartner;    // list entries per local atom (both sides)
  int nlocal, count_partners;
  int fill;     // 0: count the candidates (and release the others' history), 1: list them
  int nhist;    // history values per pair
  double reach;    // liquid bridges' largest rupture distance (LawTable::bridge_reach)

  KOKKOS_INLINE_FUNCTION void operator()(const int ii) const
  {
    const int i = nl.ilist(ii);
    const int jnum = nl.numneigh(i);
    const double xi = nl.x(i, 0), yi = nl.x(i, 1), zi = nl.x(i, 2), ri = nl.radius(i);
    int n = 0;
    const int base = fill ? offset(ii) : 0;
    for (int jj = 0; jj < jnum; jj++) {
      const int j = nl.neighbors(i, jj) & NEIGHMASK;
      const double delx = xi - nl.x(j, 0), dely = yi - nl.x(j, 1), delz = zi - nl.x(j, 2);
      const double radsum = ri + nl.radius(j) + reach;
      const double rsq = delx * delx + dely * dely + delz * delz;
      if (!fill && count_partners) {
        Kokkos::atomic_increment(&npartner(i));
        if (j < nlocal) Kokkos::atomic_increment(&npartner(j));
      }
      if (rsq >= radsum * radsum) {
        if (!fill) {
          firsttouch(i, jj) = 0;
          for (int k = 0; k < nhist; k++) firstshear(i, nhist * jj + k) = 0.0;
        }
        continue;
      }
      if (fill) {
        pairs(base + n, 0) = i;
        pairs(base + n, 1) = jj;
      }
      n++;
    }
    if (!fill) count(ii) = n;
  }
};

// step 2: exclusive prefix sum of the counts; offset(inum) = number of pairs
template <class DeviceType> struct PolyScanFunctor {
  typedef DeviceType device_type;
  typedef int value_type;
  Kokkos::View<int *, DeviceType> count, offset;
  int inum;
  KOKKOS_INLINE_FUNCTION void operator()(const int ii, int &update, const bool final) const
  {
    const int c = ii < inum ? count(ii) : 0;
    if (final) offset(ii) = update;
    update += c;
  }
};

// energy, virial and kernel-status counters of one batch
typedef polydem_kk::PairReduce<PairPolyhedron::NCOUNT> PolyReduce;

/* ----------------------------------------------------------------------
   step 3: one thread per candidate pair: gather the two bodies, the
   pipeline's polyhedron_pair_contact (as the plain style) with a
   workspace, scatter with atomics (i and j are shared between threads).
   The workspace: on GPUs that of the pair's slot in the batch (p - first);
   on CPU back ends (the execution space reaches host memory) that of the
   thread (Kokkos's UniqueToken), so that all pairs run in one kernel
   with a workspace that stays in the thread's cache (a batch of 16
   pairs per thread and kernel cost about 7 % of the dense dodecahedra's
   step in launches and cold workspaces)
------------------------------------------------------------------------- */

template <class DeviceType, int MF> struct PolyContactFunctor : PolyBodyViews<DeviceType> {
  typedef DeviceType device_type;
  typedef ArrayTypes<DeviceType> AT;
  typedef PolyReduce value_type;
  typedef polydem::OverlapWorkspace<double, MF> Workspace;
  typedef polydem_kk::WorkspaceSlot<typename DeviceType::execution_space> Slot;

  typename AT::t_neighbors_2d neighbors;
  Slot slots;    // the workspace of a pair
  typename AT::t_int_2d firsttouch;
  typename AT::t_float_2d firstshear;
  Kokkos::View<int *[2], DeviceType> pairs;
  Kokkos::View<polydem::ShapeView<double> *, DeviceType> shapes;
  polydem::LawTable<double> laws;    // entries on the device
  Kokkos::View<char *, DeviceType> workspace;
  typename AT::t_efloat_1d eatom;
  typename AT::t_virial_array vatom;
  // per-contact records by slot (pair index - first; CR_ID1 = 0: none), if store_contacts
  Kokkos::View<double *[polydem::CR_NFIELD], Kokkos::LayoutRight, DeviceType> records;
  int store_contacts;
  int first;    // pair index of slot 0
  int nlocal, newton_pair, shearupdate;
  int atomic;    // scatter with atomics (polydem_kk::needs_atomics)
  polydem_kk::TallyFlags tally;
  double dt;

  KOKKOS_INLINE_FUNCTION void operator()(const int p, PolyReduce &red) const
  {
    const int i = pairs(p, 0), jj = pairs(p, 1);
    const int j = neighbors(i, jj) & NEIGHMASK;
    const int slot = slots.acquire(p - first);
    Workspace &ws = reinterpret_cast<Workspace *>(workspace.data())[slot];
    const polydem::ShapeView<double> vi = shapes(this->pshape(i)), vj = shapes(this->pshape(j));
    const auto A = polydem::gather_polyhedron_body(*this, i, vi);
    const auto B = polydem::gather_polyhedron_body(*this, j, vj);
    // the history is that of the lower-tag atom (polydem_contact_law.h);
    // FixNeighHistoryKokkos copies it to the partner unchanged
    const auto c = polydem::polyhedron_pair_contact(A, B, laws, dt, shearupdate != 0,
                                                    &firstshear(i, polydem::pair_history_stride(laws) * jj), ws, red.cnt,
                                                    firsttouch(i, jj) != 0);
    slots.release(slot);
    firsttouch(i, jj) = c.contact;
    if (!c.contact) return;
    polydem_kk::scatter_contact(this->f, this->torque, i, j, newton_pair || j < nlocal, c.cf,
                                atomic != 0);
    const polydem::Vec3<double> &xi = A.shape.x, &xj = B.shape.x;
    if (store_contacts && c.contact == 1) {
      const double pi[3] = {xi.x, xi.y, xi.z}, pj[3] = {xj.x, xj.y, xj.z};
      if (polydem::contact_owned(newton_pair, j < nlocal, this->tag(i), this->tag(j), pi, pj))
        polydem::fill_contact_record(&records(p - first, 0), this->tag(i), this->tag(j), this->mask(i), this->mask(j), c.vmin,
                                     c.geo, c.cf);
    }
    const double F[3] = {c.cf.F_A.x, c.cf.F_A.y, c.cf.F_A.z};
    polydem_kk::ev_tally_xyz(red, tally, eatom, vatom, i, j, c.cf.energy, F, xi.x - xj.x,
                             xi.y - xj.y, xi.z - xj.z);
  }
};

}    // namespace

/* ---------------------------------------------------------------------- */

template <class DeviceType>
PairPolyhedronKokkos<DeviceType>::PairPolyhedronKokkos(LAMMPS *lmp) :
    PairPolyhedron(lmp), avecKK(nullptr), fix_historyKK(nullptr),
    params_dirty(1), npairs(0), nslots(0), store_contacts(0)
{
  kk_construct<DeviceType>();
  ws.reset();    // the plain style's host workspace is not used
}

template <class DeviceType> PairPolyhedronKokkos<DeviceType>::~PairPolyhedronKokkos()
{
  if (copymode) return;
  kk_destroy_tallies(k_eatom, k_vatom);
}

/* ---------------------------------------------------------------------- */

template <class DeviceType> int PairPolyhedronKokkos<DeviceType>::workspace_max_faces(int nfaces)
{
  if (nfaces <= 16) return 16;
  if (nfaces <= 32) return 32;
  if (nfaces <= 64) return 64;
  return 128;
}

template <class DeviceType> double PairPolyhedronKokkos<DeviceType>::workspace_bytes(int mf)
{
  switch (workspace_max_faces(mf)) {
    case 16:
      return (double) sizeof(polydem::OverlapWorkspace<double, 16>);
    case 32:
      return (double) sizeof(polydem::OverlapWorkspace<double, 32>);
    case 64:
      return (double) sizeof(polydem::OverlapWorkspace<double, 64>);
    default:
      return (double) sizeof(polydem::OverlapWorkspace<double, 128>);
  }
}

/* ----------------------------------------------------------------------
   the history fix is the Kokkos one; the rest is the plain init_style
   (checks, size + history neighbor request), made a Kokkos half list
------------------------------------------------------------------------- */

template <class DeviceType> void PairPolyhedronKokkos<DeviceType>::init_style()
{
  avecKK = kk_init_before<DeviceType>(true);
  PairPolyhedron::init_style();
  fix_historyKK = (FixNeighHistoryKokkos<DeviceType> *) fix_history;
  kk_init_after<DeviceType>();
  shapes.version = -1;
  params_dirty = 1;
}

/* ----------------------------------------------------------------------
   all templates on the device, with their dual seeds (polydem_shapes_kokkos.h)
------------------------------------------------------------------------- */

template <class DeviceType> void PairPolyhedronKokkos<DeviceType>::update_shapes()
{
  if (avec->ntemplates() == 0)
    error->all(FLERR, "pair_style polyhedron/kk: no shape defined (polyhedron_shape)");
  shapes.update(*avec, true, "polyhedron/kk");
}

/* ----------------------------------------------------------------------
   the law table (init_style, init_one) on the device
------------------------------------------------------------------------- */

template <class DeviceType> void PairPolyhedronKokkos<DeviceType>::update_params()
{
  if (!params_dirty) return;
  d_laws_table = polydem_kk::mirror_law_table<DeviceType>(laws, d_laws);
  params_dirty = 0;
}

/* ----------------------------------------------------------------------
   contact-pair array (seed §2.2): count -> exclusive scan -> fill
------------------------------------------------------------------------- */

template <class DeviceType> void PairPolyhedronKokkos<DeviceType>::build_pairs()
{
  auto *k_list = static_cast<NeighListKokkos<DeviceType> *>(list);
  const int inum = list->inum;
  if ((int) d_count.extent(0) < inum + 1) {
    d_count = Kokkos::View<int *, DeviceType>("polyhedron/kk:count", inum + 1 + inum / 5);
    d_offset = Kokkos::View<int *, DeviceType>("polyhedron/kk:offset", d_count.extent(0));
  }

  PolyCandidateFunctor<DeviceType> cnt;
  cnt.fill = 0;
  cnt.nl.bind(k_list, atomKK);
  cnt.firsttouch = fix_historyKK->k_firstflag.template view<DeviceType>();
  cnt.firstshear = fix_historyKK->k_firstvalue.template view<DeviceType>();
  cnt.count = d_count;
  cnt.offset = d_offset;
  cnt.nhist = nhistory;
  cnt.reach = laws.bridge_reach;
  static_cast<polydem_kk::FixNeighHistoryPolyhedronKokkos<DeviceType> *>(fix_historyKK)->reach =
      laws.bridge_reach;
  const int nlocal = atom->nlocal;
  cnt.count_partners = neighbor->ago == 0;
  if (cnt.count_partners)
    polydem_kk::reset_partners(d_npartner, nlocal, atom->nmax, "polyhedron/kk:npartner");
  cnt.npartner = d_npartner;
  cnt.nlocal = nlocal;
  polydem_kk::for_range<typename DeviceType::execution_space>(0, inum, cnt);
  if (cnt.count_partners) ensure_partners(nlocal);

  PolyScanFunctor<DeviceType> scan;
  scan.count = d_count;
  scan.offset = d_offset;
  scan.inum = inum;
  int total = 0;
  polydem_kk::scan_range<typename DeviceType::execution_space>(0, inum + 1, scan, total);
  npairs = total;
  if ((int) d_pairs.extent(0) < npairs)
    d_pairs = Kokkos::View<int *[2], DeviceType>("polyhedron/kk:pairs", npairs + npairs / 5 + 16);

  if (npairs == 0) return;    // nothing to list (a dilute or wall-only step)
  cnt.fill = 1;
  cnt.pairs = d_pairs;
  polydem_kk::for_range<typename DeviceType::execution_space>(0, inum, cnt);
}

// shared with ellipsoid/kk: polydem_history_kokkos.h
template <class DeviceType> void PairPolyhedronKokkos<DeviceType>::ensure_partners(int nlocal)
{
  polydem_kk::ensure_partners<DeviceType>(fix_history, d_npartner, nlocal, atom->nmax, world);
}

/* ----------------------------------------------------------------------
   narrow phase over the pair array in batches of nslots pairs, one
   preallocated OverlapWorkspace<double, MF> per slot
------------------------------------------------------------------------- */

template <class DeviceType> template <int MF> void PairPolyhedronKokkos<DeviceType>::run_pairs()
{
  typedef polydem::OverlapWorkspace<double, MF> Workspace;
  typedef PolyContactFunctor<DeviceType, MF> Functor;
  typedef typename DeviceType::execution_space ExecSpace;
  if (npairs <= 0) return;
  // CPU back ends: one workspace per thread (the functor's UniqueToken), all
  // pairs in one kernel; GPUs: one workspace per pair of a batch, as many
  // as the budget allows
  typename Functor::Slot slots;
  int batch;
  if constexpr (Functor::Slot::per_thread)
    batch = store_contacts ? std::min(npairs, (int) RECORD_BATCH_CPU) : npairs;
  else
    batch = std::min(npairs, std::max(1, (int) (WORKSPACE_BUDGET_DEVICE / sizeof(Workspace))));
  const int nws = slots.count(batch);
  if ((double) d_workspace.extent(0) < (double) nws * sizeof(Workspace)) {
    d_workspace = Kokkos::View<char *, DeviceType>();
    d_workspace = Kokkos::View<char *, DeviceType>(
        Kokkos::view_alloc(Kokkos::WithoutInitializing, "polyhedron/kk:workspace"),
        (size_t) nws * sizeof(Workspace));
  }
  nslots = (int) (d_workspace.extent(0) / sizeof(Workspace));
  if constexpr (!Functor::Slot::per_thread) batch = nslots;

  Functor fn;
  fn.slots = slots;
  fn.bind_bodies(atomKK, avecKK);
  fn.neighbors = static_cast<NeighListKokkos<DeviceType> *>(list)->d_neighbors;
  fn.firsttouch = fix_historyKK->k_firstflag.template view<DeviceType>();
  fn.firstshear = fix_historyKK->k_firstvalue.template view<DeviceType>();
  fn.pairs = d_pairs;
  fn.shapes = shapes.views;
  fn.laws = d_laws_table;
  fn.workspace = d_workspace;
  if (eflag_atom) fn.eatom = k_eatom.template view<DeviceType>();
  if (vflag_atom) fn.vatom = k_vatom.template view<DeviceType>();
  fn.nlocal = atom->nlocal;
  fn.newton_pair = force->newton_pair;
  fn.atomic = polydem_kk::needs_atomics<ExecSpace>() ? 1 : 0;
  fn.shearupdate = update->setupflag ? 0 : 1;
  fn.tally = {atom->nlocal, force->newton_pair, eflag_global, eflag_atom, vflag_global,
              vflag_atom};
  fn.dt = update->dt;
  fn.store_contacts = store_contacts;
  // records: one per pair of a batch, copied out after each batch (memory
  // by batch, not by pairs: 152 B per pair of a batch)
  if (store_contacts) {
    if ((int) d_records.extent(0) < batch)
      d_records = Kokkos::View<double *[polydem::CR_NFIELD], Kokkos::LayoutRight, DeviceType>(
          "polyhedron/kk:records", batch);
    fn.records = d_records;
  }

  PolyReduce total;
  for (int first = 0; first < npairs; first += batch) {
    const int last = std::min(npairs, first + batch);
    fn.first = first;
    if (store_contacts) Kokkos::deep_copy(d_records, 0.0);
    PolyReduce red;
    polydem_kk::reduce_range<ExecSpace>(first, last, fn, red);
    total += red;
    if (store_contacts) gather_records(last - first);
  }

  polydem_kk::add_reduced(this, fn.tally, total, local_counts, NCOUNT);
}

/* ----------------------------------------------------------------------
   the records of one batch's contacts (CR_ID1 > 0) to the host, in
   pair-array order
------------------------------------------------------------------------- */

template <class DeviceType> void PairPolyhedronKokkos<DeviceType>::gather_records(int n)
{
  auto h = Kokkos::create_mirror_view(d_records);
  Kokkos::deep_copy(h, d_records);
  for (int p = 0; p < n; p++)
    if (h(p, polydem::CR_ID1) > 0.0)
      for (int k = 0; k < record_stride; k++) contact_data.push_back(h(p, k));
}

/* ---------------------------------------------------------------------- */

template <class DeviceType> void PairPolyhedronKokkos<DeviceType>::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag, 0);
  dt = update->dt;

  kk_tally_views(k_eatom, k_vatom);

  update_shapes();
  update_params();

  kk_sync_atoms(eflag, vflag);

  fix_historyKK->k_firstflag.template sync<DeviceType>();
  fix_historyKK->k_firstvalue.template sync<DeviceType>();

  build_pairs();
  store_contacts = store_contacts_now() ? 1 : 0;
  switch (workspace_max_faces(shapes.max_faces)) {
    case 16:
      run_pairs<16>();
      break;
    case 32:
      run_pairs<32>();
      break;
    case 64:
      run_pairs<64>();
      break;
    default:
      run_pairs<128>();
      break;
  }

  if (store_contacts) contact_step = update->ntimestep;

  fix_historyKK->k_firstflag.template modify<DeviceType>();
  fix_historyKK->k_firstvalue.template modify<DeviceType>();

  kk_tally_to_host<DeviceType>(k_eatom, k_vatom);

  if (counters_due()) report_counters();
}

/* ---------------------------------------------------------------------- */

template <class DeviceType> double PairPolyhedronKokkos<DeviceType>::memory_usage()
{
  double bytes = Pair::memory_usage();
  bytes += (double) d_workspace.extent(0);
  bytes += (double) d_records.extent(0) * polydem::CR_NFIELD * sizeof(double);
  bytes += (double) contact_data.capacity() * sizeof(double);
  bytes += (double) (d_count.extent(0) + d_offset.extent(0) + 2 * d_pairs.extent(0)) * sizeof(int);
  bytes += shapes.memory_usage();
  return bytes;
}

/* ----------------------------------------------------------------------
   partner_views (polydem_history_kokkos.h): pointers to the private partner
   DualViews of FixNeighHistoryKokkos, taken through explicit instantiation,
   where the standard does not check access ([temp.spec]/6).
------------------------------------------------------------------------- */

namespace polydem_kk {
namespace {
  template <class Tag, typename Tag::type M> struct Expose {
    friend typename Tag::type member_of(Tag) { return M; }
  };
}    // namespace

// tags (one per member and type), their exposure, and partner_views<D>
#define POLYDEM_PARTNER_VIEWS(D, SUFFIX)                                                          \
  namespace {                                                                                     \
    struct Npartner##SUFFIX {                                                                     \
      typedef ArrayTypes<D>::tdual_int_1d FixNeighHistoryKokkos<D>::*type;                         \
      friend type member_of(Npartner##SUFFIX);                                                    \
    };                                                                                            \
    struct Partner##SUFFIX {                                                                      \
      typedef ArrayTypes<D>::tdual_tagint_2d FixNeighHistoryKokkos<D>::*type;                      \
      friend type member_of(Partner##SUFFIX);                                                     \
    };                                                                                            \
    struct Valuepartner##SUFFIX {                                                                 \
      typedef ArrayTypes<D>::tdual_float_2d FixNeighHistoryKokkos<D>::*type;                       \
      friend type member_of(Valuepartner##SUFFIX);                                                \
    };                                                                                            \
    template struct Expose<Npartner##SUFFIX, &FixNeighHistoryKokkos<D>::k_npartner>;              \
    template struct Expose<Partner##SUFFIX, &FixNeighHistoryKokkos<D>::k_partner>;                \
    template struct Expose<Valuepartner##SUFFIX, &FixNeighHistoryKokkos<D>::k_valuepartner>;      \
  }                                                                                               \
  template <> PartnerViews<D> partner_views<D>(FixNeighHistoryKokkos<D> * fix)                    \
  {                                                                                               \
    PartnerViews<D> v;                                                                            \
    v.npartner = &(fix->*member_of(Npartner##SUFFIX()));                                          \
    v.partner = &(fix->*member_of(Partner##SUFFIX()));                                            \
    v.valuepartner = &(fix->*member_of(Valuepartner##SUFFIX()));                                  \
    return v;                                                                                     \
  }

POLYDEM_PARTNER_VIEWS(LMPDeviceType, Device)
#ifdef LMP_KOKKOS_GPU
POLYDEM_PARTNER_VIEWS(LMPHostType, Host)
#endif
#undef POLYDEM_PARTNER_VIEWS
}    // namespace polydem_kk

namespace LAMMPS_NS {
template class PairPolyhedronKokkos<LMPDeviceType>;
#ifdef LMP_KOKKOS_GPU
template class PairPolyhedronKokkos<LMPHostType>;
#endif
}    // namespace LAMMPS_NS
