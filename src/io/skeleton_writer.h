// flowsurf — the flow topology written out (`flowsurf topology -o OUT`): JSON (the keys of
// doc/topology.md, positions in the input's coordinates), CSV (one row per critical point
// and per line vertex) and VTK PolyData .vtp (vertices with type and index, lines with kind
// and strength: ParaView styles them with its own representations; skeleton_vtp.cpp, the
// flowsurf_io_vtp target). Every file is written whole or not at all.
#pragma once

#include "skeleton/skeleton.h"

#include <string>

namespace flowsurf::io {

// What a result was computed from, written beside it.
struct SkeletonSource {
    std::string input, field;
    bool fieldReversed = false;
    size_t step = 0;
    double time = 0.0;
    skeleton::SkeletonParams params;
};

std::string skeletonJson(const skeleton::Skeleton& s, const SkeletonSource& source);
std::string skeletonCsv(const skeleton::Skeleton& s);
// By the extension of `path`: .json or .csv here; .vtp through writeSkeletonVtp.
// Throws ConfigError for another extension, IoError when the file cannot be written.
void writeSkeletonText(const std::string& path, const skeleton::Skeleton& s, const SkeletonSource& source);
void writeSkeletonVtp(const std::string& path, const skeleton::Skeleton& s, const SkeletonSource& source);

}  // namespace flowsurf::io
