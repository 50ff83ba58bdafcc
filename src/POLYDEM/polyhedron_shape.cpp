/* ----------------------------------------------------------------------
   POLYDEM - command polyhedron_shape
------------------------------------------------------------------------- */

#include "polyhedron_shape.h"

#include "atom.h"
#include "atom_vec_polyhedron.h"
#include "comm.h"
#include "error.h"
#include "polydem_shape_record.h"
#include "polydem_shape_template.h"

#include <cstring>

using namespace LAMMPS_NS;

/* ----------------------------------------------------------------------
   polyhedron_shape ID file [hull yes|no]
   Every rank parses the file itself (templates are small); errors are
   identical on all ranks, so error->all is safe.
------------------------------------------------------------------------- */

void PolyhedronShape::command(int narg, char **arg)
{
  if (narg < 2) error->all(FLERR, "Illegal polyhedron_shape command: expected ID and file");
  auto avec = dynamic_cast<AtomVecPolyhedron *>(atom->avec);
  if (!avec) error->all(FLERR, "polyhedron_shape requires atom_style polyhedron");

  const std::string id = arg[0];
  if (id.empty() || !utils::is_id(id))
    error->all(FLERR, "polyhedron_shape: shape ID '{}' must be alphanumeric or underscore", id);
  const std::string file = arg[1];

  bool hull = false;
  for (int iarg = 2; iarg < narg; iarg += 2) {
    if (strcmp(arg[iarg], "hull") == 0) {
      if (iarg + 1 >= narg) error->all(FLERR, "polyhedron_shape: keyword 'hull' needs yes or no");
      const std::string v = arg[iarg + 1];
      if (v == "yes") hull = true;
      else if (v == "no") hull = false;
      else error->all(FLERR, "polyhedron_shape: keyword 'hull' needs yes or no, got '{}'", v);
    } else
      error->all(FLERR, "polyhedron_shape: unknown keyword '{}'", arg[iarg]);
  }

  std::string err, record;
  std::vector<std::string> warnings;
  auto t = polydem::shape_from_file(file, hull, record, warnings, err);
  if (!t) error->all(FLERR, "polyhedron_shape: {}", err);
  for (const auto &w : warnings)
    if (comm->me == 0) error->warning(FLERR, "polyhedron_shape: {}", w);

  const auto v = t->view();
  const int index = avec->add_shape(id, std::move(t), record);
  if (comm->me == 0)
    utils::logmesg(lmp,
                   "polyhedron_shape {} (index {}): {} vertices, {} faces, {} edges, "
                   "volume {:.10g}, bounding radius {:.10g}, principal moments/density "
                   "{:.10g} {:.10g} {:.10g}\n",
                   id, index + 1, v.nverts, v.nfaces, v.nedges, v.volume, v.radius,
                   v.inertia[0], v.inertia[1], v.inertia[2]);
}
