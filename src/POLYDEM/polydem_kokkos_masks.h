/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - data-mask bits for the per-atom fields POLYDEM adds to LAMMPS
   (quat, pshape, pscale), used with atomKK->sync()/modified() like the
   masks of LAMMPS's atom_masks.h. The bits are free there in LAMMPS
   29Sep2021 except for styles of other packages (0x02000000 is DUCHEM_MASK
   of DPD-REACT, which never meets atom_style polyhedron/kk); 0x04000000
   (DVECTOR_MASK) is avoided because AtomKokkos itself interprets it.
------------------------------------------------------------------------- */

#ifndef LMP_POLYDEM_KOKKOS_MASKS_H
#define LMP_POLYDEM_KOKKOS_MASKS_H

#define POLYDEM_QUAT_MASK 0x08000000
#define POLYDEM_PSHAPE_MASK 0x10000000
#define POLYDEM_PSCALE_MASK 0x02000000

// everything atom_style polyhedron/kk stores beyond the standard fields
#define POLYDEM_ALL_MASK (POLYDEM_QUAT_MASK | POLYDEM_PSHAPE_MASK | POLYDEM_PSCALE_MASK)

#endif
