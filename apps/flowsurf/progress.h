// flowsurf — a one-line progress bar on stderr (only when stderr is a terminal).
#pragma once

#include <chrono>
#include <string>

namespace flowsurf::app {

class ProgressBar {
public:
    ProgressBar(std::string label, int total, bool enabled);
    ~ProgressBar();
    // `note`: extra text after the counts (e.g. the data time).
    void update(int done, const std::string& note = "");
    void finish();

private:
    std::string label_;
    int total_;
    bool enabled_;
    bool finished_ = false;
    std::chrono::steady_clock::time_point start_, lastDraw_;
};

}  // namespace flowsurf::app
