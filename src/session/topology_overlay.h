// flowsurf — --topology on: the flow topology of the step on screen (TopologySource)
// drawn over each method's image by methods::SkeletonLayer, after the method's stages and
// the quality measurement, so the texture and its metrics are the method's own. Time
// series: the nearest step's topology, analysed when the animation first shows it.
#pragma once

#include "methods/frame.h"
#include "methods/skeleton_layer/skeleton_layer.h"
#include "session/topology_source.h"

namespace flowsurf::session {

class TopologyOverlay {
public:
    // Analyses the first step shown (its errors come here); needs a current GL context.
    TopologyOverlay(core::StepProvider& steps, const RenderOptions& o);
    void draw(const methods::FlowMethod& method, const core::Camera& camera, double time);
    // The result drawn last (the viewer's hover reads it).
    const skeleton::Skeleton& current() const { return *shown_; }
    const methods::SkeletonLayer& layer() const { return layer_; }

private:
    size_t stepAt(double time) const;

    core::StepProvider& steps_;
    TopologySource source_;
    methods::SkeletonLayer layer_;
    methods::SkeletonStyle style_;
    bool series_;
    size_t fixedStep_;
    size_t uploaded_;
    const skeleton::Skeleton* shown_ = nullptr;  // source_'s result for uploaded_
};

}  // namespace flowsurf::session
