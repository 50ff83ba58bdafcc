/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - per-pair contact history for the Kokkos pair styles
   (pair_style polyhedron/kk, ellipsoid/kk): a FixNeighHistoryKokkos with
   working copy_arrays and restart, registered at run time, and the
   partner-capacity bookkeeping its LAMMPS 29Sep2021 version needs.
------------------------------------------------------------------------- */

#ifndef POLYDEM_HISTORY_KOKKOS_H
#define POLYDEM_HISTORY_KOKKOS_H

#include "atom.h"
#include "atom_kokkos.h"
#include "atom_masks.h"
#include "fix_neigh_history_kokkos.h"
#include "modify.h"
#include "neigh_list_kokkos.h"
#include "polydem_history.h"
#include "polydem_lammps_compat.h"

#include "error.h"
#include "force.h"

#include <mpi.h>

#include <algorithm>
#include <string>
#include <tuple>
#include <vector>

namespace polydem_kk {

using namespace LAMMPS_NS;

template <class DeviceType> struct HistoryMaxFunctor {
  typedef DeviceType device_type;
  typedef int value_type;
  Kokkos::View<int *, DeviceType> npartner;
  KOKKOS_INLINE_FUNCTION void operator()(const int i, int &m) const
  {
    if (npartner(i) > m) m = npartner(i);
  }
#if defined(KOKKOS_VERSION) && KOKKOS_VERSION >= 40000
  KOKKOS_INLINE_FUNCTION void join(int &dst, const int &src) const
  {
    if (src > dst) dst = src;
  }
#else
  // Kokkos 3 joins through volatile references (Kokkos 4 rejects this form)
  KOKKOS_INLINE_FUNCTION void join(volatile int &dst, const volatile int &src) const
  {
    if (src > dst) dst = src;
  }
#endif
  KOKKOS_INLINE_FUNCTION void init(int &m) const { m = 0; }
};

// What a functor over a size neighbor list reads: the list, and the atoms'
// positions and bounding radii on DeviceType (the caller syncs X_MASK |
// RADIUS_MASK before bind)
template <class DeviceType> struct SizeListViews {
  typedef ArrayTypes<DeviceType> AT;
  typename AT::t_x_array_randomread x;
  typename AT::t_float_1d_randomread radius;
  typename AT::t_int_1d_randomread ilist, numneigh;
  typename AT::t_neighbors_2d neighbors;
  void bind(NeighListKokkos<DeviceType> *list, AtomKokkos *akk)
  {
    x = akk->k_x.template view<DeviceType>();
    radius = akk->k_radius.template view<DeviceType>();
    ilist = list->d_ilist;
    numneigh = list->d_numneigh;
    neighbors = list->d_neighbors;
  }
};

// Marks the pairs of a size neighbor list within their bounding radii plus
// reach as history pairs (the bits LAMMPS's size lists set within the radii
// alone), so that FixNeighHistoryKokkos keeps their flags and values: the
// liquid bridges of separated spheres (its beyond_contact switch is newer
// than some LAMMPS versions supported).
template <class DeviceType> struct BridgeReachMarkFunctor {
  typedef DeviceType device_type;
  SizeListViews<DeviceType> nl;
  double reach;
  KOKKOS_INLINE_FUNCTION void operator()(const int ii) const
  {
    const int i = nl.ilist(ii);
    const int n = nl.numneigh(i);
    for (int jj = 0; jj < n; jj++) {
      const int j = nl.neighbors(i, jj) & NEIGHMASK;
      const double dx = nl.x(i, 0) - nl.x(j, 0), dy = nl.x(i, 1) - nl.x(j, 1),
                   dz = nl.x(i, 2) - nl.x(j, 2);
      const double rs = nl.radius(i) + nl.radius(j) + reach;
      if (dx * dx + dy * dy + dz * dz < rs * rs) nl.neighbors(i, jj) = j | (3 << SBBITS);
    }
  }
};

// The partner DualViews of a FixNeighHistoryKokkos (private there): defined
// in pair_polyhedron_kokkos.cpp, which instantiates it for the LAMMPS device
// and host types.
template <class DeviceType> struct PartnerViews {
  typename ArrayTypes<DeviceType>::tdual_int_1d *npartner;
  typename ArrayTypes<DeviceType>::tdual_tagint_2d *partner;
  typename ArrayTypes<DeviceType>::tdual_float_2d *valuepartner;
  // the three DualViews' sync / modify on Space
  template <class Space> void sync() const
  {
    npartner->template sync<Space>();
    partner->template sync<Space>();
    valuepartner->template sync<Space>();
  }
  template <class Space> void modify() const
  {
    npartner->template modify<Space>();
    partner->template modify<Space>();
    valuepartner->template modify<Space>();
  }
};
template <class DeviceType>
PartnerViews<DeviceType> partner_views(FixNeighHistoryKokkos<DeviceType> *fix);
template <>
PartnerViews<LMPDeviceType> partner_views<LMPDeviceType>(FixNeighHistoryKokkos<LMPDeviceType> *fix);
#ifdef LMP_KOKKOS_GPU
template <>
PartnerViews<LMPHostType> partner_views<LMPHostType>(FixNeighHistoryKokkos<LMPHostType> *fix);
#endif

/* ----------------------------------------------------------------------
   FixNeighHistoryKokkos of LAMMPS 29Sep2021 with a complete copy_arrays:
   the original copies one value per partner instead of dnum, which loses
   the history whenever atoms are sorted or leave a rank (AtomVec::copy),
   and the restart write of polydem_history.h (none between runs).
   Registered at run time under its own name (no style file needed).
------------------------------------------------------------------------- */

template <class DeviceType>
class FixNeighHistoryPolyhedronKokkos :
    public polydem_history::RestartBetweenRuns<FixNeighHistoryKokkos<DeviceType>> {
 public:
  // Restart files name it NEIGH_HISTORY, as the plain styles' fix: its
  // per-atom record is theirs (unpack_restart below), and Modify hands a
  // file's record only to a fix of the same ID and style, so under its
  // registered name a /kk run read from a plain run's restart file started
  // without its contact history.
  FixNeighHistoryPolyhedronKokkos(LAMMPS *lmp, int narg, char **arg) :
      polydem_history::RestartBetweenRuns<FixNeighHistoryKokkos<DeviceType>>(lmp, narg, arg)
  {
    delete[] this->style;
    this->style = utils::strdup("NEIGH_HISTORY");
  }
  // The base class writes the partner arrays on the device in pre_exchange
  // and reads them there in post_neighbor without marking or syncing its
  // DualViews. On the Serial backend host and device are one; on a GPU the
  // host copy used by exchange, sorting and restart went stale, and restart
  // data never reached the device.
  void pre_exchange() override
  {
    if (this->force->newton_pair) {
      pre_exchange_newton();
      return;
    }
    FixNeighHistoryKokkos<DeviceType>::pre_exchange();
    partner_views<DeviceType>(this).template modify<DeviceType>();
  }
  void post_neighbor() override
  {
    partner_views<DeviceType>(this).template sync<DeviceType>();
    if (reach > 0.0) {
      auto *list = static_cast<NeighListKokkos<DeviceType> *>(this->pair->list);
      AtomKokkos *akk = (AtomKokkos *) this->atom;
      akk->sync(ExecutionSpaceFromDevice<DeviceType>::space, X_MASK | RADIUS_MASK);
      BridgeReachMarkFunctor<DeviceType> m;
      m.nl.bind(list, akk);
      m.reach = reach;
      Kokkos::parallel_for(list->inum, m);
    }
    FixNeighHistoryKokkos<DeviceType>::post_neighbor();
  }
  // the pair style's largest liquid-bridge rupture distance (0: none)
  double reach = 0.0;

  /* --------------------------------------------------------------------
     newton pair on (the base class refuses it): a pair with a ghost atom
     is in the list of one rank only, so its history goes to the ghost's
     owner by reverse communication, as FixNeighHistory::pre_exchange_newton
     does for the plain styles. On the host (once per reneighboring): the
     entries of each atom counted, local and ghost, the ghosts' counts
     added to their owners; the row capacity raised on all ranks to the
     largest count; the rows filled; the ghosts' rows appended to their
     owners'. The values are the lower-tag atom's for both partners
     (PairPolydem::transfer_history copies them unchanged).
  -------------------------------------------------------------------- */
  void pre_exchange_newton()
  {
    const PartnerViews<DeviceType> v = partner_views<DeviceType>(this);
    AtomKokkos *akk = (AtomKokkos *) this->atom;
    akk->sync(Host, TAG_MASK);
    this->k_firstflag.template sync<LMPHostType>();
    this->k_firstvalue.template sync<LMPHostType>();
    v.template sync<LMPHostType>();
    auto *list = static_cast<NeighListKokkos<DeviceType> *>(this->pair->list);
    const int inum = list->inum;
    const auto ilist = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), list->d_ilist);
    const auto numneigh =
        Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), list->d_numneigh);
    const auto neighbors =
        Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), list->d_neighbors);
    const auto flag = this->k_firstflag.template view<LMPHostType>();
    const auto value = this->k_firstvalue.template view<LMPHostType>();
    const tagint *tag = this->atom->tag;
    const int nall = this->atom->nlocal + this->atom->nghost;
    const int dnum = this->dnum;

    // counts: this rank's entries of each atom, then the ghosts' added
    auto np = v.npartner->template view<LMPHostType>();
    for (int i = 0; i < nall; i++) np(i) = 0;
    for (int ii = 0; ii < inum; ii++) {
      const int i = ilist(ii);
      for (int jj = 0; jj < numneigh(i); jj++)
        if (flag(i, jj)) {
          np(i)++;
          np(neighbors(i, jj) & NEIGHMASK)++;
        }
    }
    // (the fixed-size call also brings CommKokkos's send lists to the host,
    // which the variable one below reads unsynced in LAMMPS 29Sep2021)
    rcomm = RCOMM_COUNT;
    polydem_compat::reverse_comm_fix(this->comm, this, 1);
    int most = 0, all = 0;
    for (int i = 0; i < this->atom->nlocal; i++) most = std::max(most, np(i));
    most = std::max(most, this->maxpartner);
    MPI_Allreduce(&most, &all, 1, MPI_INT, MPI_MAX, this->world);
    if (all > this->maxpartner) {
      this->maxpartner = all + 8;
      grow_arrays(this->atom->nmax);
      np = v.npartner->template view<LMPHostType>();
    }

    // the rows of local and ghost atoms, then the ghosts' to their owners
    auto partner = v.partner->template view<LMPHostType>();
    auto vp = v.valuepartner->template view<LMPHostType>();
    for (int i = 0; i < nall; i++) np(i) = 0;
    auto add = [&](int a, tagint other, int i, int jj) {
      const int m = np(a)++;
      if (m >= this->maxpartner)
        this->error->one(FLERR, "pair history: partner row of atom {} overflows", tag[a]);
      partner(a, m) = other;
      for (int k = 0; k < dnum; k++) vp(a, dnum * m + k) = value(i, dnum * jj + k);
    };
    for (int ii = 0; ii < inum; ii++) {
      const int i = ilist(ii);
      for (int jj = 0; jj < numneigh(i); jj++)
        if (flag(i, jj)) {
          const int j = neighbors(i, jj) & NEIGHMASK;
          add(i, tag[j], i, jj);
          add(j, tag[i], i, jj);
        }
    }
    rcomm = RCOMM_ROWS;
    polydem_compat::reverse_comm_fix_variable(this->comm, this);
    rcomm = RCOMM_NONE;

    v.template modify<LMPHostType>();
    v.template sync<DeviceType>();
    this->maxexchange = (dnum + 1) * this->maxpartner + 1;
  }

  // reverse communication of pre_exchange_newton: the counts, or the rows
  int pack_reverse_comm_size(int n, int first) override
  {
    const auto np = partner_views<DeviceType>(this).npartner->template view<LMPHostType>();
    int m = 0;
    for (int i = first; i < first + n; i++) m += 1 + (this->dnum + 1) * np(i);
    return m;
  }
  // the host views of the rows: counts, partner tags, values
  auto host_rows()
  {
    const PartnerViews<DeviceType> v = partner_views<DeviceType>(this);
    return std::make_tuple(v.npartner->template view<LMPHostType>(),
                           v.partner->template view<LMPHostType>(),
                           v.valuepartner->template view<LMPHostType>());
  }
  int pack_reverse_comm(int n, int first, double *buf) override
  {
    const auto [np, partner, vp] = host_rows();
    const int dnum = this->dnum;
    int m = 0;
    for (int i = first; i < first + n; i++) {
      buf[m++] = np(i);
      if (rcomm != RCOMM_ROWS) continue;
      for (int k = 0; k < np(i); k++) {
        buf[m++] = (double) partner(i, k);
        for (int d = 0; d < dnum; d++) buf[m++] = vp(i, dnum * k + d);
      }
    }
    return m;
  }
  void unpack_reverse_comm(int n, int *list, double *buf) override
  {
    const auto [np, partner, vp] = host_rows();
    const int dnum = this->dnum;
    int m = 0;
    for (int i = 0; i < n; i++) {
      const int j = list[i];
      const int c = static_cast<int>(buf[m++]);
      if (rcomm != RCOMM_ROWS) {
        np(j) += c;
        continue;
      }
      for (int k = 0; k < c; k++) {
        const int slot = np(j)++;
        if (slot >= this->maxpartner)
          this->error->one(FLERR, "pair history: partner row of atom {} overflows",
                           this->atom->tag[j]);
        partner(j, slot) = static_cast<tagint>(buf[m++]);
        for (int d = 0; d < dnum; d++) vp(j, dnum * slot + d) = buf[m++];
      }
    }
  }

 private:
  enum { RCOMM_NONE, RCOMM_COUNT, RCOMM_ROWS };
  int rcomm = RCOMM_NONE;

 public:
  // DualView::resize keeps the side marked newer. After the base's sync both
  // are equal, so it keeps the device rows with a fresh host copy, which the
  // base then marks modified. Mark the synced host newer first, so that the
  // host rows (current) are kept and reach the device at the next sync.
  void grow_arrays(int nmax) override
  {
    if (this->npartner) {
      const PartnerViews<DeviceType> v = partner_views<DeviceType>(this);
      v.template sync<LMPHostType>();
      v.template modify<LMPHostType>();
    }
    FixNeighHistoryKokkos<DeviceType>::grow_arrays(nmax);
  }
  void copy_arrays(int i, int j, int delflag) override
  {
    // syncs the host arrays, copies the partner IDs, marks the host modified
    FixNeighHistoryKokkos<DeviceType>::copy_arrays(i, j, delflag);
    for (int m = 0; m < this->dnum * this->npartner[i]; m++)
      this->valuepartner[j][m] = this->valuepartner[i][m];
  }
  // Restart: FixNeighHistory::unpack_restart puts the partners into its
  // host page allocator, which the Kokkos fix does not use (its rows are
  // DualView rows), so a /kk run lost its contact history on read_restart.
  // Reorder the restart record (n, then tag + dnum values per partner) into
  // the exchange layout (n, n tags, n * dnum values) and unpack it as the
  // Kokkos fix unpacks exchanged atoms (host rows, marked modified).
  void unpack_restart(int nlocal, int nth) override
  {
    double **extra = this->atom->extra;
    const int dnum = this->dnum;
    int m = 0;
    for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
    m++;
    const int n = static_cast<int>(extra[nlocal][m++]);
    if (n > this->maxpartner) {
      this->maxpartner = n + 8;    // made equal on all ranks by ensure_partners
      this->grow_arrays(this->atom->nmax);
    }
    std::vector<double> buf(1 + (size_t) n * (1 + dnum));
    buf[0] = n;
    for (int k = 0; k < n; k++) {
      const double *rec = &extra[nlocal][m + k * (1 + dnum)];
      buf[1 + k] = rec[0];
      for (int d = 0; d < dnum; d++) buf[1 + n + dnum * k + d] = rec[1 + d];
    }
    this->unpack_exchange(nlocal, buf.data());
  }
  static Fix *create(LAMMPS *lmp, int narg, char **arg)
  {
    return new FixNeighHistoryPolyhedronKokkos<DeviceType>(lmp, narg, arg);
  }
};

