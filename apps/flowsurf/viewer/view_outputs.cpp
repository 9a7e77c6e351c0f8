#include "view_outputs.h"

#include "core/errors.h"
#include "io/text_writer.h"
#include "session/options/json_file.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>

namespace flowsurf::app::view {

namespace {

// Per view: frames measured, and the median and worst of each metric (null: none).
nlohmann::ordered_json qualityStats(ViewPipeline& pipeline) {
    nlohmann::ordered_json views = nlohmann::ordered_json::object();
    for (size_t i = 0; i < pipeline.viewCount(); ++i) {
        const quality::QualitySummary s = pipeline.playback().quality().summary(i);
        auto value = [](double v) { return std::isnan(v) ? nlohmann::ordered_json() : nlohmann::ordered_json(v); };
        nlohmann::ordered_json median = nlohmann::ordered_json::object(), worst = median;
        for (const quality::MetricInfo& m : quality::metricTable()) {
            median[m.name] = value(s.median.*m.member);
            worst[m.name] = value(s.worst.*m.member);
        }
        views[pipeline.methodName(i)] = {{"frames", s.frames}, {"median", median}, {"worst", worst}};
    }
    return views;
}

}  // namespace

void appendKeyframe(const std::string& path, const core::Camera& c, uint32_t frame) {
    nlohmann::ordered_json doc = {{"keyframes", nlohmann::json::array()}};
    if (std::ifstream(path).good()) {
        doc = readJsonFile(path);
        if (!doc.is_object() || !doc.contains("keyframes") || !doc["keyframes"].is_array())
            throw FormatError(path + ": expected {\"keyframes\": [...]}; not appending to it");
    }
    auto& keys = doc["keyframes"];
    if (!keys.empty() && keys.back().contains("frame") && keys.back()["frame"].is_number_integer() &&
        keys.back()["frame"].get<long>() >= long(frame))
        frame = uint32_t(keys.back()["frame"].get<long>() + 30);  // keyframes must move forward
    keys.push_back({{"frame", frame},
                    {"eye", {c.eye.x, c.eye.y, c.eye.z}},
                    {"target", {c.target.x, c.target.y, c.target.z}},
                    {"up", {c.up.x, c.up.y, c.up.z}},
                    {"fov", c.fovDeg}});
    io::writeTextFile(path, doc.dump(2) + "\n");
}

std::string statsJson(ViewPipeline& pipeline, const std::vector<double>& frameMs, const std::string& renderer,
                      bool quality) {
    nlohmann::ordered_json doc;
    doc["frame_ms"] = frameMs;
    nlohmann::ordered_json stages = nlohmann::ordered_json::object();
    for (size_t i = 0; pipeline.ready() && i < pipeline.viewCount(); ++i)
        for (const auto& [stage, ms] : pipeline.method(i).timer().meanMs())
            stages[pipeline.viewCount() > 1 ? pipeline.methodName(i) + "/" + stage : stage] = ms;
    doc["stage_ms"] = stages;
    doc["renderer"] = renderer;
    doc["view_size"] = {pipeline.viewSize().width, pipeline.viewSize().height};
    if (pipeline.ready() && quality) doc["quality"] = qualityStats(pipeline);
    return doc.dump(2) + "\n";
}

}  // namespace flowsurf::app::view
