/* ----------------------------------------------------------------------
   POLYDEM - pair_style ellipsoid/kk
------------------------------------------------------------------------- */

#include "pair_ellipsoid_kokkos.h"

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

#include "polydem_ellipsoid_force.h"
#include "polydem_history_kokkos.h"
#include "polydem_tally_kokkos.h"
#include "polydem_kokkos_masks.h"
#include "polydem_shape_template.h"

using namespace LAMMPS_NS;

namespace {

typedef polydem_kk::PairReduce<PairEllipsoid::NCOUNT> EllReduce;

/* ----------------------------------------------------------------------
   one thread per list entry ii: the statements of PairEllipsoid::compute
   for all neighbors of i, with atomic accumulation
------------------------------------------------------------------------- */

template <class DeviceType> struct EllContactFunctor {
  typedef DeviceType device_type;
  typedef ArrayTypes<DeviceType> AT;
  typedef EllReduce value_type;

  typename AT::t_x_array_randomread x;
  typename AT::t_v_array_randomread v, omega;
  typename AT::t_f_array f, torque;
  typename AT::t_float_1d_randomread radius, rmass, pscale;
  typename AT::t_int_1d_randomread type, pshape;
  polydem_view_t<tdual_quat_array, DeviceType> quat;
  typename AT::t_int_1d_randomread ilist, numneigh;
  typename AT::t_neighbors_2d neighbors;
  Kokkos::View<double *[3], DeviceType> axes;
  Kokkos::View<double **, DeviceType> kn, mu;
  Kokkos::View<polydem::DampingLaw<double> **, DeviceType> damp;
  // friction (use_history): per-pair tangential displacement, stored as the
  // displacement of the lower-tag atom's point relative to the other's (the
  // Kokkos history fix copies it to the partner unchanged; see
  // pair_polyhedron_kokkos.cpp); partner counts at reneighboring
  typename AT::t_tagint_1d_randomread tag;
  typename AT::t_int_2d firsttouch;
  typename AT::t_float_2d firstshear;
  Kokkos::View<int *, DeviceType> npartner;
  int use_history, shearupdate, count_partners;
  double kt_ratio, gt_ratio;
  typename AT::t_efloat_1d eatom;
  typename AT::t_virial_array vatom;
  int nlocal, newton_pair, overlap, damping_mass;
  polydem_kk::TallyFlags tally;
  double dt, overlap_warn;

  KOKKOS_INLINE_FUNCTION polydem::EllipsoidPose<double> pose(int i) const
  {
    polydem::EllipsoidPose<double> p;
    const int t = pshape(i);
    const double s = pscale(i);
    p.x = polydem::make_vec3(x(i, 0), x(i, 1), x(i, 2));
    p.q = polydem::make_quat(quat(i, 0), quat(i, 1), quat(i, 2), quat(i, 3));
    p.axes = polydem::make_vec3(s * axes(t, 0), s * axes(t, 1), s * axes(t, 2));
    return p;
  }

  // no contact: the pair's tangential history ends
  KOKKOS_INLINE_FUNCTION void release(int i, int jj) const
  {
    if (!use_history) return;
    firsttouch(i, jj) = 0;
    for (int k = 0; k < 3; k++) firstshear(i, 3 * jj + k) = 0.0;
  }

  KOKKOS_INLINE_FUNCTION void operator()(const int ii, EllReduce &red) const
  {
    const int i = ilist(ii);
    const auto A = pose(i);
    const int jnum = numneigh(i);
    for (int jj = 0; jj < jnum; jj++) {
      const int j = neighbors(i, jj) & NEIGHMASK;
      if (count_partners) {
        Kokkos::atomic_increment(&npartner(i));
        if (j < nlocal) Kokkos::atomic_increment(&npartner(j));
      }
      const double delx = x(i, 0) - x(j, 0), dely = x(i, 1) - x(j, 1), delz = x(i, 2) - x(j, 2);
      const double radsum = radius(i) + radius(j);
      if (delx * delx + dely * dely + delz * delz >= radsum * radsum) {
        release(i, jj);
        continue;
      }
      const auto B = pose(j);
      const auto c = polydem::ellipsoid_contact(A, B);
      if (c.status != polydem::STATUS_OK) {
        if (c.status != polydem::STATUS_SEPARATED)
          red.cnt[c.status == polydem::STATUS_NO_CONVERGENCE ? PairEllipsoid::CNT_NOCONV
                                                             : PairEllipsoid::CNT_DEGENERATE] += 1.0;
        release(i, jj);
        continue;
      }
      const double w = (newton_pair || j < nlocal) ? 1.0 : 0.5;    // ghost pairs: 2 ranks
      red.cnt[PairEllipsoid::CNT_CONTACTS] += w;
      double amin = A.axes.x;
      const double ax[5] = {A.axes.y, A.axes.z, B.axes.x, B.axes.y, B.axes.z};
      for (int k = 0; k < 5; k++)
        if (ax[k] < amin) amin = ax[k];
      const int it = type(i), jt = type(j);
      const auto kin = polydem::make_kinematics(
          A.x, B.x, polydem::make_vec3(v(i, 0), v(i, 1), v(i, 2)),
          polydem::make_vec3(v(j, 0), v(j, 1), v(j, 2)),
          polydem::make_vec3(omega(i, 0), omega(i, 1), omega(i, 2)),
          polydem::make_vec3(omega(j, 0), omega(j, 1), omega(j, 2)),
          damping_mass == polydem::DAMPING_CONTACT
              ? polydem::ellipsoid_contact_mass(c, overlap, A, B, rmass(i), rmass(j))
              : rmass(i) * rmass(j) / (rmass(i) + rmass(j)),
          shearupdate ? dt : 0.0);
      const auto geo = polydem::ellipsoid_geometry(c, overlap, A.x, B.x);
      const auto law = polydem::ellipsoid_law(kn(it, jt), damp(it, jt),
                                              use_history ? mu(it, jt) : 0.0, kt_ratio, gt_ratio);
      // the history is that of the lower-tag atom (polydem_contact_law.h)
      if (use_history) firsttouch(i, jj) = 1;
      const auto cf = polydem::pair_contact_step(
          geo, law, kin, use_history ? &firstshear(i, 3 * jj) : nullptr, 3,
          use_history ? polydem::contact_history_sign(tag(i), tag(j)) : 1.0, shearupdate != 0);
      if (geo.volume > overlap_warn * amin) red.cnt[PairEllipsoid::CNT_BIGOVERLAP] += 1.0;
      if (geo.volume < cf.rate * dt) red.cnt[PairEllipsoid::CNT_COLLISIONS] += w;

      polydem_kk::scatter_contact(f, torque, i, j, newton_pair || j < nlocal, cf);
      const double F[3] = {cf.F_A.x, cf.F_A.y, cf.F_A.z};
      polydem_kk::ev_tally_xyz(red, tally, eatom, vatom, i, j, cf.energy, F, delx, dely, delz);
    }
  }
};

}    // namespace

