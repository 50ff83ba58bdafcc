/* ----------------------------------------------------------------------
   POLYDEM - atom_style polyhedron/kk
------------------------------------------------------------------------- */

#include "atom_vec_polyhedron_kokkos.h"

#include "atom_kokkos.h"
#include "atom_masks.h"
#include "comm_kokkos.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "kokkos.h"
#include "memory_kokkos.h"
#include "modify.h"
#include "polydem_launch_kokkos.h"

#include <cstring>

using namespace LAMMPS_NS;

// fields each operation reads or writes (host and device paths alike)
static constexpr unsigned int COMM_MASK = X_MASK | POLYDEM_QUAT_MASK;
static constexpr unsigned int COMM_VEL_MASK =
    X_MASK | V_MASK | MASK_MASK | OMEGA_MASK | ANGMOM_MASK | POLYDEM_QUAT_MASK;
static constexpr unsigned int REVERSE_MASK = F_MASK | TORQUE_MASK;
static constexpr unsigned int BORDER_MASK = X_MASK | TAG_MASK | TYPE_MASK | MASK_MASK |
    RADIUS_MASK | RMASS_MASK | POLYDEM_QUAT_MASK | POLYDEM_PSHAPE_MASK | POLYDEM_PSCALE_MASK;
static constexpr unsigned int BORDER_VEL_MASK = BORDER_MASK | V_MASK | OMEGA_MASK | ANGMOM_MASK;
static constexpr unsigned int EXCHANGE_MASK = X_MASK | V_MASK | TAG_MASK | TYPE_MASK | MASK_MASK |
    IMAGE_MASK | RADIUS_MASK | RMASS_MASK | OMEGA_MASK | ANGMOM_MASK | POLYDEM_ALL_MASK;
// every field this style stores
static constexpr unsigned int STYLE_MASK = EXCHANGE_MASK | F_MASK | TORQUE_MASK;

/* ======================================================================
   device functors
====================================================================== */

