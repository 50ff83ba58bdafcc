/* ----------------------------------------------------------------------
   POLYDEM - fix wall/mesh: its init (the group's shapes, the material and
   law table from the pair style's coefficients and the fix's keywords) and
   the checks of the time step and of the mesh's step
------------------------------------------------------------------------- */

#include "fix_wall_mesh.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "input.h"
#include "math_const.h"
#include "modify.h"
#include "pair.h"
#include "poly_shape_library.h"
#include "poly_timestep.h"
#include "update.h"
#include "variable.h"

#include "polydem_damping.h"
#include "polydem_shape_template.h"

#include <algorithm>
#include <cmath>
#include <vector>

using namespace LAMMPS_NS;
using MathConst::MY_PI;

static constexpr int NH = polydem::WALL_HIST_SIZE;

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
                                        wall_bridge[2] * MY_PI / 180.0, wall_bridge[3],
                                        wall_bridge[4]);
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

polydem::ContactLaw<double> FixWallMesh::law_of(int t, int ishape, double s) const
{
  if (ellipsoids) return polydem::wall_ellipsoid_law(laws, t);
  const double V = avec->shape(ishape).volume() * s * s * s;
  return polydem::wall_polyhedron_law(laws, t, V);
}
