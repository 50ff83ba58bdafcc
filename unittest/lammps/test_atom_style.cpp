// atom_style polyhedron, polyhedron_shape, polyhedron_set, fix nve/polyhedron,
// compute erotate/polyhedron, dump polyhedron/vtk through LAMMPS (issue 2).

#include "polydem_lmp.h"

#include "poly_shape_library.h"
#include "polydem_rigid.h"
#include "polydem_shape_template.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include <sys/stat.h>
#include <unistd.h>

using polydem_test::Lmp;
using polydem_test::potentials;

namespace {

std::string tmpfile(const std::string &name)
{
  return ::testing::TempDir() + "polydem_" + name;
}

std::string read_text(const std::string &path)
{
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// a periodic box of non-interacting, randomly oriented, spinning particles
// of two shapes (cube: type 1, dodecahedron: type 2)
void gas(Lmp &l, int n = 40)
{
  l.cmds({"units lj", "atom_style polyhedron", "boundary p p p",
          "region box block 0 12 0 12 0 12", "create_box 2 box",
          "polyhedron_shape cube " + potentials() + "/cube.shape",
          "polyhedron_shape dodeca " + potentials() + "/dodecahedron.shape",
          "create_atoms 1 random " + std::to_string(n / 2) + " 4711 NULL",
          "create_atoms 2 random " + std::to_string(n - n / 2) + " 4712 NULL",
          "polyhedron_set type 1 scale 1.3 density 2.0 quat/random 99",
          "polyhedron_set type 2 shape dodeca scale 0.6 density 1.5 quat/random 98",
          "velocity all create 3.0 12345 loop geom", "polyhedron_set type 1 omega 0.3 -1.2 2.0",
          "polyhedron_set type 2 angmom 0.5 0.1 -0.7", "neighbor 0.3 bin",
          "fix 1 all nve/polyhedron", "timestep 0.005"});
}

void expect_same_state(const std::map<long, Lmp::State> &a, const std::map<long, Lmp::State> &b,
                       double rel)
{
  ASSERT_EQ(a.size(), b.size());
  for (auto &kv : a) {
    auto it = b.find(kv.first);
    ASSERT_NE(it, b.end()) << "atom " << kv.first << " missing";
    const auto &p = kv.second, &q = it->second;
    auto close = [rel](double u, double v) {
      return std::fabs(u - v) <= rel * std::fmax(1.0, std::fmax(std::fabs(u), std::fabs(v)));
    };
    for (int k = 0; k < 3; k++) {
      EXPECT_PRED2(close, p.x[k], q.x[k]) << "x of atom " << kv.first;
      EXPECT_PRED2(close, p.v[k], q.v[k]) << "v of atom " << kv.first;
      EXPECT_PRED2(close, p.L[k], q.L[k]) << "angmom of atom " << kv.first;
    }
    for (int k = 0; k < 4; k++) EXPECT_PRED2(close, p.q[k], q.q[k]) << "quat of atom " << kv.first;
    EXPECT_EQ(p.shape, q.shape);
    EXPECT_PRED2(close, p.s, q.s);
    EXPECT_PRED2(close, p.m, q.m);
  }
}

// a legacy VTK polydata file as dump polyhedron/vtk writes it: its point
// count and points, its polygon count
struct VtkFile {
  bool ok = false;
  long npoints = -1, npolys = -1;
  std::vector<std::array<double, 3>> points;
};

VtkFile read_vtk(const std::string &path)
{
  VtkFile v;
  std::ifstream in(path);
  v.ok = in.good();
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    std::string w;
    ls >> w;
    if (w == "POINTS") {
      ls >> v.npoints;
      for (long i = 0; i < v.npoints; i++) {
        std::array<double, 3> p;
        in >> p[0] >> p[1] >> p[2];
        v.points.push_back(p);
      }
    } else if (w == "POLYGONS")
      ls >> v.npolys;
  }
  return v;
}

// the file tmpfile(name) of dump d, after undump d
VtkFile undump_and_read(Lmp &l, const std::string &name)
{
  l.cmd("undump d");
  return read_vtk(tmpfile(name));
}

// one grain of the template `id` (potentials/FILE) at `at` in the region
// block `box` (xlo xhi ylo yhi zlo zhi), boundaries fixed
std::vector<std::string> one_grain(const std::string &box, const std::string &id,
                                   const std::string &file, const std::string &at)
{
  return {"units si",
          "atom_style polyhedron",
          "boundary f f f",
          "region box block " + box,
          "create_box 1 box",
          "polyhedron_shape " + id + " " + potentials() + "/" + file,
          "create_atoms 1 single " + at};
}

}    // namespace

