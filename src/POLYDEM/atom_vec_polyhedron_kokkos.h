/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - atom_style polyhedron/kk: atom_style polyhedron with every
   per-atom field in a Kokkos DualView, and device kernels for forward
   (quat), ghost-velocity, border and exchange communication.

   Structure: AtomVecPolyhedronKokkos : AtomVecKokkos only, as LAMMPS's
   own /kk atom styles. The shape templates and the per-atom semantics of
   the plain style (field lists, create_atoms and read_data defaults and
   checks, write_data, property/atom) are the PolyShapeLibrary it owns, as
   atom_style polyhedron owns one: both forward their hooks to it, here
   inside the sync/modified brackets of the host paths. Other styles find
   the library with PolyShapeLibrary::of, the DualViews with
   AtomVecPolyhedronKokkos::of.
------------------------------------------------------------------------- */

#ifdef ATOM_CLASS
// clang-format off
AtomStyle(polyhedron/kk,AtomVecPolyhedronKokkos);
AtomStyle(polyhedron/kk/device,AtomVecPolyhedronKokkos);
AtomStyle(polyhedron/kk/host,AtomVecPolyhedronKokkos);
// clang-format on
#else

#ifndef LMP_ATOM_VEC_POLYHEDRON_KOKKOS_H
#define LMP_ATOM_VEC_POLYHEDRON_KOKKOS_H

#include "atom.h"
#include "atom_vec_kokkos.h"
#include "kokkos_type.h"
#include "poly_shape_library.h"
#include "polydem_kokkos_compat.h"
#include "polydem_kokkos_masks.h"

#include <type_traits>
#include <utility>

namespace LAMMPS_NS {

// quaternions (w,x,y,z): LayoutRight so that atom->quat (double **) can
// alias the host rows, as for x, v, f
typedef Kokkos::DualView<double *[4], Kokkos::LayoutRight, LMPDeviceType> tdual_quat_array;

// the view of a DualView in the memory space of DeviceType
template <class DualViewType, class DeviceType>
using polydem_view_t = typename std::decay<decltype(
    std::declval<DualViewType &>().template view<DeviceType>())>::type;

class AtomVecPolyhedronKokkos : public AtomVecKokkos, public ShapeLibraryOwner {
 public:
  AtomVecPolyhedronKokkos(class LAMMPS *);
  ~AtomVecPolyhedronKokkos() override;

  // the /kk atom style of atom, or nullptr
  static AtomVecPolyhedronKokkos *of(class Atom *atom)
  {
    return dynamic_cast<AtomVecPolyhedronKokkos *>(atom->avec);
  }
  PolyShapeLibrary *shape_library() override { return &shapes; }

  // POLYDEM per-atom fields (the standard ones are in AtomKokkos)
  tdual_quat_array k_quat;
  DAT::tdual_int_1d k_pshape;
  DAT::tdual_float_1d k_pscale;

  void process_args(int, char **) override;
  void init() override;
  void grow(int) override;
  void grow_pointers() override;
  void copy(int, int, int) override;

  // host (classic) paths: LAMMPS's generic field machinery on host data,
  // bracketed by sync(Host)/modified(Host)
  int pack_comm(int, int *, double *, int, int *) override;
  int pack_comm_vel(int, int *, double *, int, int *) override;
  void unpack_comm(int, int, double *) override;
  void unpack_comm_vel(int, int, double *) override;
  int pack_reverse(int, int, double *) override;
  void unpack_reverse(int, int *, double *) override;
  int pack_border(int, int *, double *, int, int *) override;
  int pack_border_vel(int, int *, double *, int, int *) override;
  void unpack_border(int, int, double *) override;
  void unpack_border_vel(int, int, double *) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(double *) override;
  int size_restart() override;
  int pack_restart(int, double *) override;
  int unpack_restart(double *) override;
  void create_atom(int, double *) override;
  void data_atom(POLYDEM_DATA_ATOM_PARAMS(, , , )) override;
  void pack_data(double **) override;
  void write_data(FILE *, int, double **) override;
  void data_vel(int, polydem_compat::data_values) override;
  void pack_vel(double **) override;
  void write_vel(FILE *, int, double **) override;
  double memory_usage() override;

  // per-atom semantics of the plain style (PolyShapeLibrary)
  void create_atom_post(int) override;
  void data_atom_post(int) override;
  void pack_data_pre(int) override;
  void pack_data_post(int) override;
  int property_atom(polydem_compat::property_name) override;
  void pack_property_atom(int, double *, int, int) override;

