/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - loading shape templates for LAMMPS commands, and their exact
   text record (stored in restart files so that a restart needs no shape
   files and continues bit for bit). Host only; no LAMMPS includes.
------------------------------------------------------------------------- */

#ifndef POLYDEM_SHAPE_RECORD_H
#define POLYDEM_SHAPE_RECORD_H

#include <memory>
#include <string>
#include <vector>

namespace polydem {

class PolyShapeTemplate;

// Load a shape file. On failure returns nullptr and sets err (file:line: what).
std::unique_ptr<PolyShapeTemplate> shape_from_file(const std::string &file, bool hull,
                                                   std::string &record,
                                                   std::vector<std::string> &warnings,
                                                   std::string &err);

// An ellipsoid template with semi-axes a, b, c. On failure returns nullptr
// and sets err.
std::unique_ptr<PolyShapeTemplate> shape_ellipsoid(double a, double b, double c,
                                                   const std::string &name, std::string &record,
                                                   std::string &err);

// A part of a composite: its shape's record, its name in messages, its
// position and orientation (w, x, y, z) in the composite's input frame.
struct CompositePartRecord {
  std::string id, record;
  double x[3];
  double q[4];
};

// A composite template of the given parts (each rebuilt from its record).
// On failure returns nullptr and sets err.
std::unique_ptr<PolyShapeTemplate> shape_composite(const std::vector<CompositePartRecord> &parts,
                                                   const std::string &name, std::string &record,
                                                   std::string &err);

// A composite of the convex pieces of a closed non-convex surface (an STL
// file, scaled): CGAL's convex decomposition (PolyShapeTemplate::
// convex_pieces), each piece a part named "piece1", "piece2", ...; its
// record is a composite record (restart needs no file). On failure returns
// nullptr and sets err.
std::unique_ptr<PolyShapeTemplate> shape_composite_from_surface(const std::string &file,
                                                                double scale,
                                                                const std::string &name,
                                                                std::string &record,
                                                                std::string &err);

// Rebuild a template from its record, bit-identical to the one recorded.
std::unique_ptr<PolyShapeTemplate> shape_from_record(const std::string &record,
                                                     std::string &err);

}    // namespace polydem

#endif
