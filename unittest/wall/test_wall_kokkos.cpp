// fix wall/mesh/kk (Kokkos) against plain fix wall/mesh (acceptance
// 6): dodecahedra in a closed box mesh, translating or rotating (45 rpm),
// with friction and damping, 500 steps: per-atom forces and torques to 1e-12
// of the largest, positions and velocities to 1e-12, the mesh's global
// vector and energy to 1e-12 relative.
#include "wall_kk_compare.h"

#include <fstream>

using polydem_test::Lmp;
using namespace wall_test;

namespace {

const std::vector<std::string> KK = polydem_test::kk_styles();

// 27 dodecahedra in a 6 cm box (wall_scene.h), 500 steps
KkScene scene()
{
  return {scene_setup(scene_data(tmpdir() + "/kk.data", 3, 0.06, 21)), "neighbor 0.002 bin", 50,
          "wall    "};
}

KkSnapshot run(const std::vector<std::string> &extra, const std::string &fixargs,
               const std::string &fix2args = "")
{
  return kk_run(scene(), extra, fixargs, fix2args);
}

void compare(const KkSnapshot &p, const KkSnapshot &k, const char *what)
{
  kk_compare(scene(), p, k, what);
}

}    // namespace

// composites (issue 29): every second grain two dodecahedra (one turned),
// each part on the walls with its own history, in the box translating
TEST(WallKokkos, CompositesKkEqualPlain)
{
  const std::string box = tmpdir() + "/kk_box.stl";
  write_binary(box, closed_box(0.06, 5));
  KkScene sc = scene();
  sc.setup.insert(sc.setup.begin() + 7,
                  {"polyhedron_shape comp composite part d -1.45 0 0 part d 1.45 0.3 0 quat 0.9 "
                   "0.3 0.2 0.1",
                   "variable odd atom id%2", "group odd variable odd",
                   "polyhedron_set group odd shape comp scale 0.002"});
  const std::string args = box + " friction 0.6 restitution 0.4 move translate 0.05 0 0";
  const KkSnapshot p = kk_run(sc, {}, args), k = kk_run(sc, KK, args);
  kk_compare(sc, p, k, "composites");
  EXPECT_GE(p.max_contacts, 1.0);
}

TEST(WallKokkos, KkEqualsPlain)
{
  const std::string box = tmpdir() + "/kk_box.stl";
  write_binary(box, closed_box(0.06, 5));
  for (const std::string move :
       {" move translate 0.05 0 0", " move rotate 0.03 0.03 0.03 1 0.3 0.2 rpm 45",
        " rolling 0.1 cohesion 50 move translate 0.05 0 0", " move servo 0 0 -1 0.2 0.05 0.01"}) {
    const std::string args = box + " friction 0.6 restitution 0.4" + move;
    const KkSnapshot p = run({}, args), k = run(KK, args);
    compare(p, k, move.c_str());
    EXPECT_GE(p.max_contacts, 1.0);    // the wall was touched during the run
  }
  // and a curved floor (4,608 facets, none coplanar, near lists on by
  // default) under the particles, inside the box
  const std::string curved = tmpdir() + "/kk_bowl.stl";
  write_binary(curved, bowl(0, 0.06, 0, 0.06, 0.0003, 0.3, 48));
  const std::string args = box + " friction 0.6 restitution 0.4";
  const std::string args2 = curved + " friction 0.5 restitution 0.5 pertriangle yes";
  const KkSnapshot p = run({}, args, args2), k = run(KK, args, args2);
  compare(p, k, "box and curved floor");
  EXPECT_FALSE(p.tri.empty());
  EXPECT_GE(p.max_contacts2, 5.0);    // the curved floor was touched
}

// Two-sided walls (issue 17): the same box and curved floor with their
// normals reversed (flip yes: every contact is met from the back, through
// the kept sides of the wall history, near lists on), and the box one-sided
// (sides front): /kk equals plain.
TEST(WallKokkos, TwoSidedKkEqualsPlain)
{
  const std::string box = tmpdir() + "/kk2_box.stl", curved = tmpdir() + "/kk2_bowl.stl";
  write_binary(box, closed_box(0.06, 5));
  write_binary(curved, bowl(0, 0.06, 0, 0.06, 0.0003, 0.3, 48));
  const std::string args = box + " friction 0.6 restitution 0.4 flip yes move translate 0.05 0 0";
  const std::string args2 = curved + " friction 0.5 restitution 0.5 pertriangle yes flip yes";
  const KkSnapshot p = run({}, args, args2), k = run(KK, args, args2);
  compare(p, k, "reversed box and curved floor");
  EXPECT_GE(p.max_contacts, 1.0);
  EXPECT_GE(p.max_contacts2, 5.0);
  const std::string front = box + " friction 0.6 sides front";
  const KkSnapshot pf = run({}, front), kf = run(KK, front);
  compare(pf, kf, "box, one-sided");
}

