// flowsurf view — the viewer's state and what input does to it, free of GL and of any
// window so unit tests drive it directly. The state is a session::Playback, the one owner
// of the options (the camera lives in their eye/target/up/fov, so a saved config renders
// the same view offline; the GL side opens data in it, view_pipeline.h), plus what only a
// viewer has: pause, time playback, side-by-side methods, the mouse.
// Input arrives as Events (view_events.h), from GLFW or a replayed log alike.
#pragma once

#include "core/camera.h"
#include "core/time_series.h"
#include "cli_options.h"
#include "session/playback.h"
#include "view_events.h"

#include <glm/glm.hpp>

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace flowsurf::app::view {

// Degrees of camera rotation per pixel of drag (turntable and trackball).
inline constexpr float kDegPerPixel = 0.25f;
// Zoom factor per wheel step (towards the cursor).
inline constexpr float kZoomPerStep = 0.85f;

struct KeyBinding {
    const char* name;         // as in event logs and GLFW key names ("r", "X", "space", "f1")
    const char* description;  // for the panel and --help
};
// Every key the viewer knows, in the order the panel lists them.
const std::vector<KeyBinding>& keyTable();

enum class RotateMode { Turntable, Trackball };

// What the GL side must do after events changed the state.
struct Requests {
    // The input's options (input, field, patches...) changed, as `set` name and value in
    // order: read the data again with them (the playback keeps its data when that fails).
    std::vector<std::pair<std::string, std::string>> reload;
    bool rebuild = false;   // method or parameters changed: new renderers (clock restarts)
    bool quit = false;
    std::vector<Event> outputs;  // screenshot, flow-texture, save-config, ... after the frame
    std::optional<std::string> open;        // open this file (keeps the old data on failure)
    std::optional<std::string> recordStart; // start recording MP4 to this file
    bool recordStop = false;
    std::optional<glm::ivec2> resize;       // window size in pixels
};

class ViewerState {
public:
    explicit ViewerState(const RenderOptions& options);

    // The options as they stand: method, parameters, camera (explicit once data is loaded);
    // the input's as last read (a change waits in Requests::reload until the data is read).
    const RenderOptions& options() const { return playback_->options(); }
    // Closed until the GL side opens data in it; destroy it with that GL context current.
    session::Playback& playback() { return *playback_; }
    const session::Playback& playback() const { return *playback_; }
    std::vector<methods::Method> compare;  // methods side by side; empty: options().method alone
    RotateMode rotateMode = RotateMode::Turntable;
    bool paused = false;               // no advection frames (the view still follows the camera)
    bool stepOnce = false;             // advance one frame while paused
    bool showPanel = true;
    // The panel folded to its title bar (its arrow, or `set panel-collapsed`): the views take
    // the window's whole width. A window-only setting: a headless replay has no panel.
    bool panelCollapsed = false;
    bool recording = false;            // an MP4 is being written (set by the window side)
    // Time playback of a series (data time per frame: timePerFrame; held or looped at the end).
    bool timePlaying = true;
    bool loop = false;
    double time = 0.0, timeStart = 0.0, timeEnd = 0.0, timePerFrame = 0.0;
    std::vector<double> stepTimes;     // of the loaded series; empty for steady data

    // After data is loaded: frames the camera (makeCamera of the options, unless a camera
    // path or orbit drives it), sets the time range (setTimes).
    void dataLoaded(const core::Bounds& bounds, const std::vector<double>& times, const core::TimeMapping& mapping);
    // The steps' times and the options' frame -> time mapping (after a load, or a rebuild
    // that changed them): time playback starts over at the mapping's start.
    void setTimes(const std::vector<double>& times, const core::TimeMapping& mapping);
    // Window pixel size of the whole render area (split into views side by side): the
    // window less what the panel takes beside it. A camera the viewer fitted and the user
    // has not moved is fitted again to the new size.
    void setWindowSize(int width, int height);
    core::Viewport windowSize() const { return window_; }
    // One view's size and the methods shown, left to right.
    core::Viewport viewSize() const;
    std::vector<methods::Method> shownMethods() const;

    // The camera for the current frame (orbit / camera path play until the user takes over).
    core::Camera camera() const;
    // Called after each displayed frame: advances the data time unless paused (the noise
    // clock is the playback's).
    void frameDone();
    // True if the next frame advects (not paused, or a single step asked for).
    bool advancing() const { return !paused || stepOnce; }

    // Applies one input event; errors (bad option values, unknown keys) land in `error`.
    void handle(const Event& e);
    Requests takeRequests();
    // A render option by name, as from the panel or `set`: what must happen is the option
    // table's effect (reload, rebuild, a camera that the user takes over, or nothing).
    void set(const std::string& name, const std::string& value);
    // The camera path could not be read: the camera stays where it is, the user's from now on.
    void dropCameraPath();

    // The options that render the frame drawn at noise clock `clock` (the playback's last
    // frame's) offline: `render --config` with --frames = clock gives the frame on screen,
    // at the data time on screen (see README, Viewer).
    RenderOptions batchOptions(uint32_t clock) const;

    std::string error;       // last error, shown in the panel until the next one or dismissal
    std::string status;      // last message (saved a file, ...)

private:
    void key(const std::string& name);
    // Options the viewer changes as values, not text (camera, method): through the playback.
    template <class Edit>
    void edit(Edit change) {
        RenderOptions o = options();
        change(o);
        playback_->setOptions(o);
    }
    void mouseMove(float x, float y);
    void scroll(float steps);
    void takeOverCamera();
    void setCamera(const core::Camera& c);
    void viewAlong(const glm::vec3& fromDirection);
    void resetView();
    // The default view of the bounds (makeCamera without eye and target) in the render area.
    void fit();
    // Which view (side by side) the window pixel x falls into, and its NDC.
    glm::vec2 cursorNdc(float x, float y) const;

    std::unique_ptr<session::Playback> playback_;
    core::Bounds bounds_;
    bool haveData_ = false;
    core::Viewport window_{800, 600};
    glm::vec3 turntableUp_{0, 1, 0};
    glm::vec2 mouse_{0, 0};
    std::string dragButton_;  // "" when no button is down
    bool dragPan_ = false;
    bool fitted_ = false;  // the camera is fit()'s (or the first load's), not moved since
    Requests requests_;
};

}  // namespace flowsurf::app::view