namespace {

template <class DeviceType> using t_quat = polydem_view_t<tdual_quat_array, DeviceType>;

// translation of a periodic image: x + (dx,dy,dz) (host formula of AtomVec::pack_comm)
struct Shift {
  X_FLOAT dx, dy, dz;
};

Shift comm_shift(Domain *domain, int pbc_flag, const int *pbc)
{
  Shift s = {0.0, 0.0, 0.0};
  if (!pbc_flag) return s;
  if (domain->triclinic == 0) {
    s.dx = pbc[0] * domain->xprd;
    s.dy = pbc[1] * domain->yprd;
    s.dz = pbc[2] * domain->zprd;
  } else {
    s.dx = pbc[0] * domain->xprd + pbc[5] * domain->xy + pbc[4] * domain->xz;
    s.dy = pbc[1] * domain->yprd + pbc[3] * domain->yz;
    s.dz = pbc[2] * domain->zprd;
  }
  return s;
}

// border shifts: in lamda coordinates for triclinic boxes (as CommBrick::borders)
Shift border_shift(Domain *domain, int pbc_flag, const int *pbc)
{
  Shift s = {0.0, 0.0, 0.0};
  if (!pbc_flag) return s;
  if (domain->triclinic == 0) {
    s.dx = pbc[0] * domain->xprd;
    s.dy = pbc[1] * domain->yprd;
    s.dz = pbc[2] * domain->zprd;
  } else {
    s.dx = pbc[0];
    s.dy = pbc[1];
    s.dz = pbc[2];
  }
  return s;
}

// the velocity offset of a periodic image under fix deform remap v (as
// AtomVec::pack_comm_vel); zero otherwise
void deform_dv(int vremap, const double *h_rate, int pbc_flag, const int *pbc, X_FLOAT dv[3])
{
  dv[0] = dv[1] = dv[2] = 0.0;
  if (!pbc_flag || !vremap) return;
  dv[0] = pbc[0] * h_rate[0] + pbc[5] * h_rate[5] + pbc[4] * h_rate[4];
  dv[1] = pbc[1] * h_rate[1] + pbc[3] * h_rate[3];
  dv[2] = pbc[2] * h_rate[2];
}

template <class D> struct SpaceTag {
  typedef D type;
};

// body(SpaceTag<LMPHostType>) on the host or body(SpaceTag<LMPDeviceType>) on
// the device (each builds its functor for that space and runs it), the
// fields of sync_mask synced there before and those of modify_mask (0: none)
// marked modified after
template <class Body>
void on_space(AtomKokkos *atomKK, ExecutionSpace space, unsigned int sync_mask,
              unsigned int modify_mask, Body body)
{
  atomKK->sync(space, sync_mask);
  if (space == Host)
    body(SpaceTag<LMPHostType>());
  else
    body(SpaceTag<LMPDeviceType>());
  if (modify_mask) atomKK->modified(space, modify_mask);
}

/* ---------------------------------------------------------------------- */
// forward: x (shifted), quat; with VEL also v (deform-remapped), omega, angmom

template <class DeviceType, int VEL> struct PolyPackComm {
  typedef DeviceType device_type;
  typedef ArrayTypes<DeviceType> AT;
  typename AT::t_x_array_randomread x;
  typename AT::t_v_array_randomread v, omega, angmom;
  typename AT::t_int_1d_randomread mask;
  t_quat<DeviceType> quat;
  typename AT::t_xfloat_2d_um buf;
  polydem_sendlist_view<DeviceType> list;
  int iswap, pbc_flag, deform_groupbit;
  Shift s;
  X_FLOAT dvx, dvy, dvz;

  PolyPackComm(AtomKokkos *atomKK, const tdual_quat_array &k_quat,
               const DAT::tdual_xfloat_2d &k_buf, const polydem_tdual_sendlist &k_list, int iswap_,
               int pbc_flag_, Shift s_, int deform_groupbit_, const X_FLOAT *dv) :
      x(atomKK->k_x.view<DeviceType>()),
      quat(k_quat.view<DeviceType>()), list(k_list.view<DeviceType>()), iswap(iswap_),
      pbc_flag(pbc_flag_), deform_groupbit(deform_groupbit_), s(s_)
  {
    if (VEL) {
      v = atomKK->k_v.view<DeviceType>();
      omega = atomKK->k_omega.view<DeviceType>();
      angmom = atomKK->k_angmom.view<DeviceType>();
      mask = atomKK->k_mask.view<DeviceType>();
    }
    dvx = dv[0];
    dvy = dv[1];
    dvz = dv[2];
    const int elements = VEL ? AtomVecPolyhedronKokkos::COMM_VEL_SIZE
                             : AtomVecPolyhedronKokkos::COMM_SIZE;
    const auto b = k_buf.view<DeviceType>();
    buf = typename AT::t_xfloat_2d_um(b.data(), (b.extent(0) * b.extent(1)) / elements, elements);
  }

  KOKKOS_INLINE_FUNCTION void operator()(const int &i) const
  {
    const int j = POLYDEM_KK_SEND(list, iswap, i);
    if (pbc_flag) {
      buf(i, 0) = x(j, 0) + s.dx;
      buf(i, 1) = x(j, 1) + s.dy;
      buf(i, 2) = x(j, 2) + s.dz;
    } else {
      buf(i, 0) = x(j, 0);
      buf(i, 1) = x(j, 1);
      buf(i, 2) = x(j, 2);
    }
    int m = 3;
    if (VEL) {
      const bool remap = pbc_flag && deform_groupbit && (mask(j) & deform_groupbit);
      buf(i, m++) = remap ? v(j, 0) + dvx : v(j, 0);
      buf(i, m++) = remap ? v(j, 1) + dvy : v(j, 1);
      buf(i, m++) = remap ? v(j, 2) + dvz : v(j, 2);
    }
    for (int k = 0; k < 4; k++) buf(i, m++) = quat(j, k);
    if (VEL) {
      for (int k = 0; k < 3; k++) buf(i, m++) = omega(j, k);
      for (int k = 0; k < 3; k++) buf(i, m++) = angmom(j, k);
    }
  }
};

template <class DeviceType, int VEL> struct PolyUnpackComm {
  typedef DeviceType device_type;
  typedef ArrayTypes<DeviceType> AT;
  typename AT::t_x_array x;
  typename AT::t_v_array v, omega, angmom;
  t_quat<DeviceType> quat;
  typename AT::t_xfloat_2d_const_um buf;
  int first;

  PolyUnpackComm(AtomKokkos *atomKK, const tdual_quat_array &k_quat,
                 const DAT::tdual_xfloat_2d &k_buf, int first_) :
      x(atomKK->k_x.view<DeviceType>()), quat(k_quat.view<DeviceType>()), first(first_)
  {
    if (VEL) {
      v = atomKK->k_v.view<DeviceType>();
      omega = atomKK->k_omega.view<DeviceType>();
      angmom = atomKK->k_angmom.view<DeviceType>();
    }
    const int elements = VEL ? AtomVecPolyhedronKokkos::COMM_VEL_SIZE
                             : AtomVecPolyhedronKokkos::COMM_SIZE;
    const auto b = k_buf.view<DeviceType>();
    buf = typename AT::t_xfloat_2d_const_um(b.data(), (b.extent(0) * b.extent(1)) / elements,
                                            elements);
  }

  KOKKOS_INLINE_FUNCTION void operator()(const int &i) const
  {
    const int j = i + first;
    int m = 0;
    for (int k = 0; k < 3; k++) x(j, k) = buf(i, m++);
    if (VEL)
      for (int k = 0; k < 3; k++) v(j, k) = buf(i, m++);
    for (int k = 0; k < 4; k++) quat(j, k) = buf(i, m++);
    if (VEL) {
      for (int k = 0; k < 3; k++) omega(j, k) = buf(i, m++);
      for (int k = 0; k < 3; k++) angmom(j, k) = buf(i, m++);
    }
  }
};

// forward communication with self: copy owned/ghost j to ghost i + nfirst
template <class DeviceType> struct PolyCommSelf {
  typedef DeviceType device_type;
  typedef ArrayTypes<DeviceType> AT;
  typename AT::t_x_array x;
  t_quat<DeviceType> quat;
  polydem_sendlist_view<DeviceType> list;
  int iswap, nfirst, pbc_flag;
  Shift s;

  PolyCommSelf(AtomKokkos *atomKK, const tdual_quat_array &k_quat,
               const polydem_tdual_sendlist &k_list, int iswap_, int nfirst_, int pbc_flag_,
               Shift s_) :
      x(atomKK->k_x.view<DeviceType>()),
      quat(k_quat.view<DeviceType>()), list(k_list.view<DeviceType>()), iswap(iswap_),
      nfirst(nfirst_), pbc_flag(pbc_flag_), s(s_)
  {
  }

  KOKKOS_INLINE_FUNCTION void operator()(const int &i) const
  {
    const int j = POLYDEM_KK_SEND(list, iswap, i);
    const int g = i + nfirst;
    if (pbc_flag) {
      x(g, 0) = x(j, 0) + s.dx;
      x(g, 1) = x(j, 1) + s.dy;
      x(g, 2) = x(j, 2) + s.dz;
    } else {
      x(g, 0) = x(j, 0);
      x(g, 1) = x(j, 1);
      x(g, 2) = x(j, 2);
    }
    for (int k = 0; k < 4; k++) quat(g, k) = quat(j, k);
  }
};

// all self swaps of a single-rank run in one kernel (CommKokkos::copy_swap_info):
// ghosts that are images of ghosts read the owned atom through g2l
template <class DeviceType> struct PolyCommSelfFused {
  typedef DeviceType device_type;
  typedef ArrayTypes<DeviceType> AT;
  typename AT::t_x_array x;
  t_quat<DeviceType> quat;
  typename AT::t_int_2d_const list, pbc;
  typename AT::t_int_1d_const pbc_flag, firstrecv, sendnum_scan, g2l;
  X_FLOAT xprd, yprd, zprd, xy, xz, yz;
  int triclinic;

  PolyCommSelfFused(AtomKokkos *atomKK, const tdual_quat_array &k_quat,
                    const DAT::tdual_int_2d &k_list, const DAT::tdual_int_2d &k_pbc,
                    const DAT::tdual_int_1d &k_pbc_flag, const DAT::tdual_int_1d &k_firstrecv,
                    const DAT::tdual_int_1d &k_sendnum_scan, const DAT::tdual_int_1d &k_g2l,
                    Domain *domain) :
      x(atomKK->k_x.view<DeviceType>()),
      quat(k_quat.view<DeviceType>()), list(k_list.view<DeviceType>()),
      pbc(k_pbc.view<DeviceType>()), pbc_flag(k_pbc_flag.view<DeviceType>()),
      firstrecv(k_firstrecv.view<DeviceType>()), sendnum_scan(k_sendnum_scan.view<DeviceType>()),
      g2l(k_g2l.view<DeviceType>()), xprd(domain->xprd), yprd(domain->yprd),
      zprd(domain->zprd), xy(domain->xy), xz(domain->xz), yz(domain->yz),
      triclinic(domain->triclinic)
  {
  }

  KOKKOS_INLINE_FUNCTION void operator()(const int &ii) const
  {
    int iswap = 0;
    while (ii >= sendnum_scan(iswap)) iswap++;
    const int i = iswap > 0 ? ii - sendnum_scan(iswap - 1) : ii;
    const int g = i + firstrecv(iswap);
    const int nlocal = firstrecv(0);
    int j = list(iswap, i);
    if (j >= nlocal) j = g2l(j - nlocal);
    if (pbc_flag(ii) == 0) {
      x(g, 0) = x(j, 0);
      x(g, 1) = x(j, 1);
      x(g, 2) = x(j, 2);
    } else if (triclinic == 0) {
      x(g, 0) = x(j, 0) + pbc(ii, 0) * xprd;
      x(g, 1) = x(j, 1) + pbc(ii, 1) * yprd;
      x(g, 2) = x(j, 2) + pbc(ii, 2) * zprd;
    } else {
      x(g, 0) = x(j, 0) + pbc(ii, 0) * xprd + pbc(ii, 5) * xy + pbc(ii, 4) * xz;
      x(g, 1) = x(j, 1) + pbc(ii, 1) * yprd + pbc(ii, 3) * yz;
      x(g, 2) = x(j, 2) + pbc(ii, 2) * zprd;
    }
    for (int k = 0; k < 4; k++) quat(g, k) = quat(j, k);
  }
};

/* ---------------------------------------------------------------------- */
// borders: x, tag, type, mask, radius, rmass, quat, pshape, pscale
// (+ v, omega, angmom); row stride = size of one atom in CommKokkos's buffer

template <class DeviceType, int VEL> struct PolyPackBorder {
  typedef DeviceType device_type;
  typedef ArrayTypes<DeviceType> AT;
  typename AT::t_xfloat_2d_um buf;
  polydem_sendlist_view<DeviceType> list;
  int iswap, pbc_flag, deform_groupbit;
  typename AT::t_x_array_randomread x;
  typename AT::t_tagint_1d tag;
  typename AT::t_int_1d type, mask, pshape;
  typename AT::t_float_1d radius, rmass, pscale;
  typename AT::t_v_array v, omega, angmom;
  t_quat<DeviceType> quat;
  Shift s;
  X_FLOAT dvx, dvy, dvz;

  PolyPackBorder(AtomKokkos *atomKK, AtomVecPolyhedronKokkos *avec,
                 const DAT::tdual_xfloat_2d &k_buf, const polydem_tdual_sendlist &k_list, int iswap_,
                 int pbc_flag_, Shift s_, int deform_groupbit_, const X_FLOAT *dv, int stride) :
      list(k_list.view<DeviceType>()),
      iswap(iswap_), pbc_flag(pbc_flag_), deform_groupbit(deform_groupbit_),
      x(atomKK->k_x.view<DeviceType>()), tag(atomKK->k_tag.view<DeviceType>()),
      type(atomKK->k_type.view<DeviceType>()), mask(atomKK->k_mask.view<DeviceType>()),
      pshape(avec->k_pshape.view<DeviceType>()), radius(atomKK->k_radius.view<DeviceType>()),
      rmass(atomKK->k_rmass.view<DeviceType>()), pscale(avec->k_pscale.view<DeviceType>()),
      quat(avec->k_quat.view<DeviceType>()), s(s_)
  {
    if (VEL) {
      v = atomKK->k_v.view<DeviceType>();
      omega = atomKK->k_omega.view<DeviceType>();
      angmom = atomKK->k_angmom.view<DeviceType>();
    }
    dvx = dv[0];
    dvy = dv[1];
    dvz = dv[2];
    const auto b = k_buf.view<DeviceType>();
    buf = typename AT::t_xfloat_2d_um(b.data(), (b.extent(0) * b.extent(1)) / stride, stride);
  }

  KOKKOS_INLINE_FUNCTION void operator()(const int &i) const
  {
    const int j = POLYDEM_KK_SEND(list, iswap, i);
    if (pbc_flag) {
      buf(i, 0) = x(j, 0) + s.dx;
      buf(i, 1) = x(j, 1) + s.dy;
      buf(i, 2) = x(j, 2) + s.dz;
    } else {
      buf(i, 0) = x(j, 0);
      buf(i, 1) = x(j, 1);
      buf(i, 2) = x(j, 2);
    }
    buf(i, 3) = d_ubuf(tag(j)).d;
    buf(i, 4) = d_ubuf(type(j)).d;
    buf(i, 5) = d_ubuf(mask(j)).d;
    buf(i, 6) = radius(j);
    buf(i, 7) = rmass(j);
    for (int k = 0; k < 4; k++) buf(i, 8 + k) = quat(j, k);
    buf(i, 12) = d_ubuf(pshape(j)).d;
    buf(i, 13) = pscale(j);
    if (VEL) {
      const bool remap = pbc_flag && deform_groupbit && (mask(j) & deform_groupbit);
      buf(i, 14) = remap ? v(j, 0) + dvx : v(j, 0);
      buf(i, 15) = remap ? v(j, 1) + dvy : v(j, 1);
      buf(i, 16) = remap ? v(j, 2) + dvz : v(j, 2);
      for (int k = 0; k < 3; k++) buf(i, 17 + k) = omega(j, k);
      for (int k = 0; k < 3; k++) buf(i, 20 + k) = angmom(j, k);
    }
  }
};

template <class DeviceType, int VEL> struct PolyUnpackBorder {
  typedef DeviceType device_type;
  typedef ArrayTypes<DeviceType> AT;
  typename AT::t_xfloat_2d_const_um buf;
  typename AT::t_x_array x;
  typename AT::t_tagint_1d tag;
  typename AT::t_int_1d type, mask, pshape;
  typename AT::t_float_1d radius, rmass, pscale;
  typename AT::t_v_array v, omega, angmom;
  t_quat<DeviceType> quat;
  int first;

  PolyUnpackBorder(AtomKokkos *atomKK, AtomVecPolyhedronKokkos *avec,
                   const DAT::tdual_xfloat_2d &k_buf, int first_, int stride) :
      x(atomKK->k_x.view<DeviceType>()),
      tag(atomKK->k_tag.view<DeviceType>()), type(atomKK->k_type.view<DeviceType>()),
      mask(atomKK->k_mask.view<DeviceType>()), pshape(avec->k_pshape.view<DeviceType>()),
      radius(atomKK->k_radius.view<DeviceType>()), rmass(atomKK->k_rmass.view<DeviceType>()),
      pscale(avec->k_pscale.view<DeviceType>()), quat(avec->k_quat.view<DeviceType>()),
      first(first_)
  {
    if (VEL) {
      v = atomKK->k_v.view<DeviceType>();
      omega = atomKK->k_omega.view<DeviceType>();
      angmom = atomKK->k_angmom.view<DeviceType>();
    }
    const auto b = k_buf.view<DeviceType>();
    buf = typename AT::t_xfloat_2d_const_um(b.data(), (b.extent(0) * b.extent(1)) / stride,
                                            stride);
  }

  KOKKOS_INLINE_FUNCTION void operator()(const int &i) const
  {
    const int j = i + first;
    x(j, 0) = buf(i, 0);
    x(j, 1) = buf(i, 1);
    x(j, 2) = buf(i, 2);
    tag(j) = static_cast<tagint>(d_ubuf(buf(i, 3)).i);
    type(j) = static_cast<int>(d_ubuf(buf(i, 4)).i);
    mask(j) = static_cast<int>(d_ubuf(buf(i, 5)).i);
    radius(j) = buf(i, 6);
    rmass(j) = buf(i, 7);
    for (int k = 0; k < 4; k++) quat(j, k) = buf(i, 8 + k);
    pshape(j) = static_cast<int>(d_ubuf(buf(i, 12)).i);
    pscale(j) = buf(i, 13);
    if (VEL) {
      for (int k = 0; k < 3; k++) v(j, k) = buf(i, 14 + k);
      for (int k = 0; k < 3; k++) omega(j, k) = buf(i, 17 + k);
      for (int k = 0; k < 3; k++) angmom(j, k) = buf(i, 20 + k);
    }
  }
};

/* ---------------------------------------------------------------------- */
// exchange: every field of fields_exchange; the hole left by a departing
// atom is filled from copylist (atoms that stay, taken from the end)

template <class DeviceType> struct PolyExchangeViews {
  typedef ArrayTypes<DeviceType> AT;
  typename AT::t_x_array x;
  typename AT::t_v_array v, omega, angmom;
  typename AT::t_tagint_1d tag;
  typename AT::t_int_1d type, mask, pshape;
  typename AT::t_imageint_1d image;
  typename AT::t_float_1d radius, rmass, pscale;
  t_quat<DeviceType> quat;

  PolyExchangeViews(AtomKokkos *atomKK, AtomVecPolyhedronKokkos *avec) :
      x(atomKK->k_x.view<DeviceType>()), v(atomKK->k_v.view<DeviceType>()),
      omega(atomKK->k_omega.view<DeviceType>()), angmom(atomKK->k_angmom.view<DeviceType>()),
      tag(atomKK->k_tag.view<DeviceType>()), type(atomKK->k_type.view<DeviceType>()),
      mask(atomKK->k_mask.view<DeviceType>()), pshape(avec->k_pshape.view<DeviceType>()),
      image(atomKK->k_image.view<DeviceType>()), radius(atomKK->k_radius.view<DeviceType>()),
      rmass(atomKK->k_rmass.view<DeviceType>()), pscale(avec->k_pscale.view<DeviceType>()),
      quat(avec->k_quat.view<DeviceType>())
  {
  }

  KOKKOS_INLINE_FUNCTION void copy(int from, int to) const
  {
    for (int k = 0; k < 3; k++) {
      x(to, k) = x(from, k);
      v(to, k) = v(from, k);
      omega(to, k) = omega(from, k);
      angmom(to, k) = angmom(from, k);
    }
    tag(to) = tag(from);
    type(to) = type(from);
    mask(to) = mask(from);
    image(to) = image(from);
    radius(to) = radius(from);
    rmass(to) = rmass(from);
    for (int k = 0; k < 4; k++) quat(to, k) = quat(from, k);
    pshape(to) = pshape(from);
    pscale(to) = pscale(from);
  }
};

template <class DeviceType> struct PolyPackExchange {
  typedef DeviceType device_type;
  typedef ArrayTypes<DeviceType> AT;
  PolyExchangeViews<DeviceType> a;
  typename AT::t_xfloat_2d_um buf;
  typename AT::t_int_1d_const sendlist, copylist;

  PolyPackExchange(AtomKokkos *atomKK, AtomVecPolyhedronKokkos *avec,
                   const DAT::tdual_xfloat_2d &k_buf, const DAT::tdual_int_1d &k_sendlist,
                   const DAT::tdual_int_1d &k_copylist) :
      a(atomKK, avec),
      sendlist(k_sendlist.view<DeviceType>()), copylist(k_copylist.view<DeviceType>())
  {
    const int elements = AtomVecPolyhedronKokkos::EXCHANGE_SIZE;
    const auto b = k_buf.view<DeviceType>();
    buf = typename AT::t_xfloat_2d_um(b.data(), (b.extent(0) * b.extent(1)) / elements, elements);
  }

  KOKKOS_INLINE_FUNCTION void operator()(const int &mysend) const
  {
    const int i = sendlist(mysend);
    int m = 0;
    buf(mysend, m++) = AtomVecPolyhedronKokkos::EXCHANGE_SIZE;
    for (int k = 0; k < 3; k++) buf(mysend, m++) = a.x(i, k);
    for (int k = 0; k < 3; k++) buf(mysend, m++) = a.v(i, k);
    buf(mysend, m++) = d_ubuf(a.tag(i)).d;
    buf(mysend, m++) = d_ubuf(a.type(i)).d;
    buf(mysend, m++) = d_ubuf(a.mask(i)).d;
    buf(mysend, m++) = d_ubuf(a.image(i)).d;
    buf(mysend, m++) = a.radius(i);
    buf(mysend, m++) = a.rmass(i);
    for (int k = 0; k < 3; k++) buf(mysend, m++) = a.omega(i, k);
    for (int k = 0; k < 3; k++) buf(mysend, m++) = a.angmom(i, k);
    for (int k = 0; k < 4; k++) buf(mysend, m++) = a.quat(i, k);
    buf(mysend, m++) = d_ubuf(a.pshape(i)).d;
    buf(mysend, m++) = a.pscale(i);
    const int j = copylist(mysend);
    if (j > -1) a.copy(j, i);
  }
};

template <class DeviceType> struct PolyUnpackExchange {
  typedef DeviceType device_type;
  typedef ArrayTypes<DeviceType> AT;
  PolyExchangeViews<DeviceType> a;
  typename AT::t_xfloat_2d_um buf;
  typename AT::t_int_1d nlocal;
  int dim;
  X_FLOAT lo, hi;

  PolyUnpackExchange(AtomKokkos *atomKK, AtomVecPolyhedronKokkos *avec,
                     const DAT::tdual_xfloat_2d &k_buf, const DAT::tdual_int_1d &k_nlocal, int dim_,
                     X_FLOAT lo_, X_FLOAT hi_) :
      a(atomKK, avec),
      nlocal(k_nlocal.view<DeviceType>()), dim(dim_), lo(lo_), hi(hi_)
  {
    const int elements = AtomVecPolyhedronKokkos::EXCHANGE_SIZE;
    const auto b = k_buf.view<DeviceType>();
    buf = typename AT::t_xfloat_2d_um(b.data(), (b.extent(0) * b.extent(1)) / elements, elements);
  }

  KOKKOS_INLINE_FUNCTION void operator()(const int &myrecv) const
  {
    const X_FLOAT xd = buf(myrecv, dim + 1);
    if (xd < lo || xd >= hi) return;
    const int i = Kokkos::atomic_fetch_add(&nlocal(0), 1);
    int m = 1;
    for (int k = 0; k < 3; k++) a.x(i, k) = buf(myrecv, m++);
    for (int k = 0; k < 3; k++) a.v(i, k) = buf(myrecv, m++);
    a.tag(i) = static_cast<tagint>(d_ubuf(buf(myrecv, m++)).i);
    a.type(i) = static_cast<int>(d_ubuf(buf(myrecv, m++)).i);
    a.mask(i) = static_cast<int>(d_ubuf(buf(myrecv, m++)).i);
    a.image(i) = static_cast<imageint>(d_ubuf(buf(myrecv, m++)).i);
    a.radius(i) = buf(myrecv, m++);
    a.rmass(i) = buf(myrecv, m++);
    for (int k = 0; k < 3; k++) a.omega(i, k) = buf(myrecv, m++);
    for (int k = 0; k < 3; k++) a.angmom(i, k) = buf(myrecv, m++);
    for (int k = 0; k < 4; k++) a.quat(i, k) = buf(myrecv, m++);
    a.pshape(i) = static_cast<int>(d_ubuf(buf(myrecv, m++)).i);
    a.pscale(i) = buf(myrecv, m++);
  }
};

}    // namespace

