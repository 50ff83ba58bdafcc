// The per-contact entry points (polydem_contact_pipeline.h, polydem_wall_pipeline.h) against the
// composition of the kernels they run: each entry point gives, bit for bit,
// the force, torques, energy and history of GJK -> overlap -> feng_law ->
// pair_contact_step (polyhedra), ellipsoid_contact -> ellipsoid_geometry ->
// ellipsoid_law -> pair_contact_step (ellipsoids) and wall_particle /
// wall_ellipsoid_particle with the type's wall law (walls), for coefficients
// taken from a LawTable; a pair out of contact clears its history slot;
// counters land in the caller's array; the gathers read host arrays.
#include "polydem_contact_pipeline.h"
#include "polydem_wall_pipeline.h"
#include "polydem_damping.h"
#include "polydem_stl.h"
#include "test_shapes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <vector>

using namespace polydem;

namespace {

// a 2-type table: type 1 and 2 with their own E, nu, k_n; pair e and mu
struct Table {
  std::vector<LawEntry<double>> e;
  LawTable<double> t;
  // nhist: history values per contact (0: the law table's default);
  // friction false: mu = 0 on every pair
  explicit Table(bool wall, int nhist = 0, bool friction = true)
  {
    const double E[3] = {0, 1e7, 3e7}, nu[3] = {0, 0.3, 0.2}, kn[3] = {0, 1e3, 2e3};
    const int n = wall ? 3 : 9;
    e.assign(n, LawEntry<double>());
    for (int i = 1; i <= 2; i++)
      for (int j = wall ? 0 : 1; j <= (wall ? 0 : 2); j++) {
        auto &x = wall ? e[i] : e[i * 3 + j];
        x.E1 = E[i];
        x.nu1 = nu[i];
        x.E2 = wall ? 2e7 : E[j];
        x.nu2 = wall ? 0.25 : nu[j];
        x.kn = wall ? kn[i] : 0.5 * (kn[i] + kn[j]);
        x.mu = 0.3 + 0.1 * (i + j);
        x.damping = damping_law(0.5 + 0.1 * (i + j), 1);
      }
    t = law_table(e.data(), 2, n);
    t.core = 1e-3;
    t.twist = 1;
    t.kt_ratio = 2.0 / 7.0;
    t.gt_ratio = 0.5;
    t.overlap_warn = 1e-9;    // every contact counts as a large overlap
    if (nhist) t.nhist = nhist;
    if (!friction)
      for (auto &x : e) x.mu = 0.0;
  }
};

// two atoms in host arrays, as LAMMPS keeps them
struct Atoms2 {
  double xs[2][3], qs[2][4], vs[2][3], ws[2][3];
  double *x[2], *quat[2], *v[2], *omega[2];
  double pscale[2], rmass[2];
  int type[2];
  long tag[2];
  Atoms2(double gap, double s0, double s1)
  {
    const double q0[4] = {0.9, 0.1, -0.3, 0.2}, q1[4] = {0.7, -0.2, 0.4, 0.5};
    for (int k = 0; k < 2; k++) {
      const double *q = k ? q1 : q0;
      const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
      for (int d = 0; d < 4; d++) qs[k][d] = q[d] / n;
      for (int d = 0; d < 3; d++) {
        xs[k][d] = k ? (d == 0 ? gap : 0.05 * d) : 0.0;
        vs[k][d] = k ? -0.3 + 0.1 * d : 0.5 - 0.2 * d;
        ws[k][d] = k ? 2.0 - d : -1.0 + d;
      }
      x[k] = xs[k];
      quat[k] = qs[k];
      v[k] = vs[k];
      omega[k] = ws[k];
      type[k] = k + 1;
      tag[k] = k ? 7 : 12;    // the first atom has the higher tag: sign -1
    }
    pscale[0] = s0;
    pscale[1] = s1;
    rmass[0] = 2.0;
    rmass[1] = 3.0;
  }
};

void expect_same(const ContactForce<double> &a, const ContactForce<double> &b)
{
  const double pa[12] = {a.F_A.x, a.F_A.y, a.F_A.z, a.tau_A.x, a.tau_A.y, a.tau_A.z,
                         a.tau_B.x, a.tau_B.y, a.tau_B.z, a.energy, a.fn, a.ft};
  const double pb[12] = {b.F_A.x, b.F_A.y, b.F_A.z, b.tau_A.x, b.tau_A.y, b.tau_A.z,
                         b.tau_B.x, b.tau_B.y, b.tau_B.z, b.energy, b.fn, b.ft};
  for (int k = 0; k < 12; k++) EXPECT_EQ(pa[k], pb[k]) << k;
}

Vec3<double> vec(const double *a)
{
  return make_vec3(a[0], a[1], a[2]);
}

}    // namespace

