/* ----------------------------------------------------------------------
   POLYDEM - fix wall/mesh
------------------------------------------------------------------------- */

#include "fix_wall_mesh.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "input.h"
#include "math_const.h"
#include "memory.h"
#include "modify.h"
#include "neighbor.h"
#include "pair.h"
#include "poly_shape_library.h"
#include "poly_timestep.h"
#include "update.h"
#include "variable.h"

#include "polydem_parse.h"
#include "polydem_damping.h"
#include "polydem_shape_template.h"

#include <cmath>
#include <algorithm>
#include <cstring>
#include <vector>

using namespace LAMMPS_NS;
using namespace FixConst;
using MathConst::MY_PI;

static constexpr int NH = polydem::WALL_HIST_SIZE;

/* ----------------------------------------------------------------------
   fix ID group wall/mesh file.stl keyword value ...
------------------------------------------------------------------------- */

FixWallMesh::FixWallMesh(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), binsize(0.0), merge_tol(1e-9), wall_E(-1.0), wall_nu(-2.0), wall_e(-1.0),
    wall_mu(-1.0), wall_mur(-1.0), wall_coh(-1.0), servo_ivar(-1), core(1.0e-4), patch_angle(20.0), twosided(1), twist(1), depth_warn(0.25),
    overlap_warn(0.05), elapsed(0.0), hist(nullptr),
    ellipsoids(0), reduced(0), avec(nullptr), near_cap(128), near_skin(0.02), near_builds(0),
    near_builds_all(0), near_overflows_all(0), near_lists_held(0), near_builds_run(0), pertri(0), tri_reduced(0)
{
  if (narg < 4) error->all(FLERR, "fix wall/mesh: expected 'fix ID group wall/mesh file.stl ...'");
  file = arg[3];

  scalar_flag = 1;
  extscalar = 1;
  vector_flag = 1;
  size_vector = NVEC + NSERVO;
  extvector = 1;
  global_freq = 1;
  energy_global_flag = 1;
  restart_global = 1;
  restart_peratom = 1;
  create_attribute = 1;
  time_integrate = 0;

  for (double &b : wall_bridge) b = 0.0;
  const polydem::StlTransform xf = parse_keywords(narg, arg);

  // every rank reads the file (meshes are replicated); rank 0 reports
  int ok = 1;
  std::string why;
  try {
    geom.load(file, xf, merge_tol, patch_angle);
  } catch (polydem::StlError &e) {
    ok = 0;
    why = e.what();
  }
  int allok, anyok;
  MPI_Allreduce(&ok, &allok, 1, MPI_INT, MPI_MIN, world);
  MPI_Allreduce(&ok, &anyok, 1, MPI_INT, MPI_MAX, world);
  // every rank failed alike (the usual case): error->all, which reaches the
  // log; a rank that alone cannot read the file reports itself
  if (!anyok) error->all(FLERR, "fix wall/mesh: {}", why);
  if (!allok) {
    if (!ok) error->one(FLERR, "fix wall/mesh: {}", why);
    error->all(FLERR, "fix wall/mesh: cannot read {}", file);
  }
  const auto &mesh = geom.mesh;
  const auto &merged = geom.merged;
  if (comm->me == 0) {
    // kept: before coplanar merging
    const int kept = merged.after != merged.before ? merged.before : mesh.ntri();
    utils::logmesg(lmp, "fix wall/mesh {}: {} {} STL, {} triangles read, {} kept\n", id, file,
                   mesh.binary ? "binary" : "ASCII", mesh.nread, kept);
    if (mesh.ndegenerate > 0)
      error->warning(FLERR, "fix wall/mesh: {}: {} zero-area triangles dropped", file,
                     mesh.ndegenerate);
    if (mesh.nopposite > mesh.nalong)
      error->warning(FLERR, "fix wall/mesh: {}: the facet normals stored in the file point against "
                     "the vertex order for {} of {} triangles: particles are on the side the vertex "
                     "order gives{} (see flip)", file, mesh.nopposite, mesh.nopposite + mesh.nalong,
                     xf.flip ? ", reversed by flip yes" : "");
    if (mesh.trailing > 0)
      error->warning(FLERR, "fix wall/mesh: {}: {} bytes after the {} triangles the binary header "
                     "announces, ignored", file, mesh.trailing, mesh.nread);
    if (mesh.no_endsolid)
      error->warning(FLERR, "fix wall/mesh: {}: no 'endsolid' after the last facet: the file may "
                     "be truncated ({} triangles read)", file, mesh.nread);
    if (mesh.nduplicate > 0)
      error->warning(FLERR, "fix wall/mesh: {}: {} duplicate triangles dropped", file,
                     mesh.nduplicate);
  }
  if (comm->me == 0 && merged.after != merged.before)
    utils::logmesg(lmp, "fix wall/mesh {}: {} coplanar regions re-triangulated, {} -> {} "
                   "triangles ({} holes bridged, {} regions kept as read)\n", id,
                   merged.merged_regions, merged.before, merged.after, merged.bridged_holes,
                   merged.kept_holes + merged.kept_failed);
  if (comm->me == 0)
    utils::logmesg(lmp, "fix wall/mesh {}: {} smooth regions (patch/angle {})\n", id,
                   geom.nregions, patch_angle);

  for (int k = 0; k <= NVEC; k++) local[k] = global[k] = 0.0;
  for (int k = 0; k < NCOUNTS; k++) counts_local[k] = counts_reported[k] = 0.0;
  for (double &c : fresh_local) c = 0.0;
  if (pertri) {
    array_flag = 1;
    size_array_rows = geom.mesh.ntri();
    size_array_cols = 4;
    extarray = 0;
    tri_local.assign(3 * (size_t) geom.mesh.ntri(), 0.0);
    tri_global.assign(3 * (size_t) geom.mesh.ntri(), 0.0);
    tri_touched.clear();
  }

  // composites: each part keeps its own wall history
  nh = NH * PolyShapeLibrary::of(lmp, "fix wall/mesh")->max_parts();
  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
  for (int i = 0; i < atom->nlocal; i++) set_arrays(i);
}

