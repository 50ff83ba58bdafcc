// fix insert/polyhedron (issue 14), one rank: no overlap is ever created
// (checked with the exact kernels, independently of the insertion's own
// test), the schedule's counts and mass flow, the distributions (chi^2 and
// Kolmogorov-Smirnov at significance 1e-3), the packing fraction, restart,
// and bad input.

#include "insert_scene.h"
#include "insert_stats.h"

#include "poly_shape_library.h"
#include "domain.h"
#include "compute.h"
#include "fix.h"
#include "modify.h"
#include "polydem_ellipsoid.h"
#include "polydem_gjk.h"
#include "polydem_overlap.h"
#include "polydem_shape_template.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <map>
#include <memory>

using namespace insert_test;
using LAMMPS_NS::PolyShapeLibrary;
using insert_test::ks_crit;

namespace {

struct Particle {
  long tag;
  int shape;
  double s;
  polydem::Vec3<double> x;
  polydem::Quat<double> q;
};

std::vector<Particle> particles(Lmp &l)
{
  std::vector<Particle> out;
  for (auto &kv : l.local_state()) {
    Particle p;
    p.tag = kv.first;
    p.shape = kv.second.shape;
    p.s = kv.second.s;
    p.x = polydem::make_vec3(kv.second.x[0], kv.second.x[1], kv.second.x[2]);
    p.q = polydem::make_quat(kv.second.q[0], kv.second.q[1], kv.second.q[2], kv.second.q[3]);
    out.push_back(p);
  }
  return out;
}

// posed vertices of a polyhedron, or points on an ellipsoid's surface
std::vector<polydem::Vec3<double>> surface_points(const polydem::PolyShapeTemplate &t, const Particle &p)
{
  std::vector<polydem::Vec3<double>> pts;
  const auto R = polydem::quat_to_mat(p.q);
  if (!t.is_ellipsoid()) {
    for (int i = 0; i < t.nverts(); i++) {
      const auto v = t.vertex(i);
      pts.push_back(p.x + p.s * polydem::matvec(R, polydem::make_vec3(v[0], v[1], v[2])));
    }
    return pts;
  }
  const auto &a = t.semi_axes();
  const int nt = 40, np = 80;    // a grid in (theta, phi)
  for (int i = 0; i <= nt; i++)
    for (int j = 0; j < np; j++) {
      const double th = M_PI * i / nt, ph = 2 * M_PI * j / np;
      const auto u = polydem::make_vec3(a[0] * std::sin(th) * std::cos(ph),
                                        a[1] * std::sin(th) * std::sin(ph), a[2] * std::cos(th));
      pts.push_back(p.x + p.s * polydem::matvec(R, u));
    }
  return pts;
}

bool inside(const polydem::PolyShapeTemplate &t, const Particle &p, const polydem::Vec3<double> &y)
{
  const auto R = polydem::quat_to_mat(p.q);
  const auto b = (1.0 / p.s) * polydem::matTvec(R, y - p.x);
  if (t.is_ellipsoid()) {
    const auto &a = t.semi_axes();
    return b.x * b.x / (a[0] * a[0]) + b.y * b.y / (a[1] * a[1]) + b.z * b.z / (a[2] * a[2]) < 1.0;
  }
  for (int f = 0; f < t.nfaces(); f++) {
    const auto pl = t.plane(f);
    if (pl[0] * b.x + pl[1] * b.y + pl[2] * b.z > pl[3]) return false;
  }
  return true;
}

// Every particle with tag > tag0 against every other particle, with the
// exact kernels: polyhedra by the overlap volume (and GJK), ellipsoids by
// the characteristic quartic, a mixed pair by surface points of each inside
// the other. Returns the number of overlapping pairs.
int overlaps(Lmp &l, long tag0, int *npairs_close = nullptr)
{
  auto avec = PolyShapeLibrary::of(l.lmp, "test");
  const auto ps = particles(l);
  auto ws = std::make_unique<polydem::OverlapWorkspace<double>>();
  std::vector<polydem::ShapeView<double>> views;
  for (int i = 0; i < avec->ntemplates(); i++) views.push_back(avec->shape(i).view());
  int bad = 0, close = 0;
  for (size_t i = 0; i < ps.size(); i++) {
    if (ps[i].tag <= tag0) continue;
    const auto &ti = avec->shape(ps[i].shape);
    for (size_t j = 0; j < ps.size(); j++) {
      if (i == j || (ps[j].tag > tag0 && ps[j].tag < ps[i].tag)) continue;    // each new pair once
      const auto &tj = avec->shape(ps[j].shape);
      const double rr = ti.radius() * ps[i].s + tj.radius() * ps[j].s;
      if (polydem::norm2(ps[i].x - ps[j].x) > rr * rr) continue;
      close++;
      if (!ti.is_ellipsoid() && !tj.is_ellipsoid()) {
        polydem::Pose<double> a{ps[i].x, ps[i].q, ps[i].s}, b{ps[j].x, ps[j].q, ps[j].s};
        const auto pa = polydem::make_posed(views[ps[i].shape], a);
        const auto pb = polydem::make_posed(views[ps[j].shape], b);
        const auto o = polydem::polyhedron_overlap(pa, pb, *ws);
        if (o.volume > 0.0 || polydem::gjk_intersect(pa, pb).status != polydem::STATUS_SEPARATED) bad++;
      } else if (ti.is_ellipsoid() && tj.is_ellipsoid()) {
        const auto &ai = ti.semi_axes(), &aj = tj.semi_axes();
        polydem::EllipsoidPose<double> a{ps[i].x, ps[i].q,
                                         polydem::make_vec3(ai[0] * ps[i].s, ai[1] * ps[i].s, ai[2] * ps[i].s)};
        polydem::EllipsoidPose<double> b{ps[j].x, ps[j].q,
                                         polydem::make_vec3(aj[0] * ps[j].s, aj[1] * ps[j].s, aj[2] * ps[j].s)};
        if (polydem::ellipsoid_contact(a, b).status != polydem::STATUS_SEPARATED) bad++;
      } else {
        bool hit = false;
        for (const auto &y : surface_points(ti, ps[i])) hit = hit || inside(tj, ps[j], y);
        for (const auto &y : surface_points(tj, ps[j])) hit = hit || inside(ti, ps[i], y);
        bad += hit;
      }
    }
  }
  if (npairs_close) *npairs_close = close;
  return bad;
}

// surface points of the particles with tag > tag0 outside insert_scene's
// container (x, y in (-0.02, 0.02), z > 0)
int outside_container(Lmp &l, long tag0)
{
  auto avec = PolyShapeLibrary::of(l.lmp, "test");
  int n = 0;
  for (const auto &p : particles(l)) {
    if (p.tag <= tag0) continue;
    for (const auto &y : surface_points(avec->shape(p.shape), p))
      n += !(y.x > -0.02 && y.x < 0.02 && y.y > -0.02 && y.y < 0.02 && y.z > 0.0);
  }
  return n;
}

double fvec(Lmp &l, const std::string &fix, int i)
{
  auto f = l.lmp->modify->fix[l.lmp->modify->find_fix(fix.c_str())];
  return f->compute_vector(i);
}


std::vector<std::string> mixed_box(double side = 0.06)
{
  const std::string L = std::to_string(side);
  return {"units si", "atom_style polyhedron", "atom_modify map array", "boundary p p p",
          "region box block 0 " + L + " 0 " + L + " 0 " + L, "create_box 1 box",
          "polyhedron_shape d " + potentials() + "/dodecahedron.shape",
          "polyhedron_shape c " + potentials() + "/catalyst_cylinder.shape",
          "polyhedron_shape q " + potentials() + "/cube.shape",
          "polyhedron_shape e ellipsoid 1.0 0.6 0.4"};
}

// mixed_box() packed by the fix command `fix` (mode pack: all at run 0)
void pack(Lmp &l, const std::string &fix)
{
  l.cmds(mixed_box());
  l.cmd(fix);
  l.cmd("run 0");
}

}    // namespace

