/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - fix wall/mesh: a triangulated STL wall (static, translating or
   rotating) in contact with polyhedral particles (patch-summed clipped
   prism volumes and section areas, seed §2.4) or ellipsoids (closest point
   of the affinely mapped triangles), the pair style's material model.
   Physics in polydem_wall_contact.h and polydem_wall_ellipsoid.h.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(wall/mesh,FixWallMesh);
// clang-format on
#else

#ifndef LMP_FIX_WALL_MESH_H
#define LMP_FIX_WALL_MESH_H

#include "fix.h"
#include "poly_roles.h"

#include "polydem_wall_pipeline.h"
#include "polydem_insert.h"
#include "polydem_wall_mesh.h"

#include <memory>
#include <string>
#include <vector>

namespace LAMMPS_NS {

class FixWallMesh : public Fix, public InsertionObstacle {
 public:
  FixWallMesh(class LAMMPS *, int, char **);
  ~FixWallMesh() override;
  int setmask() override;
  void init() override;
  void setup(int) override;
  void initial_integrate(int) override;
  void post_force(int) override;
  double compute_scalar() override;
  double compute_vector(int) override;
  double compute_array(int, int) override;

  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;
  void write_restart(FILE *) override;
  void restart(char *) override;
  double memory_usage() override;
  void post_run() override;
  void *extract(const char *, int &) override;

  // fix insert/polyhedron: true if body b (lab frame, orientation q) is
  // certified farther than gap from every triangle of the mesh at its
  // current pose and has no contact with it (a polyhedron no contact
  // volume, an ellipsoid no closest point; e.g. behind a one-sided wall)
  bool insertion_clear(const polydem::InsertBody<double> &b, const polydem::Quat<double> &q,
                       double gap) override;

  // vector: force on the mesh (3), torque on the mesh about its axis point
  // (3), contacts, triangles touched (summed over ranks); then the servo's
  // displacement and velocity along its direction (move servo; else 0)
  enum { NVEC = 8, NSERVO = 2 };

 protected:
  std::string file;
  polydem::WallMesh geom;    // triangles, smooth regions, bin grid, motion
  double binsize;    // user bin edge (0: automatic)
  double merge_tol;  // coplanar merging tolerance / bounding-box diagonal (< 0: off)
  double wall_E, wall_nu, wall_e, wall_mu;    // < 0: the particle type's
  double wall_mur;    // rolling friction mu_r (< 0: the particle type's like pair's)
  double wall_coh;    // dry cohesion (< 0: the particle type's like pair's)
  // liquid bridges of spheres: V_b, gamma, theta [deg] (V_b 0: none), the
  // viscous part's eta and s_min (eta 0: none)
  double wall_bridge[5];
  std::string servo_var;    // move servo: the target force's equal-style variable ("": a number)
  int servo_ivar;
  double core, patch_angle;
  int twosided;                       // keyword sides: both (1, default) or front (0)
  int twist;                          // keyword twist: torsional friction (polydem_contact_law.h)
  void servo_target();                // move servo: the target from its variable, if any
  double depth_warn, overlap_warn;    // warn beyond these x bounding radius, x particle volume
  double elapsed;    // time since the fix was defined (mesh motion)

  double **hist;     // per atom: nh values
  int nh;            // WALL_HIST_SIZE per part of the largest template (composites)
  // the law table (polydem_law_table.h), built in init: per particle type
  // (1..ntypes) the particle's E, nu, the wall's E, nu (polyhedra), k_n
  // (ellipsoids), mu and the damping law; core, twist, k_t / k_n and
  // gamma_t / gamma_n (ellipsoids, from pair_style ellipsoid)
  std::vector<polydem::LawEntry<double>> law_entries;
  polydem::LawTable<double> laws;
  int ellipsoids;    // the group's particles are ellipsoids
  double local[NVEC + 1], global[NVEC + 1];    // [NVEC]: energy
  int reduced;
  // kernel failure counts (overflow, degenerate, merged patches), near-list
  // overflows, triangles left out of the per-triangle record; contacts with
  // the centroid behind the side met, deeper than depth/warn, beyond overlap/warn
  static constexpr int NCOUNTS = 9;
  double counts_local[NCOUNTS], counts_reported[NCOUNTS];
  // contacts that begin, this call: count, largest V / V_p, depth / r,
  // wall energy / mass (at setup: initial overlaps, reported by setup())
  double fresh_local[4];
  void absorb(const polydem::WallTally<double> &t);
  void report_initial_overlaps();
  class PolyShapeLibrary *avec;
  std::unique_ptr<polydem::WallWorkspace<double>> ws;
  // near lists (keyword cache): entries per particle, skin / bounding radius;
  // per local atom, valid until the next reneighboring (plain fix; /kk has its own)
  int near_cap;
  double near_skin;
  std::vector<size_t> near_first;    // atom i's lists: near_first[i] .. near_first[i + 1] - 1
  std::vector<double> near_ref;
  std::vector<int> near_count, near_tri;
  std::vector<float> near_gap;
  std::vector<polydem::ShapeView<double>> views;    // the templates', per step
  bigint near_builds;    // lists built (statistics, this rank)
  bigint near_builds_all, near_overflows_all;    // all ranks, since the fix was defined (post_run)
  bigint near_lists_held;    // lists this rank holds (one per part of its particles in the group)
  bigint near_builds_run;    // near_builds at the start of the run
  // per-triangle forces (keyword pertriangle): force on each triangle this
  // step, this rank (3 per triangle, lab frame), and summed over ranks
  int pertri, tri_reduced;
  std::vector<double> tri_local, tri_global;
  std::vector<int> tri_touched;    // triangles with a nonzero row in tri_local (plain path)
  virtual void fetch_triangle_forces() {}    // /kk: device -> tri_local

  polydem::StlTransform parse_keywords(int narg, char **arg);
  polydem::MeshPose<double> mesh_pose() const;
  polydem::WallScene<double> scene() const;    // the mesh as the particles see it now
  polydem::ContactLaw<double> law_of(int type, int ishape, double s) const;
  void build_grid();
  void report_counts();
  void check_timestep();
  void check_mesh_step();
  virtual void compute_forces(bool update);
};

}    // namespace LAMMPS_NS

#endif
#endif