/* ======================================================================
   AtomVecPolyhedronKokkos
====================================================================== */

AtomVecPolyhedronKokkos::AtomVecPolyhedronKokkos(LAMMPS *lmp) :
    POLYDEM_KK_ATOMVEC_BASE(lmp) AtomVecKokkos(lmp), shapes(lmp, this)
{
  // e.g. a restart file written with -sf kk read without -k on
  if (!lmp->kokkos)
    error->all(FLERR, "atom_style polyhedron/kk requires Kokkos to be enabled (-k on); "
                      "use atom_style polyhedron without it");
  shapes.setup_style();

  // the device kernels above move exactly these fields (the host paths
  // follow the lists whatever they are): a change must reach the kernels
  using polydem_compat::fields_text;
  const std::pair<std::string, const char *> expected[] = {
      {fields_text(fields_comm), "quat"},
      {fields_text(fields_comm_vel), "quat omega angmom"},
      {fields_text(fields_border), "radius rmass quat pshape pscale"},
      {fields_text(fields_border_vel), "radius rmass quat pshape pscale omega angmom"},
      {fields_text(fields_exchange), "radius rmass omega angmom quat pshape pscale"}};
  for (auto &e : expected)
    if (e.first != e.second)
      error->all(FLERR,
                 "atom_style polyhedron/kk: atom_style polyhedron now communicates '{}' "
                 "instead of '{}'; update the Kokkos kernels",
                 e.first, e.second);

#if !POLYDEM_LAMMPS_NEW_API
  commKK = (CommKokkos *) comm;
#endif
  k_count = DAT::tdual_int_1d("polyhedron:count", 1);

  // device paths exist for ghost velocities too
  no_comm_vel_flag = 0;
  no_border_vel_flag = 0;
}