TEST(ContactPipeline, LawTableIndexing)
{
  Table p(false), w(true);
  EXPECT_EQ(&p.t.pair(1, 2), &p.e[5]);
  EXPECT_EQ(&p.t.pair(2, 1), &p.e[7]);
  EXPECT_EQ(&w.t.wall(2), &w.e[2]);
  const auto L = polyhedron_pair_law(p.t, 2, 1, 0.5, 0.25);
  const auto R = feng_law(3e7, 0.2, 0.5, 1e7, 0.3, 0.25, p.e[7].damping, p.e[7].mu, 1e-3, 1);
  EXPECT_EQ(L.normal.K, R.normal.K);
  EXPECT_EQ(L.tangential.Kt, R.tangential.Kt);
  EXPECT_EQ(L.normal.V0, R.normal.V0);
}

TEST(ContactPipeline, PolyhedronPairIsTheComposition)
{
  const auto shape = polydem_test::make_shape(polydem_test::cube_points(1.0));
  std::unique_ptr<polydem_test::TypedShape<double>> cube(polydem_test::typed<double>(shape));
  const ShapeView<double> &sv = cube->view;
  Table tab(false);
  auto ws = std::make_unique<OverlapWorkspace<double, 16>>();
  int ncontact = 0, napart = 0;
  for (double gap : {0.8, 1.0, 3.0}) {
    Atoms2 at(gap, 0.9, 1.1);
    const auto atoms = host_atoms(&at);
    const auto A = gather_polyhedron_body(atoms, 0, sv), B = gather_polyhedron_body(atoms, 1, sv);
    double h[CONTACT_HIST] = {1e-3, -2e-3, 5e-4, 10.0, 1e-2}, h0[CONTACT_HIST];
    for (int k = 0; k < CONTACT_HIST; k++) h0[k] = h[k];
    double cnt[PP_NCOUNT] = {0, 0, 0, 0, 0};
    // a pair in contact at the last step (its history continues)
    const auto r = polyhedron_pair_contact(A, B, tab.t, 1e-4, true, h, *ws, cnt, true);

    Pose<double> pa, pb;
    pa.x = vec(at.x[0]);
    pa.q = make_quat(at.qs[0][0], at.qs[0][1], at.qs[0][2], at.qs[0][3]);
    pa.s = 0.9;
    pb.x = vec(at.x[1]);
    pb.q = make_quat(at.qs[1][0], at.qs[1][1], at.qs[1][2], at.qs[1][3]);
    pb.s = 1.1;
    const auto a = make_posed(sv, pa), b = make_posed(sv, pb);
    const auto g = gjk_intersect(a, b);
    if (g.status == STATUS_SEPARATED) {
      EXPECT_EQ(r.contact, 0);
      for (double x : h) EXPECT_EQ(x, 0.0);
      EXPECT_EQ(cnt[PP_CONTACTS], 0.0);
      napart++;
      continue;
    }
    const auto ov = polyhedron_overlap(a, b, *ws);
    ASSERT_EQ(ov.status, STATUS_OK);
    ASSERT_EQ(r.contact, 1);
    const double Va = sv.volume * 0.9 * 0.9 * 0.9, Vb = sv.volume * 1.1 * 1.1 * 1.1;
    const auto law = feng_law(1e7, 0.3, Va, 3e7, 0.2, Vb, tab.e[5].damping, tab.e[5].mu, 1e-3, 1);
    const auto kin = make_kinematics(pa.x, pb.x, vec(at.v[0]), vec(at.v[1]), vec(at.omega[0]),
                                     vec(at.omega[1]), 2.0 * 3.0 / 5.0, 1e-4);
    // damping and friction at the centre of pressure
    auto geo = contact_geometry<double>(ov);
    geo.centroid = pressure_centre(ov.S_A, ov.M_A, pa.x, ov.centroid);
    const auto cf = pair_contact_step(geo, law, kin, h0, CONTACT_HIST, -1.0, true);
    expect_same(r.cf, cf);
    for (int k = 0; k < CONTACT_HIST; k++) EXPECT_EQ(h[k], h0[k]) << k;
    EXPECT_EQ(r.vmin, Va);
    EXPECT_EQ(cnt[PP_CONTACTS], 1.0);
    EXPECT_EQ(cnt[PP_BIGOVERLAP], 1.0);
    ncontact++;
  }
  EXPECT_EQ(ncontact, 2);
  EXPECT_EQ(napart, 1);
}