FixWallMesh::~FixWallMesh()
{
  if (copymode) return;
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  memory->destroy(hist);
}

int FixWallMesh::setmask()
{
  return INITIAL_INTEGRATE | POST_FORCE;
}

// bin edge: user value, else max(r_max / 2, twice the median triangle edge)
// (r_max: largest bounding radius of the group): a query then scans little
// beyond the sphere's box, and a bin holds a few triangles
void FixWallMesh::build_grid()
{
  double h = binsize;
  if (!(h > 0.0)) {
    double rmax = 0.0;
    for (int i = 0; i < atom->nlocal; i++)
      if (atom->mask[i] & groupbit) rmax = MAX(rmax, atom->radius[i]);
    MPI_Allreduce(MPI_IN_PLACE, &rmax, 1, MPI_DOUBLE, MPI_MAX, world);
    h = geom.automatic_bin(rmax);
  }
  if (!geom.set_grid(h)) return;
  const auto &grid = geom.grid;
  if (comm->me == 0 && binsize > 0.0 && grid.h > binsize)
    error->warning(FLERR, "fix wall/mesh {}: bin {} enlarged to {:.6g} (at most {} bins and 2^28 "
                   "entries)", id, binsize, grid.h, 1L << 22);
  if (comm->me == 0)
    utils::logmesg(lmp, "fix wall/mesh {}: bin grid {} x {} x {}, edge {:.6g}, {} entries for {} "
                   "triangles\n", id, grid.n[0], grid.n[1], grid.n[2], grid.h, grid.items.size(),
                   geom.ntri());
}

// the obstacle query of fix insert/polyhedron: the mesh answers it at its pose now
bool FixWallMesh::insertion_clear(const polydem::InsertBody<double> &lab,
                                  const polydem::Quat<double> &q, double gap)
{
  return geom.insertion_clear(mesh_pose(), lab, q, gap, twosided);
}

polydem::MeshPose<double> FixWallMesh::mesh_pose() const
{
  return geom.motion.pose(elapsed);
}

polydem::WallScene<double> FixWallMesh::scene() const
{
  return {mesh_pose(), geom.grid_view(), geom.cosmax, twosided, depth_warn, overlap_warn,
          near_skin, ellipsoids ? 0 : 1};
}

