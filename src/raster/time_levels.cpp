#include "raster/time_levels.h"

#include "core/errors.h"

#include <algorithm>
#include <cmath>

namespace flowsurf::methods {

TimeLevelSource::TimeLevelSource(core::StepStream& stream, std::string field)
    : stream_(stream), field_(std::move(field)) {}

GLuint TimeLevelSource::fieldBuffer(size_t step) {
    if (auto it = fields_.find(step); it != fields_.end()) return it->second.id();
    auto mesh = stream_.stepMesh(step);
    const core::VectorField* f = mesh->findField(field_);
    if (!f) throw FieldError(stream_.label(step) + ": no vector field '" + field_ + "' in this step");
    gl::Buffer buffer(GLsizeiptr(f->values.size() * sizeof(glm::vec3)), f->values.data(), 0);
    return fields_.emplace(step, std::move(buffer)).first->second.id();
}

bool TimeLevelSource::agrees(size_t step, size_t topologyStep) {
    if (step == topologyStep) return true;
    auto key = std::make_pair(step, topologyStep);
    if (auto it = agrees_.find(key); it != agrees_.end()) return it->second;
    bool same = core::sameTopology(*stream_.stepMesh(step), *stream_.stepMesh(topologyStep));
    agrees_.emplace(key, same);
    return same;
}

const TimeLevels& TimeLevelSource::at(double t0, double timePerStep, int halfSteps) {
    const std::vector<double>& times = stream_.times();
    levels_ = TimeLevels{};
    levels_.frameTime = t0;
    levels_.timePerStep = timePerStep;
    const double span = std::abs(timePerStep) * halfSteps;
    const double lo = std::max(t0 - span, times.front()), hi = std::min(t0 + span, times.back());
    if (!(span > 0.0) || times.size() < 2 || !(hi > lo)) return levels_;

    const core::StepBracket first = core::bracket(times, lo), last = core::bracket(times, hi);
    stream_.keepRange(first.a, last.b);
    // Knots: the window's ends and every step time strictly inside it.
    std::vector<double> knots{lo};
    for (size_t i = first.a; i <= last.b; ++i)
        if (times[i] > lo && times[i] < hi) knots.push_back(times[i]);
    knots.push_back(hi);
    if (knots.size() > size_t(kMaxLevels)) {
        knots.resize(size_t(kMaxLevels));
        for (int j = 0; j < kMaxLevels; ++j) knots[size_t(j)] = lo + (hi - lo) * j / double(kMaxLevels - 1);
    }
    const int count = int(knots.size());
    const size_t topology = stream_.topologyStep();
    std::vector<bool> valid(size_t(count), true);
    levels_.levels.resize(size_t(count));
    for (int j = 0; j < count; ++j) {
        TimeLevel& level = levels_.levels[size_t(j)];
        level.time = knots[size_t(j)];
        const core::StepBracket br = core::bracket(times, level.time);
        const bool okA = agrees(br.a, topology), okB = agrees(br.b, topology);
        if (okA && okB) {
            level.fieldA = fieldBuffer(br.a);
            level.fieldB = fieldBuffer(br.b);
            level.weight = float(br.weight);
        } else if (okA || okB) {
            level.fieldA = level.fieldB = fieldBuffer(okA ? br.a : br.b);
        } else {
            valid[size_t(j)] = false;
        }
    }
    // Hold the field across topology changes: outward from the level nearest t0.
    int centre = 0;
    for (int j = 1; j < count; ++j)
        if (std::abs(knots[size_t(j)] - t0) < std::abs(knots[size_t(centre)] - t0)) centre = j;
    if (!valid[size_t(centre)]) {
        // The frame's own step always agrees with itself.
        levels_.levels[size_t(centre)].fieldA = levels_.levels[size_t(centre)].fieldB = fieldBuffer(topology);
        valid[size_t(centre)] = true;
    }
    auto hold = [&](int j, int from) {
        TimeLevel& l = levels_.levels[size_t(j)];
        const TimeLevel& f = levels_.levels[size_t(from)];
        l.fieldA = f.fieldA;
        l.fieldB = f.fieldB;
        l.weight = f.weight;
    };
    for (int j = centre + 1; j < count; ++j)
        if (!valid[size_t(j)]) hold(j, j - 1);
    for (int j = centre - 1; j >= 0; --j)
        if (!valid[size_t(j)]) hold(j, j + 1);

    // GPU copies of steps that left the window are dropped.
    for (auto it = fields_.begin(); it != fields_.end();)
        it = (it->first < first.a || it->first > last.b) && it->first != topology ? fields_.erase(it) : std::next(it);
    return levels_;
}

}  // namespace flowsurf::methods
