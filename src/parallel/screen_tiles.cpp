#include "parallel/screen_tiles.h"

#include "core/errors.h"
#include "gl/readback.h"

#include <glm/gtc/packing.hpp>

#include <cstring>
#include <string>
#include <type_traits>

namespace flowsurf::methods {

using tile_wire::PixelFormat;
using tile_wire::pixelFormatOf;

namespace {

// `layer` -1: a 2D texture; else the z of a 3D texture.
void readRect(GLuint texture, int layer, const PixelRect& r, const PixelFormat& f, void* out) {
    gl::waitForRendering();
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureSubImage(texture, 0, r.x0, r.y0, std::max(layer, 0), r.width(), r.height(), 1, f.format, f.type,
                         GLsizei(r.area() * f.bytes), out);
}

void writeRect(GLuint texture, int layer, const PixelRect& r, const PixelFormat& f, const void* in) {
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    if (layer < 0) glTextureSubImage2D(texture, 0, r.x0, r.y0, r.width(), r.height(), f.format, f.type, in);
    else glTextureSubImage3D(texture, 0, r.x0, r.y0, layer, r.width(), r.height(), 1, f.format, f.type, in);
}

void readRect(const gl::Texture2D& t, const PixelRect& r, const PixelFormat& f, void* out) { readRect(t.id(), -1, r, f, out); }
void writeRect(const gl::Texture2D& t, const PixelRect& r, const PixelFormat& f, const void* in) {
    writeRect(t.id(), -1, r, f, in);
}

// Calls f(std::integral_constant<size_t, N>{}) for pixels of N = `bytes` bytes, so that the
// per-pixel copies below are copies of a fixed size (inlined, not a library call each).
template <class F>
void withPixelSize(size_t bytes, F&& f) {
    switch (bytes) {
        case 2: return f(std::integral_constant<size_t, 2>{});
        case 4: return f(std::integral_constant<size_t, 4>{});
        case 8: return f(std::integral_constant<size_t, 8>{});
        case 16: return f(std::integral_constant<size_t, 16>{});
        default: throw GlError("screen tiles: pixels of " + std::to_string(bytes) + " bytes cannot be exchanged");
    }
}

// The index of pixel (x, y) in an array over rectangle r, rows of r.width().
uint32_t indexIn(const PixelRect& r, int x, int y) {
    return uint32_t(size_t(y - r.y0) * size_t(r.width()) + size_t(x - r.x0));
}

// Every layer's `local` over r, into out[layer] (nothing when r is empty).
void readLayers(std::span<const TileLayer> layers, const std::vector<PixelFormat>& formats, const PixelRect& r,
                std::vector<std::vector<uint8_t>>& out) {
    out.resize(layers.size());
    if (r.empty()) return;
    for (size_t i = 0; i < layers.size(); ++i) {
        out[i].resize(r.area() * formats[i].bytes);
        readRect(layers[i].local, layers[i].layer, r, formats[i], out[i].data());
    }
}

}  // namespace

TileLayer TileLayer::of(const gl::Texture2D& local, const gl::Texture2D& tile, float fill, bool ownBackground) {
    if (local.width() != tile.width() || local.height() != tile.height() || local.format() != tile.format())
        throw GlError("screen tiles: a layer's tile texture has another size or format than its own");
    return {local.id(), tile.id(), local.format(), -1, fill, ownBackground};
}

TileLayer TileLayer::ofLayer(GLuint local3d, GLuint tile3d, GLenum format, int z) {
    return {local3d, tile3d, format, z, 0.0f, false};
}

ScreenTiles::ScreenTiles(const core::Viewport& viewport) : viewport_(viewport) {}

std::vector<PixelFormat> ScreenTiles::formatsOf(std::span<const TileLayer> layers) {
    std::vector<PixelFormat> formats;
    for (const TileLayer& l : layers) formats.push_back(pixelFormatOf(l.format));
    return formats;
}

void ScreenTiles::distribute(ProcessGroup& group, const gl::Texture2D& depth, std::span<const TileLayer> layers,
                             int guardPx, const PixelRect& footprint) {
    rank_ = group.rank();
    const PixelRect full{0, 0, viewport_.width, viewport_.height};
    const PixelRect fp = footprint.intersect(full);
    const std::vector<PixelFormat> formats = formatsOf(layers);
    readDepth(depth, fp);
    PixelRect covered;
    std::vector<float> weight = coverage(fp, covered);
    const PixelRect previous = region_;
    split(group, std::move(weight), guardPx);
    writePieces(layers, formats, covered, guardPx);
    const std::vector<std::vector<uint8_t>> in = group.exchange(sends_);
    Received received = readPieces(in, formats);
    mergeNearest(layers, formats, received, depth.id());
    writeMerge(layers, formats, received, previous);
    countCovered(fp, received.merged);
}

// This piece's depth over its footprint, into the full-size depth_ (rows of the viewport's
// width); only the footprint is read later.
void ScreenTiles::readDepth(const gl::Texture2D& depth, const PixelRect& fp) {
    const int w = viewport_.width;
    depth_.resize(size_t(w) * size_t(viewport_.height));
    if (fp.empty()) return;
    const size_t at = size_t(fp.y0) * size_t(w) + size_t(fp.x0);
    gl::waitForRendering();
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ROW_LENGTH, w);
    glGetTextureSubImage(depth.id(), 0, fp.x0, fp.y0, 0, fp.width(), fp.height(), 1, GL_DEPTH_COMPONENT, GL_FLOAT,
                         GLsizei((depth_.size() - at) * sizeof(float)), &depth_[at]);
    glPixelStorei(GL_PACK_ROW_LENGTH, 0);
}

