/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - Chebyshev centre of a bounded intersection of half-spaces
   n_i . x <= h_i (|n_i| = 1): the point x maximising the inscribed radius r,
     max r  s.t.  n_i . x + r <= h_i,
   a 4-variable LP solved by a primal active-set (simplex) method with at
   most 4 active constraints, so all linear algebra is 4x4. Used to pick the
   strictly interior polarisation point x_o of the overlap (seed 2.3, Eq. 4).
   Any feasible iterate is a valid interior point, so the iteration cap only
   limits quality, never correctness. Header-only, host and device.
------------------------------------------------------------------------- */

#ifndef POLYDEM_LP_H
#define POLYDEM_LP_H

#include "polydem_math.h"

namespace polydem {

constexpr int LP_MAX_ITER = 64;

namespace lp_detail {

  // Solve the k x k system G y = r (k <= 4) by Gaussian elimination with
  // partial pivoting; false if singular.
  template <typename T> POLYDEM_FN bool solve_small(T G[4][4], T *r, int k)
  {
    for (int c = 0; c < k; ++c) {
      int p = c;
      for (int i = c + 1; i < k; ++i)
        if (fabs(G[i][c]) > fabs(G[p][c])) p = i;
      if (!(fabs(G[p][c]) > T(0))) return false;
      if (p != c) {
        for (int j = 0; j < k; ++j) {
          const T t = G[c][j];
          G[c][j] = G[p][j];
          G[p][j] = t;
        }
        const T t = r[c];
        r[c] = r[p];
        r[p] = t;
      }
      for (int i = c + 1; i < k; ++i) {
        const T f = G[i][c] / G[c][c];
        for (int j = c; j < k; ++j) G[i][j] -= f * G[c][j];
        r[i] -= f * r[c];
      }
    }
    for (int c = k - 1; c >= 0; --c) {
      T s = r[c];
      for (int j = c + 1; j < k; ++j) s -= G[c][j] * r[j];
      r[c] = s / G[c][c];
    }
    return true;
  }

  // min_i (h_i - n_i . x) [length]
  template <typename T> POLYDEM_FN T clearance(const T *planes, int m, const T *z)
  {
    T rr = planes[3] - (planes[0] * z[0] + planes[1] * z[1] + planes[2] * z[2]);
    for (int i = 1; i < m; ++i) {
      const T *pi = planes + 4 * i;
      const T s = pi[3] - (pi[0] * z[0] + pi[1] * z[1] + pi[2] * z[2]);
      if (s < rr) rr = s;
    }
    return rr;
  }

}    // namespace lp_detail

// planes: 4*m values (n_x, n_y, n_z, h), unit normals, in coordinates where
// the start point is the origin. On return xc is the centre, r the inscribed
// radius [length] (r <= 0: empty or flat intersection). Returns the number of
// iterations used (LP_MAX_ITER if capped; the result is then still feasible).
template <typename T> POLYDEM_FN int chebyshev_centre(const T *planes, int m, Vec3<T> &xc, T &r)
{
  // z = (x, r); constraint rows a_i = (n_i, 1), objective c = (0,0,0,1)
  T z[4] = {T(0), T(0), T(0), T(0)};
  int act[4];
  int k = 0;
  {
    int imin = 0;
    for (int i = 1; i < m; ++i)
      if (planes[4 * i + 3] < planes[4 * imin + 3]) imin = i;
    z[3] = planes[4 * imin + 3];
    act[k++] = imin;
  }
  Vec3<T> xbest = make_vec3(T(0), T(0), T(0));
  T rbest = z[3];
  int dropped = -1;
  int it = 0;
  for (; it < LP_MAX_ITER; ++it) {
    // multipliers mu of the projection of c onto span(active rows)
    T G[4][4], mu[4];
    if (k == 4) {
      // vertex: solve A_W^T mu = c directly (the Gram matrix would square
      // the condition number, fatal in float)
      for (int a = 0; a < 4; ++a) {
        const T *pa = planes + 4 * act[a];
        for (int j = 0; j < 3; ++j) G[j][a] = pa[j];
        G[3][a] = T(1);
        mu[a] = a == 3 ? T(1) : T(0);
      }
    } else {
      for (int a = 0; a < k; ++a) {
        const T *pa = planes + 4 * act[a];
        for (int b = 0; b < k; ++b) {
          const T *pb = planes + 4 * act[b];
          G[a][b] = pa[0] * pb[0] + pa[1] * pb[1] + pa[2] * pb[2] + T(1);
        }
        mu[a] = T(1);    // a_i . c
      }
    }
    if (!lp_detail::solve_small(G, mu, k)) break;
    // p = c - A^T mu : steepest feasible ascent within the active set
    T p[4] = {T(0), T(0), T(0), T(1)};
    for (int a = 0; a < k; ++a) {
      const T *pa = planes + 4 * act[a];
      p[0] -= mu[a] * pa[0];
      p[1] -= mu[a] * pa[1];
      p[2] -= mu[a] * pa[2];
      p[3] -= mu[a];
    }
    const T pn2 = p[0] * p[0] + p[1] * p[1] + p[2] * p[2] + p[3] * p[3];
    // p_r = |p|^2 is also the gain in r per unit step; |p| below 256 eps is
    // projection round-off (c is in the span of the active rows)
    if (k == 4 || pn2 <= T(65536) * Eps<T>::value * Eps<T>::value) {
      // stationary in the active set: optimal if all multipliers >= 0
      int worst = -1;
      T wv = -T(16) * Eps<T>::value;
      for (int a = 0; a < k; ++a)
        if (mu[a] < wv) {
          wv = mu[a];
          worst = a;
        }
      if (worst < 0) break;
      dropped = act[worst];
      act[worst] = act[--k];
      continue;
    }
    // ratio test along p
    int enter = -1;
    T tmin = T(0);
    for (int i = 0; i < m; ++i) {
      bool in = (i == dropped);    // anti-cycling: not straight back in
      for (int a = 0; a < k; ++a) in = in || (act[a] == i);
      if (in) continue;
      const T *pi = planes + 4 * i;
      const T ap = pi[0] * p[0] + pi[1] * p[1] + pi[2] * p[2] + p[3];
      if (!(ap > T(0))) continue;
      T slack = pi[3] - (pi[0] * z[0] + pi[1] * z[1] + pi[2] * z[2] + z[3]);
      if (slack < T(0)) slack = T(0);
      const T t = slack / ap;
      if (enter < 0 || t < tmin) {
        enter = i;
        tmin = t;
      }
    }
    if (enter < 0) break;    // unbounded direction: cannot happen for bounded input
    for (int j = 0; j < 4; ++j) z[j] += tmin * p[j];
    act[k++] = enter;
    dropped = -1;
    // keep the best point by its true clearance (guards against round-off drift)
    const T rt = lp_detail::clearance(planes, m, z);
    if (rt > rbest) {
      rbest = rt;
      xbest = make_vec3(z[0], z[1], z[2]);
    }
  }
  xc = xbest;
  r = rbest;
  return it;
}

}    // namespace polydem

#endif
