// flowsurf view — the events of a viewer session as data. A live session turns mouse and
// keyboard input into these; `--play FILE` replays them from a plain-text log stamped
// with the viewer's frame counter (never wall time), so a replay is deterministic:
//   # flowsurf events 1
//   at 0 set method hybrid          any render option name without dashes, and its value
//   at 10 mouse-down left [shift]   left | middle | right
//   at 10 mouse-move 400 300        window pixels, origin top-left
//   at 25 mouse-up left
//   at 30 scroll -2                 wheel steps, positive zooms in
//   at 31 key r                     key names as in keyTable()
//   at 90 screenshot out/a.png      the rendered image without the panel
//   at 90 flow-texture out/a16.png  F_a alone, 16-bit gray
//   at 90 save-config out/a.json    the whole state, for render --config
//   at 90 save-keyframe path.json   append the camera to a --camera-path file
//   at 90 window-screenshot w.png  the whole window, panel included
//   at 90 record out/a.mp4 | record-stop | open FILE | resize W H | quit
#pragma once

#include <string>
#include <vector>

namespace flowsurf::app::view {

enum class EventType {
    Set, MouseMove, MouseDown, MouseUp, Scroll, Key, Screenshot, FlowTexture, SaveConfig, SaveKeyframe,
    Record, RecordStop, Open, Resize, Quit, WindowShot
};

struct Event {
    long frame = 0;          // viewer frame counter at which it applies
    EventType type = EventType::Quit;
    std::string name{};      // Set: option; MouseDown/Up: button; Key: key name
    std::string value{};     // Set: value; file events: path
    float x = 0, y = 0;      // MouseMove: window pixels; Scroll: x = steps; Resize: width, height
    bool shift = false;      // MouseDown: with shift held
};

// Events of the viewer's input and output, as they reach the state: input events are
// applied before frame `frame` renders, output events after it.
bool isOutputEvent(EventType type);

// Parses a log; throws FormatError naming the file and line. Events come back sorted by
// frame (stable: same-frame events keep their order).
std::vector<Event> parseEventLog(const std::string& text, const std::string& where);
std::vector<Event> readEventLog(const std::string& path);
// One event as a log line ("at 10 mouse-move 400 300").
std::string formatEvent(const Event& e);
// "# flowsurf events 1\n" and the events.
std::string formatEventLog(const std::vector<Event>& events);

}  // namespace flowsurf::app::view