// This piece's covered pixels per cell (kCellPx squared), and the rectangle they lie in.
std::vector<float> ScreenTiles::coverage(const PixelRect& fp, PixelRect& covered) const {
    const int w = viewport_.width;
    const int cellsX = (w + kCellPx - 1) / kCellPx, cellsY = (viewport_.height + kCellPx - 1) / kCellPx;
    std::vector<float> weight(size_t(cellsX) * size_t(cellsY), 0.0f);
    for (int y = fp.y0; y < fp.y1; ++y) {
        const float* row = depth_.data() + size_t(y) * size_t(w);
        int x0 = fp.x0, x1 = fp.x1;  // the row's first and last covered pixel
        while (x0 < x1 && !(row[x0] < 1.0f)) ++x0;
        while (x1 > x0 && !(row[x1 - 1] < 1.0f)) --x1;
        if (x0 == x1) continue;
        covered = covered.united({x0, y, x1, y + 1});
        float* cells = weight.data() + size_t(y / kCellPx) * size_t(cellsX);
        for (int x = x0; x < x1;) {  // cell by cell
            const int end = std::min(x1, (x / kCellPx + 1) * kCellPx);
            int count = 0;
            for (; x < end; ++x) count += row[x] < 1.0f;
            cells[(end - 1) / kCellPx] += float(count);
        }
    }
    return weight;
}

// Collective: the group's coverage summed, weighted by the measured costs, split into one
// tile per process (the same on every process); region_ is this process's tile plus guard.
void ScreenTiles::split(ProcessGroup& group, std::vector<float> weight, int guardPx) {
    const int w = viewport_.width, h = viewport_.height;
    const int cellsX = (w + kCellPx - 1) / kCellPx;
    group.sumInPlace(weight);  // counts: exact in float, the same sum on every process
    // The image stages cost mostly per surface pixel; a little per pixel keeps empty
    // screen parts from collapsing into one tile.
    for (size_t c = 0; c < weight.size(); ++c) weight[c] += 0.05f * float(kCellPx * kCellPx);
    if (costScale_.size() != weight.size()) costScale_.assign(weight.size(), 1.0f);
    for (size_t c = 0; c < weight.size(); ++c) weight[c] *= costScale_[c];
    if (shares_.size() != size_t(group.size())) shares_.clear();
    tiles_ = splitScreen(weight, cellsX, int(weight.size()) / cellsX, kCellPx, w, h, group.size(), shares_);
    weights_ = std::move(weight);
    cellsX_ = cellsX;
    splitDue_ = false;
    region_ = tile().empty() ? PixelRect{} : tile().grown(guardPx).intersect({0, 0, w, h});
}

