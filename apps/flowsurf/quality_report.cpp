#include "quality_report.h"

#include "core/errors.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <cstdio>

namespace flowsurf::app {

namespace {

nlohmann::ordered_json number(double v) { return std::isnan(v) ? nlohmann::ordered_json() : nlohmann::ordered_json(v); }

nlohmann::ordered_json metrics(const quality::FrameQuality& q) {
    nlohmann::ordered_json j = nlohmann::ordered_json::object();
    for (const quality::MetricInfo& m : quality::metricTable()) j[m.name] = number(q.*m.member);
    return j;
}

std::string cell(double median, double worst, int decimals) {
    if (std::isnan(median)) return "-";
    char a[32], b[32];
    std::snprintf(a, sizeof a, "%.*f", decimals, median);
    std::snprintf(b, sizeof b, "%.*f", decimals, worst);
    return std::string(b) == a || std::isnan(worst) ? std::string(a) : std::string(a) + " (" + b + ")";
}

}  // namespace

void validateQualityOutput(const QualityOutput& q) {
    if (q.every < 1) throw ConfigError("--quality-every: measure every N frames, N >= 1 (got " + std::to_string(q.every) + ")");
    if (q.file.empty()) return;
    const std::string ext = ".json";
    if (q.file.size() <= ext.size() || q.file.compare(q.file.size() - ext.size(), ext.size(), ext) != 0)
        throw ConfigError("--quality: '" + q.file + "' must be a .json file");
    // Checked now so that a report that cannot be written fails before any other output.
    const std::filesystem::path dir = std::filesystem::path(q.file).parent_path();
    std::error_code ec;
    if (!dir.empty() && !std::filesystem::is_directory(dir, ec))
        throw IoError("--quality: cannot write '" + q.file + "': no directory '" + dir.string() + "'");
}

std::string qualityJson(const session::RenderOptions& o, const std::string& command, const std::string& glRenderer,
                        int every, const std::vector<MethodQuality>& methods) {
    nlohmann::ordered_json doc;
    doc["flowsurf_quality"] = 1;
    doc["command"] = command;
    doc["gl_renderer"] = glRenderer;
    nlohmann::ordered_json options = nlohmann::ordered_json::object();
    for (const session::OptionSpec& s : session::renderOptionTable()) options[s.name] = s.get(o);
    doc["options"] = options;
    const quality::QualityParams p;
    doc["metric_parameters"] = {{"structure_tensor_sigma_px", p.sigmaPx},
                                {"min_coherence", p.minCoherence},
                                {"min_speed_fraction_of_p95", p.minSpeed},
                                {"edge_band_px", p.edgeBandPx},
                                {"max_lag_px", p.maxLagPx},
                                {"every_frames", every}};
    nlohmann::ordered_json help = nlohmann::ordered_json::object();
    for (const quality::MetricInfo& m : quality::metricTable()) help[m.name] = m.help;
    doc["metrics"] = help;
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (const MethodQuality& m : methods) {
        nlohmann::ordered_json j;
        j["method"] = m.method;
        j["ms_per_frame"] = number(m.msPerFrame);
        j["frames_measured"] = m.summary.frames;
        j["median"] = metrics(m.summary.median);
        j["worst"] = metrics(m.summary.worst);
        nlohmann::ordered_json frames = nlohmann::ordered_json::array();
        for (const quality::FrameQuality& f : m.frames) {
            nlohmann::ordered_json fj = {{"frame", f.frame}};
            fj.update(metrics(f));
            frames.push_back(fj);
        }
        j["frames"] = frames;
        list.push_back(j);
    }
    doc["methods"] = list;
    return doc.dump(2) + "\n";
}

std::string qualityTable(const std::vector<MethodQuality>& methods) {
    // Columns: the metric table's order; decimals per metric.
    struct Column {
        const char* title;
        double quality::FrameQuality::*member;
        int decimals;
    };
    static const Column kColumns[] = {{"orient_err", &quality::FrameQuality::orientationErrorDeg, 1},
                                      {"p90", &quality::FrameQuality::orientationErrorP90Deg, 1},
                                      {"counted", &quality::FrameQuality::countedFraction, 2},
                                      {"frame_corr", &quality::FrameQuality::frameCorrelation, 3},
                                      {"reproj_corr", &quality::FrameQuality::frameCorrelationReprojected, 3},
                                      {"contrast", &quality::FrameQuality::contrast, 3},
                                      {"edge_ratio", &quality::FrameQuality::edgeContrastRatio, 2},
                                      {"feature_px", &quality::FrameQuality::frequencyPx, 1}};
    static_assert(std::size(kColumns) == std::tuple_size_v<std::decay_t<decltype(quality::metricTable())>>);
    std::vector<std::vector<std::string>> rows;
    std::vector<std::string> head{"method", "frames"};
    for (const Column& c : kColumns) head.push_back(c.title);
    head.push_back("ms/frame");
    rows.push_back(head);
    for (const MethodQuality& m : methods) {
        std::vector<std::string> r{m.method, std::to_string(m.summary.frames)};
        for (const Column& c : kColumns)
            r.push_back(cell(m.summary.median.*c.member, m.summary.worst.*c.member, c.decimals));
        r.push_back(cell(m.msPerFrame, m.msPerFrame, 1));
        rows.push_back(r);
    }
    std::vector<size_t> width(head.size(), 0);
    for (const auto& r : rows)
        for (size_t i = 0; i < r.size(); ++i) width[i] = std::max(width[i], r[i].size());
    std::string out;
    for (const auto& r : rows) {
        for (size_t i = 0; i < r.size(); ++i) {
            out += r[i];
            if (i + 1 < r.size()) out += std::string(width[i] - r[i].size() + 2, ' ');
        }
        out += "\n";
    }
    return out;
}

}  // namespace flowsurf::app
