// flowsurf ParaView plugin — a POSIX clock in milliseconds (CLOCK_MONOTONIC for wall time,
// CLOCK_PROCESS_CPUTIME_ID / CLOCK_THREAD_CPUTIME_ID for CPU time): what rank_stats and the
// process group's MPI accounting read.
#pragma once

#include <ctime>

namespace flowsurf::paraview {

inline double clockMs(clockid_t id)
{
  timespec t{};
  clock_gettime(id, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

}  // namespace flowsurf::paraview
