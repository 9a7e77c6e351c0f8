// The GLFW window and its input; the panel is in view_panel.cpp.
#include "view_window.h"

#include "core/errors.h"
#include "io/image_writer.h"

#include <epoxy/gl.h>
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#include <cctype>
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
        e.x = float(x * fw / std::max(ww, 1));
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

Window::Window(int width, int height, const std::string& title) {
    glfwSetErrorCallback([](int code, const char* text) { std::fprintf(stderr, "flowsurf: GLFW %d: %s\n", code, text); });
    if (!glfwInit())
        throw GlError("cannot open a window: GLFW found no display (run under X11 or xvfb-run, or use --headless "
                      "--play FILE)");
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

void Window::framebufferSize(int* width, int* height) const { glfwGetFramebufferSize(window_, width, height); }

void Window::resize(int width, int height) { glfwSetWindowSize(window_, width, height); }

void Window::setTitle(const std::string& title) { glfwSetWindowTitle(window_, title.c_str()); }

void Window::emitSet(const std::string& name, const std::string& value) {
    Event e{frame_, EventType::Set, name, value};
    queue_.push_back(e);
}

void Window::present(ViewerState& state, ViewPipeline& pipeline, const FrameInfo& info) {
    int fw = 0, fh = 0;
    framebufferSize(&fw, &fh);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, fw, fh);
    glDisable(GL_SCISSOR_TEST);
    const glm::vec3 bg = state.options.params.common.background;
    glClearColor(bg.r, bg.g, bg.b, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    if (pipeline.ready()) {
        // Each view's composite, left to right, into the window.
        const core::Viewport v = pipeline.viewSize();
        for (size_t i = 0; i < pipeline.viewCount(); ++i) {
            const int x0 = int(i) * v.width;
            glBlitNamedFramebuffer(pipeline.compositeReadFbo(i), 0, 0, 0, v.width, v.height, x0, fh - v.height,
                                   x0 + v.width, fh, GL_COLOR_BUFFER_BIT, GL_NEAREST);
        }
    }
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    panel(state, pipeline, info);
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
