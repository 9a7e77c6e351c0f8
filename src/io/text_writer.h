// flowsurf — small text outputs (config files, camera paths, event logs, timing JSON),
// written through the same write-then-rename as images: never a partial file.
#pragma once

#include <string>

namespace flowsurf::io {

// Writes `content` to `path` atomically. Throws IoError naming the path and the reason.
void writeTextFile(const std::string& path, const std::string& content);

}  // namespace flowsurf::io