// Acceptance 1 (pack): 5,000 mixed dodecahedra, cylinders, cubes and
// ellipsoids into a periodic box; no pair of them overlaps.
TEST(Insert, PackMixedShapesNeverOverlap)
{
  Lmp l;
  l.cmds(mixed_box(0.045));
  l.cmd("fix ins all insert/polyhedron 5000 4711 region box mode pack density 2500 all_in no "
        "shape d 0.3 scale uniform 0.0008 0.0012 shape c 0.2 scale 0.3 "
        "shape q 0.2 scale 0.0018 shape e 0.3 scale normal 0.0014 0.0002 0.001 0.0018");
  l.cmd("run 0");
  ASSERT_EQ(l.lmp->atom->natoms, 5000);
  int close = 0;
  EXPECT_EQ(overlaps(l, 0, &close), 0);
  EXPECT_GT(close, 2000);    // dense: many pairs within their bounding spheres
  EXPECT_GT(fvec(l, "ins", 3), 0.25);
  // the check can fail: 100 particles created at random points do overlap
  l.cmds({"create_atoms 1 random 100 31 NULL",
          "polyhedron_set atom 5001*5100 shape d scale 0.001 density 2500 quat/random 5"});
  EXPECT_GT(overlaps(l, 5000), 10);
}

// polyhedra and spheres packed under pair_style polyhedron (issue 29): the
// pair style's exact overlap volumes (polyhedron pairs, polyhedron-sphere,
// sphere pairs) find no contact at the first step
TEST(Insert, PackPolyhedraAndSpheresUnderPairPolyhedron)
{
  Lmp l;
  l.cmds(mixed_box(0.03));
  l.cmds({"polyhedron_shape s ellipsoid 1.0 1.0 1.0", "comm_modify vel yes",
          "fix ins all insert/polyhedron 800 4711 region box mode pack density 2500 all_in no "
          "shape d 0.5 scale uniform 0.0008 0.0012 shape s 0.5 scale uniform 0.0008 0.0013",
          "pair_style polyhedron", "pair_coeff * * 1e7 0.3 0.5 0.3", "thermo_style custom step pe",
          "run 0"});
  ASSERT_EQ(l.lmp->atom->natoms, 800);
  int close = 0;
  EXPECT_EQ(overlaps(l, 0, &close), 0);
  EXPECT_GT(close, 100);
  EXPECT_EQ(l.thermo("pe"), 0.0);
  // and a sphere placed into the pack does touch (the check can fail)
  l.cmds({"create_atoms 1 random 20 31 NULL",
          "polyhedron_set atom 801*820 shape s scale 0.0012 density 2500", "run 0"});
  EXPECT_GT(l.thermo("pe"), 0.0);
}

