// flowsurf view — the files a viewer session writes besides images: camera keyframes and
// the `--stats` summary of a run.
#pragma once

#include "core/camera.h"
#include "view_pipeline.h"

#include <cstdint>
#include <string>
#include <vector>

namespace flowsurf::app::view {

// Appends the camera as a keyframe to a --camera-path file (created if missing); a frame
// not after the last keyframe's becomes the last's + 30. Throws FormatError for a file that
// is not a camera path.
void appendKeyframe(const std::string& path, const core::Camera& c, uint32_t frame);

// The `--stats` JSON: frame times, each view's mean stage times, the GL renderer, the view
// size and, with `quality`, each view's frames measured and the median and worst of each
// metric (null: none).
std::string statsJson(ViewPipeline& pipeline, const std::vector<double>& frameMs, const std::string& renderer,
                      bool quality);

}  // namespace flowsurf::app::view