// The piece messages (tile_wire.h) to every other tile's owner, into sends_: this piece over
// that tile plus guard where it covers it (sent_); its layers read back over the box of
// what it sends.
void ScreenTiles::writePieces(std::span<const TileLayer> layers, const std::vector<PixelFormat>& formats,
                              const PixelRect& covered, int guardPx) {
    const int n = int(tiles_.size()), me = rank_, w = viewport_.width;
    const PixelRect full{0, 0, w, viewport_.height};
    size_t layerBytes = 0;
    for (const PixelFormat& f : formats) layerBytes += f.bytes;
    sent_.assign(size_t(n), PixelRect{});
    PixelRect S;
    for (int t = 0; t < n; ++t) {
        const PixelRect& tt = tiles_[size_t(t)];
        const PixelRect r = tt.empty() ? PixelRect{} : tt.grown(guardPx).intersect(full).intersect(covered);
        sent_[size_t(t)] = r.empty() ? PixelRect{} : r;
        if (t != me) S = S.united(sent_[size_t(t)]);
    }
    readLayers(layers, formats, S, local_);
    sends_.resize(size_t(n));
    for (int t = 0; t < n; ++t) {
        const PixelRect& r = sent_[size_t(t)];
        std::vector<uint8_t>& out = sends_[size_t(t)];
        if (t == me || r.empty()) {
            out.clear();
            continue;
        }
        std::vector<uint32_t>& idx = pixelIndex_;  // the covered pixels of r, in row order
        idx.clear();
        for (int y = r.y0; y < r.y1; ++y) {
            const float* row = depth_.data() + size_t(y) * size_t(w);
            const uint32_t rowAt = indexIn(S, r.x0, y);
            for (int x = r.x0; x < r.x1; ++x)
                if (row[x] < 1.0f) idx.push_back(rowAt + uint32_t(x - r.x0));
        }
        out.resize(tile_wire::pieceBytes(r, idx.size(), layerBytes));  // all written below
        uint8_t* at = tile_wire::putRect(out.data(), r);
        for (int y = r.y0; y < r.y1; ++y, at += size_t(r.width()) * tile_wire::kDepthBytes)
            std::memcpy(at, &depth_[size_t(y) * size_t(w) + size_t(r.x0)], size_t(r.width()) * tile_wire::kDepthBytes);
        for (size_t i = 0; i < layers.size(); ++i)
            withPixelSize(formats[i].bytes, [&](auto size) {
                constexpr size_t N = decltype(size)::value;
                const uint8_t* from = local_[i].data();
                for (uint32_t k : idx) {
                    std::memcpy(at, from + size_t(k) * N, N);
                    at += N;
                }
            });
        traffic_.bytesSent += out.size();
    }
}

// The other pieces' messages read: each one's rectangle (received_) and depth there (kept
// for the return trip), where each layer's values start, and the box of all they sent.
ScreenTiles::Received ScreenTiles::readPieces(const std::vector<std::vector<uint8_t>>& in,
                                              const std::vector<PixelFormat>& formats) {
    const int n = int(tiles_.size()), me = rank_;
    size_t layerBytes = 0;
    for (const PixelFormat& f : formats) layerBytes += f.bytes;
    Received got;
    got.values.resize(size_t(n));
    got.depthOf.assign(size_t(n), nullptr);
    received_.assign(size_t(n), PixelRect{});
    receivedDepth_.resize(size_t(n));
    for (int q = 0; q < n; ++q) {
        std::vector<float>& keep = receivedDepth_[size_t(q)];
        if (q == me || in[size_t(q)].empty()) {
            keep.clear();
            if (q == me) received_[size_t(q)] = sent_[size_t(me)];
            continue;
        }
        traffic_.bytesReceived += in[size_t(q)].size();
        tile_wire::Reader rd{in[size_t(q)]};
        const PixelRect r = rd.rect();
        if (r.empty() || !(r.intersect(region_) == r))
            throw GlError("screen tiles: process " + std::to_string(q) + " sent pixels outside this tile");
        keep.resize(r.area());  // kept from the last frame: only growth is zero-filled
        std::memcpy(keep.data(), rd.take(r.area() * tile_wire::kDepthBytes), r.area() * tile_wire::kDepthBytes);
        got.depthOf[size_t(q)] = keep.data();
        size_t count = 0;
        for (float d : keep) count += d < 1.0f;
        const uint8_t* v = rd.take(count * layerBytes);
        if (!rd.atEnd())
            throw GlError("screen tiles: a message from process " + std::to_string(q) + " has trailing bytes");
        for (const PixelFormat& f : formats) {
            got.values[size_t(q)].push_back(v);
            v += count * f.bytes;
        }
        received_[size_t(q)] = r;
        got.others = got.others.united(r);
    }
    return got;
}