// A pair not in contact keeps GJK's separating axis in its history slot
// (GJK_AXIS_VALUES) and the next step tests it first; a contact starts from a
// cleared slot. Two cubes approach, turning, and part again: every step
// gives, bit for bit, the force and history of the same step with a cleared
// slot (no axis kept), and most apart steps are decided by the kept axis.
TEST(ContactPipeline, ApartPairKeepsGjkAxis)
{
  const auto shape = polydem_test::make_shape(polydem_test::cube_points(1.0));
  std::unique_ptr<polydem_test::TypedShape<double>> cube(polydem_test::typed<double>(shape));
  const ShapeView<double> &sv = cube->view;
  Table tab(false);
  ASSERT_GE(tab.t.nhist, GJK_AXIS_VALUES);
  auto ws = std::make_unique<OverlapWorkspace<double, 16>>();
  double h[CONTACT_HIST] = {0, 0, 0, 0, 0}, href[CONTACT_HIST] = {0, 0, 0, 0, 0};
  int touch = 0, touchref = 0, napart = 0, nkept = 0, ncontact = 0;
  const int nstep = 400;
  for (int step = 0; step < nstep; ++step) {
    // the gap closes from 2.0 to 0.85 and opens again
    const double t = (double) step / (nstep - 1);
    const double gap = 0.85 + 1.15 * std::fabs(2.0 * t - 1.0);
    Atoms2 at(gap, 0.9, 1.1);
    const double ang = 0.3 * t;
    const Quat<double> turn = make_quat(std::cos(ang), 0.0, std::sin(ang), 0.0);
    const Quat<double> qb = qmul(make_quat(at.qs[1][0], at.qs[1][1], at.qs[1][2], at.qs[1][3]), turn);
    at.qs[1][0] = qb.w;
    at.qs[1][1] = qb.x;
    at.qs[1][2] = qb.y;
    at.qs[1][3] = qb.z;
    const auto atoms = host_atoms(&at);
    const auto A = gather_polyhedron_body(atoms, 0, sv), B = gather_polyhedron_body(atoms, 1, sv);
    // the axis kept from the last step decides this one?
    if (!touch && (h[0] != 0.0 || h[1] != 0.0 || h[2] != 0.0)) {
      int ia = (int) h[3], ib = (int) h[4];
      nkept += gjk_axis_separates(A.shape, B.shape, make_vec3(h[0], h[1], h[2]), ia, ib);
    }
    double cnt[PP_NCOUNT] = {0, 0, 0, 0, 0}, cntref[PP_NCOUNT] = {0, 0, 0, 0, 0};
    const auto r = polyhedron_pair_contact(A, B, tab.t, 1e-4, true, h, *ws, cnt, touch != 0);
    // the reference: a slot holding no axis while apart
    if (!touchref)
      for (double &x : href) x = 0.0;
    const auto rr =
        polyhedron_pair_contact(A, B, tab.t, 1e-4, true, href, *ws, cntref, touchref != 0);
    ASSERT_EQ(r.contact, rr.contact) << "step " << step;
    for (int k = 0; k < PP_NCOUNT; k++) EXPECT_EQ(cnt[k], cntref[k]) << k;
    const bool was_touching = touch != 0;
    touch = r.contact;
    touchref = rr.contact;
    if (r.contact) {
      ++ncontact;
      expect_same(r.cf, rr.cf);
      for (int k = 0; k < CONTACT_HIST; k++) EXPECT_EQ(h[k], href[k]) << "step " << step;
    } else {
      ++napart;
      if (was_touching) {    // the contact ended (GJK not run): a cleared slot
        for (double x : h) EXPECT_EQ(x, 0.0) << "step " << step;
        continue;
      }
      // the slot holds an axis along which the cubes are apart
      int ia = (int) h[3], ib = (int) h[4];
      EXPECT_TRUE(gjk_axis_separates(A.shape, B.shape, make_vec3(h[0], h[1], h[2]), ia, ib))
          << "step " << step;
    }
  }
  // a slot holding values that are no axis (NaN, out-of-range vertices) is
  // ignored: GJK decides, as with a cleared slot
  for (double gap : {0.85, 2.0}) {
    Atoms2 at(gap, 0.9, 1.1);
    const auto atoms = host_atoms(&at);
    const auto A = gather_polyhedron_body(atoms, 0, sv), B = gather_polyhedron_body(atoms, 1, sv);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    double hbad[CONTACT_HIST] = {nan, 1.0, 0.0, 1e300, -7.0}, hz[CONTACT_HIST] = {0, 0, 0, 0, 0};
    double c1[PP_NCOUNT] = {0, 0, 0, 0, 0}, c2[PP_NCOUNT] = {0, 0, 0, 0, 0};
    const auto r1 = polyhedron_pair_contact(A, B, tab.t, 1e-4, true, hbad, *ws, c1, false);
    const auto r2 = polyhedron_pair_contact(A, B, tab.t, 1e-4, true, hz, *ws, c2, false);
    ASSERT_EQ(r1.contact, r2.contact) << gap;
    if (r1.contact) expect_same(r1.cf, r2.cf);
    for (int k = 0; k < CONTACT_HIST; k++) EXPECT_EQ(hbad[k], hz[k]) << gap << " " << k;
  }
  std::printf("[ pipeline ] cubes approaching and parting: %d apart steps (%d decided by the "
              "kept axis), %d contact steps\n", napart, nkept, ncontact);
  EXPECT_GT(ncontact, 20);
  EXPECT_GT(napart, 150);
  EXPECT_GE(nkept, 0.9 * (napart - 2));
}

