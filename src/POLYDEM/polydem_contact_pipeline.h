/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - the per-contact pipeline: one entry point per contact kind,
   called alike by the plain and the /kk loop of its style, which only
   gather the two bodies, call, and scatter/tally what comes back.
   No LAMMPS includes; host and device (no allocation, no virtual calls,
   bounded loops).

     polyhedron_pair_contact  pair polyhedron:  GJK -> overlap polyhedron
                              (polydem_overlap.h), or the exact overlap of
                              a polyhedron and a sphere or ellipsoid, or of
                              two spheres (polydem_ellipsoid_overlap.h)
                              -> Feng law; composites part pair by part
                              pair (composite_pair_contact), each with its
                              keyed history slot
     ellipsoid_pair_contact   pair ellipsoid:   characteristic quartic and
                              contact point (polydem_ellipsoid_force.h) ->
                              linear law
     algebraic_contact_step   pair polyhedron's two ellipsoids of which one has
                              unequal semi-axes: pair ellipsoid's kernel and law

   (fix wall/mesh's entry point, wall_body_contact, is in
   polydem_wall_pipeline.h; both gather their bodies with
   polydem_body_gather.h.)

   Each runs pose -> geometry -> counters -> law (from the LawTable) ->
   kinematics -> contact_step (polydem_contact_law.h) on the contact's
   history slot, and returns the force, torques and energy; its kernel
   counters are added to the caller's array (indices PP_*, EP_*). A new
   contact kind is one more entry point here.

   The law of each contact comes from the style's LawTable (polydem_law_table.h);
   the liquid bridges of non-spherical pairs from polydem_bridge_geometry.h.
------------------------------------------------------------------------- */

#ifndef POLYDEM_CONTACT_PIPELINE_H
#define POLYDEM_CONTACT_PIPELINE_H

#include "polydem_body_gather.h"
#include "polydem_bridge_geometry.h"
#include "polydem_ellipsoid_overlap.h"
#include "polydem_law_table.h"
#include "polydem_overlap.h"
#include "polydem_pair_counts.h"

