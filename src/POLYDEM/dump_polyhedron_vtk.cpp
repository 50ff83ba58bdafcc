/* ----------------------------------------------------------------------
   POLYDEM - dump polyhedron/vtk
------------------------------------------------------------------------- */

#include "dump_polyhedron_vtk.h"

#include "atom.h"
#include "domain.h"
#include "error.h"
#include "poly_shape_library.h"
#include "polydem_shape_template.h"
#include "update.h"

#include <cmath>
#include <cstdio>
#include <unistd.h>

using namespace LAMMPS_NS;

static constexpr int NREC = 11;    // id type shape scale x y z qw qx qy qz

/* ---------------------------------------------------------------------- */

DumpPolyhedronVTK::DumpPolyhedronVTK(LAMMPS *lmp, int narg, char **arg) :
    Dump(lmp, narg, arg), avec(nullptr), nexpected(0), meshes_version(-1)
{
  if (narg != 5)
    error->all(FLERR,
               "Illegal dump polyhedron/vtk command: expected ID group-ID "
               "polyhedron/vtk N file");
  if (binary || multiproc || compressed)
    error->all(FLERR, "dump polyhedron/vtk: file name must not end in .bin or .gz or contain %");
  avec = PolyShapeLibrary::of(lmp, "dump polyhedron/vtk");
  size_one = NREC;
  sort_flag = 1;
  sortcol = 0;
  buffer_allow = 0;
  buffer_flag = 0;
}