/* ---------------------------------------------------------------------- */

void FixWallMesh::setup(int /*vflag*/)
{
  compute_forces(false);
  report_initial_overlaps();
}

// Contacts without history at setup: particles created or moved into the
// mesh (issue 17). Their elastic energy is released in the first steps.
void FixWallMesh::report_initial_overlaps()
{
  double n = 0.0, mx[3];
  MPI_Allreduce(&fresh_local[0], &n, 1, MPI_DOUBLE, MPI_SUM, world);
  MPI_Allreduce(&fresh_local[1], mx, 3, MPI_DOUBLE, MPI_MAX, world);
  if (n > 0.0 && comm->me == 0)
    error->warning(FLERR,
                   "fix wall/mesh {}: {:.0f} contact(s) overlap the mesh at the start of "
                   "the run with no contact history (particles created or moved into it): "
                   "largest overlap volume {:.3g} of the particle's, depth {:.3g} of its "
                   "bounding radius; the elastic energy would launch a particle at up to "
                   "{:.3g} (velocity units)",
                   id, n, mx[0], mx[1], sqrt(2.0 * mx[2] / force->mvv2e));
}

void FixWallMesh::initial_integrate(int /*vflag*/)
{
  elapsed += update->dt;
  auto &m = geom.motion;
  if (m.style == polydem::MeshMotion::SERVO) m.s += m.v * update->dt;
}

// move servo: the velocity of the next step from this step's force on the mesh
void FixWallMesh::post_force(int /*vflag*/)
{
  compute_forces(true);
  if (geom.motion.style != polydem::MeshMotion::SERVO) return;
  compute_scalar();    // the sums over ranks
  servo_target();
  geom.motion.servo_step(global);
}

void FixWallMesh::servo_target()
{
  if (servo_ivar < 0) return;
  modify->clearstep_compute();
  geom.motion.target = input->variable->compute_equal(servo_ivar);
  modify->addstep_compute(update->ntimestep + 1);
}

void FixWallMesh::compute_forces(bool update)
{
  for (int k = 0; k <= NVEC; k++) local[k] = 0.0;
  for (double &c : fresh_local) c = 0.0;
  reduced = 0;
  tri_reduced = 0;
  // per-triangle forces: only the rows the last step wrote are cleared (a
  // large mesh has far more triangles than contacts)
  if (pertri) {
    for (const int t : tri_touched)
      for (int c = 0; c < 3; c++) tri_local[3 * (size_t) t + c] = 0.0;
    tri_touched.clear();
  }
  double **f = atom->f, **torque = atom->torque;
  const auto atoms = polydem::host_atoms(atom);
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  const auto sc = scene();
  if (!ws) ws = std::make_unique<polydem::WallWorkspace<double>>();
  ws->record = pertri;
  polydem::WallPatches<double> P;
  auto add_tri = [&](int t, double fx, double fy, double fz) {
    double *r = &tri_local[3 * (size_t) t];
    // a row that is all zero may be listed twice: clearing it twice is harmless
    if (r[0] == 0.0 && r[1] == 0.0 && r[2] == 0.0) tri_touched.push_back(t);
    r[0] += fx;
    r[1] += fy;
    r[2] += fz;
  };
  // near lists index local atoms: stale after exchange/sort (reneighboring)
  // and at setup (anything may have changed between runs); one list per
  // composite part (polydem::wall_part_near), as many as atom i's template
  // has parts from near_first[i] on (none for atoms outside the group)
  avec->views(views);
  const bool stale = !update || neighbor->ago == 0;
  if (near_cap > 0 && (stale || near_first.size() != (size_t) nlocal + 1)) {
    near_first.resize(nlocal + 1);
    near_first[0] = 0;
    for (int i = 0; i < nlocal; i++)
      near_first[i + 1] = near_first[i] +
          ((mask[i] & groupbit) ? polydem::near_lists_of(views[atom->pshape[i]]) : 0);
    const size_t n = near_first[nlocal];
    near_lists_held = (bigint) n;
    near_ref.resize(13 * n);
    near_tri.resize((size_t) near_cap * n);
    near_gap.resize((size_t) near_cap * n);
    near_count.assign(n, polydem::NEAR_REBUILD);
  }
  polydem::WallNear<double> nl;
  nl.cap = near_cap;
  polydem::WallTally<double> sum;
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    // gather: atom i with its template and semi-axes (0: a polyhedron)
    const auto &shape = avec->shape(atom->pshape[i]);
    const auto &sv = views[atom->pshape[i]];
    const auto &a = shape.semi_axes();
    const auto b =
        polydem::gather_wall_body(atoms, i, &sv,
                                  shape.is_ellipsoid() ? polydem::make_vec3(a[0], a[1], a[2])
                                                       : polydem::make_vec3(0.0, 0.0, 0.0));
    polydem::WallNear<double> *pn = nullptr;
    if (near_cap > 0) {
      const size_t l0 = near_first[i];
      nl.ref = near_ref.data() + 13 * l0;
      nl.count = near_count.data() + l0;
      nl.tri = near_tri.data() + near_cap * l0;
      nl.gap = near_gap.data() + near_cap * l0;
      pn = &nl;
    }
    // the contact (polydem_wall_pipeline.h; a composite's parts one by
    // one), tally, then scatter
    auto tally = [&](const polydem::WallBody<double> &bb,
                     const polydem::WallContactResult<double> &rr,
                     const polydem::WallPatches<double> &PP) {
      polydem::wall_tally_add(sum, bb, rr, sc.mp, PP);
      if (pertri) polydem::wall_body_triangle_forces(bb, *ws, PP, rr, add_tri);
    };
    const auto r = polydem::wall_particle_contact(b, laws, sc, lmp->update->dt, update, hist[i],
                                                  *ws, P, pn, tally);
    f[i][0] += r.wf.f.x;
    f[i][1] += r.wf.f.y;
    f[i][2] += r.wf.f.z;
    torque[i][0] += r.wf.tau.x;
    torque[i][1] += r.wf.tau.y;
    torque[i][2] += r.wf.tau.z;
  }
  absorb(sum);
  if (update && neighbor->ago == 0) report_counts();
}

