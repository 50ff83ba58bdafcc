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
    near_builds_all(0), near_overflows_all(0), near_builds_run(0), pertri(0), tri_reduced(0)
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

  wall_bridge[0] = wall_bridge[1] = wall_bridge[2] = 0.0;
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

/* ----------------------------------------------------------------------
   material per particle type: E, nu from the pair style (pair_coeff), wall
   E, nu default to the particle's; e, mu default to the type's like pair
------------------------------------------------------------------------- */

void FixWallMesh::init()
{
  if (!servo_var.empty()) {
    servo_ivar = input->variable->find(servo_var.c_str());
    if (servo_ivar < 0)
      error->all(FLERR, "fix wall/mesh {}: move servo: variable '{}' does not exist", id,
                 servo_var);
    if (!input->variable->equalstyle(servo_ivar))
      error->all(FLERR, "fix wall/mesh {}: move servo: variable '{}' is not equal-style", id,
                 servo_var);
  }
  avec = PolyShapeLibrary::of(lmp, "fix wall/mesh");
  // the group's shapes, and those an insertion fix will add to it (every
  // rank sees the same candidates: counted on rank 0)
  int nkind[4] = {0, 0, 0, -1};    // polyhedra, ellipsoids, of them spheres; a composite
  // per type: it has ellipsoids of unequal semi-axes (or parts that are)
  std::vector<int> aniso_type(atom->ntypes + 1, 0);
  auto count = [&](int ishape, int type) {    // a composite: by its parts
    const auto &sh = avec->shape(ishape);
    auto one = [&](const polydem::PolyShapeTemplate &p) {
      nkind[p.is_ellipsoid() ? 1 : 0]++;
      if (p.is_sphere()) nkind[2]++;
      if (p.is_ellipsoid() && !p.is_sphere()) aniso_type[type] = 1;
    };
    if (!sh.is_composite()) return one(sh);
    nkind[3] = ishape;
    for (int k = 0; k < sh.nparts(); k++) one(sh.part_shape(k));
  };
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->mask[i] & groupbit) count(atom->pshape[i], atom->type[i]);
  if (comm->me == 0)
    for (const auto &c : ParticleSource::candidates(lmp))
      if (c.mask & groupbit) count(c.ishape, c.type);
  MPI_Allreduce(MPI_IN_PLACE, nkind, 3, MPI_INT, MPI_SUM, world);
  MPI_Allreduce(MPI_IN_PLACE, &nkind[3], 1, MPI_INT, MPI_MAX, world);
  MPI_Allreduce(MPI_IN_PLACE, aniso_type.data(), atom->ntypes + 1, MPI_INT, MPI_MAX, world);
  if (nkind[3] >= 0 && nh < NH * avec->max_parts())
    error->all(FLERR, "fix wall/mesh {}: shape '{}' of its group is a composite defined after "
               "the fix, whose history keeps {} parts per atom: define composite shapes "
               "before fix wall/mesh", id, avec->shape_id(nkind[3]), nh / NH);
  // material: polyhedra E, nu (pair_style polyhedron), ellipsoids k_n and
  // the tangential ratios (pair_style ellipsoid); e and mu from either
  int dim = 0;
  double *E = nullptr, *nu = nullptr, **e = nullptr, **mu = nullptr, **kn = nullptr;
  double *ktr = nullptr, *gtr = nullptr, **mur = nullptr, *rkr = nullptr, *reta = nullptr;
  double **coh = nullptr, **ekn = nullptr;
  if (force->pair) {
    ekn = (double **) force->pair->extract("ellipsoid_kn", dim);
    coh = (double **) force->pair->extract("cohesion", dim);
    mur = (double **) force->pair->extract("rolling", dim);
    rkr = (double *) force->pair->extract("rolling_kr", dim);
    reta = (double *) force->pair->extract("rolling_eta", dim);
    E = (double *) force->pair->extract("youngs", dim);
    nu = (double *) force->pair->extract("poisson", dim);
    e = (double **) force->pair->extract("restitution", dim);
    mu = (double **) force->pair->extract("friction", dim);
    kn = (double **) force->pair->extract("kn", dim);
    ktr = (double *) force->pair->extract("kt_ratio", dim);
    gtr = (double *) force->pair->extract("gt_ratio", dim);
  }
  const bool poly_mat = E && nu && e && mu, ell_mat = kn && ktr && gtr && e && mu;
  const std::string pstyle = force->pair_style ? force->pair_style : "none";
  // under pair_style polyhedron, spheres take the polyhedra's volume law
  // (polydem_wall_ellipsoid.h, sphere_cap_contacts) and ellipsoids of
  // unequal semi-axes pair_style ellipsoid's linear law with the like
  // pair's 'ellipsoid k_n': all may share a wall
  const bool spheres_by_volume = poly_mat && !ell_mat;
  if (nkind[0] && nkind[1] && !spheres_by_volume)
    error->all(FLERR, "fix wall/mesh: its group has {} polyhedra and {} ellipsoids; they share "
               "a wall under pair_style polyhedron only (pair_style is '{}')", nkind[0],
               nkind[1], pstyle);
  if (nkind[1] && !ell_mat && !spheres_by_volume)
    error->all(FLERR, "fix wall/mesh: {} atoms of its group have an ellipsoid shape; their wall "
               "contact takes k_n, e and mu from pair_style ellipsoid (pair_coeff I I kn e mu) "
               "or polyhedron, pair_style is '{}'", nkind[1], pstyle);
  if (!nkind[1] && !poly_mat && !ell_mat)
    error->all(FLERR, "fix wall/mesh: requires pair_style polyhedron (the particles' E and nu "
               "come from its pair_coeff) or pair_style ellipsoid (k_n)");
  ellipsoids = (nkind[1] > 0 && !spheres_by_volume) || !poly_mat;
  if (ellipsoids && (wall_E > 0.0 || wall_nu > -1.0) && comm->me == 0)
    error->warning(FLERR, "fix wall/mesh {}: youngs and poisson do not apply to ellipsoids "
                   "(their wall stiffness is k_n of pair_coeff)", id);
  const int nt = atom->ntypes;
  law_entries.assign(nt + 1, polydem::LawEntry<double>());
  laws = polydem::law_table(law_entries.data(), nt, nt + 1);
  laws.core = core;
  laws.twist = twist;
  // the linear law's tangential ratios: pair_style ellipsoid's, or its
  // defaults for the ellipsoids of a pair_style polyhedron scene
  laws.kt_ratio = ellipsoids ? *ktr : polydem::ELLIPSOID_KT_RATIO;
  laws.gt_ratio = ellipsoids ? *gtr : polydem::ELLIPSOID_GT_RATIO;
  if (rkr) laws.roll_kr = *rkr;
  if (reta) laws.roll_eta = *reta;
  for (int t = 1; t <= nt; t++) {
    auto &L = law_entries[t];
    if (ellipsoids) {
      L.kn = kn[t][t];
    } else {
      // k_n: ellipsoids of unequal semi-axes under pair_style polyhedron
      L.kn = ekn ? ekn[t][t] : 0.0;
      if (aniso_type[t] && !(L.kn > 0.0))
        error->all(FLERR, "fix wall/mesh {}: particle type {} has ellipsoids of unequal "
                   "semi-axes, which meet the wall by the linear law of pair_style ellipsoid: "
                   "add 'ellipsoid k_n' to pair_coeff {} {}", id, t, t, t);
      L.E1 = E[t];
      L.nu1 = nu[t];
      L.E2 = wall_E > 0.0 ? wall_E : E[t];
      L.nu2 = wall_nu > -1.0 ? wall_nu : nu[t];
    }
    const double et = wall_e > 0.0 ? wall_e : e[t][t];
    L.mu = wall_mu >= 0.0 ? wall_mu : mu[t][t];
    L.mu_r = wall_mur >= 0.0 ? wall_mur : (mur ? mur[t][t] : 0.0);
    L.cohesion = wall_coh >= 0.0 ? wall_coh : (coh ? coh[t][t] : 0.0);
    L.bridge = polydem::make_bridge_law(wall_bridge[0], wall_bridge[1],
                                        wall_bridge[2] * MY_PI / 180.0);
    if (!(ellipsoids ? L.kn > 0.0 : L.E1 > 0.0) || !(et > 0.0))
      error->all(FLERR, "fix wall/mesh: particle type {} has no material (pair_coeff {} {} {})",
                 t, t, t, ellipsoids ? "kn e mu" : "E nu e mu");
    L.damping = polydem::damping_law(et, 1);
  }
  if (wall_bridge[0] > 0.0 && nkind[0] + nkind[1] > nkind[2] && comm->me == 0)
    error->warning(FLERR, "fix wall/mesh {}: liquid bridges act on spheres only; {} particles "
                   "(or parts) of its group are not spheres and get none", id,
                   nkind[0] + nkind[1] - nkind[2]);
  build_grid();
  check_timestep();
  check_mesh_step();
}