// composites (issue 29): an L of two bars, a dumbbell of a cube and a
// sphere and dodecahedra packed under pair_style polyhedron: every part
// apart from every other grain's parts (and from the box's walls), so the
// pair style's exact part-by-part overlaps find no contact at the first step;
// a composite placed into the pack does touch (the check can fail)
TEST(Insert, PackCompositesUnderPairPolyhedron)
{
  Lmp l;
  l.cmds(mixed_box(0.03));
  l.cmds({"polyhedron_shape ball ellipsoid 0.5 0.5 0.5",
          "polyhedron_shape L composite part q -0.5 0 0 part q 0.5 0 0 part q -0.5 1 0",
          "polyhedron_shape db composite part q 0 0 0 part ball 1.2 0 0",
          "comm_modify vel yes",
          "fix ins all insert/polyhedron 500 4711 region box mode pack density 2500 all_in no "
          "shape L 0.4 scale 0.0009 shape db 0.3 scale 0.001 shape d 0.3 scale 0.001",
          "pair_style polyhedron", "pair_coeff * * 1e7 0.3 0.5 0.3",
          "thermo_style custom step pe", "run 0"});
  ASSERT_EQ(l.lmp->atom->natoms, 500);
  EXPECT_EQ(l.thermo("pe"), 0.0);
  int composites = 0;
  for (int i = 0; i < l.lmp->atom->nlocal; i++) composites += l.lmp->atom->pshape[i] != 0;
  EXPECT_GT(composites, 250);
  l.cmds({"create_atoms 1 random 20 31 NULL",
          "polyhedron_set atom 501*520 shape L scale 0.0009 density 2500 quat/random 7", "run 0"});
  EXPECT_GT(l.thermo("pe"), 0.0);
}

// Acceptance 1 (rate): 5,000 insertions of the same mixture at a high rate
// into a small falling stream (no contacts: particles pass through each
// other, so the feed region stays crowded and the test of each new particle
// against the others and against the ones of its own insertion is busy).
TEST(Insert, RateMixedShapesNeverOverlapWhenTheyAppear)
{
  Lmp l;
  l.cmds(mixed_box());
  l.cmds({"region feed block 0 0.06 0 0.06 0.03 0.05",
          "fix ins all insert/polyhedron 5000 99 region feed per 500 every 50 density 2500 "
          "all_in no shape d 0.3 scale uniform 0.0008 0.0012 shape c 0.2 scale 0.3 "
          "shape q 0.2 scale 0.0018 shape e 0.3 scale 0.0014 vel constant 0 0 -1",
          "fix nve all nve/polyhedron", "timestep 1e-5"});
  long tag0 = 0;
  int total_bad = 0, events = 0;
  while (l.lmp->atom->natoms < 5000 && events < 40) {
    l.cmd(events == 0 ? "run 0" : "run 50");
    total_bad += overlaps(l, tag0);
    tag0 = (long) l.lmp->atom->natoms;
    events++;
  }
  EXPECT_EQ(l.lmp->atom->natoms, 5000);
  EXPECT_EQ(total_bad, 0);
}

// Acceptance 1 with contacts and a mesh: polyhedra poured into an STL box;
// each particle is created apart from the others and inside the container
// (every vertex strictly within the walls) at the step it appears.
TEST(Insert, PourIntoMeshNeverOverlapsParticlesOrWalls)
{
  Lmp l;
  const std::string stl = container_file();
  l.cmds(pour_scene(stl));
  l.cmd("compute cc all contact/polyhedron");
  l.cmd("thermo_style custom step atoms c_cc[1] f_w[7]");
  long tag0 = 0;
  int bad = 0, outside = 0;
  for (int e = 0; e < 10; e++) {
    l.cmd(e == 0 ? "run 0" : "run 100");
    bad += overlaps(l, tag0);
    outside += outside_container(l, tag0);
    tag0 = (long) l.lmp->atom->natoms;
  }
  // a crowded feed carries some particles to later insertions
  EXPECT_GE(l.lmp->atom->natoms, 320);
  EXPECT_EQ(fvec(l, "ins", 0), (double) l.lmp->atom->natoms);
  EXPECT_EQ(bad, 0);
  EXPECT_EQ(outside, 0);
}

// Acceptance 1 with a mesh at full count: 5,000 polyhedra inserted at a
// rate into the whole STL container (contacts and walls on), each apart from
// every particle and every vertex inside the walls at the step it appears
TEST(Insert, DenseRateFillOfAMeshContainer)
{
  Lmp l;
  const std::string stl = container_file();
  l.cmds(container_box());
  l.cmds({"region feed block -0.0205 0.0205 -0.0205 0.0205 -0.0005 0.06",
          "fix ins all insert/polyhedron 5000 31 region feed per 1250 every 100 density 2500 "
          "shape d 0.4 scale uniform 0.0006 0.0009 shape c 0.3 scale 0.3 shape q 0.3 scale 0.0014",
          "pair_style polyhedron", "pair_coeff * * 1.0e7 0.3 0.5 0.5", "neighbor 0.0005 bin",
          "fix nve all nve/polyhedron", "fix g all gravity 9.81 vector 0 0 -1",
          "fix w all wall/mesh " + stl, "timestep 2e-6", "compute cc all contact/polyhedron",
          "thermo_style custom step atoms c_cc[1] f_w[7]", "thermo 100"});
  long tag0 = 0;
  int bad = 0, outside = 0;
  for (int e = 0; e < 4; e++) {
    l.cmd(e == 0 ? "run 0" : "run 100");
    if (e == 0) {    // the first 1,250: no contact with each other or the mesh (contact computes)
      auto *cc = l.lmp->modify->compute[l.lmp->modify->find_compute("cc")];
      EXPECT_EQ(cc->vector[0], 0.0);    // computed for the thermo output of step 0
      EXPECT_EQ(fvec(l, "w", 6), 0.0);
    }
    bad += overlaps(l, tag0);
    outside += outside_container(l, tag0);
    tag0 = (long) l.lmp->atom->natoms;
  }
  EXPECT_EQ(l.lmp->atom->natoms, 5000);
  EXPECT_EQ(bad, 0);
  EXPECT_EQ(outside, 0);
}

