/* ----------------------------------------------------------------------
   POLYDEM - fix wall/mesh: its keywords (doc/fix_wall_mesh.rst)
------------------------------------------------------------------------- */

#include "fix_wall_mesh.h"

#include "error.h"
#include "math_const.h"
#include "polydem_parse.h"

#include <cmath>
#include <cstring>
#include <string>

using namespace LAMMPS_NS;
using MathConst::MY_PI;

/* ----------------------------------------------------------------------
   fix ID group wall/mesh file.stl keyword value ...: the keywords after the
   file name set the fix's settings and the mesh's motion; returns the
   load-time transform of the file (scale, rotate, offset, flip)
------------------------------------------------------------------------- */

polydem::StlTransform FixWallMesh::parse_keywords(int narg, char **arg)
{
  auto &motion = geom.motion;
  polydem::StlTransform xf;
  double rot_angle = 0.0, rot_axis[3] = {0.0, 0.0, 1.0};
  auto need = [&](int iarg, int n, const char *what) {
    if (iarg + n >= narg)
      error->all(FLERR, "fix wall/mesh: keyword '{}' needs {} value(s): {}", arg[iarg], n, what);
  };
  // numbers must be finite (1e400 parses as inf)
  auto num = [&](int k) {
    const double v = polydem_parse::numeric(FLERR, arg[k], lmp);
    if (!std::isfinite(v))
      error->all(FLERR, "fix wall/mesh: '{}' (argument {}) is not a finite number", arg[k], k + 1);
    return v;
  };
  // length of a vector of finite values, scaled so that it cannot overflow
  auto length = [](const double *a) {
    const double m = MAX(fabs(a[0]), MAX(fabs(a[1]), fabs(a[2])));
    if (!(m > 0.0)) return 0.0;
    return m * sqrt((a[0] / m) * (a[0] / m) + (a[1] / m) * (a[1] / m) + (a[2] / m) * (a[2] / m));
  };
  // the keywords of one number in a range: (lo, hi) open or closed at each end
  struct NumberKeyword {
    const char *name, *what;
    double *value;
    double lo, hi;
    bool lo_closed, hi_closed;
  };
  const double inf = HUGE_VAL;
  const NumberKeyword numbers[] = {
      {"scale", "s", &xf.scale, 0.0, inf, false, false},
      {"depth/warn", "fraction of the bounding radius", &depth_warn, 0.0, 2.0, false, true},
      {"overlap/warn", "fraction of the particle volume", &overlap_warn, 0.0, 1.0, false, true},
      {"youngs", "E", &wall_E, 0.0, inf, false, false},
      {"poisson", "nu", &wall_nu, -1.0, 0.5, false, false},
      {"restitution", "e", &wall_e, 0.0, 1.0, false, true},
      {"friction", "mu", &wall_mu, 0.0, inf, true, false},
      {"rolling", "mu_r", &wall_mur, 0.0, inf, true, false},
      {"cohesion", "k_c or Gamma", &wall_coh, 0.0, inf, true, false},
      {"core", "fraction", &core, 0.0, 1.0, true, false},
      {"patch/angle", "degrees", &patch_angle, 0.0, 90.0, true, false},
      {"bin", "edge length", &binsize, 0.0, inf, false, false},
      {"cache/skin", "skin / particle bounding radius", &near_skin, 0.0, 1.0, false, true}};
  auto number_keyword = [&](const std::string &kw, int iarg) {
    for (const auto &k : numbers) {
      if (kw != k.name) continue;
      need(iarg, 1, k.what);
      const double v = num(iarg + 1);
      const bool above = k.lo_closed ? v >= k.lo : v > k.lo;
      const bool below = k.hi_closed ? v <= k.hi : v < k.hi;
      if (!above || !below) {
        if (k.hi == inf)
          error->all(FLERR, "fix wall/mesh: {} must be {} {}, got '{}'", k.name,
                     k.lo_closed ? ">=" : ">", k.lo, arg[iarg + 1]);
        error->all(FLERR, "fix wall/mesh: {} must be in {}{}, {}{}, got '{}'", k.name,
                   k.lo_closed ? "[" : "(", k.lo, k.hi, k.hi_closed ? "]" : ")", arg[iarg + 1]);
      }
      *k.value = v;
      return true;
    }
    return false;
  };
  // a keyword of two words: true for the first
  auto choice = [&](int iarg, const char *first, const char *second) {
    need(iarg, 1, (std::string(first) + " or " + second).c_str());
    return polydem_parse::choice(FLERR, lmp, "fix wall/mesh", arg[iarg], arg[iarg + 1], first,
                                 second);
  };
  int iarg = 4;
  while (iarg < narg) {
    const std::string kw = arg[iarg];
    if (number_keyword(kw, iarg)) {
      iarg += 2;
    } else if (kw == "bridge") {
      need(iarg, 3, "V_b gamma theta(degrees)");
      for (int k = 0; k < 3; k++) wall_bridge[k] = num(iarg + 1 + k);
      if (!(wall_bridge[0] >= 0.0) || !(wall_bridge[1] > 0.0) ||
          !(wall_bridge[2] >= 0.0 && wall_bridge[2] < 90.0))
        error->all(FLERR, "fix wall/mesh: bridge needs V_b >= 0 (0: none), gamma > 0 and theta "
                   "in [0, 90) degrees, got '{} {} {}'", arg[iarg + 1], arg[iarg + 2],
                   arg[iarg + 3]);
      iarg += 4;
    } else if (kw == "viscous") {
      need(iarg, 2, "eta s_min");
      for (int k = 0; k < 2; k++) wall_bridge[3 + k] = num(iarg + 1 + k);
      if (!(wall_bridge[3] > 0.0) || !(wall_bridge[4] > 0.0))
        error->all(FLERR, "fix wall/mesh: viscous needs the liquid's viscosity eta > 0 and the "
                   "smallest gap s_min > 0, got '{} {}'", arg[iarg + 1], arg[iarg + 2]);
      iarg += 3;
    } else if (kw == "offset") {
      need(iarg, 3, "dx dy dz");
      for (int k = 0; k < 3; k++) xf.offset[k] = num(iarg + 1 + k);
      iarg += 4;
    } else if (kw == "rotate") {
      need(iarg, 4, "angle(degrees) ax ay az");
      rot_angle = num(iarg + 1);
      for (int k = 0; k < 3; k++) rot_axis[k] = num(iarg + 2 + k);
      iarg += 5;
    } else if (kw == "flip") {
      xf.flip = choice(iarg, "yes", "no");
      iarg += 2;
    } else if (kw == "twist") {
      twist = choice(iarg, "yes", "no");
      iarg += 2;
    } else if (kw == "sides") {
      twosided = choice(iarg, "both", "front");
      iarg += 2;
    } else if (kw == "pertriangle") {
      pertri = choice(iarg, "yes", "no");
      iarg += 2;
    } else if (kw == "cache") {
      need(iarg, 1, "entries per particle (0: off)");
      const double c = num(iarg + 1);
      if (!(c >= 0.0 && c <= 100000.0) || c != floor(c))
        error->all(FLERR, "fix wall/mesh: cache must be an integer in [0, 100000], got '{}'",
                   arg[iarg + 1]);
      near_cap = (int) c;
      iarg += 2;
    } else if (kw == "merge") {
      need(iarg, 1, "no or a tolerance");
      if (strcmp(arg[iarg + 1], "no") == 0) merge_tol = -1.0;
      else {
        merge_tol = num(iarg + 1);
        if (!(merge_tol >= 0.0 && merge_tol < 1e-3))
          error->all(FLERR, "fix wall/mesh: merge must be 'no' or a tolerance in [0, 1e-3), "
                     "got '{}'", arg[iarg + 1]);
      }
      iarg += 2;
    } else if (kw == "move") {
      need(iarg, 1, "none, translate, rotate, wiggle or servo");
      const std::string m = arg[iarg + 1];
      if (m == "none") {
        motion.style = polydem::MeshMotion::NONE;
        iarg += 2;
      } else if (m == "translate") {
        need(iarg + 1, 3, "vx vy vz");
        motion.style = polydem::MeshMotion::TRANSLATE;
        for (int k = 0; k < 3; k++) motion.vel[k] = num(iarg + 2 + k);
        iarg += 5;
      } else if (m == "wiggle") {
        need(iarg + 1, 4, "Ax Ay Az motion.period");
        motion.style = polydem::MeshMotion::WIGGLE;
        for (int k = 0; k < 3; k++) motion.amp[k] = num(iarg + 2 + k);
        motion.period = num(iarg + 5);
        if (!(motion.period > 0.0) || !std::isfinite(2.0 * MY_PI / motion.period))
          error->all(FLERR, "fix wall/mesh: move wiggle period must be > 0, got '{}'", arg[iarg + 5]);
        for (int k = 0; k < 3; k++)
          if (!std::isfinite(motion.amp[k]))
            error->all(FLERR, "fix wall/mesh: move wiggle amplitude must be finite, got '{}'",
                       arg[iarg + 2 + k]);
        iarg += 6;
      } else if (m == "servo") {
        need(iarg + 1, 6, "ax ay az force vmax gain");
        motion.style = polydem::MeshMotion::SERVO;
        for (int k = 0; k < 3; k++) motion.dir[k] = num(iarg + 2 + k);
        const double l = length(motion.dir);
        if (!(l > 0.0)) error->all(FLERR, "fix wall/mesh: move servo direction must be non-zero");
        for (int k = 0; k < 3; k++) motion.dir[k] /= l;
        if (strncmp(arg[iarg + 5], "v_", 2) == 0 && arg[iarg + 5][2] != '\0')
          servo_var = arg[iarg + 5] + 2;    // evaluated every step (a load program)
        else
          motion.target = num(iarg + 5);
        motion.vmax = num(iarg + 6);
        motion.gain = num(iarg + 7);
        if (!(motion.vmax > 0.0))
          error->all(FLERR, "fix wall/mesh: move servo vmax must be > 0, got '{}'", arg[iarg + 6]);
        if (!(motion.gain > 0.0))
          error->all(FLERR, "fix wall/mesh: move servo gain must be > 0, got '{}'", arg[iarg + 7]);
        motion.s = motion.v = 0.0;
        iarg += 8;
      } else if (m == "rotate") {
        need(iarg + 1, 8, "ox oy oz ax ay az omega|rpm value");
        motion.style = polydem::MeshMotion::ROTATE;
        for (int k = 0; k < 3; k++) motion.origin[k] = num(iarg + 2 + k);
        for (int k = 0; k < 3; k++) motion.axis[k] = num(iarg + 5 + k);
        const std::string u = arg[iarg + 8];
        const double val = num(iarg + 9);
        if (u == "omega") motion.omega = val;
        else if (u == "rpm") motion.omega = val * 2.0 * MY_PI / 60.0;
        else
          error->all(FLERR, "fix wall/mesh: move rotate expects 'omega' or 'rpm', got '{}'", u);
        if (!std::isfinite(motion.omega))
          error->all(FLERR, "fix wall/mesh: move rotate {} {} is not a finite rate", u, val);
        const double l = length(motion.axis);
        if (!(l > 0.0)) error->all(FLERR, "fix wall/mesh: move rotate axis must be non-zero");
        for (int k = 0; k < 3; k++) motion.axis[k] /= l;
        iarg += 10;
      } else
        error->all(FLERR, "fix wall/mesh: unknown move style '{}' (none, translate, rotate, "
                   "wiggle, servo)", m);
    } else
      error->all(FLERR, "fix wall/mesh: unknown keyword '{}'", kw);
  }
  if (wall_bridge[3] > 0.0 && !(wall_bridge[0] > 0.0))
    error->all(FLERR, "fix wall/mesh: 'viscous eta s_min' is the viscous part of a liquid "
               "bridge; give 'bridge V_b gamma theta' with it");

  // load-time rotation (Rodrigues), applied after the scale
  {
    const double l = length(rot_axis);
    if (!(l > 0.0)) error->all(FLERR, "fix wall/mesh: rotate axis must be non-zero");
    const double c = cos(rot_angle * MY_PI / 180.0), s = sin(rot_angle * MY_PI / 180.0);
    const double u[3] = {rot_axis[0] / l, rot_axis[1] / l, rot_axis[2] / l};
    for (int i = 0; i < 3; i++)
      for (int j = 0; j < 3; j++) xf.R[i][j] = (i == j ? c : 0.0) + (1.0 - c) * u[i] * u[j];
    xf.R[0][1] -= s * u[2];
    xf.R[0][2] += s * u[1];
    xf.R[1][0] += s * u[2];
    xf.R[1][2] -= s * u[0];
    xf.R[2][0] -= s * u[1];
    xf.R[2][1] += s * u[0];
  }
  return xf;
}
