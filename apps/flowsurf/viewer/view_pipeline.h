// flowsurf view — the GL side of the viewer: the data that the state's session::Playback
// (the frame loop `render` and the library run, one method per view) has open, and the
// framebuffers the window shows it through. Needs a current GL 4.5 context: a GLFW
// window's or a headless EGL one.
#pragma once

#include "cli_options.h"
#include "core/time_series.h"
#include "session/playback.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace flowsurf::app::view {

class ViewPipeline {
public:
    // Renders through `playback` (the viewer state's), which must outlive the pipeline.
    explicit ViewPipeline(session::Playback& playback) : playback_(playback) {}

    // Opens the input of `o` and reopens the playback with `o` (at o.size) and `views`; on
    // failure throws, and the playback keeps the data and options it had, textures
    // included (the views apply from the next build).
    void load(const RenderOptions& o, const std::vector<methods::Method>& views);
    // New renderers (the clock restarts) for `views`, each of `viewSize`, and the options
    // as the playback has them. Throws; on failure those of the last build stay.
    void build(core::Viewport viewSize, const std::vector<methods::Method>& views);
    bool ready() const { return playback_.isOpen(); }
    session::Playback& playback() { return playback_; }
    const session::Playback& playbackView() const { return playback_; }

    size_t viewCount() const { return playback_.views().size(); }
    methods::FlowMethod& method(size_t i) { return *playback_.views()[i]; }
    // A read framebuffer on view i's composite (made once per build), for the window blit.
    GLuint compositeReadFbo(size_t i) const { return readFbos_[i].id(); }
    std::string methodName(size_t i) const;
    core::Viewport viewSize() const { return ready() ? playback_.options().size : core::Viewport{}; }

    // About the data, for the panel and the state.
    const core::Bounds& bounds() const { return bounds_; }
    const std::vector<double>& times() const { return playback_.surface().times(); }
    const core::TimeMapping& mapping() const { return playback_.surface().mapping(); }
    const std::vector<std::string>& vectorFields() const { return fields_; }
    const std::string& field() const { return playback_.surface().field(); }
    size_t triangles() const { return triangles_; }
    const std::string& input() const { return input_; }

    // Every view's stage list for one frame (see session::Playback::render).
    void render(const session::Playback::LiveFrame& f, bool advance);
    // The range of the colour values over the surface's pixels that view 0 shows (its
    // shade's colour value mapped back through the range and scale it was drawn with, at
    // data time `time`), or none when the view shows fewer than two distinct values.
    std::optional<glm::vec2> visibleColorRange(double time);
    // The views side by side as one RGB8 image, rows top to bottom (screenshots, video).
    std::vector<uint8_t> readImage(int* width, int* height) const { return playback_.readImage(width, height); }

private:
    void framebuffers();

    session::Playback& playback_;
    std::unique_ptr<core::StepProvider> steps_;  // what the playback has open
    std::vector<gl::Framebuffer> readFbos_;
    core::Bounds bounds_;
    std::vector<std::string> fields_;
    std::string input_;
    size_t triangles_ = 0;
};

}  // namespace flowsurf::app::view