// A moving region: every particle appears inside the region where it is at
// the step of its insertion (a block sliding along x, and a rotating one)
TEST(Insert, MovingRegionsAreFollowed)
{
  for (int rot = 0; rot < 2; rot++) {
    Lmp l;
    l.cmds(mixed_box());
    l.cmds({"variable dx equal 0.3*time", "variable th equal 20*time",
            rot ? "region feed block 0.02 0.04 0.025 0.035 0.01 0.05 rotate v_th 0.03 0.03 0.03 0 0 1 "
                  "units box"
                : "region feed block 0.0 0.01 0.0 0.06 0.01 0.05 move v_dx NULL NULL units box",
            "fix ins all insert/polyhedron 0 5 region feed per 20 every 100 density 1000 "
            "mass/total 1.0 shape d 1 scale 0.0008",
            "fix nve all nve/polyhedron", "timestep 1e-4"});
    auto avec = PolyShapeLibrary::of(l.lmp, "test");
    long tag0 = 0;
    int outside = 0, n = 0;
    for (int e = 0; e < 6; e++) {
      l.cmd(e == 0 ? "run 0" : "run 100");
      const double t = e * 100 * 1e-4;
      const double c = std::cos(20 * t), sn = std::sin(20 * t);    // theta in radians
      for (const auto &p : particles(l)) {
        if (p.tag <= tag0) continue;
        n++;
        for (const auto &y : surface_points(avec->shape(p.shape), p)) {
          if (rot) {    // back into the region's own frame: rotate by -theta about (0.03, 0.03)
            const double u = y.x - 0.03, v = y.y - 0.03;
            const double xr = 0.03 + c * u + sn * v, yr = 0.03 - sn * u + c * v;
            outside += !(xr > 0.02 && xr < 0.04 && yr > 0.025 && yr < 0.035);
          } else
            outside += !(y.x > 0.3 * t && y.x < 0.01 + 0.3 * t);
        }
      }
      tag0 = (long) l.lmp->atom->natoms;
    }
    EXPECT_EQ(n, 120) << "rotate " << rot;
    EXPECT_EQ(outside, 0) << "rotate " << rot;
  }
}

// Acceptance 2: exact counts per insertion (per), counts of a number rate,
// and a mass rate within 1 %.
TEST(Insert, ScheduleCountsAndMassFlow)
{
  // the atoms after each of n insertions `every` steps of 1e-5 s apart by
  // the fix command `ins` in mixed_box()
  auto counts = [](const std::string &ins, int every, int n) {
    Lmp l;
    l.cmds(mixed_box());
    l.cmds({ins, "fix nve all nve/polyhedron", "timestep 1e-5"});
    std::vector<long long> c;
    for (int k = 0; k < n; k++) {
      l.cmd(k == 0 ? "run 0" : "run " + std::to_string(every));
      c.push_back((long long) l.lmp->atom->natoms);
    }
    return c;
  };
  const auto per = counts("fix ins all insert/polyhedron 1000 5 region box per 7 every 20 "
                          "density 1000 all_in no shape d 1 scale 0.001", 20, 5);
  for (int k = 0; k < 5; k++) EXPECT_EQ(per[k], 7 * (k + 1));
  // 3.3e4 particles/s, every 30 steps of 1e-5 s: 9.9 per insertion
  const auto rate = counts("fix ins all insert/polyhedron 1000 5 region box rate 33000 every 30 "
                           "density 1000 all_in no shape d 1 scale 0.001", 30, 6);
  for (int k = 0; k < 6; k++) EXPECT_EQ(rate[k], std::llround(33000 * (k + 1) * 30 * 1e-5));
  {
    // mass rate: 0.02 kg/s of a mixture with scale distributions
    Lmp l;
    l.cmds(mixed_box());
    l.cmds({"fix ins all insert/polyhedron 0 5 region box rate/mass 0.02 every 100 density 2500 "
            "mass/total 1.0 all_in no shape d 0.5 scale uniform 0.0004 0.0006 "
            "shape q 0.5 scale normal 0.0007 0.0001 0.0005 0.0009",
            "fix nve all nve/polyhedron", "timestep 1e-4"});
    for (int k = 0; k < 20; k++) {
      l.cmd(k == 0 ? "run 0" : "run 100");
      const double want = 0.02 * (k + 1) * 100 * 1e-4;
      double m = 0.0;
      for (int i = 0; i < l.lmp->atom->nlocal; i++) m += l.lmp->atom->rmass[i];
      EXPECT_NEAR(fvec(l, "ins", 1), m, 1e-12 * m);
      if (k >= 2) EXPECT_NEAR(m / want, 1.0, 0.01) << "insertion " << k;
    }
  }
}

