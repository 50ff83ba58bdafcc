// POLYDEM kernel tests: random and degenerate pair generators shared by the suites.
#ifndef POLYDEM_PAIR_GEN_H
#define POLYDEM_PAIR_GEN_H

#include "polydem_overlap.h"
#include "test_shapes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <memory>

namespace polydem_test {

using polydem::make_vec3;
using polydem::Pose;
using polydem::Quat;
using polydem::Vec3;

struct Pair {
  int a, b;    // shape indices in the pool
  Pose<double> pa, pb;
  const char *family;
};

// pool of templates: random hulls (4-64 vertices, aspect ratio 1-10) and
// regular shapes; index 0 cube (side 1), 1 dodecahedron, 2 cylinder (D 1, L 0.6625)
struct ShapePool {
  std::vector<ShapeData> data;
  std::vector<std::unique_ptr<TypedShape<double>>> d;
  std::vector<std::unique_ptr<TypedShape<float>>> f;
  explicit ShapePool(int nrandom, unsigned seed = 1234)
  {
    std::mt19937_64 rng(seed);
    add(make_shape(cube_points(1.0)));
    add(make_shape(dodecahedron_points(1.0)));
    add(make_shape(cylinder_points(1.0, 0.6625, 20)));
    std::uniform_int_distribution<int> nv(4, 64);
    std::uniform_real_distribution<double> asp(1.0, 10.0);
    for (int i = 0; i < nrandom; ++i) add(make_shape(random_points(rng, nv(rng), asp(rng))));
    for (const char *f : SHIPPED_SHAPES) add(make_shape(shipped_points(f)));
  }
  void add(ShapeData s)
  {
    data.push_back(std::move(s));
    d.emplace_back(typed<double>(data.back()));
    f.emplace_back(typed<float>(data.back()));
  }
};

inline Pose<double> make_pose(Vec3<double> x, Quat<double> q, double s)
{
  Pose<double> p;
  p.x = x;
  p.q = q;
  p.s = s;
  return p;
}

inline Pose<float> to_float(const Pose<double> &p)
{
  Pose<float> r;
  r.x = make_vec3((float) p.x.x, (float) p.x.y, (float) p.x.z);
  r.q = polydem::make_quat((float) p.q.w, (float) p.q.x, (float) p.q.y, (float) p.q.z);
  r.s = (float) p.s;
  return r;
}

inline Quat<double> axis_angle(Vec3<double> axis, double ang)
{
  axis = (1.0 / polydem::norm(axis)) * axis;
  const double s = std::sin(0.5 * ang);
  return polydem::make_quat(std::cos(0.5 * ang), s * axis.x, s * axis.y, s * axis.z);
}

// quaternion rotating unit vector u onto unit vector v
inline Quat<double> align(Vec3<double> u, Vec3<double> v)
{
  const double c = polydem::dot(u, v);
  if (c < -1 + 1e-12) {
    Vec3<double> a = polydem::cross(u, make_vec3(1.0, 0.0, 0.0));
    if (polydem::norm2(a) < 1e-6) a = polydem::cross(u, make_vec3(0.0, 1.0, 0.0));
    return axis_angle(a, M_PI);
  }
  Vec3<double> a = polydem::cross(u, v);
  return polydem::qnormalize(polydem::make_quat(1 + c, a.x, a.y, a.z));
}

inline Vec3<double> random_unit(std::mt19937_64 &rng)
{
  std::normal_distribution<double> g(0, 1);
  Vec3<double> v = make_vec3(g(rng), g(rng), g(rng));
  return (1.0 / polydem::norm(v)) * v;
}

// random pairs in random poses, centre distance uniform in [0, 1.1] of rA+rB
inline Pair random_pair(const ShapePool &pool, std::mt19937_64 &rng)
{
  std::uniform_int_distribution<int> pick(0, (int) pool.data.size() - 1);
  std::uniform_real_distribution<double> u(0, 1);
  Pair p;
  p.a = pick(rng);
  p.b = pick(rng);
  const double sa = 0.5 + 1.5 * u(rng), sb = 0.5 + 1.5 * u(rng);
  const Vec3<double> xa = make_vec3(20 * u(rng) - 10, 20 * u(rng) - 10, 20 * u(rng) - 10);
  const double rr = sa * pool.data[p.a].radius + sb * pool.data[p.b].radius;
  const Vec3<double> xb = xa + (1.1 * rr * u(rng)) * random_unit(rng);
  p.pa = make_pose(xa, random_quat(rng), sa);
  p.pb = make_pose(xb, random_quat(rng), sb);
  p.family = "random";
  return p;
}

// outward unit normal (lab) and face centroid (lab) of face f of a posed shape
inline void posed_face(const ShapeData &s, const Pose<double> &p, int f, Vec3<double> &n,
                       Vec3<double> &c)
{
  auto R = polydem::quat_to_mat(p.q);
  n = polydem::matvec(R, make_vec3(s.planes[4 * f], s.planes[4 * f + 1], s.planes[4 * f + 2]));
  Vec3<double> cb = make_vec3(0.0, 0.0, 0.0);
  int k0 = s.face_start[f], k1 = s.face_start[f + 1];
  for (int k = k0; k < k1; ++k) {
    int v = s.face_verts[k];
    cb += make_vec3(s.verts[3 * v], s.verts[3 * v + 1], s.verts[3 * v + 2]);
  }
  cb = (1.0 / (k1 - k0)) * cb;
  c = p.x + p.s * polydem::matvec(R, cb);
}

// degenerate families. kind: 0 coplanar face-face (axis-aligned cubes),
// 1 parallel edge-edge, 2 vertex on face (depth delta), 3 identical coincident,
// 4 one inside the other, 5 touching face-face, 6 face-face sliver of depth
// delta (random shapes, antiparallel faces)
inline Pair degenerate_pair(const ShapePool &pool, std::mt19937_64 &rng, int kind, double delta)
{
  std::uniform_real_distribution<double> u(0, 1);
  std::uniform_int_distribution<int> pick(0, (int) pool.data.size() - 1);
  const Quat<double> id = polydem::make_quat(1.0, 0.0, 0.0, 0.0);
  Pair p;
  p.a = p.b = 0;
  const Vec3<double> x0 = make_vec3(u(rng), u(rng), u(rng));
  switch (kind) {
    case 0: {    // cubes side 1 (exact), lateral offsets on a 1/8 grid, depth k/16
      p.family = "coplanar face-face";
      const double dx = 1.0 - (1 + (int) (15 * u(rng))) / 16.0;
      const double dy = (int) (9 * u(rng)) / 8.0 - 0.5, dz = (int) (9 * u(rng)) / 8.0 - 0.5;
      p.pa = make_pose(make_vec3(0.0, 0.0, 0.0), id, 1.0);
      p.pb = make_pose(make_vec3(dx, dy, dz), id, 1.0);
      break;
    }
    case 1: {    // cubes rotated 45 deg about z: vertical edges parallel
      p.family = "parallel edge-edge";
      const Quat<double> q = axis_angle(make_vec3(0.0, 0.0, 1.0), M_PI / 4);
      const double d = std::sqrt(2.0) * (1 - 0.1 * u(rng));
      p.pa = make_pose(x0, q, 1.0);
      p.pb = make_pose(x0 + make_vec3(d, 0.0, 0.3 * u(rng)), q, 1.0);
      break;
    }
    case 2: {    // a vertex of B pressed delta into a face of A
      p.family = "vertex on face";
      p.a = pick(rng);
      p.b = pick(rng);
      p.pa = make_pose(x0, random_quat(rng), 1.0);
      const ShapeData &A = pool.data[p.a];
      const int f = (int) (u(rng) * A.nfaces()) % A.nfaces();
      Vec3<double> n, c;
      posed_face(A, p.pa, f, n, c);
      p.pb = make_pose(make_vec3(0.0, 0.0, 0.0), random_quat(rng), 1.0);
      // B's support vertex in direction -n at c - delta n
      auto vb = posed_vertices(pool.data[p.b], p.pb);
      int best = 0;
      for (size_t i = 1; i < vb.size(); ++i)
        if (-n.x * vb[i][0] - n.y * vb[i][1] - n.z * vb[i][2] >
            -n.x * vb[best][0] - n.y * vb[best][1] - n.z * vb[best][2])
          best = (int) i;
      const double L = std::max(A.radius, pool.data[p.b].radius);
      p.pb.x = c - make_vec3(vb[best][0], vb[best][1], vb[best][2]) - (delta * L) * n;
      break;
    }
    case 3:
      p.family = "identical coincident";
      p.a = p.b = pick(rng);
      p.pa = p.pb = make_pose(x0, random_quat(rng), 0.5 + u(rng));
      break;
    case 4:
      p.family = "one inside other";
      p.a = pick(rng);
      p.b = pick(rng);
      p.pa = make_pose(x0, random_quat(rng), 1.0);
      p.pb = make_pose(x0, random_quat(rng), 0.05);
      break;
    case 5: {
      p.family = "touching face-face";
      const double dy = (int) (9 * u(rng)) / 8.0 - 0.5;
      p.pa = make_pose(make_vec3(0.0, 0.0, 0.0), id, 1.0);
      p.pb = make_pose(make_vec3(1.0, dy, 0.25), id, 1.0);
      break;
    }
    default: {    // antiparallel faces, B's face pressed delta*L into A's face plane
      p.family = "face-face sliver";
      p.a = pick(rng);
      p.b = pick(rng);
      p.pa = make_pose(x0, random_quat(rng), 1.0);
      const ShapeData &A = pool.data[p.a], &B = pool.data[p.b];
      const int fa = (int) (u(rng) * A.nfaces()) % A.nfaces();
      const int fb = (int) (u(rng) * B.nfaces()) % B.nfaces();
      Vec3<double> na, ca, nb0, cb0;
      posed_face(A, p.pa, fa, na, ca);
      p.pb = make_pose(make_vec3(0.0, 0.0, 0.0), id, 1.0);
      posed_face(B, p.pb, fb, nb0, cb0);
      Quat<double> q = polydem::qmul(axis_angle(na, 2 * M_PI * u(rng)), align(nb0, -na));
      p.pb.q = q;
      posed_face(B, p.pb, fb, nb0, cb0);    // now nb0 = -na, centroid cb0 (x_B = 0)
      const double L = std::max(A.radius, B.radius);
      const double hb = polydem::dot(na, cb0);    // B's face plane offset along na
      // lateral: put B's face centroid on A's face centroid
      Vec3<double> lat = ca - cb0;
      lat = lat - polydem::dot(lat, na) * na;
      p.pb.x = lat + (polydem::dot(na, ca) - hb - delta * L) * na;
      break;
    }
  }
  return p;
}

// central differences of f(Pose) about p: ft in translation (step h), fr
// in rotation about the lab axes through p.x (step ha, radians)
template <class F>
inline void pose_differences(F f, const Pose<double> &p, double h, double ha, Vec3<double> &ft,
                             Vec3<double> &fr)
{
  for (int k = 0; k < 3; ++k) {
    Vec3<double> e = make_vec3(0.0, 0.0, 0.0);
    e[k] = 1.0;
    Pose<double> a = p, b = p;
    a.x += h * e;
    b.x -= h * e;
    ft[k] = (f(a) - f(b)) / (2 * h);
    a = b = p;
    a.q = polydem::qmul(axis_angle(e, ha), p.q);
    b.q = polydem::qmul(axis_angle(e, -ha), p.q);
    fr[k] = (f(a) - f(b)) / (2 * ha);
  }
}

// S_A, M_A, M_B of r against their central differences fs, fma, fmb: the
// errors relative to |S_A| (the moments' to |S_A| L) kept as maxima in
// emax[3], each expected <= tol
inline void expect_gradients(const polydem::OverlapResult<double> &r, const Vec3<double> &fs,
                             const Vec3<double> &fma, const Vec3<double> &fmb, double L,
                             double *emax, double tol = 1e-6)
{
  using polydem::norm;
  const double es = norm(fs - r.S_A) / norm(r.S_A);
  const double ema = norm(fma - r.M_A) / (norm(r.S_A) * L);
  const double emb = norm(fmb - r.M_B) / (norm(r.S_A) * L);
  emax[0] = std::max(emax[0], es);
  emax[1] = std::max(emax[1], ema);
  emax[2] = std::max(emax[2], emb);
  EXPECT_LE(es, tol);
  EXPECT_LE(ema, tol);
  EXPECT_LE(emb, tol);
}

}    // namespace polydem_test

#endif
