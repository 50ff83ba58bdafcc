/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - the shape-template library of atom_style polyhedron, and the
   per-atom semantics of that style (seed §2.1, §2.6).

   atom_style polyhedron and polyhedron/kk each own one (composition: the
   two AtomVecs share this code, not a base class) and forward their hooks
   here: field lists, shape records of a restart, create_atoms and
   read_data defaults and checks, write_data, compute property/atom. Every
   other style of the package reaches the library through
   PolyShapeLibrary::of(lmp, who).

   The per-atom helpers read and write the host arrays of Atom (rmass,
   radius, pshape, pscale, quat, ...); with KOKKOS the caller syncs them.
------------------------------------------------------------------------- */

#ifndef LMP_POLY_SHAPE_LIBRARY_H
#define LMP_POLY_SHAPE_LIBRARY_H

#include "pointers.h"

#include <memory>
#include <string>
#include <vector>

namespace polydem {
class PolyShapeTemplate;
template <typename T> struct ShapeView;
}

namespace LAMMPS_NS {

class PolyShapeLibrary : protected Pointers {
 public:
  // 'owner' is the atom style whose arguments carry the shape records
  PolyShapeLibrary(class LAMMPS *, class AtomVec *owner);
  ~PolyShapeLibrary() override;

  // the library of the current atom style; error "WHO requires atom_style
  // polyhedron" when the atom style is another one
  static PolyShapeLibrary *of(class LAMMPS *, const std::string &who);

  // ---- shape templates (shared by every style of the package)
  int ntemplates() const { return (int) templates.size(); }
  const polydem::PolyShapeTemplate &shape(int i) const { return *templates[i]; }
  const std::string &shape_id(int i) const { return template_ids[i]; }
  // its serialised form (polydem_shape_record.h), as stored in restart files
  const std::string &shape_record(int i) const { return template_records[i]; }
  // largest part count of the templates (1: none is a composite)
  int max_parts() const;
  int find_shape(const std::string &id) const;
  // add a template; 'record' is its serialised form, kept in the atom style's
  // arguments so that restart files carry the templates (see process_args)
  int add_shape(const std::string &id, std::unique_ptr<polydem::PolyShapeTemplate> t,
                const std::string &record);
  // incremented whenever templates change: styles refresh device copies
  int shape_version() const { return version; }
  // every template's view, by template index (a style's loop over atoms
  // takes them from here rather than building one per atom or pair)
  void views(std::vector<polydem::ShapeView<double>> &out) const;

  // ---- per-atom helpers
  // set template and scale of atom i, keeping its density
  void set_shape_scale(int i, int ishape, double scale);
  // principal moments of atom i (body frame): I_k = m s^2 J_k / V
  void inertia(int i, double *moments) const;
  bool mass_is_normal(int i) const;    // mass in (0, 1e250], moments normal
  // the same for a particle of template ishape, mass and scale (insertion)
  bool mass_is_normal(int ishape, double mass, double scale) const;
  double density(int i) const;
  void check_dimension();              // error unless 3-d
  void check_inserting_fixes();        // error for fix pour, fix deposit

  // ---- the atom style's hooks (AtomVecPolyhedron and AtomVecPolyhedronKokkos)
  void setup_style();    // flags and field lists of the owner (its constructor)
  void process_args(int, char **);
  void init();
  void create_atom_post(int);
  void data_atom_post(int);
  void check_data_vel(int);    // after AtomVec::data_vel
  void pack_data_pre(int);
  void pack_data_post(int);
  static int property_atom(const std::string &);
  void pack_property_atom(int, double *, int, int);

 private:
  class AtomVec *owner;
  std::vector<std::unique_ptr<polydem::PolyShapeTemplate>> templates;
  std::vector<std::string> template_ids, template_records;
  int version;

  int pshape_one;    // atom values swapped out by pack_data_pre
  double rmass_one;
};

// The role of the package's atom styles (plain and /kk) for every other
// style: the owner of the shape library, found by PolyShapeLibrary::of()
// without naming the atom style classes.
class ShapeLibraryOwner {
 public:
  virtual PolyShapeLibrary *shape_library() = 0;

 protected:
  ~ShapeLibraryOwner() = default;
};

}    // namespace LAMMPS_NS

#endif