// Acceptance 3: number and mass fractions (chi^2, 2 d.o.f., critical 13.8
// at 1e-3), the scale distribution and a body axis (KS at 1e-3).
TEST(Insert, FractionsScalesAndOrientationsFollowTheRequest)
{
  for (int mass = 0; mass < 2; mass++) {
    Lmp l;
    pack(l, std::string("fix ins all insert/polyhedron 6000 77 region box mode pack density 2500 "
                        "all_in no fractions ") +
                (mass ? "mass" : "number") +
                " shape d 0.5 scale uniform 0.0005 0.0007 shape q 0.3 scale 0.0008 "
                "shape c 0.2 scale 0.12 density 1000");
    ASSERT_EQ(l.lmp->atom->natoms, 6000);
    auto avec = PolyShapeLibrary::of(l.lmp, "test");
    const double f[3] = {0.5, 0.3, 0.2};
    const int idx[3] = {0, 2, 1};    // template index of d, q, c
    double p[3];
    if (!mass) {
      for (int k = 0; k < 3; k++) p[k] = f[k];
    } else {    // p_i ~ w_i / <m_i>
      const double m[3] = {2500 * avec->shape(0).volume() * (std::pow(0.0007, 4) - std::pow(0.0005, 4)) /
                               (4 * 0.0002),
                           2500 * avec->shape(2).volume() * std::pow(0.0008, 3),
                           1000 * avec->shape(1).volume() * std::pow(0.12, 3)};
      double sum = 0;
      for (int k = 0; k < 3; k++) sum += p[k] = f[k] / m[k];
      for (double &x : p) x /= sum;
    }
    double cnt[3] = {0, 0, 0}, msum[3] = {0, 0, 0};
    std::vector<double> sd, cz;
    for (auto &kv : l.local_state()) {
      for (int k = 0; k < 3; k++)
        if (kv.second.shape == idx[k]) cnt[k]++, msum[k] += kv.second.m;
      if (kv.second.shape == 0) sd.push_back(kv.second.s);
      const auto R = polydem::quat_to_mat(polydem::make_quat(kv.second.q[0], kv.second.q[1],
                                                             kv.second.q[2], kv.second.q[3]));
      cz.push_back(R.m[2][0]);    // z component of the body x axis
    }
    double chi2 = 0.0;
    for (int k = 0; k < 3; k++) chi2 += std::pow(cnt[k] - 6000 * p[k], 2) / (6000 * p[k]);
    EXPECT_LT(chi2, 13.8) << (mass ? "mass" : "number") << " fractions";
    if (mass) {
      const double mt = msum[0] + msum[1] + msum[2];
      for (int k = 0; k < 3; k++) EXPECT_NEAR(msum[k] / mt, f[k], 0.05) << k;
    }
    const double crit = 1.9495;
    EXPECT_LT(ks(sd, [](double s) { return (s - 0.0005) / 0.0002; }) * std::sqrt(sd.size()), crit);
    EXPECT_LT(ks(cz, [](double c) { return 0.5 * (c + 1.0); }) * std::sqrt(cz.size()), crit);
  }
}

// orient fixed: every particle as written in its file, turned by theta about
// the axis; orient axis: turned by a random angle about it, so the file's z
// axis (the pellet's axis) stays along the lab axis and the angle is uniform
TEST(Insert, FixedAndAxisOrientations)
{
  for (int axis = 0; axis < 2; axis++) {
    Lmp l;
    pack(l, std::string("fix ins all insert/polyhedron 400 3 region box mode pack density 1000 "
                        "all_in no shape c 1 scale 0.5 orient ") +
                (axis ? "axis 1 0 0" : "fixed 1 0 0 30"));
    auto avec = PolyShapeLibrary::of(l.lmp, "test");
    const auto q0 = avec->shape(1).input_orientation();    // file frame -> principal frame
    std::vector<double> ang;
    for (const auto &p : particles(l)) {
      // rotation taking the file's frame to the lab: q q0^-1
      const auto r = polydem::qmul(p.q, polydem::qconj(q0));
      const auto R = polydem::quat_to_mat(r);
      if (!axis) {
        const double c = std::cos(M_PI / 12), sn = std::sin(M_PI / 12);    // half of 30 deg
        ASSERT_NEAR(std::fabs(r.w), c, 1e-12);
        ASSERT_NEAR(std::fabs(r.x), sn, 1e-12);
      } else {
        ASSERT_NEAR(R.m[0][0], 1.0, 1e-12);    // the lab x axis is kept
        ang.push_back(std::atan2(R.m[2][1], R.m[1][1]));
      }
    }
    if (axis) {
      EXPECT_EQ(ang.size(), 400u);
      EXPECT_LT(ks(ang, [](double a) { return (a + M_PI) / (2 * M_PI); }), ks_crit(ang.size()));
    }
  }
}

// Acceptance 4: random sequential addition of dodecahedra to a solid
// fraction of 0.35 in a periodic box (2,924 particles).
TEST(Insert, PackReachesSolidFraction035)
{
  Lmp l;
  l.cmds({"units si", "atom_style polyhedron", "atom_modify map array", "boundary p p p",
          "region box block 0 0.2 0 0.2 0 0.2", "create_box 1 box",
          "polyhedron_shape d " + potentials() + "/dodecahedron.shape",
          "fix ins all insert/polyhedron 0 4711 region box mode pack shape d 1.0 scale 0.005 "
          "density 2500 fraction 0.35 attempts 10000 misses 100 all_in no",
          "run 0"});
  const double phi = l.lmp->atom->natoms * 7.6631189606246319 * std::pow(0.005, 3) / 0.008;
  EXPECT_GE(phi, 0.35);
  EXPECT_NEAR(fvec(l, "ins", 3), phi, 1e-9);
  EXPECT_EQ(overlaps(l, 0), 0);
}