TEST(ContactPipeline, EllipsoidPairIsTheComposition)
{
  const Vec3<double> ax = make_vec3(0.6, 0.4, 0.3);
  for (int overlap : {OVERLAP_CENTRE, OVERLAP_CHORD})
    for (int mass : {DAMPING_REDUCED, DAMPING_CONTACT})
      for (bool friction : {true, false}) {
        Table tab(false, ELLIPSOID_HIST, friction);
        tab.t.overlap = overlap;
        tab.t.damping_mass = mass;
        Atoms2 at(0.5, 1.0, 0.8);
        const auto atoms = host_atoms(&at);
        const auto A = gather_ellipsoid_body(atoms, 0, ax), B = gather_ellipsoid_body(atoms, 1, ax);
        double h[ELLIPSOID_HIST] = {1e-3, -2e-3, 5e-4}, h0[ELLIPSOID_HIST];
        for (int k = 0; k < ELLIPSOID_HIST; k++) h0[k] = h[k];
        double cnt[EP_NCOUNT] = {0, 0, 0, 0, 0};
        const auto r = ellipsoid_pair_contact(A, B, tab.t, 1e-4, true, friction ? h : nullptr,
                                              0.5, cnt);
        ASSERT_EQ(r.contact, 1);

        EllipsoidPose<double> pa, pb;
        pa.x = vec(at.x[0]);
        pa.q = make_quat(at.qs[0][0], at.qs[0][1], at.qs[0][2], at.qs[0][3]);
        pa.axes = 1.0 * ax;
        pb.x = vec(at.x[1]);
        pb.q = make_quat(at.qs[1][0], at.qs[1][1], at.qs[1][2], at.qs[1][3]);
        pb.axes = 0.8 * ax;
        const auto c = ellipsoid_contact(pa, pb);
        ASSERT_EQ(c.status, STATUS_OK);
        const double meff = mass == DAMPING_CONTACT
            ? ellipsoid_contact_mass(c, overlap, pa, pb, 2.0, 3.0)
            : 2.0 * 3.0 / 5.0;
        const auto kin = make_kinematics(pa.x, pb.x, vec(at.v[0]), vec(at.v[1]), vec(at.omega[0]),
                                         vec(at.omega[1]), meff, 1e-4);
        const auto geo = ellipsoid_geometry(c, overlap, pa.x, pb.x);
        const auto law = ellipsoid_law(1.5e3, tab.e[5].damping, tab.e[5].mu, 2.0 / 7.0, 0.5);
        const auto cf =
            pair_contact_step(geo, law, kin, friction ? h0 : nullptr, ELLIPSOID_HIST, -1.0, true);
        expect_same(r.cf, cf);
        for (int k = 0; k < ELLIPSOID_HIST; k++) EXPECT_EQ(h[k], h0[k]) << k;
        EXPECT_EQ(cnt[EP_CONTACTS], 0.5);
        EXPECT_EQ(cnt[EP_BIGOVERLAP], 1.0);
      }
  // apart: no contact, the history slot cleared
  Table tab(false, ELLIPSOID_HIST);
  Atoms2 at(5.0, 1.0, 1.0);
  const auto atoms = host_atoms(&at);
  double h[ELLIPSOID_HIST] = {1.0, 2.0, 3.0}, cnt[EP_NCOUNT] = {0, 0, 0, 0, 0};
  const auto r = ellipsoid_pair_contact(gather_ellipsoid_body(atoms, 0, ax),
                                        gather_ellipsoid_body(atoms, 1, ax), tab.t, 1e-4, true, h,
                                        1.0, cnt);
  EXPECT_EQ(r.contact, 0);
  for (double x : h) EXPECT_EQ(x, 0.0);
}

