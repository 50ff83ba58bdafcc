// fix wall/mesh sides (issue 17 items 1, 2): walls act from both sides by
// default, the side being where the particle's centroid is when its contact
// begins, kept in the wall history (and restart files); sides front for
// one-sided walls; warnings for particles behind a one-sided wall, deeper
// than depth/warn, beyond overlap/warn, and for initial overlaps.
#include "polydem_lmp.h"
#include "wall_meshes.h"
#include "wall_scene.h"

#include "poly_shape_library.h"
#include "fix.h"
#include "fix_wall_mesh.h"
#include "modify.h"
#include "polydem_shape_template.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace polydem_test;
using namespace wall_test;

namespace {

LAMMPS_NS::Fix *fix_of(Lmp &l, const std::string &id)
{
  return l.lmp->modify->fix[l.lmp->modify->find_fix(id)];
}

// the preamble, a cube of edge 2.5 cm x scale
std::vector<std::string> cube_scene(double scale, const std::string &where, double density = 1500)
{
  return {"units si",
          "atom_style polyhedron",
          "atom_modify map array",
          "boundary f f f",
          "comm_modify vel yes",
          "region box block -0.05 0.05 -0.05 0.05 -0.05 0.05",
          "create_box 1 box",
          "polyhedron_shape c " + potentials() + "/cuboid_2p5cm.shape",
          "create_atoms 1 single " + where,
          "polyhedron_set group all scale " + num(scale) + " density " + num(density),
          "pair_style polyhedron",
          "pair_coeff * * 1e6 0.1 0.5 0.5",
          "timestep 1e-5"};
}

// a box [-h, h]^3 of two triangles per side, normals inward (or outward)
Tris cube_box(double h, bool outward)
{
  Tris t = closed_box(2 * h, 1);
  for (double &c : t) c -= h;
  if (outward)
    for (size_t k = 0; k < t.size(); k += 9)
      for (int d = 0; d < 3; d++) std::swap(t[k + 3 + d], t[k + 6 + d]);
  return t;
}

double max_speed(Lmp &l)
{
  double vmax = 0.0;
  for (auto &kv : l.local_state())
    vmax = std::fmax(vmax,
                     std::sqrt(kv.second.v[0] * kv.second.v[0] + kv.second.v[1] * kv.second.v[1] +
                               kv.second.v[2] * kv.second.v[2]));
  return vmax;
}

}    // namespace

// Issue 17 item 1, the user's case: a cube falling inside a 4 cm box mesh
// whose normals point out (the usual STL export) met the floor from behind
// and left at 138 m/s. Two-sided walls: the same trajectory as the box with
// inward normals, bit for bit; sides front keeps the one-sided wall, which
// now warns about the particle behind it.
TEST(WallSides, OutwardNormalBoxActsAsInward)
{
  const std::string in = tmpdir() + "/box4_in.stl", out = tmpdir() + "/box4_out.stl";
  write_ascii(in, cube_box(0.02, false));
  write_ascii(out, cube_box(0.02, true));
  struct Run {
    std::vector<double> traj;    // x, v, q every 100 steps
    double vmax = 0.0, contacts = 0.0;
    std::string log;
  };
  auto run = [&](const std::string &stl, const std::string &args, const std::string &name) {
    Run r;
    const std::string log = tmpdir() + "/" + name + ".log";
    {
      Lmp l({"-log", log});
      l.cmds(cube_scene(0.24, "0.003 -0.002 0.01"));    // a 6 mm cube
      const double q[4] = {0.9, 0.1, -0.3, 0.2}, qn = std::sqrt(0.95);
      for (int k = 0; k < 4; k++) l.lmp->atom->quat[0][k] = q[k] / qn;    // tilted
      l.cmds({"velocity all set 0.3 0.2 -0.5", "fix nve all nve/polyhedron",
              "fix g all gravity 9.81 vector 0 0 -1", "fix w all wall/mesh " + stl + " " + args,
              "thermo_modify lost ignore"});
      for (int k = 0; k < 80; k++) {
        l.cmd("run 100");
        r.contacts += fix_of(l, "w")->compute_vector(6);
        r.vmax = std::fmax(r.vmax, max_speed(l));
        for (auto &kv : l.local_state()) {
          r.traj.insert(r.traj.end(), kv.second.x, kv.second.x + 3);
          r.traj.insert(r.traj.end(), kv.second.v, kv.second.v + 3);
          r.traj.insert(r.traj.end(), kv.second.q, kv.second.q + 4);
        }
      }
    }
    r.log = read_text(log);
    return r;
  };
  const Run a = run(in, "", "box4_in"), b = run(out, "", "box4_out");
  const Run c = run(out, "sides front", "box4_front"), d = run(in, "flip yes", "box4_flip");
  std::printf("[ sides    ] 4 cm box: max speed inward %.3g, outward %.3g, outward one-sided "
              "%.3g m/s\n",
              a.vmax, b.vmax, c.vmax);
  EXPECT_GT(a.contacts, 0.0);
  ASSERT_EQ(a.traj.size(), b.traj.size());
  EXPECT_EQ(a.traj, b.traj);    // bit for bit
  EXPECT_EQ(a.traj, d.traj);    // flip yes changes nothing on a two-sided wall
  EXPECT_LT(a.vmax, 1.0);       // dropped from 1 cm at 0.6 m/s: never faster
  EXPECT_GT(c.vmax, 10.0);      // the one-sided outward box throws it out
  EXPECT_NE(c.log.find("contacts of particles whose centroid is behind the wall (sides front"),
            std::string::npos)
      << c.log;
  EXPECT_EQ(a.log.find("behind the wall"), std::string::npos);
}

