#include "session/animated_surface.h"

#include "core/errors.h"
#include "session/scene_setup.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace flowsurf::session {

core::TimeMapping makeTimeMapping(const RenderOptions& o, const std::vector<double>& times) {
    core::TimeMapping m;
    m.start = o.timeRange ? o.timeRange->first : times.front();
    m.end = o.timeRange ? o.timeRange->second : times.back();
    if (o.timePerFrame > 0.0) {
        m.perFrame = o.timePerFrame * (m.end >= m.start ? 1.0 : -1.0);
    } else if (o.framesPerStep > 0 && times.size() > 1) {
        double spacing = (times.back() - times.front()) / double(times.size() - 1);
        m.perFrame = spacing / o.framesPerStep * (m.end >= m.start ? 1.0 : -1.0);
    } else {
        // The range over the frames: to the last frame written, k = frames for a PNG (the
        // image after --frames frames), k = frames - 1 for a movie or PNG sequence of
        // --frames frames.
        bool movie = false;  // an output name that is neither (the viewer's, Python's): as a PNG
        try { movie = outputKind(o.output) != OutputKind::Png; } catch (const ConfigError&) {}
        const int last = movie ? o.frames - 1 : o.frames;
        m.perFrame = last > 0 ? (m.end - m.start) / last : 0.0;
    }
    return m;
}

AnimatedSurface::AnimatedSurface(const RenderOptions& o, core::StepProvider& steps, methods::ProcessGroup* group)
    : options_(o),
      common_(o.params.common),
      field_(selectSeriesField(steps, o.field)),
      reversed_(fieldShownReversed(o, field_)),
      prepared_(steps, field_, core::DerivedFieldOptions{o.curvatureRadius}, shownField(o, field_)),
      provider_(prepared_),
      group_(group) {
    const bool series = steps.count() > 1 && !o.timeStepGiven;
    if (!series) {
        if (o.timeStep >= steps.count())
            throw ConfigError("--time-step " + std::to_string(o.timeStep) + ": " + steps.label(0) + " has " +
                              std::to_string(steps.count()) + " time step(s)");
        core::SurfaceMesh mesh = provider_.load(o.timeStep);
        noteUnits(mesh);
        checkScalarArrays(mesh, steps.label(o.timeStep));
        upload(mesh, steps.label(o.timeStep));
        common_.colorRange = surface_->colorRange();
        return;
    }
    resolveRanges();
    stream_ = std::make_unique<core::StepStream>(provider_, 3, true);
    mapping_ = makeTimeMapping(o, stream_->times());
    levels_ = std::make_unique<methods::TimeLevelSource>(*stream_, field_);
    if (units_.empty()) noteUnits(stream_->meshAt(mapping_.at(0)));
    checkScalarArrays(stream_->meshAt(mapping_.at(0)), steps.label(0));
}

void AnimatedSurface::checkScalarArrays(const core::SurfaceMesh& mesh, const std::string& where) const {
    if (mesh.triangleCount() == 0) return;  // an empty piece of a parallel render
    for (const auto& [option, spec] : {std::pair{"--color-by", common_.colorBy}, std::pair{"--mask-by", common_.maskBy}}) {
        std::vector<float> values;
        if (spec.empty() || core::evalScalar(mesh, core::ScalarSpec::parse(spec), values)) continue;
        std::string names;
        for (const auto& a : mesh.scalars) names += (names.empty() ? "" : ", ") + a.name;
        for (const auto& a : mesh.fields) names += (names.empty() ? "" : ", ") + a.name;
        throw FieldError(std::string(option) + " " + spec + ": " + where + " has no point array '" +
                         core::ScalarSpec::parse(spec).array + "' (available: " + (names.empty() ? "none" : names) + ")");
    }
}

methods::MethodParams AnimatedSurface::paramsFor(const methods::MethodParams& params) const {
    return withUnitsInTitle(params, field_, units_, reversed_);
}