// Free fall under fix gravity: velocity Verlet is exact for a constant force,
// so z(t) = z0 + vz0 t - g t^2 / 2 holds to round-off.
TEST(AtomStyle, FreeFallMatchesAnalytic)
{
  Lmp l;
  l.cmds(one_grain("-1 1 -1 1 -10 10", "d", "dodecahedron.shape", "0.1 0.2 5.0"));
  l.cmds({"polyhedron_set atom 1 scale 0.01 density 2500", "velocity all set 0.5 0 2.0",
          "fix 1 all nve/polyhedron", "fix 2 all gravity 9.81 vector 0 0 -1", "timestep 1e-4",
          "run 10000"});
  auto s = l.local_state().at(1);
  const double t = 1.0;
  EXPECT_NEAR(s.x[2], 5.0 + 2.0 * t - 0.5 * 9.81 * t * t, 1e-12 * 5.0);
  EXPECT_NEAR(s.x[0], 0.1 + 0.5 * t, 1e-12);
  EXPECT_NEAR(s.v[2], 2.0 - 9.81 * t, 1e-12 * 9.81);
  EXPECT_NEAR(s.m, 2500 * 7.6631189606246319 * 1e-6, 1e-12 * s.m);
}

// A torque-free asymmetric grain (three distinct moments) through LAMMPS follows the free-rotor kernel exactly,
// and conserves rotational energy (compute erotate/polyhedron).
TEST(AtomStyle, TorqueFreeGrainFollowsKernel)
{
  Lmp l;
  l.cmds(one_grain("-1 1 -1 1 -1 1", "c", "mineral18.shape", "0 0 0"));
  l.cmds({"polyhedron_set atom 1 density 2500 quat 1 2 3 40",
          "polyhedron_set atom 1 omega 0.5 30.0 0.4", "fix 1 all nve/polyhedron",
          "compute er all erotate/polyhedron", "thermo_style custom step c_er",
          "timestep 1e-4", "run 0"});
  const double e0 = l.thermo("c_er");
  auto s0 = l.local_state().at(1);
  auto avec = LAMMPS_NS::PolyShapeLibrary::of(l.lmp, "test");
  ASSERT_NE(avec, nullptr);
  double inertia[3];
  avec->inertia(0, inertia);
  EXPECT_NEAR(e0, polydem::rotational_energy(inertia, s0.L, s0.q), 1e-14 * e0);

  l.cmd("run 20000");
  auto s1 = l.local_state().at(1);
  double q[4] = {s0.q[0], s0.q[1], s0.q[2], s0.q[3]}, L[3] = {s0.L[0], s0.L[1], s0.L[2]};
  for (int i = 0; i < 20000; i++) polydem::free_rotor_step(1e-4, inertia, L, q);
  for (int k = 0; k < 4; k++) EXPECT_EQ(s1.q[k], q[k]);
  for (int k = 0; k < 3; k++) EXPECT_EQ(s1.L[k], L[k]);
  EXPECT_NEAR(l.thermo("c_er"), e0, 1e-6 * e0);
  const double qn = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
  EXPECT_NEAR(qn, 1.0, 1e-14);
}

// write_restart -> read_restart continues bit for bit, with the templates
// carried by the restart file (no polyhedron_shape after read_restart).
TEST(AtomStyle, RestartContinuesBitIdentically)
{
  const std::string rfile = tmpfile("restart.bin");
  std::map<long, Lmp::State> a, b;
  {
    Lmp l;
    gas(l);
    l.cmds({"run 300", "write_restart " + rfile, "run 300"});
    a = l.local_state();
  }
  {
    Lmp l;
    l.cmds({"read_restart " + rfile, "neighbor 0.3 bin", "fix 1 all nve/polyhedron",
            "timestep 0.005", "run 300"});
    b = l.local_state();
    auto avec = LAMMPS_NS::PolyShapeLibrary::of(l.lmp, "test");
    ASSERT_EQ(avec->ntemplates(), 2);
    EXPECT_EQ(avec->shape_id(1), "dodeca");
  }
  expect_same_state(a, b, 0.0);
  std::remove(rfile.c_str());
}