// The same closed container with many grains (dodecahedra thrown into a
// box mesh of 4 x 4 cells per side, with friction, near lists on): either
// normal convention, the same trajectory.
TEST(WallSides, ContainerEitherNormalConvention)
{
  const double B = 0.06;
  const std::string data = scene_data(tmpdir() + "/sides.data", 3, B, 11);
  const std::string stl = tmpdir() + "/sides_box.stl";
  write_binary(stl, closed_box(B, 4));
  auto run = [&](const std::string &args, double &contacts) {
    Lmp l;
    l.cmds(scene_setup(data));
    l.cmds({"fix w all wall/mesh " + stl + " friction 0.6 " + args, "thermo_modify lost ignore"});
    contacts = 0.0;
    for (int k = 0; k < 10; k++) {
      l.cmd("run 100");
      contacts += fix_of(l, "w")->compute_vector(6);
    }
    std::vector<double> s;
    for (auto &kv : l.local_state()) {
      s.insert(s.end(), kv.second.x, kv.second.x + 3);
      s.insert(s.end(), kv.second.v, kv.second.v + 3);
      s.insert(s.end(), kv.second.w, kv.second.w + 3);
    }
    for (int k = 0; k < 8; k++) s.push_back(fix_of(l, "w")->compute_vector(k));
    return s;
  };
  double c_in, c_out, c_front, c_merge_in, c_merge_out;
  const auto in = run("merge no", c_in), out = run("merge no flip yes", c_out);
  const auto front = run("merge no flip yes sides front", c_front);
  const auto min = run("", c_merge_in), mout = run("flip yes", c_merge_out);
  std::printf("[ sides    ] box of 18 grains: %g wall contacts (over 10 samples)\n", c_in);
  EXPECT_GT(c_in, 10.0);
  ASSERT_EQ(in.size(), out.size());
  EXPECT_EQ(in, out);
  ASSERT_EQ(min.size(), mout.size());
  double worst = 0.0, scale = 0.0;
  for (size_t k = 0; k < min.size(); k++) {
    worst = std::fmax(worst, std::fabs(min[k] - mout[k]));
    scale = std::fmax(scale, std::fabs(min[k]));
  }
  std::printf("[ sides    ] merged box: max |inward - outward| %.3g of %.3g\n", worst, scale);
  EXPECT_LE(worst, 1e-12 * scale);
  EXPECT_NE(in, front);    // the one-sided outward box is another scene
}