/* ---------------------------------------------------------------------- */

template <class DeviceType>
PairEllipsoidKokkos<DeviceType>::PairEllipsoidKokkos(LAMMPS *lmp) :
    PairEllipsoid(lmp), avecKK(nullptr), shape_version(-1), params_dirty(1)
{
  kokkosable = 1;
  atomKK = (AtomKokkos *) atom;
  execution_space = ExecutionSpaceFromDevice<DeviceType>::space;
  datamask_read = X_MASK | V_MASK | OMEGA_MASK | F_MASK | TORQUE_MASK | TYPE_MASK | MASK_MASK | TAG_MASK |
      ENERGY_MASK | VIRIAL_MASK | RMASS_MASK | RADIUS_MASK | POLYDEM_ALL_MASK;
  datamask_modify = F_MASK | TORQUE_MASK | ENERGY_MASK | VIRIAL_MASK;
}

template <class DeviceType> PairEllipsoidKokkos<DeviceType>::~PairEllipsoidKokkos()
{
  if (copymode) return;
  memoryKK->destroy_kokkos(k_eatom, eatom);
  memoryKK->destroy_kokkos(k_vatom, vatom);
  eatom = nullptr;
  vatom = nullptr;
}

/* ----------------------------------------------------------------------
   the plain init_style (checks, size request) made a Kokkos half list
------------------------------------------------------------------------- */