// write_data -> read_data reproduces every per-atom value (mass through the
// density column, to round-off).
TEST(AtomStyle, DataFileRoundTrip)
{
  const std::string dfile = tmpfile("data.txt");
  std::map<long, Lmp::State> a, b;
  {
    Lmp l;
    gas(l);
    l.cmds({"run 50", "write_data " + dfile});
    a = l.local_state();
  }
  {
    Lmp l;
    l.cmds({"units lj", "atom_style polyhedron", "boundary p p p",
            "polyhedron_shape cube " + potentials() + "/cube.shape",
            "polyhedron_shape dodeca " + potentials() + "/dodecahedron.shape",
            "read_data " + dfile});
    b = l.local_state();
  }
  ASSERT_EQ(a.size(), b.size());
  for (auto &kv : a) {
    const auto &p = kv.second, &q = b.at(kv.first);
    for (int k = 0; k < 3; k++) {
      EXPECT_EQ(p.x[k], q.x[k]);
      EXPECT_EQ(p.v[k], q.v[k]);
      EXPECT_EQ(p.L[k], q.L[k]);
    }
    for (int k = 0; k < 4; k++) EXPECT_EQ(p.q[k], q.q[k]);
    EXPECT_EQ(p.shape, q.shape);
    EXPECT_EQ(p.s, q.s);
    EXPECT_EQ(p.r, q.r);
    EXPECT_NEAR(p.m, q.m, 1e-14 * p.m);
  }
  std::remove(dfile.c_str());
}

// dump polyhedron/vtk: every particle's faces; its points lie at distance
// <= scale * bounding radius from its centre, with equality for some vertex.
TEST(AtomStyle, DumpVTKHasEveryPolyhedron)
{
  const std::string vfile = tmpfile("snap.*.vtk");
  Lmp l;
  gas(l, 10);
  l.cmds({"dump d all polyhedron/vtk 10 " + vfile, "dump_modify d sort id", "run 10"});
  const VtkFile vtk = undump_and_read(l, "snap.10.vtk");
  ASSERT_TRUE(vtk.ok) << "snap.10.vtk";
  const long npoints = vtk.npoints, npolys = vtk.npolys;
  const auto &pts = vtk.points;
  // 5 cubes (8 vertices, 6 faces) + 5 dodecahedra (20 vertices, 12 faces)
  EXPECT_EQ(npoints, 5 * 8 + 5 * 20);
  EXPECT_EQ(npolys, 5 * 6 + 5 * 12);
  auto st = l.local_state();
  auto avec = LAMMPS_NS::PolyShapeLibrary::of(l.lmp, "test");
  size_t off = 0;
  for (auto &kv : st) {
    const auto v = avec->shape(kv.second.shape).view();
    double rmax = 0.0;
    for (int k = 0; k < v.nverts; k++) {
      double d2 = 0.0;
      for (int c = 0; c < 3; c++) d2 += std::pow(pts[off + k][c] - kv.second.x[c], 2);
      rmax = std::fmax(rmax, std::sqrt(d2));
    }
    EXPECT_NEAR(rmax, kv.second.s * v.radius, 1e-7 * kv.second.s * v.radius);
    off += v.nverts;
  }
  std::remove(tmpfile("snap.10.vtk").c_str());
  std::remove(tmpfile("snap.0.vtk").c_str());
}

// Issue 17 item 3: a file name without '*' (snap.vtk, snap, dir/snap.vtk)
// crashed in fwrite (the file was never opened); now the file holds the
// latest snapshot, one valid dataset, on plain and kk
TEST(AtomStyle, DumpVTKSingleFileHoldsTheLatestSnapshot)
{
  const std::string dir = tmpfile("vtkdir");
  mkdir(dir.c_str(), 0755);
  for (const std::vector<std::string> &extra :
       polydem_test::plain_and_kk())
    for (const std::string &name : {tmpfile("single.vtk"), tmpfile("single"), dir + "/snap.vtk"}) {
      std::remove(name.c_str());
      {
        Lmp l(extra);
        gas(l, 10);
        l.cmds({"dump d all polyhedron/vtk 10 " + name, "run 20"});
        const std::string e = l.error_of("dump_modify d append yes");
        if (e.empty()) l.expect_error("run 0", "append yes");
      }
      const std::string text = read_text(name);
      size_t n = 0;
      for (size_t p = text.find("# vtk DataFile"); p != std::string::npos;
           p = text.find("# vtk DataFile", p + 1))
        n++;
      EXPECT_EQ(n, 1u) << name;
      EXPECT_NE(text.find("timestep 20\n"), std::string::npos) << name;
      EXPECT_NE(text.find("POINTS 140 double"), std::string::npos) << name;
      EXPECT_NE(text.find("POLYGONS 90 "), std::string::npos) << name;
      std::remove(name.c_str());
    }
  rmdir(dir.c_str());
}