// Two ellipsoids of unequal semi-axes under pair polyhedron's entry point
// meet by the algebraic contact: the same force, torques, energy and history
// as ellipsoid_pair_contact, bit for bit. As a part of a composite (offset
// and turned in its body), the force and the torques about the bodies'
// centres are minus the gradient of the energy 1/2 k_n delta^2 (central
// differences of the bodies' poses, to 1e-6 of the largest).
TEST(ContactPipeline, EllipsoidPairsOfPairPolyhedronAreAlgebraic)
{
  const Vec3<double> ax = make_vec3(0.6, 0.4, 0.3);
  ShapeView<double> egg;
  egg.axes[0] = ax.x;
  egg.axes[1] = ax.y;
  egg.axes[2] = ax.z;
  egg.radius = ax.x;    // bounding radius (the composite's part pairs by bounding spheres)
  for (bool friction : {true, false}) {
    Table tab(false, CONTACT_HIST, friction);
    Atoms2 at(0.5, 1.0, 0.8);
    const auto atoms = host_atoms(&at);
    const auto A = gather_polyhedron_body(atoms, 0, egg), B = gather_polyhedron_body(atoms, 1, egg);
    OverlapWorkspace<double, 64> ws;
    double h[CONTACT_HIST] = {1e-3, -2e-3, 5e-4, 0, 0}, h0[CONTACT_HIST];
    for (int k = 0; k < CONTACT_HIST; k++) h0[k] = h[k];
    double cnt[PP_NCOUNT] = {}, ecnt[EP_NCOUNT] = {};
    const auto r = polyhedron_pair_contact(A, B, tab.t, 1e-4, true, friction ? h : nullptr, ws, cnt);
    ASSERT_EQ(r.contact, 1);
    const auto e = ellipsoid_pair_contact(gather_ellipsoid_body(atoms, 0, ax),
                                          gather_ellipsoid_body(atoms, 1, ax), tab.t, 1e-4, true,
                                          friction ? h0 : nullptr, 1.0, ecnt);
    expect_same(r.cf, e.cf);
    for (int k = 0; k < CONTACT_HIST; k++) EXPECT_EQ(h[k], h0[k]) << k;
    EXPECT_EQ(cnt[PP_CONTACTS], 1.0);
    EXPECT_EQ(r.geo.volume, e.geo.volume);
  }

  // the egg as the one part of a composite, off its centre and turned
  ShapePart<double> part;
  part.view = &egg;
  const double px[3] = {0.25, -0.1, 0.15};
  const Quat<double> pq = qnormalize(make_quat(0.8, 0.3, -0.2, 0.4));
  const Mat3<double> pR = quat_to_mat(pq);
  for (int i = 0; i < 3; i++) {
    part.x[i] = px[i];
    for (int j = 0; j < 3; j++) part.R[i][j] = pR.m[i][j];
  }
  part.q[0] = pq.w;
  part.q[1] = pq.x;
  part.q[2] = pq.y;
  part.q[3] = pq.z;
  ShapeView<double> comp;
  comp.nparts = 1;
  comp.parts = &part;
  comp.radius = 0.3 + ax.x;
  Table tab(false, CONTACT_HIST);
  tab.t.nslot = 1;    // composites keep keyed part contacts
  for (auto &x : tab.e) {
    x.mu = 0.0;
    x.cohesion = 50.0;    // the volume law's adhesive stress: not applied here
  }
  const Pose<double> pa0{make_vec3(0.0, 0.0, 0.0), qnormalize(make_quat(0.9, 0.1, -0.3, 0.2)), 1.0};
  const Pose<double> pb0{make_vec3(0.75, 0.05, 0.1), qnormalize(make_quat(0.7, -0.2, 0.4, 0.5)),
                         0.8};
  auto body = [&](const ShapeView<double> &v, const Pose<double> &p, int type, long tag) {
    PolyhedronBody<double> b;
    b.shape = make_posed(v, p);
    b.v = b.w = make_vec3(0.0, 0.0, 0.0);
    b.m = 2.0;
    b.type = type;
    b.tag = tag;
    return b;
  };
  OverlapWorkspace<double, 64> ws;
  auto contact = [&](const Pose<double> &pa, const Pose<double> &pb) {
    double hist[1 + CONTACT_HIST] = {}, cnt[PP_NCOUNT] = {};
    return polyhedron_pair_contact(body(comp, pa, 1, 12), body(egg, pb, 2, 7), tab.t, 1e-4, false,
                                   hist, ws, cnt);
  };
  const auto r = contact(pa0, pb0);
  ASSERT_EQ(r.contact, 1);
  ASSERT_GT(r.cf.energy, 0.0);
  // the record's overlap is the algebraic contact's length over the smallest
  // semi-axis (0.8 x 0.3), not mixed with a volume; the energy is the
  // spring's alone (no cohesion)
  EXPECT_EQ(r.vmin, 0.8 * 0.3);
  EXPECT_GT(r.geo.volume, 0.0);
  EXPECT_LT(r.geo.volume, r.vmin);
  EXPECT_NEAR(r.cf.energy, 0.5 * tab.e[1 * 3 + 2].kn * r.geo.volume * r.geo.volume,
              1e-12 * r.cf.energy);
  const double d = 1e-6;
  double gx[3], gtA[3], gtB[3], fmax = 0.0, tmax = 0.0;
  for (int k = 0; k < 3; k++) {
    Pose<double> p = pa0, m = pa0;
    (&p.x.x)[k] += d;
    (&m.x.x)[k] -= d;
    gx[k] = (contact(p, pb0).cf.energy - contact(m, pb0).cf.energy) / (2 * d);
    // small rotations about lab axis k of body A, then of body B, about their centres
    double w[3] = {0, 0, 0};
    w[k] = 0.5 * d;
    const Quat<double> qp = make_quat(std::sqrt(1 - w[k] * w[k]), w[0], w[1], w[2]);
    const Quat<double> qm = qconj(qp);
    Pose<double> ap = pa0, am = pa0, bp = pb0, bm = pb0;
    ap.q = qmul(qp, pa0.q);
    am.q = qmul(qm, pa0.q);
    bp.q = qmul(qp, pb0.q);
    bm.q = qmul(qm, pb0.q);
    gtA[k] = (contact(ap, pb0).cf.energy - contact(am, pb0).cf.energy) / (2 * d);
    gtB[k] = (contact(pa0, bp).cf.energy - contact(pa0, bm).cf.energy) / (2 * d);
  }
  const double F[3] = {r.cf.F_A.x, r.cf.F_A.y, r.cf.F_A.z};
  const double tA[3] = {r.cf.tau_A.x, r.cf.tau_A.y, r.cf.tau_A.z};
  const double tB[3] = {r.cf.tau_B.x, r.cf.tau_B.y, r.cf.tau_B.z};
  for (int k = 0; k < 3; k++) {
    fmax = std::fmax(fmax, std::fabs(F[k]));
    tmax = std::fmax(tmax, std::fmax(std::fabs(tA[k]), std::fabs(tB[k])));
  }
  for (int k = 0; k < 3; k++) {
    EXPECT_NEAR(F[k], -gx[k], 1e-6 * fmax) << k;
    EXPECT_NEAR(tA[k], -gtA[k], 1e-6 * tmax) << k;
    EXPECT_NEAR(tB[k], -gtB[k], 1e-6 * tmax) << k;
  }
  std::printf("composite's egg part on an egg: F %.6g %.6g %.6g, tau_A %.6g %.6g %.6g (energy "
              "gradient by central differences agrees)\n",
              F[0], F[1], F[2], tA[0], tA[1], tA[2]);
}

