// flowsurf — the vector field around a frame's data time, for a method that integrates
// through time: [W §3] "in the case of a time-dependent flow, the projection of the vector
// data has to be performed within the integration loop". The levels are the data's own
// time steps inside the data-time window the particles cover, plus the window's ends; each
// is a blend of two steps' raw per-vertex fields on the frame's vertices. The data is
// linear in time between steps, so linear interpolation between levels reproduces it
// exactly while the window spans fewer than kMaxLevels steps (wider windows get
// kMaxLevels levels spaced evenly in time).
#pragma once

#include "core/step_stream.h"
#include "gl/objects.h"
#include "gpu/shader_limits.h"

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace flowsurf::methods {

// One time level: (1 - weight) fieldA + weight fieldB, raw vectors (vec3 per vertex,
// not yet tangential or scaled) on the vertices of the frame's surface.
struct TimeLevel {
    GLuint fieldA = 0, fieldB = 0;
    float weight = 0.0f;
    double time = 0.0;
    bool operator==(const TimeLevel&) const = default;
};

struct TimeLevels {
    double frameTime = 0.0;    // t0, the data time of the frame
    double timePerStep = 0.0;  // data time per integration step (backward steps: -)
    std::vector<TimeLevel> levels;  // increasing time
    // Fewer than two levels: the window is empty (no time per step, or a single step).
    bool empty() const { return levels.size() < 2; }
    bool operator==(const TimeLevels&) const = default;
};

// Builds TimeLevels from a streamed series; owns the GPU copies of the steps' fields.
class TimeLevelSource {
public:
    static constexpr int kMaxLevels = kMaxTimeLevels;
    // `stream` must outlive this; `field`: the vector field's name in every step.
    TimeLevelSource(core::StepStream& stream, std::string field);
    // The levels over [t0 - halfSteps tau, t0 + halfSteps tau], clamped to the data's time
    // range, for the surface the stream's last meshAt() returned. A level whose steps have
    // other triangles than that surface holds the field of the nearest level that agrees
    // (the field is held across a topology change). Throws what loading a step throws, or
    // FieldError when a step lacks the field.
    const TimeLevels& at(double t0, double timePerStep, int halfSteps);

private:
    GLuint fieldBuffer(size_t step);
    bool agrees(size_t step, size_t topologyStep);

    core::StepStream& stream_;
    std::string field_;
    std::map<size_t, gl::Buffer> fields_;
    std::map<std::pair<size_t, size_t>, bool> agrees_;
    TimeLevels levels_;
};

}  // namespace flowsurf::methods