// Acceptance 5 (restart): a pour stopped and continued from a restart file
// (insertion count, generator state and schedule) ends bit-identical to the
// uninterrupted continuation.
TEST(Insert, RestartContinuesBitIdentical)
{
  const std::string stl = container_file();
  const std::string rfile = wall_test::tmpdir() + "/insert.restart";
  std::vector<double> straight, continued;
  {
    Lmp l;
    l.cmds(pour_scene(stl));
    l.cmds({"run 350", "write_restart " + rfile, "run 450"});
    straight = gather_state(l, MPI_COMM_WORLD);
  }
  {
    Lmp l;
    l.cmd("read_restart " + rfile);
    // the scene's commands after the box and the shapes (which the restart keeps)
    for (const auto &c : pour_scene(stl)) {
      const bool setup = c.rfind("units", 0) == 0 || c.rfind("atom_", 0) == 0 ||
                         c.rfind("boundary", 0) == 0 || c.rfind("region box", 0) == 0 ||
                         c.rfind("create_box", 0) == 0 || c.rfind("polyhedron_shape", 0) == 0;
      if (!setup) l.cmd(c);
    }
    l.cmd("run 450");
    continued = gather_state(l, MPI_COMM_WORLD);
  }
  ASSERT_EQ(straight.size(), continued.size());
  EXPECT_GT(straight.size() / 13, 300u);
  for (size_t i = 0; i < straight.size(); i++) ASSERT_EQ(straight[i], continued[i]) << i;
}

// Acceptance 6: bad input gets a clear error naming the keyword.
TEST(Insert, BadInputIsRefusedClearly)
{
  const auto box = mixed_box();
  const std::string f = "fix ins all insert/polyhedron ";
  // the command in a new instance of the scene `box`
  auto refused = [&](const std::string &cmd, const std::string &what) {
    Lmp l;
    l.cmds(box);
    l.expect_error(cmd, what);
  };
  refused(f + "10 1 density 1 shape d 1 scale 0.001 per 1", "'region' is required");
  refused(f + "10 1 density 1 region box shape x 1 scale 0.001 per 1", "shape 'x' is not defined");
  refused(f + "10 1 density 1 region box shape d 0.5 scale 0.001 shape q 0.3 scale 0.001 per 1",
          "sum to 0.8");
  refused(f + "10 1 density 1 region box shape d 1 scale -0.001 per 1", "scale values must be finite and > 0");
  refused(f + "10 1 density 1 region box shape d 1 scale normal 1 0.01 2 3 per 1", "probability");
  refused(f + "10 1 region box shape d 1 scale 0.001 shape q 0 scale 0.001 density 1 per 1",
          "shape 'd' has no density");
  refused(f + "10 1 density 1 region box shape d 1 scale 0.001 density 1", "needs one of the keywords rate");
  refused(f + "0 1 density 1 region box shape d 1 scale 0.001 per 1", "needs a limit");
  refused(f + "10 1 density 1 region box mode pack fraction 1.5 shape d 1 scale 0.001 density 1", "fraction must be in (0, 1)");
  refused(f + "10 1 density 1 region box shape d 1 scale 0.001 per 1 colour red", "unknown keyword 'colour'");
  refused(f + "10 0 density 1 region box shape d 1 scale 0.001 per 1", "seed must be > 0");
  // one value > 0 (gap: >= 0), named with what was given
  const std::string d1 = "10 1 region box shape d 1 scale 0.001 ";
  refused(f + d1 + "per 1 density 0", "density must be > 0, got 0");
  refused(f + d1 + "per 1 density 1 every 0", "every must be > 0, got 0");
  refused(f + d1 + "per 1 density 1 gap -1", "gap must be >= 0, got -1");
  refused(f + d1 + "rate/mass 1 mass/total 0 density 1", "mass/total must be > 0, got 0");
  refused(f + d1 + "density 1 mode pack attempts 0", "attempts must be > 0, got 0");
  refused(f + d1 + "density 1 mode pack misses -2", "misses must be > 0, got -2");
  // numbers are read in full (LAMMPS's own reader takes "1e" as 1)
  refused(f + "10 1 density 1e region box shape d 1 scale 0.001 per 1", "'1e' is not a finite number");
  refused("polyhedron_shape bad ellipsoid 1e 1 1", "'1e' is not a finite number");
  refused("polyhedron_shape bad ellipsoid 1.2.3 1 1", "'1.2.3' is not a finite number");
  // run-time checks: a missing or zero-volume region, an ellipsoid where
  // only polyhedra are allowed, a fraction the region cannot take
  {
    Lmp l;
    l.cmds(box);
    l.cmd(f + "10 1 density 1 region nowhere shape d 1 scale 0.001 per 1");
    l.expect_error("run 0", "region 'nowhere' does not exist");
  }
  {
    Lmp l;
    l.cmds(box);
    l.cmds({"region flat block 0 0.06 0 0.06 0.01 0.01",
            f + "10 1 density 1 region flat shape d 1 scale 0.001 per 1"});
    l.expect_error("run 0", "zero volume");
  }
  {
    Lmp l;
    l.cmds(box);
    l.cmds({"comm_modify vel yes", f + "10 1 density 1 region box shape e 1 scale 0.001 per 1",
            "pair_style polyhedron", "pair_coeff * * 1e7 0.3 0.5 0.5"});
    l.expect_error("run 0", "shape 'e' is an ellipsoid with unequal semi-axes");
    // with the stiffness of ellipsoid pairs they go in (issue 29)
    l.cmds({"pair_coeff * * 1e7 0.3 0.5 0.5 ellipsoid 1e3", "timestep 1e-6", "run 3"});
    EXPECT_GE(l.lmp->atom->natoms, 1);    // one per insertion event ("per 1")
  }
  {
    // and the other way round (the pair styles refuse, through ParticleSource)
    Lmp l;
    l.cmds(box);
    l.cmds({"comm_modify vel yes", f + "10 1 density 1 region box shape d 1 scale 0.001 per 1",
            "pair_style ellipsoid", "pair_coeff * * 1e4 0.5 0.5"});
    l.expect_error("run 0", "shape 'd' is a polyhedron, but pair_style ellipsoid");
  }
  {
    // a target fraction beyond reach: a warning, and what was placed stays
    Lmp l;
    l.cmds(box);
    l.cmd(f + "0 1 density 1 region box mode pack fraction 0.6 attempts 50 misses 3 all_in no "
              "shape d 1 scale 0.003 density 1");
    l.cmd("run 0");
    EXPECT_GT(l.lmp->atom->natoms, 100);
    EXPECT_LT(fvec(l, "ins", 3), 0.6);
    EXPECT_EQ(fvec(l, "ins", 0), (double) l.lmp->atom->natoms);
  }
}

