#include "core/program_dirs.h"

#include <dlfcn.h>

#include <algorithm>

namespace flowsurf::core {

std::vector<std::filesystem::path> programDirs() {
    namespace fs = std::filesystem;
    std::vector<fs::path> dirs;
    auto add = [&](const char* file) {
        std::error_code ec;
        const fs::path self = fs::canonical(file, ec);
        if (!ec && std::find(dirs.begin(), dirs.end(), self.parent_path()) == dirs.end())
            dirs.push_back(self.parent_path());
    };
    Dl_info info{};
    if (dladdr(reinterpret_cast<void*>(&programDirs), &info) && info.dli_fname) add(info.dli_fname);
    add("/proc/self/exe");
    return dirs;
}

}  // namespace flowsurf::core
