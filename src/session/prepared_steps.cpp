#include "session/prepared_steps.h"

#include "core/errors.h"
#include "skeleton/skeleton.h"

#include <algorithm>

#include <cstdio>
#include <mutex>
#include <set>

namespace flowsurf::session {

PreparedSteps::PreparedSteps(core::StepProvider& inner, std::string field, core::DerivedFieldOptions derived,
                             ShownField shown)
    : inner_(inner), field_(std::move(field)), derived_(derived), shown_(std::move(shown)) {}

ShownField shownField(const RenderOptions& o, const std::string& field) {
    ShownField s;
    s.reversed = fieldShownReversed(o, field);
    for (const std::string& spec : {o.params.common.colorBy, o.params.common.maskBy}) {
        if (spec.empty()) continue;
        const std::string array = core::ScalarSpec::parse(spec).array;
        if (skeleton::isDerivedScalar(array) &&
            std::find(s.derivedScalars.begin(), s.derivedScalars.end(), array) == s.derivedScalars.end())
            s.derivedScalars.push_back(array);
    }
    return s;
}

core::SurfaceMesh PreparedSteps::load(size_t i) {
    core::SurfaceMesh mesh = loadField(i);
    core::VectorField* shown = nullptr;
    for (auto& f : mesh.fields)
        if (f.name == field_) shown = &f;
    if (!shown) return mesh;
    if (shown_.reversed)
        for (glm::vec3& v : shown->values) v = -v;
    for (const std::string& name : shown_.derivedScalars)
        if (!mesh.findScalar(name) && mesh.triangleCount() > 0)
            mesh.scalars.push_back({name, skeleton::derivedScalar(mesh, shown->values, name)});
    return mesh;
}

core::SurfaceMesh PreparedSteps::loadField(size_t i) {
    core::SurfaceMesh mesh = inner_.load(i);
    if (field_.empty() || mesh.findField(field_)) return mesh;
    if (core::isDerivedField(field_)) {
        core::addDerivedField(mesh, field_, derived_);
    } else {
        // A field is still that field where it is zero or not yet written.
        static std::mutex lock;
        static std::set<std::string> said;
        const std::string where = inner_.label(i);
        {
            std::lock_guard<std::mutex> guard(lock);
            if (said.insert(field_).second)
                std::fprintf(stderr, "flowsurf: warning: %s has no '%s'; shown as zero vectors there (the noise "
                             "stands still)\n", where.c_str(), field_.c_str());
        }
        mesh.fields.push_back({field_, std::vector<glm::vec3>(mesh.vertexCount(), glm::vec3(0.0f))});
    }
    return mesh;
}

std::string selectSeriesField(core::StepProvider& steps, const std::string& requested) {
    if (core::isDerivedField(requested)) return requested;
    std::string first;
    for (size_t i = 0; i < steps.count(); ++i) {
        core::SurfaceMesh mesh = steps.load(i);
        if (!requested.empty()) {
            if (mesh.findField(requested)) return requested;
            continue;
        }
        if (const core::VectorField* f = mesh.defaultField()) {
            if (first.empty()) first = f->name;
            for (const auto& v : f->values)
                if (v != glm::vec3(0.0f)) return f->name;
        }
        if (steps.count() == 1) break;
    }
    if (!first.empty()) return first;
    core::SurfaceMesh mesh0 = steps.load(0);
    if (!requested.empty()) {
        std::string names;
        for (const auto& f : mesh0.fields) names += (names.empty() ? "" : ", ") + f.name;
        throw FieldError(steps.label(0) + ": no vector field '" + requested + "' in any time step (available: " +
                         (names.empty() ? "none" : names) + ")");
    }
    throw FieldError(steps.label(0) + ": no 3-component point array to use as the vector field in any time step "
                     "(a geometry-only mesh: try --field curvature-max, down:0,-1,0 or gradient:ARRAY)");
}

}  // namespace flowsurf::session
