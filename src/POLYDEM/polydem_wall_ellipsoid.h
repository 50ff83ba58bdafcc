/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - contact of one ellipsoid with a triangle mesh (fix wall/mesh and
   /kk), host and device. No LAMMPS includes; no allocation, loops bounded
   by the grid's bin lists, a few hundred bytes of stack.

   Ellipsoid: centre c, rotation R (body -> mesh frame), semi-axes
   A = diag(a, b, c); M = R A^2 R^T. The affine map p' = A^-1 R^T (p - c)
   takes it to the unit sphere and a triangle to a triangle. For each
   candidate triangle (met from its side s, WallSides: wall normal n_w = s n_t
   towards the particle, h = n_w . (c - t0) the centre's height) let q' be
   the closest point of the mapped triangle to the origin, r' = |q'|:
   r' < 1 is a contact. With u' = q' / r' (a point of the unit sphere), the
   contact normal, from the particle into the wall, is the ellipsoid's
   surface normal at p* = c + R A u',
     n_s = R A^-1 u' / |R A^-1 u'|,
   and the overlap is the depth of the support plane through the closest
   point,  delta = (1 - r') sigma(n_s),  sigma(n) = sqrt(n^T M n).

   Faces (q' inside the mapped triangle, the foot of the centre on the
   plane): r' = h / sigma(n_w), n_s = -n_w, delta = sigma(n_w) - h and
   p* = c - M n_w / sigma(n_w), the deepest point: exactly the support-
   function depth of the plane, computed from the stored plane (not from
   q', so that coplanar triangles give the same numbers). The force
   -k_n delta n_s at p* (any point of that line) is then the exact gradient
   of 1/2 k_n delta^2 in translation (d delta/dc = n_s) and rotation (d delta
   /dtheta = (p* - c) x n_s, the envelope theorem on sigma). Edges and
   vertices: the same depth continued with the triangle's own support,
   delta = (1 - r') sigma(n_w), and its exact gradient (ellipsoid_triangle),
   so that the elastic energy is conserved there too. A flat wall gives one contact whatever its
   triangulation: the coplanar triangles under the foot all give it, the
   others are farther (r' larger, delta smaller: one sigma(n_w)), and per
   patch the largest delta is kept (on a curved region too: the energy is
   then the largest of continuous ones).

   Each triangle's contact is continuous in the pose, so are their sums; at
   a convex sharp edge (beyond the patch angle) both faces' contacts can see
   the edge (up to twice one contact's force there, as the prisms of
   polyhedra overlap behind a convex edge).

   Patches: the touching triangles are grouped by the mesh's smooth regions
   (wall_patch_slot, at most WALL_MAX_PATCH; beyond, the closest normal,
   counted as merged); each patch keeps its deepest point and is one contact of the contact layer
   (wall_ellipsoid_contacts -> wall_contact_forces): measure delta, area 0,
   S_A, M_A the gradient of delta (n_s, (p* - x) x n_s on a face), point damping at the contact point
   p_c = p* - delta n_s (on the force line, in the wall's plane for a face).

   Centre behind the acting side (h < 0: a kept contact pushed past its
   centre, or a one-sided wall met from behind): faces keep the plane
   formula (delta = sigma - h > sigma, pushed back to the side the contact
   began on); edges and vertices reflect the normal part of q' (q' = f' + e',
   f' the foot, e' in the plane): u' ~ e' - f', r' = |e'| - |f'|, continuous
   with both the face formula (e' = 0) and the front (h = 0).
------------------------------------------------------------------------- */

#ifndef POLYDEM_WALL_ELLIPSOID_H
#define POLYDEM_WALL_ELLIPSOID_H

#include "polydem_ellipsoid_force.h"    // ellipsoid_law
#include "polydem_wall_contact.h"

namespace polydem {

// One ellipsoid in the mesh frame
template <typename T> struct WallEllipsoid {
  Vec3<T> c;     // centre
  Mat3<T> R;     // body -> mesh frame
  Vec3<T> ax;    // semi-axes [length]
};

// Support of the ellipsoid along n (unit): sigma(n) = |A R^T n|; Av = A^2 R^T n
// (body frame), so that M n = R Av
template <typename T>
POLYDEM_FN T ellipsoid_support(const WallEllipsoid<T> &e, const Vec3<T> &n, Vec3<T> &Av)
{
  const Vec3<T> nb = matTvec(e.R, n);
  const Vec3<T> v = make_vec3(e.ax.x * nb.x, e.ax.y * nb.y, e.ax.z * nb.z);
  Av = make_vec3(e.ax.x * v.x, e.ax.y * v.y, e.ax.z * v.z);
  return norm(v);
}

// Overlap of the ellipsoid with triangle t met from side 'side' (+1 front).
// Returns false if they do not touch; else r' (r), delta, the normal n_s
// into the wall, the point p* (ps), the gradients S = d delta/dc and
// M = d delta/dtheta (mesh frame), and whether the closest point is the
// foot of the centre with the centre behind the plane (behind).
template <typename T>
POLYDEM_FN bool ellipsoid_triangle(const WallEllipsoid<T> &e, const MeshGridView<T> &g, int t,
                                   int side, T &r, T &delta, Vec3<T> &ns, Vec3<T> &ps,
                                   Vec3<T> &S, Vec3<T> &M, int &behind, int &degenerate)
{
  const T *pl = g.plane + 4 * t;
  const Vec3<T> nw = T(side) * make_vec3(pl[0], pl[1], pl[2]);
  const T h = T(side) * (pl[0] * e.c.x + pl[1] * e.c.y + pl[2] * e.c.z - pl[3]);
  Vec3<T> Av;
  const T sig = ellipsoid_support(e, nw, Av);
  degenerate = !(h == h) || !(sig > T(0)) || !(sig < T(1e300));
  if (degenerate || !(h < sig)) return false;    // the plane is not reached
  // the triangle mapped to the unit sphere's frame, and its closest point q'
  Vec3<T> tp[3];
  const T *q = g.tri + 9 * t;
  T pmax = T(0);
  for (int v = 0; v < 3; ++v) {
    const Vec3<T> d = matTvec(e.R, make_vec3(q[3 * v], q[3 * v + 1], q[3 * v + 2]) - e.c);
    tp[v] = make_vec3(d.x / e.ax.x, d.y / e.ax.y, d.z / e.ax.z);
    const T a = norm(tp[v]);
    pmax = a > pmax ? a : pmax;
  }
  int face;
  const Vec3<T> qp = triangle_closest_point(make_vec3(T(0), T(0), T(0)), tp[0], tp[1], tp[2], face);
  // the mapped plane: unit normal N' = A R^T n_w / sigma (to the acting
  // side), foot of the origin f' = -(h / sigma) N'; e' = q' - f' in the plane
  const Vec3<T> Np = matTvec(e.R, nw);
  const Vec3<T> N = (T(1) / sig) * make_vec3(e.ax.x * Np.x, e.ax.y * Np.y, e.ax.z * Np.z);
  const Vec3<T> ep = qp + (h / sig) * N;
  const T en = norm(ep);
  // round-off of q' on the border through the foot [mapped length]: the foot
  if (face || !(en > T(1e-13) * (T(1) + pmax))) {
    r = h / sig;
    ns = -nw;
    delta = sig - h;
    ps = e.c - (T(1) / sig) * matvec(e.R, Av);
    S = ns;
    M = cross(ps - e.c, ns);
    behind = h < T(0);
    return true;
  }
  const Vec3<T> Mnw = matvec(e.R, Av);    // M n_w
  behind = 0;
  Vec3<T> u;
  if (h >= T(0)) {
    r = norm(qp);
    u = (T(1) / r) * qp;
  } else {    // reflect the normal part: u' ~ e' - f', r' = |e'| - |f'|
    r = en + h / sig;
    const Vec3<T> qr = ep + (h / sig) * N;
    u = (T(1) / norm(qr)) * qr;
  }
  if (!(r < T(1))) return false;
  const Vec3<T> w = matvec(e.R, make_vec3(u.x / e.ax.x, u.y / e.ax.y, u.z / e.ax.z));
  ns = (T(1) / norm(w)) * w;
  // delta = (1 - r') sigma(n_w): the face's support depth where q' is the
  // foot, continued with the triangle's own sigma(n_w) over its edges and
  // vertices (C1 across the face's border). By the envelope theorem on
  // r' = min |A^-1 R^T (p - c)| over the triangle, dr'/dc = -w and
  // dr'/dtheta = -(p - c) x w (p the closest point, p - c = r' (p* - c)),
  // and d sigma(n_w)/dtheta = (M n_w x n_w) / sigma, so
  //   S = sigma w,  M = sigma r' (p* - c) x w + (1 - r') (M n_w x n_w) / sigma:
  // the exact gradient, so k delta^2 / 2 is conserved at open borders and
  // sharp edges. (Centre behind the side, the reflected form: continuous,
  // the point force along n_s.)
  delta = (T(1) - r) * sig;
  ps = e.c + matvec(e.R, make_vec3(e.ax.x * u.x, e.ax.y * u.y, e.ax.z * u.z));
  if (h >= T(0)) {
    S = sig * w;
    M = (sig * r) * cross(ps - e.c, w) + ((T(1) - r) / sig) * cross(Mnw, nw);
  } else {
    S = (sig / ellipsoid_support(e, ns, Av)) * ns;
    M = cross(ps - e.c, S);
  }
  return delta > T(0);
}

// Overlap volume fraction of the unit ball cut by a plane at distance r'
// from its centre (a cap of height 1 - r', clamped to [0, 2]): the volume
// fraction of the ellipsoid behind its support plane (affine maps keep
// volume ratios)
template <typename T> POLYDEM_FN T ellipsoid_cap_fraction(T r)
{
  T x = T(1) - r;
  x = x < T(0) ? T(0) : (x > T(2) ? T(2) : x);
  return T(0.25) * x * x * (T(3) - x);
}

// A sphere (centre c, radius a) apart from triangle t met from side
// 'side': the gap s = |p - c| - a to its closest point p (face, edge or
// vertex), the unit normal n = (p - c) / |p - c| into the wall. False if the
// centre is not in front of the side or s is not below reach (the liquid
// bridge's rupture distance). s is the distance to the patch's nearest
// triangle point: continuous in the pose, and its gradient in c is -n.
template <typename T>
POLYDEM_FN bool sphere_triangle_gap(const Vec3<T> &c, T a, const MeshGridView<T> &g, int t,
                                    int side, T reach, T &s, Vec3<T> &n, Vec3<T> &p)
{
  const T *pl = g.plane + 4 * t;
  const T h = T(side) * (pl[0] * c.x + pl[1] * c.y + pl[2] * c.z - pl[3]);
  if (!(h > T(0)) || !(h < a + reach)) return false;
  const T *q = g.tri + 9 * t;
  int face;
  p = triangle_closest_point(c, make_vec3(q[0], q[1], q[2]), make_vec3(q[3], q[4], q[5]),
                             make_vec3(q[6], q[7], q[8]), face);
  const Vec3<T> d = p - c;
  const T dist = norm(d);
  s = dist - a;
  if (!(s < reach) || !(dist > T(0))) return false;
  if (s < T(0)) s = T(0);    // touching within round-off of the contact test
  n = (T(1) / dist) * d;
  return true;
}

// grid visitor: each touching triangle joins the patch of its smooth region
// (wall_patch_slot; without regions the closest normal), which keeps its
// deepest contact (largest delta). A sphere with a liquid bridge law (reach
// = its rupture distance > 0): a triangle within reach that it does not
// touch makes its patch a bridge patch (depth 0, the smallest gap) unless
// the patch has a contact.
template <typename T> struct WallEllipsoidAccumulate {
  const WallEllipsoid<T> *e;
  const MeshGridView<T> *g;
  WallPatches<T> *out;
  T cosmax, rb, vol;    // cos(patch angle), bounding radius, ellipsoid volume
  T reach;              // spheres: liquid bridges' rupture distance (0: none)
  const WallSides<T> *sides;
  T dbest[WALL_MAX_PATCH];

  // the patch of triangle t (side), opened as neither contact nor bridge
  POLYDEM_FN int patch_of(int t, int side)
  {
    const T *pl = g->plane + 4 * t;
    const Vec3<T> nw = T(side) * make_vec3(pl[0], pl[1], pl[2]);
    bool opened;
    const int k = wall_patch_slot(*out, *g, wall_region_key(*g, t, side), nw, cosmax, opened);
    if (opened) {
      const T *q = g->tri + 9 * t;
      WallPatch<T> &p = out->p[k];
      p.p0 = make_vec3(q[0], q[1], q[2]);
      p.behind = 0;
      p.depth = T(0);
      p.gap = T(-1);
      dbest[k] = T(-1);    // < any contact's delta (> 0)
    }
    return k;
  }

  // a bridge candidate: kept if its patch has no contact and it is nearer
  POLYDEM_FN void bridge(int t, int side)
  {
    T s;
    Vec3<T> n, p;
    if (!sphere_triangle_gap(e->c, e->ax.x, *g, t, side, reach, s, n, p)) return;
    WallPatch<T> &q = out->p[patch_of(t, side)];
    if (q.depth > T(0) || (q.gap >= T(0) && !(s < q.gap))) return;
    q.gap = s;
    q.volume = q.area = T(0);
    q.S = n;
    q.M = make_vec3(T(0), T(0), T(0));
    q.ac = e->c + (e->ax.x + T(0.5) * s) * n;    // mid-gap on the line to p
    q.vc = p;
    q.tri = t;
  }

  POLYDEM_FN void operator()(int t)
  {
    const int side = wall_side(sides, g->plane + 4 * t, e->c, rb);
    T r, delta;
    Vec3<T> ns, ps, S, M;
    int behind, degenerate;
    if (!ellipsoid_triangle(*e, *g, t, side, r, delta, ns, ps, S, M, behind, degenerate)) {
      out->ndegenerate += degenerate;
      if (reach > T(0) && !degenerate) bridge(t, side);
      return;
    }
    out->ntri++;
    const int k = patch_of(t, side);
    WallPatch<T> &p = out->p[k];
    p.behind |= behind;
    // The deepest triangle: the patch's energy k delta^2 / 2 is then the
    // largest of continuous functions of the pose, so continuous. (The
    // smallest r', as before, is the same on a flat wall, where sigma(n_w)
    // is one, but between non-coplanar triangles of a curved region the
    // choice jumped from one delta to another.) Ties: the first (coplanar
    // triangles agree).
    if (!(delta > dbest[k])) return;
    dbest[k] = delta;
    p.gap = T(-1);
    p.volume = vol * ellipsoid_cap_fraction(r);
    p.area = T(0);
    p.S = S;
    p.M = M;
    p.ac = ps - delta * ns;
    p.vc = ps;
    p.depth = delta;
    p.tri = t;
  }
};

// grid visitor of a sphere's near-list build: keeps (t, e_t), e_t = d_t - r
// (d_t the triangle's distance from the centre), for e_t <= skin; valid =
// the smallest e_t of the triangles left out (at most the query's extra
// reach); a full list keeps the cap smallest (near_list_keep).
template <typename T> struct SphereNearBuild {
  WallNear<T> *near;
  T r, skin, valid;
  int n;
  POLYDEM_FN void operator()(int t, T d2)
  {
    const T ds = sqrt(d2) - r;
    if (ds > skin) {
      valid = ds < valid ? ds : valid;
      return;
    }
    const float e = float(ds - T(1e-6) * fabs(ds));    // rounded down (float: < 1e-7 relative)
    near_list_keep(*near, n, t, e, valid);
  }
};

// Visits, through a near list, every triangle within r of the centre c of a
// sphere that moves without regard to its rotation (an ellipsoid's bounding
// sphere, widened by a liquid bridge's reach): the triangles the grid query
// mesh_for_each_near(g, c, r) finds. A triangle within r of c now was
// within r + m of the list's centre, m = |c - c_ref|, so while m stays below
// the smallest e_t left out only the entries with e_t <= m are tested. The
// list is rebuilt past that (from the grid, NEAR_REACH skins beyond r).
// False if it cannot be used (overflow: more than cap triangles within
// skin/16; a pose not finite): the caller queries the grid. The entries are
// visited in the order of the build's grid query, which is this step's
// unless the query's bins have shifted since: then a patch may be named by
// another of its facets (its first), as the grid query's own order does
// from step to step.
template <typename T, typename F>
POLYDEM_FN bool wall_sphere_near_visit(const MeshGridView<T> &g, const Vec3<T> &c, T r,
                                       WallNear<T> &near, F &acc)
{
  near.built = 0;
  if (*near.count == NEAR_OVERFLOW) return false;
  if (!(norm2(c) < T(1e300)) || !(r > T(0))) return false;
  T amax = fabs(c.x) > fabs(c.y) ? fabs(c.x) : fabs(c.y);
  amax = fabs(c.z) > amax ? fabs(c.z) : amax;
  const T slack = T(1e-7) * r + T(1e-13) * amax;    // round-off of the distances [length]
  T m = T(0);
  if (*near.count >= 0) {
    m = norm(c - make_vec3(near.ref[0], near.ref[1], near.ref[2])) + slack;
    if (!(m <= near.ref[12])) *near.count = NEAR_REBUILD;
  }
  if (*near.count == NEAR_REBUILD) {
    SphereNearBuild<T> b;
    b.near = &near;
    b.r = r;
    b.skin = near.skin;
    b.valid = T(NEAR_REACH) * b.skin;
    b.n = 0;
    near.built = 1;
    mesh_for_each_near_dist2(g, c, r + b.valid, b);
    if (!(b.valid * T(1 - 1e-6) >= T(0.0625) * b.skin)) {
      *near.count = NEAR_OVERFLOW;
      return false;
    }
    near.ref[12] = b.valid * T(1 - 1e-6);
    *near.count = b.n;
    near.ref[0] = c.x;
    near.ref[1] = c.y;
    near.ref[2] = c.z;
    m = slack;
  }
  const int n = *near.count;
  for (int e = 0; e < n; ++e) {
    if (!(T(near.gap[e]) <= m)) continue;
    const int t = near.tri[e];
    if (mesh_tri_near(g, t, c, r)) acc(t);
  }
  return true;
}

// Patches of ellipsoid e (mesh frame) against the mesh: every triangle
// within its bounding sphere (the grid, or the near list near when given:
// wall_sphere_near_visit). sides: which side of each triangle acts (null:
// the front only). reach > 0 (spheres with a liquid bridge law): also the
// bridge patches within that gap.
template <typename T>
POLYDEM_FN void wall_ellipsoid_patches(const WallEllipsoid<T> &e, const MeshGridView<T> &g,
                                       T cosmax, WallPatches<T> &out,
                                       const WallSides<T> *sides = nullptr, T reach = T(0),
                                       WallNear<T> *near = nullptr)
{
  out.n = out.noverflow = out.ndegenerate = out.nmerged = out.ntri = out.nunrecorded = 0;
  WallEllipsoidAccumulate<T> acc;
  acc.e = &e;
  acc.g = &g;
  acc.out = &out;
  acc.cosmax = cosmax;
  acc.sides = sides;
  acc.rb = e.ax.x > e.ax.y ? e.ax.x : e.ax.y;
  acc.rb = e.ax.z > acc.rb ? e.ax.z : acc.rb;
  acc.vol = T(4.18879020478639098462) * e.ax.x * e.ax.y * e.ax.z;    // 4/3 pi abc
  acc.reach = reach > T(0) ? reach : T(0);
  const T r = acc.rb + acc.reach;
  if (!(near && near->cap > 0 && wall_sphere_near_visit(g, e.c, r, *near, acc)))
    mesh_for_each_near(g, e.c, r, acc);
}

// ellipsoid patches -> contacts of the contact layer (lab frame)
template <typename T>
POLYDEM_FN WallContacts<T> wall_ellipsoid_contacts(const WallPatches<T> &P, const MeshPose<T> &mp)
{
  WallContacts<T> C;
  C.n = P.n;
  const Vec3<T> xw = mesh_axis_point(mp);
  for (int k = 0; k < P.n; ++k) {
    const WallPatch<T> &q = P.p[k];
    // 1: a contact; 2: a liquid bridge across the gap (a sphere's patch
    // within reach, WallEllipsoidAccumulate), which acts only if it formed
    // in contact (wall_contact_forces)
    C.on[k] = q.depth > T(0) ? 1 : (q.gap >= T(0) ? 2 : 0);
    if (!C.on[k]) continue;
    ContactGeometry<T> &g = C.g[k];
    g.volume = q.depth;
    g.area = T(0);
    g.S_A = matvec(mp.R, q.S);
    g.normal = (T(1) / norm(g.S_A)) * g.S_A;    // from the particle into the wall
    C.key[k] = -matvec(mp.R, q.nseed);
    C.kpoint[k] = lab_point(mp, xw, q.p0);
    g.M_A = matvec(mp.R, q.M);
    g.M_B = make_vec3(T(0), T(0), T(0));
    g.centroid = lab_point(mp, xw, q.ac);
    g.gradient_damping = 0;
    // the bridge's gap: the separation, or minus the depth in contact
    // (U(s < 0) = U(0) + F(0) s, whose gradient is the pull F(0) n)
    g.has_gap = 1;
    g.gap = C.on[k] == 2 ? q.gap : -q.depth;
  }
  return C;
}

// A sphere of radius r under the volume law (fix wall/mesh with the
// material of pair_style polyhedron): each patch's measure delta becomes the
// volume of the cap the patch's plane cuts off, V = pi delta^2 (3r - delta)/3,
// exact where the section lies within the patch, and its gradient
// dV/d delta = pi delta (2r - delta) (the section's area) times delta's:
// the force stays the gradient of W(V(delta)).
template <typename T> POLYDEM_FN void sphere_cap_contacts(WallContacts<T> &C, T r)
{
  constexpr T PI = T(3.14159265358979323846264338327950288);
  for (int k = 0; k < C.n; ++k) {
    if (C.on[k] != 1) continue;
    ContactGeometry<T> &g = C.g[k];
    const T d = g.volume < T(2) * r ? g.volume : T(2) * r;
    const T A = PI * d * (T(2) * r - d);
    g.volume = PI * d * d * (T(3) * r - d) / T(3);
    g.S_A = A * g.S_A;
    g.M_A = A * g.M_A;
    g.area = norm(g.S_A);
  }
}

// Everything for one ellipsoid (semi-axes ax [length], lab pose x, q;
// velocity v, spin w; near its near list or null): pose into the mesh frame, patches, forces back in the
// lab frame (wall_contact_forces, the contact point's mass with the solid
// ellipsoid's moments I_x = m (b^2 + c^2) / 5, ...). law: ellipsoid_law;
// or, for a sphere with sphere_volume, wall_polyhedron_law (sphere_cap_contacts).
// A sphere whose law has a liquid bridge (law.bridge.volume > 0, R set) also
// finds the bridge patches within its rupture distance.
template <typename T>
POLYDEM_FN WallForce<T>
wall_ellipsoid_particle(const Vec3<T> &ax, const Pose<T> &lab, const MeshPose<T> &mp,
                        const MeshGridView<T> &g, const ContactLaw<T> &law, T m, T dt, T cosmax,
                        int both, const Vec3<T> &v, const Vec3<T> &w, T *hist, bool update,
                        WallPatches<T> &P, bool sphere_volume = false, WallNear<T> *near = nullptr)
{
  WallEllipsoid<T> e;
  e.c = mesh_point(mp, lab.x);
  e.R = quat_to_mat(mesh_orientation(mp, lab.q));
  e.ax = ax;
  const WallSides<T> sides = wall_kept_sides(hist, mp, both);
  const T reach = law.bridge.volume > T(0) ? law.bridge.rupture : T(0);
  wall_ellipsoid_patches(e, g, cosmax, P, &sides, reach, near);
  WallContacts<T> C = wall_ellipsoid_contacts(P, mp);
  if (sphere_volume) sphere_cap_contacts(C, ax.x);
  return wall_contact_forces(C, mp, law, m, ellipsoid_inverse_moments(m, ax),
                             quat_to_mat(lab.q), cosmax, lab.x, v, w, dt, hist, update);
}

// Per-triangle forces (pertriangle yes): each patch's force on the wall
// goes to the triangle of its closest point.
template <typename T, typename F>
POLYDEM_FN void wall_ellipsoid_triangle_forces(const WallPatches<T> &P, const WallForce<T> &wf,
                                               F &add)
{
  for (int k = 0; k < P.n; ++k)
    if (P.p[k].depth > T(0) || P.p[k].gap >= T(0))
      add(P.p[k].tri, -wf.fpatch[k].x, -wf.fpatch[k].y, -wf.fpatch[k].z);
}

}    // namespace polydem

#endif
