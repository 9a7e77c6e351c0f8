#include "session/options/config_file.h"

#include "core/errors.h"
#include "session/options/json_file.h"

#include <nlohmann/json.hpp>

#include <cerrno>
#include <cstring>
#include <fstream>

namespace flowsurf::session {

namespace {

// A JSON value as the option's command-line text.
std::string valueText(const OptionSpec& spec, const nlohmann::ordered_json& v, const std::string& where) {
    if (v.is_string()) return v.get<std::string>();
    if (v.is_boolean()) {
        if (spec.kind == OptionKind::Choice && spec.choices == std::vector<std::string>{"on", "off"})
            return v.get<bool>() ? "on" : "off";
        return v.get<bool>() ? "true" : "false";
    }
    if (v.is_number_integer()) return std::to_string(v.get<long long>());
    if (v.is_number_unsigned()) return std::to_string(v.get<unsigned long long>());
    if (v.is_number_float()) return formatDouble(v.get<double>());
    if (v.is_array()) {
        std::string text;
        for (const auto& e : v) {
            if (!e.is_number()) throw ConfigError(where + ": array elements must be numbers");
            text += (text.empty() ? "" : spec.arraySeparator) + (e.is_number_float() ? formatDouble(e.get<double>())
                                                                      : std::to_string(e.get<long long>()));
        }
        return text;
    }
    throw ConfigError(where + ": expected a string, number, boolean or array");
}

}  // namespace

void applyConfigFile(const std::string& path, RenderOptions& o) {
    const nlohmann::ordered_json doc = readJsonFile(path);
    if (!doc.is_object()) throw FormatError(path + ": expected a JSON object of option names and values");
    for (const auto& [key, value] : doc.items()) {
        if (key == "flowsurf-config") {
            if (value != 1) throw FormatError(path + ": \"flowsurf-config\" version " + value.dump() + " is not 1");
            continue;
        }
        const std::string where = path + ": \"" + key + "\"";
        const OptionSpec* spec = findOption(key);
        if (!spec) throw ConfigError(where + " is not a flowsurf option (see flowsurf render --help)");
        try {
            spec->set(o, valueText(*spec, value, where));
        } catch (const ConfigError& e) {
            throw ConfigError(path + ": " + e.what());
        }
    }
}

std::string configJson(const RenderOptions& o) {
    nlohmann::ordered_json doc;
    doc["flowsurf-config"] = 1;
    for (const OptionSpec& spec : renderOptionTable()) {
        if (!spec.takes(FrontEnd::Config)) continue;
        const std::string text = spec.get(o);
        if (text.empty()) continue;
        switch (spec.kind) {
        case OptionKind::Flag: doc[spec.name] = text == "true"; break;
        case OptionKind::Int: doc[spec.name] = std::stoll(text); break;
        case OptionKind::Float: doc[spec.name] = std::stod(text); break;
        case OptionKind::Vec3:
        case OptionKind::Color: {
            nlohmann::json xyz = nlohmann::json::array();
            size_t start = 0;
            for (size_t comma; (comma = text.find(',', start)) != std::string::npos; start = comma + 1)
                xyz.push_back(std::stod(text.substr(start, comma - start)));
            xyz.push_back(std::stod(text.substr(start)));
            doc[spec.name] = xyz;
            break;
        }
        default: doc[spec.name] = text; break;
        }
    }
    return doc.dump(2) + "\n";
}


std::optional<std::string> findConfigArgument(int argc, const char* const* argv) {
    std::optional<std::string> found;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--") break;
        if (a == "--config") {
            if (i + 1 >= argc) throw ConfigError("--config needs a FILE");
            found = argv[++i];
        } else if (a.rfind("--config=", 0) == 0) {
            found = a.substr(9);
        }
    }
    return found;
}

}  // namespace flowsurf::session
