// flowsurf — move-only RAII wrappers of OpenGL 4.5 objects (direct state access).
// A default-constructed wrapper owns nothing and needs no context.
#pragma once

#include <epoxy/gl.h>

#include <cstddef>
#include <deque>
#include <string>
#include <utility>
#include <vector>

namespace flowsurf::gl {

template <void (*Delete)(GLuint)>
class Handle {
public:
    Handle() = default;
    explicit Handle(GLuint id) : id_(id) {}
    ~Handle() { reset(); }
    Handle(Handle&& o) noexcept : id_(std::exchange(o.id_, 0)) {}
    Handle& operator=(Handle&& o) noexcept {
        if (this != &o) { reset(); id_ = std::exchange(o.id_, 0); }
        return *this;
    }
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;
    GLuint id() const { return id_; }
    explicit operator bool() const { return id_ != 0; }
    void reset() { if (id_) Delete(id_); id_ = 0; }

private:
    GLuint id_ = 0;
};

namespace detail {
inline void deleteTexture(GLuint id) { glDeleteTextures(1, &id); }
inline void deleteBuffer(GLuint id) { glDeleteBuffers(1, &id); }
inline void deleteFramebuffer(GLuint id) { glDeleteFramebuffers(1, &id); }
inline void deleteVertexArray(GLuint id) { glDeleteVertexArrays(1, &id); }
void deleteProgram(GLuint id);  // through the current RetiredPrograms, if any
inline void deleteQuery(GLuint id) { glDeleteQueries(1, &id); }
}  // namespace detail

// Program objects freed while this list is current on the thread are held back from
// glDeleteProgram, the last kHeld of them; the context's destruction frees what is held.
// HeadlessContext makes its own list current with itself. Why: on NVIDIA's driver (580.159,
// H100 and H200) a program linked just after another was deleted sometimes draws with wrong
// state, never on llvmpipe. The 39 tests that remake a method at once, 12 times over: 24 and 55
// of 456 runs failed without the list, 0 and 0 with it (doc/bench/gpu_hopper.md, seventh
// lease). A held program is never used again, so nothing else changes.
class RetiredPrograms {
public:
    static constexpr size_t kHeld = 64;
    RetiredPrograms() = default;
    RetiredPrograms(const RetiredPrograms&) = delete;
    RetiredPrograms& operator=(const RetiredPrograms&) = delete;
    void retire(GLuint program);
    size_t held() const { return held_.size(); }
    // The calling thread's current list (nullptr: programs are deleted at once).
    static RetiredPrograms* current();
    static void makeCurrent(RetiredPrograms* list);

private:
    std::deque<GLuint> held_;
};

// A 2D texture with immutable storage.
class Texture2D {
public:
    Texture2D() = default;
    Texture2D(GLenum internalFormat, int width, int height, GLenum filter = GL_LINEAR);
    GLuint id() const { return h_.id(); }
    int width() const { return width_; }
    int height() const { return height_; }
    GLenum format() const { return format_; }
    explicit operator bool() const { return bool(h_); }

private:
    Handle<detail::deleteTexture> h_;
    int width_ = 0, height_ = 0;
    GLenum format_ = 0;
};

class Buffer {
public:
    Buffer() = default;
    // Immutable storage of `bytes`, optionally initialised from `data`; GlError when the
    // store cannot be allocated.
    Buffer(GLsizeiptr bytes, const void* data, GLbitfield flags = GL_DYNAMIC_STORAGE_BIT);
    GLuint id() const { return h_.id(); }
    GLsizeiptr size() const { return size_; }
    explicit operator bool() const { return bool(h_); }

private:
    Handle<detail::deleteBuffer> h_;
    GLsizeiptr size_ = 0;
};

// A buffer texture: `buffer`'s bytes read as texels of `internalFormat` (texelFetch on a
// samplerBuffer); it does not own the buffer.
class BufferTexture {
public:
    BufferTexture() = default;
    BufferTexture(GLenum internalFormat, const Buffer& buffer);
    GLuint id() const { return h_.id(); }
    explicit operator bool() const { return bool(h_); }

private:
    Handle<detail::deleteTexture> h_;
};

class Framebuffer {
public:
    Framebuffer() = default;
    static Framebuffer create();
    GLuint id() const { return h_.id(); }
    void attach(GLenum attachment, const Texture2D& texture);
    // Sets the draw buffers to COLOR_ATTACHMENT0..n-1 and checks completeness.
    void finish(int colorAttachments);

private:
    Handle<detail::deleteFramebuffer> h_;
};

class VertexArray {
public:
    VertexArray() = default;
    static VertexArray create();
    GLuint id() const { return h_.id(); }

private:
    Handle<detail::deleteVertexArray> h_;
};

// A linked program from embedded shader sources (see cmake/EmbedShaders.cmake).
class Program {
public:
    Program() = default;
    // `stages`: pairs of (GL shader type, embedded shader name such as "isa/overlay.frag").
    // `defines` are prepended after #version to make variants. Throws ShaderError.
    Program(std::initializer_list<std::pair<GLenum, std::string>> stages, const std::string& defines = "");
    GLuint id() const { return h_.id(); }
    // The location of an active uniform, looked up once at link time. A name the linked
    // program does not use throws ShaderError (never a silent -1).
    GLint uniform(const char* name) const;
    // The same, -1 where a program variant compiled the uniform out.
    GLint uniformIfActive(const char* name) const;
    void use() const { glUseProgram(h_.id()); }
    explicit operator bool() const { return bool(h_); }

private:
    Handle<detail::deleteProgram> h_;
    std::string names_;                                // "isa/x.vert+isa/x.frag", for messages
    std::vector<std::pair<std::string, GLint>> uniforms_;  // sorted by name
};

// Looks up an embedded shader source by name; throws ShaderError if unknown.
const std::string& shaderSource(const std::string& name);

}  // namespace flowsurf::gl