// A mesh that moves farther in one step than a particle is thick can pass
// through it with no contact (a plate at 2 cm per step through a 6 mm
// cube): warn when its largest displacement per step, |v| dt (wiggle: its
// largest speed) or |omega| dt times its largest distance from the axis,
// exceeds MESH_STEP_WARN of the smallest inscribed radius in the group
// (and of the particles an insertion fix will add to it)
void FixWallMesh::check_mesh_step()
{
  constexpr double MESH_STEP_WARN = 0.1;
  const double speed = geom.motion.max_speed(geom.mesh.tri);
  if (!(speed > 0.0)) return;
  double rin = 1e300;
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->mask[i] & groupbit)
      rin = MIN(rin, avec->shape(atom->pshape[i]).inradius() * atom->pscale[i]);
  if (comm->me == 0)
    for (const auto &c : ParticleSource::candidates(lmp))
      if (c.mask & groupbit) rin = MIN(rin, avec->shape(c.ishape).inradius() * c.scale);
  MPI_Allreduce(MPI_IN_PLACE, &rin, 1, MPI_DOUBLE, MPI_MIN, world);
  const double step = speed * update->dt;
  if (comm->me == 0 && rin < 1e300 && step > MESH_STEP_WARN * rin)
    error->warning(FLERR,
                   "fix wall/mesh {}: the mesh moves up to {:.4g} per step (speed {:.4g}, "
                   "timestep {:.4g}), more than {} of the smallest particle's inscribed radius "
                   "{:.4g}: it can pass through particles with no contact; lower the timestep or "
                   "the mesh speed",
                   id, step, speed, update->dt, MESH_STEP_WARN, rin);
}