TEST(ContactPipeline, WallBodyIsTheComposition)
{
  // a flat square z = 0, two triangles
  const std::vector<double> tri = {-3, -3, 0, 3, -3, 0, 3, 3, 0, -3, -3, 0, 3, 3, 0, -3, 3, 0};
  const MeshGrid mg = build_mesh_grid(tri, 1.0);
  WallScene<double> sc;
  sc.mp.o = sc.mp.d = sc.mp.vw = sc.mp.w = make_vec3(0.0, 0.0, 0.0);
  sc.mp.q = make_quat(1.0, 0.0, 0.0, 0.0);
  sc.mp.R = quat_to_mat(sc.mp.q);
  sc.grid = MeshGridView<double>{tri.data(),     2,
                                 {mg.lo[0], mg.lo[1], mg.lo[2]},
                                 mg.h,           {mg.n[0], mg.n[1], mg.n[2]},
                                 mg.start.data(), mg.items.data(),
                                 mg.plane.data(), mg.box.data()};
  sc.cosmax = std::cos(20.0 * 3.14159265358979323846 / 180.0);
  sc.both = 1;
  sc.depth_warn = 0.25;
  sc.overlap_warn = 0.05;
  sc.near_skin = 0.02;
  sc.sphere_volume = 0;
  Table tab(true);

  const auto shape = polydem_test::make_shape(polydem_test::cube_points(1.0));
  std::unique_ptr<polydem_test::TypedShape<double>> cube(polydem_test::typed<double>(shape));
  ShapeView<double> sv = cube->view;
  sv.inertia[0] = sv.inertia[1] = sv.inertia[2] = 1.0 / 6.0;
  auto ws = std::make_unique<WallWorkspace<double>>();
  for (bool ellipsoid : {false, true}) {
    Atoms2 at(0.0, 0.9, 0.9);
    at.xs[0][2] = ellipsoid ? 0.35 : 0.5;    // into the wall
    const auto atoms = host_atoms(&at);
    const Vec3<double> ax = ellipsoid ? make_vec3(0.6, 0.4, 0.45) : make_vec3(0.0, 0.0, 0.0);
    const auto b = gather_wall_body(atoms, 0, &sv, ax);
    double h[WALL_HIST_SIZE] = {}, h0[WALL_HIST_SIZE] = {};
    WallPatches<double> P, P0;
    WallNear<double> *none = nullptr;
    const auto r = wall_body_contact(b, tab.t, sc, 1e-4, true, h, *ws, P, none);
    ASSERT_GT(r.wf.ncontact, 0);

    const double s = 0.9, V = sv.volume * s * s * s;
    WallForce<double> wf;
    if (ellipsoid)
      wf = wall_ellipsoid_particle(s * ax, b.pose, sc.mp, sc.grid,
                                   ellipsoid_law(1e3, tab.e[1].damping, tab.e[1].mu, 2.0 / 7.0, 0.5),
                                   2.0, 1e-4, sc.cosmax, 1, vec(at.v[0]), vec(at.omega[0]), h0,
                                   true, P0);
    else
      wf = wall_particle(
          sv, b.pose, sc.mp, sc.grid,
          [&] { return wall_law(1e7, 0.3, 2e7, 0.25, V, tab.e[1].damping, tab.e[1].mu, 1e-3, 1); },
          2.0, 1e-4, sc.cosmax, 1, vec(at.v[0]), vec(at.omega[0]), h0, true, *ws, P0);
    const double fa[7] = {r.wf.f.x, r.wf.f.y, r.wf.f.z, r.wf.tau.x, r.wf.tau.y, r.wf.tau.z,
                          r.wf.energy};
    const double fb[7] = {wf.f.x, wf.f.y, wf.f.z, wf.tau.x, wf.tau.y, wf.tau.z, wf.energy};
    for (int k = 0; k < 7; k++) EXPECT_EQ(fa[k], fb[k]) << k;
    for (int k = 0; k < WALL_HIST_SIZE; k++) EXPECT_EQ(h[k], h0[k]) << k;
    EXPECT_EQ(P.n, P0.n);
    const auto w = wall_warnings(P0, wf, V, sv.radius * s, 2.0, 0.25, 0.05);
    EXPECT_EQ(r.warn.fresh, w.fresh);
    EXPECT_EQ(r.warn.fresh_v, w.fresh_v);
    WallTally<double> sum;
    wall_tally_add(sum, b, r, sc.mp, P);
    EXPECT_EQ(sum.force[2], -wf.f.z);
  }
}
