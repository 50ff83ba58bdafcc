/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - the differences of LAMMPS's host API between the versions
   POLYDEM builds against: 29 Sep 2021 (Debian bookworm), 4 Feb 2025
   (trixie), 4 Jul 2026 (sid). POLYDEM_LAMMPS_VERSION (YYYYMMDD) comes from
   the LAMMPS tree's src/version.h, read by cmake/PolydemLammps.cmake.
   Only the API differences live here; the styles themselves are one code.
------------------------------------------------------------------------- */

#ifndef LMP_POLYDEM_LAMMPS_COMPAT_H
#define LMP_POLYDEM_LAMMPS_COMPAT_H

#include "polydem_lammps_version.h"

#include "comm.h"
#include "domain.h"
#include "neigh_request.h"
#include "neighbor.h"
#include "utils.h"

#include <string>
#include <vector>

// 24 Mar 2022 reworked the neighbor requests (Neighbor::add_request, the
// NeighRequest members protected), Domain's region list (get_region_by_id),
// AtomVec's field lists (std::vector<std::string>) and the data-file
// hooks (values as std::vector<std::string>).
#define POLYDEM_LAMMPS_NEW_API (POLYDEM_LAMMPS_VERSION >= 20220324)

// Region::extent_* of a moving (dynamic) region follow its motion (after
// 4 Feb 2025; 4 Jul 2026 has it): Region::bbox_update, called by prematch
#define POLYDEM_LAMMPS_REGION_EXTENT_MOVES (POLYDEM_LAMMPS_VERSION > 20250204)

// Pair::transfer_history also gets the two atom types (after 29 Sep 2021):
//   void transfer_history(double *, double * POLYDEM_TRANSFER_HISTORY_TYPES) override;
#if POLYDEM_LAMMPS_NEW_API
#define POLYDEM_TRANSFER_HISTORY_TYPES , int, int
#else
#define POLYDEM_TRANSFER_HISTORY_TYPES
#endif

// AtomVec::data_atom: the values of an Atoms line, and (since 24 Mar 2022)
// the type label; declare with POLYDEM_DATA_ATOM_PARAMS(coord, image, values,
// label), forward with POLYDEM_DATA_ATOM_ARGS(...)
#if POLYDEM_LAMMPS_NEW_API
#define POLYDEM_DATA_ATOM_PARAMS(coord, image, values, label) \
  double *coord, imageint image, const std::vector<std::string> &values, std::string &label
#define POLYDEM_DATA_ATOM_ARGS(coord, image, values, label) coord, image, values, label
#else
#define POLYDEM_DATA_ATOM_PARAMS(coord, image, values, label) \
  double *coord, imageint image, char **values
#define POLYDEM_DATA_ATOM_ARGS(coord, image, values, label) coord, image, values
#endif

namespace LAMMPS_NS {
class Fix;
class Pair;
class Region;

namespace polydem_compat {

#if POLYDEM_LAMMPS_NEW_API
// AtomVec::data_vel / data_atom_bonus ... values of one data-file line
using data_values = const std::vector<std::string> &;
// AtomVec::property_atom's argument
using property_name = const std::string &;
#else
using data_values = char **;
using property_name = char *;
#endif

// AtomVec::fields_*: a space-separated list of per-atom field names
inline void set_fields(char *&field, const char *names)
{
  field = const_cast<char *>(names);
}
inline void set_fields(std::vector<std::string> &field, const char *names)
{
  field = utils::split_words(names);
}

// the field names of an AtomVec::fields_* list, space-separated
inline std::string fields_text(const char *field)
{
  return field ? field : "";
}
inline std::string fields_text(const std::vector<std::string> &field)
{
  std::string text;
  for (const auto &f : field) text += (text.empty() ? "" : " ") + f;
  return text;
}

// a pair style's half neighbor list with the size flag (finite-size
// particles), optionally with per-pair history (fix NEIGH_HISTORY);
// returns the request
inline NeighRequest *request_size_list(Neighbor *neighbor, Pair *pair, int instance_me,
                                       bool history)
{
#if POLYDEM_LAMMPS_NEW_API
  (void) instance_me;
  return neighbor->add_request(pair, NeighConst::REQ_SIZE |
                                         (history ? NeighConst::REQ_HISTORY : 0));
#else
  const int irequest = neighbor->request(pair, instance_me);
  neighbor->requests[irequest]->size = 1;
  if (history) neighbor->requests[irequest]->history = 1;
  return neighbor->requests[irequest];
#endif
}

// the /kk pair styles: the request the plain init_style just made, turned
// into a half list of Kokkos (host or device)
inline void request_kokkos_half_list(Neighbor *neighbor, Pair *pair, bool host, bool device)
{
#if POLYDEM_LAMMPS_NEW_API
  NeighRequest *req = neighbor->find_request(pair);
  req->set_kokkos_host(host ? 1 : 0);
  req->set_kokkos_device(device ? 1 : 0);    // half: the default since 24 Mar 2022
#else
  (void) pair;
  const int irequest = neighbor->nrequest - 1;
  neighbor->requests[irequest]->kokkos_host = host;
  neighbor->requests[irequest]->kokkos_device = device;
  neighbor->requests[irequest]->full = 0;
  neighbor->requests[irequest]->half = 1;
#endif
}

// reverse communication of a fix: a fixed number of values per atom (size,
// 0: the fix's comm_reverse), and a number the fix's pack_reverse_comm_size
// tells per swap
inline void reverse_comm_fix(Comm *comm, Fix *fix, int size)
{
#if POLYDEM_LAMMPS_NEW_API
  comm->reverse_comm(fix, size);
#else
  comm->reverse_comm_fix(fix, size);
#endif
}
inline void reverse_comm_fix_variable(Comm *comm, Fix *fix)
{
#if POLYDEM_LAMMPS_NEW_API
  comm->reverse_comm_variable(fix);
#else
  comm->reverse_comm_fix_variable(fix);
#endif
}

// the region with this ID, nullptr when there is none
inline Region *find_region(Domain *domain, const std::string &id)
{
#if POLYDEM_LAMMPS_NEW_API
  return domain->get_region_by_id(id);
#else
  const int iregion = domain->find_region(id.c_str());
  return iregion < 0 ? nullptr : domain->regions[iregion];
#endif
}

}    // namespace polydem_compat
}    // namespace LAMMPS_NS

#endif
