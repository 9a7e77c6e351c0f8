// flowsurf — the flow topology of each step of an input as the options show its field (the
// field selected, derived and reversed as the texture's, session::PreparedSteps), analysed
// once per step and kept: what `flowsurf topology`, the overlay of --topology on, Python's
// flowsurf.topology and the C++ API's Surface::topology all read (doc/topology.md).
#pragma once

#include "session/options/options.h"
#include "session/prepared_steps.h"
#include "skeleton/skeleton.h"

#include <map>
#include <string>

namespace flowsurf::session {

class TopologySource {
public:
    // `steps` must outlive this. Throws FieldError when no step has the field.
    TopologySource(core::StepProvider& steps, const RenderOptions& o);
    size_t count() const { return steps_.count(); }
    // Step i's topology (analysed on the first call). Throws FieldError (zero field, no
    // triangles) naming the step, ConfigError (a step index out of range, a parameter).
    const skeleton::Skeleton& at(size_t step);
    const std::string& field() const { return field_; }
    bool reversed() const { return shown_.reversed; }
    const skeleton::SkeletonParams& params() const { return params_; }

private:
    core::StepProvider& steps_;
    std::string field_;
    ShownField shown_;
    PreparedSteps prepared_;
    skeleton::SkeletonParams params_;
    std::map<size_t, skeleton::Skeleton> done_;
};

// The analysis parameters of the options (--topology-parts and the thresholds).
skeleton::SkeletonParams topologyParams(const RenderOptions& o);

}  // namespace flowsurf::session