/* ----------------------------------------------------------------------
   AtomKokkos's destructor has already released the standard fields when
   the Atom dies; when only the atom style is replaced (read_restart after
   atom_style) they stay with AtomKokkos. Either way ~AtomVec must not
   memory->destroy() them: forget the field lists. The POLYDEM fields are
   ours: release the DualViews and the row pointers of quat.
------------------------------------------------------------------------- */

AtomVecPolyhedronKokkos::~AtomVecPolyhedronKokkos()
{
  memoryKK->destroy_kokkos(k_quat, atom->quat);
  memoryKK->destroy_kokkos(k_pshape, atom->pshape);
  memoryKK->destroy_kokkos(k_pscale, atom->pscale);
  release_fields();
}

/* ---------------------------------------------------------------------- */

void AtomVecPolyhedronKokkos::process_args(int narg, char **arg)
{
  shapes.process_args(narg, arg);
  setup_fields();
}

/* ---------------------------------------------------------------------- */

void AtomVecPolyhedronKokkos::init()
{
  AtomVecKokkos::init();

  // the device kernels hard-code the field lists of atom_style polyhedron
  if (size_forward != COMM_SIZE || size_velocity != COMM_VEL_SIZE - 3 ||
      size_border != BORDER_SIZE)
    error->all(FLERR,
               "atom_style polyhedron/kk: the communicated fields of atom_style polyhedron "
               "changed (forward {} velocity {} border {}); update the Kokkos kernels",
               size_forward, size_velocity, size_border);
  shapes.init();
}

