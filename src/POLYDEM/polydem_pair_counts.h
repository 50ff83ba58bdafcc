/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - the kernel counters of the pair styles, in the order the
   contact pipeline (polydem_contact_pipeline.h) increments them and the
   styles sum, report and print them (no LAMMPS, host and device)
------------------------------------------------------------------------- */

#ifndef POLYDEM_PAIR_COUNTS_H
#define POLYDEM_PAIR_COUNTS_H

namespace polydem {

// pair polyhedron's counters (PairPolyhedron::counters, plain and /kk)
enum PolyhedronPairCount : int {
  PP_OVERFLOW,      // overlap workspace overflows (contact skipped)
  PP_DEGENERATE,    // degenerate overlaps (contact skipped)
  PP_NOCONV,        // GJK non-convergences (overlap computed anyway)
  PP_BIGOVERLAP,    // V > overlap_warn x smaller volume
  PP_NOSLOT,        // part contacts of composites beyond the pair's slots (no history)
  PP_NOBRIDGE,      // bridge-law contacts without a bridge (unequal ellipsoids, also parts)
  PP_DAMPCAP,       // contact-steps with the normal damping capped at m_eff / dt
  PP_CONTACTS,      // pair-steps in contact
  PP_NCOUNT
};

// pair ellipsoid's counters (PairEllipsoid::counters, plain and /kk)
enum EllipsoidPairCount : int {
  EP_DEGENERATE,    // coincident centres or NaN (skipped)
  EP_NOCONV,        // contact search without convergence (skipped)
  EP_BIGOVERLAP,    // delta > overlap_warn x smallest semi-axis
  EP_DAMPCAP,       // contact-steps whose normal dashpot was capped at m_eff / dt (x share)
  EP_CONTACTS,      // pair-steps in contact (x share)
  EP_COLLISIONS,    // contacts in their first step, delta < (d delta/dt) dt (x share)
  EP_NCOUNT
};

}    // namespace polydem

#endif
