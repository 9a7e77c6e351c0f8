// flowsurf — the surface of every animation frame: steady data uploads once; a time series
// streams through core::StepStream, frame k showing data time t(k) (--time,
// --time-per-frame, --frames-per-step), interpolated between steps of equal topology.
#pragma once

#include "core/step_stream.h"
#include "parallel/process_group.h"
#include "raster/surface_gpu.h"
#include "raster/time_levels.h"
#include "session/options/options.h"
#include "session/prepared_steps.h"

#include <map>
#include <memory>

namespace flowsurf::session {

class AnimatedSurface {
public:
    // Reads steps from `steps` (which must outlive this); needs a current GL context.
    // Throws ConfigError/FieldError, and what loading a step throws. `group`: the
    // processes that each hold a piece of a steady surface (its statistics are the whole
    // surface's), or null.
    AnimatedSurface(const RenderOptions& o, core::StepProvider& steps, methods::ProcessGroup* group = nullptr);
    // The surface for frame k (uploaded when the data changed since the last call).
    const methods::SurfaceGpu& at(int frame) { return atTime(mapping_.at(frame)); }
    // The surface at data time t (the viewer's clock runs apart from the frame count).
    const methods::SurfaceGpu& atTime(double t);
    // The surface last uploaded (what the last frame drew); null before the first upload.
    const methods::SurfaceGpu* current() const { return surface_.get(); }
    // For methods that integrate through time (the hybrid's pathlines, [W §3]): the field
    // around data time t, over the particles' time window (--trace-dt per step, default the
    // data time per frame, `perFrame`; --filter-length steps). Null for steady data. Call
    // after atTime(t).
    const methods::TimeLevels* levelsAtTime(double t, double perFrame);
    // The mesh at data time t on the CPU (dye needs its triangles and vectors); uploads as
    // atTime(t) does. Steady data is read again on the first call and kept.
    const core::SurfaceMesh& meshAtTime(double t);
    bool unsteady() const { return stream_ != nullptr; }
    double timeAt(int frame) const { return mapping_.at(frame); }
    const core::TimeMapping& mapping() const { return mapping_; }
    // The values at the ends of the colour map (fixed over the animation unless auto).
    glm::vec2 colorRange() const { return common_.colorRange; }
    // The data times of the steps (empty for steady data).
    const std::vector<double>& times() const;
    const std::string& field() const { return field_; }
    bool fieldReversed() const { return reversed_; }
    // `params` for a method drawing this data: without --title, the legend's title gains
    // the colour array's units where the file gives them ("|U| [m/s]", "p [m2/s2]").
    methods::MethodParams paramsFor(const methods::MethodParams& params) const;

private:
    // Throws FieldError when --color-by or --mask-by names an array `mesh` lacks (the first
    // step shown: a later step lacking it shows NaN, the no-value colour).
    void checkScalarArrays(const core::SurfaceMesh& mesh, const std::string& where) const;
    void upload(const core::SurfaceMesh& mesh, const std::string& where);
    void noteUnits(const core::SurfaceMesh& mesh) { if (units_.empty()) units_ = mesh.units; }

    // The colour and mask ranges the options leave to the data: over every step of a series.
    void resolveRanges();

    const RenderOptions& options_;
    methods::CommonParams common_;  // the options' with the colour range resolved
    std::string field_;
    bool reversed_ = false;
    PreparedSteps prepared_;
    core::StepProvider& provider_;
    std::unique_ptr<core::StepStream> stream_;
    core::TimeMapping mapping_;
    std::unique_ptr<methods::SurfaceGpu> surface_;
    std::unique_ptr<core::SurfaceMesh> steadyMesh_;  // meshAtTime() of steady data
    std::unique_ptr<methods::TimeLevelSource> levels_;
    methods::ProcessGroup* group_ = nullptr;
    size_t uploadedTopology_ = 0;  // step whose triangles surface_ holds
    std::map<std::string, std::string> units_;  // of the data's arrays, from the first step read
};

// `params` with the legend title the data gives when --title is not set: the colour
// array's name as SurfaceGpu shows it ("|U|", "p", "U:x") and its units, if known, and
// whether the field is shown reversed (--reverse-field).
methods::MethodParams withUnitsInTitle(const methods::MethodParams& params, const std::string& field,
                                       const std::map<std::string, std::string>& units, bool reversed = false);

// The frame -> data time mapping of the options for these step times.
core::TimeMapping makeTimeMapping(const RenderOptions& o, const std::vector<double>& times);

}  // namespace flowsurf::session
