#include "parallel/screen_split.h"

#include "core/errors.h"

#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

namespace flowsurf::methods {

namespace {

// Recursive bisection of the cell rectangle [cx0, cx1) x [cy0, cy1) into the parts
// [part, part + parts), of weights in proportion to `shares` (cumulative: shares[i] the sum
// of the first i).
void split(std::span<const float> w, int cellsX, int cx0, int cy0, int cx1, int cy1, int part, int parts,
           std::span<const double> shares, std::vector<std::array<int, 4>>& out) {
    if (parts == 1) {
        out.push_back({cx0, cy0, cx1, cy1});
        return;
    }
    const int first = parts / 2;
    const bool alongX = (cx1 - cx0) >= (cy1 - cy0);
    const int lo = alongX ? cx0 : cy0, hi = alongX ? cx1 : cy1;
    // The weight of each slice across the cut direction.
    std::vector<double> slice(size_t(std::max(0, hi - lo)), 0.0);
    for (int y = cy0; y < cy1; ++y)
        for (int x = cx0; x < cx1; ++x) slice[size_t((alongX ? x : y) - lo)] += w[size_t(y) * size_t(cellsX) + size_t(x)];
    double total = 0;
    for (double s : slice) total += s;
    const double all = shares[size_t(part + parts)] - shares[size_t(part)];
    const double below = shares[size_t(part + first)] - shares[size_t(part)];
    const double fraction = all > 0 ? below / all : double(first) / double(parts);
    const double target = total * fraction;
    // The cut c (lo < c < hi where possible) whose weight below is nearest the target.
    int cut = lo + int(double(hi - lo) * fraction);
    if (total > 0) {
        double sum = 0, best = -1;
        for (int c = lo + 1; c < hi; ++c) {
            sum += slice[size_t(c - 1 - lo)];
            const double miss = std::abs(sum - target);
            if (best < 0 || miss < best) best = miss, cut = c;
        }
    }
    if (hi - lo >= 2) cut = std::clamp(cut, lo + 1, hi - 1);
    if (alongX) {
        split(w, cellsX, cx0, cy0, cut, cy1, part, first, shares, out);
        split(w, cellsX, cut, cy0, cx1, cy1, part + first, parts - first, shares, out);
    } else {
        split(w, cellsX, cx0, cy0, cx1, cut, part, first, shares, out);
        split(w, cellsX, cx0, cut, cx1, cy1, part + first, parts - first, shares, out);
    }
}

}  // namespace

namespace {

// The rectangle around `bounds`' projection, a pixel wider on each side, its coordinates
// clamped to just beyond the image but not cut to it (so that a union of several keeps the
// reach of a part outside the image); nullopt when a corner lies behind the eye.
std::optional<PixelRect> projectedSpan(const core::Bounds& bounds, const glm::mat4& viewProj, int width, int height) {
    glm::vec2 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (int c = 0; c < 8; ++c) {
        const glm::vec3 p((c & 1) ? bounds.hi.x : bounds.lo.x, (c & 2) ? bounds.hi.y : bounds.lo.y,
                          (c & 4) ? bounds.hi.z : bounds.lo.z);
        const glm::vec4 clip = viewProj * glm::vec4(p, 1.0f);
        if (!(clip.w > 1e-6f)) return std::nullopt;
        const glm::vec2 px = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * glm::vec2(width, height);
        lo = glm::min(lo, px);
        hi = glm::max(hi, px);
    }
    const auto floorTo = [](float v, int limit) { return int(std::clamp(std::floor(v), -1.0f, float(limit) + 1.0f)); };
    return PixelRect{floorTo(lo.x, width) - 1, floorTo(lo.y, height) - 1, floorTo(hi.x, width) + 2,
                     floorTo(hi.y, height) + 2};
}

}  // namespace

PixelRect projectedRect(const core::Bounds& bounds, const glm::mat4& viewProj, int width, int height) {
    const PixelRect all{0, 0, width, height};
    if (!bounds.valid()) return {};
    const std::optional<PixelRect> span = projectedSpan(bounds, viewProj, width, height);
    return span ? span->intersect(all) : all;
}

std::vector<core::Bounds> surfaceParts(const core::SurfaceMesh& mesh, int cells) {
    const core::Bounds whole = mesh.bounds();
    if (!whole.valid() || mesh.triangles.empty()) return {};
    const glm::vec3 scale = glm::vec3(float(cells)) / glm::max(whole.hi - whole.lo, glm::vec3(1e-30f));
    std::vector<core::Bounds> parts(size_t(cells) * size_t(cells) * size_t(cells));
    for (const glm::vec3& p : mesh.positions) {
        const glm::ivec3 cell = glm::clamp(glm::ivec3((p - whole.lo) * scale), 0, cells - 1);
        parts[(size_t(cell.z) * size_t(cells) + size_t(cell.y)) * size_t(cells) + size_t(cell.x)].extend(p);
    }
    std::erase_if(parts, [](const core::Bounds& b) { return !b.valid(); });
    return parts;
}

PixelRect projectedRect(std::span<const core::Bounds> parts, const glm::mat4& viewProj, int width, int height) {
    const PixelRect all{0, 0, width, height};
    std::optional<PixelRect> span;
    for (const core::Bounds& part : parts) {
        if (!part.valid()) continue;
        const std::optional<PixelRect> r = projectedSpan(part, viewProj, width, height);
        if (!r) return all;
        span = span ? span->united(*r) : *r;
    }
    return span ? span->intersect(all) : PixelRect{};
}

std::vector<float> costWeights(std::span<const float> weights, int cellsX, int cellPx,
                               const std::vector<PixelRect>& tiles, std::span<const float> ms) {
    if (tiles.size() != ms.size()) throw GlError("costWeights: one cost per tile");
    // The tile holding each cell (its lower-left pixel), and each tile's weight.
    std::vector<int> owner(weights.size(), -1);
    std::vector<double> tileWeight(tiles.size(), 0.0);
    for (size_t c = 0; c < weights.size(); ++c) {
        const int x = int(c % size_t(cellsX)) * cellPx, y = int(c / size_t(cellsX)) * cellPx;
        for (size_t t = 0; t < tiles.size(); ++t)
            if (x >= tiles[t].x0 && x < tiles[t].x1 && y >= tiles[t].y0 && y < tiles[t].y1) {
                owner[c] = int(t);
                tileWeight[t] += weights[c];
                break;
            }
    }
    double cost = 0, weight = 0;
    for (size_t t = 0; t < tiles.size(); ++t) cost += ms[t], weight += tileWeight[t];
    const double mean = weight > 0 ? cost / weight : 0.0;
    std::vector<float> out(weights.begin(), weights.end());
    if (!(mean > 0)) return out;
    for (size_t c = 0; c < weights.size(); ++c) {
        const int t = owner[c];
        if (t < 0 || !(tileWeight[size_t(t)] > 0) || !(ms[size_t(t)] > 0)) continue;
        out[c] = float(double(weights[c]) * (double(ms[size_t(t)]) / tileWeight[size_t(t)]) / mean);
    }
    return out;
}

std::vector<PixelRect> splitScreen(std::span<const float> cellWeights, int cellsX, int cellsY, int cellPx,
                                   int width, int height, int parts, std::span<const float> shares) {
    if (cellWeights.size() != size_t(cellsX) * size_t(cellsY))
        throw GlError("splitScreen: " + std::to_string(cellWeights.size()) + " weights for " + std::to_string(cellsX) +
                      " x " + std::to_string(cellsY) + " cells");
    parts = std::max(1, parts);
    if (!shares.empty() && shares.size() != size_t(parts))
        throw GlError("splitScreen: " + std::to_string(shares.size()) + " shares for " + std::to_string(parts) + " parts");
    std::vector<double> cumulative(size_t(parts) + 1, 0.0);
    for (int i = 0; i < parts; ++i)
        cumulative[size_t(i) + 1] = cumulative[size_t(i)] + (shares.empty() ? 1.0 : std::max(0.0, double(shares[size_t(i)])));
    std::vector<std::array<int, 4>> cells;
    split(cellWeights, cellsX, 0, 0, cellsX, cellsY, 0, parts, cumulative, cells);
    std::vector<PixelRect> rects;
    for (const auto& c : cells)
        rects.push_back({std::min(c[0] * cellPx, width), std::min(c[1] * cellPx, height), std::min(c[2] * cellPx, width),
                         std::min(c[3] * cellPx, height)});
    return rects;
}

std::vector<float> tileShares(std::span<const float> tileMs, std::span<const float> ownMs) {
    if (tileMs.size() != ownMs.size()) throw GlError("tileShares: one own cost per tile cost");
    const size_t n = tileMs.size();
    double total = 0;
    for (size_t t = 0; t < n; ++t) total += double(tileMs[t]) + double(ownMs[t]);
    const double mean = n ? total / double(n) : 0.0;
    std::vector<float> shares(n, 1.0f);
    double sum = 0;
    for (size_t t = 0; t < n; ++t) sum += std::max(0.0, mean - double(ownMs[t]));
    if (!(sum > 0)) return shares;
    for (size_t t = 0; t < n; ++t) shares[t] = float(std::max(0.0, mean - double(ownMs[t])) / sum * double(n));
    return shares;
}

}  // namespace flowsurf::methods
