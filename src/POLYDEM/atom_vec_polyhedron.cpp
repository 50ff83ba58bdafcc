/* ----------------------------------------------------------------------
   POLYDEM - atom_style polyhedron: LAMMPS's generic AtomVec machinery on
   the fields of PolyShapeLibrary::setup_style, whose hooks it forwards
------------------------------------------------------------------------- */

#include "atom_vec_polyhedron.h"

using namespace LAMMPS_NS;

/* ---------------------------------------------------------------------- */

AtomVecPolyhedron::AtomVecPolyhedron(LAMMPS *lmp) : AtomVec(lmp), shapes(lmp, this)
{
  shapes.setup_style();
}

void AtomVecPolyhedron::process_args(int narg, char **arg)
{
  shapes.process_args(narg, arg);
  setup_fields();
}

void AtomVecPolyhedron::init()
{
  AtomVec::init();
  shapes.init();
}

/* ---------------------------------------------------------------------- */

void AtomVecPolyhedron::create_atom_post(int ilocal)
{
  shapes.create_atom_post(ilocal);
}

void AtomVecPolyhedron::data_atom_post(int ilocal)
{
  shapes.data_atom_post(ilocal);
}

void AtomVecPolyhedron::data_vel(int ilocal, polydem_compat::data_values values)
{
  AtomVec::data_vel(ilocal, values);
  shapes.check_data_vel(ilocal);
}

void AtomVecPolyhedron::pack_data_pre(int ilocal)
{
  shapes.pack_data_pre(ilocal);
}

void AtomVecPolyhedron::pack_data_post(int ilocal)
{
  shapes.pack_data_post(ilocal);
}

int AtomVecPolyhedron::property_atom(polydem_compat::property_name name)
{
  return PolyShapeLibrary::property_atom(name);
}

void AtomVecPolyhedron::pack_property_atom(int index, double *buf, int nvalues, int groupbit)
{
  shapes.pack_property_atom(index, buf, nvalues, groupbit);
}
