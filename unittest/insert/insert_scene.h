// Scenes of the fix insert/polyhedron tests, shared by the plain, /kk and
// MPI-rank tests.
#ifndef POLYDEM_TEST_INSERT_SCENE_H
#define POLYDEM_TEST_INSERT_SCENE_H

#include "polydem_allgather.h"
#include "polydem_lmp.h"
#include "wall_meshes.h"

#include <mpi.h>

#include <algorithm>
#include <string>
#include <vector>

namespace insert_test {

using polydem_test::Lmp;
using polydem_test::potentials;

// open box container [x0,x1] x [y0,y1] x [z0,z1] without a lid: floor and
// four sides, normals inward
inline wall_test::Tris container(double x0, double x1, double y0, double y1, double z0, double z1)
{
  wall_test::Tris t;
  auto quad = [&](const double *a, const double *b, const double *c, const double *d) {
    const double *q[6] = {a, b, c, a, c, d};
    for (auto p : q) t.insert(t.end(), p, p + 3);
  };
  const double A[3] = {x0, y0, z0}, B[3] = {x1, y0, z0}, C[3] = {x1, y1, z0}, D[3] = {x0, y1, z0};
  const double E[3] = {x0, y0, z1}, F[3] = {x1, y0, z1}, G[3] = {x1, y1, z1}, H[3] = {x0, y1, z1};
  quad(A, B, C, D);    // floor, normal +z
  quad(A, E, F, B);    // y = y0, normal +y
  quad(B, F, G, C);    // x = x1, normal -x
  quad(C, G, H, D);    // y = y1, normal -y
  quad(D, H, E, A);    // x = x0, normal +x
  return t;
}

inline std::string container_file()
{
  int me;
  MPI_Comm_rank(MPI_COMM_WORLD, &me);
  const std::string f = wall_test::tmpdir() + "/insert_container.stl";
  if (me == 0) wall_test::write_ascii(f, container(-0.02, 0.02, -0.02, 0.02, 0.0, 0.06));
  MPI_Barrier(MPI_COMM_WORLD);
  return f;
}

// the box around the container above and three templates: d (dodecahedron),
// c (catalyst cylinder), q (cube)
inline std::vector<std::string> container_box()
{
  return {"units si", "atom_style polyhedron", "atom_modify map array", "boundary f f f",
          "comm_modify vel yes", "region box block -0.021 0.021 -0.021 0.021 -0.001 0.07",
          "create_box 1 box", "polyhedron_shape d " + potentials() + "/dodecahedron.shape",
          "polyhedron_shape c " + potentials() + "/catalyst_cylinder.shape",
          "polyhedron_shape q " + potentials() + "/cube.shape"};
}

// Polyhedra poured at a rate into the container above, with contacts and
// the mesh wall (or, contacts false, neither)
inline std::vector<std::string> pour_scene(const std::string &stl, bool contacts = true)
{
  std::vector<std::string> c = container_box();
  c.insert(c.end(), {
      "region feed block -0.02 0.02 -0.02 0.02 0.01 0.05",
      "fix ins all insert/polyhedron 400 4711 region feed per 40 every 100 density 2500 "
      "shape d 0.4 scale uniform 0.0012 0.0016 shape c 0.3 scale 0.7 shape q 0.3 scale 0.0025 "
      "vel uniform -0.05 0.05 -0.05 0.05 -0.5 -0.3 omega constant 0 0 3"});
  if (contacts) c.insert(c.end(), {"pair_style polyhedron", "pair_coeff * * 1.0e7 0.3 0.5 0.5"});
  c.insert(c.end(), {"neighbor 0.001 bin", "neigh_modify every 1 delay 0 check yes",
                     "fix nve all nve/polyhedron", "fix g all gravity 9.81 vector 0 0 -1"});
  if (contacts) c.push_back("fix w all wall/mesh " + stl);    // needs the pair style's material
  c.insert(c.end(), {"timestep 5e-6", "thermo 100"});
  return c;
}

// (tag, shape, scale, x, q, v) of every atom on every rank, sorted by tag
inline std::vector<double> gather_state(Lmp &l, MPI_Comm comm)
{
  auto st = l.local_state();
  std::vector<double> mine;
  for (auto &kv : st) {
    mine.push_back((double) kv.first);
    mine.push_back(kv.second.shape);
    mine.push_back(kv.second.s);
    mine.insert(mine.end(), kv.second.x, kv.second.x + 3);
    mine.insert(mine.end(), kv.second.q, kv.second.q + 4);
    mine.insert(mine.end(), kv.second.v, kv.second.v + 3);
  }
  return polydem_test::allgather_by_tag(mine, 13, comm);
}

}    // namespace insert_test

#endif
