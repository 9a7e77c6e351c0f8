#include "view_events.h"

#include "core/camera.h"
#include "core/errors.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

namespace flowsurf::app::view {

namespace {

struct TypeName {
    EventType type;
    const char* name;
};
constexpr TypeName kTypes[] = {
    {EventType::Set, "set"},           {EventType::MouseMove, "mouse-move"},
    {EventType::MouseDown, "mouse-down"}, {EventType::MouseUp, "mouse-up"},
    {EventType::Scroll, "scroll"},     {EventType::Key, "key"},
    {EventType::Screenshot, "screenshot"}, {EventType::FlowTexture, "flow-texture"},
    {EventType::SaveConfig, "save-config"}, {EventType::SaveKeyframe, "save-keyframe"},
    {EventType::Record, "record"},     {EventType::RecordStop, "record-stop"},
    {EventType::Open, "open"},         {EventType::Resize, "resize"},
    {EventType::Quit, "quit"},         {EventType::WindowShot, "window-screenshot"},
};

std::string trim(const std::string& s) {
    size_t a = s.find_first_not_of(" \t\r");
    if (a == std::string::npos) return {};
    size_t b = s.find_last_not_of(" \t\r");
    return s.substr(a, b - a + 1);
}

float number(const std::string& word, const std::string& where) {
    try {
        size_t used = 0;
        float v = std::stof(word, &used);
        if (used == word.size() && std::isfinite(v)) return v;
    } catch (const std::exception&) {
    }
    throw FormatError(where + ": '" + word + "' is not a number");
}

// The words after the event's name: its arguments, into `e`.
void parseArguments(Event& e, const std::string& typeText, const std::string& rest, const std::string& at) {
    std::istringstream args(rest);
    std::vector<std::string> w;
    for (std::string a; args >> a;) w.push_back(a);
    auto need = [&](size_t n, const char* form) {
        if (w.size() != n) throw FormatError(at + ": expected '" + typeText + (*form ? " " : "") + form + "'");
    };
    switch (e.type) {
    case EventType::Set: {
        if (w.empty()) throw FormatError(at + ": expected 'set OPTION VALUE'");
        e.name = w[0];
        e.value = trim(rest.substr(rest.find(w[0]) + w[0].size()));
        break;
    }
    case EventType::MouseMove:
        need(2, "X Y");
        e.x = number(w[0], at);
        e.y = number(w[1], at);
        break;
    case EventType::MouseDown:
    case EventType::MouseUp:
        if (w.empty() || w.size() > 2 || (w.size() == 2 && w[1] != "shift"))
            throw FormatError(at + ": expected '" + typeText + " left|middle|right [shift]'");
        if (w[0] != "left" && w[0] != "middle" && w[0] != "right")
            throw FormatError(at + ": unknown mouse button '" + w[0] + "' (left, middle, right)");
        e.name = w[0];
        e.shift = w.size() == 2;
        break;
    case EventType::Scroll:
        need(1, "STEPS");
        e.x = number(w[0], at);
        break;
    case EventType::Key:
        need(1, "NAME");
        e.name = w[0];
        break;
    case EventType::Resize:
        need(2, "WIDTH HEIGHT");
        e.x = number(w[0], at);
        e.y = number(w[1], at);
        if (e.x < core::kMinImageSide || e.y < core::kMinImageSide || e.x > core::kMaxImageSide ||
            e.y > core::kMaxImageSide)
            throw FormatError(at + ": window size out of range (" + std::to_string(core::kMinImageSide) + ".." +
                              std::to_string(core::kMaxImageSide) + ")");
        break;
    case EventType::Screenshot:
    case EventType::WindowShot:
    case EventType::FlowTexture:
    case EventType::SaveConfig:
    case EventType::SaveKeyframe:
    case EventType::Record:
    case EventType::Open:
        if (rest.empty()) throw FormatError(at + ": '" + typeText + "' needs a FILE");
        e.value = rest;
        break;
    case EventType::RecordStop:
    case EventType::Quit:
        need(0, "");
        break;
    }
}

// "at FRAME EVENT ARGS..." (trimmed, comment removed); `at`: file and line for errors.
Event parseLine(const std::string& line, const std::string& at) {
    std::istringstream words(line);
    std::string kw, frameText, typeText;
    words >> kw >> frameText >> typeText;
    if (kw != "at" || typeText.empty())
        throw FormatError(at + ": expected 'at FRAME EVENT ...', got '" + line + "'");
    Event e;
    try {
        size_t used = 0;
        long f = std::stol(frameText, &used);
        if (used != frameText.size() || f < 0) throw std::invalid_argument(frameText);
        e.frame = f;
    } catch (const std::exception&) {
        throw FormatError(at + ": frame '" + frameText + "' is not a non-negative integer");
    }
    const TypeName* type = std::find_if(std::begin(kTypes), std::end(kTypes),
                                        [&](const TypeName& t) { return typeText == t.name; });
    if (type == std::end(kTypes)) throw FormatError(at + ": unknown event '" + typeText + "'");
    e.type = type->type;
    std::string rest;
    std::getline(words, rest);
    parseArguments(e, typeText, trim(rest), at);
    return e;
}

}  // namespace

bool isOutputEvent(EventType t) {
    return t == EventType::Screenshot || t == EventType::WindowShot || t == EventType::FlowTexture || t == EventType::SaveConfig ||
           t == EventType::SaveKeyframe || t == EventType::Quit;
}

std::vector<Event> parseEventLog(const std::string& text, const std::string& where) {
    std::vector<Event> events;
    std::istringstream in(text);
    std::string line;
    int lineNo = 0;
    while (std::getline(in, line)) {
        ++lineNo;
        // Comments: a line starting with '#', or " #" after an event.
        if (size_t hash = line.find(" #"); hash != std::string::npos) line.resize(hash);
        line = trim(line);
        if (line.empty() || line[0] == '#') continue;
        events.push_back(parseLine(line, where + ":" + std::to_string(lineNo)));
    }
    std::stable_sort(events.begin(), events.end(), [](const Event& a, const Event& b) { return a.frame < b.frame; });
    return events;
}

std::vector<Event> readEventLog(const std::string& path) {
    std::ifstream f(path);
    if (!f) throw IoError(path + ": cannot open (" + std::strerror(errno) + ")");
    std::stringstream ss;
    ss << f.rdbuf();
    return parseEventLog(ss.str(), path);
}

std::string formatEvent(const Event& e) {
    const char* type = "quit";
    for (const TypeName& t : kTypes)
        if (t.type == e.type) type = t.name;
    std::ostringstream s;
    s << "at " << e.frame << " " << type;
    switch (e.type) {
    case EventType::Set: s << " " << e.name << " " << e.value; break;
    case EventType::MouseMove: s << " " << e.x << " " << e.y; break;
    case EventType::MouseDown:
    case EventType::MouseUp: s << " " << e.name << (e.shift ? " shift" : ""); break;
    case EventType::Scroll: s << " " << e.x; break;
    case EventType::Key: s << " " << e.name; break;
    case EventType::Resize: s << " " << e.x << " " << e.y; break;
    case EventType::RecordStop:
    case EventType::Quit: break;
    default: s << " " << e.value; break;
    }
    return s.str();
}

std::string formatEventLog(const std::vector<Event>& events) {
    std::string out = "# flowsurf events 1\n";
    for (const Event& e : events) out += formatEvent(e) + "\n";
    return out;
}

}  // namespace flowsurf::app::view
