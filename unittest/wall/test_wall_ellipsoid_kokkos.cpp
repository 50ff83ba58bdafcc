// fix wall/mesh/kk (Kokkos) against plain fix wall/mesh for
// ellipsoids (issue 16): 18 ellipsoids in a closed box mesh, translating or
// rotating (45 rpm), a curved floor with per-triangle forces, friction and
// damping, rolling resistance (issue 30), 1,500 steps (30 or more wall
// contacts summed over 150 samples):
// per-atom forces and torques to 1e-12 of the largest, positions and
// velocities to 1e-12, the mesh's global vector, energy and per-triangle
// array to 1e-12 relative (measured: bit-identical on Kokkos Serial).
#include "wall_ellipsoid_scene.h"
#include "wall_kk_compare.h"

using namespace wall_test;

namespace {

const std::vector<std::string> KK = polydem_test::kk_styles();

KkScene scene()
{
  return {ellipsoid_scene_setup(ellipsoid_scene_data(tmpdir() + "/ell_kk.data", 21)),
          "neighbor 0.0006 bin", 150, "ell wall"};
}

// the closed box of the tests, written to tmpdir()/name
std::string box_file(const std::string &name)
{
  const std::string box = tmpdir() + "/" + name;
  write_binary(box, closed_box(EB, 4));
  return box;
}

// scene() under pair_style polyhedron with the pair_coeff command `coeff`
// and, where given, the template command `shape` in place of the ellipsoid's
KkScene scene_under_pair_polyhedron(const std::string &coeff, const std::string &shape = "")
{
  KkScene sc = scene();
  for (auto &c : sc.setup) {
    if (!shape.empty() && c.rfind("polyhedron_shape e", 0) == 0) c = shape;
    if (c.rfind("pair_style", 0) == 0) c = "pair_style polyhedron";
    if (c.rfind("pair_coeff", 0) == 0) c = coeff;
  }
  return sc;
}

}    // namespace

TEST(WallEllipsoidKokkos, KkEqualsPlain)
{
  const std::string box = box_file("ell_kk_box.stl");
  const std::string curved = tmpdir() + "/ell_kk_bowl.stl";
  write_binary(curved, bowl(0, EB, 0, EB, 0.0004, 0.1, 24));
  for (const std::string move :
       {" move translate 0.05 0 0", " move rotate 0.015 0.015 0.015 1 0.3 0.2 rpm 45",
        " rolling 0.2 cohesion 0.05 move translate 0.05 0 0"}) {
    const std::string args = box + " friction 0.5 restitution 0.5" + move;
    const KkScene sc = scene();
    const KkSnapshot p = kk_run(sc, {}, args), k = kk_run(sc, KK, args);
    kk_compare(sc, p, k, move.c_str());
    EXPECT_GE(p.contacts, 30.0);    // the walls were touched
  }
  // the box reversed (every contact met from its back) and a curved floor
  // inside it (pertriangle)
  const std::string args = box + " friction 0.5 flip yes";
  const std::string args2 = curved + " friction 0.4 restitution 0.7 pertriangle yes";
  const KkScene sc = scene();
  const KkSnapshot p = kk_run(sc, {}, args, args2), k = kk_run(sc, KK, args, args2);
  kk_compare(sc, p, k, "reversed box and curved floor");
  EXPECT_GE(p.contacts, 30.0);
}

// spheres under pair_style polyhedron (issue 29): the wall's volume law for
// spheres (sphere_cap_contacts) alike in the plain and /kk fixes, also with
// liquid bridges on the walls (issue 30)
TEST(WallEllipsoidKokkos, SpheresByVolumeKkEqualsPlain)
{
  const std::string box = box_file("sph_kk_box.stl");
  const KkScene sc = scene_under_pair_polyhedron("pair_coeff * * 1e6 0.3 0.6 0.3",
                                                 "polyhedron_shape e ellipsoid 0.7 0.7 0.7");
  // with liquid bridges on the walls (V_b 5e-12: s_c 0.19 mm, F(0) 4.6x a sphere's weight),
  // then with their viscous part (water, s_min 1 um)
  for (const std::string kw :
       {"", " bridge 5e-12 0.072 10", " bridge 5e-12 0.072 10 viscous 1e-3 1e-6"}) {
    const std::string args = box + " friction 0.5 restitution 0.5 move translate 0.05 0 0" + kw;
    const KkSnapshot p = kk_run(sc, {}, args), k = kk_run(sc, KK, args);
    kk_compare(sc, p, k, ("spheres by volume" + kw).c_str());
    EXPECT_GE(p.contacts, 30.0);
  }
}

// ellipsoids of unequal semi-axes under pair_style polyhedron (issue 29):
// their pairs by the algebraic contact, the wall by the linear law, both
// with pair_coeff's 'ellipsoid k_n', alike in the plain and /kk styles
TEST(WallEllipsoidKokkos, UnequalAxesUnderPairPolyhedronKkEqualsPlain)
{
  const std::string box = box_file("ellp_kk_box.stl");
  const KkScene sc = scene_under_pair_polyhedron("pair_coeff * * 1e6 0.3 0.6 0.3 ellipsoid 5e4");
  const std::string args = box + " friction 0.5 restitution 0.5 move translate 0.05 0 0";
  const KkSnapshot p = kk_run(sc, {}, args), k = kk_run(sc, KK, args);
  kk_compare(sc, p, k, "ellipsoids under pair polyhedron");
  EXPECT_GE(p.contacts, 30.0);
}
