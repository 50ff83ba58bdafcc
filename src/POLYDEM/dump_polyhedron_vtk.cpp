/* ----------------------------------------------------------------------
   POLYDEM - dump polyhedron/vtk
------------------------------------------------------------------------- */

#include "dump_polyhedron_vtk.h"

#include "atom.h"
#include "atom_vec_polyhedron.h"
#include "domain.h"
#include "error.h"
#include "polydem_shape_template.h"
#include "update.h"

using namespace LAMMPS_NS;

static constexpr int NREC = 11;    // id type shape scale x y z qw qx qy qz

/* ---------------------------------------------------------------------- */

DumpPolyhedronVTK::DumpPolyhedronVTK(LAMMPS *lmp, int narg, char **arg) :
    Dump(lmp, narg, arg), avec(nullptr), nexpected(0)
{
  if (narg != 5) error->all(FLERR, "Illegal dump polyhedron/vtk command: expected ID group-ID "
                            "polyhedron/vtk N file");
  if (binary || multiproc || compressed)
    error->all(FLERR, "dump polyhedron/vtk: file name must not end in .bin or .gz or contain %");
  avec = dynamic_cast<AtomVecPolyhedron *>(atom->avec);
  if (!avec) error->all(FLERR, "dump polyhedron/vtk requires atom_style polyhedron");
  size_one = NREC;
  sort_flag = 1;
  sortcol = 0;
  buffer_allow = 0;
  buffer_flag = 0;
}

void DumpPolyhedronVTK::init_style()
{
  avec = dynamic_cast<AtomVecPolyhedron *>(atom->avec);
  if (!avec) error->all(FLERR, "dump polyhedron/vtk requires atom_style polyhedron");
  if (!multifile && me == 0)
    error->warning(FLERR, "dump polyhedron/vtk: without '*' in the file name every snapshot "
                   "is appended to one file, which VTK readers show as the first only");
}

void DumpPolyhedronVTK::write_header(bigint n)
{
  nexpected = n;
  records.clear();
  if (n == 0) write_snapshot();
}

void DumpPolyhedronVTK::pack(tagint *ids)
{
  int *mask = atom->mask;
  double **x = atom->x, **quat = atom->quat;
  int m = 0, n = 0;
  for (int i = 0; i < atom->nlocal; i++)
    if (mask[i] & groupbit) {
      buf[m++] = atom->tag[i];
      buf[m++] = atom->type[i];
      buf[m++] = atom->pshape[i];
      buf[m++] = atom->pscale[i];
      for (int k = 0; k < 3; k++) buf[m++] = x[i][k];
      for (int k = 0; k < 4; k++) buf[m++] = quat[i][k];
      if (ids) ids[n++] = atom->tag[i];
    }
}

/* ----------------------------------------------------------------------
   chunks arrive rank by rank; legacy VTK needs all points before all
   polygons, so collect the snapshot and write it when complete
------------------------------------------------------------------------- */

void DumpPolyhedronVTK::write_data(int n, double *mybuf)
{
  records.insert(records.end(), mybuf, mybuf + (size_t) n * NREC);
  if ((bigint) (records.size() / NREC) >= nexpected) write_snapshot();
}

void DumpPolyhedronVTK::write_snapshot()
{
  const size_t np = records.size() / NREC;
  bigint nv = 0, nf = 0, nidx = 0;
  for (size_t p = 0; p < np; p++) {
    const auto v = avec->shape((int) records[p * NREC + 2]).view();
    nv += v.nverts;
    nf += v.nfaces;
    nidx += v.nfaces + v.face_start[v.nfaces];
  }
  fmt::print(fp, "# vtk DataFile Version 3.0\nPOLYDEM polyhedra, timestep {}\nASCII\n"
             "DATASET POLYDATA\nPOINTS {} double\n", update->ntimestep, nv);
  for (size_t p = 0; p < np; p++) {
    const double *r = &records[p * NREC];
    const auto v = avec->shape((int) r[2]).view();
    const double s = r[3];
    const auto rot = polydem::quat_to_mat(polydem::make_quat(r[7], r[8], r[9], r[10]));
    for (int k = 0; k < v.nverts; k++) {
      const auto b = polydem::make_vec3(v.verts[3 * k], v.verts[3 * k + 1], v.verts[3 * k + 2]);
      const auto l = polydem::matvec(rot, b);
      fmt::print(fp, "{:.9g} {:.9g} {:.9g}\n", r[4] + s * l.x, r[5] + s * l.y, r[6] + s * l.z);
    }
  }
  fmt::print(fp, "POLYGONS {} {}\n", nf, nidx);
  bigint offset = 0;
  for (size_t p = 0; p < np; p++) {
    const auto v = avec->shape((int) records[p * NREC + 2]).view();
    for (int f = 0; f < v.nfaces; f++) {
      fmt::print(fp, "{}", v.face_start[f + 1] - v.face_start[f]);
      for (int j = v.face_start[f]; j < v.face_start[f + 1]; j++)
        fmt::print(fp, " {}", offset + v.face_verts[j]);
      fmt::print(fp, "\n");
    }
    offset += v.nverts;
  }
  const char *names[3] = {"id", "type", "shape"};
  fmt::print(fp, "CELL_DATA {}\n", nf);
  for (int c = 0; c < 3; c++) {
    fmt::print(fp, "SCALARS {} int 1\nLOOKUP_TABLE default\n", names[c]);
    for (size_t p = 0; p < np; p++) {
      const double *r = &records[p * NREC];
      const auto v = avec->shape((int) r[2]).view();
      const bigint val = (c == 2) ? (bigint) r[2] + 1 : (bigint) r[c];
      for (int f = 0; f < v.nfaces; f++) fmt::print(fp, "{}\n", val);
    }
  }
  fflush(fp);
  records.clear();
}
