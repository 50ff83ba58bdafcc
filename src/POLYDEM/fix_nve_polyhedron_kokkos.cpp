/* ----------------------------------------------------------------------
   POLYDEM - fix nve/polyhedron/kk
------------------------------------------------------------------------- */

#include "fix_nve_polyhedron_kokkos.h"

#include "atom_kokkos.h"
#include "atom_masks.h"
#include "atom_vec_polyhedron_kokkos.h"
#include "error.h"
#include "polydem_kokkos_masks.h"
#include "polydem_launch_kokkos.h"
#include "polydem_rigid.h"
#include "polydem_shape_template.h"

using namespace LAMMPS_NS;

namespace {

/* ----------------------------------------------------------------------
   one half step for atom i, the arithmetic of FixNVEPolyhedron statement
   for statement (kick v and L by dt/2, drift x by dt, free rotation of
   q and L by dt; omega from L): identical results on a CPU backend
------------------------------------------------------------------------- */

template <class DeviceType, int MODE> struct FixNVEPolyhedronKokkosFunctor {
  typedef DeviceType device_type;
  typedef ArrayTypes<DeviceType> AT;
  typename AT::t_x_array x;
  typename AT::t_v_array v, omega, angmom;
  typename AT::t_f_array_const f, torque;
  typename AT::t_float_1d_randomread rmass, pscale;
  typename AT::t_int_1d_randomread mask, pshape;
  polydem_view_t<tdual_quat_array, DeviceType> quat;
  polydem_view_t<tdual_shape_props, DeviceType> props;
  double dtv, dtf;
  int groupbit;

  FixNVEPolyhedronKokkosFunctor(AtomKokkos *atomKK, AtomVecPolyhedronKokkos *avecKK,
                                const tdual_shape_props &k_props, double dtv_, double dtf_,
                                int groupbit_) :
      x(atomKK->k_x.view<DeviceType>()),
      v(atomKK->k_v.view<DeviceType>()), omega(atomKK->k_omega.view<DeviceType>()),
      angmom(atomKK->k_angmom.view<DeviceType>()), f(atomKK->k_f.view<DeviceType>()),
      torque(atomKK->k_torque.view<DeviceType>()), rmass(atomKK->k_rmass.view<DeviceType>()),
      pscale(avecKK->k_pscale.view<DeviceType>()), mask(atomKK->k_mask.view<DeviceType>()),
      pshape(avecKK->k_pshape.view<DeviceType>()), quat(avecKK->k_quat.view<DeviceType>()),
      props(k_props.view<DeviceType>()), dtv(dtv_), dtf(dtf_), groupbit(groupbit_)
  {
  }

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const
  {
    if (!(mask(i) & groupbit)) return;
    // each atom's values read once into locals and written once (the Views
    // may alias, so the compiler would reload them after every store)
    double L[3] = {angmom(i, 0), angmom(i, 1), angmom(i, 2)};
    if (MODE != FixNVEPolyhedronKokkos<DeviceType>::OMEGA_ONLY) {
      const double dtfm = dtf / rmass(i);
      for (int k = 0; k < 3; k++) {
        const double vk = v(i, k) + dtfm * f(i, k);
        v(i, k) = vk;
        if (MODE == FixNVEPolyhedronKokkos<DeviceType>::INITIAL) x(i, k) += dtv * vk;
        L[k] += dtf * torque(i, k);
      }
    }
    // principal moments I_k = m s^2 J_k / V (as PolyShapeLibrary::inertia)
    const int t = pshape(i);
    const double J[3] = {props(t, 1), props(t, 2), props(t, 3)};
    double inertia[3];
    polydem::scaled_moments(rmass(i), pscale(i), props(t, 0), J, inertia);
    double q[4] = {quat(i, 0), quat(i, 1), quat(i, 2), quat(i, 3)};
    if (MODE == FixNVEPolyhedronKokkos<DeviceType>::INITIAL) {
      polydem::free_rotor_step(dtv, inertia, L, q);
      for (int k = 0; k < 4; k++) quat(i, k) = q[k];
    }
    if (MODE != FixNVEPolyhedronKokkos<DeviceType>::OMEGA_ONLY)
      for (int k = 0; k < 3; k++) angmom(i, k) = L[k];
    double w[3];
    polydem::omega_from_angmom(inertia, L, q, w);
    for (int k = 0; k < 3; k++) omega(i, k) = w[k];
  }
};

}    // namespace

