// flowsurf — the value syntaxes of the options: numbers, WxH, x,y,z, colours, output
// kinds, and numbers as the shortest text that reads back exactly.
#include "session/options/options.h"

#include "core/camera.h"
#include "core/errors.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <type_traits>

namespace flowsurf::session {

namespace {

// A whole string as a finite number of type T (float: rounded once, as strtof does).
template <typename T>
T parseFinite(const std::string& s, const std::string& what) {
    try {
        size_t used = 0;
        T v;
        if constexpr (std::is_same_v<T, float>) v = std::stof(s, &used);
        else v = std::stod(s, &used);
        if (used != s.size() || !std::isfinite(v)) throw std::invalid_argument(s);
        return v;
    } catch (const std::exception&) {
        throw ConfigError(what + ": '" + s + "' is not a finite number");
    }
}

}  // namespace

float parseFloat(const std::string& s, const std::string& what) { return parseFinite<float>(s, what); }

std::vector<methods::Method> parseMethodList(const std::string& text, const std::string& what) {
    std::vector<methods::Method> out;
    std::stringstream ss(text);
    for (std::string m; std::getline(ss, m, ',');)
        if (!m.empty()) out.push_back(parseName(methods::kMethodNames, m, what));
    return out;
}

namespace {

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
    return s;
}

}  // namespace

core::Viewport parseSize(const std::string& text, const std::string& what) {
    int w = 0, h = 0;
    char x = 0, extra = 0;
    if (std::sscanf(text.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || (x != 'x' && x != 'X'))
        throw ConfigError(what + ": '" + text + "' is not WIDTHxHEIGHT (e.g. 800x600)");
    if (w < core::kMinImageSide || h < core::kMinImageSide || w > core::kMaxImageSide || h > core::kMaxImageSide)
        throw ConfigError(what + ": " + text + " is out of range (each side " + std::to_string(core::kMinImageSide) +
                          ".." + std::to_string(core::kMaxImageSide) + " pixels)");
    return {w, h};
}

glm::vec3 parseVec3(const std::string& text, const std::string& what) {
    std::vector<std::string> parts;
    std::stringstream ss(text);
    for (std::string p; std::getline(ss, p, ',');) parts.push_back(p);
    if (parts.size() != 3) throw ConfigError(what + ": '" + text + "' is not x,y,z");
    return {parseFloat(parts[0], what), parseFloat(parts[1], what), parseFloat(parts[2], what)};
}

glm::vec3 parseColor(const std::string& text, const std::string& what) {
    if (!text.empty() && text[0] == '#') {
        unsigned v = 0;
        char extra = 0;
        if (text.size() != 7 || std::sscanf(text.c_str() + 1, "%6x%c", &v, &extra) != 1)
            throw ConfigError(what + ": '" + text + "' is not #RRGGBB");
        return glm::vec3(float((v >> 16) & 255), float((v >> 8) & 255), float(v & 255)) / 255.0f;
    }
    std::string t = lower(text);
    if (t == "black") return glm::vec3(0.0f);
    if (t == "white") return glm::vec3(1.0f);
    if (t == "gray" || t == "grey") return glm::vec3(0.5f);
    // Dye colours by name (--dye): full-saturation hues.
    static const std::pair<const char*, glm::vec3> kNamed[] = {
        {"red", {1, 0, 0}},    {"green", {0, 0.8f, 0}}, {"blue", {0, 0.2f, 1}},     {"yellow", {1, 0.9f, 0}},
        {"cyan", {0, 0.9f, 1}}, {"magenta", {1, 0, 1}},  {"orange", {1, 0.5f, 0}}};
    for (const auto& [name, c] : kNamed)
        if (t == name) return c;
    if (text.find(',') == std::string::npos) {
        std::string names = "black, white, gray";
        for (const auto& named : kNamed) names += std::string(", ") + named.first;
        throw ConfigError(what + ": '" + text + "' is not a colour (#RRGGBB, r,g,b in 0..1, or one of " + names + ")");
    }
    glm::vec3 c = parseVec3(text, what);
    if (glm::any(glm::lessThan(c, glm::vec3(0.0f))) || glm::any(glm::greaterThan(c, glm::vec3(1.0f))))
        throw ConfigError(what + ": components of '" + text + "' must be in 0..1");
    return c;
}

OutputKind outputKind(const std::string& path) {
    std::string l = lower(path);
    auto ends = [&](const std::string& e) { return l.size() >= e.size() && l.compare(l.size() - e.size(), e.size(), e) == 0; };
    if (ends(".mp4")) return OutputKind::Mp4;
    if (ends(".png")) return l.find('%') != std::string::npos ? OutputKind::PngSequence : OutputKind::Png;
    throw ConfigError("--output: '" + path + "' must end in .png, .mp4, or be a %04d.png pattern");
}

std::string formatFloat(float value) {
    char buf[64];
    for (int digits = 1; digits <= 9; ++digits) {  // the shortest text that reads back exactly
        std::snprintf(buf, sizeof buf, "%.*g", digits, double(value));
        if (std::strtof(buf, nullptr) == value) break;
    }
    return buf;
}

std::string formatDouble(double value) {
    char buf[64];
    for (int digits = 1; digits <= 17; ++digits) {
        std::snprintf(buf, sizeof buf, "%.*g", digits, value);
        if (std::strtod(buf, nullptr) == value) break;
    }
    return buf;
}

double parseNumber(const std::string& s, const std::string& what) { return parseFinite<double>(s, what); }

}  // namespace flowsurf::session
