/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - gathering a contact's body from per-atom arrays, for the entry
   points of polydem_contact_pipeline.h (pairs) and polydem_wall_pipeline.h
   (walls): its pose (centre, orientation, scale) and its motion (velocity,
   spin, mass, type). No LAMMPS includes; host and device.
------------------------------------------------------------------------- */

#ifndef POLYDEM_BODY_GATHER_H
#define POLYDEM_BODY_GATHER_H

#include "polydem_math.h"
#include "polydem_shape_view.h"

#include <type_traits>

namespace polydem {

// ---------------------------------------------------------------------------
// gathering a body from per-atom arrays: `atoms` has x, quat, v, omega
// (atoms.x(k, d)) and pscale, rmass, type, tag (atoms.rmass(k)): the Views
// of a /kk functor, or HostAtoms over the host arrays of a LAMMPS Atom

template <typename T> struct HostRows {
  T *const *a;
  T operator()(int k, int d) const { return a[k][d]; }
};
template <typename T> struct HostVals {
  const T *a;
  T operator()(int k) const { return a[k]; }
};
template <typename Tag> struct HostAtoms {
  HostRows<double> x, quat, v, omega;
  HostVals<double> pscale, rmass;
  HostVals<int> type;
  HostVals<Tag> tag;
};
template <class Atom> inline auto host_atoms(const Atom *atom)
{
  HostAtoms<std::remove_cv_t<std::remove_pointer_t<std::decay_t<decltype(atom->tag)>>>> a;
  a.x.a = atom->x;
  a.quat.a = atom->quat;
  a.v.a = atom->v;
  a.omega.a = atom->omega;
  a.pscale.a = atom->pscale;
  a.rmass.a = atom->rmass;
  a.type.a = atom->type;
  a.tag.a = atom->tag;
  return a;
}

template <typename T, class Atoms> POLYDEM_FN Pose<T> gather_pose(const Atoms &atoms, int k)
{
  Pose<T> p;
  p.x = make_vec3<T>(atoms.x(k, 0), atoms.x(k, 1), atoms.x(k, 2));
  p.q = make_quat<T>(atoms.quat(k, 0), atoms.quat(k, 1), atoms.quat(k, 2), atoms.quat(k, 3));
  p.s = atoms.pscale(k);
  return p;
}

// what every body carries besides its shape and pose: velocity, spin (lab),
// mass, type
template <typename T> struct BodyMotion {
  Vec3<T> v, w;
  T m;
  int type;
};

// velocity, spin, mass and type of atom k into a body
template <typename T, class Atoms>
POLYDEM_FN void gather_motion(const Atoms &atoms, int k, BodyMotion<T> &b)
{
  b.v = make_vec3<T>(atoms.v(k, 0), atoms.v(k, 1), atoms.v(k, 2));
  b.w = make_vec3<T>(atoms.omega(k, 0), atoms.omega(k, 1), atoms.omega(k, 2));
  b.m = atoms.rmass(k);
  b.type = atoms.type(k);
}

}    // namespace polydem

#endif
