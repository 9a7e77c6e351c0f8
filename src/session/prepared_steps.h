// flowsurf — the steps as the methods see them: each loaded step gets the derived field
// the options ask for (curvature directions, a gradient, a tangential direction; see
// core/derived_fields.h), and a named field a step lacks (a transient case at rest, a
// field written later) is that field with zero vectors, not an error. Thread-safe as the
// wrapped provider is (StepStream prefetches).
#pragma once

#include "core/derived_fields.h"
#include "core/time_series.h"

#include <string>

namespace flowsurf::session {

class PreparedSteps final : public core::StepProvider {
public:
    // `field`: the requested field ("" = none named: nothing is added).
    PreparedSteps(core::StepProvider& inner, std::string field, core::DerivedFieldOptions derived);
    size_t count() const override { return inner_.count(); }
    double time(size_t i) const override { return inner_.time(i); }
    core::SurfaceMesh load(size_t i) override;
    std::string label(size_t i) const override { return inner_.label(i); }
    core::Bounds bounds() override { return inner_.bounds(); }

private:
    core::StepProvider& inner_;
    std::string field_;
    core::DerivedFieldOptions derived_;
};

// The field to show over a series: `requested` as given (checked to exist in some step
// when it is not derived), else the first field that is not zero everywhere in the first
// step that has one (a case starting from rest shows its flow), else the first field.
// Throws FieldError naming the input when no step has a vector field.
std::string selectSeriesField(core::StepProvider& steps, const std::string& requested);

}  // namespace flowsurf::session