// The merge over `merged` (the region; only the box of what others sent when every layer's
// own values stand for the background, TileLayer::ownBackground), in rank order: a strictly
// nearer fragment wins, so on a tie the lowest rank keeps the pixel (as mergeByDepth). The
// winner of each pixel: its process and the index of its values there.
void ScreenTiles::mergeNearest(std::span<const TileLayer> layers, const std::vector<PixelFormat>& formats,
                               Received& got, GLuint depth) {
    const int n = int(tiles_.size()), me = rank_, w = viewport_.width;
    bool ownBackground = true;
    for (const TileLayer& l : layers) ownBackground = ownBackground && (l.ownBackground || l.local == depth);
    got.merged = ownBackground ? got.others : region_;
    const PixelRect& M = got.merged;
    // This piece's layers where they take part in the merge.
    const PixelRect O = sent_[size_t(me)].intersect(M);
    readLayers(layers, formats, O, own_);
    for (size_t i = 0; i < layers.size(); ++i) got.values[size_t(me)].push_back(own_[i].data());
    best_.assign(M.area(), 1.0f);
    winner_.assign(M.area(), -1);
    winnerAt_.resize(M.area());
    for (int q = 0; q < n && !M.empty(); ++q) {
        const bool own = q == me;
        const PixelRect r = own ? O : received_[size_t(q)];
        if (r.empty()) continue;
        // q's values are in row order of its covered pixels: of O for this process (own_),
        // of the rectangle it sent (r itself) for another.
        uint32_t k = 0;
        for (int y = r.y0; y < r.y1; ++y) {
            const float* depth = own ? depth_.data() + size_t(y) * size_t(w) + size_t(r.x0)
                                     : got.depthOf[size_t(q)] + indexIn(r, r.x0, y);
            const size_t rowAt = indexIn(M, r.x0, y);
            for (int i = 0; i < r.width(); ++i) {
                const float d = depth[i];
                if (!(d < 1.0f)) continue;
                const uint32_t at = own ? indexIn(O, r.x0 + i, y) : k;
                ++k;
                const size_t p = rowAt + size_t(i);
                if (!(d < best_[p])) continue;
                best_[p] = d;
                winner_[p] = q;
                winnerAt_[p] = at;
            }
        }
    }
}

// Each layer over the merge's pixels copied from the winners (`fill` where none won), then
// on the GPU: what the last region held and this one does not cleared; this piece's own
// layers over the region where only the box of what others sent is merged; the merge.
void ScreenTiles::writeMerge(std::span<const TileLayer> layers, const std::vector<PixelFormat>& formats,
                             const Received& got, const PixelRect& previous) {
    const PixelRect& M = got.merged;
    const PixelRect& R = region_;
    merged_.resize(layers.size());
    for (size_t i = 0; i < layers.size() && !M.empty(); ++i)
        withPixelSize(formats[i].bytes, [&](auto size) {
            constexpr size_t N = decltype(size)::value;
            merged_[i].resize(M.area() * N);
            uint8_t background[N] = {};  // every channel `fill` (a depth layer's 1)
            const float fill = formats[i].depth ? 1.0f : layers[i].fill;
            if (formats[i].type == GL_FLOAT)
                for (size_t c = 0; c < N / 4; ++c) std::memcpy(&background[c * 4], &fill, 4);
            else
                for (size_t c = 0; c < N / 2; ++c) {
                    const uint16_t half = glm::packHalf1x16(fill);
                    std::memcpy(&background[c * 2], &half, 2);
                }
            uint8_t* to = merged_[i].data();
            for (size_t p = 0; p < M.area(); ++p, to += N) {
                const int q = winner_[p];
                std::memcpy(to, q < 0 ? background : got.values[size_t(q)][i] + size_t(winnerAt_[p]) * N, N);
            }
        });
    for (size_t i = 0; i < layers.size(); ++i) {
        const PixelFormat& f = formats[i];
        if (!previous.empty() && !(previous == R) && layers[i].tile != layers[i].local) {
            const float fill = f.depth ? 1.0f : layers[i].fill;
            const float value[4] = {fill, fill, fill, fill};
            glClearTexSubImage(layers[i].tile, 0, previous.x0, previous.y0, std::max(layers[i].layer, 0), previous.width(),
                               previous.height(), 1, f.format, GL_FLOAT, value);
        }
    }
    if (!(M == R)) copyOwn(layers, R);
    for (size_t i = 0; i < layers.size() && !M.empty(); ++i)
        writeRect(layers[i].tile, layers[i].layer, M, formats[i], merged_[i].data());
    written_ = M;
}

