// Test helper: every rank's values, concatenated in rank order, on every rank.
#ifndef POLYDEM_TEST_ALLGATHER_H
#define POLYDEM_TEST_ALLGATHER_H

#include <mpi.h>

#include <algorithm>
#include <vector>

namespace polydem_test {

inline std::vector<double> allgather(const std::vector<double> &mine, MPI_Comm comm = MPI_COMM_WORLD)
{
  int nprocs, n = (int) mine.size();
  MPI_Comm_size(comm, &nprocs);
  std::vector<int> counts(nprocs), displs(nprocs);
  MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
  int total = 0;
  for (int p = 0; p < nprocs; p++) displs[p] = total, total += counts[p];
  std::vector<double> all(total);
  MPI_Allgatherv(mine.data(), n, MPI_DOUBLE, all.data(), counts.data(), displs.data(), MPI_DOUBLE,
                 comm);
  return all;
}

// records of `width` values, the first an atom ID: every rank's, on every
// rank, sorted by ID (so 1 and N ranks compare record by record)
inline std::vector<double> allgather_by_tag(const std::vector<double> &mine, int width,
                                            MPI_Comm comm = MPI_COMM_WORLD)
{
  const std::vector<double> all = allgather(mine, comm);
  std::vector<std::vector<double>> recs;
  for (size_t i = 0; i + width <= all.size(); i += width)
    recs.emplace_back(all.begin() + i, all.begin() + i + width);
  std::sort(recs.begin(), recs.end());
  std::vector<double> out;
  for (auto &r : recs) out.insert(out.end(), r.begin(), r.end());
  return out;
}

}    // namespace polydem_test

#endif
