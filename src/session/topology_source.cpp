#include "session/topology_source.h"

#include "core/errors.h"

namespace flowsurf::session {

skeleton::SkeletonParams topologyParams(const RenderOptions& o) {
    skeleton::SkeletonParams p = o.topologyParams;
    p.lines = o.topologyParts != "points";
    return p;
}

TopologySource::TopologySource(core::StepProvider& steps, const RenderOptions& o)
    : steps_(steps),
      field_(selectSeriesField(steps, o.field)),
      shown_{fieldShownReversed(o, field_), {}},
      prepared_(steps, field_, core::DerivedFieldOptions{o.curvatureRadius}, shown_),
      params_(topologyParams(o)) {}

const skeleton::Skeleton& TopologySource::at(size_t step) {
    if (step >= steps_.count())
        throw ConfigError("topology: step " + std::to_string(step) + " of " + steps_.label(0) + ", which has " +
                          std::to_string(steps_.count()) + " time step(s)");
    auto it = done_.find(step);
    if (it != done_.end()) return it->second;
    const core::SurfaceMesh mesh = prepared_.load(step);
    const core::VectorField* f = mesh.findField(field_);
    FLOWSURF_CHECK(f != nullptr);  // PreparedSteps adds a missing field as zero vectors
    return done_.emplace(step, skeleton::analyze(mesh, f->values, params_, steps_.label(step) + ", field '" +
                                                                               field_ + "'")).first->second;
}

}  // namespace flowsurf::session
