#include "gl/stage_timer.h"

#include <epoxy/gl.h>

namespace flowsurf::gl {

namespace {

// Frames left on the GPU before beginFrame waits for the oldest (a caller that never
// asks for meanMs() must not grow the list).
constexpr size_t kMaxPending = 8;

}  // namespace

void StageTimer::beginFrame() {
    if (!enabled_) return;
    if (queries_ < 0)
        queries_ = !synchronous_ && (epoxy_gl_version() >= 33 || epoxy_has_gl_extension("GL_ARB_timer_query"));
    if (!queries_) {
        glFinish();
        stage_.clear();
        since_ = Clock::now();
        cpuSince_ = std::clock();
        return;
    }
    recycle(current_);  // a frame that never ended (an exception mid-frame)
    collect(kMaxPending - 1);
    mark("");
}

void StageTimer::begin(const char* name) {
    if (!enabled_) return;
    mark(name);
}

void StageTimer::endFrame() {
    if (!enabled_) return;
    mark("");
    if (queries_ > 0) {
        pending_.push_back(std::move(current_));
        current_.clear();
    } else if (queries_ == 0) {
        ++frames_;
    }
}

void StageTimer::mark(const char* stage) {
    if (queries_ < 0) return;  // begin() before any beginFrame(): nothing to time against
    if (!queries_) {
        glFinish();
        const auto now = Clock::now();
        const std::clock_t cpu = std::clock();
        if (!stage_.empty()) {
            add(stage_, std::chrono::duration<double, std::milli>(now - since_).count());
            totalCpuMs_[stage_] += double(cpu - cpuSince_) * 1e3 / CLOCKS_PER_SEC;
        }
        stage_ = stage;
        since_ = now;
        cpuSince_ = cpu;
        return;
    }
    Mark m{stage, {}};
    if (free_.empty()) {
        GLuint id = 0;
        glCreateQueries(GL_TIMESTAMP, 1, &id);
        m.query = Query(id);
    } else {
        m.query = std::move(free_.back());
        free_.pop_back();
    }
    glQueryCounter(m.query.id(), GL_TIMESTAMP);
    current_.push_back(std::move(m));
}

void StageTimer::collect(size_t keep) const {
    while (!pending_.empty()) {
        std::vector<Mark>& marks = pending_.front();
        if (pending_.size() <= keep) {
            // Queries complete in order: the frame's last one tells for all.
            GLuint64 ready = 0;
            glGetQueryObjectui64v(marks.back().query.id(), GL_QUERY_RESULT_AVAILABLE, &ready);
            if (!ready) return;
        }
        std::vector<GLuint64> ns(marks.size());
        for (size_t i = 0; i < marks.size(); ++i) glGetQueryObjectui64v(marks[i].query.id(), GL_QUERY_RESULT, &ns[i]);
        for (size_t i = 0; i + 1 < marks.size(); ++i)
            if (!marks[i].stage.empty()) add(marks[i].stage, double(ns[i + 1] - ns[i]) * 1e-6);
        ++frames_;
        recycle(marks);
        pending_.pop_front();
    }
}

void StageTimer::recycle(std::vector<Mark>& marks) const {
    for (Mark& m : marks) free_.push_back(std::move(m.query));
    marks.clear();
}

void StageTimer::add(const std::string& stage, double ms) const {
    if (!totalMs_.count(stage)) order_.push_back(stage);
    totalMs_[stage] += ms;
}

std::vector<std::pair<std::string, double>> StageTimer::meanMs(bool waitForGpu) const {
    collect(waitForGpu ? 0 : kMaxPending);
    std::vector<std::pair<std::string, double>> out;
    for (const auto& n : order_) out.emplace_back(n, frames_ ? totalMs_.at(n) / frames_ : 0.0);
    return out;
}

std::vector<std::pair<std::string, double>> StageTimer::meanCpuMs() const {
    std::vector<std::pair<std::string, double>> out;
    if (queries_ != 0) return out;
    for (const auto& n : order_) {
        const auto it = totalCpuMs_.find(n);
        out.emplace_back(n, frames_ && it != totalCpuMs_.end() ? it->second / frames_ : 0.0);
    }
    return out;
}

void StageTimer::reset() {
    for (auto& marks : pending_) recycle(marks);
    pending_.clear();
    order_.clear();
    totalMs_.clear();
    totalCpuMs_.clear();
    frames_ = 0;
}

}  // namespace flowsurf::gl
