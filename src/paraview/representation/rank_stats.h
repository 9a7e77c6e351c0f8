// flowsurf ParaView plugin — what each process's renders cost, for the scaling benchmark
// (bench/paraview/scaling.sh): with FLOWSURF_RANK_STATS=DIR every process appends one JSON
// line per render that ran frames to DIR/rank<r>.jsonl: method and parallel mode, wall and
// CPU time of the frame loop (the process's clock: llvmpipe's threads included), the stage
// times (glFinish at every stage boundary, in this mode only) and what the screen tiles
// exchanged (methods::TileTraffic).
#pragma once

#include "session/playback.h"

#include <memory>
#include <string>

namespace flowsurf::paraview {

class RankStats
{
public:
  // Null unless FLOWSURF_RANK_STATS names a folder.
  static std::unique_ptr<RankStats> fromEnvironment();
  // Before the frame loop: synchronous stage timing on, the clocks read.
  void begin(session::Playback& playback);
  // After it: this render's line, for process `rank` of `ranks`.
  void end(session::Playback& playback, int rank, int ranks, bool warmup);

private:
  explicit RankStats(std::string dir)
    : dir_(std::move(dir))
  {
  }
  std::string dir_;
  double wallMs_ = 0, cpuMs_ = 0;
  long renders_ = 0;
};

}  // namespace flowsurf::paraview
