// The viewer's Dear ImGui panel: read-outs, and every method/overlay option as a widget
// generated from the option table (same names, ranges and defaults as the command line).
// Edits become `set` events (recorded like mouse and keys), applied on the next frame.
#include "view_window.h"

#include "cli_options.h"
#include "session/options/dye_sources.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace flowsurf::app::view {

namespace {

std::string upper(std::string s) {
    for (char& c : s) c = char(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

}  // namespace

void Window::optionWidget(const OptionSpec& spec, const ViewerState& state, bool visibleRange) {
    const std::string current = spec.get(state.options());
    const char* label = spec.name.c_str();
    switch (spec.kind) {
    case OptionKind::Flag: {
        bool v = current == "true";
        if (ImGui::Checkbox(label, &v)) emitSet(spec.name, v ? "true" : "false");
        break;
    }
    case OptionKind::Choice: {
        int index = int(std::find(spec.choices.begin(), spec.choices.end(), current) - spec.choices.begin());
        if (ImGui::BeginCombo(label, current.c_str())) {
            for (int i = 0; i < int(spec.choices.size()); ++i)
                if (ImGui::Selectable(spec.choices[size_t(i)].c_str(), i == index)) emitSet(spec.name, spec.choices[size_t(i)]);
            ImGui::EndCombo();
        }
        break;
    }
    case OptionKind::Int:
    case OptionKind::Float: {
        // Sliders over the option's range; the value is applied when the edit ends (a new
        // value rebuilds the renderers, which a drag should not do every frame).
        auto it = edits_.find(spec.name);
        double v = std::stod(it != edits_.end() ? it->second : current);
        bool slider = spec.max - spec.min <= 10000.0;
        if (spec.kind == OptionKind::Int) {
            int i = int(v);
            if (slider) ImGui::SliderInt(label, &i, int(spec.min), int(spec.max), "%d", ImGuiSliderFlags_AlwaysClamp);
            else ImGui::InputInt(label, &i);
            v = i;
        } else {
            float f = float(v);
            if (slider) ImGui::SliderFloat(label, &f, float(spec.min), float(spec.max), "%.3g", ImGuiSliderFlags_AlwaysClamp);
            else ImGui::InputFloat(label, &f, 0, 0, "%.6g");
            v = f;
        }
        const std::string text = spec.kind == OptionKind::Int ? std::to_string(int64_t(v)) : formatFloat(float(v));
        if (ImGui::IsItemActive()) edits_[spec.name] = text;
        if (ImGui::IsItemDeactivatedAfterEdit()) emitSet(spec.name, text);
        if (!ImGui::IsItemActive()) edits_.erase(spec.name);
        break;
    }
    case OptionKind::Color: {
        const glm::vec3 c = parseColor(current, "--" + spec.name);
        float rgb[3] = {c.r, c.g, c.b};
        ImGui::ColorEdit3(label, rgb);
        if (ImGui::IsItemDeactivatedAfterEdit())
            emitSet(spec.name, formatFloat(rgb[0]) + "," + formatFloat(rgb[1]) + "," + formatFloat(rgb[2]));
        break;
    }
    default: {
        std::string& text = edits_.try_emplace(spec.name, current).first->second;
        ImGui::InputText(label, &text, ImGuiInputTextFlags_EnterReturnsTrue);
        if (ImGui::IsItemDeactivatedAfterEdit()) emitSet(spec.name, text);
        if (!ImGui::IsItemActive()) edits_.erase(spec.name);
        // Range options [doc/contrast.md, the viewer's framing]: one click rescales to the data's whole or robust range,
        // or (colour) to the values the view shows, set as MIN:MAX so that a log replays it.
        if (spec.rescale != RangeRescale::None) {
            ImGui::PushID(label);
            ImGui::TextUnformatted("  rescale:");
            for (const char* to : {"robust", "data"}) {
                ImGui::SameLine();
                if (ImGui::SmallButton(to)) emitSet(spec.name, to);
            }
            if (spec.rescale == RangeRescale::DataAndView && visibleRange) {
                ImGui::SameLine();
                if (ImGui::SmallButton("visible")) emitSet(spec.name, "visible");  // resolved by the session
                if (ImGui::IsItemHovered())
                    ImGui::SetTooltip("The range of the colour values over the surface's visible pixels");
            }
            ImGui::PopID();
        }
        break;
    }
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("--%s: %s (default %s)", spec.name.c_str(), spec.help.c_str(),
                                                  defaultText(spec).c_str());
}

void Window::dyePanel(const ViewerState& state) {
    ImGui::TextWrapped("ctrl + click on the surface releases dye there");
    std::vector<methods::DyeSource> sources = state.options().dye;
    int removed = -1;
    bool moved = false;
    for (size_t i = 0; i < sources.size(); ++i) {
        ImGui::PushID(int(i));
        methods::DyeSource& s = sources[i];
        ImGui::ColorButton("##c", ImVec4(s.color.r, s.color.g, s.color.b, 1.0f), ImGuiColorEditFlags_NoTooltip);
        ImGui::SameLine();
        // Edited in place; the option changes when the field is left (one event per move).
        ImGui::InputFloat3("##p", &s.point.x, "%.4g");
        moved |= ImGui::IsItemDeactivatedAfterEdit();
        ImGui::SameLine();
        if (ImGui::SmallButton("x")) removed = int(i);
        ImGui::PopID();
    }
    if (removed >= 0) sources.erase(sources.begin() + removed);
    if (removed >= 0 || moved) emitSet("dye", session::dyeSourcesText(sources));
    for (const OptionSpec& spec : renderOptionTable())
        if (spec.role.group == OptionGroup::Dye && spec.takes(FrontEnd::Panel)) optionWidget(spec, state);
}

void Window::panel(ViewerState& state, ViewPipeline& pipeline, const FrameInfo& info) {
    // Method labels over the views, side by side.
    if (pipeline.ready() && pipeline.viewCount() > 1) {
        ImDrawList* draw = ImGui::GetForegroundDrawList();
        for (size_t i = 0; i < pipeline.viewCount(); ++i)
            draw->AddText(ImVec2(float(panelWidth() + int(i) * pipeline.viewSize().width) + 8.0f, 6.0f),
                          IM_COL32(255, 255, 255, 230),
                          upper(pipeline.methodName(i)).c_str());
    }
    panelShown_ = state.showPanel;
    if (!state.showPanel) return;
    // A column at the window's left, beside the views (never over the data); it scrolls
    // rather than running off the bottom. Collapsed (its title bar's arrow), it gives its
    // width back to the views: the render area changes with the next frame.
    ImGui::SetNextWindowPos(ImVec2(0, 0), ImGuiCond_Always);
    const float width = state.panelCollapsed ? 110.0f : float(kPanelWidth);  // collapsed: the title bar only
    ImGui::SetNextWindowSize(ImVec2(width, ImGui::GetIO().DisplaySize.y), ImGuiCond_Always);
    ImGui::SetNextWindowCollapsed(state.panelCollapsed, ImGuiCond_Always);
    const bool open = ImGui::Begin("flowsurf", nullptr,
                                   ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                       ImGuiWindowFlags_AlwaysVerticalScrollbar | ImGuiWindowFlags_NoSavedSettings);
    // A click on the title bar's arrow becomes an event (recorded, replayed in a window).
    panelCollapsed_ = ImGui::IsWindowCollapsed();
    if (panelCollapsed_ != state.panelCollapsed) emitSet("panel-collapsed", panelCollapsed_ ? "true" : "false");
    if (!open) {
        ImGui::End();
        return;
    }
    ImGui::PushItemWidth(170);
    readout(state, pipeline, info);
    methodSection(state, pipeline);
    timeSection(state);
    optionSections(state, pipeline);
    stageTimes(pipeline);
    qualitySection(state, pipeline);
    saveSection(state);
    keysSection();
    ImGui::PopItemWidth();
    ImGui::End();
}

// The last error and message; what is shown and what it costs.
void Window::readout(ViewerState& state, const ViewPipeline& pipeline, const FrameInfo& info) {
    if (!state.error.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, IM_COL32(255, 110, 100, 255));
        ImGui::TextWrapped("Error: %s", state.error.c_str());
        ImGui::PopStyleColor();
        if (ImGui::SmallButton("dismiss")) state.error.clear();
    }
    if (!state.status.empty()) ImGui::TextWrapped("%s", state.status.c_str());

    ImGui::Text("%s", pipeline.input().c_str());
    ImGui::Text("%zu triangles, %dx%d per view", pipeline.triangles(), pipeline.viewSize().width,
                pipeline.viewSize().height);
    ImGui::Text("%s", info.renderer.c_str());
    ImGui::Text("frame %.1f ms (%.1f fps), clock k = %u%s", info.frameMs, info.frameMs > 0 ? 1000.0 / info.frameMs : 0.0,
                state.playback().lastFrame().clock, state.paused ? ", paused" : "");
}

// Method (one, or all side by side), pause and step, and the field shown.
void Window::methodSection(const ViewerState& state, const ViewPipeline& pipeline) {
    std::string all;
    for (const auto& [m, name] : methods::kMethodNames) {
        if (!all.empty()) ImGui::SameLine();
        all += (all.empty() ? "" : ",") + std::string(name);
        if (ImGui::RadioButton(upper(std::string(name)).c_str(), state.compare.empty() && state.options().method == m))
            emitSet("method", std::string(name)), emitSet("compare", "off");
    }
    bool side = !state.compare.empty();
    ImGui::SameLine();
    if (ImGui::Checkbox("side by side", &side)) emitSet("compare", side ? all : "off");
    bool paused = state.paused;
    if (ImGui::Checkbox("paused", &paused)) emitSet("paused", paused ? "true" : "false");
    ImGui::SameLine();
    if (ImGui::Button("step")) queue_.push_back({frame_, EventType::Key, "n"});

    if (!pipeline.vectorFields().empty() && ImGui::BeginCombo("field", pipeline.field().c_str())) {
        for (const std::string& f : pipeline.vectorFields())
            if (ImGui::Selectable(f.c_str(), f == pipeline.field())) emitSet("field", f);
        ImGui::EndCombo();
    }
}

// Time playback of a series.
void Window::timeSection(const ViewerState& state) {
    if (!state.stepTimes.empty() && ImGui::CollapsingHeader("Time", ImGuiTreeNodeFlags_DefaultOpen)) {
        if (ImGui::Button(state.timePlaying ? "pause time" : "play time"))
            emitSet("time-playing", state.timePlaying ? "false" : "true");
        ImGui::SameLine();
        bool loop = state.loop;
        if (ImGui::Checkbox("loop", &loop)) emitSet("loop", loop ? "true" : "false");
        ImGui::Text("t = %.6g  (%.6g .. %.6g)", state.time, state.timeStart, state.timeEnd);
        const auto& t = state.stepTimes;
        int step = int(std::lower_bound(t.begin(), t.end(), state.time - 1e-12) - t.begin());
        step = std::clamp(step, 0, int(t.size()) - 1);
        if (ImGui::SliderInt("step", &step, 0, int(t.size()) - 1)) {
            emitSet("time-playing", "false");
            emitSet("time-now", formatDouble(t[size_t(step)]));
        }
        double speed = state.timePerFrame;
        if (ImGui::InputDouble("time/frame", &speed, 0, 0, "%.6g", ImGuiInputTextFlags_EnterReturnsTrue))
            emitSet("speed", formatDouble(speed));
    }
}

// The camera read-out (editable) and the option rows of the panel, by group.
void Window::optionSections(const ViewerState& state, const ViewPipeline& pipeline) {
    if (ImGui::CollapsingHeader("Camera")) {
        int mode = state.rotateMode == RotateMode::Turntable ? 0 : 1;
        if (ImGui::Combo("rotate", &mode, "turntable\0trackball\0")) emitSet("rotate", mode == 0 ? "turntable" : "trackball");
        for (const OptionSpec& spec : renderOptionTable())
            if (spec.role.group == OptionGroup::Camera && spec.takes(FrontEnd::Panel)) optionWidget(spec, state);
        if (ImGui::Button("reset view")) queue_.push_back({frame_, EventType::Key, "r"});
    }

    // A row shows when it applies to a method shown (its row's methods).
    const std::vector<methods::Method> shown = state.shownMethods();
    const auto applies = [&](const OptionSpec& spec) {
        return std::any_of(shown.begin(), shown.end(), [&](methods::Method m) { return spec.appliesTo(m); });
    };
    for (const OptionGroup group : {OptionGroup::Method, OptionGroup::Overlay})
        if (ImGui::CollapsingHeader(group == OptionGroup::Method ? "Method parameters" : "Overlay"))
            for (const OptionSpec& spec : renderOptionTable())
                if (spec.role.group == group && spec.takes(FrontEnd::Panel) && applies(spec))
                    optionWidget(spec, state, pipeline.ready());

    if (ImGui::CollapsingHeader("Dye")) dyePanel(state);
}

// Per-stage times of each view (mean over the last frames).
void Window::stageTimes(ViewPipeline& pipeline) {
    if (pipeline.ready() && ImGui::CollapsingHeader("Stage times", ImGuiTreeNodeFlags_DefaultOpen)) {
        for (size_t i = 0; i < pipeline.viewCount(); ++i) {
            auto& timer = pipeline.method(i).timer();
            ImGui::Text("%s%s", upper(pipeline.methodName(i)).c_str(),
                        pipeline.method(i).lastFrameDynamic() ? " (dynamic case)" : " (static case)");
            for (const auto& [stage, ms] : timer.meanMs(false)) ImGui::BulletText("%-28s %7.2f ms", stage.c_str(), ms);
        }
    }
}

// Screenshot, recording, settings, camera keyframe, open.
void Window::saveSection(const ViewerState& state) {
    if (ImGui::CollapsingHeader("Save")) {
        ImGui::InputText("##shot", &screenshotPath_);
        ImGui::SameLine();
        if (ImGui::Button("screenshot")) queue_.push_back({frame_, EventType::Screenshot, "", screenshotPath_});
        ImGui::InputText("##rec", &recordPath_);
        ImGui::SameLine();
        if (ImGui::Button(state.recording ? "stop recording" : "record MP4"))
            queue_.push_back(state.recording ? Event{frame_, EventType::RecordStop}
                                             : Event{frame_, EventType::Record, "", recordPath_});
        ImGui::InputText("##cfg", &configPath_);
        ImGui::SameLine();
        if (ImGui::Button("save settings")) queue_.push_back({frame_, EventType::SaveConfig, "", configPath_});
        ImGui::InputText("##key", &keyframePath_);
        ImGui::SameLine();
        if (ImGui::Button("save camera keyframe")) queue_.push_back({frame_, EventType::SaveKeyframe, "", keyframePath_});
        ImGui::InputText("##open", &openPath_);
        ImGui::SameLine();
        if (ImGui::Button("open")) queue_.push_back({frame_, EventType::Open, "", openPath_});
    }
}

void Window::keysSection() {
    if (ImGui::CollapsingHeader("Mouse and keys")) {
        ImGui::BulletText("left drag: rotate (turntable; trackball with t)");
        ImGui::BulletText("middle drag or shift + left drag: pan");
        ImGui::BulletText("wheel: zoom towards the cursor; right drag: zoom");
        ImGui::BulletText("drop a file on the window: open it");
        ImGui::BulletText("ctrl + click on the surface: release dye there");
        for (const KeyBinding& k : keyTable()) ImGui::BulletText("%-6s %s", k.name, k.description);
    }
}

// How faithful each view's texture is to the field: off by default (a measured frame
// costs a surface pass, a read-back and CPU work); on, every N-th frame is measured. The
// widgets emit `set quality N|off`, recorded like every edit.
void Window::qualitySection(const ViewerState& state, ViewPipeline& pipeline) {
    bool on = state.playback().quality().every() > 0;
    if (on) ImGui::SetNextItemOpen(true, ImGuiCond_Once);  // turned on by an event or a replay
    if (!ImGui::CollapsingHeader("Quality")) return;
    if (ImGui::Checkbox("measure", &on)) emitSet("quality", on ? "10" : "off");
    if (on) {
        int every = state.playback().quality().every();
        ImGui::SameLine();
        ImGui::SetNextItemWidth(100);
        if (ImGui::SliderInt("every N frames", &every, 2, 60)) emitSet("quality", std::to_string(every));
    }
    if (!on || !pipeline.ready()) return;
    session::Playback& playback = pipeline.playback();
    for (size_t i = 0; i < pipeline.viewCount(); ++i) {
        const auto& frames = playback.quality().frames(i);
        ImGui::Text("%s: %zu frames measured", upper(pipeline.methodName(i)).c_str(), frames.size());
        if (frames.empty()) continue;
        const quality::QualitySummary summary = playback.quality().summary(i);
        for (const quality::MetricInfo& m : quality::metricTable()) {
            ImGui::BulletText("%-30s %8.3f  (median %.3f)", m.name, frames.back().*m.member, summary.median.*m.member);
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", m.help);
        }
    }
}

}  // namespace flowsurf::app::view