// the sums of one call (plain loop or /kk reduction) into the fix's
// output vector, energy, kernel counts and warnings
void FixWallMesh::absorb(const polydem::WallTally<double> &t)
{
  for (int k = 0; k < 3; k++) {
    local[k] = t.force[k];
    local[3 + k] = t.torque[k];
  }
  local[6] = t.ncontact;
  local[7] = t.ntri;
  local[NVEC] = t.energy;
  counts_local[0] += t.noverflow;
  counts_local[1] += t.ndegenerate;
  counts_local[2] += t.nmerged;
  counts_local[3] += t.near_overflow;
  counts_local[4] += t.nunrecorded;
  counts_local[5] += t.behind;
  counts_local[6] += t.deep;
  counts_local[7] += t.large;
  counts_local[8] += t.ncapped;
  fresh_local[0] = t.fresh;
  fresh_local[1] = t.fresh_v;
  fresh_local[2] = t.fresh_d;
  fresh_local[3] = t.fresh_em;
  near_builds += (bigint) t.near_builds;
}

// kernel failures are counted and reported (collectively) as warnings: the
// first one, then each time a count has doubled since its last warning
void FixWallMesh::report_counts()
{
  double all[NCOUNTS];
  MPI_Allreduce(counts_local, all, NCOUNTS, MPI_DOUBLE, MPI_SUM, world);
  if (comm->me != 0) return;
  const std::string what[NCOUNTS] = {
      "clip workspace overflows (triangle skipped)",
      "degenerate particle-triangle contacts (NaN; triangle skipped)",
      "facets joined to the closest of the 4 contact patches",
      fmt::format("near-list overflows (more than cache = {} triangles within reach; those "
                  "particles query the grid every step: same forces, slower)",
                  near_cap),
      fmt::format("triangle contacts left out of the per-triangle forces (more than {} "
                  "triangles under one particle; the forces on the mesh are complete)",
                  polydem::WALL_MAX_CAND),
      twosided ? std::string("contacts whose particle's centroid has crossed the plane of the "
                             "side it touches (pushed more than halfway through the wall; "
                             "still pushed back to the side its contact began on)")
               : std::string("contacts of particles whose centroid is behind the wall (sides "
                             "front: the wall pushes them through; check the normals, flip, "
                             "or sides both)"),
      fmt::format("contacts deeper than depth/warn = {} of the particle's bounding radius",
                  depth_warn),
      fmt::format("contacts whose overlap volume exceeds overlap/warn = {} of the particle's "
                  "volume",
                  overlap_warn),
      std::string("contact-steps whose normal damping (dashpot or a liquid bridge's viscosity) "
                  "was capped at m_eff/dt, less than asked: the time step is too long for these "
                  "contacts")};
  for (int k = 0; k < NCOUNTS; k++)
    if (all[k] > 0.0 && all[k] >= 2.0 * counts_reported[k]) {
      error->warning(FLERR, "fix wall/mesh {}: {:.0f} {} by step {}", id, all[k], what[k],
                     update->ntimestep);
      counts_reported[k] = all[k];
    }
}