// dump polyhedron/vtk draws an ellipsoid as 114 points of its surface and 128
// faces: every point, taken back to the body frame, satisfies
// (x/a)^2 + (y/b)^2 + (z/c)^2 = 1 (to the 9 digits written), rotated and scaled.
TEST(AtomStyle, DumpVTKDrawsEllipsoids)
{
  const std::string vfile = tmpfile("ell.*.vtk");
  Lmp l;
  l.cmds({"units si", "atom_style polyhedron", "atom_modify map array", "boundary p p p",
          "region box block 0 1 0 1 0 1", "create_box 1 box",
          "polyhedron_shape e ellipsoid 0.03 0.02 0.01", "create_atoms 1 single 0.3 0.4 0.5",
          "create_atoms 1 single 0.6 0.5 0.5", "polyhedron_set group all density 1000",
          "polyhedron_set atom 2 quat 1 2 3 50", "polyhedron_set atom 2 scale 1.5",
          "dump d all polyhedron/vtk 1 " + vfile, "dump_modify d sort id", "run 0"});
  const VtkFile vtk = undump_and_read(l, "ell.0.vtk");
  ASSERT_TRUE(vtk.ok) << "ell.0.vtk";
  const long npoints = vtk.npoints, npolys = vtk.npolys;
  const auto &pts = vtk.points;
  EXPECT_EQ(npoints, 2 * 114);
  EXPECT_EQ(npolys, 2 * 128);
  auto st = l.local_state();
  size_t off = 0;
  double worst = 0.0;
  for (auto &kv : st) {
    const auto &S = kv.second;
    const auto R = polydem::quat_to_mat(polydem::make_quat(S.q[0], S.q[1], S.q[2], S.q[3]));
    for (int k = 0; k < 114; k++) {
      const auto d = polydem::make_vec3(pts[off + k][0] - S.x[0], pts[off + k][1] - S.x[1],
                                        pts[off + k][2] - S.x[2]);
      const auto b = polydem::matTvec(R, d);
      const double u = std::pow(b.x / (S.s * 0.03), 2) + std::pow(b.y / (S.s * 0.02), 2) +
          std::pow(b.z / (S.s * 0.01), 2);
      worst = std::fmax(worst, std::fabs(u - 1.0));
    }
    off += 114;
  }
  EXPECT_LT(worst, 1e-6);
  std::remove(tmpfile("ell.0.vtk").c_str());
}