namespace {

// a cube of 2.5 cm face down at height z (centroid), velocity vz, and a
// flat plate z = 0 (normal +z, 2 x 2 cells); no gravity. Returns vz after
// the contact (or after nsteps).
struct Bounce {
  double vz, vx, wz;
  std::string log;
  bool touched;
};

Bounce plate_bounce(double z, double vz, const std::string &args, const std::string &name)
{
  const std::string stl = tmpdir() + "/plate.stl";
  write_ascii(stl, flat(-0.05, 0.05, -0.05, 0.05, 0.0, 2, 2, true));
  const std::string log = tmpdir() + "/" + name + ".log";
  Bounce b;
  {
    Lmp l({"-log", log});
    l.cmds(cube_scene(1.0, "0.001 0.002 " + num(z)));
    l.cmds({"velocity all set 0.01 0 " + num(vz), "fix nve all nve/polyhedron",
            "fix w all wall/mesh " + stl + " " + args, "thermo_modify lost ignore", "run 0"});
    b.touched = false;
    for (int k = 0; k < 400; k++) {
      l.cmd("run 10 pre no post no");
      const bool c = fix_of(l, "w")->compute_vector(6) > 0.0;
      if (b.touched && !c) break;
      b.touched = b.touched || c;
    }
    l.cmd("run 0");
    b.vz = l.lmp->atom->v[0][2];
    b.vx = l.lmp->atom->v[0][0];
    b.wz = l.lmp->atom->omega[0][2];
  }
  b.log = read_text(log);
  return b;
}

}    // namespace

// A thin plate (one layer of triangles) acts from both sides: a cube thrown
// at it from above bounces up, one thrown from below bounces down, mirror
// images of each other. One-sided (sides front), the cube from below is
// pushed through, with a warning.
TEST(WallSides, ThinPlateActsFromBothSides)
{
  const double h = 0.0125 + 1e-4, V = 0.2;
  const Bounce up = plate_bounce(h, -V, "", "plate_above");
  const Bounce down = plate_bounce(-h, V, "", "plate_below");
  const Bounce front = plate_bounce(-h, V, "sides front", "plate_front");
  std::printf("[ sides    ] thin plate: v_z after %.6g (from above), %.6g (from below), %.6g "
              "(from below, sides front)\n",
              up.vz, down.vz, front.vz);
  EXPECT_TRUE(up.touched);
  EXPECT_TRUE(down.touched);
  EXPECT_GT(up.vz, 0.3 * V);    // e = 0.5: bounced
  EXPECT_LT(up.vz, 0.7 * V);
  EXPECT_NEAR(down.vz, -up.vz, 1e-9 * V);
  EXPECT_NEAR(down.vx, up.vx, 1e-9 * V);
  EXPECT_GT(front.vz, V);    // not bounced: shot through the plate
  EXPECT_NE(front.log.find("whose centroid is behind the wall"), std::string::npos) << front.log;
  EXPECT_EQ(down.log.find("behind the wall"), std::string::npos) << down.log;
}

