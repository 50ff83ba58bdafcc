// Test scenario shared by the plain and /kk restart tests of pair polyhedron:
// a cube held on a 20 degree incline by its tangential spring (loaded
// contact history), either run straight through or written to a restart file
// half-way and continued from it in a new LAMMPS instance. The cube sits at
// x = 0 on a row of 5 frozen cubes centred there, so that on 2 ranks its
// contacts have partners on both sides of the subdomain boundary.
#ifndef POLYDEM_TEST_PAIR_RESTART_CASE_H
#define POLYDEM_TEST_PAIR_RESTART_CASE_H

#include "polydem_lmp.h"

#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

namespace polydem_test {

// position and angular momentum of the cube (atom 6) at the end
struct RestartResult {
  double ref[6];    // uninterrupted run
  double got[6];    // continued from the restart file
};

// extra: LAMMPS command-line arguments (e.g. -k on -sf kk ...); host: makes
// the host arrays current (AtomKokkos::sync for /kk runs); newton: pair
// setting of the first run (the restart file keeps it); extra_read: the
// arguments of the run read from the file, if not extra (a plain run's file
// continued by /kk)
inline RestartResult pair_restart_case(const std::vector<std::string> &extra,
                                       const std::string &rfile,
                                       const std::function<void(Lmp &)> &host,
                                       const std::string &newton = "on",
                                       const std::vector<std::string> *extra_read = nullptr)
{
  auto num = [](double x) {
    char buf[32];
    std::snprintf(buf, sizeof(buf), "%.17g", x);
    return std::string(buf);
  };
  const double th = 20.0 * M_PI / 180.0;
  const std::string tilt =
      "fix g top gravity 9.81 vector " + num(std::sin(th)) + " 0 " + num(-std::cos(th));
  RestartResult r;
  auto state = [&](Lmp &l, double *out) {
    host(l);
    auto *a = l.lmp->atom;
    const int i = a->map(6);
    double mine[6] = {0, 0, 0, 0, 0, 0};    // from the rank that owns atom 6
    if (i >= 0 && i < a->nlocal)
      for (int k = 0; k < 3; k++) mine[k] = a->x[i][k], mine[3 + k] = a->angmom[i][k];
    MPI_Allreduce(mine, out, 6, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  };
  {
    Lmp l(extra);
    std::vector<std::string> c = {
        "units si", "newton " + newton, "atom_style polyhedron", "atom_modify map array",
        "boundary f f f", "comm_modify vel yes", "region box block -0.3 0.3 -0.05 0.05 -0.05 0.08",
        "create_box 2 box", "polyhedron_shape c " + potentials() + "/cuboid_2p5cm.shape"};
    for (int k = 0; k < 5; k++)
      c.push_back("create_atoms 1 single " + num(-0.05 + 0.025 * k) + " 0 0");
    for (const std::string &x : std::vector<std::string>{
             "create_atoms 2 single 0.001 0.003 0.02501", "polyhedron_set group all density 1500",
             "polyhedron_set type 2 quat 0 0 1 10", "group top type 2",
             "pair_style polyhedron core 2e-4", "pair_coeff * * 1.0e6 0.1 0.3 0.5",
             "neighbor 0.001 bin", "neigh_modify exclude type 1 1", "fix 1 top nve/polyhedron",
             "fix g top gravity 9.81 vector 0 0 -1", "timestep 1e-5", "run 3000", "unfix g",
             tilt, "run 1000", "write_restart " + rfile, "run 1000"})
      c.push_back(x);
    l.cmds(c);
    state(l, r.ref);
  }
  {
    Lmp l(extra_read ? *extra_read : extra);
    l.cmds({"read_restart " + rfile, "comm_modify vel yes", "group top type 2",
            "neighbor 0.001 bin", "neigh_modify exclude type 1 1", "fix 1 top nve/polyhedron",
            tilt, "timestep 1e-5", "run 1000"});
    state(l, r.got);
  }
  int me;
  MPI_Comm_rank(MPI_COMM_WORLD, &me);
  MPI_Barrier(MPI_COMM_WORLD);
  if (me == 0) std::remove(rfile.c_str());
  return r;
}

}    // namespace polydem_test

#endif
