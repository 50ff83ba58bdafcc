/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - a style's LawTable (polydem_law_table.h) on the device: its
   entries copied to a View that the /kk style keeps, and the same table
   pointing into it (what the /kk functors hold).
------------------------------------------------------------------------- */

#ifndef POLYDEM_LAW_TABLE_KOKKOS_H
#define POLYDEM_LAW_TABLE_KOKKOS_H

#include "polydem_law_table.h"

#include <Kokkos_Core.hpp>

namespace polydem_kk {

template <class DeviceType>
using LawEntryView = Kokkos::View<polydem::LawEntry<double> *, DeviceType>;

template <class DeviceType>
polydem::LawTable<double> mirror_law_table(const polydem::LawTable<double> &host,
                                           LawEntryView<DeviceType> &d)
{
  d = LawEntryView<DeviceType>("polydem:law_table", host.nentry > 0 ? host.nentry : 1);
  auto m = Kokkos::create_mirror_view(d);
  for (int k = 0; k < host.nentry; k++) m(k) = host.entry[k];
  Kokkos::deep_copy(d, m);
  polydem::LawTable<double> t = host;
  t.entry = d.data();
  return t;
}

}    // namespace polydem_kk

#endif