// A heavy cube thrown through a soft plate: its side is kept after its
// centroid has crossed the plate (the wall still pushes it back up, and
// warns that it was pushed more than halfway through), and a restart keeps
// that side. A fix of another ID starts without history: each triangle is
// then met on the centroid's side, and the force flips.
TEST(WallSides, PushedBeyondCentroidKeepsSideAcrossRestart)
{
  const std::string stl = tmpdir() + "/soft_plate.stl";
  write_ascii(stl, flat(-0.05, 0.05, -0.05, 0.05, 0.0, 2, 2, true));
  const std::string rst = tmpdir() + "/sides.restart", log = tmpdir() + "/crossed.log";
  const std::string fix = " all wall/mesh " + stl + " youngs 1e4 restitution 1";
  std::vector<double> ref;    // force on the mesh f_w[3], every 20 steps after the restart
  double zr = 0.0;
  {
    Lmp l({"-log", log});
    l.cmds(cube_scene(1.0, "0.001 0.002 " + num(0.0125 + 1e-4)));
    l.cmds({"pair_coeff * * 1e4 0.1 1 0.5", "timestep 2e-6", "velocity all set 0 0 -5",
            "fix nve all nve/polyhedron", "fix w" + fix, "run 0"});
    int k = 0;
    for (; k < 2000 && l.lmp->atom->x[0][2] > -0.002; k++) l.cmd("run 10");
    zr = l.lmp->atom->x[0][2];
    ASSERT_LT(zr, 0.0);        // centroid below the plate ...
    ASSERT_GT(zr, -0.0125);    // ... and the cube still through it
    ASSERT_GT(fix_of(l, "w")->compute_vector(6), 0.0);
    EXPECT_LT(fix_of(l, "w")->compute_vector(2), 0.0);    // the cube pushed up: the mesh down
    l.cmd("write_restart " + rst);
    for (int j = 0; j < 10; j++) {
      l.cmd("run 20");
      ref.push_back(fix_of(l, "w")->compute_vector(2));
    }
  }
  const std::string text = read_text(log);
  EXPECT_NE(text.find("contacts whose particle's centroid has crossed the plane of the side it "
                      "touches"),
            std::string::npos)
      << text;
  auto restarted = [&](const std::string &id) {
    Lmp l;
    l.cmds({"read_restart " + rst, "comm_modify vel yes", "fix nve all nve/polyhedron",
            "fix " + id + fix});
    std::vector<double> f;
    for (int j = 0; j < 10; j++) {
      l.cmd("run 20");
      f.push_back(fix_of(l, id)->compute_vector(2));
    }
    return f;
  };
  const auto again = restarted("w"), lost = restarted("other");
  std::printf("[ sides    ] pushed through (centroid at z = %.3g mm): force on the mesh %.4g N, "
              "after a restart %.4g N, without history %.4g N\n",
              1e3 * zr, ref[0], again[0], lost[0]);
  EXPECT_EQ(again, ref);
  for (double f : ref) EXPECT_LT(f, 0.0);
  for (double f : lost) EXPECT_GT(f, 0.0);    // pushed on down through the plate
}

// Issue 17 item 2: a 6 mm cube created 2.5 mm above a floor mesh (0.5 mm
// into it) left at 25.7 m/s with no warning. Now the setup warns, with the
// largest overlap and the speed its elastic energy could give; overlaps
// beyond overlap/warn and contacts deeper than depth/warn are counted and
// warned during the run. A cube created apart from the floor: no warning.
TEST(WallSides, InitialOverlapWarns)
{
  const std::string stl = tmpdir() + "/floor_ov.stl";
  write_ascii(stl, flat(-0.05, 0.05, -0.05, 0.05, 0.0, 2, 2));
  auto start_log = [&](const std::string &z, const std::string &args, const std::string &name,
                     double &vafter) {
    const std::string log = tmpdir() + "/" + name + ".log";
    {
      Lmp l({"-log", log});
      l.cmds(cube_scene(0.24, "0 0 " + z));
      l.cmds({"fix nve all nve/polyhedron", "fix w all wall/mesh " + stl + " " + args,
              "timestep 2e-6", "run 500"});
      vafter = max_speed(l);
    }
    return read_text(log);
  };
  double v1, v2, v3;
  const std::string over = start_log("0.0025", "", "overlap_start", v1);
  const std::string apart = start_log("0.0031", "", "apart_start", v2);
  const std::string tight = start_log("0.0025", "overlap/warn 0.2 depth/warn 0.05", "tight", v3);
  const size_t at =
      over.find("WARNING: fix wall/mesh w: 1 contact(s) overlap the mesh at the start "
                "of the run with no contact history");
  ASSERT_NE(at, std::string::npos) << over;
  const size_t u = over.find("launch a particle at up to ", at);
  ASSERT_NE(u, std::string::npos);
  const double bound = std::atof(over.c_str() + u + 27);
  std::printf("[ sides    ] 6 mm cube 0.5 mm into the floor: %.3g m/s after 1 ms, elastic "
              "bound %.3g m/s\n",
              v1, bound);
  EXPECT_GT(v1, 1.0);
  EXPECT_LE(v1, bound);
  EXPECT_NE(over.find("largest overlap volume 0.0833 of the particle's"), std::string::npos)
      << over;
  EXPECT_NE(over.find("contacts whose overlap volume exceeds overlap/warn = 0.05"),
            std::string::npos)
      << over;
  EXPECT_EQ(over.find("deeper than depth/warn"), std::string::npos) << over;
  EXPECT_EQ(apart.find("WARNING: fix wall/mesh"), std::string::npos) << apart;
  EXPECT_EQ(tight.find("exceeds overlap/warn"), std::string::npos) << tight;
  EXPECT_NE(tight.find("contacts deeper than depth/warn = 0.05 of the particle's bounding radius"),
            std::string::npos)
      << tight;
}

