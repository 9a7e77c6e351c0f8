// flowsurf — the option rows' helpers that are not templates (option_rows.h).
#include "session/options/option_rows.h"

namespace flowsurf::session::rows {

std::string dashed(const std::string& name) { return "--" + name; }

std::string vec3Text(const glm::vec3& v) {
    return formatFloat(v.x) + "," + formatFloat(v.y) + "," + formatFloat(v.z);
}

glm::vec2 parseRange(const std::string& v, const std::string& what) {
    auto colon = v.find(':', v[0] == '-' ? 1 : 0);
    while (colon != std::string::npos && colon > 0 && (v[colon - 1] == 'e' || v[colon - 1] == 'E'))
        colon = v.find(':', colon + 1);
    if (colon == std::string::npos) throw ConfigError(what + ": '" + v + "' is not MIN:MAX");
    const glm::vec2 r(parseFloat(v.substr(0, colon), what), parseFloat(v.substr(colon + 1), what));
    if (!(r.x < r.y)) throw ConfigError(what + ": '" + v + "': MIN must be less than MAX");
    return r;
}

OptionSpec shortNamed(std::string shortName, OptionSpec spec) {
    spec.shortName = std::move(shortName);
    return spec;
}

OptionSpec vec3(std::string name, OptionRole role, std::string help, std::optional<glm::vec3> RenderOptions::*field) {
    const std::string n = name;
    return {.name = std::move(name),
            .role = role,
            .help = std::move(help),
            .kind = OptionKind::Vec3,
            .set = [n, field](RenderOptions& o, const std::string& t) {
                if (t.empty()) o.*field = std::nullopt;
                else o.*field = parseVec3(t, dashed(n));
            },
            .get = [field](const RenderOptions& o) { return o.*field ? vec3Text(*(o.*field)) : std::string(); }};
}

}  // namespace flowsurf::session::rows
