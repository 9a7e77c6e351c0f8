// flowsurf — where flowsurf's own files are found at run time (the reader process, the label
// font), so that an installed tree or an unpacked tarball works from any folder: PREFIX/bin,
// PREFIX/lib -> PREFIX/libexec/flowsurf/, PREFIX/share/flowsurf/.
#pragma once

#include <filesystem>
#include <vector>

namespace flowsurf::core {

// The folder of the binary or shared library this code is linked into (dladdr), then the
// folder of the running program (/proc/self/exe: for code in the executable dladdr gives
// argv[0], which is no path when the program was found through PATH). Canonical, no
// duplicates; empty when neither can be found.
std::vector<std::filesystem::path> programDirs();

}  // namespace flowsurf::core
