// fix insert/polyhedron on several ranks (mpirun -np 2 or 4) and with /kk:
// the inserted particles (IDs, shapes, scales, positions, orientations,
// velocities) are bit-identical to a one-rank plain run (acceptance 5).

#include "insert_scene.h"

#include <gtest/gtest.h>

using namespace insert_test;

namespace {

// a pack into a bed, then a stream falling through it (no contacts, so
// every particle's motion is its own, whatever the ranks; contact forces
// would be summed in another order on other ranks)
// composites: the stream also takes L's of three unit cubes and cube-sphere
// dumbbells (each part tested against the grains gathered from every rank)
std::vector<std::string> scene(const std::string &stl, bool composites = false)
{
  const std::string kinds =
      composites ? "shape d 0.2 scale uniform 0.0012 0.0016 shape c 0.2 scale 0.7 shape e 0.2 "
                   "scale 0.002 shape L 0.2 scale uniform 0.0008 0.001 shape db 0.2 scale 0.001"
                 : "shape d 0.4 scale uniform 0.0012 0.0016 shape c 0.3 scale 0.7 shape e 0.3 "
                   "scale 0.002";
  return {"units si", "atom_style polyhedron", "atom_modify map array", "boundary p p f",
          "comm_modify vel yes", "region box block -0.02 0.02 -0.02 0.02 -0.001 0.07",
          "create_box 2 box", "polyhedron_shape d " + potentials() + "/dodecahedron.shape",
          "polyhedron_shape c " + potentials() + "/catalyst_cylinder.shape",
          "polyhedron_shape e ellipsoid 1 0.5 0.5",
          "polyhedron_shape q " + potentials() + "/cube.shape",
          "polyhedron_shape ball ellipsoid 0.5 0.5 0.5",
          "polyhedron_shape L composite part q -0.5 0 0 part q 0.5 0 0 part q -0.5 1 0",
          "polyhedron_shape db composite part q 0 0 0 part ball 1.2 0 0",
          "region bed block INF INF INF INF 0.0 0.012",
          "fix pack all insert/polyhedron 600 17 region bed mode pack density 2000 all_in no "
          "shape d 0.5 scale uniform 0.001 0.0014 shape c 0.5 scale 0.5",
          "group stream empty",
          "region feed block -0.02 0.02 -0.02 0.02 0.03 0.05",
          "fix ins stream insert/polyhedron 300 4711 region feed per 30 every 100 density 2500 type 2 " +
              kinds + " vel uniform -0.05 0.05 -0.05 0.05 -0.5 -0.3 omega constant 0 0 3",
          "neighbor 0.001 bin", "fix nve all nve/polyhedron",
          "fix g stream gravity 9.81 vector 0 0 -1", "timestep 5e-6", "run 0", "run 1000"};
}

}    // namespace

namespace {
void same_on_one_and_many_ranks(bool composites)
{
  int me, nprocs;
  MPI_Comm_rank(MPI_COMM_WORLD, &me);
  MPI_Comm_size(MPI_COMM_WORLD, &nprocs);
  const std::string stl = container_file();
  std::vector<double> multi;
  {
    Lmp l({}, MPI_COMM_WORLD);
    l.cmds(scene(stl, composites));
    multi = gather_state(l, MPI_COMM_WORLD);
  }
  MPI_Comm self;
  MPI_Comm_split(MPI_COMM_WORLD, me, 0, &self);
  if (me == 0) {
    Lmp l({}, self);
    l.cmds(scene(stl, composites));
    const auto single = gather_state(l, self);
    ASSERT_EQ(single.size(), multi.size());
    EXPECT_GE(single.size() / 13, 600u);
    for (size_t i = 0; i < single.size(); i++) ASSERT_EQ(single[i], multi[i]) << i << " of " << nprocs;
    if (composites) {    // the stream did take composites
      int ncomp = 0;
      for (int i = 0; i < l.lmp->atom->nlocal; i++) ncomp += l.lmp->atom->pshape[i] >= 5;
      EXPECT_GT(ncomp, 20);
    }
  }
  MPI_Comm_free(&self);
}
}    // namespace

TEST(InsertRanks, SameParticlesOnOneAndManyRanks)
{
  same_on_one_and_many_ranks(false);
}

// composites (issue 29) in the stream: the same on 1, 2 and 4 ranks
TEST(InsertRanks, CompositesSameOnOneAndManyRanks)
{
  same_on_one_and_many_ranks(true);
}

#ifdef POLYDEM_TEST_KOKKOS
// /kk (Kokkos Serial): the pour without contacts equals the plain run bit
// for bit (atoms created during a Kokkos run are synced); with
// contacts and the mesh wall (pair polyhedron/kk, whose forces equal plain
// to 1e-12 relative, not bitwise; fix wall/mesh/kk), the same particles are
// inserted, at the same places to 1e-9
TEST(InsertRanks, KokkosEqualsPlain)
{
  const std::string stl = container_file();
  for (int contacts = 0; contacts < 2; contacts++) {
    std::vector<double> plain, kk;
    {
      Lmp l;
      l.cmds(pour_scene(stl, contacts));
      l.cmd("run 900");
      plain = gather_state(l, MPI_COMM_WORLD);
    }
    {
      Lmp l(polydem_test::kk_styles());
      l.cmds(pour_scene(stl, contacts));
      l.cmd("run 900");
      kk = gather_state(l, MPI_COMM_WORLD);
    }
    ASSERT_EQ(plain.size(), kk.size()) << "contacts " << contacts;
    EXPECT_GE(plain.size() / 13, 300u);
    for (size_t i = 0; i < plain.size(); i++) {
      const int col = (int) (i % 13);
      if (!contacts || col < 3)    // without contacts, and tag, shape, scale: exact
        ASSERT_EQ(plain[i], kk[i]) << i << " contacts " << contacts;
      else
        ASSERT_NEAR(plain[i], kk[i], 1e-9 * (col < 6 ? 0.07 : (col < 10 ? 1.0 : 1.0)))
            << i << " column " << col;
    }
  }
}
#endif
