// Test helper: every rank's values, concatenated in rank order, on every rank.
#ifndef POLYDEM_TEST_ALLGATHER_H
#define POLYDEM_TEST_ALLGATHER_H

#include <mpi.h>

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

}    // namespace polydem_test

#endif