namespace polydem {

// ---------------------------------------------------------------------------
// pairs

// what a pair entry point returns: contact = 0: none (the history slot was
// cleared, nothing to scatter); else the geometry, the forces on A and B,
// and the smaller body measure (polyhedra: volume, for contact records)
template <typename T> struct PairContactResult {
  int contact;
  ContactGeometry<T> geo;
  ContactForce<T> cf;
  T vmin;
};

// no contact: the pair's history ends (hist may be null: none kept)
template <typename T> POLYDEM_FN void history_release(T *hist, int n)
{
  if (hist)
    for (int k = 0; k < n; ++k) hist[k] = T(0);
}

// A pair's body: the template at its pose (make_posed; the ShapeView it
// points to outlives the body), its motion, its tag.
template <typename T> struct PolyhedronBody : BodyMotion<T> {
  PosedShape<T> shape;
  long tag;
};

// The overlap of a pair of which at least one is an ellipsoid template
// (view_is_ellipsoid): a polyhedron and an ellipsoid (either order), two
// spheres; two ellipsoids of which one has unequal semi-axes are
// STATUS_UNSUPPORTED (pair_style polyhedron refuses them at its init).
template <typename T>
POLYDEM_FN OverlapResult<T> mixed_pair_overlap(const PosedShape<T> &A, const PosedShape<T> &B)
{
  const T *aa = A.view->axes, *ab = B.view->axes;
  const bool ea = view_is_ellipsoid(*A.view), eb = view_is_ellipsoid(*B.view);
  if (ea && eb) {
    const T ra = posed_sphere_radius(A), rb = posed_sphere_radius(B);
    if (ra > T(0) && rb > T(0)) return sphere_pair_overlap(A.x, ra, B.x, rb);
    OverlapResult<T> r = ellipsoid_overlap_detail::no_overlap<T>();
    r.status = STATUS_UNSUPPORTED;
    return r;
  }
  if (eb) return polyhedron_ellipsoid_overlap(A, B.x, B.R, B.s * make_vec3(ab[0], ab[1], ab[2]));
  // A is the ellipsoid: B against A, the roles swapped back
  OverlapResult<T> r = polyhedron_ellipsoid_overlap(B, A.x, A.R, A.s * make_vec3(aa[0], aa[1], aa[2]));
  const Vec3<T> m = r.M_A;
  r.S_A = -r.S_A;
  r.normal = -r.normal;
  r.M_A = r.M_B;
  r.M_B = m;
  return r;
}

// A polyhedron pair that is not in contact holds no contact history; its
// history slot keeps GJK's separating axis instead (GJK_AXIS_VALUES values:
// the axis, A's and B's support vertices), which decides most such pairs at
// the next step without GJK (gjk_axis_separates). A contact starts from a
// cleared slot.
constexpr int GJK_AXIS_VALUES = 5;

// The overlap of two convex shapes (polyhedra, spheres, ellipsoids):
// status counted in count[PP_*]; GJK (a filter for polyhedron pairs) is
// skipped if touching. axis (or null): the GJK_AXIS_VALUES values of a pair
// not touching, read and, where the pair is apart along an axis, written;
// cleared otherwise.
template <typename T, int MF, typename C>
POLYDEM_FN OverlapResult<T> convex_overlap(const PosedShape<T> &A, const PosedShape<T> &B,
                                           OverlapWorkspace<T, MF> &ws, C *count, bool touching,
                                           T *axis = nullptr)
{
  const bool mixed = view_is_ellipsoid(*A.view) || view_is_ellipsoid(*B.view);
  if (!touching && !mixed) {
    bool apart = false;
    int ia = 0, ib = 0;
    if (axis) {    // vertex indices checked before the conversion (NaN, stale values)
      const T fa = axis[3], fb = axis[4];
      ia = fa >= T(0) && fa < T(A.view->nverts) ? (int) fa : -1;
      ib = fb >= T(0) && fb < T(B.view->nverts) ? (int) fb : -1;
      apart = gjk_axis_separates(A, B, make_vec3(axis[0], axis[1], axis[2]), ia, ib);
    }
    if (!apart) {
      const auto g = gjk_intersect(A, B);
      if (g.status != STATUS_SEPARATED && g.status != STATUS_OK) count[PP_NOCONV] += C(1);
      apart = g.status == STATUS_SEPARATED;
      if (apart && axis) {
        axis[0] = g.axis.x;
        axis[1] = g.axis.y;
        axis[2] = g.axis.z;
      }
      ia = g.ia;
      ib = g.ib;
    }
    if (apart) {
      if (axis) {
        axis[3] = T(ia);
        axis[4] = T(ib);
      }
      OverlapResult<T> r = ellipsoid_overlap_detail::no_overlap<T>();
      r.status = STATUS_SEPARATED;
      return r;
    }
  }
  history_release(axis, GJK_AXIS_VALUES);
  const OverlapResult<T> ov = mixed ? mixed_pair_overlap(A, B) : polyhedron_overlap(A, B, ws);
  if (ov.status == STATUS_OVERFLOW)
    count[PP_OVERFLOW] += C(1);
  else if (ov.status == STATUS_DEGENERATE || ov.status == STATUS_UNSUPPORTED)
    count[PP_DEGENERATE] += C(1);
  return ov;
}

// The contact of convex shapes a (of body A) and b (of body B) with overlap
// ov: the law of their volumes, the bodies' kinematics about their centres,
// the history h (nhist values, or null), counted. bridges: a liquid bridge
// law acts (two spheres, a sphere and a polyhedron, two polyhedra, also as
// parts of composites, whose slots keep the bridge across the gap:
// composite_pair_contact); false: none (counted as PP_NOBRIDGE).
template <typename T, typename C>
POLYDEM_FN PairContactResult<T>
convex_contact_step(const PolyhedronBody<T> &A, const PolyhedronBody<T> &B,
                    const PosedShape<T> &a, const PosedShape<T> &b, const OverlapResult<T> &ov,
                    const LawTable<T> &tab, T dt, bool update, T *h, C *count,
                    bool bridges = true)
{
  PairContactResult<T> r;
  r.contact = 1;
  count[PP_CONTACTS] += C(1);
  const T Vi = posed_volume(a), Vj = posed_volume(b);
  r.vmin = Vi < Vj ? Vi : Vj;
  if (ov.volume > tab.overlap_warn * r.vmin) count[PP_BIGOVERLAP] += C(1);

  ContactLaw<T> law = polyhedron_pair_law(tab, A.type, B.type, Vi, Vj);
  const ContactKinematics<T> kin = make_kinematics(A.shape.x, B.shape.x, A.v, B.v, A.w, B.w,
                                                   A.m * B.m / (A.m + B.m), update ? dt : T(0),
                                                   A.m, B.m);
  r.geo = contact_geometry<T>(ov);
  r.geo.centroid = pressure_centre(ov.S_A, ov.M_A, a.x, ov.centroid);
  if (law.rolling.mu_r > T(0)) {
    // a sphere on a polyhedron rolls on its own radius (the face is flat),
    // not on r_A r_B / (r_A + r_B) of the distances to the centres
    const T ra = posed_sphere_radius(a), rb = posed_sphere_radius(b);
    const bool pa = !view_is_ellipsoid(*a.view), pb = !view_is_ellipsoid(*b.view);
    if (ra > T(0) && pb) law.rolling.R = ra;
    if (rb > T(0) && pa) law.rolling.R = rb;
  }
  // liquid bridge: between spheres, the gap along the line of centres (in
  // the contact law); a sphere and a polyhedron, the gap to its surface
  // (sphere_polyhedron_bridge), two convex polyhedra, their signed distance
  // (polyhedron_pair_bridge), both added after the contact law
  BridgeLaw<T> sphere_poly = law.bridge, poly_poly = law.bridge;
  sphere_poly.volume = T(0);
  poly_poly.volume = T(0);
  if (law.bridge.volume > T(0)) {
    const T ra = posed_sphere_radius(a), rb = posed_sphere_radius(b);
    const bool pa = view_is_convex_polyhedron(*a.view), pb = view_is_convex_polyhedron(*b.view);
    if (bridges && ra > T(0) && rb > T(0)) {
      law.bridge.R = T(2) * ra * rb / (ra + rb);
      r.geo.has_gap = 1;
      r.geo.gap = norm(b.x - a.x) - ra - rb;
    } else {
      if (bridges && ((ra > T(0) && pb) || (rb > T(0) && pa)))
        sphere_poly = law.bridge;
      else if (bridges && pa && pb)
        poly_poly = law.bridge;
      else
        count[PP_NOBRIDGE] += C(1);
      law.bridge.volume = T(0);
    }
  }
  // dV/dtheta about the bodies' centres (Feng's Eq. 9 torques): rotating a
  // part about its body's centre also moves it by theta x (x_part - x_body)
  r.geo.M_A += cross(a.x - A.shape.x, ov.S_A);
  r.geo.M_B -= cross(b.x - B.shape.x, ov.S_A);
  r.cf = pair_contact_step(r.geo, law, kin, h, tab.nhist,
                           T(contact_history_sign(A.tag, B.tag)), update);
  if (sphere_poly.volume > T(0)) {
    const bool sa = posed_sphere_radius(a) > T(0);
    sphere_polyhedron_bridge(sa ? a : b, sa ? b : a, sphere_poly, sa, kin, r.cf);
  }
  if (poly_poly.volume > T(0)) polyhedron_pair_bridge(a, b, poly_poly, kin, r.cf);
  return r;
}

// Two separated spheres a, b, a separated sphere and convex polyhedron, or
// two separated convex polyhedra, whose liquid bridge formed when they touched (the pair's touch flag): the
// bridge's pull while the gap is below its rupture distance (contact = 2:
// no overlap, the pair stays flagged), else none (contact = 0: ruptured).
// The history (friction, rolling) is cleared.
template <typename T>
POLYDEM_FN PairContactResult<T> bridge_contact(const PolyhedronBody<T> &A, const PolyhedronBody<T> &B,
                                               const PosedShape<T> &a, const PosedShape<T> &b,
                                               const LawTable<T> &tab, T dt)
{
  PairContactResult<T> r;
  r.contact = 0;
  const LawEntry<T> &e = tab.pair(A.type, B.type);
  const T ra = posed_sphere_radius(a), rb = posed_sphere_radius(b);
  if (!(e.bridge.volume > T(0))) return r;
  if ((ra > T(0)) != (rb > T(0)) &&
      view_is_convex_polyhedron(ra > T(0) ? *b.view : *a.view)) {
    const ContactKinematics<T> kin = make_kinematics(A.shape.x, B.shape.x, A.v, B.v, A.w, B.w,
                                                     A.m * B.m / (A.m + B.m), dt, A.m, B.m);
    r.cf = ContactForce<T>{};
    const bool sa = ra > T(0);
    if (!sphere_polyhedron_bridge(sa ? a : b, sa ? b : a, e.bridge, sa, kin, r.cf)) return r;
    r.contact = 2;
    r.geo = ContactGeometry<T>{};
    r.geo.normal = (T(1) / norm(r.cf.F_A)) * r.cf.F_A;
    const T Vi = posed_volume(a), Vj = posed_volume(b);
    r.vmin = Vi < Vj ? Vi : Vj;
    return r;
  }
  if (view_is_convex_polyhedron(*a.view) && view_is_convex_polyhedron(*b.view)) {
    // two convex polyhedra: Willett's force across their distance
    const ContactKinematics<T> kin = make_kinematics(A.shape.x, B.shape.x, A.v, B.v, A.w, B.w,
                                                     A.m * B.m / (A.m + B.m), dt, A.m, B.m);
    r.cf = ContactForce<T>{};
    ContactGeometry<T> g{};
    if (!polyhedron_pair_bridge(a, b, e.bridge, kin, r.cf, &g)) return r;
    r.contact = 2;
    r.geo = g;
    const T Vi = posed_volume(a), Vj = posed_volume(b);
    r.vmin = Vi < Vj ? Vi : Vj;
    return r;
  }
  if (!(ra > T(0) && rb > T(0))) return r;
  const Vec3<T> d = b.x - a.x;
  const T dist = norm(d);
  const T gap = dist - ra - rb;
  if (!(gap < e.bridge.rupture) || !(dist > T(0))) return r;
  r.contact = 2;
  BridgeLaw<T> law = e.bridge;
  law.R = T(2) * ra * rb / (ra + rb);
  ContactGeometry<T> g{};
  g.normal = (T(1) / dist) * d;
  g.centroid = a.x + (ra + T(0.5) * gap) * g.normal;    // mid-gap on the line of centres
  g.has_gap = 1;
  g.gap = gap;
  r.geo = g;
  const ContactKinematics<T> kin = make_kinematics(A.shape.x, B.shape.x, A.v, B.v, A.w, B.w,
                                                   A.m * B.m / (A.m + B.m), dt, A.m, B.m);
  r.cf = ContactForce<T>{};
  add_bridge(g, law, kin, r.cf);
  const T Vi = posed_volume(a), Vj = posed_volume(b);
  r.vmin = Vi < Vj ? Vi : Vj;
  return r;
}

// Two ellipsoids of which one has unequal semi-axes (either may be a part of
// a composite): they have no overlap-volume kernel and meet by the
// algebraic contact of pair_style ellipsoid instead.
template <typename T>
POLYDEM_FN bool algebraic_pair(const PosedShape<T> &a, const PosedShape<T> &b)
{
  return view_is_ellipsoid(*a.view) && view_is_ellipsoid(*b.view) &&
         !(posed_sphere_radius(a) > T(0) && posed_sphere_radius(b) > T(0));
}

// The algebraic contact of ellipsoids a (of body A) and b (of body B)
// (algebraic_pair): the linear law of pair_style ellipsoid (ellipsoid seed
// Eqs. 23-24) with the type pair's k_n (LawEntry::kn; pair_coeff ...
// ellipsoid k_n), the overlap delta = r (1/W0 - 1) along the line of
// centres, whose force is the exact gradient of 1/2 k_n delta^2
// (OVERLAP_CENTRE), the dashpot of the reduced mass; the torques about the
// bodies' centres. h: the contact's tab.nhist values or null. vmin is the
// smallest semi-axis (the overlap is a length). No liquid bridge (counted
// as PP_NOBRIDGE where the pair has one) and no dry cohesion.
template <typename T, typename C>
POLYDEM_FN PairContactResult<T>
algebraic_contact_step(const PolyhedronBody<T> &A, const PolyhedronBody<T> &B,
                       const PosedShape<T> &a, const PosedShape<T> &b, const LawTable<T> &tab,
                       T dt, bool update, T *h, C *count)
{
  PairContactResult<T> r;
  r.contact = 0;
  EllipsoidFrame<T> fa, fb;
  fa.x = a.x;
  fa.R = a.R;
  fa.axes = a.s * make_vec3(a.view->axes[0], a.view->axes[1], a.view->axes[2]);
  fb.x = b.x;
  fb.R = b.R;
  fb.axes = b.s * make_vec3(b.view->axes[0], b.view->axes[1], b.view->axes[2]);
  const EllipsoidContact<T> c = ellipsoid_contact(fa, fb);
  if (c.status != STATUS_OK) {
    if (c.status != STATUS_SEPARATED) count[PP_DEGENERATE] += C(1);
    history_release(h, tab.nhist);
    return r;
  }
  r.contact = 1;
  count[PP_CONTACTS] += C(1);
  T amin = fa.axes.x;
  const T ax[5] = {fa.axes.y, fa.axes.z, fb.axes.x, fb.axes.y, fb.axes.z};
  for (int k = 0; k < 5; ++k)
    if (ax[k] < amin) amin = ax[k];
  r.vmin = amin;
  const ContactKinematics<T> kin = make_kinematics(A.shape.x, B.shape.x, A.v, B.v, A.w, B.w,
                                                   A.m * B.m / (A.m + B.m), update ? dt : T(0),
                                                   A.m, B.m);
  r.geo = ellipsoid_geometry(c, OVERLAP_CENTRE, a.x, b.x);
  // d delta/d theta about the bodies' centres (a part's centre moves too)
  r.geo.M_A += cross(a.x - A.shape.x, r.geo.S_A);
  r.geo.M_B -= cross(b.x - B.shape.x, r.geo.S_A);
  ContactLaw<T> law = ellipsoid_pair_law(tab, A.type, B.type);
  if (law.bridge.volume > T(0)) {
    count[PP_NOBRIDGE] += C(1);
    law.bridge.volume = T(0);
  }
  // the pair's cohesion k_c is the volume law's adhesive stress, not the
  // linear law's surface energy: none here (pair polyhedron warns at init)
  law.cohesion = T(0);
  r.cf = pair_contact_step(r.geo, law, kin, h, tab.nhist,
                           T(contact_history_sign(A.tag, B.tag)), update);
  if (r.geo.volume > tab.overlap_warn * amin) count[PP_BIGOVERLAP] += C(1);
  return r;
}

// the force, torques, energy and force magnitudes of a part contact added
// to the composite pair's result (the first sets them)
template <typename T>
POLYDEM_FN void add_part_force(PairContactResult<T> &r, const ContactForce<T> &cf)
{
  if (!r.contact) {
    r.cf = cf;
    return;
  }
  r.cf.F_A += cf.F_A;
  r.cf.tau_A += cf.tau_A;
  r.cf.tau_B += cf.tau_B;
  r.cf.energy += cf.energy;
  r.cf.fn += cf.fn;
  r.cf.ft += cf.ft;
  r.cf.capped |= cf.capped;
}

// Bit k of bits is set where part k of body (n parts; a convex body: itself)
// has a bounding sphere, and a composite's part also a bounding box
// (ShapePart mid, half), that meets other's bounding sphere scaled by 1 + 1e-9.
template <typename T>
POLYDEM_FN void part_reach_bits(const PosedShape<T> &body, const PosedShape<T> &other, int n,
                                unsigned &bits)
{
  const ShapeView<T> &v = *body.view;
  const T ro = posed_radius(other);
  for (int k = 0; k < n; ++k) {
    Vec3<T> x = body.x;
    T r = posed_radius(body);
    if (view_is_composite(v)) {
      const ShapePart<T> &p = v.parts[k];
      x = body.x + body.s * matvec(body.R, make_vec3(p.x[0], p.x[1], p.x[2]));
      r = body.s * p.view->radius;
    }
    const T reach = (r + ro) * T(1.000000001);
    if (!(norm2(x - other.x) < reach * reach)) continue;
    if (view_is_composite(v)) {
      // the other sphere against the part's box (in the part's frame, unit
      // scale): a box out of its reach holds a part out of it
      const ShapePart<T> &p = v.parts[k];
      const Vec3<T> d = other.x - x;
      const Vec3<T> e = make_vec3(body.R.m[0][0] * d.x + body.R.m[1][0] * d.y + body.R.m[2][0] * d.z,
                                  body.R.m[0][1] * d.x + body.R.m[1][1] * d.y + body.R.m[2][1] * d.z,
                                  body.R.m[0][2] * d.x + body.R.m[1][2] * d.y + body.R.m[2][2] * d.z);
      T out2 = T(0);
      for (int i = 0; i < 3; ++i) {
        const T u = (p.R[0][i] * e.x + p.R[1][i] * e.y + p.R[2][i] * e.z) / body.s - p.mid[i];
        const T o = (u < T(0) ? -u : u) - p.half[i];
        if (o > T(0)) out2 += o * o;
      }
      const T ru = ro / body.s * T(1.000000001);
      if (!(out2 < ru * ru)) continue;
    }
    bits |= 1u << k;
  }
}

// a part's bounding box in its own frame, unit scale
template <typename T> struct PartBox {
  T mid[3], half[3];
};

// part k's box of a body (a composite: ShapePart's; a convex body: the cube
// about its bounding sphere, an ellipsoid's semi-axes), unit scale
template <typename T> POLYDEM_FN PartBox<T> part_box(const PosedShape<T> &body, int k)
{
  const ShapeView<T> &v = *body.view;
  PartBox<T> r;
  for (int i = 0; i < 3; ++i) {
    r.mid[i] = view_is_composite(v) ? v.parts[k].mid[i] : T(0);
    r.half[i] = view_is_composite(v) ? v.parts[k].half[i]
                                     : (view_is_ellipsoid(v) ? v.axes[i] : v.radius);
  }
  return r;
}

// Whether the bounding boxes of posed parts a and b (ShapePart mid, half in
// each part's frame) are apart along one of the 15 axes of the separating
// axis test (the 3 + 3 box axes and their 9 cross products), with a
// relative margin of 1e-9: apart boxes hold apart parts.
template <typename T>
POLYDEM_FN bool part_boxes_apart(const PosedShape<T> &a, const PartBox<T> &pa,
                                 const PosedShape<T> &b, const PartBox<T> &pb)
{
  const Vec3<T> ca = a.x + a.s * matvec(a.R, make_vec3(pa.mid[0], pa.mid[1], pa.mid[2]));
  const Vec3<T> cb = b.x + b.s * matvec(b.R, make_vec3(pb.mid[0], pb.mid[1], pb.mid[2]));
  const T ha[3] = {a.s * pa.half[0], a.s * pa.half[1], a.s * pa.half[2]};
  const T hb[3] = {b.s * pb.half[0], b.s * pb.half[1], b.s * pb.half[2]};
  const Vec3<T> d = cb - ca;
  T C[3][3], A[3][3], t[3];    // C = Ra^T Rb, A = |C|, t = Ra^T d
  for (int i = 0; i < 3; ++i) {
    t[i] = a.R.m[0][i] * d.x + a.R.m[1][i] * d.y + a.R.m[2][i] * d.z;
    for (int j = 0; j < 3; ++j) {
      C[i][j] = a.R.m[0][i] * b.R.m[0][j] + a.R.m[1][i] * b.R.m[1][j] + a.R.m[2][i] * b.R.m[2][j];
      A[i][j] = (C[i][j] < T(0) ? -C[i][j] : C[i][j]) + T(1e-12);
    }
  }
  const T m = T(1) + T(1e-9);
  auto apart = [m](T dist, T ra, T rb) { return (dist < T(0) ? -dist : dist) > (ra + rb) * m; };
  for (int i = 0; i < 3; ++i)    // a's axes
    if (apart(t[i], ha[i], hb[0] * A[i][0] + hb[1] * A[i][1] + hb[2] * A[i][2])) return true;
  for (int j = 0; j < 3; ++j)    // b's axes
    if (apart(t[0] * C[0][j] + t[1] * C[1][j] + t[2] * C[2][j],
              ha[0] * A[0][j] + ha[1] * A[1][j] + ha[2] * A[2][j], hb[j]))
      return true;
  for (int i = 0; i < 3; ++i)    // a_i x b_j
    for (int j = 0; j < 3; ++j) {
      const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
      if (apart(t[i2] * C[i1][j] - t[i1] * C[i2][j], ha[i1] * A[i2][j] + ha[i2] * A[i1][j],
                hb[j1] * A[i][j2] + hb[j2] * A[i][j1]))
        return true;
    }
  return false;
}

// A pair of which one or both are composites, in a table with part slots
// (tab.nslot > 0): every pair of parts that may touch (part_reach_bits,
// bounding spheres, part_boxes_apart) is a contact of its own, with its
// history in the slot keyed 1 + (part of the lower-tag body) x
// MAX_COMPOSITE_PARTS + (part of the other); the forces and torques are
// summed on the bodies. The result's geometry is that of
// the deepest part contact with the summed volume and area (of the part
// contacts by overlap volume; if there are none, the deepest algebraic one's,
// its overlap length over its smallest semi-axis in vmin). A part pair
// that touched and came apart keeps its slot while its liquid bridge holds
// (bridge_contact); if bridges are all the pair has, contact = 2.
template <typename T, int MF, typename C>
POLYDEM_FN PairContactResult<T>
composite_pair_contact(const PolyhedronBody<T> &A, const PolyhedronBody<T> &B,
                       const LawTable<T> &tab, T dt, bool update, T *hist,
                       OverlapWorkspace<T, MF> &ws, C *count)
{
  PairContactResult<T> r;
  r.contact = 0;
  const int na = view_is_composite(*A.shape.view) ? A.shape.view->nparts : 1;
  const int nb = view_is_composite(*B.shape.view) ? B.shape.view->nparts : 1;
  const bool a_low = A.tag < B.tag;
  const int stride = 1 + tab.nhist;
  T deepest = T(-1), volume = T(0), area = T(0), deepest_alg = T(-1);
  bool by_volume = false;    // a part contact by overlap volume (else algebraic only)
  // the parts that can reach the other body: a part whose bounding sphere
  // or box misses the other body's sphere (which holds all its parts'
  // corners) touches none of its parts (a bit per part; 1e-9 of margin)
  unsigned reach_a = 0u, reach_b = 0u;
  part_reach_bits(A.shape, B.shape, na, reach_a);
  part_reach_bits(B.shape, A.shape, nb, reach_b);
  // the keys that hold a slot (1 + 16 ka + kb <= 256): a part pair out of
  // reach without a slot has nothing to do
  unsigned long long held[4] = {0ull, 0ull, 0ull, 0ull};
  for (int k = 0; k < tab.nslot; ++k) {
    const T v = hist[k * stride];
    if (v >= T(1) && v <= T(MAX_COMPOSITE_PARTS * MAX_COMPOSITE_PARTS)) {
      const int bit = (int) v - 1;
      held[bit >> 6] |= 1ull << (bit & 63);
    }
  }
  PosedShape<T> a = A.shape, b = B.shape;
  int posed_a = -1, posed_b = -1;
  // the part pairs in the lower tag's order, whichever body is A: slots are
  // taken in the same order on every rank (and given up alike when they run out)
  for (int idx = 0; idx < na * nb; ++idx) {
    const int ka = a_low ? idx / nb : idx % na, kb = a_low ? idx % nb : idx / na;
    const int ikey = a_low ? ka * MAX_COMPOSITE_PARTS + kb : kb * MAX_COMPOSITE_PARTS + ka;
    const bool has_slot = (held[ikey >> 6] >> (ikey & 63)) & 1ull;
    if (!has_slot && !((reach_a >> ka) & 1u && (reach_b >> kb) & 1u)) continue;
    // a part is posed when its index changes (the outer one's once per row)
    if (ka != posed_a) {
      a = posed_part(A.shape, ka);
      posed_a = ka;
    }
    if (kb != posed_b) {
      b = posed_part(B.shape, kb);
      posed_b = kb;
    }
    {
      const T key = T(1 + ikey);
      T *slot = nullptr;
      if (has_slot)
        for (int k = 0; k < tab.nslot; ++k)
          if (hist[k * stride] == key) slot = hist + k * stride;
      const T reach = a.s * a.view->radius + b.s * b.view->radius;
      const bool algebraic = algebraic_pair(a, b);
      OverlapResult<T> ov;
      ov.status = STATUS_SEPARATED;
      if (norm2(a.x - b.x) < reach * reach) {
        if (algebraic)
          ov.status = STATUS_OK;    // decided by the algebraic contact below
        else if (slot || !part_boxes_apart(a, part_box(A.shape, ka), b, part_box(B.shape, kb)))
          ov = convex_overlap(a, b, ws, count, slot != nullptr);
      }
      if (ov.status != STATUS_OK) {
        // a part pair that touched (its slot is kept) and has come apart:
        // its liquid bridge while the gap is below the rupture distance
        // (bridge_contact: the slot keeps its key, its friction and rolling
        // history are cleared), else the slot is given up
        if (slot && ov.status == STATUS_SEPARATED && tab.bridge_reach > T(0)) {
          const PairContactResult<T> c = bridge_contact(A, B, a, b, tab, update ? dt : T(0));
          if (c.contact == 2) {
            history_release(slot + 1, tab.nhist);
            add_part_force(r, c.cf);
            if (!r.contact) {
              r.contact = 2;
              r.geo = c.geo;
              r.vmin = c.vmin;
            }
            continue;
          }
        }
        history_release(slot, stride);
        continue;
      }
      if (!slot && update)
        for (int k = 0; k < tab.nslot && !slot; ++k)
          if (hist[k * stride] == T(0)) {
            slot = hist + k * stride;
            slot[0] = key;
          }
      if (!slot && update) count[PP_NOSLOT] += C(1);    // more part contacts than slots
      T *h = slot ? slot + 1 : nullptr;
      const PairContactResult<T> c =
          algebraic ? algebraic_contact_step(A, B, a, b, tab, dt, update, h, count)
                    : convex_contact_step(A, B, a, b, ov, tab, dt, update, h, count);
      if (!c.contact) {
        // the algebraic contact found them apart: the slot taken above is freed
        history_release(slot, stride);
        continue;
      }
      if (r.contact != 1) {
        // the first part contact by overlap: the record's geometry is one
        // of these (below), not a bridge's
        r.geo = c.geo;
        r.vmin = c.vmin;
        r.cf.rate = c.cf.rate;
      }
      add_part_force(r, c.cf);
      r.contact = 1;
      if (algebraic) {
        // an overlap length, not a volume: the record's geometry only if
        // no part contact has a volume (then the deepest, over its semi-axis)
        if (!by_volume && c.geo.volume / c.vmin > deepest_alg) {
          deepest_alg = c.geo.volume / c.vmin;
          r.geo = c.geo;
          r.vmin = c.vmin;
          r.cf.rate = c.cf.rate;
        }
        continue;
      }
      by_volume = true;
      volume += c.geo.volume;
      area += c.geo.area;
      if (c.geo.volume > deepest) {
        deepest = c.geo.volume;
        r.geo = c.geo;
        r.cf.rate = c.cf.rate;
      }
    }
  }
  if (r.contact && by_volume) {
    r.geo.volume = volume;
    r.geo.area = area;
    const T Vi = posed_volume(A.shape), Vj = posed_volume(B.shape);
    r.vmin = Vi < Vj ? Vi : Vj;
  }
  return r;
}

// One pair of pair polyhedron (A = the list's i): polyhedra, spheres,
// ellipsoids and composites of them by their overlap volume; hist = its
// pair_history_stride(tab) values in the pair convention
// (contact_history_sign), advanced and kept if update (not at setup, where
// dt does not increment it); ws: the overlap workspace; count[PP_*]
// incremented. touching: the pair was in contact at the last step (the
// neighbor history's flag); then GJK, only a filter, is skipped, since the
// overlap decides separation by itself and a pair in contact mostly stays so.
template <typename T, int MF, typename C>
POLYDEM_FN PairContactResult<T>
polyhedron_pair_forces(const PolyhedronBody<T> &A, const PolyhedronBody<T> &B,
                       const LawTable<T> &tab, T dt, bool update, T *hist,
                       OverlapWorkspace<T, MF> &ws, C *count, bool touching)
{
  const bool ca = view_is_composite(*A.shape.view), cb = view_is_composite(*B.shape.view);
  if (tab.nslot > 0 && (ca || cb))
    return composite_pair_contact(A, B, tab, dt, update, hist, ws, count);
  // convex, or composites of one part (no slots): the part itself
  const PosedShape<T> a = ca ? posed_part(A.shape, 0) : A.shape;
  const PosedShape<T> b = cb ? posed_part(B.shape, 0) : B.shape;
  if (algebraic_pair(a, b)) return algebraic_contact_step(A, B, a, b, tab, dt, update, hist, count);
  // not touching: the slot holds at most GJK's axis (GJK_AXIS_VALUES)
  T *axis = !touching && hist && tab.nhist >= GJK_AXIS_VALUES ? hist : nullptr;
  const OverlapResult<T> ov = convex_overlap(a, b, ws, count, touching, axis);
  if (ov.status != STATUS_OK) {
    if (axis)    // the axis convex_overlap kept, the rest cleared
      history_release(hist + GJK_AXIS_VALUES, tab.nhist - GJK_AXIS_VALUES);
    else
      history_release(hist, tab.nhist);
    PairContactResult<T> r;
    r.contact = 0;
    if (touching && tab.bridge_reach > T(0) && ov.status == STATUS_SEPARATED)
      r = bridge_contact(A, B, a, b, tab, update ? dt : T(0));
    return r;
  }
  if (axis) history_release(hist, tab.nhist);    // a contact begins: no history
  return convex_contact_step(A, B, a, b, ov, tab, dt, update, hist, count);
}
template <typename T, int MF, typename C>
POLYDEM_FN PairContactResult<T>
polyhedron_pair_contact(const PolyhedronBody<T> &A, const PolyhedronBody<T> &B,
                        const LawTable<T> &tab, T dt, bool update, T *hist,
                        OverlapWorkspace<T, MF> &ws, C *count, bool touching = false)
{
  const PairContactResult<T> r =
      polyhedron_pair_forces(A, B, tab, dt, update, hist, ws, count, touching);
  if (r.contact && r.cf.capped) count[PP_DAMPCAP] += C(1);
  return r;
}

// atom k with its template's view (which outlives the body)
template <typename T, class Atoms>
POLYDEM_FN PolyhedronBody<T> gather_polyhedron_body(const Atoms &atoms, int k,
                                                    const ShapeView<T> &view)
{
  PolyhedronBody<T> b;
  b.shape = make_posed(view, gather_pose<T>(atoms, k));
  gather_motion<T>(atoms, k, b);
  b.tag = atoms.tag(k);
  return b;
}

// An ellipsoid pair's body: pose with scaled semi-axes, its motion, its tag.
template <typename T> struct EllipsoidBody : BodyMotion<T> {
  EllipsoidPose<T> pose;
  long tag;
};

// atom k with its template's semi-axes at unit scale
template <typename T, class Atoms>
POLYDEM_FN EllipsoidBody<T> gather_ellipsoid_body(const Atoms &atoms, int k, const Vec3<T> &axes)
{
  EllipsoidBody<T> b;
  const Pose<T> p = gather_pose<T>(atoms, k);
  b.pose.x = p.x;
  b.pose.q = p.q;
  b.pose.axes = make_vec3(p.s * axes.x, p.s * axes.y, p.s * axes.z);
  gather_motion<T>(atoms, k, b);
  b.tag = atoms.tag(k);
  return b;
}

constexpr int ELLIPSOID_HIST = 3;    // tangential displacement s (polydem_contact_law.h)
// (CONTACT_HIST_ROLL with rolling resistance: slots 3 and 4 unused)


// One ellipsoid pair: hist = its tab.nhist values in the pair
// convention, or null (frictionless: none kept); share: the part of the pair
// this call counts in the contact statistics (1/2 for a pair seen on two
// ranks); count[EP_*] incremented.
template <typename T, typename C>
POLYDEM_FN PairContactResult<T>
ellipsoid_pair_contact(const EllipsoidBody<T> &A, const EllipsoidBody<T> &B, const LawTable<T> &tab,
                       T dt, bool update, T *hist, C share, C *count)
{
  PairContactResult<T> r;
  r.contact = 0;
  const EllipsoidContact<T> c = ellipsoid_contact(A.pose, B.pose);
  if (c.status != STATUS_OK) {
    if (c.status != STATUS_SEPARATED)
      count[c.status == STATUS_NO_CONVERGENCE ? EP_NOCONV : EP_DEGENERATE] += C(1);
    history_release(hist, tab.nhist);
    return r;
  }
  r.contact = 1;
  count[EP_CONTACTS] += share;
  T amin = A.pose.axes.x;
  const T ax[5] = {A.pose.axes.y, A.pose.axes.z, B.pose.axes.x, B.pose.axes.y, B.pose.axes.z};
  for (int k = 0; k < 5; ++k)
    if (ax[k] < amin) amin = ax[k];
  r.vmin = amin;
  const ContactKinematics<T> kin =
      make_kinematics(A.pose.x, B.pose.x, A.v, B.v, A.w, B.w,
                      tab.damping_mass == DAMPING_CONTACT
                          ? ellipsoid_contact_mass(c, tab.overlap, A.pose, B.pose, A.m, B.m)
                          : A.m * B.m / (A.m + B.m),
                      update ? dt : T(0), A.m, B.m);
  r.geo = ellipsoid_geometry(c, tab.overlap, A.pose.x, B.pose.x);
  const ContactLaw<T> law = ellipsoid_pair_law(tab, A.type, B.type);
  r.cf = pair_contact_step(r.geo, law, kin, hist, tab.nhist,
                           T(contact_history_sign(A.tag, B.tag)), update);
  if (r.geo.volume > tab.overlap_warn * amin) count[EP_BIGOVERLAP] += C(1);
  if (r.cf.capped) count[EP_DAMPCAP] += share;
  if (r.geo.volume < r.cf.rate * dt) count[EP_COLLISIONS] += share;
  return r;
}

}    // namespace polydem

#endif
