// The GLFW window and its input; the panel is in view_panel.cpp.
#include "view_window.h"

#include "core/errors.h"
#include "io/image_writer.h"
#include "session/options/dye_sources.h"

#include <epoxy/gl.h>
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#include <algorithm>
#include <cmath>
#include <cctype>
#include <iterator>
#include <cstdio>
#include <utility>

namespace flowsurf::app::view {

struct WindowCallbacks {
    static Window& self(GLFWwindow* w) { return *static_cast<Window*>(glfwGetWindowUserPointer(w)); }

    static void cursor(GLFWwindow* w, double x, double y) {
        if (ImGui::GetCurrentContext() && ImGui::GetIO().WantCaptureMouse) return;
        Window& s = self(w);
        // Window coordinates -> framebuffer pixels (equal on X11; differ on HiDPI screens).
        int ww = 1, wh = 1, fw = 1, fh = 1;
        glfwGetWindowSize(w, &ww, &wh);
        glfwGetFramebufferSize(w, &fw, &fh);
        Event e{s.frame_, EventType::MouseMove};
        e.x = float(x * fw / std::max(ww, 1)) - float(s.panelWidth());  // render-area pixels
        e.y = float(y * fh / std::max(wh, 1));
        s.queue_.push_back(e);
    }
    static void button(GLFWwindow* w, int button, int action, int mods) {
        if (ImGui::GetCurrentContext() && ImGui::GetIO().WantCaptureMouse && action == GLFW_PRESS) return;
        const char* name = button == GLFW_MOUSE_BUTTON_LEFT     ? "left"
                           : button == GLFW_MOUSE_BUTTON_MIDDLE ? "middle"
                           : button == GLFW_MOUSE_BUTTON_RIGHT  ? "right"
                                                                : nullptr;
        if (!name) return;
        Window& s = self(w);
        if (button == GLFW_MOUSE_BUTTON_LEFT && action == GLFW_PRESS && (mods & GLFW_MOD_CONTROL)) {
            // ctrl + click: dye at the surface point under the cursor (resolved in present()).
            double cx = 0, cy = 0;
            int ww = 1, wh = 1, fw = 1, fh = 1;
            glfwGetCursorPos(w, &cx, &cy);
            glfwGetWindowSize(w, &ww, &wh);
            glfwGetFramebufferSize(w, &fw, &fh);
            s.dyeClick_ = glm::vec2(float(cx * fw / std::max(ww, 1)) - float(s.panelWidth()), float(cy * fh / std::max(wh, 1)));
            s.swallowRelease_ = true;
            return;
        }
        if (button == GLFW_MOUSE_BUTTON_LEFT && action == GLFW_RELEASE && s.swallowRelease_) {
            s.swallowRelease_ = false;
            return;
        }
        Event e{s.frame_, action == GLFW_PRESS ? EventType::MouseDown : EventType::MouseUp, name};
        e.shift = action == GLFW_PRESS && (mods & GLFW_MOD_SHIFT);
        s.queue_.push_back(e);
    }
    static void scroll(GLFWwindow* w, double, double dy) {
        if (ImGui::GetCurrentContext() && ImGui::GetIO().WantCaptureMouse) return;
        Window& s = self(w);
        Event e{s.frame_, EventType::Scroll};
        e.x = float(dy);
        s.queue_.push_back(e);
    }
    static void key(GLFWwindow* w, int key, int scancode, int action, int mods) {
        if (action != GLFW_PRESS && action != GLFW_REPEAT) return;
        if (ImGui::GetCurrentContext() && ImGui::GetIO().WantCaptureKeyboard) return;
        std::string name;
        switch (key) {
        case GLFW_KEY_SPACE: name = "space"; break;
        case GLFW_KEY_ESCAPE: name = "escape"; break;
        case GLFW_KEY_LEFT: name = "left"; break;
        case GLFW_KEY_RIGHT: name = "right"; break;
        case GLFW_KEY_F1: name = "f1"; break;
        default:
            if (const char* n = glfwGetKeyName(key, scancode); n && n[1] == '\0' && std::isalpha((unsigned char)n[0])) {
                name = std::string(1, char(std::tolower((unsigned char)n[0])));
                if ((mods & GLFW_MOD_SHIFT) && (name == "x" || name == "y" || name == "z"))
                    name[0] = char(std::toupper((unsigned char)name[0]));
            }
        }
        bool known = false;
        for (const KeyBinding& k : keyTable())
            known |= name == k.name || (name.size() == 1 && std::tolower((unsigned char)name[0]) == k.name[0] &&
                                        k.name[1] == '\0');
        if (name.empty() || (!known && name != "escape" && name != "f1")) return;
        Window& s = self(w);
        s.queue_.push_back({s.frame_, EventType::Key, name});
    }
    static void drop(GLFWwindow* w, int count, const char** paths) {
        if (count < 1) return;
        Window& s = self(w);
        s.queue_.push_back({s.frame_, EventType::Open, "", paths[0]});
    }
};

Window::Window(int width, int height, const std::string& title, bool fitScreen) {
    glfwSetErrorCallback([](int code, const char* text) { std::fprintf(stderr, "flowsurf: GLFW %d: %s\n", code, text); });
    if (!glfwInit())
        throw GlError("cannot open a window: GLFW found no display (run under X11 or xvfb-run, or use --headless "
                      "--play FILE)");
    width += kPanelWidth;
    if (GLFWmonitor* monitor = glfwGetPrimaryMonitor(); fitScreen && monitor) {
        // 90 % of the work area (the screen less task bars), never smaller than the panel
        // beside a 320 x 240 view.
        int x = 0, y = 0, w = 0, h = 0;
        glfwGetMonitorWorkarea(monitor, &x, &y, &w, &h);
        if (w > 0 && h > 0) {
            width = std::max(kPanelWidth + 320, w * 9 / 10);
            height = std::max(240, h * 9 / 10);
        }
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!window_) {
        glfwTerminate();
        throw GlError("cannot open a window with an OpenGL 4.5 core context (GLFW)");
    }
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(0);  // frame times measure the pipeline, not the display's refresh
    glfwSetWindowUserPointer(window_, this);
    glfwSetCursorPosCallback(window_, WindowCallbacks::cursor);
    glfwSetMouseButtonCallback(window_, WindowCallbacks::button);
    glfwSetScrollCallback(window_, WindowCallbacks::scroll);
    glfwSetKeyCallback(window_, WindowCallbacks::key);
    glfwSetDropCallback(window_, WindowCallbacks::drop);
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini next to the user's files
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForOpenGL(window_, true);  // chains to the callbacks above
    ImGui_ImplOpenGL3_Init("#version 450 core");
}

Window::~Window() {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    glfwDestroyWindow(window_);
    glfwTerminate();
}

std::vector<Event> Window::poll(long frame, bool idle) {
    frame_ = frame;
    if (idle && queue_.empty()) glfwWaitEventsTimeout(0.05);
    else glfwPollEvents();
    std::vector<Event> out;
    out.swap(queue_);
    for (Event& e : out) e.frame = frame;  // panel edits were queued during the last frame
    return out;
}

bool Window::closeRequested() const { return glfwWindowShouldClose(window_); }

void Window::framebufferSize(int* width, int* height) const {
    glfwGetFramebufferSize(window_, width, height);
    *width = std::max(0, *width - panelWidth());
}

void Window::resize(int width, int height) { glfwSetWindowSize(window_, width + panelWidth(), height); }

void Window::setTitle(const std::string& title) { glfwSetWindowTitle(window_, title.c_str()); }

void Window::emitSet(const std::string& name, const std::string& value) {
    Event e{frame_, EventType::Set, name, value};
    queue_.push_back(e);
}

void Window::dropDye(const ViewerState& state, ViewPipeline& pipeline) {
    const glm::vec2 click = *dyeClick_;
    dyeClick_.reset();
    if (!pipeline.ready() || pipeline.viewCount() == 0) return;
    const core::Viewport v = pipeline.viewSize();
    const int view = std::clamp(int(click.x) / std::max(v.width, 1), 0, int(pipeline.viewCount()) - 1);
    const int x = int(click.x) - view * v.width, y = v.height - 1 - int(click.y);  // GL rows bottom to top
    if (x < 0 || x >= v.width || y < 0 || y >= v.height) return;
    float depth = 1.0f;
    glGetTextureSubImage(pipeline.method(size_t(view)).surfaceDepth().id(), 0, x, y, 0, 1, 1, 1, GL_DEPTH_COMPONENT,
                         GL_FLOAT, sizeof depth, &depth);
    if (depth >= 1.0f) return;  // background: nothing to dye
    const glm::mat4 inv = glm::inverse(pipeline.playback().lastFrame().camera.viewProjection(v.aspect()));
    const glm::vec4 ndc((x + 0.5f) / float(v.width) * 2.0f - 1.0f, (y + 0.5f) / float(v.height) * 2.0f - 1.0f,
                        depth * 2.0f - 1.0f, 1.0f);
    const glm::vec4 p = inv * ndc;
    std::vector<methods::DyeSource> sources = state.options().dye;
    sources.push_back(session::dyeSource(glm::vec3(p) / p.w, 0.0f, std::nullopt, sources.size(), "--dye"));
    emitSet("dye", session::dyeSourcesText(sources));
}

// --topology on: the type and position of the critical point under the cursor.
void Window::topologyTooltip(const ViewPipeline& pipeline) const {
    const skeleton::Skeleton* s = pipeline.ready() ? pipeline.playbackView().lastFrame().topology : nullptr;
    if (!s || s->criticalPoints.empty() || ImGui::GetIO().WantCaptureMouse) return;
    int ww = 1, wh = 1, fw = 1, fh = 1;
    glfwGetWindowSize(window_, &ww, &wh);
    glfwGetFramebufferSize(window_, &fw, &fh);
    const ImVec2 mouse = ImGui::GetMousePos();
    const core::Viewport v = pipeline.viewSize();
    const float x = mouse.x * float(fw) / float(std::max(ww, 1)) - float(panelWidth());
    const float yUp = float(v.height) - mouse.y * float(fh) / float(std::max(wh, 1));
    if (x < 0.0f || v.width <= 0) return;
    const float xInView = std::fmod(x, float(v.width));
    const float reach = 0.5f * pipeline.playbackView().options().topologyGlyphSize + 3.0f;
    const skeleton::CriticalPoint* best = nullptr;
    float bestDist = reach;
    for (const skeleton::CriticalPoint& p : s->criticalPoints) {
        const glm::vec3 px = core::projectToPixels(pipeline.playbackView().lastFrame().camera, v, p.position);
        const float d = glm::length(glm::vec2(px.x - xInView, px.y - yUp));
        if (px.z < 1.0f && d < bestDist) { best = &p; bestDist = d; }
    }
    if (best)
        ImGui::SetTooltip("%s (index %+d)\nat %.6g, %.6g, %.6g", skeleton::pointTypeName(best->type), best->index,
                          double(best->position.x), double(best->position.y), double(best->position.z));
}

void Window::present(ViewerState& state, ViewPipeline& pipeline, const FrameInfo& info) {
    if (dyeClick_) dropDye(state, pipeline);
    int fw = 0, fh = 0;
    glfwGetFramebufferSize(window_, &fw, &fh);  // the whole window: panel and views
    const int left = panelWidth();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, fw, fh);
    glDisable(GL_SCISSOR_TEST);
    const glm::vec3 bg = state.options().params.common.background;
    glClearColor(bg.r, bg.g, bg.b, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    if (pipeline.ready()) {
        // Each view's composite, left to right, into the window right of the panel.
        const core::Viewport v = pipeline.viewSize();
        for (size_t i = 0; i < pipeline.viewCount(); ++i) {
            const int x0 = left + int(i) * v.width;
            glBlitNamedFramebuffer(pipeline.compositeReadFbo(i), 0, 0, 0, v.width, v.height, x0, fh - v.height,
                                   x0 + v.width, fh, GL_COLOR_BUFFER_BIT, GL_NEAREST);
        }
    }
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    panel(state, pipeline, info);
    topologyTooltip(pipeline);
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    if (!windowShot_.empty()) {
        std::vector<uint8_t> rgb(size_t(fw) * size_t(fh) * 3), flipped(rgb.size());
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadBuffer(GL_BACK);
        glReadPixels(0, 0, fw, fh, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
        for (int y = 0; y < fh; ++y)
            std::copy_n(&rgb[size_t(fh - 1 - y) * fw * 3], size_t(fw) * 3, &flipped[size_t(y) * fw * 3]);
        const std::string path = std::exchange(windowShot_, {});
        try {
            io::writePngRgb8(path, fw, fh, 3, flipped);
        } catch (const std::exception& e) {
            state.error = e.what();
        }
    }
    glfwSwapBuffers(window_);
}

}  // namespace flowsurf::app::view