// The warnings' counts and maxima reduced over /kk threads: the initial
// overlap of a 6 mm cube created 0.5 mm into a floor (issue 17 item 2), and
// the overlap/warn and depth/warn counts of its run, as the plain fix.
TEST(WallKokkos, WarningsAsPlain)
{
  const std::string stl = tmpdir() + "/kk_floor.stl";
  write_ascii(stl, flat(-0.05, 0.05, -0.05, 0.05, 0.0, 2, 2));
  auto warnings = [&](const std::vector<std::string> &extra, const std::string &name) {
    const std::string log = tmpdir() + "/" + name + ".log";
    {
      std::vector<std::string> args = {"-log", log};
      args.insert(args.end(), extra.begin(), extra.end());
      Lmp l(args);
      l.cmds({"units si", "atom_style polyhedron", "atom_modify map array", "boundary f f f",
              "comm_modify vel yes", "newton off",
              "region box block -0.05 0.05 -0.05 0.05 -0.05 0.05", "create_box 1 box",
              "polyhedron_shape c " + polydem_test::potentials() + "/cuboid_2p5cm.shape",
              "create_atoms 1 single 0 0 0.0025", "create_atoms 1 single 0.02 0 0.0026",
              "polyhedron_set group all scale 0.24 density 1500", "pair_style polyhedron",
              "pair_coeff * * 1e6 0.1 0.5 0.5", "fix nve all nve/polyhedron",
              "fix w all wall/mesh " + stl + " depth/warn 0.05", "timestep 2e-6", "run 200"});
    }
    std::ifstream in(log);
    std::string line, out;
    while (std::getline(in, line))
      if (line.find("WARNING: fix wall/mesh w:") != std::string::npos &&
          line.find("timestep") == std::string::npos)
        out += line.substr(0, line.find(" (src/")) + "\n";
    return out;
  };
  const std::string p = warnings({}, "warn_plain"), k = warnings(KK, "warn_kk");
  std::printf("%s", p.c_str());
  EXPECT_NE(p.find("2 contact(s) overlap the mesh at the start of the run"), std::string::npos);
  EXPECT_NE(p.find("depth/warn"), std::string::npos);
  EXPECT_NE(p.find("overlap/warn"), std::string::npos);
  EXPECT_EQ(p, k);
}

// The near lists are sized by each particle's own parts (polydem::
// near_lists_of): with a template of three disjoint parts defined and every
// second grain of the 18 using it, the wall keeps 9 x 3 + 9 = 36 lists (one
// for each convex grain, not three), and 9 when it acts on the convex grains
// only; plain and /kk alike.
TEST(WallKokkos, NearListsOnePerPart)
{
  const std::string box = tmpdir() + "/kk_box.stl";
  write_binary(box, closed_box(0.06, 5));
  std::vector<std::vector<std::string>> variants = {{}};
  if (polydem_test::has_kokkos()) variants.push_back(KK);
  for (const auto &extra : variants)
    for (const std::string group : {"all", "even"}) {
      KkScene sc = scene();
      sc.setup.insert(sc.setup.begin() + 7,
                      {"polyhedron_shape tri composite part d -3 0 0 part d 3 0 0 part d 0 3 0",
                       "variable odd atom id%2", "group odd variable odd",
                       "group even subtract all odd",
                       "polyhedron_set group odd shape tri scale 0.001"});
      Lmp l(extra);
      l.cmds(sc.setup);
      l.cmds({"fix w " + group + " wall/mesh " + box, "run 0"});
      ASSERT_EQ(l.lmp->atom->natoms, 18);
      auto *fix = l.lmp->modify->fix[l.lmp->modify->find_fix("w")];
      int dim;
      const auto *held = (const LAMMPS_NS::bigint *) fix->extract("near_lists", dim);
      ASSERT_NE(held, nullptr);
      const LAMMPS_NS::bigint want = group == "all" ? 36 : 9;
      EXPECT_EQ(*held, want) << fix->style << " on " << group;
      l.cmd("run 20");    // the lists in use: rebuilt at each reneighboring, same count
      EXPECT_EQ(*held, want) << fix->style << " on " << group;
    }
}
