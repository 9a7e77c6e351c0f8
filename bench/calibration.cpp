#include "calibration.h"

#include "core/errors.h"
#include "gl/objects.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace flowsurf::bench {

namespace {

// Fixed on purpose (not shared with shaders/): the workload must not change with the code
// it calibrates.
// Its own binding points, named once and handed to the shaders as #defines.
constexpr int kPosLocation = 0, kColorOutput = 0, kNoiseUnit = 0, kGridBuffer = 0;
constexpr const char* kGridVert = R"(
layout(location = POS_LOCATION) in vec2 pos;
out vec2 uv;
void main() {
    uv = pos * 0.5 + 0.5;
    gl_Position = vec4(pos, 0.5 * sin(7.0 * pos.x) * cos(5.0 * pos.y), 1.0);
}
)";
constexpr const char* kGridFrag = R"(
in vec2 uv;
layout(location = COLOR_OUTPUT) out vec4 color;
void main() { color = vec4(uv, fract(uv.x * 37.0 + uv.y * 11.0), 1.0); }
)";
constexpr const char* kFetchVert = R"(
void main() {
    vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
    gl_Position = vec4(2.0 * p - 1.0, 0.0, 1.0);
}
)";
constexpr const char* kFetchFrag = R"(
layout(binding = NOISE_UNIT) uniform sampler2D noise;
layout(location = COLOR_OUTPUT) out vec4 color;
void main() {
    vec2 p = gl_FragCoord.xy / 512.0;
    vec4 sum = vec4(0.0);
    for (int i = 0; i < 16; ++i) {
        vec4 t = texture(noise, p);
        sum += t;
        p += (t.xy - 0.5) * 0.004;
    }
    color = sum / 16.0;
}
)";

constexpr int kSize = 512, kGrid = 200;  // 2 * 200^2 = 80,000 triangles

GLuint compile(GLenum type, const char* body) {
    const std::string source = "#version 450 core\n#define POS_LOCATION " + std::to_string(kPosLocation) +
                               "\n#define COLOR_OUTPUT " + std::to_string(kColorOutput) + "\n#define NOISE_UNIT " +
                               std::to_string(kNoiseUnit) + "\n" + body;
    const char* text = source.c_str();
    GLuint s = glCreateShader(type);
    glShaderSource(s, 1, &text, nullptr);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[1024] = {};
        glGetShaderInfoLog(s, sizeof log, nullptr, log);
        glDeleteShader(s);
        throw ShaderError(std::string("bench calibration shader: ") + log);
    }
    return s;
}

gl::Handle<gl::detail::deleteProgram> link(const char* vert, const char* frag) {
    GLuint p = glCreateProgram(), v = compile(GL_VERTEX_SHADER, vert), f = compile(GL_FRAGMENT_SHADER, frag);
    glAttachShader(p, v);
    glAttachShader(p, f);
    glLinkProgram(p);
    glDeleteShader(v);
    glDeleteShader(f);
    GLint ok = 0;
    glGetProgramiv(p, GL_LINK_STATUS, &ok);
    gl::Handle<gl::detail::deleteProgram> program(p);
    if (!ok) throw ShaderError("bench calibration: program does not link");
    return program;
}

}  // namespace

double calibrationMs(int frames, int repeats) {
    // The grid: kGrid x kGrid cells over 90 % of the image, two triangles each.
    std::vector<float> pos;
    for (int j = 0; j <= kGrid; ++j)
        for (int i = 0; i <= kGrid; ++i) {
            pos.push_back(-0.9f + 1.8f * float(i) / kGrid);
            pos.push_back(-0.9f + 1.8f * float(j) / kGrid);
        }
    std::vector<uint32_t> index;
    for (uint32_t j = 0; j < kGrid; ++j)
        for (uint32_t i = 0; i < kGrid; ++i) {
            const uint32_t a = j * (kGrid + 1) + i, b = a + 1, c = a + kGrid + 1, d = c + 1;
            index.insert(index.end(), {a, b, d, a, d, c});
        }
    gl::Buffer vertices(GLsizeiptr(pos.size() * sizeof(float)), pos.data(), 0);
    gl::Buffer indices(GLsizeiptr(index.size() * sizeof(uint32_t)), index.data(), 0);
    gl::VertexArray gridVao = gl::VertexArray::create(), emptyVao = gl::VertexArray::create();
    glVertexArrayVertexBuffer(gridVao.id(), kGridBuffer, vertices.id(), 0, 2 * sizeof(float));
    glVertexArrayElementBuffer(gridVao.id(), indices.id());
    glEnableVertexArrayAttrib(gridVao.id(), kPosLocation);
    glVertexArrayAttribFormat(gridVao.id(), kPosLocation, 2, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(gridVao.id(), kPosLocation, kGridBuffer);

    // A 256^2 hash noise texture, repeated.
    std::vector<uint32_t> texels(256 * 256);
    for (uint32_t k = 0; k < texels.size(); ++k) {
        uint32_t h = k * 0x9E3779B1u;
        h ^= h >> 15;
        h *= 0x85EBCA77u;
        texels[k] = h ^ (h >> 13);
    }
    gl::Texture2D noise(GL_RGBA8, 256, 256, GL_LINEAR);
    glTextureSubImage2D(noise.id(), 0, 0, 0, 256, 256, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
    glTextureParameteri(noise.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTextureParameteri(noise.id(), GL_TEXTURE_WRAP_T, GL_REPEAT);

    gl::Texture2D colorTex(GL_RGBA8, kSize, kSize), depthTex(GL_DEPTH_COMPONENT24, kSize, kSize);
    gl::Framebuffer fbo = gl::Framebuffer::create();
    fbo.attach(GL_COLOR_ATTACHMENT0 + kColorOutput, colorTex);
    fbo.attach(GL_DEPTH_ATTACHMENT, depthTex);
    fbo.finish(1);
    auto grid = link(kGridVert, kGridFrag), fetch = link(kFetchVert, kFetchFrag);

    auto frame = [&] {
        glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
        glViewport(0, 0, kSize, kSize);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glEnable(GL_DEPTH_TEST);
        glUseProgram(grid.id());
        glBindVertexArray(gridVao.id());
        glDrawElements(GL_TRIANGLES, GLsizei(index.size()), GL_UNSIGNED_INT, nullptr);
        glDisable(GL_DEPTH_TEST);
        glUseProgram(fetch.id());
        glBindTextureUnit(kNoiseUnit, noise.id());
        glBindVertexArray(emptyVao.id());
        glDrawArrays(GL_TRIANGLES, 0, 3);
    };
    for (int k = 0; k < 3; ++k) frame();
    glFinish();
    std::vector<double> ms;
    for (int r = 0; r < repeats; ++r) {
        auto t0 = std::chrono::steady_clock::now();
        for (int k = 0; k < frames; ++k) frame();
        glFinish();
        ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count() / frames);
    }
    glBindVertexArray(0);
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    std::nth_element(ms.begin(), ms.begin() + ms.size() / 2, ms.end());
    return ms[ms.size() / 2];
}

}  // namespace flowsurf::bench
