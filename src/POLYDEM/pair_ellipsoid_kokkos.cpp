/* ----------------------------------------------------------------------
   POLYDEM - pair_style ellipsoid/kk
------------------------------------------------------------------------- */

#include "pair_ellipsoid_kokkos.h"
#include "pair_polydem_kokkos.h"

#include "atom_kokkos.h"
#include "atom_masks.h"
#include "atom_vec_polyhedron_kokkos.h"
#include "comm.h"
#include "error.h"
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
#include "polydem_history_kokkos.h"
#include "polydem_kokkos_masks.h"
#include "polydem_law_table_kokkos.h"
#include "polydem_shape_template.h"
#include "polydem_tally_kokkos.h"

using namespace LAMMPS_NS;

namespace {

typedef polydem_kk::PairReduce<PairEllipsoid::NCOUNT> EllReduce;

/* ----------------------------------------------------------------------
   one thread per list entry ii, as PairEllipsoid::compute: gather, the
   pipeline's ellipsoid_pair_contact, scatter with atomics
------------------------------------------------------------------------- */

template <class DeviceType> struct EllContactFunctor : PolyBodyViews<DeviceType> {
  typedef DeviceType device_type;
  typedef ArrayTypes<DeviceType> AT;
  typedef EllReduce value_type;

  typename AT::t_float_1d_randomread radius;
  typename AT::t_int_1d_randomread ilist, numneigh;
  typename AT::t_neighbors_2d neighbors;
  Kokkos::View<double *[3], DeviceType> axes;
  polydem::LawTable<double> laws;    // entries on the device
  // friction (use_history): per-pair history in the pair convention (the
  // Kokkos history fix copies it to the partner unchanged; see
  // pair_polyhedron_kokkos.cpp); partner counts at reneighboring
  typename AT::t_int_2d firsttouch;
  typename AT::t_float_2d firstshear;
  Kokkos::View<int *, DeviceType> npartner;
  int use_history, shearupdate, count_partners;
  typename AT::t_efloat_1d eatom;
  typename AT::t_virial_array vatom;
  int nlocal, newton_pair;
  int atomic;    // scatter with atomics (polydem_kk::needs_atomics)
  polydem_kk::TallyFlags tally;
  double dt;

  // gather: atom k with its template's semi-axes
  KOKKOS_INLINE_FUNCTION polydem::EllipsoidBody<double> body(int k) const
  {
    const int t = this->pshape(k);
    return polydem::gather_ellipsoid_body(*this, k,
                                          polydem::make_vec3(axes(t, 0), axes(t, 1), axes(t, 2)));
  }

  KOKKOS_INLINE_FUNCTION void operator()(const int ii, EllReduce &red) const
  {
    const int i = ilist(ii);
    const auto A = body(i);
    const int jnum = numneigh(i);
    for (int jj = 0; jj < jnum; jj++) {
      const int j = neighbors(i, jj) & NEIGHMASK;
      if (count_partners) {
        Kokkos::atomic_increment(&npartner(i));
        if (j < nlocal) Kokkos::atomic_increment(&npartner(j));
      }
      double *shear = use_history ? &firstshear(i, laws.nhist * jj) : nullptr;
      const auto &x = this->x;
      const double delx = x(i, 0) - x(j, 0), dely = x(i, 1) - x(j, 1), delz = x(i, 2) - x(j, 2);
      const double radsum = radius(i) + radius(j);
      const bool to_j = newton_pair || j < nlocal;    // else the pair is seen on 2 ranks
      polydem::PairContactResult<double> c;
      c.contact = 0;
      if (delx * delx + dely * dely + delz * delz >= radsum * radsum)
        polydem::history_release(shear, laws.nhist);
      else
        c = polydem::ellipsoid_pair_contact(A, body(j), laws, dt, shearupdate != 0, shear,
                                            to_j ? 1.0 : 0.5, red.cnt);
      if (use_history) firsttouch(i, jj) = c.contact;
      if (!c.contact) continue;
      polydem_kk::scatter_contact(this->f, this->torque, i, j, to_j, c.cf, atomic != 0);
      const double F[3] = {c.cf.F_A.x, c.cf.F_A.y, c.cf.F_A.z};
      polydem_kk::ev_tally_xyz(red, tally, eatom, vatom, i, j, c.cf.energy, F, delx, dely, delz);
    }
  }
};

}    // namespace

/* ---------------------------------------------------------------------- */

