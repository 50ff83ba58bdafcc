/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - the contact layer: one contact law and one contact step for
   every geometry (pair polyhedron, pair ellipsoid, fix wall/mesh; plain and
   /kk alike). No LAMMPS includes; host and device.

   A geometry kernel (polydem_overlap.h for two polyhedra, polydem_wall_contact.h
   for a polyhedron on a mesh patch, polydem_ellipsoid_force.h for two
   ellipsoids) returns a ContactGeometry: an overlap measure m (the overlap
   volume V, or an overlap length delta), its gradient with respect to both
   bodies' positions and rotations, a unit normal n (from A towards B), a
   contact point and the contact area. A ContactLaw, chosen per type pair
   (and per wall), names its parts:
     normal      W(m) and W'(m): Feng's energy-conserving law in the overlap
                 volume with its polynomial core (polyhedral seed Eqs. 12-13),
                 or the linear spring 1/2 k_n delta^2 (ellipsoid seed Eq. 23);
     damping     the dashpot g = 2 zeta sqrt(k m_eff) (seed Eq. 14) on the
                 local normal stiffness k, zeta from one restitution
                 calibration over the contact's exponent q (polydem_damping.h);
     tangential  one Cundall-Strack spring-slider (Eqs. 17-20) with the
                 incremental k_t as an option, and a torsional spring-slider
                 for area contacts (twisting friction).
   contact_step(geometry, law, kinematics, history) is the only place where
   forces, torques and the contact energy are made. New parts (rolling
   resistance, cohesion) add a member to ContactLaw and a block to
   contact_step without touching the others.

   Normal (elastic): F_A = -W'(m) dm/dx_A, tau_A = -W'(m) dm/dtheta_A,
   tau_B = -W'(m) dm/dtheta_B, F_B = -F_A: the exact negative gradient of
   W(m) in translation and rotation (for the ellipsoids' chord measure, whose
   "gradient" is a point force at C along n, it is not; polydem_ellipsoid_force.h).
   Feng, m = V, K = E_A/R_A + E_B/R_B (R: volume-equivalent radii):
     W'(V) = K V^{1/3},  W(V) = 3/4 K V^{4/3} - 5/36 K V0^{4/3}        V >= V0
     W'(V) = K V0^{-2/3} (5/3 V - 2/3 V^2/V0),
     W(V)  = K V0^{-2/3} (5/6 V^2 - 2/9 V^3/V0)                        V <  V0
   (W, W', W'' continuous, W(0) = 0; the core bounds the stiffness of small
   overlaps by 5/3 K V0^{-2/3} A_n^2: a flat face resting under gravity
   would otherwise need vanishing time steps). The local stiffness of the
   normal coordinate delta = V / A_n is k = W''(V) A_n^2, the local exponent
   q = dln W'/dln V (1/3 above the core, -> 1 deep in it).
   Linear, m = delta: W = 1/2 k_n delta^2, W' = k_n delta, k = k_n, q = 1.

   Damping (Eq. 14, with the local stiffness instead of Eq. 15's K A_n: the
   V^{1/3} law is far stiffer near its maximum overlap, and with K A_n
   face-to-face cubes rebound with 0.99 for e = 0.85): on a point contact
   F_A^d = -g v_n n at the contact point (v_n: normal velocity of A relative
   to B there); with gradient damping (ellipsoids' centre measure) the
   Rayleigh force -g (dm/dt) grad m. g dt <= m_eff (the explicit stability
   limit; binds only in the first steps of a flat contact, where k -> inf).

   Tangential (Eqs. 17-20): the accumulated displacement s is kept in the
   current tangent plane (its length kept), F_t = -k_t s - g_t v_t with
   k_t = K_t A_n (area contacts; K_t = sum E/(2(1+nu)R)) or a constant k_t,
   g_t = 2 zeta_t sqrt(k_t m_eff), zeta_t = zeta_ratio x zeta; capped by
   mu F_n (then s is reset to the capped force). Incremental k_t: a growing
   area does not scale up the force already stored (-k_old s), only the new
   increment uses k_t; a shrinking one scales it down (Mindlin unloading);
   scaling a loaded spring up with the area pumped energy into dense
   frictional packings.

   Twisting (area contacts, keyword twist): a point spring cannot resist
   spin about n, a face contact does. The patch is taken as the disk of its
   area, a^2 = A_n / pi, with the tangential spring and dashpot spread
   uniformly over it: k_r = k_t a^2 / 2, g_r = g_t a^2 / 2 (the polar moment
   of the disk over its area); the twist angle phi of A relative to B about n
   gives M = -k_r phi - g_r w_n (w_n = (w_A - w_B).n), capped by the Coulomb
   torque of a uniform pressure on the disk, mu F_n r_eff, r_eff = 2/3 a
   (a square face: the exact lever is 0.3826 L, the disk's 0.3761 L).
   Pairs apply damping and friction at the centre of pressure
   (pressure_centre), on the elastic force's line of action.

   Dry cohesion (pair_coeff ... cohesion c; fix wall/mesh cohesion): a pull
   that is the exact gradient of U = -c m, a constant subtracted from W'(m),
   so that elastic contacts keep conserving energy. Feng (m = V): c = k_c,
   an adhesive stress; the pull k_c dV/dx_A = k_c A_n n is proportional to
   the contact area (the volume analogue of LIGGGHTS's SJKR), and the
   largest pull a contact can hold is k_c A_n at V -> 0 (W' -> 0 in the
   core). Linear (m = delta): c = 2 pi Gamma R_r, the DMT pull-off force of
   surface energy Gamma (Derjaguin, Muller and Toporov 1975), constant while
   in contact. R_r as for rolling; exact for spheres (for other shapes R_r
   follows the contact point, and U is the energy only at fixed R_r).

   Rolling resistance (pair_coeff ... rolling mu_r; fix wall/mesh rolling):
   the elastic-plastic spring-dashpot (EPSD) model, Ai, Chen, Rotter and
   Ooi, Powder Technol. 206 (2011) 269, model C (Eqs. 12-18). The relative
   rolling spin w_r = (w_A - w_B) - ((w_A - w_B).n) n loads a torque spring
   incrementally, M_k <- M_k - k_r w_r dt, k_r = k_rf k mu_r^2 R_r^2 (Eq. 13,
   k_rf = 2.25; k the normal stiffness of the damping coordinate), with a
   dashpot M_d = -C_r w_r, C_r = 2 eta_r sqrt(I_r k_r) (Eqs. 16-17),
   I_r^{-1} = sum_k (7/5 m_k r_k^2)^{-1} (a sphere's moment about the contact
   point; a wall has none). The torque M_k + M_d is capped at
   M_m = mu_r R_r F_n (Eq. 14) and the spring then reset to the capped torque
   less the dashpot's, as the tangential part does (and LAMMPS's rolling
   sds): a fully mobilised contact resists with exactly M_m (model C), and
   the dashpot cannot exceed the limit while the spring loads. Rolling radius R_r = r_A r_B / (r_A + r_B), r_k
   the distance from body k's centre to the contact point (on a wall
   R_r = r_A): the radii for spheres; a sphere on a polyhedron's flat face
   rolls on its own radius (RollingLaw::R, set by the pipeline). M_k is kept in the tangent plane with
   its length, like s. The torque M_k + M_d acts on A, its opposite on B;
   the spring stores |M_k|^2 / (2 k_r) (counted with spring_energy).

   History of one contact (CONTACT_HIST values, CONTACT_HIST_ROLL with rolling):
   s (3), k_old (1), phi (1), M_k (3).
   One sign convention everywhere: a pair's s and M_k are those of its
   lower-tag particle relative to the other (contact_history_sign); k_old is a
   magnitude, phi the same seen from either particle. Walls keep theirs per particle.
------------------------------------------------------------------------- */

#ifndef POLYDEM_CONTACT_LAW_H
#define POLYDEM_CONTACT_LAW_H

#include "polydem_math.h"

#include <cmath>

namespace polydem {

using std::cbrt;
using std::log;
using std::atan;

// ---------------------------------------------------------------------------
// geometry -> law

template <typename T> struct ContactGeometry {
  T volume;             // overlap measure m: volume V [L^3] (Feng) or length delta [L] (linear)
  T area;               // contact area A_n [L^2] (0: point contact)
  Vec3<T> normal;       // unit normal, from A towards B
  Vec3<T> centroid;     // contact point
  Vec3<T> S_A, M_A, M_B;    // dm/dx_A, dm/dtheta_A, dm/dtheta_B (dm/dx_B = -S_A)
  int gradient_damping = 0;    // 1: Rayleigh dashpot along grad m; 0: at the point along n
  // liquid bridge: 1 if gap is the surfaces' separation along n (two
  // spheres: |x_B - x_A| - r_A - r_B, negative in overlap); 0: unknown
  int has_gap = 0;
  T gap = T(0);
};

// The fields of an overlap result (polydem_overlap.h OverlapResult).
template <typename T, typename Overlap>
POLYDEM_FN ContactGeometry<T> contact_geometry(const Overlap &ov)
{
  ContactGeometry<T> g;
  g.volume = ov.volume;
  g.area = ov.area;
  g.normal = ov.normal;
  g.centroid = ov.centroid;
  g.S_A = ov.S_A;
  g.M_A = ov.M_A;
  g.M_B = ov.M_B;
  g.gradient_damping = 0;
  return g;
}

// The centre of pressure of an overlap-volume contact: the point of the line
// of action of the elastic force (-W' S_A on A, moment -W' M_A about x_A, so
// the line is x_A + S_A x M_A / |S_A|^2 + t S_A) nearest the overlap's
// centroid. Damping and friction act there, in line with the elastic force.
// For a face lying flat on another it is the centroid of the contact face,
// which stays put when the faces tilt by a hair; the centroid of the thin
// overlap wedge moves by a good part of the face for a tilt of 1e-8 rad (the
// wedge's thickness changes sign across the face), and friction applied
// there tipped spinning cubes onto an edge. Two spheres (M_A = 0): the line
// of centres. The volume centroid if S_A = 0, or if the point is farther from
// it than sqrt(A_n): where S_A nearly cancels (an overlap around both sides
// of a thin piece) the line is ill-conditioned, and a point far outside the
// overlap would put friction on a long lever.
template <typename T>
POLYDEM_FN Vec3<T> pressure_centre(const Vec3<T> &S_A, const Vec3<T> &M_A, const Vec3<T> &xA,
                                   const Vec3<T> &centroid)
{
  const T s2 = norm2(S_A);
  if (!(s2 > T(0))) return centroid;
  const Vec3<T> p = xA + (T(1) / s2) * cross(S_A, M_A);
  const Vec3<T> c = p + (dot(centroid - p, S_A) / s2) * S_A;
  return norm2(c - centroid) <= sqrt(s2) ? c : centroid;
}

// ---------------------------------------------------------------------------
// normal law

enum NormalKind : int { NORMAL_FENG = 0, NORMAL_LINEAR = 1 };

template <typename T> struct NormalLaw {
  int kind;
  T K;     // Feng: E_A/R_A + E_B/R_B [pressure/length]; linear: k_n [force/length]
  T V0;    // Feng: volume below which W' is the polynomial core (0: pure V^{1/3})
};

template <typename T> struct NormalValue {
  T W;     // energy W(m)
  T Wp;    // W'(m)
  T k;     // stiffness of the damping coordinate: W''(V) A_n^2 (Feng), k_n (linear)
  T q;     // local exponent dln W'/dln m
};

template <typename T> POLYDEM_FN NormalValue<T> normal_value(const NormalLaw<T> &L, T m, T area)
{
  NormalValue<T> r;
  if (L.kind == NORMAL_LINEAR) {
    r.Wp = L.K * m;
    r.W = T(0.5) * L.K * m * m;
    r.k = L.K;
    r.q = T(1);
    return r;
  }
  if (m < L.V0) {
    const T c0 = cbrt(L.V0);
    const T c = L.K / (c0 * c0);
    const T u = m / L.V0;
    r.Wp = c * m * (T(5) / T(3) - T(2) / T(3) * u);
    r.W = c * m * m * (T(5) / T(6) - T(2) / T(9) * u);
    r.k = c * (T(5) / T(3) - T(4) / T(3) * u) * area * area;
    r.q = (T(5) / T(3) - T(4) / T(3) * u) / (T(5) / T(3) - T(2) / T(3) * u);
  } else {
    const T v13 = cbrt(m);
    r.Wp = L.K * v13;
    r.W = T(0.75) * r.Wp * m - T(5) / T(36) * L.K * L.V0 * cbrt(L.V0);
    r.k = v13 > T(0) ? L.K * area * area / (T(3) * v13 * v13) : T(0);
    r.q = T(1) / T(3);
  }
  return r;
}

// ---------------------------------------------------------------------------
// damping law: zeta(e, q) of polydem_damping.h at q = 1/3 and q = 1 (exact
// there; linear in q between), filled on the host (damping_law)

template <typename T> struct DampingLaw {
  T z[2];       // zeta(e, 1/3), zeta(e, 1)
  int local;    // 1: zeta at the contact's local exponent q; 0: zeta(e, 1/3) always
};

template <typename T> POLYDEM_FN T damping_zeta(const DampingLaw<T> &d, T q)
{
  if (!d.local) return d.z[0];
  T w = (q - T(1) / T(3)) * T(1.5);
  w = w < T(0) ? T(0) : (w > T(1) ? T(1) : w);
  return (T(1) - w) * d.z[0] + w * d.z[1];
}

// dashpot coefficient g = 2 zeta sqrt(k m_eff), capped at g dt <= m_eff (dt > 0):
// beyond it the explicit step would reverse the relative velocity instead of
// damping it (the time step too long for this contact); capped set to 1 then
template <typename T> POLYDEM_FN T dashpot(T zeta, T k, T meff, T dt, int &capped)
{
  T g = T(2) * zeta * sqrt(k * meff);
  if (dt > T(0) && g * dt > meff) {
    g = meff / dt;
    capped = 1;
  }
  return g;
}

// ---------------------------------------------------------------------------
// tangential law

template <typename T> struct TangentialLaw {
  T mu;              // Coulomb coefficient (0: no tangential part, history zeroed)
  T Kt;              // k_t = Kt A_n (area_scaled) or k_t = Kt
  T zeta_ratio;      // zeta_t / zeta of the normal dashpot
  int area_scaled;   // k_t proportional to the contact area
  int incremental;   // k_old in the history (incremental k_t)
  int twist;         // torsional spring-slider (area contacts)
  int cap_abs;       // cap mu |F_n| (polyhedra, as in the seed) instead of mu max(F_n, 0)
  int spring_energy; // 1/2 k_t |s|^2 counted in the contact energy
};

// rolling resistance (EPSD, Ai et al. 2011); mu_r = 0: none
template <typename T> struct RollingLaw {
  T mu_r = T(0);    // rolling friction coefficient (M_m = mu_r R_r F_n)
  T kr = T(2.25);   // k_r = kr k mu_r^2 R_r^2 (Ai et al. Eq. 13)
  T eta = T(0.3);   // dashpot C_r = 2 eta sqrt(I_r k_r) (Eq. 17)
  T R = T(0);       // R_r of the contact if known (a sphere on a flat face: its
                    // radius); 0: from the lever arms (rolling_radius)
};

// liquid bridge (Willett et al. 2000), between spheres; volume = 0: none
template <typename T> struct BridgeLaw {
  T volume = T(0);       // liquid volume of the bridge V_b [L^3]
  T gamma = T(0);        // surface tension [force/length]
  T cos_theta = T(1);    // cosine of the contact angle
  T rupture = T(0);      // rupture separation s_c = (1 + theta/2) V_b^(1/3)
  T R = T(0);            // the pair's radius 2 r_A r_B / (r_A + r_B) (set per contact)
  T eta = T(0);          // viscosity of the liquid (0: no viscous part)
  T smin = T(0);         // the viscous part's smallest gap (the surfaces' roughness)
};

template <typename T> struct ContactLaw {
  NormalLaw<T> normal;
  DampingLaw<T> damping;
  TangentialLaw<T> tangential;
  RollingLaw<T> rolling;
  // dry cohesion (0: none): Feng, the adhesive stress k_c [pressure],
  // U = -k_c V; linear, the surface energy Gamma [energy/area] of DMT,
  // U = -2 pi Gamma R_r delta
  T cohesion = T(0);
  BridgeLaw<T> bridge;
};

// ---------------------------------------------------------------------------
// kinematics, history, result

template <typename T> struct ContactKinematics {
  Vec3<T> xA, xB;    // reference points of the torques (centres of mass)
  Vec3<T> vA, vB, wA, wB;
  T meff;            // mass the contact sees (reduced mass, or contact-point mass)
  T dt;              // time step; 0: no increment of the history (setup)
  T mA = T(0), mB = T(0);    // the bodies' masses (rolling); mB = 0: B is a wall
};

template <typename T>
POLYDEM_FN ContactKinematics<T> make_kinematics(const Vec3<T> &xA, const Vec3<T> &xB,
                                                const Vec3<T> &vA, const Vec3<T> &vB,
                                                const Vec3<T> &wA, const Vec3<T> &wB, T meff, T dt,
                                                T mA = T(0), T mB = T(0))
{
  return ContactKinematics<T>{xA, xB, vA, vB, wA, wB, meff, dt, mA, mB};    // in the members' order
}

constexpr int CONTACT_HIST = 5;         // s (3), k_old, phi
constexpr int CONTACT_HIST_ROLL = 8;    // + M_k (3) of rolling resistance
constexpr int HIST_K = 3, HIST_TWIST = 4, HIST_ROLL = 5;

template <typename T> struct ContactForce {
  Vec3<T> F_A;      // force on A (B gets -F_A)
  Vec3<T> tau_A;    // torque on A about x_A
  Vec3<T> tau_B;    // torque on B about x_B
  T energy;         // W(m) (+ the tangential spring's, spring_energy)
  T fn;             // normal force (elastic + damping) on A along -n
  T ft;             // tangential force magnitude
  T rate;           // rate of the damping coordinate (v_n, or dm/dt)
  int capped = 0;    // normal dashpot or bridge viscosity cut to m_eff / dt
};

// a pair's history is that of its lower-tag particle relative to the other:
// s and M_k change sign with the order; k_old and phi do not (phi is the
// twist of A relative to B about n, and swapping A and B negates both)
POLYDEM_FN double contact_history_sign(long tag_i, long tag_j)
{
  return tag_i < tag_j ? 1.0 : -1.0;
}
template <typename T> POLYDEM_FN void history_orient(T *h, int n, T sign)
{
  for (int k = 0; k < n && k < 3; ++k) h[k] *= sign;
  for (int k = HIST_ROLL; k < n && k < HIST_ROLL + 3; ++k) h[k] *= sign;
}

// velocity of A's material point at the contact point relative to B's
template <typename T>
POLYDEM_FN Vec3<T> contact_relative_velocity(const ContactGeometry<T> &g,
                                             const ContactKinematics<T> &kin)
{
  return (kin.vA + cross(kin.wA, g.centroid - kin.xA)) -
      (kin.vB + cross(kin.wB, g.centroid - kin.xB));
}

// rate of the damping coordinate: dm/dt (gradient damping), else v_n
template <typename T>
POLYDEM_FN T contact_rate(const ContactGeometry<T> &g, const ContactKinematics<T> &kin)
{
  if (g.gradient_damping)
    return dot(g.S_A, kin.vA - kin.vB) + dot(g.M_A, kin.wA) + dot(g.M_B, kin.wB);
  return dot(contact_relative_velocity(g, kin), g.normal);
}

// the contact's rolling radius R_r = r_A r_B / (r_A + r_B), r_k the
// distance from body k's centre to the contact point; r_A on a wall (mB = 0)
template <typename T> POLYDEM_FN T rolling_radius(T rA, T rB, const ContactKinematics<T> &kin)
{
  return kin.mB > T(0) ? rA * rB / (rA + rB) : rA;
}
template <typename T>
POLYDEM_FN T rolling_radius(const ContactGeometry<T> &g, const ContactKinematics<T> &kin)
{
  const T rA = norm(g.centroid - kin.xA);
  if (!(kin.mB > T(0))) return rA;
  return rolling_radius(rA, norm(g.centroid - kin.xB), kin);
}

// Rolling resistance of one contact (EPSD, see above): the torque on A
// (B gets its opposite) from the spring M_k in hist[0..2], updated in place;
// fn the normal force, k the normal stiffness; energy += the spring's
// (spring_energy).
template <typename T>
POLYDEM_FN Vec3<T> rolling_torque(const ContactGeometry<T> &g, const RollingLaw<T> &rl,
                                  const ContactKinematics<T> &kin, T fn, T k, int spring_energy,
                                  T *hist, T &energy)
{
  const Vec3<T> n = g.normal;
  const T rA = norm(g.centroid - kin.xA), rB = norm(g.centroid - kin.xB);
  const T Rr = rl.R > T(0) ? rl.R : rolling_radius(rA, rB, kin);    // the two norms once
  const T kr = rl.kr * k * rl.mu_r * rl.mu_r * Rr * Rr;
  // M_k in the current tangent plane, its length kept
  Vec3<T> M = make_vec3(hist[0], hist[1], hist[2]);
  const T m0 = norm(M);
  M -= dot(M, n) * n;
  const T m1 = norm(M);
  if (m1 > T(0)) M = (m0 / m1) * M;
  const Vec3<T> dw = kin.wA - kin.wB;
  const Vec3<T> wr = dw - dot(dw, n) * n;
  M -= (kr * kin.dt) * wr;
  T Cr = T(0);
  if (kin.mA > T(0) && rA > T(0)) {
    T iIr = T(5) / (T(7) * kin.mA * rA * rA);
    if (kin.mB > T(0) && rB > T(0)) iIr += T(5) / (T(7) * kin.mB * rB * rB);
    Cr = T(2) * rl.eta * sqrt(kr / iIr);
  }
  const Vec3<T> Md = (-Cr) * wr;
  Vec3<T> Mt = M + Md;
  const T mmax = rl.mu_r * Rr * (fn > T(0) ? fn : T(0));
  const T mt = norm(Mt);
  if (mt > mmax) {    // fully mobilised: M_m, the spring reset to it less the dashpot
    Mt = (mt > T(0) ? mmax / mt : T(0)) * Mt;
    M = Mt - Md;
  }
  hist[0] = M.x;
  hist[1] = M.y;
  hist[2] = M.z;
  if (spring_energy && kr > T(0)) energy += T(0.5) * norm2(M) / kr;
  return Mt;
}

// Liquid bridge between two spheres (Willett, Adams, Johnson and Seville,
// Langmuir 16 (2000) 9396, the closed form of their Eq. 13 with the full
// separation s): F(s) = 2 pi R gamma cos(theta) / (1 + 1.05 s^ + 2.5 s^2),
// s^ = s sqrt(R / V_b), R = 2 r_A r_B / (r_A + r_B) (Derjaguin's mean radius
// for unequal spheres); F(s <= 0) = F(0). The bridge forms when the spheres
// touch and ruptures at s_c = (1 + theta/2) V_b^(1/3) (Lian, Thornton and
// Adams, J. Colloid Interface Sci. 161 (1993) 138). Its energy is
// U(s) = -int_s^s_c F ds' (arctan closed form; U(s < 0) = U(0) + F(0) s),
// so that the pull F n on A is -dU/dx_A; the U(0) it has on forming is
// what a rupture dissipates.
//
// Its optional viscous part (Pitois, Moucheront and Chateau, J. Colloid
// Interface Sci. 231 (2000) 26, their closed form for two equal spheres of
// radius R, here with the bridge's R): a force on A along -n proportional
// to the approach speed v_n (the relative velocity at the bridge's point
// along n; positive when the gap closes),
//   F_v = -(3/2) pi eta R^2 / D (1 - 1/sqrt(1 + 2 V_b / (pi R D^2)))^2 v_n,
// D = max(s, s_min): Reynolds' lubrication force 6 pi eta R*^2 v / D
// (R* = R/2) for a bridge much wider than the gap, falling to zero as the
// gap outgrows the liquid; s_min (the surfaces' roughness) bounds it where
// the gap closes. It acts across the gap (s > 0) only: in contact the
// contact's own dashpot damps the normal motion, and the two together could
// exceed the stable step. As the normal dashpot, its coefficient is capped
// at m_eff / dt. It stores nothing: all its work is dissipated.
// the law of V_b, gamma, theta [radians], and of the viscous part eta,
// s_min (R set per contact); V_b or gamma not > 0: none; eta or s_min not
// > 0: no viscous part
template <typename T>
POLYDEM_FN BridgeLaw<T> make_bridge_law(T volume, T gamma, T theta, T eta = T(0), T smin = T(0))
{
  BridgeLaw<T> b;
  if (!(volume > T(0) && gamma > T(0))) return b;
  b.volume = volume;
  b.gamma = gamma;
  b.cos_theta = cos(theta);
  b.rupture = (T(1) + T(0.5) * theta) * cbrt(volume);
  if (eta > T(0) && smin > T(0)) {
    b.eta = eta;
    b.smin = smin;
  }
  return b;
}
template <typename T> POLYDEM_FN T bridge_force(const BridgeLaw<T> &b, T s)
{
  const T k = sqrt(b.R / b.volume);
  const T u = s > T(0) ? s * k : T(0);
  return T(2) * T(3.14159265358979323846) * b.R * b.gamma * b.cos_theta /
      (T(1) + T(1.05) * u + T(2.5) * u * u);
}
template <typename T> POLYDEM_FN T bridge_energy(const BridgeLaw<T> &b, T s)
{
  // int du / (1 + a u + c u^2) = 2 / w atan((2 c u + a) / w), w = sqrt(4c - a^2)
  const T a = T(1.05), c = T(2.5), w = sqrt(T(4) * c - a * a);
  const T k = sqrt(b.R / b.volume);
  const T F0 = T(2) * T(3.14159265358979323846) * b.R * b.gamma * b.cos_theta;
  const T u = s > T(0) ? s * k : T(0), uc = b.rupture * k;
  const T U = -F0 / k * (T(2) / w) *
      (atan((T(2) * c * uc + a) / w) - atan((T(2) * c * u + a) / w));
  return s < T(0) ? U + F0 * s : U;
}

// the viscous part's coefficient c at gap s: F_v = -c v_n n on A (Pitois)
template <typename T> POLYDEM_FN T bridge_viscous_coefficient(const BridgeLaw<T> &b, T s)
{
  const T pi = T(3.14159265358979323846);
  const T D = s > b.smin ? s : b.smin;
  const T q = T(1) - T(1) / sqrt(T(1) + T(2) * b.volume / (pi * b.R * D * D));
  return T(1.5) * pi * b.eta * b.R * b.R / D * q * q;
}

// the bridge's pull on A along n at the contact point (g.has_gap), and its
// viscous force across a gap where it has one, added to a contact's forces
// and energy
template <typename T, typename Out>
POLYDEM_FN void add_bridge(const ContactGeometry<T> &g, const BridgeLaw<T> &b,
                           const ContactKinematics<T> &kin, Out &out)
{
  T f = bridge_force(b, g.gap);
  if (b.eta > T(0) && g.gap > T(0)) {
    T c = bridge_viscous_coefficient(b, g.gap);
    if (kin.dt > T(0) && c * kin.dt > kin.meff) {
      c = kin.meff / kin.dt;
      out.capped = 1;
    }
    f -= c * dot(contact_relative_velocity(g, kin), g.normal);
  }
  const Vec3<T> F = f * g.normal;
  out.F_A += F;
  out.tau_A += cross(g.centroid - kin.xA, F);
  out.tau_B -= cross(g.centroid - kin.xB, F);
  out.energy += bridge_energy(b, g.gap);
}

// Forces of one contact. hist: the contact's history, nhist values in use
// (3: s only; 4: + k_old; 5: + phi; 8: + M_k of rolling), updated in place
// (the caller keeps it or not, e.g. at setup).
template <typename T>
POLYDEM_FORCE_FN ContactForce<T> contact_step(const ContactGeometry<T> &g,
                                              const ContactLaw<T> &law,
                                              const ContactKinematics<T> &kin, T *hist, int nhist)
{
  ContactForce<T> out;
  NormalValue<T> nv = normal_value(law.normal, g.volume, g.area);
  if (law.cohesion > T(0)) {
    // dry cohesion: a constant c subtracted from W'(m), the exact gradient of
    // U = -c m (Feng: c = k_c, the pull k_c A_n; linear: c = 2 pi Gamma R_r,
    // the DMT pull-off force)
    const T c = law.normal.kind == NORMAL_LINEAR
        ? T(2) * T(3.14159265358979323846) * law.cohesion * rolling_radius(g, kin)
        : law.cohesion;
    nv.Wp -= c;
    nv.W -= c * g.volume;
  }
  out.energy = nv.W;
  out.F_A = -nv.Wp * g.S_A;
  out.tau_A = -nv.Wp * g.M_A;
  out.tau_B = -nv.Wp * g.M_B;

  const Vec3<T> n = g.normal;
  const Vec3<T> rA = g.centroid - kin.xA, rB = g.centroid - kin.xB;
  const Vec3<T> vr = contact_relative_velocity(g, kin);
  const T vn = dot(vr, n);

  // normal damping, Eq. 14, on the local stiffness
  const T zeta = damping_zeta(law.damping, nv.q);
  const T gn = dashpot(zeta, nv.k, kin.meff, kin.dt, out.capped);
  if (g.gradient_damping) {
    out.rate = contact_rate(g, kin);
    const T s = gn * out.rate;
    out.F_A -= s * g.S_A;
    out.tau_A -= s * g.M_A;
    out.tau_B -= s * g.M_B;
    out.fn = -dot(out.F_A, n);
  } else {
    out.rate = vn;
    const Vec3<T> Fd = (-gn * vn) * n;
    out.F_A += Fd;
    out.tau_A += cross(rA, Fd);
    out.tau_B -= cross(rB, Fd);
    out.fn = law.normal.kind == NORMAL_FENG ? nv.Wp * g.area + gn * vn : -dot(out.F_A, n);
  }
  out.ft = T(0);
  if (law.bridge.volume > T(0) && g.has_gap) add_bridge(g, law.bridge, kin, out);

  // rolling resistance (EPSD)
  if (nhist >= HIST_ROLL + 3) {
    if (law.rolling.mu_r > T(0)) {
      const Vec3<T> Mr = rolling_torque(g, law.rolling, kin, out.fn, nv.k,
                                        law.tangential.spring_energy, hist + HIST_ROLL, out.energy);
      out.tau_A += Mr;
      out.tau_B -= Mr;
    } else
      for (int k = HIST_ROLL; k < HIST_ROLL + 3; ++k) hist[k] = T(0);
  }

  const TangentialLaw<T> &tl = law.tangential;
  if (!(tl.mu > T(0))) {
    for (int k = 0; k < nhist && k < HIST_ROLL; ++k) hist[k] = T(0);
    return out;
  }

  // tangential, Eqs. 17-20: keep s in the current tangent plane (same length)
  Vec3<T> s = make_vec3(hist[0], hist[1], hist[2]);
  const T s0 = norm(s);
  s -= dot(s, n) * n;
  const T s1 = norm(s);
  if (s1 > T(0)) s = (s0 / s1) * s;
  const Vec3<T> vt = vr - vn * n;
  const T kt = tl.area_scaled ? tl.Kt * g.area : tl.Kt;
  const T kold = tl.incremental ? hist[HIST_K] : kt;
  if (kt > kold && kt > T(0)) s = (kold / kt) * s;
  s += kin.dt * vt;
  const T gt = T(2) * (tl.zeta_ratio * zeta) * sqrt(kt * kin.meff);
  Vec3<T> Ft = (-kt) * s - gt * vt;
  const T ftm = norm(Ft);
  const T fnc = tl.cap_abs ? fabs(out.fn) : (out.fn > T(0) ? out.fn : T(0));
  const T fmax = tl.mu * fnc;
  out.ft = ftm;
  if (ftm > fmax) {
    // slip: cap at mu F_n and reset the spring to the capped force
    Ft = (ftm > T(0) ? fmax / ftm : T(0)) * Ft;
    if (kt > T(0)) s = (T(-1) / kt) * (Ft + gt * vt);
    out.ft = norm(Ft);
  }
  hist[0] = s.x;
  hist[1] = s.y;
  hist[2] = s.z;
  if (tl.incremental) hist[HIST_K] = kt;
  out.F_A += Ft;
  out.tau_A += cross(rA, Ft);
  out.tau_B -= cross(rB, Ft);
  if (tl.spring_energy) out.energy += T(0.5) * kt * norm2(s);

  // twisting: torsional spring-slider on the disk of the contact area
  if (tl.twist && nhist > HIST_TWIST) {
    const T a2 = g.area * T(0.31830988618379067154);    // A_n / pi
    const T kr = T(0.5) * kt * a2, gr = T(0.5) * gt * a2;
    const T wn = dot(kin.wA - kin.wB, n);
    T phi = hist[HIST_TWIST];
    // k_r ~ k_t^2 when k_t ~ A_n: the incremental rule of the spring
    if (tl.incremental && kt > kold && kt > T(0)) phi *= (kold / kt) * (kold / kt);
    phi += kin.dt * wn;
    T Mt = -kr * phi - gr * wn;
    const T mmax = fmax * (T(2) / T(3)) * sqrt(a2);
    if (fabs(Mt) > mmax) {
      Mt = Mt > T(0) ? mmax : -mmax;
      phi = kr > T(0) ? -(Mt + gr * wn) / kr : T(0);
    }
    hist[HIST_TWIST] = phi;
    out.tau_A += Mt * n;
    out.tau_B -= Mt * n;
    if (tl.spring_energy && kr > T(0)) out.energy += T(0.5) * kr * phi * phi;
  } else if (nhist > HIST_TWIST)
    hist[HIST_TWIST] = T(0);
  return out;
}

// contact_step of a pair (A = the pair's first atom) on its stored history
// (n values in the pair convention, sign = contact_history_sign of A and B;
// null: none, e.g. frictionless), written back if keep (not at setup)
template <typename T>
POLYDEM_FN ContactForce<T> pair_contact_step(const ContactGeometry<T> &g, const ContactLaw<T> &law,
                                             const ContactKinematics<T> &kin, T *stored, int n,
                                             T sign, bool keep)
{
  T h[CONTACT_HIST_ROLL];
  for (int k = 0; k < n; ++k) h[k] = stored ? stored[k] : T(0);
  history_orient(h, n, sign);
  const ContactForce<T> cf = contact_step(g, law, kin, h, n);
  if (stored && keep) {
    history_orient(h, n, sign);
    for (int k = 0; k < n; ++k) stored[k] = h[k];
  }
  return cf;
}

// forces and torques of a contact to atoms i and, if to_j, j (host arrays)
template <typename T>
inline void scatter_contact_host(T **f, T **torque, int i, int j, bool to_j,
                                 const ContactForce<T> &cf)
{
  const T F[3] = {cf.F_A.x, cf.F_A.y, cf.F_A.z};
  const T tA[3] = {cf.tau_A.x, cf.tau_A.y, cf.tau_A.z}, tB[3] = {cf.tau_B.x, cf.tau_B.y, cf.tau_B.z};
  for (int k = 0; k < 3; ++k) {
    f[i][k] += F[k];
    torque[i][k] += tA[k];
    if (to_j) {
      f[j][k] -= F[k];
      torque[j][k] += tB[k];
    }
  }
}

// ---------------------------------------------------------------------------
// the laws of the package's styles

// Polyhedra (Feng): K, K_t from the two particles' E, nu and (scaled)
// volumes (Eqs. 13, 19; R: radius of the sphere of equal volume), V0 = core
// x the smaller volume; damping d; friction mu; twist on or off.
template <typename T>
POLYDEM_FN ContactLaw<T> feng_law(T Ei, T nui, T Vi, T Ej, T nuj, T Vj, const DampingLaw<T> &d,
                                  T mu, T core, int twist)
{
  const T f = T(3) / (T(4) * T(3.14159265358979323846));
  const T Ri = cbrt(f * Vi), Rj = Vj == Vi ? Ri : cbrt(f * Vj);    // walls, equal grains: one cbrt
  ContactLaw<T> L;
  L.normal.kind = NORMAL_FENG;
  L.normal.K = Ei / Ri + Ej / Rj;
  L.normal.V0 = core * (Vi < Vj ? Vi : Vj);
  L.damping = d;
  L.tangential.mu = mu;
  L.tangential.Kt = Ei / (T(2) * (T(1) + nui) * Ri) + Ej / (T(2) * (T(1) + nuj) * Rj);
  L.tangential.zeta_ratio = T(1);
  L.tangential.area_scaled = 1;
  L.tangential.incremental = 1;
  L.tangential.twist = twist;
  L.tangential.cap_abs = 1;
  L.tangential.spring_energy = 0;
  return L;
}

// Explicit stability limit of a flat face contact (area A, e.g. the largest
// face) resting in the core: its local stiffness W''(V) A^2 is largest at
// V -> 0, W''(0) A^2 = 5/3 K V0^(-2/3) A^2, and velocity Verlet is stable for
// dt < 2 sqrt(m_eff / k). 0 if there is no core (V0 = 0: no bound).
template <typename T> POLYDEM_FN T face_contact_stable_dt(const NormalLaw<T> &L, T meff, T A)
{
  if (!(L.V0 > T(0)) || !(A > T(0))) return T(0);
  const T k = T(5) / T(3) * L.K / cbrt(L.V0 * L.V0) * A * A;
  return T(2) * sqrt(meff / k);
}

}    // namespace polydem

#endif