/* ----------------------------------------------------------------------
   grow atom arrays; n = 0 grows by a chunk, n > 0 allocates n
------------------------------------------------------------------------- */

void AtomVecPolyhedronKokkos::grow(int n)
{
  const int step = MAX(LMP_KOKKOS_AV_DELTA, nmax * 0.01);
  if (n == 0) nmax += step;
  else nmax = n;
  atom->nmax = nmax;
  if (nmax < 0 || nmax > MAXSMALLINT) error->one(FLERR, "Per-processor system is too big");

  // resize with both copies current, device data authoritative (as LAMMPS's styles)
  atomKK->sync(Device, ALL_MASK);
  atomKK->modified(Device, ALL_MASK);

  memoryKK->grow_kokkos(atomKK->k_tag, atomKK->tag, nmax, "atom:tag");
  memoryKK->grow_kokkos(atomKK->k_type, atomKK->type, nmax, "atom:type");
  memoryKK->grow_kokkos(atomKK->k_mask, atomKK->mask, nmax, "atom:mask");
  memoryKK->grow_kokkos(atomKK->k_image, atomKK->image, nmax, "atom:image");
  memoryKK->grow_kokkos(atomKK->k_x, atomKK->x, nmax, "atom:x");
  memoryKK->grow_kokkos(atomKK->k_v, atomKK->v, nmax, "atom:v");
  memoryKK->grow_kokkos(atomKK->k_f, atomKK->f, nmax, "atom:f");
  memoryKK->grow_kokkos(atomKK->k_radius, atomKK->radius, nmax, "atom:radius");
  memoryKK->grow_kokkos(atomKK->k_rmass, atomKK->rmass, nmax, "atom:rmass");
  memoryKK->grow_kokkos(atomKK->k_omega, atomKK->omega, nmax, "atom:omega");
  memoryKK->grow_kokkos(atomKK->k_angmom, atomKK->angmom, nmax, "atom:angmom");
  memoryKK->grow_kokkos(atomKK->k_torque, atomKK->torque, nmax, "atom:torque");
  memoryKK->grow_kokkos(k_quat, atomKK->quat, nmax, "atom:quat");
  memoryKK->grow_kokkos(k_pshape, atomKK->pshape, nmax, "atom:pshape");
  memoryKK->grow_kokkos(k_pscale, atomKK->pscale, nmax, "atom:pscale");

  for (int iextra = 0; iextra < atom->nextra_grow; iextra++)
    modify->fix[atom->extra_grow[iextra]]->grow_arrays(nmax);

  grow_pointers();
  atomKK->sync(Host, ALL_MASK);
}

/* ----------------------------------------------------------------------
   pointers of LAMMPS's generic AtomVec code (host data)
------------------------------------------------------------------------- */

void AtomVecPolyhedronKokkos::grow_pointers()
{
  tag = atomKK->tag;
  type = atomKK->type;
  mask = atomKK->mask;
  image = atomKK->image;
  x = atomKK->x;
  v = atomKK->v;
  f = atomKK->f;
  h_x = atomKK->k_x.h_view;
  h_v = atomKK->k_v.h_view;
  h_f = atomKK->k_f.h_view;
}

/* ----------------------------------------------------------------------
   host paths: the generic AtomVec code, on current host data. on_host()
   syncs the fields of mask to the host, runs the call and, for a call that
   writes them (WRITES), marks them modified on the host.
------------------------------------------------------------------------- */

namespace {
enum HostAccess { READS, WRITES };
template <class F>
auto on_host(AtomKokkos *a, unsigned int mask, HostAccess access, F &&call) -> decltype(call())
{
  a->sync(Host, mask);
  struct Mark {
    AtomKokkos *a;
    unsigned int mask;
    bool on;
    ~Mark()
    {
      if (on) a->modified(Host, mask);
    }
  } mark{a, mask, access == WRITES};
  return call();
}
}    // namespace

