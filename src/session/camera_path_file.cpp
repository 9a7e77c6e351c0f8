#include "session/camera_path_file.h"

#include "core/errors.h"
#include "session/options/json_file.h"

#include <nlohmann/json.hpp>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>

namespace flowsurf::session {

namespace {

glm::vec3 vec3At(const nlohmann::ordered_json& k, const char* key, const glm::vec3& fallback, const std::string& where) {
    if (!k.contains(key)) return fallback;
    const auto& v = k.at(key);
    if (!v.is_array() || v.size() != 3 || !v[0].is_number() || !v[1].is_number() || !v[2].is_number())
        throw FormatError(where + ": \"" + key + "\" must be [x, y, z]");
    glm::vec3 r(v[0].get<float>(), v[1].get<float>(), v[2].get<float>());
    if (!std::isfinite(r.x) || !std::isfinite(r.y) || !std::isfinite(r.z))
        throw FormatError(where + ": \"" + key + "\" is not finite");
    return r;
}

}  // namespace

core::CameraPath readCameraPath(const std::string& path, const core::Camera& defaults) {
    const nlohmann::ordered_json doc = readJsonFile(path);
    if (!doc.is_object() || !doc.contains("keyframes") || !doc["keyframes"].is_array() || doc["keyframes"].empty())
        throw FormatError(path + ": expected {\"keyframes\": [ ... ]} with at least one keyframe");
    std::vector<core::CameraKeyframe> keys;
    for (size_t i = 0; i < doc["keyframes"].size(); ++i) {
        const auto& k = doc["keyframes"][i];
        const std::string where = path + ": keyframe " + std::to_string(i);
        if (!k.is_object() || !k.contains("frame") || !k["frame"].is_number_integer() || k["frame"].get<long>() < 0)
            throw FormatError(where + ": needs \"frame\", a non-negative integer");
        if (!k.contains("eye")) throw FormatError(where + ": needs \"eye\"");
        core::CameraKeyframe key;
        key.frame = int(k["frame"].get<long>());
        key.camera = defaults;
        key.camera.eye = vec3At(k, "eye", defaults.eye, where);
        key.camera.target = vec3At(k, "target", defaults.target, where);
        key.camera.up = vec3At(k, "up", defaults.up, where);
        if (k.contains("fov")) {
            if (!k["fov"].is_number() || k["fov"].get<float>() <= 0.0f || k["fov"].get<float>() >= 180.0f)
                throw FormatError(where + ": \"fov\" must be a number of degrees in (0, 180)");
            key.camera.fovDeg = k["fov"].get<float>();
        }
        if (glm::length(key.camera.eye - key.camera.target) == 0.0f)
            throw FormatError(where + ": eye and target coincide");
        keys.push_back(key);
    }
    return core::CameraPath(std::move(keys));
}

}  // namespace flowsurf::session
