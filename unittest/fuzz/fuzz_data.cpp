// Fuzz harness of the data-file columns of atom_style polyhedron (issue 17):
// read_data of an input (Atoms: id type shape scale density x y z qw qi qj
// qk; Velocities: id v angmom) with one cube template, in a fresh LAMMPS
// instance each time. An input must end in atoms whose mass, scale and
// quaternion are finite and normal, or in a LAMMPS error (an exception
// here); a crash, hang or sanitizer report is a finding. Linked with the
// bounded driver in ctest (fuzz.data); needs LAMMPS, so not in unittest/scripts/fuzz.sh.
#include "atom.h"
#include "error.h"
#include "input.h"
#include "lammps.h"

#include "fuzz_common.h"

#include <mpi.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <dirent.h>
#include <string>
#include <unistd.h>
#include <vector>

namespace {

using polydem_fuzz::check;
using polydem_fuzz::scratch;
using polydem_fuzz::write_input;

// LAMMPS 2021's read_data leaves its file open when it throws an error (in
// a normal run the error ends the process): close what refers to the
// scratch file, else the descriptors run out after some 10^4 inputs and
// the harness itself fails (fopen of the next input)
void close_leaked(const std::string &path)
{
  DIR *d = opendir("/proc/self/fd");
  if (!d) return;
  std::vector<int> fds;
  while (dirent *e = readdir(d)) {
    if (e->d_name[0] == '.') continue;
    const int fd = std::atoi(e->d_name);
    char target[4096];
    const std::string link = std::string("/proc/self/fd/") + e->d_name;
    const ssize_t n = readlink(link.c_str(), target, sizeof(target) - 1);
    if (n <= 0) continue;
    target[n] = '\0';
    if (path == target) fds.push_back(fd);
  }
  closedir(d);
  for (int fd : fds) close(fd);
}

}    // namespace

extern "C" int LLVMFuzzerInitialize(int *argc, char ***argv)
{
  int init = 0;
  MPI_Initialized(&init);
  if (!init) {
    MPI_Init(argc, argv);
    std::atexit([] {
      MPI_Finalize();
    });
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  if (size > (1u << 16)) return 0;    // bound the atoms per input
  write_input(data, size);
  const char *args[] = {"lmp", "-log", "none", "-screen", "none", "-nocite"};
  auto *lmp = new LAMMPS_NS::LAMMPS(6, const_cast<char **>(args), MPI_COMM_WORLD);
  bool ok = true;
  try {
    for (const std::string c :
         {"units si", "atom_style polyhedron", "atom_modify map array",
          // periodic boxes hang in LAMMPS 2021's own remap of a coordinate far
          // outside the box (1e15 in a 0.2 box: Domain::remap steps one period
          // at a time, any atom style; bench/RESULTS.md), before these columns
          "boundary f f f", "polyhedron_shape c " POLYDEM_POTENTIALS_DIR "/cube.shape"})
      lmp->input->one(c);
    lmp->input->one("read_data " + scratch());
  } catch (LAMMPS_NS::LAMMPSAbortException &) {
    ok = false;
  } catch (LAMMPS_NS::LAMMPSException &) {
    ok = false;
  }
  if (ok) {
    auto *a = lmp->atom;
    for (int i = 0; i < a->nlocal; i++) {
      check(std::isnormal(a->rmass[i]) && a->rmass[i] > 0, "mass finite, normal, positive");
      check(std::isnormal(a->pscale[i]) && a->pscale[i] > 0, "scale finite, normal, positive");
      double qn = 0.0;
      for (int k = 0; k < 4; k++) qn += a->quat[i][k] * a->quat[i][k];
      check(std::fabs(qn - 1.0) < 1e-9, "quaternion normalised");
      for (int k = 0; k < 3; k++)
        check(std::isfinite(a->x[i][k]) && std::isfinite(a->v[i][k]) &&
                  std::isfinite(a->angmom[i][k]),
              "positions, velocities, angular momenta finite");
    }
  }
  delete lmp;
  close_leaked(scratch());
  return 0;
}