  // device paths
  int pack_comm_kokkos(const int &n, const polydem_tdual_sendlist &list, POLYDEM_KK_ISWAP_REF
                       const DAT::tdual_xfloat_2d &buf, const int &pbc_flag,
                       const int pbc[]) override;
  void unpack_comm_kokkos(const int &n, const int &nfirst,
                          const DAT::tdual_xfloat_2d &buf) override;
  int pack_comm_vel_kokkos(const int &n, const polydem_tdual_sendlist &list, POLYDEM_KK_ISWAP_REF
                           const DAT::tdual_xfloat_2d &buf, const int &pbc_flag,
                           const int pbc[]) override;
  void unpack_comm_vel_kokkos(const int &n, const int &nfirst,
                              const DAT::tdual_xfloat_2d &buf) override;
  int pack_comm_self(const int &n, const polydem_tdual_sendlist &list, POLYDEM_KK_ISWAP_REF
                     const int nfirst, const int &pbc_flag, const int pbc[]) override;
  int pack_comm_self_fused(const int &n, const DAT::tdual_int_2d &list,
                           const DAT::tdual_int_1d &sendnum_scan,
                           const DAT::tdual_int_1d &firstrecv,
                           const DAT::tdual_int_1d &pbc_flag, const DAT::tdual_int_2d &pbc,
                           const DAT::tdual_int_1d &g2l) override;
  int pack_border_kokkos(int n, polydem_tdual_sendlist k_sendlist, DAT::tdual_xfloat_2d buf,
                         POLYDEM_KK_ISWAP_INT int pbc_flag, int *pbc, ExecutionSpace space) override;
  void unpack_border_kokkos(const int &n, const int &nfirst, const DAT::tdual_xfloat_2d &buf,
                            ExecutionSpace space) override;
  int pack_border_vel_kokkos(int n, polydem_tdual_sendlist k_sendlist, DAT::tdual_xfloat_2d buf,
                             POLYDEM_KK_ISWAP_INT int pbc_flag, int *pbc,
                             ExecutionSpace space) override;
  void unpack_border_vel_kokkos(const int &n, const int &nfirst,
                                const DAT::tdual_xfloat_2d &buf, ExecutionSpace space) override;
  int pack_exchange_kokkos(const int &nsend, DAT::tdual_xfloat_2d &buf,
                           DAT::tdual_int_1d k_sendlist, DAT::tdual_int_1d k_copylist,
                           ExecutionSpace space POLYDEM_KK_EXCHANGE_BOUNDS) override;
  int unpack_exchange_kokkos(DAT::tdual_xfloat_2d &k_buf, int nrecv, int nlocal, int dim,
                             X_FLOAT lo, X_FLOAT hi,
                             ExecutionSpace space POLYDEM_KK_EXCHANGE_INDICES) override;

#if POLYDEM_LAMMPS_NEW_API
  void sort_kokkos(Kokkos::BinSort<KeyViewType, BinOp> &Sorter) override;
#endif
  void sync(ExecutionSpace space, unsigned int mask) override;
  void modified(ExecutionSpace space, unsigned int mask) override;
  void sync_overlapping_device(ExecutionSpace space, unsigned int mask) override;

  // values per atom of the device buffers (checked against the generic
  // sizes in init(); the host and device paths carry the same fields)
  static constexpr int COMM_SIZE = 7;         // x, quat
  static constexpr int COMM_VEL_SIZE = 16;    // x, v, quat, omega, angmom
  static constexpr int BORDER_SIZE = 14;      // x, tag, type, mask, radius, rmass, quat, pshape, pscale
  static constexpr int BORDER_VEL_EXTRA = 9;    // v, omega, angmom
  static constexpr int EXCHANGE_SIZE = 25;    // count, x, v, tag, type, mask, image, radius, rmass,
                                              // omega, angmom, quat, pshape, pscale

 private:
  PolyShapeLibrary shapes;
  template <class F> void for_each_dual(unsigned int mask, F f);    // f(DualView) per field
  // forget the field lists so that ~AtomVec frees nothing: AtomKokkos owns
  // the standard DualViews, this class the POLYDEM ones
  void release_fields() { ngrow = 0; }

  DAT::tdual_int_1d k_count;
};

}    // namespace LAMMPS_NS

#endif
#endif
