// Test helpers: a LAMMPS instance driven through its C++ interface.
#ifndef POLYDEM_TEST_LMP_H
#define POLYDEM_TEST_LMP_H

#include "atom.h"
#include "error.h"
#include "input.h"
#include "lammps.h"
#include "library.h"

#include <gtest/gtest.h>

#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace polydem_test {

inline std::string potentials() { return POLYDEM_POTENTIALS_DIR; }

// whether this LAMMPS has the KOKKOS package (the /kk styles): not in builds
// against LAMMPS 4 Feb 2025 or later here, whose KOKKOS needs Kokkos 4
inline bool has_kokkos() { return lammps_config_has_package("KOKKOS") != 0; }

// the command-line extras of a plain run and, with KOKKOS, of a /kk run
// a double as LAMMPS input text, exactly (17 significant digits)
inline std::string num(double x)
{
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.17g", x);
  return buf;
}

// the whole text of a file (a log), empty if it cannot be read
// an empty unit box (SI units, atom_style polyhedron) with ntypes atom
// types, then the commands `more`
inline std::vector<std::string> unit_box(int ntypes, const std::vector<std::string> &more = {})
{
  std::vector<std::string> c = {"units si", "atom_style polyhedron",
                                "region box block 0 1 0 1 0 1",
                                "create_box " + std::to_string(ntypes) + " box"};
  c.insert(c.end(), more.begin(), more.end());
  return c;
}

// two frictionless elastic cubes of edge a (density 2000, E), the second
// at (a - delta, dy, 0): a face-to-face overlap of a (a - dy) delta; the
// commands up to the integrator (pair_style polyhedron core `core`)
inline std::vector<std::string> cube_faces(double a, double delta, double dy, double E,
                                           const std::string &core)
{
  return {"units si", "atom_style polyhedron", "atom_modify map array", "boundary f f f",
          "comm_modify vel yes", "region box block -0.1 0.1 -0.1 0.1 -0.1 0.1",
          "create_box 1 box", "polyhedron_shape c " + potentials() + "/cube.shape",
          "create_atoms 1 single 0 0 0",
          "create_atoms 1 single " + num(a - delta) + " " + num(dy) + " 0",
          "polyhedron_set group all scale " + num(a) + " density 2000",
          "pair_style polyhedron core " + core, "pair_coeff * * " + num(E) + " 0.3 1.0 0.0",
          "neighbor 0.001 bin", "fix 1 all nve/polyhedron"};
}