template <class DeviceType> void PairEllipsoidKokkos<DeviceType>::init_style()
{
  avecKK = AtomVecPolyhedronKokkos::of(atom);
  if (!avecKK) error->all(FLERR, "pair_style ellipsoid/kk requires atom_style polyhedron/kk");
  // as pair polyhedron/kk: forces on ghosts are not reverse-communicated here
  if (force->newton_pair)
    error->all(FLERR,
               "pair_style ellipsoid/kk requires newton pair off: use "
               "'-pk kokkos newton off' or 'package kokkos newton off' (default on GPUs)");
  // friction: the Kokkos history fix takes the placeholder's place before
  // the plain init_style (which would otherwise create a plain one)
  if (friction_used() && fix_history == nullptr) {
    fix_history = polydem_kk::create_history_fix<DeviceType>(
        modify, "NEIGH_HISTORY_ELL" + std::to_string(history_id),
        "NEIGH_HISTORY_ELL_DUMMY" + std::to_string(history_id), 3, execution_space == Device);
    fix_history->pair = this;
  }
  PairEllipsoid::init_style();
  polydem_compat::request_kokkos_half_list(
      neighbor, this,
      std::is_same<DeviceType, LMPHostType>::value &&
          !std::is_same<DeviceType, LMPDeviceType>::value,
      std::is_same<DeviceType, LMPDeviceType>::value);
  params_dirty = 1;
}

/* ----------------------------------------------------------------------
   semi-axes of all templates and the per-type-pair coefficients on the device
------------------------------------------------------------------------- */

template <class DeviceType> void PairEllipsoidKokkos<DeviceType>::update_device_data()
{
  if (shape_version != avec->shape_version()) {
    const PolyShapeLibrary *av = avec;
    const int n = av->ntemplates();
    d_axes = Kokkos::View<double *[3], DeviceType>("ellipsoid/kk:axes", n > 0 ? n : 1);
    auto h = Kokkos::create_mirror_view(d_axes);
    for (int t = 0; t < n; t++)
      for (int k = 0; k < 3; k++) h(t, k) = av->shape(t).semi_axes()[k];
    Kokkos::deep_copy(d_axes, h);
    shape_version = av->shape_version();
  }
  if (params_dirty) {
    const int n = atom->ntypes;
    d_kn = Kokkos::View<double **, DeviceType>("ellipsoid/kk:kn", n + 1, n + 1);
    d_damp = Kokkos::View<polydem::DampingLaw<double> **, DeviceType>("ellipsoid/kk:damp", n + 1,
                                                                     n + 1);
    d_mu = Kokkos::View<double **, DeviceType>("ellipsoid/kk:mu", n + 1, n + 1);
    auto hm = Kokkos::create_mirror_view(d_mu);
    auto hk = Kokkos::create_mirror_view(d_kn);
    auto hd = Kokkos::create_mirror_view(d_damp);
    for (int i = 1; i <= n; i++)
      for (int j = 1; j <= n; j++) {
        hk(i, j) = kn[i][j];
        hd(i, j) = damping[i * (n + 1) + j];
        hm(i, j) = friction[i][j];
      }
    Kokkos::deep_copy(d_kn, hk);
    Kokkos::deep_copy(d_damp, hd);
    Kokkos::deep_copy(d_mu, hm);
    params_dirty = 0;
  }
}

/* ---------------------------------------------------------------------- */

