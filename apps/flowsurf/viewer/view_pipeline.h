// flowsurf view — the GL side of the viewer: the data, the surface of the current data
// time and one renderer per view, built from the same library calls as `render`
// (openInput, AnimatedSurface, methods::makeMethod). Needs a current GL 4.5 context:
// a GLFW window's or a headless EGL one.
#pragma once

#include "session/animated_surface.h"
#include "core/time_series.h"
#include "methods/common/frame.h"
#include "cli_options.h"
#include "methods/make_renderer.h"

#include <memory>
#include <string>
#include <vector>

namespace flowsurf::app::view {

class ViewPipeline {
public:
    // Opens the input of `o` and checks its field; on failure throws and keeps what was
    // loaded before.
    void load(const RenderOptions& o);
    // A new surface and one renderer per method at `size` (the clock restarts). Throws;
    // on failure the previous renderers stay.
    void build(const RenderOptions& o, const std::vector<std::string>& methodNames, const core::Viewport& size);
    bool ready() const { return !methods_.empty(); }
    // Runs every renderer's stage list for one frame.
    void render(const core::Camera& camera, uint32_t clock, double time, double perFrame);

    size_t viewCount() const { return methods_.size(); }
    methods::FlowMethod& method(size_t i) { return *methods_[i]; }
    // A read framebuffer on view i's composite (made once per build), for the window blit.
    GLuint compositeReadFbo(size_t i) const { return readFbos_[i].id(); }
    const std::string& methodName(size_t i) const { return names_[i]; }
    core::Viewport viewSize() const { return size_; }

    // About the data, for the panel and the state.
    const core::Bounds& bounds() const { return bounds_; }
    const std::vector<double>& times() const { return times_; }
    double defaultPerFrame() const { return perFrame_; }
    const std::vector<std::string>& vectorFields() const { return fields_; }
    const std::string& field() const { return field_; }
    size_t triangles() const { return triangles_; }
    const std::string& input() const { return input_; }

    // The views side by side as one RGB8 image, rows top to bottom (screenshots, video).
    std::vector<uint8_t> readImage(int* width, int* height);

private:
    std::unique_ptr<RenderOptions> options_;  // AnimatedSurface keeps a reference to it
    std::unique_ptr<core::StepProvider> steps_;
    std::unique_ptr<AnimatedSurface> surface_;
    std::vector<std::unique_ptr<methods::FlowMethod>> methods_;
    std::vector<std::string> names_;
    std::vector<gl::Framebuffer> readFbos_;
    core::Viewport size_;
    core::Bounds bounds_;
    std::vector<double> times_;
    double perFrame_ = 0.0;
    std::vector<std::string> fields_;
    std::string field_, input_;
    size_t triangles_ = 0;
};

}  // namespace flowsurf::app::view