void AtomVecPolyhedronKokkos::copy(int i, int j, int delflag)
{
  on_host(atomKK, EXCHANGE_MASK, WRITES, [&] { AtomVec::copy(i, j, delflag); });
}
int AtomVecPolyhedronKokkos::pack_comm(int n, int *list, double *buf, int pbc_flag, int *pbc)
{
  return on_host(atomKK, COMM_MASK, READS,
                 [&] { return AtomVec::pack_comm(n, list, buf, pbc_flag, pbc); });
}
void AtomVecPolyhedronKokkos::unpack_comm(int n, int first, double *buf)
{
  on_host(atomKK, COMM_MASK, WRITES, [&] { AtomVec::unpack_comm(n, first, buf); });
}
int AtomVecPolyhedronKokkos::pack_comm_vel(int n, int *list, double *buf, int pbc_flag, int *pbc)
{
  return on_host(atomKK, COMM_VEL_MASK, READS,
                 [&] { return AtomVec::pack_comm_vel(n, list, buf, pbc_flag, pbc); });
}
void AtomVecPolyhedronKokkos::unpack_comm_vel(int n, int first, double *buf)
{
  on_host(atomKK, COMM_VEL_MASK, WRITES, [&] { AtomVec::unpack_comm_vel(n, first, buf); });
}
int AtomVecPolyhedronKokkos::pack_reverse(int n, int first, double *buf)
{
  return on_host(atomKK, REVERSE_MASK, READS, [&] { return AtomVec::pack_reverse(n, first, buf); });
}
void AtomVecPolyhedronKokkos::unpack_reverse(int n, int *list, double *buf)
{
  on_host(atomKK, REVERSE_MASK, WRITES, [&] { AtomVec::unpack_reverse(n, list, buf); });
}
int AtomVecPolyhedronKokkos::pack_border(int n, int *list, double *buf, int pbc_flag, int *pbc)
{
  return on_host(atomKK, BORDER_MASK, READS,
                 [&] { return AtomVec::pack_border(n, list, buf, pbc_flag, pbc); });
}
void AtomVecPolyhedronKokkos::unpack_border(int n, int first, double *buf)
{
  on_host(atomKK, BORDER_MASK, WRITES, [&] { AtomVec::unpack_border(n, first, buf); });
}
int AtomVecPolyhedronKokkos::pack_border_vel(int n, int *list, double *buf, int pbc_flag, int *pbc)
{
  return on_host(atomKK, BORDER_VEL_MASK, READS,
                 [&] { return AtomVec::pack_border_vel(n, list, buf, pbc_flag, pbc); });
}
void AtomVecPolyhedronKokkos::unpack_border_vel(int n, int first, double *buf)
{
  on_host(atomKK, BORDER_VEL_MASK, WRITES, [&] { AtomVec::unpack_border_vel(n, first, buf); });
}
int AtomVecPolyhedronKokkos::pack_exchange(int i, double *buf)
{
  return on_host(atomKK, EXCHANGE_MASK, READS, [&] { return AtomVec::pack_exchange(i, buf); });
}
int AtomVecPolyhedronKokkos::unpack_exchange(double *buf)
{
  return on_host(atomKK, EXCHANGE_MASK, WRITES, [&] { return AtomVec::unpack_exchange(buf); });
}
int AtomVecPolyhedronKokkos::size_restart()
{
  return AtomVec::size_restart();
}
int AtomVecPolyhedronKokkos::pack_restart(int i, double *buf)
{
  return on_host(atomKK, EXCHANGE_MASK, READS, [&] { return AtomVec::pack_restart(i, buf); });
}
int AtomVecPolyhedronKokkos::unpack_restart(double *buf)
{
  return on_host(atomKK, EXCHANGE_MASK, WRITES, [&] { return AtomVec::unpack_restart(buf); });
}
void AtomVecPolyhedronKokkos::create_atom(int itype, double *coord)
{
  on_host(atomKK, STYLE_MASK, WRITES, [&] { AtomVec::create_atom(itype, coord); });
}
void AtomVecPolyhedronKokkos::data_atom(POLYDEM_DATA_ATOM_PARAMS(coord, imagetmp, values, label))
{
  on_host(atomKK, STYLE_MASK, WRITES,
          [&] { AtomVec::data_atom(POLYDEM_DATA_ATOM_ARGS(coord, imagetmp, values, label)); });
}
void AtomVecPolyhedronKokkos::pack_data(double **buf)
{
  on_host(atomKK, STYLE_MASK, READS, [&] { AtomVec::pack_data(buf); });
}
void AtomVecPolyhedronKokkos::write_data(FILE *fp, int n, double **buf)
{
  AtomVec::write_data(fp, n, buf);
}
void AtomVecPolyhedronKokkos::data_vel(int ilocal, polydem_compat::data_values values)
{
  on_host(atomKK, STYLE_MASK, WRITES, [&] {
    AtomVec::data_vel(ilocal, values);
    shapes.check_data_vel(ilocal);
  });
}
void AtomVecPolyhedronKokkos::pack_vel(double **buf)
{
  on_host(atomKK, STYLE_MASK, READS, [&] { AtomVec::pack_vel(buf); });
}
void AtomVecPolyhedronKokkos::write_vel(FILE *fp, int n, double **buf)
{
  AtomVec::write_vel(fp, n, buf);
}
double AtomVecPolyhedronKokkos::memory_usage()
{
  return AtomVec::memory_usage();
}

/* ----------------------------------------------------------------------
   per-atom semantics of the plain style: called from the generic code
   above (inside its sync/modified brackets) or, for the property hooks,
   by compute property/atom on the host
------------------------------------------------------------------------- */

void AtomVecPolyhedronKokkos::create_atom_post(int ilocal)
{
  shapes.create_atom_post(ilocal);
}

void AtomVecPolyhedronKokkos::data_atom_post(int ilocal)
{
  shapes.data_atom_post(ilocal);
}

void AtomVecPolyhedronKokkos::pack_data_pre(int ilocal)
{
  shapes.pack_data_pre(ilocal);
}

void AtomVecPolyhedronKokkos::pack_data_post(int ilocal)
{
  shapes.pack_data_post(ilocal);
}

int AtomVecPolyhedronKokkos::property_atom(polydem_compat::property_name name)
{
  return PolyShapeLibrary::property_atom(name);
}

void AtomVecPolyhedronKokkos::pack_property_atom(int index, double *buf, int nvalues, int groupbit)
{
  on_host(atomKK, STYLE_MASK, READS,
          [&] { shapes.pack_property_atom(index, buf, nvalues, groupbit); });
}

/* ======================================================================
   device paths
====================================================================== */

int AtomVecPolyhedronKokkos::pack_comm_kokkos(const int &n, const polydem_tdual_sendlist &list,
                                              POLYDEM_KK_ISWAP_REF const DAT::tdual_xfloat_2d &buf,
                                              const int &pbc_flag, const int pbc[])
{
  POLYDEM_KK_NO_ISWAP
  const Shift s = comm_shift(domain, pbc_flag, pbc);
  const X_FLOAT dv[3] = {0.0, 0.0, 0.0};
  const ExecutionSpace space = POLYDEM_KK_FORWARD_COMM_ON_HOST ? Host : Device;
  on_space(atomKK, space, COMM_MASK, 0, [&](auto on) {
    PolyPackComm<typename decltype(on)::type, 0> f(atomKK, k_quat, buf, list, iswap, pbc_flag, s,
                                                   0, dv);
    polydem_kk::for_range<typename decltype(on)::type::execution_space>(0, n, f);
  });
  return n * COMM_SIZE;
}

