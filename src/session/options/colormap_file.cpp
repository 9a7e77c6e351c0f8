#include "session/options/colormap_file.h"

#include "core/errors.h"
#include "session/options/json_file.h"

#include <algorithm>

namespace flowsurf::session {

std::vector<glm::vec3> readParaViewColormap(const std::string& path) {
    const nlohmann::ordered_json doc = readJsonFile(path);
    const nlohmann::ordered_json& preset = doc.is_array() && !doc.empty() ? doc[0] : doc;
    if (!preset.is_object() || !preset.contains("RGBPoints") || !preset["RGBPoints"].is_array())
        throw ConfigError(path + ": no \"RGBPoints\" list (expected a ParaView colour map preset)");
    const auto& pts = preset["RGBPoints"];
    if (pts.size() < 8 || pts.size() % 4 != 0)
        throw ConfigError(path + ": \"RGBPoints\" must hold x, r, g, b for two or more points (has " +
                          std::to_string(pts.size()) + " numbers)");
    std::vector<std::pair<double, glm::vec3>> points;
    for (size_t i = 0; i < pts.size(); i += 4) {
        for (size_t k = 0; k < 4; ++k)
            if (!pts[i + k].is_number())
                throw ConfigError(path + ": \"RGBPoints\" entry " + std::to_string(i + k) + " is not a number");
        points.push_back({pts[i].get<double>(), glm::clamp(glm::vec3(pts[i + 1].get<float>(), pts[i + 2].get<float>(),
                                                                       pts[i + 3].get<float>()),
                                                             0.0f, 1.0f)});
    }
    std::stable_sort(points.begin(), points.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    const double lo = points.front().first, hi = points.back().first;
    std::vector<glm::vec3> table(256);
    for (int i = 0; i < 256; ++i) {
        const double x = lo + (hi - lo) * i / 255.0;
        size_t j = 1;
        while (j + 1 < points.size() && points[j].first < x) ++j;
        const double span = points[j].first - points[j - 1].first;
        const float w = span > 0.0 ? float(std::clamp((x - points[j - 1].first) / span, 0.0, 1.0)) : 1.0f;
        table[size_t(i)] = glm::mix(points[j - 1].second, points[j].second, w);
    }
    return table;
}

}  // namespace flowsurf::session
