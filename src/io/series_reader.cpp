#include "io/series_reader.h"

#include "core/builtin_scenes.h"
#include "core/errors.h"
#include "io/reader_process.h"

#include <glob.h>

#include <algorithm>
#include <cstdlib>
#include <regex>
#include <sstream>

namespace flowsurf::io {

namespace {

// One file with one or more steps, each read when asked for by one reader process.
class FileSteps final : public core::StepProvider {
public:
    FileSteps(const std::string& path, const SourceOptions& options)
        : path_(path), info_(reader_.open(path, options)) {}
    size_t count() const override { return info_.times.empty() ? 1 : info_.times.size(); }
    double time(size_t i) const override { return info_.times.empty() ? 0.0 : info_.times[i]; }
    core::SurfaceMesh load(size_t i) override { return reader_.readStep(i, label(i)); }
    std::string label(size_t i) const override { return wire::stepLabel(path_, info_.times, i); }

private:
    std::string path_;
    detail::ReaderProcess reader_;
    detail::ReaderProcess::SourceInfo info_;
};

// Numbered files, one step each, read by one reader process with the same options (a
// CGNS or OpenFOAM series: the same patches of every file).
class PatternSteps final : public core::StepProvider {
public:
    PatternSteps(std::vector<std::string> files, std::vector<double> times, const SourceOptions& options)
        : files_(std::move(files)), times_(std::move(times)), options_(options) {}
    size_t count() const override { return files_.size(); }
    double time(size_t i) const override { return times_[i]; }
    core::SurfaceMesh load(size_t i) override {
        reader_.open(files_[i], options_);  // errors name the file
        return reader_.readStep(0, label(i));
    }
    std::string label(size_t i) const override {
        std::ostringstream s;
        s << files_[i] << " (step " << i + 1 << " of " << files_.size() << ", t = " << times_[i] << ")";
        return s.str();
    }

private:
    std::vector<std::string> files_;
    std::vector<double> times_;
    SourceOptions options_;
    detail::ReaderProcess reader_;
};

// "surf_%04d.vtp" -> glob "surf_*.vtp"; globs pass through.
std::string toGlob(const std::string& pattern) {
    static const std::regex printfInt("%0?[0-9]*d");
    return std::regex_replace(pattern, printfInt, "*");
}

// The number in `file` where the glob's first wildcard stands; NaN-free: falls back to -1.
bool numberAt(const std::string& globPattern, const std::string& file, double& value) {
    size_t star = globPattern.find_first_of("*?");
    if (star == std::string::npos) return false;
    std::string prefix = globPattern.substr(0, star);
    if (file.compare(0, prefix.size(), prefix) != 0) return false;
    const char* begin = file.c_str() + prefix.size();
    char* end = nullptr;
    value = std::strtod(begin, &end);
    return end != begin;
}

}  // namespace

bool isSeriesPattern(const std::string& input) { return input.find_first_of("%*?") != std::string::npos; }

std::unique_ptr<core::StepProvider> openSeries(const std::string& input, const SourceOptions& options) {
    if (!isSeriesPattern(input)) return std::make_unique<FileSteps>(input, options);
    const std::string pattern = toGlob(input);
    glob_t g{};
    int rc = glob(pattern.c_str(), 0, nullptr, &g);
    std::vector<std::string> files;
    if (rc == 0)
        for (size_t i = 0; i < g.gl_pathc; ++i) files.emplace_back(g.gl_pathv[i]);
    globfree(&g);
    if (files.empty()) throw IoError(input + ": no file matches this series pattern");
    // Order by the number in the name (numeric, not lexical: 9 before 10).
    std::vector<std::pair<double, std::string>> numbered;
    bool allNumbered = true;
    for (const auto& f : files) {
        double v = 0;
        allNumbered = allNumbered && numberAt(pattern, f, v);
        numbered.emplace_back(v, f);
    }
    if (allNumbered) std::stable_sort(numbered.begin(), numbered.end());
    std::vector<double> times;
    files.clear();
    for (size_t i = 0; i < numbered.size(); ++i) {
        files.push_back(numbered[i].second);
        times.push_back(allNumbered ? numbered[i].first : double(i));
    }
    for (size_t i = 1; i < times.size(); ++i)
        if (times[i] == times[i - 1])
            throw FormatError(input + ": " + files[i - 1] + " and " + files[i] + " have the same time " +
                              std::to_string(times[i]));
    return std::make_unique<PatternSteps>(std::move(files), std::move(times), options);
}

std::unique_ptr<core::StepProvider> openInput(const std::string& input, const SourceOptions& options) {
    if (core::isBuiltinSpec(input)) return std::make_unique<core::DatasetSteps>(core::makeBuiltin(input));
    return openSeries(input, options);
}

}  // namespace flowsurf::io