template <class DeviceType>
PairEllipsoidKokkos<DeviceType>::PairEllipsoidKokkos(LAMMPS *lmp) :
    PairEllipsoid(lmp), avecKK(nullptr), params_dirty(1)
{
  kk_construct<DeviceType>();
}

template <class DeviceType> PairEllipsoidKokkos<DeviceType>::~PairEllipsoidKokkos()
{
  if (copymode) return;
  kk_destroy_tallies(k_eatom, k_vatom);
}

/* ----------------------------------------------------------------------
   the plain init_style (checks, size request) made a Kokkos half list
------------------------------------------------------------------------- */

template <class DeviceType> void PairEllipsoidKokkos<DeviceType>::init_style()
{
  avecKK = kk_init_before<DeviceType>(friction_used() || rolling_used());
  PairEllipsoid::init_style();
  kk_init_after<DeviceType>();
  params_dirty = 1;
}

/* ----------------------------------------------------------------------
   semi-axes of all templates and the per-type-pair coefficients on the device
------------------------------------------------------------------------- */

template <class DeviceType> void PairEllipsoidKokkos<DeviceType>::update_device_data()
{
  shapes.update(*avec, false, "ellipsoid/kk");    // the semi-axes are what it uses
  if (params_dirty) {
    d_laws_table = polydem_kk::mirror_law_table<DeviceType>(laws, d_laws);
    params_dirty = 0;
  }
}

/* ---------------------------------------------------------------------- */

template <class DeviceType> void PairEllipsoidKokkos<DeviceType>::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag, 0);
  kk_tally_views(k_eatom, k_vatom);
  update_device_data();

  kk_sync_atoms(eflag, vflag);

  auto *k_list = static_cast<NeighListKokkos<DeviceType> *>(list);
  EllContactFunctor<DeviceType> fn;
  fn.bind_bodies(atomKK, avecKK);
  fn.radius = atomKK->k_radius.view<DeviceType>();
  fn.ilist = k_list->d_ilist;
  fn.numneigh = k_list->d_numneigh;
  fn.neighbors = k_list->d_neighbors;
  fn.axes = shapes.axes;
  fn.laws = d_laws_table;
  fn.use_history = use_history;
  fn.shearupdate = update->setupflag ? 0 : 1;
  fn.count_partners = 0;
  const int nlocal = atom->nlocal;
  if (use_history) {
    auto *fh = (FixNeighHistoryKokkos<DeviceType> *) fix_history;
    fh->k_firstflag.template sync<DeviceType>();    // read and written on the device below
    fh->k_firstvalue.template sync<DeviceType>();
    fn.firsttouch = fh->k_firstflag.template view<DeviceType>();
    fn.firstshear = fh->k_firstvalue.template view<DeviceType>();
    fn.count_partners = neighbor->ago == 0;
    if (fn.count_partners)
      polydem_kk::reset_partners(d_npartner, nlocal, atom->nmax, "ellipsoid/kk:npartner");
    fn.npartner = d_npartner;
  }
  if (eflag_atom) fn.eatom = k_eatom.template view<DeviceType>();
  if (vflag_atom) fn.vatom = k_vatom.template view<DeviceType>();
  fn.nlocal = atom->nlocal;
  fn.newton_pair = force->newton_pair;
  fn.atomic = polydem_kk::needs_atomics<typename DeviceType::execution_space>() ? 1 : 0;
  fn.tally = {atom->nlocal, force->newton_pair, eflag_global, eflag_atom, vflag_global,
              vflag_atom};
  fn.dt = update->dt;

  EllReduce red;
  polydem_kk::reduce_range<typename DeviceType::execution_space>(0, list->inum, fn, red);
  if (use_history) {
    auto *fh = (FixNeighHistoryKokkos<DeviceType> *) fix_history;
    fh->k_firstflag.template modify<DeviceType>();
    fh->k_firstvalue.template modify<DeviceType>();
  }
  if (fn.count_partners)
    polydem_kk::ensure_partners<DeviceType>(fix_history, d_npartner, nlocal, atom->nmax, world);
  polydem_kk::add_reduced(this, fn.tally, red, local_counts, NCOUNT);

  kk_tally_to_host<DeviceType>(k_eatom, k_vatom);
  pvector[0] = local_counts[polydem::EP_COLLISIONS];
  pvector[1] = local_counts[polydem::EP_CONTACTS];
  if (counters_due()) report_counters();
}

namespace LAMMPS_NS {
template class PairEllipsoidKokkos<LMPDeviceType>;
#ifdef LMP_KOKKOS_GPU
template class PairEllipsoidKokkos<LMPHostType>;
#endif
}    // namespace LAMMPS_NS
