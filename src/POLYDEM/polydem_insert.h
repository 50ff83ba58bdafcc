/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - kernels of fix insert/polyhedron: a counter-free random
   generator whose whole state fits a restart file, the draws of a
   candidate (scale distributions, orientation uniform on SO(3)), and the
   exact rejection test of a posed polyhedron or ellipsoid against another
   one or a triangle (certified GJK distance bound, polydem_gjk.h).
   No LAMMPS includes (DESIGN.md 4.1); host code, device-safe where marked.
------------------------------------------------------------------------- */

#ifndef POLYDEM_INSERT_H
#define POLYDEM_INSERT_H

#include "polydem_gjk.h"

#include <cmath>
#include <cstdint>

namespace polydem {

// xoshiro256** (Blackman & Vigna, "Scrambled linear pseudorandom number
// generators", ACM TOMS 47, 2021), seeded through splitmix64 (Steele et al.
// 2014). Period 2^256 - 1; the state is four 64-bit words, so a restart
// carries it exactly (as eight 32-bit halves).
struct InsertRng {
  uint64_t s[4];

  static uint64_t splitmix(uint64_t &x)
  {
    uint64_t z = (x += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  void seed(uint64_t seed)
  {
    uint64_t x = seed;
    for (auto &w : s) w = splitmix(x);
  }
  static uint64_t rotl(uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
  uint64_t next()
  {
    const uint64_t r = rotl(s[1] * 5, 7) * 9;
    const uint64_t t = s[1] << 17;
    s[2] ^= s[0];
    s[3] ^= s[1];
    s[1] ^= s[2];
    s[0] ^= s[3];
    s[2] ^= t;
    s[3] = rotl(s[3], 45);
    return r;
  }
  // uniform in the open interval (0, 1): 53 random bits, offset by half a step
  double uniform() { return ((double) (next() >> 11) + 0.5) * 0x1.0p-53; }
  // standard normal by Box-Muller from two fresh uniforms (no cached value,
  // so the state is only s[])
  double normal()
  {
    const double u = uniform(), v = uniform();
    return sqrt(-2.0 * log(u)) * cos(2.0 * M_PI * v);
  }
};

// Scale distribution of one template (fix insert/polyhedron keyword scale).
struct ScaleDist {
  enum Kind { CONSTANT, UNIFORM, NORMAL, LOGNORMAL, LIST };
  int kind = CONSTANT;
  double a = 1.0, b = 0.0;      // constant: a; uniform: [a, b]; normal: mean a, sd b;
                                // lognormal: median a, sd b of ln s
  double lo = 0.0, hi = 0.0;    // cut-offs (normal, lognormal)
  int nlist = 0;
  static constexpr int MAXLIST = 32;
  double val[MAXLIST], cum[MAXLIST];       // list: values, cumulative weights (last = 1)
  static constexpr int MAXTRY = 100000;    // truncated draws (truncated mass >= 1e-3)

  double pdf(double s) const    // unnormalised density of the continuous kinds
  {
    if (kind == NORMAL) return exp(-0.5 * (s - a) * (s - a) / (b * b));
    if (kind == LOGNORMAL) {
      const double z = (log(s) - log(a)) / b;
      return exp(-0.5 * z * z) / s;
    }
    return 1.0;
  }
  // probability mass of [lo, hi] under the untruncated normal/lognormal
  double truncated_mass() const
  {
    if (kind == NORMAL)
      return 0.5 * (erf((hi - a) / (b * M_SQRT2)) - erf((lo - a) / (b * M_SQRT2)));
    if (kind == LOGNORMAL)
      return 0.5 * (erf(log(hi / a) / (b * M_SQRT2)) - erf(log(lo / a) / (b * M_SQRT2)));
    return 1.0;
  }
  double min() const
  {
    return kind == CONSTANT || kind == UNIFORM ? a : (kind == LIST ? listmin() : lo);
  }
  double max() const
  {
    return kind == CONSTANT ? a : (kind == UNIFORM ? b : (kind == LIST ? listmax() : hi));
  }
  double listmin() const
  {
    double m = val[0];
    for (int i = 1; i < nlist; ++i) m = val[i] < m ? val[i] : m;
    return m;
  }
  double listmax() const
  {
    double m = val[0];
    for (int i = 1; i < nlist; ++i) m = val[i] > m ? val[i] : m;
    return m;
  }

  double draw(InsertRng &rng) const
  {
    switch (kind) {
      case CONSTANT:
        return a;
      case UNIFORM:
        return a + (b - a) * rng.uniform();
      case LIST: {
        const double u = rng.uniform();
        for (int i = 0; i < nlist - 1; ++i)
          if (u < cum[i]) return val[i];
        return val[nlist - 1];
      }
      default: {
        // rejection from the untruncated law: bounded, and exact in law
        for (int t = 0; t < MAXTRY; ++t) {
          const double z = rng.normal();
          const double s = kind == NORMAL ? a + b * z : a * exp(b * z);
          if (s >= lo && s <= hi) return s;
        }
        return 0.5 * (lo + hi);    // unreachable for truncated mass >= 1e-3
      }
    }
  }

  // E[s^k] of the (truncated) law: exact for constant, uniform and list,
  // composite Simpson on [lo, hi] with 4096 intervals otherwise (relative
  // error < 1e-10 for the smooth densities here)
  double moment(int k) const
  {
    if (kind == CONSTANT) return pow(a, k);
    if (kind == UNIFORM)
      return a == b ? pow(a, k) : (pow(b, k + 1) - pow(a, k + 1)) / ((k + 1) * (b - a));
    if (kind == LIST) {
      double m = 0.0, prev = 0.0;
      for (int i = 0; i < nlist; ++i) {
        m += (cum[i] - prev) * pow(val[i], k);
        prev = cum[i];
      }
      return m;
    }
    const int n = 4096;
    const double h = (hi - lo) / n;
    double num = 0.0, den = 0.0;
    for (int i = 0; i <= n; ++i) {
      const double s = lo + i * h;
      const double w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
      const double p = pdf(s);
      num += w * p * pow(s, k);
      den += w * p;
    }
    return num / den;
  }
};

// Uniform rotation on SO(3) (Shoemake, Graphics Gems III, 1992): three
// uniforms, unit quaternion (w, x, y, z).
inline Quat<double> random_quat(InsertRng &rng)
{
  const double u = rng.uniform();
  const double t1 = sqrt(1.0 - u), t2 = sqrt(u);
  const double a1 = 2.0 * M_PI * rng.uniform(), a2 = 2.0 * M_PI * rng.uniform();
  return make_quat(cos(a2) * t2, sin(a1) * t1, cos(a1) * t1, sin(a2) * t2);
}

// rotation by angle theta [rad] about the unit axis u
inline Quat<double> axis_quat(const Vec3<double> &u, double theta)
{
  const double s = sin(0.5 * theta);
  return make_quat(cos(0.5 * theta), s * u.x, s * u.y, s * u.z);
}

// A posed convex body for the rejection test: a polyhedron (view, R, s)
// or an ellipsoid (semi-axes ax, already scaled), centroid x.
template <typename T> struct InsertBody {
  const ShapeView<T> *view;    // polyhedron, or nullptr: ellipsoid
  Vec3<T> x;
  Mat3<T> R;
  T s;
  Vec3<T> ax;    // ellipsoid semi-axes [length]
  T radius;      // bounding radius [length]
  T inradius;    // radius of a ball about x inside the body [length]

  POLYDEM_FN Vec3<T> operator()(const Vec3<T> &d) const
  {
    if (view) {
      PosedShape<T> p;
      p.view = view;
      p.x = x;
      p.R = R;
      p.s = s;
      return support_point(p, d);
    }
    // ellipsoid x + R A u, |u| = 1: support R A^2 db / |A db|, db = R^T d
    const Vec3<T> db = matTvec(R, d);
    const Vec3<T> e = make_vec3(ax.x * db.x, ax.y * db.y, ax.z * db.z);
    const T n = norm(e);
    if (!(n > T(0))) return x;
    return x + matvec(R, make_vec3(ax.x * e.x / n, ax.y * e.y / n, ax.z * e.z / n));
  }
};

// A triangle as a support functor
template <typename T> struct TriangleSupport {
  T p[9];
  POLYDEM_FN Vec3<T> operator()(const Vec3<T> &d) const { return support_of_points(p, 3, d); }
};

// A single point as a support functor
template <typename T> struct PointSupport {
  Vec3<T> p;
  POLYDEM_FN Vec3<T> operator()(const Vec3<T> &) const { return p; }
};

// true if point p is certified within distance r of body a (GJK upper bound)
template <typename T> POLYDEM_FN bool point_within(const InsertBody<T> &a, const Vec3<T> &p, T r)
{
  PointSupport<T> ps;
  ps.p = p;
  T lb, ub;
  gjk_gap_bounds(a, ps, a.x - p, T(1e-12) * a.radius, r, r, lb, ub);
  return ub <= r;
}

// Relative round-off margin of the rejection test: a candidate is accepted
// only if its certified distance exceeds gap + INSERT_MARGIN x size.
constexpr double INSERT_MARGIN = 1e-9;

// true if a and b are certified apart by more than gap [length]
template <typename T>
POLYDEM_FN bool bodies_apart(const InsertBody<T> &a, const InsertBody<T> &b, T gap)
{
  const Vec3<T> d = a.x - b.x;
  const T dd = norm2(d);
  const T far = a.radius + b.radius + gap;
  if (dd > far * far) return true;    // bounding spheres apart
  const T in = a.inradius + b.inradius;
  if (dd < in * in) return false;    // inscribed balls overlap
  const T L = a.radius > b.radius ? a.radius : b.radius;
  const T stop = gap + T(INSERT_MARGIN) * L;
  return gjk_gap_lower_bound(a, b, d, T(1e-12) * L, stop) > stop;
}

// true if body a is certified apart from triangle t by more than gap
template <typename T>
POLYDEM_FN bool body_triangle_apart(const InsertBody<T> &a, const TriangleSupport<T> &t, T gap)
{
  const T stop = gap + T(INSERT_MARGIN) * a.radius;
  const Vec3<T> c = make_vec3((t.p[0] + t.p[3] + t.p[6]) / T(3), (t.p[1] + t.p[4] + t.p[7]) / T(3),
                              (t.p[2] + t.p[5] + t.p[8]) / T(3));
  return gjk_gap_lower_bound(a, t, a.x - c, T(1e-12) * a.radius, stop) > stop;
}

}    // namespace polydem

#endif
