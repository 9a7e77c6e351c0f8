// The fuzz input as a file, for parsers that take a path: one file per process in
// /dev/shm (memory), rewritten for every input.
#pragma once

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <string>

inline std::string fuzzInputFile(const uint8_t* data, size_t size, const char* extension) {
    static const std::string path = "/dev/shm/flowsurf-fuzz-" + std::to_string(getpid()) + extension;
    if (FILE* f = std::fopen(path.c_str(), "wb")) {
        std::fwrite(data, 1, size, f);
        std::fclose(f);
    }
    return path;
}
