#include "rank_stats.h"

#include "clock_ms.h"

#include "dye/dye.h"
#include "methods/stages.h"
#include "parallel/process_group.h"
#include "params/params.h"

#include <epoxy/gl.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <fstream>

namespace flowsurf::paraview {

std::unique_ptr<RankStats> RankStats::fromEnvironment()
{
  const char* dir = std::getenv("FLOWSURF_RANK_STATS");
  return dir && *dir ? std::unique_ptr<RankStats>(new RankStats(dir)) : nullptr;
}

void RankStats::begin(session::Playback& playback, const VtkProcessGroup* group)
{
  for (const auto& method : playback.views())
  {
    method->timer().setSynchronous(true);
  }
  playback.setStageTiming(true);
  wallMs_ = clockMs(CLOCK_MONOTONIC);
  cpuMs_ = clockMs(CLOCK_PROCESS_CPUTIME_ID);
  mpiCpuMs_ = group ? group->mpiCpuMs() : 0.0;
}

void RankStats::end(session::Playback& playback, const VtkProcessGroup* group, bool warmup)
{
  const int rank = group ? group->rank() : 0, ranks = group ? group->size() : 1;
  glFinish();
  methods::FlowMethod& method = *playback.views()[0];
  const methods::TileTraffic t = method.tileTraffic();
  nlohmann::ordered_json line = { { "rank", rank }, { "ranks", ranks }, { "render", renders_++ },
    { "method", method.name() },
    { "parallel", methods::nameOf(methods::kParallelModeNames, playback.options().params.common.parallel) },
    { "warmup", warmup }, { "dynamic", method.lastFrameDynamic() },
    { "wall_ms", clockMs(CLOCK_MONOTONIC) - wallMs_ }, { "cpu_ms", clockMs(CLOCK_PROCESS_CPUTIME_ID) - cpuMs_ },
    { "mpi_cpu_ms", group ? group->mpiCpuMs() - mpiCpuMs_ : 0.0 },
    { "oversubscribed", group && group->oversubscribed() },
    { "bytes_sent", t.bytesSent }, { "bytes_received", t.bytesReceived }, { "tile_px", t.tilePixels },
    { "guard_px", t.guardPixels }, { "covered_px", t.coveredPixels } };
  nlohmann::ordered_json stages = nlohmann::ordered_json::object();
  for (const auto& [stage, ms] : method.timer().meanMs())
  {
    stages[stage] = ms;
  }
  line["stages_ms"] = stages;
  nlohmann::ordered_json stagesCpu = nlohmann::ordered_json::object();
  double computeCpuMs = 0.0;
  for (const auto& [stage, ms] : method.timer().meanCpuMs())
  {
    stagesCpu[stage] = ms;
    if (!methods::isExchangeStage(stage))
    {
      computeCpuMs += ms;
    }
  }
  line["stages_cpu_ms"] = stagesCpu;
  line["compute_cpu_ms"] = computeCpuMs;
  if (const methods::DyeField* dye = playback.dye().field())
  {
    line["dye_voxels"] = dye->advectedVoxels();
    line["dye_halo_bytes_sent"] = dye->haloBytesSent();
  }
  method.timer().reset();
  std::ofstream(dir_ + "/rank" + std::to_string(rank) + ".jsonl", std::ios::app) << line.dump() << "\n";
}

}  // namespace flowsurf::paraview