TEST(WallSides, BadInput)
{
  const std::string stl = tmpdir() + "/floor_bad.stl";
  write_ascii(stl, flat(-0.05, 0.05, -0.05, 0.05, 0.0, 2, 2));
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"sides back", "fix wall/mesh: sides expects both or front, got 'back'"},
      {"sides", "keyword 'sides' needs 1 value(s)"},
      {"depth/warn 0", "fix wall/mesh: depth/warn must be in (0, 2], got '0'"},
      {"overlap/warn 1.5", "fix wall/mesh: overlap/warn must be in (0, 1], got '1.5'"},
      {"overlap/warn 1e400", "is not a finite number"},
  };
  for (const auto &c : cases) {
    Lmp l;
    l.cmds(cube_scene(1.0, "0 0 0.02"));
    const std::string msg = l.error_of("fix w all wall/mesh " + stl + " " + c.first);
    EXPECT_NE(msg.find(c.second), std::string::npos) << c.first << " -> '" << msg << "'";
  }
}

// fix insert/polyhedron asks the wall whether a candidate is clear
// (FixWallMesh::insertion_clear: apart from every triangle and no contact
// volume). With no history each triangle is met on the side of the
// candidate's centroid: a 6 mm cube 1 mm from the floor of a box with
// outward normals is clear, as with inward ones (one-sided, it is behind the
// floor and refused, also 1 cm from it); touching the floor it is refused
// from either side.
TEST(WallSides, InsertionClearFromEitherSide)
{
  const std::string in = tmpdir() + "/ins_in.stl", out = tmpdir() + "/ins_out.stl";
  write_ascii(in, cube_box(0.02, false));
  write_ascii(out, cube_box(0.02, true));
  struct Case {
    std::string stl, args;
    bool near_clear;
  };
  for (const Case &c : {Case{in, "", true}, Case{out, "", true}, Case{in, "sides front", true},
                        Case{out, "sides front", false}}) {
    Lmp l;
    l.cmds(cube_scene(0.24, "0 0 0"));
    l.cmds({"fix w all wall/mesh " + c.stl + " " + c.args, "run 0"});
    auto *w = dynamic_cast<LAMMPS_NS::FixWallMesh *>(fix_of(l, "w"));
    ASSERT_NE(w, nullptr);
    auto *avec = LAMMPS_NS::PolyShapeLibrary::of(l.lmp, "test");
    const auto sv = avec->shape(0).view();
    polydem::InsertBody<double> b;
    b.view = &sv;
    b.s = 0.24;
    b.radius = sv.radius * b.s;
    b.inradius = 0.003;
    b.ax = polydem::make_vec3(0.0, 0.0, 0.0);
    const auto q = polydem::make_quat(1.0, 0.0, 0.0, 0.0);
    b.R = polydem::quat_to_mat(q);
    auto clear_at = [&](double gap_to_floor) {
      b.x = polydem::make_vec3(0.001, -0.002, -0.02 + 0.003 + gap_to_floor);
      return w->insertion_clear(b, q, 0.0);
    };
    EXPECT_LT(0.003 + 0.001, b.radius);    // the floor is within the cube's reach
    EXPECT_EQ(clear_at(0.001), c.near_clear) << c.stl << " " << c.args;
    EXPECT_FALSE(clear_at(-0.0005)) << c.stl << " " << c.args;
    // farther off it: one-sided, the centroid is still behind the floor
    // (in its prism, issue 32 item 3) and refused at any distance
    EXPECT_EQ(clear_at(0.01), c.near_clear) << c.stl << " " << c.args;
  }
}
