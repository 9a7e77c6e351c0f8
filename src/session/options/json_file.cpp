#include "session/options/json_file.h"

#include "core/errors.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace flowsurf::session {

nlohmann::ordered_json readJsonFile(const std::string& path) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) throw IoError(path + ": cannot read (it is a folder)");
    std::ifstream f(path);
    if (!f) throw IoError(path + ": cannot open (" + std::strerror(errno) + ")");
    try {
        return nlohmann::ordered_json::parse(f);
    } catch (const nlohmann::json::exception& e) {  // parse_error, and out_of_range for 1e999
        throw FormatError(path + ": not valid JSON (" + e.what() + ")");
    } catch (const std::ios_base::failure& e) {  // a read error under the stream (found by fuzz_options)
        throw IoError(path + ": cannot read (" + e.what() + ")");
    }
}

}  // namespace flowsurf::session