// A face lying flat on the wall in the core has the largest stiffness of the
// model (polydem_contact_law.h, face_contact_stable_dt): warn when the time
// step exceeds its explicit stability limit, for the largest face of each
// particle of the group.
void FixWallMesh::check_timestep()
{
  TimestepCheck check;
  bigint nover = 0;
  auto consider = [&](int type, int ishape, double s, double m) {
    if (avec->shape(ishape).is_ellipsoid() && (ellipsoids || !avec->shape(ishape).is_sphere())) {
      // ellipsoids: the linear spring's contact time (central impact)
      check.contact(m, law_entries[type].kn * force->ftm2v);
      return;
    }
    if (avec->shape(ishape).is_ellipsoid()) {
      // spheres under the volume law: as pair polyhedron, k_n = 2 E R
      check.contact(m, 2.0 * law_entries[type].E1 * s * avec->shape(ishape).semi_axes()[0] *
                           force->ftm2v);
      return;
    }
    const auto L = law_of(type, ishape, s);
    const double dtf = polydem::face_contact_stable_dt(L.normal, m / force->ftm2v,
                                                       avec->shape(ishape).max_face_area() * s * s);
    if (dtf > 0.0 && std::isfinite(dtf))
      check.flat_face(dtf);
    else
      nover++;
  };
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->mask[i] & groupbit)
      consider(atom->type[i], atom->pshape[i], atom->pscale[i], atom->rmass[i]);
  // and the smallest particle of each kind an insertion fix will add here
  // (counted on rank 0 only: every rank sees the same candidates)
  if (comm->me == 0)
    for (const auto &c : ParticleSource::candidates(lmp))
      if (c.mask & groupbit) consider(c.type, c.ishape, c.scale, c.mass);
  // a stiffness that overflows (youngs 1e300) made every contact NaN
  MPI_Allreduce(MPI_IN_PLACE, &nover, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (nover)
    error->all(FLERR,
               "fix wall/mesh {}: the contact stiffness of {} atom(s) overflows (youngs "
               "{:.4g} of the wall, the particles' from pair_coeff): lower youngs",
               id, nover, wall_E > 0.0 ? wall_E : law_entries[1].E1);
  check.report(lmp, fmt::format("fix wall/mesh {}", id), "an ellipsoid on the wall", "the wall",
               core);
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

polydem::ContactLaw<double> FixWallMesh::law_of(int t, int ishape, double s) const
{
  if (ellipsoids) return polydem::wall_ellipsoid_law(laws, t);
  const double V = avec->shape(ishape).volume() * s * s * s;
  return polydem::wall_polyhedron_law(laws, t, V);
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
  if (pertri) std::fill(tri_local.begin(), tri_local.end(), 0.0);
  double **f = atom->f, **torque = atom->torque;
  const auto atoms = polydem::host_atoms(atom);
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  const auto sc = scene();
  if (!ws) ws = std::make_unique<polydem::WallWorkspace<double>>();
  ws->record = pertri;
  polydem::WallPatches<double> P;
  auto add_tri = [&](int t, double fx, double fy, double fz) {
    tri_local[3 * (size_t) t] += fx;
    tri_local[3 * (size_t) t + 1] += fy;
    tri_local[3 * (size_t) t + 2] += fz;
  };
  // near lists index local atoms: stale after exchange/sort (reneighboring)
  // and at setup (anything may have changed between runs)
  const bool stale = !update || neighbor->ago == 0;
  if (near_cap > 0 && (stale || (int) near_count.size() < nlocal)) {
    const size_t n = std::max<size_t>(nlocal, near_count.size());
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
    const auto sv = shape.view();
    const auto &a = shape.semi_axes();
    const auto b =
        polydem::gather_wall_body(atoms, i, &sv,
                                  shape.is_ellipsoid() ? polydem::make_vec3(a[0], a[1], a[2])
                                                       : polydem::make_vec3(0.0, 0.0, 0.0));
    polydem::WallNear<double> *pn = nullptr;
    if (near_cap > 0) {
      nl.ref = &near_ref[13 * (size_t) i];
      nl.count = &near_count[i];
      nl.tri = &near_tri[(size_t) near_cap * i];
      nl.gap = &near_gap[(size_t) near_cap * i];
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
                  overlap_warn)};
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
   pertriangle: row = triangle (as used, after merging), columns 1-3 the
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
  if (j < 3) return tri_global[3 * (size_t) i + j];
  const auto mp = mesh_pose();
  const double *pl = &geom.grid.plane[4 * (size_t) i];
  const auto n = polydem::matvec(mp.R, polydem::make_vec3(pl[0], pl[1], pl[2]));
  const double *q = &geom.mesh.tri[9 * (size_t) i];
  const auto e1 = polydem::make_vec3(q[3] - q[0], q[4] - q[1], q[5] - q[2]);
  const auto e2 = polydem::make_vec3(q[6] - q[0], q[7] - q[1], q[8] - q[2]);
  const double area = 0.5 * polydem::norm(polydem::cross(e1, e2));
  const double *f = &tri_global[3 * (size_t) i];
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
  return nullptr;
}

double FixWallMesh::memory_usage()
{
  double bytes = (double) atom->nmax * nh * sizeof(double);
  bytes += geom.mesh.tri.size() * sizeof(double);
  bytes += (geom.grid.start.size() + geom.grid.items.size()) * sizeof(int);
  bytes += near_ref.size() * sizeof(double) + (near_count.size() + near_tri.size()) * sizeof(int) +
      near_gap.size() * sizeof(float);
  return bytes;
}