// The traffic's pixel counts: the tile, its guard, and the whole surface's pixels in the
// region: the merge's in `M`, this piece's elsewhere (depth_ holds the footprint only).
void ScreenTiles::countCovered(const PixelRect& fp, const PixelRect& M) {
    const int w = viewport_.width;
    const PixelRect& R = region_;
    traffic_.tilePixels = tile().area();
    traffic_.guardPixels = R.area() - tile().area();
    const auto ownCovered = [&](const PixelRect& r) {
        size_t count = 0;
        for (int y = r.y0; y < r.y1; ++y)
            for (int x = r.x0; x < r.x1; ++x) count += depth_[size_t(y) * size_t(w) + size_t(x)] < 1.0f;
        return count;
    };
    traffic_.coveredPixels += ownCovered(R.intersect(fp)) - ownCovered(M.intersect(fp)) +
                              size_t(std::count_if(best_.begin(), best_.end(), [](float d) { return d < 1.0f; }));
}

// Each layer's tile over `R`: this piece's own layer, which holds the merge's background
// where this piece has no fragment (TileLayer::ownBackground); a layer merged in place has it
// already.
void ScreenTiles::copyOwn(std::span<const TileLayer> layers, const PixelRect& R) {
    if (R.empty()) return;
    for (const TileLayer& l : layers) {
        if (l.tile == l.local) continue;
        const GLenum target = l.layer < 0 ? GL_TEXTURE_2D : GL_TEXTURE_3D;
        const int z = std::max(l.layer, 0);
        glCopyImageSubData(l.local, target, 0, R.x0, R.y0, z, l.tile, target, 0, R.x0, R.y0, z, R.width(), R.height(), 1);
    }
}

float ScreenTiles::finishedMs(Clock::time_point start) {
    glFinish();
    return std::chrono::duration<float, std::milli>(Clock::now() - start).count();
}

void ScreenTiles::reportCost(ProcessGroup& group, float ms, float ownMs) {
    if (!ready()) return;
    const float mine[2] = {ms, ownMs};
    const std::vector<float> all = group.gather(mine);  // tile, own; per process in rank order
    const size_t n = all.size() / 2;
    std::vector<float> tileMs(n), own(n);
    double total = 0, slowest = 0;
    for (size_t t = 0; t < n; ++t) {
        tileMs[t] = all[2 * t];
        own[t] = all[2 * t + 1];
        total += double(tileMs[t]) + double(own[t]);
        slowest = std::max(slowest, double(tileMs[t]) + double(own[t]));
    }
    const double mean = total / double(n);
    imbalanced_ = slowest > double(kImbalance) * mean && mean > 0 ? imbalanced_ + 1 : 0;
    if (imbalanced_ < kImbalanceFrames) return;
    // The same on every process: the same gathered costs and the same last split.
    const std::vector<float> scaled = costWeights(weights_, cellsX_, kCellPx, tiles_, tileMs);
    for (size_t c = 0; c < scaled.size(); ++c) costScale_[c] *= weights_[c] > 0 ? scaled[c] / weights_[c] : 1.0f;
    shares_ = tileShares(tileMs, own);
    imbalanced_ = 0;
    splitDue_ = true;
}

void ScreenTiles::pull(ProcessGroup& group, const gl::Texture2D& texture, const std::vector<PixelRect>& madeWith,
                       const PixelRect& wanted) {
    const int n = group.size(), me = group.rank();
    if (int(madeWith.size()) != n) throw GlError("screen tiles: history pulled from another number of processes");
    const PixelFormat f = pixelFormatOf(texture.format());
    const float mine[4] = {float(wanted.x0), float(wanted.y0), float(wanted.x1), float(wanted.y1)};
    const std::vector<float> all = group.gather(mine);  // pixel coordinates: exact in float
    std::vector<std::vector<uint8_t>> sends(static_cast<size_t>(n));
    for (int q = 0; q < n; ++q) {
        if (q == me) continue;
        const size_t at = size_t(q) * 4;
        const PixelRect want{int(all[at]), int(all[at + 1]), int(all[at + 2]), int(all[at + 3])};
        const PixelRect r = want.intersect(madeWith[size_t(me)]);
        if (r.empty()) continue;
        std::vector<uint8_t>& out = sends[size_t(q)];
        out.resize(tile_wire::historyBytes(r, f.bytes));
        readRect(texture, r, f, tile_wire::putRect(out.data(), r));
        traffic_.bytesSent += out.size();
    }
    const std::vector<std::vector<uint8_t>> in = group.exchange(sends);
    for (int t = 0; t < n; ++t) {
        if (t == me || in[size_t(t)].empty()) continue;
        tile_wire::Reader rd{in[size_t(t)]};
        const PixelRect r = rd.rect();
        if (r.empty() || !(r.intersect(wanted) == r) || !(r.intersect(madeWith[size_t(t)]) == r))
            throw GlError("screen tiles: process " + std::to_string(t) + " sent history outside what was asked");
        writeRect(texture, r, f, rd.take(r.area() * f.bytes));
        traffic_.bytesReceived += in[size_t(t)].size();
    }
}