void AtomVecPolyhedronKokkos::unpack_comm_kokkos(const int &n, const int &first,
                                                 const DAT::tdual_xfloat_2d &buf)
{
  const ExecutionSpace space = POLYDEM_KK_FORWARD_COMM_ON_HOST ? Host : Device;
  on_space(atomKK, space, COMM_MASK, COMM_MASK, [&](auto on) {
    PolyUnpackComm<typename decltype(on)::type, 0> f(atomKK, k_quat, buf, first);
    polydem_kk::for_range<typename decltype(on)::type::execution_space>(0, n, f);
  });
}

int AtomVecPolyhedronKokkos::pack_comm_vel_kokkos(const int &n, const polydem_tdual_sendlist &list,
                                                  POLYDEM_KK_ISWAP_REF const DAT::tdual_xfloat_2d &buf,
                                                  const int &pbc_flag, const int pbc[])
{
  POLYDEM_KK_NO_ISWAP
  const Shift s = comm_shift(domain, pbc_flag, pbc);
  X_FLOAT dv[3];
  deform_dv(deform_vremap, h_rate, pbc_flag, pbc, dv);
  const int groupbit = deform_vremap ? deform_groupbit : 0;
  const ExecutionSpace space = POLYDEM_KK_FORWARD_COMM_ON_HOST ? Host : Device;
  on_space(atomKK, space, COMM_VEL_MASK, 0, [&](auto on) {
    PolyPackComm<typename decltype(on)::type, 1> f(atomKK, k_quat, buf, list, iswap, pbc_flag, s,
                                                   groupbit, dv);
    polydem_kk::for_range<typename decltype(on)::type::execution_space>(0, n, f);
  });
  return n * COMM_VEL_SIZE;
}

void AtomVecPolyhedronKokkos::unpack_comm_vel_kokkos(const int &n, const int &first,
                                                     const DAT::tdual_xfloat_2d &buf)
{
  const ExecutionSpace space = POLYDEM_KK_FORWARD_COMM_ON_HOST ? Host : Device;
  on_space(atomKK, space, COMM_VEL_MASK, COMM_VEL_MASK, [&](auto on) {
    PolyUnpackComm<typename decltype(on)::type, 1> f(atomKK, k_quat, buf, first);
    polydem_kk::for_range<typename decltype(on)::type::execution_space>(0, n, f);
  });
}

int AtomVecPolyhedronKokkos::pack_comm_self(const int &n, const polydem_tdual_sendlist &list,
                                            POLYDEM_KK_ISWAP_REF const int nfirst, const int &pbc_flag,
                                            const int pbc[])
{
  POLYDEM_KK_NO_ISWAP
  const Shift s = comm_shift(domain, pbc_flag, pbc);
  const ExecutionSpace space = POLYDEM_KK_FORWARD_COMM_ON_HOST ? Host : Device;
  on_space(atomKK, space, COMM_MASK, COMM_MASK, [&](auto on) {
    PolyCommSelf<typename decltype(on)::type> f(atomKK, k_quat, list, iswap, nfirst, pbc_flag, s);
    polydem_kk::for_range<typename decltype(on)::type::execution_space>(0, n, f);
  });
  return n * COMM_SIZE;
}

int AtomVecPolyhedronKokkos::pack_comm_self_fused(const int &n, const DAT::tdual_int_2d &list,
                                                  const DAT::tdual_int_1d &sendnum_scan,
                                                  const DAT::tdual_int_1d &firstrecv,
                                                  const DAT::tdual_int_1d &pbc_flag,
                                                  const DAT::tdual_int_2d &pbc,
                                                  const DAT::tdual_int_1d &g2l)
{
  const ExecutionSpace space = POLYDEM_KK_FORWARD_COMM_ON_HOST ? Host : Device;
  on_space(atomKK, space, COMM_MASK, COMM_MASK, [&](auto on) {
    PolyCommSelfFused<typename decltype(on)::type> f(atomKK, k_quat, list, pbc, pbc_flag,
                                                     firstrecv, sendnum_scan, g2l, domain);
    polydem_kk::for_range<typename decltype(on)::type::execution_space>(0, n, f);
  });
  return n * COMM_SIZE;
}

/* ---------------------------------------------------------------------- */

int AtomVecPolyhedronKokkos::pack_border_kokkos(int n, polydem_tdual_sendlist k_sendlist,
                                                DAT::tdual_xfloat_2d buf, POLYDEM_KK_ISWAP_INT int pbc_flag,
                                                int *pbc, ExecutionSpace space)
{
  POLYDEM_KK_NO_ISWAP
  const Shift s = border_shift(domain, pbc_flag, pbc);
  const X_FLOAT dv[3] = {0.0, 0.0, 0.0};
  // all fields, as LAMMPS's styles do: outside the run loop (auto_sync) this
  // is where host-side changes by input commands reach the device
  on_space(atomKK, space, ALL_MASK, 0, [&](auto on) {
    PolyPackBorder<typename decltype(on)::type, 0> f(atomKK, this, buf, k_sendlist, iswap,
                                                     pbc_flag, s, 0, dv, size_border);
    polydem_kk::for_range<typename decltype(on)::type::execution_space>(0, n, f);
  });
  return n * size_border;
}

void AtomVecPolyhedronKokkos::unpack_border_kokkos(const int &n, const int &first,
                                                   const DAT::tdual_xfloat_2d &buf,
                                                   ExecutionSpace space)
{
  while (first + n >= nmax) grow(0);
  on_space(atomKK, space, BORDER_MASK, BORDER_MASK, [&](auto on) {
    PolyUnpackBorder<typename decltype(on)::type, 0> f(atomKK, this, buf, first, size_border);
    polydem_kk::for_range<typename decltype(on)::type::execution_space>(0, n, f);
  });
}

// CommKokkos sizes a ghost-velocity border record as size_border + size_velocity
int AtomVecPolyhedronKokkos::pack_border_vel_kokkos(int n, polydem_tdual_sendlist k_sendlist,
                                                    DAT::tdual_xfloat_2d buf, POLYDEM_KK_ISWAP_INT
                                                    int pbc_flag, int *pbc, ExecutionSpace space)
{
  POLYDEM_KK_NO_ISWAP
  const Shift s = border_shift(domain, pbc_flag, pbc);
  X_FLOAT dv[3];
  deform_dv(deform_vremap, h_rate, pbc_flag, pbc, dv);
  const int groupbit = deform_vremap ? deform_groupbit : 0;
  const int stride = size_border + size_velocity;
  on_space(atomKK, space, ALL_MASK, 0, [&](auto on) {
    PolyPackBorder<typename decltype(on)::type, 1> f(atomKK, this, buf, k_sendlist, iswap,
                                                     pbc_flag, s, groupbit, dv, stride);
    polydem_kk::for_range<typename decltype(on)::type::execution_space>(0, n, f);
  });
  return n * stride;
}

