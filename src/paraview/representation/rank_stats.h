// flowsurf ParaView plugin — what each process's renders cost, for the scaling benchmark
// (bench/paraview/scaling.sh): with FLOWSURF_RANK_STATS=DIR every process appends one JSON
// line per render that ran frames to DIR/rank<r>.jsonl: method and parallel mode, wall and
// CPU time of the frame loop (the process's clock: llvmpipe's threads included), of that the
// CPU time spent inside the group's MPI calls (copies, and polling while the others work),
// the stage times (glFinish at every stage boundary, in this mode only) and what the screen
// tiles exchanged (methods::TileTraffic).
#pragma once

#include "parallel/process_group.h"
#include "session/playback.h"
#include "vtk_process_group.h"

#include <memory>
#include <string>

namespace flowsurf::paraview {

class RankStats
{
public:
  // Null unless FLOWSURF_RANK_STATS names a folder.
  static std::unique_ptr<RankStats> fromEnvironment();
  // Before the frame loop: synchronous stage timing on, the clocks read. `group`: this
  // process's (null at one process).
  void begin(session::Playback& playback, const VtkProcessGroup* group);
  // After it: this render's line.
  void end(session::Playback& playback, const VtkProcessGroup* group, bool warmup);

private:
  explicit RankStats(std::string dir)
    : dir_(std::move(dir))
  {
  }
  std::string dir_;
  double wallMs_ = 0, cpuMs_ = 0, mpiCpuMs_ = 0;
  long renders_ = 0;
};

}  // namespace flowsurf::paraview