/* ---------------------------------------------------------------------- */

template <class DeviceType>
FixNVEPolyhedronKokkos<DeviceType>::FixNVEPolyhedronKokkos(LAMMPS *lmp, int narg, char **arg) :
    FixNVE(lmp, narg, arg), avec(nullptr), avecKK(nullptr), table_version(-1)
{
  if (narg != 3) error->all(FLERR, "Illegal fix nve/polyhedron/kk command: no arguments expected");
  kokkosable = 1;
  atomKK = (AtomKokkos *) atom;
  execution_space = ExecutionSpaceFromDevice<DeviceType>::space;
  datamask_read = EMPTY_MASK;
  datamask_modify = EMPTY_MASK;
  find_style();
}

/* ---------------------------------------------------------------------- */

template <class DeviceType> void FixNVEPolyhedronKokkos<DeviceType>::find_style()
{
  avecKK = AtomVecPolyhedronKokkos::of(atom);
  if (!avecKK) error->all(FLERR, "Fix nve/polyhedron/kk requires atom_style polyhedron/kk");
  avec = PolyShapeLibrary::of(lmp, "Fix nve/polyhedron/kk");
}

/* ----------------------------------------------------------------------
   device copy of the templates' volume and principal moments
------------------------------------------------------------------------- */

template <class DeviceType> void FixNVEPolyhedronKokkos<DeviceType>::update_table()
{
  if (table_version == avec->shape_version()) return;
  const int n = avec->ntemplates();
  if (n == 0) error->all(FLERR, "Fix nve/polyhedron/kk: no shape defined (polyhedron_shape)");
  k_props = tdual_shape_props("nve/polyhedron/kk:props", n);
  for (int t = 0; t < n; t++) {
    const auto sv = avec->shape(t).view();
    k_props.h_view(t, 0) = sv.volume;
    for (int k = 0; k < 3; k++) k_props.h_view(t, 1 + k) = sv.inertia[k];
  }
  k_props.modify<LMPHostType>();
  k_props.sync<DeviceType>();
  table_version = avec->shape_version();
}

/* ----------------------------------------------------------------------
   omega follows from angmom, orientation and inertia before the first step
------------------------------------------------------------------------- */

template <class DeviceType> void FixNVEPolyhedronKokkos<DeviceType>::init()
{
  FixNVE::init();
  find_style();
  table_version = -1;
  update_table();
  integrate<OMEGA_ONLY>(atom->nlocal);
}

/* ---------------------------------------------------------------------- */

template <class DeviceType> void FixNVEPolyhedronKokkos<DeviceType>::initial_integrate(int)
{
  int nlocal = atom->nlocal;
  if (igroup == atom->firstgroup) nlocal = atom->nfirst;
  integrate<INITIAL>(nlocal);
}

template <class DeviceType> void FixNVEPolyhedronKokkos<DeviceType>::final_integrate()
{
  int nlocal = atom->nlocal;
  if (igroup == atom->firstgroup) nlocal = atom->nfirst;
  integrate<FINAL>(nlocal);
}

/* ---------------------------------------------------------------------- */

template <class DeviceType>
template <int MODE>
void FixNVEPolyhedronKokkos<DeviceType>::integrate(int nlocal)
{
  update_table();

  unsigned int read = MASK_MASK | RMASS_MASK | ANGMOM_MASK | POLYDEM_ALL_MASK;
  unsigned int modify = OMEGA_MASK;
  if (MODE != OMEGA_ONLY) {
    read |= V_MASK | F_MASK | TORQUE_MASK;
    modify |= V_MASK | ANGMOM_MASK;
  }
  if (MODE == INITIAL) {
    read |= X_MASK;
    modify |= X_MASK | POLYDEM_QUAT_MASK;
  }
  atomKK->sync(execution_space, read);

  FixNVEPolyhedronKokkosFunctor<DeviceType, MODE> functor(atomKK, avecKK, k_props, dtv, dtf,
                                                          groupbit);
  polydem_kk::for_range<typename DeviceType::execution_space>(0, nlocal, functor);

  atomKK->modified(execution_space, modify);
}

namespace LAMMPS_NS {
template class FixNVEPolyhedronKokkos<LMPDeviceType>;
#ifdef LMP_KOKKOS_GPU
template class FixNVEPolyhedronKokkos<LMPHostType>;
#endif
}    // namespace LAMMPS_NS