double FixWallMesh::compute_scalar()
{
  if (!reduced) {
    MPI_Allreduce(local, global, NVEC + 1, MPI_DOUBLE, MPI_SUM, world);
    reduced = 1;
  }
  return global[NVEC];
}

/* ----------------------------------------------------------------------
   pertriangle: row = triangle (in the order as read and merged), columns 1-3 the
   force of the particles on it (lab frame), 4 its normal pressure
   -F . n / area (n the triangle's outward normal, lab frame)
------------------------------------------------------------------------- */

double FixWallMesh::compute_array(int i, int j)
{
  if (!tri_reduced) {
    fetch_triangle_forces();
    MPI_Allreduce(tri_local.data(), tri_global.data(), (int) tri_local.size(), MPI_DOUBLE,
                  MPI_SUM, world);
    tri_reduced = 1;
  }
  const size_t t = (size_t) geom.tri_of_row[i];    // rows in the order as read
  if (j < 3) return tri_global[3 * t + j];
  const auto mp = mesh_pose();
  const double *pl = &geom.grid.plane[4 * t];
  const auto n = polydem::matvec(mp.R, polydem::make_vec3(pl[0], pl[1], pl[2]));
  const double *q = &geom.mesh.tri[9 * t];
  const auto e1 = polydem::make_vec3(q[3] - q[0], q[4] - q[1], q[5] - q[2]);
  const auto e2 = polydem::make_vec3(q[6] - q[0], q[7] - q[1], q[8] - q[2]);
  const double area = 0.5 * polydem::norm(polydem::cross(e1, e2));
  const double *f = &tri_global[3 * t];
  return -(f[0] * n.x + f[1] * n.y + f[2] * n.z) / area;
}

double FixWallMesh::compute_vector(int n)
{
  if (n == NVEC) return geom.motion.s;
  if (n == NVEC + 1) return geom.motion.v;
  compute_scalar();
  return global[n];
}

/* ---------------------------------------------------------------------- */

void FixWallMesh::grow_arrays(int nmax)
{
  memory->grow(hist, nmax, nh, "wall/mesh:hist");
}

void FixWallMesh::copy_arrays(int i, int j, int /*delflag*/)
{
  for (int k = 0; k < nh; k++) hist[j][k] = hist[i][k];
}

void FixWallMesh::set_arrays(int i)
{
  for (int k = 0; k < nh; k++) hist[i][k] = 0.0;
}

int FixWallMesh::pack_exchange(int i, double *buf)
{
  for (int k = 0; k < nh; k++) buf[k] = hist[i][k];
  return nh;
}

int FixWallMesh::unpack_exchange(int nlocal, double *buf)
{
  for (int k = 0; k < nh; k++) hist[nlocal][k] = buf[k];
  return nh;
}

int FixWallMesh::pack_restart(int i, double *buf)
{
  buf[0] = nh + 1;    // other fixes skip by this count
  for (int k = 0; k < nh; k++) buf[k + 1] = hist[i][k];
  return nh + 1;
}

