// flowsurf — time series read lazily, one step at a time (for core::StepStream): a
// multi-step file (.pvd, OpenFOAM .foam with its time directories, Exodus, EnSight, ...)
// or a numbered file series given as a printf pattern ("surf_%04d.vtp") or a glob
// ("surf_*.vtp"). Memory holds only the steps the stream keeps.
#pragma once

#include "core/time_series.h"
#include "io/dataset_reader.h"

#include <memory>
#include <string>

namespace flowsurf::io {

// True if `input` names a file series: it contains '%', '*' or '?'.
bool isSeriesPattern(const std::string& input);

// Opens the metadata (file list or time values) now; steps load on demand. A series
// file's time is the number in its name where the pattern varies (else its index).
// Throws IoError (no file matches, unreadable) or FormatError.
// `options`: the boundary patches (OpenFOAM, CGNS; every file of a series) and OpenFOAM's case layout.
std::unique_ptr<core::StepProvider> openSeries(const std::string& input, const SourceOptions& options = {});
// Any input of the command line as steps loaded on demand: builtin:NAME (made in memory),
// a file or a file series (openSeries).
std::unique_ptr<core::StepProvider> openInput(const std::string& input, const SourceOptions& options = {});

}  // namespace flowsurf::io
