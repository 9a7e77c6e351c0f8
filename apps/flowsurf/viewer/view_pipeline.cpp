#include "view_pipeline.h"

#include "core/errors.h"
#include "methods/make_renderer.h"
#include "gl/readback.h"
#include "session/scene_setup.h"

#include <epoxy/gl.h>

#include <algorithm>

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

}  // namespace

void ViewPipeline::load(const RenderOptions& o) {
    std::unique_ptr<core::StepProvider> steps = openInput(o);
    if (steps->count() == 1) steps = std::make_unique<CachedStep>(std::move(steps));
    auto options = std::make_unique<RenderOptions>(o);
    // The surface checks the field and loads the first step: errors surface here.
    auto surface = std::make_unique<AnimatedSurface>(*options, *steps);
    const core::Bounds bounds = steps->bounds();
    const core::SurfaceMesh first = steps->load(o.timeStepGiven ? o.timeStep : 0);
    std::vector<std::string> fields;
    for (const auto& f : first.fields) fields.push_back(f.name);

    methods_.clear();
    names_.clear();
    surface_.reset();
    steps_ = std::move(steps);
    options_ = std::move(options);
    surface_ = std::move(surface);
    bounds_ = bounds;
    times_ = surface_->times();
    perFrame_ = surface_->unsteady() ? surface_->mapping().perFrame : 0.0;
    fields_ = std::move(fields);
    field_ = surface_->field();
    input_ = o.input;
    triangles_ = first.triangles.size();
}

void ViewPipeline::build(const RenderOptions& o, const std::vector<std::string>& methodNames,
                         const core::Viewport& size) {
    if (!steps_) throw ConfigError("no data loaded");
    auto options = std::make_unique<RenderOptions>(o);
    options->size = size;
    // One surface streams from the provider at a time (its prefetch thread reads it).
    surface_.reset();
    std::vector<std::unique_ptr<methods::FlowMethod>> made;
    try {
        surface_ = std::make_unique<AnimatedSurface>(*options, *steps_);
        for (const std::string& name : methodNames) {
            made.push_back(methods::makeMethod(name, surface_->paramsFor(options->params), size));
            made.back()->timer().setEnabled(true);
        }
    } catch (...) {
        surface_.reset();
        if (options_) surface_ = std::make_unique<AnimatedSurface>(*options_, *steps_);
        throw;
    }
    options_ = std::move(options);
    methods_ = std::move(made);
    readFbos_.clear();
    for (const auto& m : methods_) {
        readFbos_.push_back(gl::Framebuffer::create());
        readFbos_.back().attach(GL_COLOR_ATTACHMENT0, m->composite());
        glNamedFramebufferReadBuffer(readFbos_.back().id(), GL_COLOR_ATTACHMENT0);
    }
    names_ = methodNames;
    size_ = size;
    field_ = surface_->field();
}

void ViewPipeline::render(const core::Camera& camera, uint32_t clock, double time, double perFrame) {
    if (!surface_) return;
    const methods::SurfaceGpu& s = surface_->atTime(time);
    triangles_ = s.triangleCount();
    for (auto& m : methods_) {
        const methods::TimeLevels* levels = m->usesTimeLevels() ? surface_->levelsAtTime(time, perFrame) : nullptr;
        m->renderFrame({&s, camera, clock, levels});
    }
}

std::vector<uint8_t> ViewPipeline::readImage(int* width, int* height) {
    const int n = int(methods_.size());
    *width = n * size_.width;
    *height = size_.height;
    std::vector<uint8_t> out(size_t(*width) * size_t(*height) * 3);
    for (int i = 0; i < n; ++i) {
        std::vector<uint8_t> img = gl::readRgb8TopDown(methods_[size_t(i)]->composite());
        for (int y = 0; y < size_.height; ++y)
            std::copy_n(&img[size_t(y) * size_.width * 3], size_t(size_.width) * 3,
                        &out[(size_t(y) * size_t(*width) + size_t(i) * size_.width) * 3]);
    }
    return out;
}

}  // namespace flowsurf::app::view
