/* ----------------------------------------------------------------------
   POLYDEM - command polyhedron_shape
------------------------------------------------------------------------- */

#include "polyhedron_shape.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "poly_shape_library.h"
#include "polydem_parse.h"
#include "polydem_shape_record.h"
#include "polydem_shape_template.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;

/* ----------------------------------------------------------------------
   polyhedron_shape ID file [hull yes|no]
   polyhedron_shape ID ellipsoid a b c
   polyhedron_shape ID composite part SHAPE x y z [quat w i j k] part ...
   polyhedron_shape ID composite FILE.stl [scale s]
   Every rank parses the file itself (templates are small); errors are
   identical on all ranks, so error->all is safe.
------------------------------------------------------------------------- */

void PolyhedronShape::command(int narg, char **arg)
{
  if (narg < 2) error->all(FLERR, "Illegal polyhedron_shape command: expected ID and file");
  auto avec = PolyShapeLibrary::of(lmp, "polyhedron_shape");
  avec->check_dimension();

  const std::string id = arg[0];
  if (id.empty() || !utils::is_id(id))
    error->all(FLERR, "polyhedron_shape: shape ID '{}' must be alphanumeric or underscore", id);
  // polyhedron_shape ID ellipsoid a b c
  if (strcmp(arg[1], "ellipsoid") == 0) {
    if (narg != 5)
      error->all(FLERR, "polyhedron_shape {} ellipsoid: expected 3 semi-axes a b c, got {} "
                 "values", id, narg - 2);
    double ax[3];
    for (int k = 0; k < 3; k++) {
      ax[k] = polydem_parse::number(FLERR, arg[2 + k], lmp, "polyhedron_shape " + id + " ellipsoid");
      if (!(ax[k] > 0.0) || !std::isfinite(ax[k]))
        error->all(FLERR, "polyhedron_shape {} ellipsoid: semi-axis {} must be > 0, got '{}'",
                   id, "abc"[k], arg[2 + k]);
    }
    std::string err, record;
    auto t = polydem::shape_ellipsoid(ax[0], ax[1], ax[2], id, record, err);
    if (!t) error->all(FLERR, "polyhedron_shape: {}", err);
    const std::string what = fmt::format("ellipsoid, semi-axes {:.10g} {:.10g} {:.10g}, volume "
                                         "{:.10g}", ax[0], ax[1], ax[2], t->view().volume);
    add(id, std::move(t), record, what);
    return;
  }

  if (strcmp(arg[1], "composite") == 0) {
    composite(id, narg - 2, arg + 2);
    return;
  }

  const std::string file = arg[1];

  bool hull = false;
  for (int iarg = 2; iarg < narg; iarg += 2) {
    if (strcmp(arg[iarg], "hull") == 0) {
      hull = polydem_parse::choice(FLERR, lmp, "polyhedron_shape", "hull",
                                   iarg + 1 < narg ? arg[iarg + 1] : nullptr, "yes", "no");
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
  add(id, std::move(t), record,
      fmt::format("{} vertices, {} faces, {} edges, volume {:.10g}, bounding radius {:.10g}",
                  v.nverts, v.nfaces, v.nedges, v.volume, v.radius));
}

// registers the template t as shape `id` and logs its index, `what` (its
// description) and its principal moments
void PolyhedronShape::add(const std::string &id, std::unique_ptr<polydem::PolyShapeTemplate> t,
                          const std::string &record, const std::string &what)
{
  const auto v = t->view();
  auto avec = PolyShapeLibrary::of(lmp, "polyhedron_shape");
  const int index = avec->add_shape(id, std::move(t), record);
  if (comm->me == 0)
    utils::logmesg(lmp,
                   "polyhedron_shape {} (index {}): {}, principal moments/density {:.10g} "
                   "{:.10g} {:.10g}\n",
                   id, index + 1, what, v.inertia[0], v.inertia[1], v.inertia[2]);
}

/* ----------------------------------------------------------------------
   polyhedron_shape ID composite part SHAPE x y z [quat w i j k] part ...
   SHAPE: a convex template defined before (polyhedron or ellipsoid);
   x y z: its centroid, quat: its orientation, in the composite's frame
------------------------------------------------------------------------- */

void PolyhedronShape::composite(const std::string &id, int narg, char **arg)
{
  auto avec = PolyShapeLibrary::of(lmp, "polyhedron_shape");
  const std::string me = "polyhedron_shape " + id + " composite";
  std::vector<polydem::CompositePartRecord> parts;
  std::string err, record;
  std::unique_ptr<polydem::PolyShapeTemplate> t;
  std::string how;
  if (narg >= 1 && strcmp(arg[0], "part") != 0) {
    // polyhedron_shape ID composite FILE.stl [scale s]: its convex decomposition
    double scale = 1.0;
    if (narg == 3 && strcmp(arg[1], "scale") == 0) {
      scale = polydem_parse::number(FLERR, arg[2], lmp, me);
      if (!(scale > 0.0) || !std::isfinite(scale))
        error->all(FLERR, "{}: scale must be > 0, got '{}'", me, arg[2]);
    } else if (narg != 1)
      error->all(FLERR, "{}: expected 'FILE.stl [scale s]' or 'part SHAPE x y z ...', got '{}'",
                 me, arg[1]);
    t = polydem::shape_composite_from_surface(arg[0], scale, id, record, err);
    if (!t) error->all(FLERR, "polyhedron_shape: {}", err);
    how = fmt::format(" (convex decomposition of {})", arg[0]);
    add_composite(id, std::move(t), record, how);
    return;
  }
  int iarg = 0;
  while (iarg < narg) {
    if (strcmp(arg[iarg], "part") != 0)
      error->all(FLERR, "{}: expected 'part SHAPE x y z [quat w i j k]', got '{}'", me, arg[iarg]);
    if (iarg + 5 > narg)
      error->all(FLERR, "{}: 'part' needs a shape ID and a position x y z", me);
    const std::string pid = arg[iarg + 1];
    const int k = avec->find_shape(pid);
    if (k < 0)
      error->all(FLERR, "{}: part shape '{}' is not defined (define it with polyhedron_shape "
                 "first)", me, pid);
    if (avec->shape(k).is_composite())
      error->all(FLERR, "{}: part shape '{}' is a composite (parts are polyhedra or ellipsoids)",
                 me, pid);
    polydem::CompositePartRecord p;
    p.id = pid;
    p.record = avec->shape_record(k);
    for (int d = 0; d < 3; d++) p.x[d] = polydem_parse::number(FLERR, arg[iarg + 2 + d], lmp, me);
    p.q[0] = 1.0;
    p.q[1] = p.q[2] = p.q[3] = 0.0;
    iarg += 5;
    if (iarg < narg && strcmp(arg[iarg], "quat") == 0) {
      if (iarg + 5 > narg) error->all(FLERR, "{}: 'quat' needs 4 values w i j k", me);
      for (int d = 0; d < 4; d++) p.q[d] = polydem_parse::number(FLERR, arg[iarg + 1 + d], lmp, me);
      iarg += 5;
    }
    parts.push_back(p);
  }
  if (parts.empty()) error->all(FLERR, "{}: no parts (part SHAPE x y z [quat w i j k] ...)", me);
  if ((int) parts.size() > polydem::MAX_COMPOSITE_PARTS)
    error->all(FLERR, "{}: {} parts, at most {}", me, parts.size(), polydem::MAX_COMPOSITE_PARTS);

  t = polydem::shape_composite(parts, id, record, err);
  if (!t) error->all(FLERR, "polyhedron_shape: {}", err);
  add_composite(id, std::move(t), record, how);
}

void PolyhedronShape::add_composite(const std::string &id,
                                    std::unique_ptr<polydem::PolyShapeTemplate> t,
                                    const std::string &record, const std::string &how)
{
  for (const auto &w : t->warnings())
    if (comm->me == 0) error->warning(FLERR, "polyhedron_shape: {}", w);
  const auto v = t->view();
  const auto c = t->input_centroid();
  const std::string what = fmt::format(
      "composite of {} parts{}, volume {:.10g} ({:.10g} of the parts' sum), {} contact "
      "parts{}, centroid {:.10g} {:.10g} {:.10g}, bounding radius {:.10g}",
      t->input_parts().size(), how, v.volume, t->union_fraction(), v.nparts,
      t->decomposed() ? " (the convex pieces of the overlapping parts' union)" : "", c[0], c[1],
      c[2], v.radius);
  add(id, std::move(t), record, what);
}
