// fix wall/mesh (issue 32 item 4): a mesh that moves farther in one step
// than a particle is thick passes through it with no contact; the fix warns
// when its largest displacement per step exceeds 0.1 of the smallest
// particle's inscribed radius, and stays silent below that.
#include "polydem_lmp.h"
#include "wall_meshes.h"

#include <gtest/gtest.h>

#include <string>

using namespace polydem_test;
using namespace wall_test;

namespace {

const char *WARNING = "the mesh moves up to";

// a 6 mm cube (the 2.5 cm cuboid at scale 0.24) at rest at the origin, a
// plate 2 cm above it moving as 'move' says; the log of 3 steps of dt
std::string plate_log(const std::string &move, double dt, const std::string &name)
{
  const std::string stl = tmpdir() + "/jump_plate.stl";
  write_ascii(stl, flat(-0.05, 0.05, -0.05, 0.05, 0.02, 2, 2, true));
  const std::string log = tmpdir() + "/" + name + ".log";
  {
    Lmp l({"-log", log});
    l.cmds({"units si", "atom_style polyhedron", "atom_modify map array", "boundary f f f",
            "comm_modify vel yes", "region box block -0.05 0.05 -0.05 0.05 -0.05 0.05",
            "create_box 1 box", "polyhedron_shape c " + potentials() + "/cuboid_2p5cm.shape",
            "create_atoms 1 single 0 0 0", "polyhedron_set group all scale 0.24 density 1500",
            "pair_style polyhedron", "pair_coeff * * 1e6 0.1 0.5 0.5",
            "fix nve all nve/polyhedron", "fix w all wall/mesh " + stl + " " + move,
            "thermo_modify lost ignore", "timestep " + num(dt), "run 3"});
  }
  return read_text(log);
}

}    // namespace

// 20,000 m/s at dt 1e-6: 2 cm per step, through a 6 mm cube
TEST(WallJump, TranslatingMeshFasterThanAParticleWarns)
{
  const std::string text = plate_log("move translate 0 0 -20000", 1e-6, "jump_translate");
  ASSERT_NE(text.find(WARNING), std::string::npos) << text;
  EXPECT_NE(text.find("fix wall/mesh w: the mesh moves up to 0.02 per step"), std::string::npos);
  EXPECT_NE(text.find("inscribed radius 0.003"), std::string::npos);
}

// 1e7 rpm about the y axis: the plate's far corner (0.057 from the axis)
// moves 6 cm per step of 1e-6
TEST(WallJump, RotatingMeshFasterThanAParticleWarns)
{
  const std::string text = plate_log("move rotate 0 0 0 0 1 0 rpm 1e7", 1e-6, "jump_rotate");
  EXPECT_NE(text.find(WARNING), std::string::npos) << text;
}

// 1 m/s at dt 1e-6 (1 micron per step), and a static plate: no warning
TEST(WallJump, SlowOrStaticMeshIsSilent)
{
  EXPECT_EQ(plate_log("move translate 0 0 -1", 1e-6, "jump_slow").find(WARNING), std::string::npos);
  EXPECT_EQ(plate_log("", 1e-6, "jump_static").find(WARNING), std::string::npos);
  // and the threshold: 0.1 x 3 mm = 0.3 mm per step; 0.4 mm warns, 0.2 mm does not
  EXPECT_NE(plate_log("move translate 0 0 -400", 1e-6, "jump_04").find(WARNING), std::string::npos);
  EXPECT_EQ(plate_log("move translate 0 0 -200", 1e-6, "jump_02").find(WARNING), std::string::npos);
}
