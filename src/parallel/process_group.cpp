#include "parallel/process_group.h"

#include "core/errors.h"
#include "gl/readback.h"

#include <climits>
#include <string>

namespace flowsurf::methods {

namespace {

int channelsOf(GLenum internalFormat) {
    switch (internalFormat) {
        case GL_R32F: case GL_R16F: return 1;
        case GL_RG32F: case GL_RG16F: return 2;
        case GL_RGBA32F: case GL_RGBA16F: return 4;
        default: throw GlError("mergeByDepth: texture format " + std::to_string(internalFormat) + " is not a float format");
    }
}

GLenum pixelFormat(int channels) {
    return channels == 1 ? GL_RED : channels == 2 ? GL_RG : GL_RGBA;
}

std::vector<float> readBack(const gl::Texture2D& t, GLenum format, int channels) {
    std::vector<float> v(size_t(t.width()) * size_t(t.height()) * size_t(channels));
    gl::waitForRendering();
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTextureImage(t.id(), 0, format, GL_FLOAT, GLsizei(v.size() * sizeof(float)), v.data());
    return v;
}

void upload(const gl::Texture2D& t, GLenum format, const std::vector<float>& v) {
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTextureSubImage2D(t.id(), 0, 0, 0, t.width(), t.height(), format, GL_FLOAT, v.data());
}

}  // namespace

void mergeByDepth(ProcessGroup& group, std::vector<float>& depth, std::span<std::vector<float>* const> layers) {
    const size_t n = depth.size();
    std::vector<float> nearest = depth;
    group.minInPlace(nearest);
    // The owner of a pixel: the lowest rank holding its nearest fragment.
    const int32_t me = group.rank();
    std::vector<int32_t> owner(n);
    for (size_t i = 0; i < n; ++i) owner[i] = depth[i] == nearest[i] ? me : INT32_MAX;
    group.minInPlace(owner);
    for (std::vector<float>* layer : layers) {
        const size_t channels = n ? layer->size() / n : 0;
        if (channels * n != layer->size()) throw GlError("mergeByDepth: a layer's size is not a multiple of the pixels");
        for (size_t i = 0; i < n; ++i)
            if (owner[i] != me)
                for (size_t c = 0; c < channels; ++c) (*layer)[i * channels + c] = 0.0f;
        group.sumInPlace(*layer);
    }
    depth = std::move(nearest);
}

void mergeByDepth(ProcessGroup& group, const gl::Texture2D& depth, std::initializer_list<const gl::Texture2D*> layers) {
    if (group.size() <= 1) return;
    std::vector<float> d = readBack(depth, GL_DEPTH_COMPONENT, 1);
    std::vector<std::vector<float>> values;
    values.reserve(layers.size());
    for (const gl::Texture2D* t : layers) {
        if (t->width() != depth.width() || t->height() != depth.height())
            throw GlError("mergeByDepth: a layer is not the size of the depth buffer");
        const int c = channelsOf(t->format());
        values.push_back(readBack(*t, pixelFormat(c), c));
    }
    std::vector<std::vector<float>*> ptrs;
    for (auto& v : values) ptrs.push_back(&v);
    mergeByDepth(group, d, ptrs);
    upload(depth, GL_DEPTH_COMPONENT, d);
    size_t k = 0;
    for (const gl::Texture2D* t : layers) {
        upload(*t, pixelFormat(channelsOf(t->format())), values[k]);
        ++k;
    }
}

std::vector<std::vector<uint8_t>> allGather(ProcessGroup& group, std::vector<uint8_t> bytes) {
    std::vector<std::vector<uint8_t>> sends(size_t(group.size()), bytes);
    sends[size_t(group.rank())].clear();
    std::vector<std::vector<uint8_t>> all = group.exchange(sends);
    all[size_t(group.rank())] = std::move(bytes);
    return all;
}

}  // namespace flowsurf::methods
