/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - per-pair contact history of pair_style polyhedron and
   ellipsoid: LAMMPS's FixNeighHistory with a restart write that leaves the
   run after a write_restart command unchanged (issue 32 item 2). The /kk
   history fix (polydem_history_kokkos.h) takes the same write.
------------------------------------------------------------------------- */

#ifndef POLYDEM_HISTORY_H
#define POLYDEM_HISTORY_H

#include "comm.h"
#include "fix_neigh_history.h"
#include "modify.h"
#include "update.h"
#include "utils.h"

#include <cstdio>
#include <string>

namespace polydem_history {

using namespace LAMMPS_NS;

// FixNeighHistory::write_restart copies the history out of the neighbor
// list (pre_exchange) before the per-atom arrays are written. During a run
// (restart output) the list is current. Between runs post_run has made that
// copy already, and the write_restart command has since wrapped the atoms
// into the periodic box and rebuilt the ghosts (Comm::exchange, borders),
// so the list's ghost indices name other atoms: the copy gave frictional
// contacts across a periodic boundary another pair's history, in the file
// and in the run that continued (LAMMPS 29 Sep 2021, whose core pair
// gran/hooke/history shows the same, and 4 Feb 2025 make that copy). Copy
// during a run only.
template <class Base> class RestartBetweenRuns : public Base {
 public:
  using Base::Base;
  void write_restart(FILE *fp) override
  {
    if (this->update->whichflag) this->pre_exchange();
    if (this->comm->me == 0) {
      int size = 0;
      fwrite(&size, sizeof(int), 1, fp);
    }
  }
};

// the plain styles' history fix. Restart files name it by LAMMPS's style
// NEIGH_HISTORY, so files written before and after it was introduced are
// read alike.
class FixNeighHistoryPolydem : public RestartBetweenRuns<FixNeighHistory> {
 public:
  FixNeighHistoryPolydem(LAMMPS *lmp, int narg, char **arg) :
      RestartBetweenRuns<FixNeighHistory>(lmp, narg, arg)
  {
    delete[] style;
    style = utils::strdup("NEIGH_HISTORY");
  }
  static Fix *create(LAMMPS *lmp, int narg, char **arg)
  {
    return new FixNeighHistoryPolydem(lmp, narg, arg);
  }
};

// Replaces the pair style's placeholder fix dummy_id by the history fix id
// with nvalues per pair (registered under a run-time style name).
inline FixNeighHistory *create_history_fix(Modify *modify, const std::string &id,
                                           const std::string &dummy_id, int nvalues)
{
  const std::string style = "NEIGH_HISTORY/POLYDEM";
  (*modify->fix_map)[style] = &FixNeighHistoryPolydem::create;
  const std::string cmd = id + " all " + style + " " + std::to_string(nvalues);
  return (FixNeighHistory *) modify->replace_fix(dummy_id, cmd, 1);
}

}    // namespace polydem_history

#endif
