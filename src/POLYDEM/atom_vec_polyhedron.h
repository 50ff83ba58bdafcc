/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - atom_style polyhedron: rigid convex polyhedra built from shape
   templates (polyhedral seed §2.1, §2.6). Per atom: template index, scale,
   quaternion, angular momentum/velocity, mass and bounding radius. Ghosts
   carry template index, scale, quaternion (and velocities), never vertices.
------------------------------------------------------------------------- */

#ifdef ATOM_CLASS
// clang-format off
AtomStyle(polyhedron,AtomVecPolyhedron);
// clang-format on
#else

#ifndef LMP_ATOM_VEC_POLYHEDRON_H
#define LMP_ATOM_VEC_POLYHEDRON_H

#include "atom_vec.h"

#include <memory>
#include <string>
#include <vector>

namespace polydem {
class PolyShapeTemplate;
}

namespace LAMMPS_NS {

class AtomVecPolyhedron : public AtomVec {
 public:
  AtomVecPolyhedron(class LAMMPS *);
  ~AtomVecPolyhedron() override;
  void process_args(int, char **) override;

  void grow_pointers() override;
  void create_atom_post(int) override;
  void data_atom_post(int) override;
  void data_vel(int, char **) override;
  // Velocities section: v and angmom of atom i must be finite (an overflowing
  // number such as 1e999 parses as inf); shared with atom_style polyhedron/kk
  static void check_data_vel(class Error *error, const double *v, const double *angmom);
  void pack_data_pre(int) override;
  void pack_data_post(int) override;
  void init() override;
  int property_atom(char *) override;
  void pack_property_atom(int, double *, int, int) override;

  // ---- shape templates (shared by every style of the package)
  int ntemplates() const { return (int) templates.size(); }
  const polydem::PolyShapeTemplate &shape(int i) const { return *templates[i]; }
  const std::string &shape_id(int i) const { return template_ids[i]; }
  int find_shape(const std::string &id) const;
  // add a template; 'record' is its serialised form, kept in the atom style's
  // arguments so that restart files carry the templates (see process_args)
  int add_shape(const std::string &id, std::unique_ptr<polydem::PolyShapeTemplate> t,
                const std::string &record);
  // incremented whenever templates change: styles refresh device copies
  int shape_version() const { return version; }

  // ---- per-atom helpers
  // set template and scale of atom i, keeping its density
  void set_shape_scale(int i, int ishape, double scale);
  // principal moments of atom i (body frame): I_k = m s^2 J_k / V
  void inertia(int i, double *moments) const;
  bool mass_is_normal(int i) const;    // mass in (0, 1e250], moments normal
  void check_dimension();              // error unless 3-d
  void check_inserting_fixes();        // error for fix pour, fix deposit
  double density(int i) const;

 private:
  double *radius, *rmass;
  double **omega, **angmom, **quat;
  int *pshape;
  double *pscale;

  std::vector<std::unique_ptr<polydem::PolyShapeTemplate>> templates;
  std::vector<std::string> template_ids;
  int version;

  int pshape_one;
  double rmass_one;
};

}    // namespace LAMMPS_NS

#endif
#endif