void DumpPolyhedronVTK::init_style()
{
  avec = PolyShapeLibrary::of(lmp, "dump polyhedron/vtk");
  // without '*' one file holds the latest snapshot, rewritten each time
  // (several datasets in one legacy VTK file are read as the first only)
  if (!multifile) {
    if (append_flag)
      error->all(FLERR,
                 "dump polyhedron/vtk: dump_modify append yes would put several VTK "
                 "datasets in one file; use '*' in the file name for one file per snapshot");
    openfile();
  }
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

/* ----------------------------------------------------------------------
   drawing mesh of a template: a polyhedron's vertices and faces; an
   ellipsoid (a, b, c) as NLAT x NLON points of its surface
   (a sin(t) cos(p), b sin(t) sin(p), c cos(t)): triangle fans at the poles,
   quadrilaterals between the rings (every point lies on the surface)
------------------------------------------------------------------------- */

// the faces of a convex template (an ellipsoid: a UV sphere of 128 faces),
// body frame, unit scale
static void draw_convex(const polydem::PolyShapeTemplate &t, DumpPolyhedronVTK::DrawMesh &m)
{
  if (t.is_ellipsoid()) {
    constexpr int NLAT = 8, NLON = 16;    // 2 + 7 x 16 points, 128 faces
    const auto ax = t.semi_axes();
    auto point = [&](double th, double ph) {
      m.verts.insert(m.verts.end(),
                     {ax[0] * std::sin(th) * std::cos(ph), ax[1] * std::sin(th) * std::sin(ph),
                      ax[2] * std::cos(th)});
    };
    point(0.0, 0.0);    // north pole: 0
    for (int i = 1; i < NLAT; i++)
      for (int j = 0; j < NLON; j++) point(M_PI * i / NLAT, 2.0 * M_PI * j / NLON);
    point(M_PI, 0.0);    // south pole: 1 + (NLAT - 1) NLON
    const int south = 1 + (NLAT - 1) * NLON;
    auto ring = [&](int i, int j) {
      return 1 + (i - 1) * NLON + (j % NLON);
    };
    m.face_start.push_back(0);
    auto face = [&](std::initializer_list<int> f) {
      m.face_verts.insert(m.face_verts.end(), f);
      m.face_start.push_back((int) m.face_verts.size());
    };
    for (int j = 0; j < NLON; j++) face({0, ring(1, j), ring(1, j + 1)});    // outward
    for (int i = 1; i < NLAT - 1; i++)
      for (int j = 0; j < NLON; j++)
        face({ring(i, j), ring(i + 1, j), ring(i + 1, j + 1), ring(i, j + 1)});
    for (int j = 0; j < NLON; j++) face({south, ring(NLAT - 1, j + 1), ring(NLAT - 1, j)});
  } else {
    const auto v = t.view();
    m.verts.assign(v.verts, v.verts + 3 * v.nverts);
    m.face_start.assign(v.face_start, v.face_start + v.nfaces + 1);
    m.face_verts.assign(v.face_verts, v.face_verts + v.face_start[v.nfaces]);
  }
}

const DumpPolyhedronVTK::DrawMesh &DumpPolyhedronVTK::mesh_of(int shape)
{
  if (meshes_version != avec->shape_version()) {
    meshes.clear();
    meshes_version = avec->shape_version();
  }
  if ((int) meshes.size() <= shape) meshes.resize(shape + 1);
  DrawMesh &m = meshes[shape];
  if (!m.face_start.empty()) return m;
  const auto &t = avec->shape(shape);
  if (!t.is_composite()) {
    draw_convex(t, m);
    return m;
  }
  // a composite: each part's faces, placed in the body frame
  m.face_start.push_back(0);
  for (int k = 0; k < t.nparts(); k++) {
    DrawMesh pm;
    draw_convex(t.part_shape(k), pm);
    const auto &pl = t.part(k);
    const int base = m.nverts();
    for (int v = 0; v < pm.nverts(); v++) {
      const double *b = &pm.verts[3 * v];
      for (int i = 0; i < 3; i++)
        m.verts.push_back(pl.x[i] + pl.R[i][0] * b[0] + pl.R[i][1] * b[1] + pl.R[i][2] * b[2]);
    }
    for (int f = 0; f < pm.nfaces(); f++) {
      for (int j = pm.face_start[f]; j < pm.face_start[f + 1]; j++)
        m.face_verts.push_back(base + pm.face_verts[j]);
      m.face_start.push_back((int) m.face_verts.size());
    }
  }
  return m;
}

void DumpPolyhedronVTK::write_snapshot()
{
  if (!multifile) rewind(fp);
  const size_t np = records.size() / NREC;
  bigint nv = 0, nf = 0, nidx = 0;
  for (size_t p = 0; p < np; p++) {
    const auto &v = mesh_of((int) records[p * NREC + 2]);
    nv += v.nverts();
    nf += v.nfaces();
    nidx += v.nfaces() + v.face_start.back();
  }
  fmt::print(fp,
             "# vtk DataFile Version 3.0\nPOLYDEM polyhedra, timestep {}\nASCII\n"
             "DATASET POLYDATA\nPOINTS {} double\n",
             update->ntimestep, nv);
  for (size_t p = 0; p < np; p++) {
    const double *r = &records[p * NREC];
    const auto &v = mesh_of((int) r[2]);
    const double s = r[3];
    const auto rot = polydem::quat_to_mat(polydem::make_quat(r[7], r[8], r[9], r[10]));
    for (int k = 0; k < v.nverts(); k++) {
      const auto b = polydem::make_vec3(v.verts[3 * k], v.verts[3 * k + 1], v.verts[3 * k + 2]);
      const auto l = polydem::matvec(rot, b);
      fmt::print(fp, "{:.9g} {:.9g} {:.9g}\n", r[4] + s * l.x, r[5] + s * l.y, r[6] + s * l.z);
    }
  }
  fmt::print(fp, "POLYGONS {} {}\n", nf, nidx);
  bigint offset = 0;
  for (size_t p = 0; p < np; p++) {
    const auto &v = mesh_of((int) records[p * NREC + 2]);
    for (int f = 0; f < v.nfaces(); f++) {
      fmt::print(fp, "{}", v.face_start[f + 1] - v.face_start[f]);
      for (int j = v.face_start[f]; j < v.face_start[f + 1]; j++)
        fmt::print(fp, " {}", offset + v.face_verts[j]);
      fmt::print(fp, "\n");
    }
    offset += v.nverts();
  }
  const char *names[3] = {"id", "type", "shape"};
  fmt::print(fp, "CELL_DATA {}\n", nf);
  for (int c = 0; c < 3; c++) {
    fmt::print(fp, "SCALARS {} int 1\nLOOKUP_TABLE default\n", names[c]);
    for (size_t p = 0; p < np; p++) {
      const double *r = &records[p * NREC];
      const int nfp = mesh_of((int) r[2]).nfaces();
      const bigint val = (c == 2) ? (bigint) r[2] + 1 : (bigint) r[c];
      for (int f = 0; f < nfp; f++) fmt::print(fp, "{}\n", val);
    }
  }
  fflush(fp);
  // a single file: drop what is left of a longer earlier snapshot
  if (!multifile && ftruncate(fileno(fp), ftell(fp)) != 0)
    error->one(FLERR, "dump polyhedron/vtk: cannot truncate {}: {}", filename,
               utils::getsyserror());
  records.clear();
}
