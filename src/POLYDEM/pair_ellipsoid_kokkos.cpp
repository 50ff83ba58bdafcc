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
#include "neigh_list_kokkos.h"
#include "neigh_request.h"
#include "neighbor.h"
#include "update.h"

#include "polydem_ellipsoid_force.h"
#include "polydem_kokkos_masks.h"
#include "polydem_shape_template.h"

using namespace LAMMPS_NS;

namespace {

struct EllReduce {
  double evdwl;
  double v[6];
  double cnt[PairEllipsoid::NCOUNT];
  KOKKOS_INLINE_FUNCTION EllReduce()
  {
    evdwl = 0.0;
    for (int k = 0; k < 6; k++) v[k] = 0.0;
    for (int k = 0; k < PairEllipsoid::NCOUNT; k++) cnt[k] = 0.0;
  }
  KOKKOS_INLINE_FUNCTION void operator+=(const EllReduce &r)
  {
    evdwl += r.evdwl;
    for (int k = 0; k < 6; k++) v[k] += r.v[k];
    for (int k = 0; k < PairEllipsoid::NCOUNT; k++) cnt[k] += r.cnt[k];
  }
  KOKKOS_INLINE_FUNCTION void operator+=(const volatile EllReduce &r) volatile
  {
    evdwl += r.evdwl;
    for (int k = 0; k < 6; k++) v[k] += r.v[k];
    for (int k = 0; k < PairEllipsoid::NCOUNT; k++) cnt[k] += r.cnt[k];
  }
};

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
  Kokkos::View<double **, DeviceType> kn, en;
  typename AT::t_efloat_1d eatom;
  typename AT::t_virial_array vatom;
  int nlocal, newton_pair, overlap, damping_mass;
  int eflag_global, eflag_atom, vflag_global, vflag_atom;
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