// Bad input gives a LAMMPS error naming the command and the bad word.
TEST(AtomStyle, BadInputErrors)
{
  {
    Lmp l;
    l.expect_error("atom_style polyhedron foo", "Illegal atom_style polyhedron");
  }
  Lmp l;
  l.cmds({"units lj", "atom_style polyhedron", "region box block 0 10 0 10 0 10",
          "create_box 1 box"});
  l.expect_error("create_atoms 1 single 1 1 1", "polyhedron_shape");
  std::string e = l.error_of("polyhedron_shape s /nonexistent/x.shape");
  EXPECT_NE(e.find("/nonexistent/x.shape"), std::string::npos) << e;
  e = l.error_of("polyhedron_shape s " + potentials() + "/cube.shape color red");
  EXPECT_NE(e.find("unknown keyword 'color'"), std::string::npos) << e;
  l.expect_error("polyhedron_shape", "polyhedron_shape");
  {
    // a malformed shape file: the error names the command, the file and the line
    const std::string bad = tmpfile("bad.shape");
    std::ofstream(bad) << "# broken\nvertices 4\n0 0 0\n1 0\n0 1 0\n0 0 1\n";
    e = l.error_of("polyhedron_shape s " + bad);
    EXPECT_NE(e.find("polyhedron_shape"), std::string::npos) << e;
    EXPECT_NE(e.find("bad.shape:4"), std::string::npos) << e;
    std::ofstream(bad) << "vertices 4\n0 0 0\n1 0 nan\n0 1 0\n0 0 1\n";
    e = l.error_of("polyhedron_shape s " + bad);
    EXPECT_NE(e.find("bad.shape:3"), std::string::npos) << e;
    std::remove(bad.c_str());
  }
  l.cmd("polyhedron_shape cube " + potentials() + "/cube.shape");
  e = l.error_of("polyhedron_shape cube " + potentials() + "/cube.shape");
  EXPECT_NE(e.find("already defined"), std::string::npos) << e;
  l.cmd("create_atoms 1 single 1 1 1");
  e = l.error_of("polyhedron_set atom 1 shape sphere");
  EXPECT_NE(e.find("unknown shape ID 'sphere'"), std::string::npos) << e;
  e = l.error_of("polyhedron_set atom 1 scale -2");
  EXPECT_NE(e.find("scale must be > 0"), std::string::npos) << e;
  e = l.error_of("polyhedron_set atom 1 density nan");
  EXPECT_FALSE(e.empty());
  e = l.error_of("polyhedron_set atom 1 wobble 3");
  EXPECT_NE(e.find("unknown keyword 'wobble'"), std::string::npos) << e;
  e = l.error_of("polyhedron_set atom 1 quat 0 0 0 30");
  EXPECT_NE(e.find("quat"), std::string::npos) << e;
  e = l.error_of("polyhedron_set molecule 1 scale 2");
  EXPECT_NE(e.find("unknown style 'molecule'"), std::string::npos) << e;
  e = l.error_of("polyhedron_set atom 1 omega 1 2");
  EXPECT_NE(e.find("needs 3 value(s)"), std::string::npos) << e;
  e = l.error_of("fix 1 all nve/polyhedron extra");
  EXPECT_NE(e.find("nve/polyhedron"), std::string::npos) << e;
  {
    Lmp a;
    a.cmds({"atom_style atomic", "region box block 0 1 0 1 0 1", "create_box 1 box"});
    e = a.error_of("fix 1 all nve/polyhedron");
    EXPECT_NE(e.find("requires atom_style polyhedron"), std::string::npos) << e;
    e = a.error_of("polyhedron_shape c " + potentials() + "/cube.shape");
    EXPECT_NE(e.find("requires atom_style polyhedron"), std::string::npos) << e;
  }
}

// read_data: an out-of-range shape index and a zero quaternion are errors.
TEST(AtomStyle, BadDataFile)
{
  auto write = [](const std::string &f, const std::string &atoms) {
    std::ofstream o(f);
    o << "test\n\n1 atoms\n1 atom types\n0 10 xlo xhi\n0 10 ylo yhi\n0 10 zlo zhi\n\nAtoms\n\n"
      << atoms << "\n";
  };
  const std::string f = tmpfile("bad.data");
  write(f, "1 1 3 1.0 1.0 5 5 5 1 0 0 0");
  {
    Lmp l;
    l.cmds({"atom_style polyhedron", "polyhedron_shape c " + potentials() + "/cube.shape"});
    const std::string e = l.error_of("read_data " + f);
    EXPECT_NE(e.find("Invalid shape index 3"), std::string::npos) << e;
  }
  write(f, "1 1 1 1.0 1.0 5 5 5 0 0 0 0");
  {
    Lmp l;
    l.cmds({"atom_style polyhedron", "polyhedron_shape c " + potentials() + "/cube.shape"});
    const std::string e = l.error_of("read_data " + f);
    EXPECT_NE(e.find("Invalid quaternion"), std::string::npos) << e;
  }
  write(f, "1 1 1 -1.0 1.0 5 5 5 1 0 0 0");
  {
    Lmp l;
    l.cmds({"atom_style polyhedron", "polyhedron_shape c " + potentials() + "/cube.shape"});
    const std::string e = l.error_of("read_data " + f);
    EXPECT_NE(e.find("Invalid scale"), std::string::npos) << e;
  }
  std::remove(f.c_str());
}