// ---- issue 32 item 3: what polyhedron_set refuses, and runs that never end

// scale 1e-11 (rate) and 1e-12 (pack): the candidate grid (and the void
// cells) grew as (region / particle)^3 and the run stopped in std::bad_alloc;
// the grids are capped, and the particles are inserted
TEST(Insert, TinyScalesGetACappedGrid)
{
  for (const std::string mode : {"per 20", "mode pack"}) {
    Lmp l;
    l.cmds(mixed_box());
    const std::string scale = mode == "per 20" ? "1e-11" : "1e-12";
    l.cmds({"fix ins all insert/polyhedron 20 5 region box " + mode +
                " density 2500 all_in no shape d 1 scale " + scale,
            "fix nve all nve/polyhedron", "timestep 1e-5", "run 0"});
    EXPECT_EQ(l.lmp->atom->natoms, 20) << mode;
    EXPECT_EQ(overlaps(l, 0), 0) << mode;
  }
}

// density 1e308 or 1e-320, scale 1e-300: a mass that is infinite or zero
// (temperature inf or NaN from step 0) is refused, naming the shape
TEST(Insert, MassOutOfRangeIsRefusedNamingTheShape)
{
  const std::string f = "fix ins all insert/polyhedron 10 1 region box per 1 ";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"density 1e308 shape d 1 scale 1", "shape 'd': density 1e+308 and scale 1"},
      {"density 1e-320 shape d 1 scale 0.001", "shape 'd': density 9.99989e-321"},
      {"density 2500 shape d 1 scale 1e-300", "shape 'd': density 2500 and scale 1e-300"},
      {"density 2500 shape d 0.5 scale 0.001 shape q 0.5 scale uniform 0.001 1e100",
       "shape 'q': density 2500 and scale 1e+100"},
      {"shape d 0.5 scale 0.001 density 1 shape q 0.5 scale 0.001 density 1e300",
       "shape 'q': density 1e+300"}};
  for (const auto &c : cases) {
    Lmp l;
    l.cmds(mixed_box());
    const std::string msg = l.error_of(f + c.first);
    EXPECT_NE(msg.find(c.second), std::string::npos) << c.first << ": " << msg;
    EXPECT_NE(msg.find("outside (0, 1e250]"), std::string::npos) << msg;
  }
  // small and large masses that pass
  Lmp l;
  l.cmds(mixed_box());
  EXPECT_EQ(l.error_of(f + "density 1e-250 shape d 1 scale 0.001"), "");
  EXPECT_EQ(l.error_of("fix ins2 all insert/polyhedron 10 1 region box per 1 density 1e240 "
                       "shape d 1 scale 1"),
            "");
}

// rate 1e25 (and per 1e25) overflowed the integer target of an insertion,
// which then asked for nothing; the target is clamped to N
TEST(Insert, HugeRatesAreClampedToN)
{
  for (const std::string rate : {"rate 1e25", "per 1e25"}) {
    Lmp l;
    l.cmds(mixed_box());
    l.cmds({"fix ins all insert/polyhedron 30 5 region box " + rate +
                " every 20 density 1000 all_in no shape d 1 scale 0.001",
            "fix nve all nve/polyhedron", "timestep 1e-5", "run 0"});
    EXPECT_EQ(l.lmp->atom->natoms, 30) << rate;
    l.cmd("run 40");
    EXPECT_EQ(l.lmp->atom->natoms, 30) << rate;
  }
}

