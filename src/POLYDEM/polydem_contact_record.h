/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - per-contact record stored by pair polyhedron (plain and /kk) on
   the steps a contact compute needs it (compute contact/polyhedron/local,
   compute contact/polyhedron). Plain doubles so that the /kk style fills
   the same layout on the device. No LAMMPS includes; host and device.
------------------------------------------------------------------------- */

#ifndef POLYDEM_CONTACT_RECORD_H
#define POLYDEM_CONTACT_RECORD_H

#include "polydem_contact_law.h"

namespace polydem {

// field offsets in one record of CR_NFIELD doubles
enum ContactRecordField {
  CR_MASK1,      // group masks of i and j (for the compute's group)
  CR_MASK2,
  CR_VOL,        // overlap volume V
  CR_VMIN,       // smaller particle volume (V/VMIN: overlap fraction)
  CR_ID1,        // atom ID of i (the atom whose force is F)
  CR_ID2,        // atom ID of j
  CR_AREA,       // contact area A_n = |S_A|
  CR_F,          // 3: force on i from j (elastic + damping + friction)
  CR_N = CR_F + 3,    // 3: unit normal from i towards j
  CR_C = CR_N + 3,    // 3: contact point (centroid of the overlap; i's image)
  CR_FN = CR_C + 3,    // normal force magnitude (elastic + damping)
  CR_FT,         // tangential force magnitude
  CR_ENERGY,     // W(V)
  CR_NFIELD
};
// A summary record is the first CR_NSUMMARY fields (masks, V, V_min): all
// compute contact/polyhedron reads. The pair stores summaries (32 B instead
// of 152 B per contact) where no compute contact/polyhedron/local is
// defined.
constexpr int CR_NSUMMARY = CR_VMIN + 1;

// Each contact is stored once over all ranks: with newton off a pair with a
// ghost j is computed on the ranks of both atoms; keep it where tag i < tag j
// (equal tags: periodic self-image, keep the copy whose j lies above i).
POLYDEM_FN bool contact_owned(bool newton_pair, bool j_is_local, long tag_i, long tag_j,
                              const double *xi, const double *xj)
{
  if (newton_pair || j_is_local) return true;
  if (tag_i != tag_j) return tag_i < tag_j;
  if (xj[2] != xi[2]) return xj[2] > xi[2];
  if (xj[1] != xi[1]) return xj[1] > xi[1];
  return xj[0] > xi[0];
}

// both atoms of record r in the group of groupbit
inline bool contact_in_group(const double *r, int groupbit)
{
  return ((int) r[CR_MASK1] & groupbit) && ((int) r[CR_MASK2] & groupbit);
}

template <typename T>
POLYDEM_FN void fill_contact_record(double *r, long tag_i, long tag_j, int mask_i, int mask_j,
                                    T vmin, const ContactGeometry<T> &g, const ContactForce<T> &f)
{
  r[CR_ID1] = (double) tag_i;
  r[CR_ID2] = (double) tag_j;
  r[CR_MASK1] = (double) mask_i;
  r[CR_MASK2] = (double) mask_j;
  r[CR_VOL] = g.volume;
  r[CR_VMIN] = vmin;
  r[CR_AREA] = g.area;
  r[CR_F + 0] = f.F_A.x;
  r[CR_F + 1] = f.F_A.y;
  r[CR_F + 2] = f.F_A.z;
  r[CR_N + 0] = g.normal.x;
  r[CR_N + 1] = g.normal.y;
  r[CR_N + 2] = g.normal.z;
  r[CR_C + 0] = g.centroid.x;
  r[CR_C + 1] = g.centroid.y;
  r[CR_C + 2] = g.centroid.z;
  r[CR_FN] = f.fn;
  r[CR_FT] = f.ft;
  r[CR_ENERGY] = f.energy;
}

}    // namespace polydem

#endif
