/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - helpers shared by the shape template's host sources
   (polydem_shape_*.cpp): numbers in messages and the long double vector
   arithmetic of the hull, the principal frame and the face planes.
   Internal: included by those .cpp files only, never by other headers.
------------------------------------------------------------------------- */

#ifndef POLYDEM_SHAPE_TEMPLATE_IMPL_H
#define POLYDEM_SHAPE_TEMPLATE_IMPL_H

#include "polydem_shape_template.h"

#include <array>
#include <cmath>
#include <cstddef>
#include <sstream>
#include <string>
#include <vector>

namespace polydem {
namespace shape_impl {

  using Pt = PolyShapeTemplate::Point;

  inline std::string fmt_num(double x)
  {
    std::ostringstream os;
    os.precision(17);
    os << x;
    return os.str();
  }

  using V3 = std::array<long double, 3>;
  inline V3 vcross(const V3 &a, const V3 &b)
  {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  }
  inline long double vdot(const V3 &a, const V3 &b)
  {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  }
  inline V3 vunit(const V3 &a)
  {
    long double n = std::sqrt(vdot(a, a));
    return {a[0] / n, a[1] / n, a[2] / n};
  }

  inline V3 vsub(const Pt &a, const Pt &b)
  {
    return {(long double) a[0] - b[0], (long double) a[1] - b[1], (long double) a[2] - b[2]};
  }

  // Newell normal (area-weighted, not normalised) of a vertex loop.
  inline V3 newell(const std::vector<Pt> &v, const std::vector<int> &loop)
  {
    V3 n = {0, 0, 0};
    for (size_t i = 0; i < loop.size(); ++i) {
      const Pt &a = v[loop[i]], &b = v[loop[(i + 1) % loop.size()]];
      n[0] += ((long double) a[1] - b[1]) * ((long double) a[2] + b[2]);
      n[1] += ((long double) a[2] - b[2]) * ((long double) a[0] + b[0]);
      n[2] += ((long double) a[0] - b[0]) * ((long double) a[1] + b[1]);
    }
    return n;
  }

  // Principal axes of an inertia tensor as the columns of R (a proper
  // rotation), moments ascending; degenerate moments keep the input axes
  // (polydem_shape_mass.cpp).
  void principal_axes(const double inertia[3][3], double R[3][3]);
  // a proper rotation matrix as a unit quaternion (w >= 0; Shepperd's method)
  Quat<double> rotation_quat(const std::array<std::array<double, 3>, 3> &m);

}    // namespace shape_impl
}    // namespace polydem

#endif