void ScreenTiles::returnValues(ProcessGroup& group, const gl::Texture2D& values) {
    const int n = group.size(), me = group.rank();
    const int w = viewport_.width;
    if (!ready() || n != int(tiles_.size())) throw GlError("screen tiles: values returned before the tiles were made");
    const PixelFormat f = pixelFormatOf(values.format());
    if (f.bytes != 4 || f.type != GL_FLOAT) throw GlError("screen tiles: returned values must be R32F");
    const PixelRect& T = tile();
    std::vector<float>& mine = tileValues_;
    mine.resize(T.area());
    if (!T.empty()) readRect(values, T, f, mine.data());

    // To each process q, the values at the pixels of this tile that q covers, in row order.
    std::vector<std::vector<uint8_t>>& sends = returns_;
    sends.resize(size_t(n));
    for (int q = 0; q < n; ++q) {
        std::vector<uint8_t>& out = sends[size_t(q)];
        const PixelRect r = q == me ? PixelRect{} : received_[size_t(q)].intersect(T);
        const PixelRect& qr = received_[size_t(q)];
        const float* qd = receivedDepth_[size_t(q)].data();
        size_t count = 0;
        for (int y = r.y0; y < r.y1; ++y) {
            const float* depth = qd + indexIn(qr, r.x0, y);
            for (int i = 0; i < r.width(); ++i) count += depth[i] < 1.0f;
        }
        out.resize(tile_wire::returnBytes(count));
        if (out.empty()) continue;
        uint8_t* at = out.data();
        for (int y = r.y0; y < r.y1; ++y) {
            const float* depth = qd + indexIn(qr, r.x0, y);
            const float* value = mine.data() + indexIn(T, r.x0, y);
            for (int i = 0; i < r.width(); ++i)
                if (depth[i] < 1.0f) {
                    std::memcpy(at, &value[i], 4);
                    at += 4;
                }
        }
        traffic_.bytesSent += out.size();
    }
    std::vector<std::vector<uint8_t>> in = group.exchange(sends);

    // This process's covered pixels: its own tile's values, then every other owner's in the
    // order that owner wrote them.
    PixelRect covered;
    for (const PixelRect& r : sent_) covered = covered.united(r);
    if (covered.empty()) return;
    values_.resize(covered.area());
    readRect(values, covered, f, values_.data());  // what is not this piece's stays as it is
    for (int t = 0; t < n; ++t) {
        const PixelRect r = sent_[size_t(t)].intersect(tiles_[size_t(t)]);
        if (r.empty()) continue;
        tile_wire::Reader rd{in[size_t(t)]};
        if (t != me) traffic_.bytesReceived += in[size_t(t)].size();
        for (int y = r.y0; y < r.y1; ++y) {
            const float* depth = depth_.data() + size_t(y) * size_t(w) + size_t(r.x0);
            float* to = values_.data() + indexIn(covered, r.x0, y);
            if (t == me) {
                const float* from = mine.data() + indexIn(T, r.x0, y);
                for (int i = 0; i < r.width(); ++i)
                    if (depth[i] < 1.0f) to[i] = from[i];
                continue;
            }
            int count = 0;  // the row's covered pixels: their values are next in t's message
            for (int i = 0; i < r.width(); ++i) count += depth[i] < 1.0f;
            const uint8_t* from = rd.take(tile_wire::returnBytes(size_t(count)));
            for (int i = 0; i < r.width(); ++i)
                if (depth[i] < 1.0f) {
                    std::memcpy(&to[i], from, 4);
                    from += 4;
                }
        }
    }
    writeRect(values, covered, f, values_.data());
}

}  // namespace flowsurf::methods
