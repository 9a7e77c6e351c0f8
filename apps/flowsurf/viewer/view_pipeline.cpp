#include "view_pipeline.h"
#include "io/series_reader.h"

#include "core/errors.h"
#include "gl/readback.h"
#include "session/scene_setup.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <limits>

namespace flowsurf::app::view {

namespace {

// A one-step input read once: rebuilding the renderers (every parameter change) must
// not read the file again.
class CachedStep final : public core::StepProvider {
public:
    explicit CachedStep(std::unique_ptr<core::StepProvider> inner) : inner_(std::move(inner)) {}
    size_t count() const override { return inner_->count(); }
    double time(size_t i) const override { return inner_->time(i); }
    core::SurfaceMesh load(size_t i) override {
        if (!cached_ || cachedIndex_ != i) {
            cached_ = std::make_unique<core::SurfaceMesh>(inner_->load(i));
            cachedIndex_ = i;
        }
        return *cached_;
    }
    std::string label(size_t i) const override { return inner_->label(i); }
    core::Bounds bounds() override { return load(0).bounds(); }

private:
    std::unique_ptr<core::StepProvider> inner_;
    std::unique_ptr<core::SurfaceMesh> cached_;
    size_t cachedIndex_ = 0;
};

// The field list offers skin-friction, derived on reading (a reload), where the input may
// have a volume with a velocity: an OpenFOAM case with U, a .vtu/.vtk file with a velocity
// array (a .vtk surface then says so when it is picked, and the old data stay).
bool offersSkinFriction(const std::string& input, const std::vector<std::string>& fields) {
    std::string ext = std::filesystem::path(input).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (ext != ".foam" && ext != ".vtu" && ext != ".vtk") return false;
    for (const std::string& f : fields) {
        std::string n = f;
        std::transform(n.begin(), n.end(), n.begin(), [](unsigned char c) { return char(std::tolower(c)); });
        if (n == "skin-friction") return false;  // already read
        if (n == "u" || n == "velocity" || n == "vel") return true;
    }
    return false;
}

}  // namespace

void ViewPipeline::load(const RenderOptions& o, const std::vector<methods::Method>& views) {
    std::unique_ptr<core::StepProvider> steps = io::openInput(o.input, session::sourceOptions(o));
    if (steps->count() == 1) steps = std::make_unique<CachedStep>(std::move(steps));
    const core::Bounds bounds = steps->bounds();
    const core::SurfaceMesh first = steps->load(o.timeStepGiven ? o.timeStep : 0);
    std::vector<std::string> fields;
    for (const auto& f : first.fields) fields.push_back(f.name);
    if (offersSkinFriction(o.input, fields)) fields.push_back("skin-friction");
    // The playback checks the field and loads the first step: errors surface here, and
    // the old data and its renderers stay.
    playback_.setViews(views);
    playback_.reopen(*steps, o);
    steps_ = std::move(steps);
    bounds_ = bounds;
    fields_ = std::move(fields);
    input_ = o.input;
    triangles_ = first.triangles.size();
    framebuffers();
}

void ViewPipeline::build(core::Viewport viewSize, const std::vector<methods::Method>& views) {
    if (!ready()) throw ConfigError("no data loaded");
    RenderOptions o = playback_.options();
    o.size = viewSize;
    playback_.setOptions(o);
    playback_.setViews(views);
    try {
        playback_.rebuild();  // on failure: the options and views of the last build that worked
    } catch (...) {
        framebuffers();
        throw;
    }
    framebuffers();
}

void ViewPipeline::framebuffers() {
    readFbos_.clear();
    for (const auto& m : playback_.views()) {
        readFbos_.push_back(gl::Framebuffer::create());
        readFbos_.back().attach(GL_COLOR_ATTACHMENT0, m->composite());
        glNamedFramebufferReadBuffer(readFbos_.back().id(), GL_COLOR_ATTACHMENT0);
    }
}

std::string ViewPipeline::methodName(size_t i) const {
    return playback_.views()[i]->name();
}

void ViewPipeline::render(const session::Playback::LiveFrame& f, bool advance) {
    if (!ready()) return;
    playback_.render(f, advance);
    triangles_ = playback_.surface().atTime(f.time).triangleCount();
}

std::optional<glm::vec2> ViewPipeline::visibleColorRange(double time) {
    if (!ready() || viewCount() == 0) return std::nullopt;
    const methods::FlowMethod& m = method(0);
    const std::vector<float> value = gl::readChannel(m.surfaceShade(), 3), depth = gl::readDepth(m.surfaceDepth());
    float lo = std::numeric_limits<float>::infinity(), hi = -lo;
    for (size_t i = 0; i < value.size() && i < depth.size(); ++i)
        if (depth[i] < 1.0f && std::isfinite(value[i])) lo = std::min(lo, value[i]), hi = std::max(hi, value[i]);
    if (!(lo < hi)) return std::nullopt;
    // Back through the range and scale the shade's value 0..1 was made with (SurfaceGpu).
    const glm::vec2 r = playback_.surface().atTime(time).colorRange();
    const bool log = playback_.options().params.common.colorScale == methods::ColorScale::Log && r.x > 0.0f;
    auto value01 = [&](float t) {
        if (!log) return r.x + t * (r.y - r.x);
        const double a = std::log10(double(r.x)), b = std::log10(double(r.y));
        return float(std::pow(10.0, a + double(t) * (b - a)));
    };
    const glm::vec2 out(value01(lo), value01(hi));
    if (!(out.x < out.y)) return std::nullopt;
    return out;
}

}  // namespace flowsurf::app::view
