// flowsurf view — the GLFW window (OpenGL 4.5 core, X11) with the Dear ImGui panel.
// Turns mouse, keyboard, drops and panel edits into Events; shows the views.
#pragma once

#include "view_events.h"
#include "view_pipeline.h"
#include "view_state.h"

#include <map>
#include <optional>
#include <memory>
#include <string>
#include <vector>

struct GLFWwindow;

namespace flowsurf::app::view {

struct FrameInfo {
    double frameMs = 0.0;  // wall time of the last frame
    std::string renderer;  // GL_RENDERER
};

class Window {
public:
    // The panel's width in pixels: it sits at the window's left, beside the views, so it
    // never covers the data [doc/contrast.md, the viewer's framing]; collapsed or hidden, the views take it.
    static constexpr int kPanelWidth = 380;
    // Opens the window with a render area of width x height beside the panel, or, with
    // `fitScreen`, at a size that suits the screen (the primary monitor's work area, less
    // a margin); throws GlError when no display or no 4.5 core context.
    Window(int width, int height, const std::string& title, bool fitScreen = false);
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    // Polls input: returns the events since the last call (stamped `frame`). `idle`:
    // nothing animates, so wait up to 50 ms for input instead of spinning.
    std::vector<Event> poll(long frame, bool idle = false);
    bool closeRequested() const;
    // Render area size in pixels: the framebuffer less the panel's width.
    void framebufferSize(int* width, int* height) const;
    // Pixels at the window's left that the panel takes (0: hidden or collapsed).
    int panelWidth() const { return panelShown_ && !panelCollapsed_ ? kPanelWidth : 0; }
    // Resizes the window to a render area of width x height beside the panel.
    void resize(int width, int height);
    void setTitle(const std::string& title);
    // Blits the views, draws the panel (if shown; its edits come back from the next
    // poll) and swaps.
    void present(ViewerState& state, ViewPipeline& pipeline, const FrameInfo& info);
    // The whole window of the next present(), panel included, to a PNG.
    void requestWindowShot(const std::string& path) { windowShot_ = path; }

private:
    void panel(ViewerState& state, ViewPipeline& pipeline, const FrameInfo& info);
    void topologyTooltip(const ViewPipeline& pipeline) const;
    // The panel's sections, top to bottom.
    void readout(ViewerState& state, const ViewPipeline& pipeline, const FrameInfo& info);
    void methodSection(const ViewerState& state, const ViewPipeline& pipeline);
    void timeSection(const ViewerState& state);
    void optionSections(const ViewerState& state, const ViewPipeline& pipeline);
    static void stageTimes(ViewPipeline& pipeline);
    void saveSection(const ViewerState& state);
    static void keysSection();
    // `visibleRange`: the colour range gets a "visible" button (`set color-range visible`).
    void optionWidget(const struct OptionSpec& spec, const ViewerState& state, bool visibleRange = false);
    void emitSet(const std::string& name, const std::string& value);
    // The panel's Quality section (doc/algorithms.md §9): off until turned on.
    void qualitySection(const ViewerState& state, ViewPipeline& pipeline);
    // Dye [doc/algorithms.md §10]: the panel's list of sources, and a ctrl + click turned into a source
    // at the surface point under the cursor (the view's depth read back and unprojected),
    // emitted as `set dye` so that the event log replays it without a read-back.
    void dyePanel(const ViewerState& state);
    void dropDye(const ViewerState& state, ViewPipeline& pipeline);

    GLFWwindow* window_ = nullptr;
    std::vector<Event> queue_;
    long frame_ = 0;
    std::map<std::string, std::string> edits_;  // text of widgets being edited
    std::string configPath_ = "flowsurf_view.json", keyframePath_ = "flowsurf_camera_path.json";
    std::string screenshotPath_ = "flowsurf_screenshot.png", recordPath_ = "flowsurf_recording.mp4";
    std::string openPath_, windowShot_;
    std::optional<glm::vec2> dyeClick_;  // framebuffer pixels of a ctrl + click, origin top-left
    bool swallowRelease_ = false;        // the release of that click is not a drag's end
    bool panelShown_ = true, panelCollapsed_ = false;  // as of the last present()

    friend struct WindowCallbacks;
};

}  // namespace flowsurf::app::view