// Found by the fuzz run (fuzz.data): an overflowing number in the
// Velocities section (-2e0475784 parses as -inf) was taken as the angular
// momentum; now an error, plain and /kk. A finite one is read as given.
TEST(AtomStyle, NonFiniteVelocitiesRefused)
{
  const std::string f = tmpfile("vel.data");
  for (const std::string vel :
       {"1 0.1 -0.2 0.3 1e-7 0 -2e0475784", "1 1e999 0 0 0 0 0", "1 0.1 -0.2 0.3 1e-7 0 -2e-7"})
    for (const std::vector<std::string> &extra :
         polydem_test::plain_and_kk()) {
      {
        std::ofstream o(f);
        o << "test\n\n1 atoms\n1 atom types\n0 10 xlo xhi\n0 10 ylo yhi\n0 10 zlo zhi\n\n"
             "Atoms\n\n1 1 1 1.0 1.0 5 5 5 1 0 0 0\n\nVelocities\n\n"
          << vel << "\n";
      }
      Lmp l(extra);
      l.cmds({"atom_style polyhedron", "polyhedron_shape c " + potentials() + "/cube.shape"});
      const std::string e = l.error_of("read_data " + f);
      if (vel.find("e-7 0 -2e-7") != std::string::npos) {
        EXPECT_EQ(e, "") << e;
        EXPECT_EQ(l.lmp->atom->angmom[0][2], -2e-7);
      } else if (lammps_version(l.lmp) >= 20220324)
        // later LAMMPS's own reader stops first: its text, naming the number
        EXPECT_NE(e.find("in input script or data file is out of range"), std::string::npos)
            << vel << " -> '" << e << "'";
      else
        EXPECT_NE(e.find("in Velocities section of data file: not finite"), std::string::npos)
            << vel << " -> '" << e << "'";
    }
  std::remove(f.c_str());
}

// Issue 17 item 7: atom_style polyhedron is 3-d only (in 2-d particles left
// the plane): dimension 2 before or after the atom style is an error
TEST(AtomStyle, TwoDimensionsRefused)
{
  {
    Lmp l;
    l.cmd("dimension 2");
    const std::string e = l.error_of("atom_style polyhedron");
    EXPECT_NE(e.find("atom_style polyhedron: 3-d only, got 'dimension 2'"), std::string::npos) << e;
  }
  for (const std::vector<std::string> &extra :
       polydem_test::plain_and_kk()) {
    Lmp l(extra);
    l.cmds({"units si", "atom_style polyhedron", "dimension 2",
            "region box block -0.05 0.05 -0.05 0.05 -0.05 0.05", "create_box 1 box"});
    std::string e = l.error_of("polyhedron_shape c " + potentials() + "/cube.shape");
    EXPECT_NE(e.find("3-d only, got 'dimension 2'"), std::string::npos) << e;
    e = l.error_of("run 0");
    EXPECT_NE(e.find("3-d only, got 'dimension 2'"), std::string::npos) << e;
  }
}

// Issue 17 item 8: a mass or moment that is zero, subnormal or huge (NaN or
// inf kinetic energy later) is refused by polyhedron_set and read_data
TEST(AtomStyle, MassMustBeNormal)
{
  auto one = [](Lmp &l) {
    l.cmds(one_grain("-0.05 0.05 -0.05 0.05 -0.05 0.05", "c", "cube.shape", "0 0 0"));
  };
  for (const char *kw : {"density 1e308", "scale 1e-300", "density 1e-320", "mass 1e-320",
                         "scale 1e-100 density 1"}) {
    Lmp l;
    one(l);
    const std::string e = l.error_of(std::string("polyhedron_set atom 1 ") + kw);
    EXPECT_NE(e.find("polyhedron_set: 1 atom(s) (first: ID 1) get a mass outside (0, 1e250]"),
              std::string::npos)
        << kw << ": " << e;
  }
  {
    Lmp l;
    one(l);
    l.cmd("polyhedron_set atom 1 scale 1e-20 density 1e10");    // small but normal: fine
    EXPECT_GT(l.lmp->atom->rmass[0], 0.0);
  }
  const std::string f = tmpfile("mass.data");
  for (const char *cols : {"1 1 1 1e-320 1.0 5 5 5 1 0 0 0", "1 1 1 1.0 1e-320 5 5 5 1 0 0 0",
                           "1 1 1 1e308 1.0 5 5 5 1 0 0 0"}) {
    std::ofstream(f) << "test\n\n1 atoms\n1 atom types\n0 10 xlo xhi\n0 10 ylo yhi\n0 10 zlo zhi\n"
                        "\nAtoms\n\n"
                     << cols << "\n";
    Lmp l;
    l.cmds({"atom_style polyhedron", "polyhedron_shape c " + potentials() + "/cube.shape"});
    const std::string e = l.error_of("read_data " + f);
    // LAMMPS 4 Feb 2025's own reader refuses the subnormal first, naming it
    // (29 Sep 2021 and 4 Jul 2026 read it, and POLYDEM's check names the mass)
    const bool lammps_range = lammps_version(l.lmp) >= 20220324 &&
        e.find("Floating point number 1e-320 in input script or data file is out of range") !=
            std::string::npos;
    EXPECT_TRUE(lammps_range ||
                e.find("in Atoms section of data file: the mass") != std::string::npos)
        << cols << ": " << e;
  }
  std::remove(f.c_str());
}