methods::MethodParams withUnitsInTitle(const methods::MethodParams& params, const std::string& field,
                                       const std::map<std::string, std::string>& units, bool reversed) {
    methods::MethodParams p = params;
    if (!p.common.title.empty()) return p;
    // The name SurfaceGpu gives the colour array, with the units of the array behind it.
    const std::string array = p.common.colorBy.empty() ? field : core::ScalarSpec::parse(p.common.colorBy).array;
    const std::string name = p.common.colorBy.empty() ? "|" + field + "|" : p.common.colorBy;
    const auto it = units.find(array);
    const bool withUnits = it != units.end() && !it->second.empty();
    if (withUnits) p.common.title = name + " [" + it->second + "]";
    if (reversed) p.common.title = (withUnits ? p.common.title : name) + ", " + field + " reversed";
    return p;
}

void AnimatedSurface::resolveRanges() {
    const bool colorGiven = common_.colorRangeAuto || common_.colorRange.x <= common_.colorRange.y;
    const bool maskGiven = common_.maskBy.empty() || common_.maskRangeAuto || common_.maskRange.x <= common_.maskRange.y;
    if (colorGiven && maskGiven) return;
    // One pass over the series, a step at a time (memory stays at one step and a bounded
    // summary of the values), so a movie's colours do not pump [docs/cfd.md: once per data set].
    methods::RangeAccumulator ranges(common_);
    bool any = false;
    // A step that cannot be read is skipped here: the frame that needs it reports it, after
    // the frames before it were written.
    for (size_t i = 0; i < provider_.count(); ++i) {
        try {
            const core::SurfaceMesh mesh = provider_.load(i);
            noteUnits(mesh);
            ranges.add(methods::statisticsSamples(mesh, field_, common_));
            any = true;
        } catch (const IoError&) {
        } catch (const FormatError&) {
        }
    }
    if (!any) return;
    if (!colorGiven) {
        const glm::vec2 r = ranges.colorRange();
        if (r.x <= r.y) common_.colorRange = r;
    }
    if (!maskGiven) {
        const glm::vec2 r = ranges.maskRange();
        if (r.x <= r.y) common_.maskRange = r;
    }
}

const std::vector<double>& AnimatedSurface::times() const {
    static const std::vector<double> none;
    return stream_ ? stream_->times() : none;
}

const methods::TimeLevels* AnimatedSurface::levelsAtTime(double t, double perFrame) {
    if (!stream_) return nullptr;
    const double perStep = options_.traceDt ? *options_.traceDt : std::abs(perFrame);
    const int halfSteps = std::max(0, (options_.params.hybrid.filterLength - 1) / 2);
    const methods::TimeLevels& levels = levels_->at(t, perStep, halfSteps);
    return levels.empty() ? nullptr : &levels;
}

void AnimatedSurface::upload(const core::SurfaceMesh& mesh, const std::string& where) {
    if (!mesh.findField(field_))
        throw FieldError(where + ": no vector field '" + field_ + "' in this step");
    std::optional<methods::SurfaceStatistics> whole;
    std::optional<methods::PieceSeams> seams;
    if (group_) whole = methods::wholeSurfaceStatistics(*group_, mesh, field_, common_);
    if (options_.params.ibfvs.edgeMask) seams = methods::pieceSeams(group_, mesh);
    surface_ = std::make_unique<methods::SurfaceGpu>(mesh, field_, common_, options_.params.ibfvs.edgeMask,
                                                     whole ? &*whole : nullptr, seams ? &*seams : nullptr);
}

const methods::SurfaceGpu& AnimatedSurface::atTime(double t) {
    if (stream_) {
        bool changed = false;
        const core::SurfaceMesh& mesh = stream_->meshAt(t, &changed);
        if (!changed && surface_) return *surface_;
        const size_t topology = stream_->topologyStep();
        const std::string where = provider_.label(topology);
        // Same topology as the last upload: rewrite the vertices in place.
        if (surface_ && topology == uploadedTopology_ && mesh.findField(field_) &&
            surface_->updateVertices(mesh, field_, common_))
            return *surface_;
        upload(mesh, where);
        uploadedTopology_ = topology;
    }
    return *surface_;
}

const core::SurfaceMesh& AnimatedSurface::meshAtTime(double t) {
    atTime(t);
    if (stream_) return stream_->meshAt(t);
    if (!steadyMesh_) steadyMesh_ = std::make_unique<core::SurfaceMesh>(provider_.load(options_.timeStep));
    return *steadyMesh_;
}

}  // namespace flowsurf::session