void FixWallMesh::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  // the layout before rolling resistance (4 + CONTACT_HIST values per
  // patch) is read with the rolling torques zero; a file from a version
  // with another layout (7 values per contact before the two-sided walls)
  // cannot be read as this one
  constexpr int OLD_PATCH = 4 + polydem::CONTACT_HIST;
  constexpr int OLD_NH = polydem::WALL_MAX_PATCH * OLD_PATCH;
  const int nread = static_cast<int>(extra[nlocal][m]) - 1;
  if (nread != nh && nread != OLD_NH) {
    error->one(FLERR,
               "fix wall/mesh {}: the restart file keeps {} wall-history values per atom, "
               "this run {} (composite shapes keep {} per part): define the fix with another "
               "ID to start without history",
               id, nread, nh, NH);
  }
  m++;
  if (nread == nh) {
    for (int k = 0; k < nh; k++) hist[nlocal][k] = extra[nlocal][m++];
    return;
  }
  for (int k = 0; k < nh; k++) hist[nlocal][k] = 0.0;
  for (int p = 0; p < polydem::WALL_MAX_PATCH; p++)
    for (int k = 0; k < OLD_PATCH; k++) hist[nlocal][p * polydem::WALL_HIST + k] = extra[nlocal][m++];
}

int FixWallMesh::size_restart(int /*nlocal*/)
{
  return nh + 1;
}

int FixWallMesh::maxsize_restart()
{
  return nh + 1;
}

// global state: the time the mesh has moved for (its offset or angle)
void FixWallMesh::write_restart(FILE *fp)
{
  if (comm->me != 0) return;
  // (-ntri - 1: the servo's state follows; older files have ntri >= 0 and
  // no more)
  const double list[4] = {elapsed, -(double) geom.mesh.ntri() - 1.0, geom.motion.s,
                          geom.motion.v};
  const int size = 4 * sizeof(double);
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(list, sizeof(double), 4, fp);
}

void FixWallMesh::restart(char *buf)
{
  const auto *list = (const double *) buf;
  elapsed = list[0];
  const bool servo_state = list[1] < 0.0;
  const int ntri = servo_state ? (int) (-list[1] - 1.0) : (int) list[1];
  if (ntri != geom.mesh.ntri())
    error->all(FLERR, "fix wall/mesh: the restart file's mesh had {} triangles, {} has {}",
               ntri, file, geom.mesh.ntri());
  if (servo_state && geom.motion.style == polydem::MeshMotion::SERVO) {
    geom.motion.s = list[2];
    geom.motion.v = list[3];
  }
}

/* ----------------------------------------------------------------------
   near-list statistics of the run (log), for choosing cache and cache/skin
------------------------------------------------------------------------- */

void FixWallMesh::post_run()
{
  report_counts();    // what the last steps since reneighboring added
  bigint mine[2] = {near_builds, (bigint) counts_local[3]}, all[2];
  MPI_Allreduce(mine, all, 2, MPI_LMP_BIGINT, MPI_SUM, world);
  const bigint run_builds = all[0] - near_builds_run;
  near_builds_all = all[0];
  near_overflows_all = all[1];
  near_builds_run = all[0];
  if (comm->me == 0 && near_cap > 0)
    utils::logmesg(lmp, "fix wall/mesh {}: {} near lists built in this run, {} overflows so far "
                   "(cache {}, cache/skin {})\n", id, run_builds, all[1], near_cap, near_skin);
}

void *FixWallMesh::extract(const char *name, int &dim)
{
  dim = 0;
  if (strcmp(name, "near_builds") == 0) return &near_builds_all;
  if (strcmp(name, "near_overflows") == 0) return &near_overflows_all;
  if (strcmp(name, "near_lists") == 0) return &near_lists_held;
  return nullptr;
}

double FixWallMesh::memory_usage()
{
  double bytes = (double) atom->nmax * nh * sizeof(double);
  bytes += geom.mesh.tri.size() * sizeof(double);
  bytes += (geom.regions.size() + geom.row.size() + geom.tri_of_row.size()) * sizeof(int);
  bytes += (geom.grid.plane.size() + geom.grid.box.size() + geom.grid.sphere.size()) * sizeof(double);
  bytes += (geom.grid.start.size() + geom.grid.items.size()) * sizeof(int);
  bytes += near_ref.size() * sizeof(double) + (near_count.size() + near_tri.size()) * sizeof(int) +
      near_gap.size() * sizeof(float) + near_first.size() * sizeof(size_t);
  return bytes;
}
