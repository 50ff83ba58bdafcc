/* ----------------------------------------------------------------------
   POLYDEM - shape-template records for restart files.

   A record holds the points exactly as they entered the hull computation
   (after the file's own scale), printed with 17 significant digits, which
   round-trips IEEE doubles exactly, plus the hull option. Rebuilding from
   the same points runs the same deterministic processing, so the rebuilt
   template equals the original bit for bit.
   Format: "polydem-shape-1 <hull 0|1> <name> <npoints> x y z x y z ..."
   Ellipsoids: "polydem-ellipsoid-1 <name> a b c" (semi-axes, 17 digits).
   Composites: "polydem-composite-1 <name> <nparts>" and per part
   " <id> x y z qw qx qy qz <length> <the part's record>".
------------------------------------------------------------------------- */

#include "polydem_shape_record.h"

#include "polydem_shape_template.h"
#include "polydem_stl.h"

#include <cstdio>
#include <sstream>

namespace polydem {

static const char *RECORD_TAG = "polydem-shape-1";

static const char *ELLIPSOID_TAG = "polydem-ellipsoid-1";

static const char *COMPOSITE_TAG = "polydem-composite-1";

static std::string record_name(std::string name)
{
  for (char &c : name)
    if (c == ' ' || c == '\t' || c == '\n') c = '_';
  if (name.empty()) name = "shape";
  return name;
}

static std::string make_record(const PolyShapeTemplate &t, bool hull)
{
  const std::string name = record_name(t.name());
  const auto &pts = t.input_points();
  std::string rec = std::string(RECORD_TAG) + " " + (hull ? "1" : "0") + " " + name + " " +
      std::to_string(pts.size());
  char buf[32];
  for (const auto &p : pts)
    for (int k = 0; k < 3; k++) {
      snprintf(buf, sizeof(buf), " %.17g", p[k]);
      rec += buf;
    }
  return rec;
}

std::unique_ptr<PolyShapeTemplate> shape_from_file(const std::string &file, bool hull,
                                                   std::string &record,
                                                   std::vector<std::string> &warnings,
                                                   std::string &err)
{
  try {
    ShapeOptions opt;
    opt.hull = hull;
    auto t = std::make_unique<PolyShapeTemplate>(PolyShapeTemplate::from_file(file, opt));
    warnings = t->warnings();
    record = make_record(*t, hull);
    return t;
  } catch (std::exception &e) {
    err = e.what();
    return nullptr;
  }
}

std::unique_ptr<PolyShapeTemplate> shape_ellipsoid(double a, double b, double c,
                                                   const std::string &name, std::string &record,
                                                   std::string &err)
{
  try {
    auto t = std::make_unique<PolyShapeTemplate>(
        PolyShapeTemplate::ellipsoid(a, b, c, record_name(name)));
    char buf[96];
    snprintf(buf, sizeof(buf), " %.17g %.17g %.17g", a, b, c);
    record = std::string(ELLIPSOID_TAG) + " " + t->name() + buf;
    return t;
  } catch (std::exception &e) {
    err = e.what();
    return nullptr;
  }
}

std::unique_ptr<PolyShapeTemplate> shape_composite(const std::vector<CompositePartRecord> &parts,
                                                   const std::string &name, std::string &record,
                                                   std::string &err)
{
  std::vector<PolyShapeTemplate::InputPart> in;
  std::string rec = std::string(COMPOSITE_TAG) + " " + record_name(name) + " " +
      std::to_string(parts.size());
  char buf[256];
  for (const auto &p : parts) {
    auto t = shape_from_record(p.record, err);
    if (!t) {
      err = name + ": part '" + p.id + "': " + err;
      return nullptr;
    }
    PolyShapeTemplate::InputPart ip;
    ip.shape = std::move(t);
    ip.id = p.id;
    ip.x = {p.x[0], p.x[1], p.x[2]};
    ip.q = make_quat(p.q[0], p.q[1], p.q[2], p.q[3]);
    in.push_back(std::move(ip));
    snprintf(buf, sizeof(buf), " %.17g %.17g %.17g %.17g %.17g %.17g %.17g", p.x[0], p.x[1],
             p.x[2], p.q[0], p.q[1], p.q[2], p.q[3]);
    rec += " " + record_name(p.id) + buf + " " + std::to_string(p.record.size()) + " " + p.record;
  }
  try {
    auto t = std::make_unique<PolyShapeTemplate>(PolyShapeTemplate::composite(in, record_name(name)));
    record = rec;
    return t;
  } catch (std::exception &e) {
    err = e.what();
    return nullptr;
  }
}

std::unique_ptr<PolyShapeTemplate> shape_composite_from_surface(const std::string &file,
                                                                double scale,
                                                                const std::string &name,
                                                                std::string &record,
                                                                std::string &err)
{
  try {
    StlTransform xf;
    xf.scale = scale;
    const StlMesh mesh = read_stl(file, xf);
    const auto pieces = PolyShapeTemplate::convex_pieces(mesh.tri, file);
    std::vector<CompositePartRecord> parts;
    ShapeOptions opt;
    opt.hull = true;    // corners on a piece's edges or faces are not vertices
    for (size_t k = 0; k < pieces.size(); ++k) {
      const std::string id = "piece" + std::to_string(k + 1);
      const auto t = PolyShapeTemplate::from_points(pieces[k], {}, opt, name + "_" + id);
      CompositePartRecord p;
      p.id = id;
      p.record = make_record(t, true);
      const auto c = t.input_centroid();
      const auto q = t.input_orientation();
      for (int i = 0; i < 3; ++i) p.x[i] = c[i];
      p.q[0] = q.w;
      p.q[1] = q.x;
      p.q[2] = q.y;
      p.q[3] = q.z;
      parts.push_back(p);
    }
    if ((int) parts.size() > MAX_COMPOSITE_PARTS) {
      err = file + ": its convex decomposition has " + std::to_string(parts.size()) +
          " pieces, more than a composite's " + std::to_string(MAX_COMPOSITE_PARTS) +
          " parts (simplify the surface)";
      return nullptr;
    }
    return shape_composite(parts, name, record, err);
  } catch (std::exception &e) {
    err = e.what();
    return nullptr;
  }
}

static std::unique_ptr<PolyShapeTemplate> composite_from_record(std::istringstream &in,
                                                                std::string &err)
{
  std::string tag, name;
  long n = 0;
  if (!(in >> tag >> name >> n) || tag != COMPOSITE_TAG || n < 1 || n > MAX_COMPOSITE_PARTS) {
    err = "not a POLYDEM composite record";
    return nullptr;
  }
  std::vector<CompositePartRecord> parts((size_t) n);
  for (auto &p : parts) {
    std::string tok[7];
    long len = 0;
    if (!(in >> p.id >> tok[0] >> tok[1] >> tok[2] >> tok[3] >> tok[4] >> tok[5] >> tok[6] >>
          len) ||
        len < 1 || len > 100000000L || in.get() != ' ') {
      err = "composite record truncated";
      return nullptr;
    }
    for (int k = 0; k < 3; k++) p.x[k] = std::strtod(tok[k].c_str(), nullptr);
    for (int k = 0; k < 4; k++) p.q[k] = std::strtod(tok[3 + k].c_str(), nullptr);
    p.record.resize((size_t) len);
    if (!in.read(&p.record[0], len)) {
      err = "composite record truncated";
      return nullptr;
    }
  }
  std::string rec;
  return shape_composite(parts, name, rec, err);
}

std::unique_ptr<PolyShapeTemplate> shape_from_record(const std::string &record, std::string &err)
{
  std::istringstream in(record);
  if (record.rfind(COMPOSITE_TAG, 0) == 0) return composite_from_record(in, err);
  if (record.rfind(ELLIPSOID_TAG, 0) == 0) {
    std::string tag, name, tok[3];
    if (!(in >> tag >> name >> tok[0] >> tok[1] >> tok[2]) || tag != ELLIPSOID_TAG) {
      err = "not a POLYDEM ellipsoid record";
      return nullptr;
    }
    double ax[3];
    for (int k = 0; k < 3; k++) ax[k] = std::strtod(tok[k].c_str(), nullptr);
    std::string rec;
    return shape_ellipsoid(ax[0], ax[1], ax[2], name, rec, err);
  }
  std::string tag, name;
  int hull = 0;
  long n = 0;
  if (!(in >> tag >> hull >> name >> n) || tag != RECORD_TAG || n < 4 || n > 1000000) {
    err = "not a POLYDEM shape record";
    return nullptr;
  }
  std::vector<PolyShapeTemplate::Point> pts((size_t) n);
  for (auto &p : pts)
    for (int k = 0; k < 3; k++) {
      std::string tok;
      if (!(in >> tok)) {
        err = "record truncated";
        return nullptr;
      }
      p[k] = std::strtod(tok.c_str(), nullptr);
    }
  try {
    ShapeOptions opt;
    opt.hull = hull != 0;
    return std::make_unique<PolyShapeTemplate>(
        PolyShapeTemplate::from_points(pts, {}, opt, name));
  } catch (std::exception &e) {
    err = e.what();
    return nullptr;
  }
}

}    // namespace polydem