void AtomVecPolyhedronKokkos::unpack_border_vel_kokkos(const int &n, const int &first,
                                                       const DAT::tdual_xfloat_2d &buf,
                                                       ExecutionSpace space)
{
  while (first + n >= nmax) grow(0);
  const int stride = size_border + size_velocity;
  on_space(atomKK, space, BORDER_VEL_MASK, BORDER_VEL_MASK, [&](auto on) {
    PolyUnpackBorder<typename decltype(on)::type, 1> f(atomKK, this, buf, first, stride);
    polydem_kk::for_range<typename decltype(on)::type::execution_space>(0, n, f);
  });
}

/* ---------------------------------------------------------------------- */

int AtomVecPolyhedronKokkos::pack_exchange_kokkos(const int &nsend, DAT::tdual_xfloat_2d &k_buf,
                                                  DAT::tdual_int_1d k_sendlist,
                                                  DAT::tdual_int_1d k_copylist,
                                                  ExecutionSpace space POLYDEM_KK_EXCHANGE_BOUNDS)
{
  const int width = k_buf.view<LMPHostType>().extent(1);
  if (nsend > (int) (k_buf.view<LMPHostType>().extent(0) * width) / EXCHANGE_SIZE) {
    const int newsize = nsend * (EXCHANGE_SIZE + 1) / width + 1;
    k_buf.resize(newsize, width);
  }
  on_space(atomKK, space, EXCHANGE_MASK, EXCHANGE_MASK, [&](auto on) {
    PolyPackExchange<typename decltype(on)::type> f(atomKK, this, k_buf, k_sendlist, k_copylist);
    polydem_kk::for_range<typename decltype(on)::type::execution_space>(0, nsend, f);
  });
  return nsend * EXCHANGE_SIZE;
}

int AtomVecPolyhedronKokkos::unpack_exchange_kokkos(DAT::tdual_xfloat_2d &k_buf, int nrecv,
                                                    int nlocal, int dim, X_FLOAT lo, X_FLOAT hi,
                                                    ExecutionSpace space POLYDEM_KK_EXCHANGE_INDICES)
{
  // room for every incoming atom (CommKokkos does not grow before unpacking)
  const int nincoming = nrecv / EXCHANGE_SIZE;
  while (nlocal + nincoming >= nmax) grow(0);

  atomKK->sync(space, EXCHANGE_MASK);
  k_count.h_view(0) = nlocal;
  if (space == Host) {
    k_count.modify<LMPHostType>();
    PolyUnpackExchange<LMPHostType> f(atomKK, this, k_buf, k_count, dim, lo, hi);
    polydem_kk::for_range<LMPHostType::execution_space>(0, nincoming, f);
  } else {
    k_count.modify<LMPHostType>();
    k_count.sync<LMPDeviceType>();
    PolyUnpackExchange<LMPDeviceType> f(atomKK, this, k_buf, k_count, dim, lo, hi);
    polydem_kk::for_range<LMPDeviceType::execution_space>(0, nincoming, f);
    k_count.modify<LMPDeviceType>();
    k_count.sync<LMPHostType>();
  }
  atomKK->modified(space, EXCHANGE_MASK);
  return k_count.h_view(0);
}

/* ======================================================================
   sync / modified: the DualViews of the fields in mask, one order for all
====================================================================== */

template <class F> void AtomVecPolyhedronKokkos::for_each_dual(unsigned int mask, F f)
{
  if (mask & X_MASK) f(atomKK->k_x);
  if (mask & V_MASK) f(atomKK->k_v);
  if (mask & F_MASK) f(atomKK->k_f);
  if (mask & TAG_MASK) f(atomKK->k_tag);
  if (mask & TYPE_MASK) f(atomKK->k_type);
  if (mask & MASK_MASK) f(atomKK->k_mask);
  if (mask & IMAGE_MASK) f(atomKK->k_image);
  if (mask & RADIUS_MASK) f(atomKK->k_radius);
  if (mask & RMASS_MASK) f(atomKK->k_rmass);
  if (mask & OMEGA_MASK) f(atomKK->k_omega);
  if (mask & ANGMOM_MASK) f(atomKK->k_angmom);
  if (mask & TORQUE_MASK) f(atomKK->k_torque);
  if (mask & POLYDEM_QUAT_MASK) f(k_quat);
  if (mask & POLYDEM_PSHAPE_MASK) f(k_pshape);
  if (mask & POLYDEM_PSCALE_MASK) f(k_pscale);
}

#if POLYDEM_LAMMPS_NEW_API
// atom sorting on the device (LAMMPS after 29 Sep 2021): every per-atom field
// of the style, in the order of the sorter's permutation
void AtomVecPolyhedronKokkos::sort_kokkos(Kokkos::BinSort<KeyViewType, BinOp> &Sorter)
{
  // ALL_MASK includes the POLYDEM fields' bits (polydem_kokkos_masks.h)
  atomKK->sync(Device, ALL_MASK & ~F_MASK & ~TORQUE_MASK);
  Sorter.sort(LMPDeviceType(), atomKK->k_tag.d_view);
  Sorter.sort(LMPDeviceType(), atomKK->k_type.d_view);
  Sorter.sort(LMPDeviceType(), atomKK->k_mask.d_view);
  Sorter.sort(LMPDeviceType(), atomKK->k_image.d_view);
  Sorter.sort(LMPDeviceType(), atomKK->k_x.d_view);
  Sorter.sort(LMPDeviceType(), atomKK->k_v.d_view);
  Sorter.sort(LMPDeviceType(), atomKK->k_radius.d_view);
  Sorter.sort(LMPDeviceType(), atomKK->k_rmass.d_view);
  Sorter.sort(LMPDeviceType(), atomKK->k_omega.d_view);
  Sorter.sort(LMPDeviceType(), atomKK->k_angmom.d_view);
  Sorter.sort(LMPDeviceType(), k_quat.d_view);
  Sorter.sort(LMPDeviceType(), k_pshape.d_view);
  Sorter.sort(LMPDeviceType(), k_pscale.d_view);
  atomKK->modified(Device, ALL_MASK & ~F_MASK & ~TORQUE_MASK);
}
#endif

void AtomVecPolyhedronKokkos::sync(ExecutionSpace space, unsigned int mask)
{
  if (space == Device)
    for_each_dual(mask, [](auto &k) {
      k.template sync<LMPDeviceType>();
    });
  else
    for_each_dual(mask, [](auto &k) {
      k.template sync<LMPHostType>();
    });
}

void AtomVecPolyhedronKokkos::modified(ExecutionSpace space, unsigned int mask)
{
  if (space == Device)
    for_each_dual(mask, [](auto &k) {
      k.template modify<LMPDeviceType>();
    });
  else
    for_each_dual(mask, [](auto &k) {
      k.template modify<LMPHostType>();
    });
}

void AtomVecPolyhedronKokkos::sync_overlapping_device(ExecutionSpace space, unsigned int mask)
{
  for_each_dual(mask, [&](auto &k) {
    const bool stale = space == Device ? k.template need_sync<LMPDeviceType>()
                                       : k.template need_sync<LMPHostType>();
    if (stale) perform_async_copy(k, space);
  });
}