// Issue 17 item 12: the documented per-atom outputs (quatw quati quatj quatk,
// shape, scale, density) through compute property/polyhedron (compute
// property/atom refuses quat* for styles other than ellipsoid and body)
TEST(AtomStyle, ComputePropertyPolyhedron)
{
  for (const std::vector<std::string> &extra :
       polydem_test::plain_and_kk()) {
    Lmp l(extra);
    gas(l, 10);
    l.cmds({"compute q all property/polyhedron quatw quati quatj quatk shape scale density",
            "compute w all property/polyhedron quatw", "run 20"});
    auto *a = l.lmp->atom;
    auto *avec = LAMMPS_NS::PolyShapeLibrary::of(l.lmp, "test");
    auto *q = (double **) lammps_extract_compute(l.lmp, "q", LMP_STYLE_ATOM, LMP_TYPE_ARRAY);
    auto *w = (double *) lammps_extract_compute(l.lmp, "w", LMP_STYLE_ATOM, LMP_TYPE_VECTOR);
    ASSERT_TRUE(q && w);
    for (int i = 0; i < a->nlocal; i++) {
      for (int k = 0; k < 4; k++) EXPECT_EQ(q[i][k], a->quat[i][k]) << "atom " << i;
      EXPECT_EQ(w[i], a->quat[i][0]);
      EXPECT_EQ(q[i][4], a->pshape[i] + 1);
      EXPECT_EQ(q[i][5], a->pscale[i]);
      EXPECT_DOUBLE_EQ(q[i][6], avec->density(i));
      EXPECT_NE(a->quat[i][0], 1.0);    // rotated (quat/random), so not a default
    }
    const std::string e = l.error_of("compute bad all property/polyhedron quatx");
    EXPECT_NE(e.find("compute property/polyhedron: unknown keyword 'quatx'"), std::string::npos)
        << e;
  }
}

// Issue 32 item 5: compute property/atom quatw quati quatj quatk give a
// polyhedron's orientation on every LAMMPS version (29 Sep 2021 stopped with
// "atom property that isn't allocated"; the build points LAMMPS's quat
// keywords at Atom::quat there, as LAMMPS itself does from 24 Mar 2022 on),
// in a group (0 outside it), next to another keyword
TEST(AtomStyle, ComputePropertyAtomGivesTheQuaternion)
{
  for (const std::vector<std::string> &extra : polydem_test::plain_and_kk()) {
    Lmp l(extra);
    gas(l, 10);
    l.cmds({"group cubes type 1", "compute q all property/atom quatw quati quatj quatk id",
            "compute w cubes property/atom quatk", "run 20"});
    auto *a = l.lmp->atom;
    auto *q = (double **) lammps_extract_compute(l.lmp, "q", LMP_STYLE_ATOM, LMP_TYPE_ARRAY);
    auto *w = (double *) lammps_extract_compute(l.lmp, "w", LMP_STYLE_ATOM, LMP_TYPE_VECTOR);
    ASSERT_TRUE(q && w);
    for (int i = 0; i < a->nlocal; i++) {
      for (int k = 0; k < 4; k++) EXPECT_EQ(q[i][k], a->quat[i][k]) << "atom " << i;
      EXPECT_EQ(q[i][4], (double) a->tag[i]);
      EXPECT_EQ(w[i], a->type[i] == 1 ? a->quat[i][3] : 0.0);
      EXPECT_NE(a->quat[i][0], 1.0);    // rotated (quat/random), so not a default
    }
  }
}

