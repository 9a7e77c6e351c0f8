// flowsurf — one reader per file extension, seen as a list of time steps (private to
// src/io). VTK readers for most formats (where one crashes or loops on bad input, the
// reader process's limits and sandbox stop it), behind checks of what VTK would read
// silently wrong (checks.h, a truncated binary STL); our own parsers for PLY and OBJ
// (parsers.h); OpenFOAM cases in openfoam_source.cpp.
// A StepSource hands out the raw output per step; surface_pipeline.h turns that into
// a triangle surface.
#pragma once

#include "io/dataset_reader.h"
#include "io/reader/vtk_messages.h"

#include <vtkAlgorithm.h>
#include <vtkDataObject.h>
#include <vtkSmartPointer.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace flowsurf::io::detail {

class StepSource {
public:
    StepSource(std::string path, std::string format) : path_(std::move(path)), format_(std::move(format)) {}
    virtual ~StepSource() = default;

    const std::string& path() const { return path_; }
    // Human-readable format, e.g. "VTK XML PolyData".
    const std::string& format() const { return format_; }
    // Sorted time values; empty when the file carries no time information (one step).
    const std::vector<double>& times() const { return times_; }
    size_t stepCount() const { return times_.empty() ? 1 : times_.size(); }
    // The reader's output for step `index` (may be composite). Throws FormatError.
    virtual vtkSmartPointer<vtkDataObject> readStep(size_t index) = 0;
    // Every boundary condition the file declares, read or not (CGNS); empty for others.
    virtual std::vector<PatchInfo> patches() const { return {}; }

protected:
    std::string path_, format_;
    std::vector<double> times_;
};

// A VTK reader's output as steps (the reader's TIME_STEPS, or one step). Each step is a
// shallow copy, so reading the next step cannot change what the caller holds. Readers that
// need more per step (OpenFOAM: warnings, units) override the hooks.
class AlgorithmSource : public StepSource {
public:
    AlgorithmSource(vtkAlgorithm* reader, std::string path, std::string format, VtkMessageTrap& trap);
    vtkSmartPointer<vtkDataObject> readStep(size_t index) override;

protected:
    // After the reader ran without error, with the trap still holding its messages.
    virtual void afterUpdate(VtkMessageTrap& /*trap*/) {}
    // On the copy handed out.
    virtual void adapt(vtkDataObject& /*step*/) {}

private:
    vtkSmartPointer<vtkAlgorithm> reader_;
    VtkMessageTrap& trap_;
};

// Reads `reader`'s header (watched by `trap`; again after a selection that needs the
// names the header lists); throws FormatError with what the reader reported.
void readInformation(vtkAlgorithm* reader, const std::string& path, const std::string& format, VtkMessageTrap& trap);

// OpenFOAM cases (openfoam_source.cpp); `format` ("OpenFOAM case") names them in messages,
// with the layout read. Throws as openSource, ConfigError for --patches or --foam-case.
std::unique_ptr<StepSource> openOpenFoam(const std::string& path, const std::string& format, VtkMessageTrap& trap,
                                         const SourceOptions& options);

// CGNS files (cgns_source.cpp): the wall patches of volume zones (--patches: those whose BC
// or family name matches), else the volume's boundary. Throws as openSource, ConfigError for
// --patches.
std::unique_ptr<StepSource> openCgns(const std::string& path, const std::string& format, VtkMessageTrap& trap,
                                     const SourceOptions& options);
// What `flowsurf info` says of --field skin-friction on an OpenFOAM case: where it comes
// from and the viscosity, or "not available: why" (the header is read, not the mesh).
std::string foamSkinFrictionNote(const std::string& path, const SourceOptions& options);

// `inner`'s steps with each volume data set replaced by its boundary surface carrying the
// derived skin-friction (volume_walls.cpp); the first step without volume cells throws FormatError.
std::unique_ptr<StepSource> withSkinFriction(std::unique_ptr<StepSource> inner, const SourceOptions& options);

// Picks the reader by extension (case-insensitive) and reads the file's metadata.
// Throws IoError (missing, unreadable, a folder) or FormatError (unknown extension,
// empty file, header the reader refuses). Every reader is watched by `trap`.
// `options`: OpenFOAM's boundary patches and case layout; skin-friction (FormatError for a
// format that holds surfaces only).
std::unique_ptr<StepSource> openSource(const std::string& path, VtkMessageTrap& trap, const SourceOptions& options = {});

}  // namespace flowsurf::io::detail
