#include "gl/stage_timer.h"

#include <epoxy/gl.h>

namespace flowsurf::gl {

void StageTimer::beginFrame() {
    if (!enabled_) return;
    glFinish();
    current_.clear();
    mark_ = Clock::now();
}

void StageTimer::close() {
    glFinish();
    auto now = Clock::now();
    if (!current_.empty()) {
        if (!totalMs_.count(current_)) order_.push_back(current_);
        totalMs_[current_] += std::chrono::duration<double, std::milli>(now - mark_).count();
    }
    mark_ = now;
}

void StageTimer::begin(const char* name) {
    if (!enabled_) return;
    close();
    current_ = name;
}

void StageTimer::endFrame() {
    if (!enabled_) return;
    close();
    current_.clear();
    ++frames_;
}

std::vector<std::pair<std::string, double>> StageTimer::meanMs() const {
    std::vector<std::pair<std::string, double>> out;
    for (const auto& n : order_) out.emplace_back(n, frames_ ? totalMs_.at(n) / frames_ : 0.0);
    return out;
}

void StageTimer::reset() {
    order_.clear();
    totalMs_.clear();
    frames_ = 0;
}

}  // namespace flowsurf::gl