template <class DeviceType> void PairEllipsoidKokkos<DeviceType>::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag, 0);
  if (eflag_atom) {
    memoryKK->destroy_kokkos(k_eatom, eatom);
    memoryKK->create_kokkos(k_eatom, eatom, maxeatom, "pair:eatom");
  }
  if (vflag_atom) {
    memoryKK->destroy_kokkos(k_vatom, vatom);
    memoryKK->create_kokkos(k_vatom, vatom, maxvatom, "pair:vatom");
  }
  update_device_data();

  atomKK->sync(execution_space, datamask_read);
  if (eflag || vflag)
    atomKK->modified(execution_space, datamask_modify);
  else
    atomKK->modified(execution_space, F_MASK | TORQUE_MASK);

  auto *k_list = static_cast<NeighListKokkos<DeviceType> *>(list);
  EllContactFunctor<DeviceType> fn;
  fn.x = atomKK->k_x.view<DeviceType>();
  fn.v = atomKK->k_v.view<DeviceType>();
  fn.omega = atomKK->k_omega.view<DeviceType>();
  fn.f = atomKK->k_f.view<DeviceType>();
  fn.torque = atomKK->k_torque.view<DeviceType>();
  fn.radius = atomKK->k_radius.view<DeviceType>();
  fn.rmass = atomKK->k_rmass.view<DeviceType>();
  fn.pscale = avecKK->k_pscale.view<DeviceType>();
  fn.type = atomKK->k_type.view<DeviceType>();
  fn.pshape = avecKK->k_pshape.view<DeviceType>();
  fn.quat = avecKK->k_quat.view<DeviceType>();
  fn.ilist = k_list->d_ilist;
  fn.numneigh = k_list->d_numneigh;
  fn.neighbors = k_list->d_neighbors;
  fn.axes = d_axes;
  fn.kn = d_kn;
  fn.damp = d_damp;
  fn.mu = d_mu;
  fn.use_history = use_history;
  fn.kt_ratio = kt_ratio;
  fn.gt_ratio = gt_ratio;
  fn.shearupdate = update->setupflag ? 0 : 1;
  fn.count_partners = 0;
  const int nlocal = atom->nlocal;
  if (use_history) {
    auto *fh = (FixNeighHistoryKokkos<DeviceType> *) fix_history;
    fh->k_firstflag.template sync<DeviceType>();    // read and written on the device below
    fh->k_firstvalue.template sync<DeviceType>();
    fn.tag = atomKK->k_tag.view<DeviceType>();
    fn.firsttouch = fh->k_firstflag.template view<DeviceType>();
    fn.firstshear = fh->k_firstvalue.template view<DeviceType>();
    fn.count_partners = neighbor->ago == 0;
    if (fn.count_partners) {
      if ((int) d_npartner.extent(0) < nlocal)
        d_npartner = Kokkos::View<int *, DeviceType>("ellipsoid/kk:npartner", atom->nmax);
      Kokkos::deep_copy(d_npartner, 0);
    }
    fn.npartner = d_npartner;
  }
  if (eflag_atom) fn.eatom = k_eatom.template view<DeviceType>();
  if (vflag_atom) fn.vatom = k_vatom.template view<DeviceType>();
  fn.nlocal = atom->nlocal;
  fn.newton_pair = force->newton_pair;
  fn.overlap = overlap;
  fn.damping_mass = damping_mass;
  fn.tally = {atom->nlocal, force->newton_pair, eflag_global, eflag_atom, vflag_global,
              vflag_atom};
  fn.dt = update->dt;
  fn.overlap_warn = overlap_warn;

  EllReduce red;
  Kokkos::parallel_reduce(
      Kokkos::RangePolicy<typename DeviceType::execution_space>(0, list->inum), fn, red);
  if (use_history) {
    auto *fh = (FixNeighHistoryKokkos<DeviceType> *) fix_history;
    fh->k_firstflag.template modify<DeviceType>();
    fh->k_firstvalue.template modify<DeviceType>();
  }
  if (fn.count_partners)
    polydem_kk::ensure_partners<DeviceType>(fix_history, d_npartner, nlocal, atom->nmax, world);
  polydem_kk::add_reduced(this, fn.tally, red, local_counts, NCOUNT);

  if (eflag_atom) {
    k_eatom.template modify<DeviceType>();
    k_eatom.template sync<LMPHostType>();
  }
  if (vflag_atom) {
    k_vatom.template modify<DeviceType>();
    k_vatom.template sync<LMPHostType>();
  }
  pvector[0] = local_counts[CNT_COLLISIONS];
  pvector[1] = local_counts[CNT_CONTACTS];
  if (neighbor->ago == 0) report_counters();
}

namespace LAMMPS_NS {
template class PairEllipsoidKokkos<LMPDeviceType>;
#ifdef LMP_KOKKOS_GPU
template class PairEllipsoidKokkos<LMPHostType>;
#endif
}    // namespace LAMMPS_NS