// mode pack prints the count it aims at (each limit's, and the nearest)
// before the fill, and progress lines at 1e4, 2e4, 5e4, ... particles
TEST(Insert, PackPrintsItsEstimateAndProgress)
{
  const std::string log = wall_test::tmpdir() + "/insert_progress.log";
  {
    Lmp l({"-log", log});
    l.cmds(mixed_box());
    // fraction 0.3 of the box needs 8.1e6 cubes of 0.2 mm; N stops at 12000
    l.cmds({"fix ins all insert/polyhedron 12000 7 region box mode pack fraction 0.3 "
            "density 1000 all_in no shape q 1 scale 0.0002",
            "run 0"});
    EXPECT_EQ(l.lmp->atom->natoms, 12000);
  }
  const std::string text = polydem_test::read_text(log);
  EXPECT_NE(text.find("mode pack into region 'box' aims at about 1.2e+04 particle(s) "
                      "(N 12000: 1.2e+04; fraction 0.3: 8.1e+06;"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("fix insert/polyhedron ins: packed 10000 of about 1.2e+04 particle(s)"),
            std::string::npos)
      << text;
  EXPECT_EQ(text.find("packed 20000"), std::string::npos);
}

// a fill that needs more particles than atom IDs can number (fraction 0.3
// of the box in 1 micron cubes, 6.5e13) is refused before it starts; it
// ran without end
TEST(Insert, PackBeyondTheAtomIdsIsRefused)
{
  Lmp l;
  l.cmds(mixed_box());
  l.cmd("fix ins all insert/polyhedron 0 7 region box mode pack fraction 0.3 density 1000 "
        "all_in no shape q 1 scale 1e-6");
  const std::string msg = l.error_of("run 0");
  EXPECT_NE(msg.find("fix insert/polyhedron: mode pack into region 'box' needs about 6.48e+13 "
                     "particles (fraction 0.3: 6.48e+13), more than atom IDs can number"),
            std::string::npos)
      << msg;
}

// a restart read with a changed command warns about each changed keyword
// (it continues the stored counts, schedule and generator state); the same
// command, numbers written differently, is silent
TEST(Insert, RestartWarnsAboutEachChangedKeyword)
{
  const std::string rfile = wall_test::tmpdir() + "/insert_changed.restart";
  const std::string cmd0 = "fix ins all insert/polyhedron 100 5 region box per 7 every 20 "
                           "density 1000 all_in no shape d 1 scale 0.001";
  {
    Lmp l;
    l.cmds(mixed_box());
    l.cmds(
        {cmd0, "fix nve all nve/polyhedron", "timestep 1e-5", "run 30", "write_restart " + rfile});
  }
  auto continued = [&](const std::string &cmd, const std::string &name) {
    const std::string log = wall_test::tmpdir() + "/" + name + ".log";
    {
      Lmp l({"-log", log});
      l.cmds({"read_restart " + rfile, "region box block 0 0.06 0 0.06 0 0.06", cmd,
              "fix nve all nve/polyhedron", "timestep 1e-5", "run 0"});
      EXPECT_EQ(l.lmp->atom->natoms, 14) << name;    // the stored schedule continues
    }
    return polydem_test::read_text(log);
  };
  const std::string same = continued("fix ins all insert/polyhedron 100 5 region box per 7.0 "
                                     "every 20 density 1e3 all_in no shape d 1.0 scale 1e-3",
                                     "insert_same");
  EXPECT_EQ(same.find("when the restart file was written"), std::string::npos) << same;
  const std::string changed =
      continued("fix ins all insert/polyhedron 100 6 region box per 9 every 50 density 1000 "
                "all_in no shape d 1 scale 0.002 vel constant 0 0 -1",
                "insert_changed");
  for (const std::string w :
       {"keyword 'seed' was '5' when the restart file was written, now '6'",
        "keyword 'per' was '7' when the restart file was written, now '9'",
        "keyword 'every' was '20' when the restart file was written, now '50'",
        "keyword 'shape d' was '1 scale 0.001' when the restart file was written, now '1 scale "
        "0.002'",
        "keyword 'vel' was not given when the restart file was written, now 'constant 0 0 -1'"})
    EXPECT_NE(changed.find(w), std::string::npos) << w << "\n" << changed;
  EXPECT_EQ(changed.find("keyword 'region'"), std::string::npos);
}

// mode pack toward a one-sided floor (sides front) across the middle of
// the box: no centroid below it (half of them were), while a two-sided
// floor lets particles fill both halves
TEST(Insert, PackRefusesPosesBehindAOneSidedWall)
{
  const std::string stl = wall_test::tmpdir() + "/insert_floor.stl";
  wall_test::write_ascii(stl, wall_test::flat(0, 0.06, 0, 0.06, 0.03, 2, 2));
  for (const std::string sides : {"front", "both"}) {
    Lmp l;
    l.cmds({"units si", "atom_style polyhedron", "atom_modify map array", "boundary f f f",
            "comm_modify vel yes", "region box block 0 0.06 0 0.06 0 0.06", "create_box 1 box",
            "polyhedron_shape q " + potentials() + "/cube.shape", "pair_style polyhedron",
            "pair_coeff * * 1e7 0.3 0.5 0.5", "fix w all wall/mesh " + stl + " sides " + sides,
            "fix ins all insert/polyhedron 400 3 region box mode pack density 1000 "
            "shape q 1 scale 0.003",
            "run 0"});
    int below = 0, above = 0;
    for (const auto &p : particles(l)) (p.x.z < 0.03 ? below : above)++;
    EXPECT_EQ(below + above, 400) << sides;
    if (sides == "front")
      EXPECT_EQ(below, 0);
    else
      EXPECT_GT(below, 100);
  }
}