// Issue 17 item 13: fix pour and fix deposit create atoms without a
// polyhedron's data (fix pour segfaulted at its first insertion): refused,
// naming the fix to use
TEST(AtomStyle, CoreInsertionFixesRefused)
{
  for (const std::vector<std::string> &extra :
       polydem_test::plain_and_kk())
    for (const std::string &fix : {std::string("pour 10 1 4711 region ins diam one 0.005"),
                                   std::string("deposit 10 1 100 4711 region ins")}) {
      if (!extra.empty() && fix.rfind("pour", 0) == 0) continue;    // LAMMPS: no pour with kk
      Lmp l(extra);
      l.cmds({"units si", "atom_style polyhedron", "atom_modify map array", "comm_modify vel yes",
              "region box block -0.05 0.05 -0.05 0.05 -0.05 0.05", "create_box 1 box",
              "polyhedron_shape c " + potentials() + "/cube.shape",
              "region ins block -0.04 0.04 -0.04 0.04 0.0 0.04",
              "fix g all gravity 9.81 vector 0 0 -1", "fix 1 all nve/polyhedron",
              "fix p all " + fix});
      const std::string e = l.error_of("run 10");
      const std::string style = fix.substr(0, fix.find(' '));
      EXPECT_NE(e.find("fix " + style + " cannot insert atom_style polyhedron particles"),
                std::string::npos)
          << e;
      EXPECT_NE(e.find("use fix insert/polyhedron"), std::string::npos) << e;
      EXPECT_EQ(l.lmp->atom->natoms, 0);
    }
}

// LAMMPS 4 Feb 2025 and later have Atom::quat (POLYDEM's quat is then
// LAMMPS's own, cmake/PolydemLammps.cmake): set quat, displace_atoms rotate
// and fix move rotate turn a polyhedron's orientation there. LAMMPS 29 Sep
// 2021 knew no per-atom quaternion: set refuses (quat is no attribute of
// the style there), displace_atoms and fix move
// turn positions only.
TEST(AtomStyle, LammpsQuaternionCommands)
{
  const double c = std::cos(M_PI / 4), s = std::sin(M_PI / 4);
  const double turned[4] = {c, 0.0, 0.0, s}, same[4] = {1.0, 0.0, 0.0, 0.0};
  auto setup = [](Lmp &l) {
    l.cmds({"units lj", "atom_style polyhedron", "atom_modify map array",
            "region box block -6 6 -6 6 -6 6", "create_box 1 box",
            "polyhedron_shape cube " + potentials() + "/cube.shape",
            "create_atoms 1 single 3 0 0", "polyhedron_set atom 1 density 1.0 quat 1 0 0 0"});
  };
  auto expect_quat = [](Lmp &l, const double *q, double tol, const char *what) {
    for (int k = 0; k < 4; k++) EXPECT_NEAR(l.lmp->atom->quat[0][k], q[k], tol) << what << " " << k;
  };
  bool own_quat;
  {
    Lmp l;
    own_quat = lammps_version(l.lmp) >= 20220324;
    setup(l);
    if (own_quat) {
      l.cmd("set atom 1 quat 0 0 1 90");
      expect_quat(l, turned, 1e-15, "set quat");
    } else {
      const std::string e = l.error_of("set atom 1 quat 0 0 1 90");
      EXPECT_NE(e.find("Cannot set this attribute for this atom style"), std::string::npos) << e;
    }
  }
  {
    Lmp l;
    setup(l);
    l.cmd("displace_atoms all rotate 0 0 0 0 0 1 90 units box");
    EXPECT_NEAR(l.lmp->atom->x[0][0], 0.0, 1e-14);
    EXPECT_NEAR(l.lmp->atom->x[0][1], 3.0, 1e-14);
    expect_quat(l, own_quat ? turned : same, 1e-15, "displace_atoms rotate");
  }
  {
    Lmp l;
    setup(l);
    // a quarter of the period 4: 90 degrees about z
    l.cmds({"fix m all move rotate 0 0 0 0 0 1 4.0", "timestep 0.01", "run 100"});
    EXPECT_NEAR(l.lmp->atom->x[0][0], 0.0, 1e-12);
    EXPECT_NEAR(l.lmp->atom->x[0][1], 3.0, 1e-12);
    expect_quat(l, own_quat ? turned : same, 1e-12, "fix move rotate");
  }
}
