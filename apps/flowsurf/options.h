// flowsurf — the options of `flowsurf render` (one table: CLI11 drives --help from it)
// and the parsers of their value syntaxes. Library-free of GL so unit tests cover it.
#pragma once

#include "core/camera.h"
#include "methods/common/params.h"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace flowsurf::app {

struct RenderOptions {
    std::string input;                  // file or builtin:NAME
    std::string method = "isa";
    std::string field;                  // empty: first 3-component point array
    core::Viewport size{800, 600};      // --size WxH
    int frames = 90;                    // advection frames before the output frame
    std::string output = "flowsurf.png";
    std::string flowTexture;            // --flow-texture FILE.png (16-bit gray F_a)
    // Camera; unset means "fit the bounds".
    std::optional<glm::vec3> eye, target, up;
    float fov = 30.0f;
    float ortho = 0.0f;                 // > 0: orthographic view height
    float orbit = 0.0f;                 // degrees per frame about the up axis
    std::string cameraPath;             // --camera-path FILE (JSON keyframes)
    size_t timeStep = 0;                // --time-step: render this one step, steady
    bool timeStepGiven = false;
    std::optional<std::pair<double, double>> timeRange;  // --time START:END (data time)
    double timePerFrame = 0.0;          // --time-per-frame DT (0: see framesPerStep)
    int framesPerStep = 0;              // --frames-per-step N (0: the range over --frames)
    std::optional<double> traceDt;      // --trace-dt: hybrid data time per particle step
    int fps = 30;
    int crf = 18;
    bool quiet = false;
    bool verbose = false;
    bool listBuiltins = false;
    methods::MethodParams params;
};

// Adds the render options, grouped by topic, to `cmd`.
void addRenderOptions(CLI::App& cmd, RenderOptions& opt);
// Checks ranges and combinations after parsing; throws ConfigError naming the option.
void validateRenderOptions(const RenderOptions& opt);

// Value syntaxes (throw ConfigError naming `what`):
float parseFloat(const std::string& text, const std::string& what);
core::Viewport parseSize(const std::string& text, const std::string& what = "--size");
glm::vec3 parseVec3(const std::string& text, const std::string& what);
glm::vec3 parseColor(const std::string& text, const std::string& what = "--background");

// Output kind from the file name: .png (final frame), .mp4 (all frames), %d pattern.
enum class OutputKind { Png, Mp4, PngSequence };
OutputKind outputKind(const std::string& path);

}  // namespace flowsurf::app
