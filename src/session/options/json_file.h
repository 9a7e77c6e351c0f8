// flowsurf — reading a small JSON file (config, camera path, keyframes): one place that
// turns "cannot open" into IoError and a syntax error into FormatError, naming the file.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace flowsurf::session {

// The document, keys in file order. Throws IoError or FormatError naming `path`.
nlohmann::ordered_json readJsonFile(const std::string& path);

}  // namespace flowsurf::session