inline std::string read_text(const std::string &path)
{
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// "-k on" for the /kk runs, plus "t N" when POLYDEM_KK_THREADS=N is set (the
// *_threads ctest entries run the /kk tests with N = 2 real threads), then rest
inline std::vector<std::string> kk(const std::vector<std::string> &rest)
{
  std::vector<std::string> a = {"-k", "on"};
  if (const char *t = std::getenv("POLYDEM_KK_THREADS")) {
    a.push_back("t");
    a.push_back(t);
  }
  a.insert(a.end(), rest.begin(), rest.end());
  return a;
}

// the arguments that run the /kk styles (-sf kk) with newton pair off (the
// Kokkos default on GPUs), or on
inline std::vector<std::string> kk_styles(const std::string &newton = "off")
{
  return kk({"-sf", "kk", "-pk", "kokkos", "newton", newton});
}

// no suffix, and /kk (with POLYDEM_KK_THREADS threads) where LAMMPS has KOKKOS
inline std::vector<std::vector<std::string>> plain_and_kk()
{
  if (!has_kokkos()) return {{}};
  return {{}, kk({"-sf", "kk"})};
}

// the thread count the /kk runs ask for (1 unless POLYDEM_KK_THREADS is set)
inline int kk_threads()
{
  const char *t = std::getenv("POLYDEM_KK_THREADS");
  return t ? std::atoi(t) : 1;
}

class Lmp {
 public:
  // extra: e.g. {"-k","on","-sf","kk"}
  explicit Lmp(const std::vector<std::string> &extra = {}, MPI_Comm comm = MPI_COMM_WORLD)
  {
    std::vector<std::string> args = {"lmp", "-log", "none", "-screen", "none", "-nocite"};
    args.insert(args.end(), extra.begin(), extra.end());
    std::vector<char *> argv;
    for (auto &a : args) argv.push_back(const_cast<char *>(a.c_str()));
    lmp = new LAMMPS_NS::LAMMPS((int) argv.size(), argv.data(), comm);
  }
  ~Lmp() { delete lmp; }
  Lmp(const Lmp &) = delete;
  Lmp &operator=(const Lmp &) = delete;

  void cmd(const std::string &line) { lmp->input->one(line); }
  void cmds(const std::vector<std::string> &lines)
  {
    for (auto &l : lines) cmd(l);
  }
  // run a command that must fail; returns the error message
  std::string error_of(const std::string &line)
  {
    try {
      lmp->input->one(line);
    } catch (LAMMPS_NS::LAMMPSAbortException &e) {
      return e.what();
    } catch (LAMMPS_NS::LAMMPSException &e) {
      return e.what();
    }
    return "";
  }
  // run a command that must fail with an error message naming `what`
  void expect_error(const std::string &line, const std::string &what)
  {
    const std::string e = error_of(line);
    EXPECT_NE(e.find(what), std::string::npos) << line << " -> " << e;
  }
  // thermo keyword, or "c_ID" for a compute's global scalar
  double thermo(const std::string &keyword)
  {
    if (keyword.compare(0, 2, "c_") == 0) {
      auto *p = (double *) lammps_extract_compute(lmp, keyword.substr(2).c_str(),
                                                  LMP_STYLE_GLOBAL, LMP_TYPE_SCALAR);
      return p ? *p : std::nan("");
    }
    return lammps_get_thermo(lmp, keyword.c_str());
  }

  // per-atom state of local atoms, keyed by atom ID
  struct State {
    double x[3], v[3], q[4], L[3], w[3], m, r, s;
    int shape;
  };
  std::map<long, State> local_state()
  {
    std::map<long, State> out;
    auto *a = lmp->atom;
    for (int i = 0; i < a->nlocal; i++) {
      State s;
      for (int k = 0; k < 3; k++) {
        s.x[k] = a->x[i][k];
        s.v[k] = a->v[i][k];
        s.L[k] = a->angmom[i][k];
        s.w[k] = a->omega[i][k];
      }
      for (int k = 0; k < 4; k++) s.q[k] = a->quat[i][k];
      s.m = a->rmass[i];
      s.r = a->radius[i];
      s.s = a->pscale[i];
      s.shape = a->pshape[i];
      out[(long) a->tag[i]] = s;
    }
    return out;
  }

  LAMMPS_NS::LAMMPS *lmp;
};

// A simple-cubic lattice (spacing 1, LJ units) of nx x ny x nz sites, half
// cubes (edge 0.95: in-radius 0.475, circumradius 0.82), half dodecahedra
// (edge 0.43: 0.48 / 0.60), jittered and randomly oriented: the commands from
// the lattice to the shapes, inserted into `before` ... `after`.
inline std::vector<std::string> cube_dode_lattice(std::vector<std::string> before, int nx,
                                                  int ny, int nz,
                                                  const std::vector<std::string> &after)
{
  const std::vector<std::string> lattice = {
      "lattice sc 1.0",
      "region box block 0 " + std::to_string(nx) + " 0 " + std::to_string(ny) + " 0 " +
          std::to_string(nz),
      "create_box 2 box",
      "polyhedron_shape cube " + potentials() + "/cube.shape",
      "polyhedron_shape dode " + potentials() + "/dodecahedron.shape",
      "create_atoms 1 box",
      "set type 1 type/fraction 2 0.5 8123",
      "displace_atoms all random 0.04 0.04 0.04 4242 units box",
      "polyhedron_set type 1 shape cube scale 0.95 density 1.0 quat/random 17",
      "polyhedron_set type 2 shape dode scale 0.43 density 1.5 quat/random 18"};
  before.insert(before.end(), lattice.begin(), lattice.end());
  before.insert(before.end(), after.begin(), after.end());
  return before;
}

}    // namespace polydem_test

#endif
