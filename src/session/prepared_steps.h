// flowsurf — the steps as the methods see them: each loaded step gets the derived field
// the options ask for (curvature directions, a gradient, a tangential direction; see
// core/derived_fields.h), and a named field a step lacks (a transient case at rest, a
// field written later) is that field with zero vectors, not an error; the field shown
// reversed where the options say so (--reverse-field), and the scalars derived from it that
// --color-by or --mask-by name (divergence, normalized-divergence). Thread-safe as the
// wrapped provider is (StepStream prefetches).
#pragma once

#include "core/derived_fields.h"
#include "core/time_series.h"
#include "session/options/options.h"

#include <string>

namespace flowsurf::session {

// How the field is shown: reversed or as stored, and which derived scalars come with it.
struct ShownField {
    bool reversed = false;                    // the field's vectors negated
    std::vector<std::string> derivedScalars;  // of skeleton::kDerivedScalarNames
};

class PreparedSteps final : public core::StepProvider {
public:
    // `field`: the requested field ("" = none named: nothing is added).
    PreparedSteps(core::StepProvider& inner, std::string field, core::DerivedFieldOptions derived, ShownField shown = {});
    size_t count() const override { return inner_.count(); }
    double time(size_t i) const override { return inner_.time(i); }
    core::SurfaceMesh load(size_t i) override;
    std::string label(size_t i) const override { return inner_.label(i); }
    core::Bounds bounds() override { return inner_.bounds(); }

private:
    core::SurfaceMesh loadField(size_t i);  // the step with the field, as read or derived

    core::StepProvider& inner_;
    std::string field_;
    core::DerivedFieldOptions derived_;
    ShownField shown_;
};

// What the options make of `field` as shown: reversed (--reverse-field) and the derived
// scalars --color-by and --mask-by name.
ShownField shownField(const RenderOptions& o, const std::string& field);

// The field to show over a series: `requested` as given (checked to exist in some step
// when it is not derived), else the first field that is not zero everywhere in the first
// step that has one (a case starting from rest shows its flow), else the first field.
// Throws FieldError naming the input when no step has a vector field.
std::string selectSeriesField(core::StepProvider& steps, const std::string& requested);

}  // namespace flowsurf::session
