#include "session/options/dye_sources.h"

#include "core/errors.h"
#include "session/options/json_file.h"
#include "session/options/options.h"

#include <cmath>
#include <cstdio>
#include <iterator>
#include <sstream>

namespace flowsurf::session {

namespace {
glm::vec3 paletteColor(size_t i) { return methods::kDyePalette[i % std::size(methods::kDyePalette)]; }

std::string colorText(const glm::vec3& c) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "#%02x%02x%02x", int(std::lround(c.r * 255.0f)), int(std::lround(c.g * 255.0f)),
                  int(std::lround(c.b * 255.0f)));
    return buf;
}

// Quantised to what "#rrggbb" can say, so that the text reads back to the same source.
glm::vec3 quantised(const glm::vec3& c) { return glm::round(glm::clamp(c, 0.0f, 1.0f) * 255.0f) / 255.0f; }

float checkedRadius(float r, const std::string& what, const std::string& item) {
    if (!(r >= 0.0f) || !std::isfinite(r))
        throw ConfigError(what + ": radius in '" + item + "' must be >= 0 (0: a few pixels)");
    return r;
}
}  // namespace

methods::DyeSource dyeSource(const glm::vec3& point, float radius, const std::optional<std::string>& color,
                             size_t index, const std::string& what) {
    if (!std::isfinite(point.x) || !std::isfinite(point.y) || !std::isfinite(point.z))
        throw ConfigError(what + ": the point " + formatFloat(point.x) + "," + formatFloat(point.y) + "," +
                          formatFloat(point.z) + " is not finite");
    methods::DyeSource s;
    s.point = point;  // formatFloat writes what reads back exactly
    s.radius = checkedRadius(radius, what, formatFloat(radius));
    s.color = quantised(color ? parseColor(*color, what) : paletteColor(index));
    return s;
}

std::vector<methods::DyeSource> parseDyeSources(const std::string& text, const std::string& what) {
    std::vector<methods::DyeSource> out;
    std::stringstream ss(text);
    for (std::string item; std::getline(ss, item, ';');) {
        if (item.empty()) continue;
        const size_t c1 = item.find(':');
        const size_t c2 = c1 == std::string::npos ? std::string::npos : item.find(':', c1 + 1);
        const glm::vec3 point = parseVec3(item.substr(0, c1), what);
        float radius = 0.0f;
        if (c1 != std::string::npos) {
            const std::string r = item.substr(c1 + 1, c2 == std::string::npos ? std::string::npos : c2 - c1 - 1);
            radius = r.empty() ? 0.0f : checkedRadius(parseFloat(r, what), what, item);
        }
        const std::optional<std::string> color =
            c2 == std::string::npos ? std::nullopt : std::optional<std::string>(item.substr(c2 + 1));
        out.push_back(dyeSource(point, radius, color, out.size(), what));
    }
    return out;
}

std::string dyeSourcesText(const std::vector<methods::DyeSource>& sources) {
    std::string out;
    for (const methods::DyeSource& s : sources) {
        if (!out.empty()) out += ';';
        out += formatFloat(s.point.x) + "," + formatFloat(s.point.y) + "," + formatFloat(s.point.z) + ":" +
               formatFloat(s.radius) + ":" + colorText(s.color);
    }
    return out;
}

std::vector<methods::DyeSource> readDyeFile(const std::string& path) {
    const nlohmann::ordered_json doc = readJsonFile(path);
    const nlohmann::ordered_json& list = doc.is_object() && doc.contains("sources") ? doc["sources"] : doc;
    if (!list.is_array()) throw ConfigError(path + ": expected a list of dye sources (or {\"sources\": [...]})");
    std::vector<methods::DyeSource> out;
    for (size_t i = 0; i < list.size(); ++i) {
        const auto& e = list[i];
        const std::string where = path + ": source " + std::to_string(i);
        if (!e.is_object() || !e.contains("point") || !e["point"].is_array() || e["point"].size() != 3)
            throw ConfigError(where + ": \"point\" must be [x, y, z]");
        methods::DyeSource s;
        for (int k = 0; k < 3; ++k) {
            if (!e["point"][size_t(k)].is_number()) throw ConfigError(where + ": \"point\" must be [x, y, z]");
            s.point[k] = e["point"][size_t(k)].get<float>();
        }
        if (e.contains("radius")) {
            if (!e["radius"].is_number()) throw ConfigError(where + ": \"radius\" is not a number");
            s.radius = checkedRadius(e["radius"].get<float>(), where, "radius");
        }
        s.color = paletteColor(i);
        if (e.contains("color")) {
            const auto& c = e["color"];
            if (c.is_string()) s.color = parseColor(c.get<std::string>(), where);
            else if (c.is_array() && c.size() == 3 && c[0].is_number() && c[1].is_number() && c[2].is_number())
                s.color = parseColor(std::to_string(c[0].get<float>()) + "," + std::to_string(c[1].get<float>()) + "," +
                                     std::to_string(c[2].get<float>()), where);
            else throw ConfigError(where + ": \"color\" must be a name, #rrggbb or [r, g, b]");
        }
        for (const char* key : {"start", "stop"}) {
            if (!e.contains(key)) continue;
            const auto& v = e[key];
            if (!v.is_number_integer() || v.get<long long>() < 0 || v.get<long long>() > 100000000)
                throw ConfigError(where + ": \"" + key + "\" must be a frame number >= 0");
            (std::string(key) == "start" ? s.start : s.stop) = int(v.get<long long>());
        }
        if (s.stop >= 0 && s.stop <= s.start)
            throw ConfigError(where + ": \"stop\" (" + std::to_string(s.stop) + ") must be after \"start\" (" +
                              std::to_string(s.start) + ")");
        out.push_back(s);
    }
    return out;
}

}  // namespace flowsurf::session
