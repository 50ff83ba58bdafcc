// Statistics of the insertion tests: the Kolmogorov-Smirnov statistic.
#ifndef POLYDEM_TEST_INSERT_STATS_H
#define POLYDEM_TEST_INSERT_STATS_H

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace insert_test {

// sup |F_n - F| of the sample against the CDF F
inline double ks(std::vector<double> x, const std::function<double(double)> &F)
{
  std::sort(x.begin(), x.end());
  const double n = (double) x.size();
  double d = 0.0;
  for (size_t i = 0; i < x.size(); i++) {
    const double f = F(x[i]);
    d = std::max(d, std::max(f - i / n, (i + 1) / n - f));
  }
  return d;
}

// critical value of the KS statistic at significance 1e-3 (asymptotic:
// sqrt(-ln(a/2)/2) / sqrt(n))
inline double ks_crit(size_t n) { return 1.9495 / std::sqrt((double) n); }

}    // namespace insert_test

#endif