  KOKKOS_INLINE_FUNCTION void operator()(const int ii, EllReduce &red) const
  {
    const int i = ilist(ii);
    const auto A = pose(i);
    const int jnum = numneigh(i);
    for (int jj = 0; jj < jnum; jj++) {
      const int j = neighbors(i, jj) & NEIGHMASK;
      const double delx = x(i, 0) - x(j, 0), dely = x(i, 1) - x(j, 1), delz = x(i, 2) - x(j, 2);
      const double radsum = radius(i) + radius(j);
      if (delx * delx + dely * dely + delz * delz >= radsum * radsum) continue;
      const auto B = pose(j);
      const auto c = polydem::ellipsoid_contact(A, B);
      if (c.status == polydem::STATUS_SEPARATED) continue;
      if (c.status != polydem::STATUS_OK) {
        red.cnt[c.status == polydem::STATUS_NO_CONVERGENCE ? PairEllipsoid::CNT_NOCONV
                                                           : PairEllipsoid::CNT_DEGENERATE] += 1.0;
        continue;
      }
      const double w = (newton_pair || j < nlocal) ? 1.0 : 0.5;    // ghost pairs: 2 ranks
      red.cnt[PairEllipsoid::CNT_CONTACTS] += w;
      double amin = A.axes.x;
      const double ax[5] = {A.axes.y, A.axes.z, B.axes.x, B.axes.y, B.axes.z};
      for (int k = 0; k < 5; k++)
        if (ax[k] < amin) amin = ax[k];
      const int it = type(i), jt = type(j);
      const double meff = damping_mass == polydem::DAMPING_CONTACT
          ? polydem::ellipsoid_contact_mass(c, overlap, A, B, rmass(i), rmass(j))
          : rmass(i) * rmass(j) / (rmass(i) + rmass(j));
      const double gamma = polydem::ellipsoid_damping(kn(it, jt), meff, en(it, jt));
      const auto cf = polydem::ellipsoid_force(
          c, overlap, kn(it, jt), gamma, A.x, B.x, polydem::make_vec3(v(i, 0), v(i, 1), v(i, 2)),
          polydem::make_vec3(v(j, 0), v(j, 1), v(j, 2)),
          polydem::make_vec3(omega(i, 0), omega(i, 1), omega(i, 2)),
          polydem::make_vec3(omega(j, 0), omega(j, 1), omega(j, 2)));
      if (cf.delta > overlap_warn * amin) red.cnt[PairEllipsoid::CNT_BIGOVERLAP] += 1.0;
      if (cf.delta < cf.rate * dt) red.cnt[PairEllipsoid::CNT_COLLISIONS] += w;

      const double F[3] = {cf.F_A.x, cf.F_A.y, cf.F_A.z};
      const double tA[3] = {cf.tau_A.x, cf.tau_A.y, cf.tau_A.z};
      const double tB[3] = {cf.tau_B.x, cf.tau_B.y, cf.tau_B.z};
      for (int k = 0; k < 3; k++) {
        Kokkos::atomic_add(&f(i, k), F[k]);
        Kokkos::atomic_add(&torque(i, k), tA[k]);
      }
      if (newton_pair || j < nlocal)
        for (int k = 0; k < 3; k++) {
          Kokkos::atomic_add(&f(j, k), -F[k]);
          Kokkos::atomic_add(&torque(j, k), tB[k]);
        }

      // Pair::ev_tally_xyz
      const bool ti = newton_pair || i < nlocal, tj = newton_pair || j < nlocal;
      const double e = cf.energy;
      if (eflag_global) {
        if (newton_pair)
          red.evdwl += e;
        else {
          if (i < nlocal) red.evdwl += 0.5 * e;
          if (j < nlocal) red.evdwl += 0.5 * e;
        }
      }
      if (eflag_atom) {
        if (ti) Kokkos::atomic_add(&eatom(i), 0.5 * e);
        if (tj) Kokkos::atomic_add(&eatom(j), 0.5 * e);
      }
      if (vflag_global || vflag_atom) {
        const double vv[6] = {delx * F[0], dely * F[1], delz * F[2],
                              delx * F[1], delx * F[2], dely * F[2]};
        const double wi = newton_pair ? 1.0 : (i < nlocal ? 0.5 : 0.0);
        const double wj = newton_pair ? 0.0 : (j < nlocal ? 0.5 : 0.0);
        if (vflag_global)
          for (int k = 0; k < 6; k++) red.v[k] += (wi + wj) * vv[k];
        if (vflag_atom) {
          if (ti)
            for (int k = 0; k < 6; k++) Kokkos::atomic_add(&vatom(i, k), 0.5 * vv[k]);
          if (tj)
            for (int k = 0; k < 6; k++) Kokkos::atomic_add(&vatom(j, k), 0.5 * vv[k]);
        }
      }
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
  datamask_read = X_MASK | V_MASK | OMEGA_MASK | F_MASK | TORQUE_MASK | TYPE_MASK | MASK_MASK |
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
  if (friction_used())
    error->all(FLERR, "pair_style ellipsoid/kk: friction (pair_coeff mu > 0) is not available "
               "in the Kokkos style yet; use the plain pair_style ellipsoid (-sf kk off for this "
               "style: 'suffix off' before pair_style)");
  PairEllipsoid::init_style();
  int irequest = neighbor->nrequest - 1;
  neighbor->requests[irequest]->kokkos_host = std::is_same<DeviceType, LMPHostType>::value &&
      !std::is_same<DeviceType, LMPDeviceType>::value;
  neighbor->requests[irequest]->kokkos_device = std::is_same<DeviceType, LMPDeviceType>::value;
  neighbor->requests[irequest]->full = 0;
  neighbor->requests[irequest]->half = 1;
  params_dirty = 1;
}

/* ----------------------------------------------------------------------
   semi-axes of all templates and the per-type-pair coefficients on the device
------------------------------------------------------------------------- */

template <class DeviceType> void PairEllipsoidKokkos<DeviceType>::update_device_data()
{
  if (shape_version != avecKK->shape_version()) {
    AtomVecPolyhedron *av = avecKK;
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
    d_en = Kokkos::View<double **, DeviceType>("ellipsoid/kk:en", n + 1, n + 1);
    auto hk = Kokkos::create_mirror_view(d_kn);
    auto he = Kokkos::create_mirror_view(d_en);
    for (int i = 1; i <= n; i++)
      for (int j = 1; j <= n; j++) {
        hk(i, j) = kn[i][j];
        he(i, j) = restitution[i][j];
      }
    Kokkos::deep_copy(d_kn, hk);
    Kokkos::deep_copy(d_en, he);
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
  fn.en = d_en;
  if (eflag_atom) fn.eatom = k_eatom.template view<DeviceType>();
  if (vflag_atom) fn.vatom = k_vatom.template view<DeviceType>();
  fn.nlocal = atom->nlocal;
  fn.newton_pair = force->newton_pair;
  fn.overlap = overlap;
  fn.damping_mass = damping_mass;
  fn.eflag_global = eflag_global;
  fn.eflag_atom = eflag_atom;
  fn.vflag_global = vflag_global;
  fn.vflag_atom = vflag_atom;
  fn.dt = update->dt;
  fn.overlap_warn = overlap_warn;

  EllReduce red;
  Kokkos::parallel_reduce(
      Kokkos::RangePolicy<typename DeviceType::execution_space>(0, list->inum), fn, red);
  if (eflag_global) eng_vdwl += red.evdwl;
  if (vflag_global)
    for (int k = 0; k < 6; k++) virial[k] += red.v[k];
  for (int k = 0; k < NCOUNT; k++) local_counts[k] += red.cnt[k];

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
