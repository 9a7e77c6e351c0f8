// flowsurf library — what a public Surface holds: an in-memory dataset (arrays, built-in
// scenes, one-step files) shared by every renderer, or the path of a series that each
// renderer streams; plus what the accessors report.
#pragma once

#include "core/mesh.h"
#include "core/time_series.h"
#include "io/dataset_reader.h"

#include <memory>
#include <string>
#include <vector>

namespace flowsurf::detail {

struct SurfaceData {
    std::string source;                        // path, builtin:NAME or "arrays"
    std::string field;                         // the vector array to show
    io::SourceOptions read;                    // how `source` is read (OpenFOAM patches, case)
    std::shared_ptr<const core::Dataset> dataset;  // in memory, or null: stream `source`
    std::vector<double> times;
    core::Bounds bounds;
    std::vector<std::string> fields;
    size_t points = 0, triangles = 0;

    // The steps for one renderer (a stream of the series, or a view of the dataset).
    std::unique_ptr<core::StepProvider> provider() const;
};

}  // namespace flowsurf::detail
