#include "progress.h"

#include <unistd.h>

#include <cstdio>

namespace flowsurf::app {

ProgressBar::ProgressBar(std::string label, int total, bool enabled)
    : label_(std::move(label)), total_(total), enabled_(enabled && isatty(fileno(stderr))),
      start_(std::chrono::steady_clock::now()) {}

ProgressBar::~ProgressBar() {
    if (enabled_ && !finished_) std::fputc('\n', stderr);
}

void ProgressBar::update(int done, const std::string& note) {
    if (!enabled_) return;
    auto now = std::chrono::steady_clock::now();
    if (done < total_ && now - lastDraw_ < std::chrono::milliseconds(100)) return;
    lastDraw_ = now;
    double elapsed = std::chrono::duration<double>(now - start_).count();
    double eta = done > 0 ? elapsed * (total_ - done) / done : 0.0;
    const int width = 30;
    int filled = total_ > 0 ? width * done / total_ : width;
    std::string bar(size_t(filled), '#');
    bar.resize(width, '.');
    std::fprintf(stderr, "\r%s [%s] %d/%d %s  %.1fs, %.1fs left ", label_.c_str(), bar.c_str(), done, total_,
                 note.c_str(), elapsed, eta);
    std::fflush(stderr);
}

void ProgressBar::finish() {
    if (!enabled_ || finished_) return;
    update(total_);
    std::fputc('\n', stderr);
    finished_ = true;
}

}  // namespace flowsurf::app