// the protected partner capacity of FixNeighHistory (see ensure_partners)
struct HistoryAccess : public FixNeighHistory {
  static int &capacity(FixNeighHistory *f) { return f->*(&HistoryAccess::maxpartner); }
};

/* ----------------------------------------------------------------------
   FixNeighHistoryKokkos of LAMMPS 29Sep2021 grows its partner arrays in
   pre_exchange without refreshing the device views it writes through
   (out-of-bounds writes, lost history), and its rows have a fixed
   capacity that unpack_exchange assumes equal on all ranks. Keep one
   capacity on all ranks, above the number of list entries of every local
   atom (npartner, counted at reneighboring), set at each reneighboring
   (collective: all ranks reneighbor together); grow_arrays() reallocates
   and refreshes the views.
------------------------------------------------------------------------- */

template <class DeviceType>
void ensure_partners(FixNeighHistory *fix, const Kokkos::View<int *, DeviceType> &npartner,
                     int nlocal, int nmax, MPI_Comm world)
{
  HistoryMaxFunctor<DeviceType> fmax;
  fmax.npartner = npartner;
  int mine = 0, most = 0, allcap = 0;
  Kokkos::parallel_reduce(Kokkos::RangePolicy<typename DeviceType::execution_space>(0, nlocal),
                          fmax, mine);
  MPI_Allreduce(&mine, &most, 1, MPI_INT, MPI_MAX, world);
  int &cap = HistoryAccess::capacity(fix);
  // a rank may have grown alone (unpack_restart): take the largest capacity
  MPI_Allreduce(&cap, &allcap, 1, MPI_INT, MPI_MAX, world);
  const int want = most > allcap ? most + 8 : allcap;
  if (want != cap) {
    cap = want;
    fix->grow_arrays(nmax);
  }
}

// Before the kernel that counts the list entries of each local atom: the
// counts zeroed, the View grown to nmax where it holds fewer than nlocal.
template <class DeviceType>
void reset_partners(Kokkos::View<int *, DeviceType> &npartner, int nlocal, int nmax,
                    const char *label)
{
  if ((int) npartner.extent(0) < nlocal)
    npartner = Kokkos::View<int *, DeviceType>(std::string(label), nmax);
  Kokkos::deep_copy(npartner, 0);
}

// Replaces the pair style's placeholder fix dummy_id by the Kokkos history
// fix id with nvalues per pair (registered under a run-time style name).
template <class DeviceType>
FixNeighHistory *create_history_fix(Modify *modify, const std::string &id,
                                    const std::string &dummy_id, int nvalues, bool device)
{
  const std::string style = std::string("NEIGH_HISTORY/POLYHEDRON/KK/") + (device ? "DEVICE" : "HOST");
  (*modify->fix_map)[style] = &FixNeighHistoryPolyhedronKokkos<DeviceType>::create;
  const std::string cmd = id + " all " + style + " " + std::to_string(nvalues);
  return (FixNeighHistory *) modify->replace_fix(dummy_id, cmd, 1);
}

}    // namespace polydem_kk

#endif
