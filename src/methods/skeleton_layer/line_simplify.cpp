#include "methods/skeleton_layer/line_simplify.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace flowsurf::methods {

std::vector<ViewVertex> projectLine(std::span<const glm::vec3> pointsObj, const core::Camera& camera,
                                    const core::Viewport& viewport) {
    // the matrices the shader gets (float), applied in double: the decisions do not hang on rounding
    const glm::dmat4 viewProj(camera.viewProjection(viewport.aspect())), view(camera.view());
    const glm::dvec2 sizePx(viewport.width, viewport.height);
    std::vector<ViewVertex> out;
    out.reserve(pointsObj.size());
    for (const glm::vec3& p : pointsObj) {
        const glm::dvec4 pos(glm::dvec3(p), 1.0), clip = viewProj * pos;
        ViewVertex v;
        v.inFront = clip.w > 0.0;
        v.eye = -(view * pos).z;
        if (v.inFront) v.px = (glm::dvec2(clip) / clip.w * 0.5 + 0.5) * sizePx;
        out.push_back(v);
    }
    return out;
}

double deviation(const ViewVertex& v, const ViewVertex& a, const ViewVertex& b, bool orthographic,
                 const SimplifyParams& p) {
    const glm::dvec2 ab = b.px - a.px;
    const double len2 = glm::dot(ab, ab);
    const double t = len2 > 0.0 ? std::clamp(glm::dot(v.px - a.px, ab) / len2, 0.0, 1.0) : 0.0;
    const double offPx = glm::length(v.px - (a.px + t * ab));
    // the piece's eye distance where v lies on it: window depth is affine on screen, so is 1/eye
    // in perspective and eye itself in an orthographic view
    const double eyeOnPiece = orthographic ? a.eye + t * (b.eye - a.eye) : 1.0 / (1.0 / a.eye + t * (1.0 / b.eye - 1.0 / a.eye));
    const double offDepth = std::abs(v.eye - eyeOnPiece) / std::abs(v.eye);
    const double d = std::max(offPx / double(p.tolerancePx), offDepth / double(p.depthTolerance));
    return std::isfinite(d) ? d : HUGE_VAL;  // an eye distance of 0: keep the vertex
}

std::vector<uint32_t> keptVertices(std::span<const ViewVertex> v, bool orthographic, const SimplifyParams& p) {
    const size_t n = v.size();
    std::vector<char> keep(n, 0);
    if (n == 0) return {};
    keep.front() = keep.back() = 1;
    std::vector<std::pair<size_t, size_t>> stack;  // pieces [i, j] still to check, both ends kept
    for (size_t s = 0; s < n;) {
        if (!v[s].inFront) {
            keep[s] = 1;
            ++s;
            continue;
        }
        size_t e = s;
        while (e + 1 < n && v[e + 1].inFront) ++e;
        keep[s] = keep[e] = 1;  // a run's ends: the line's, or the neighbours of a vertex behind the eye
        stack.emplace_back(s, e);
        while (!stack.empty()) {
            const auto [i, j] = stack.back();
            stack.pop_back();
            size_t worst = i;
            double most = 1.0;
            for (size_t k = i + 1; k < j; ++k) {
                const double d = deviation(v[k], v[i], v[j], orthographic, p);
                if (d > most) most = d, worst = k;
            }
            if (worst == i) continue;  // every vertex between within the tolerances
            keep[worst] = 1;
            stack.emplace_back(worst, j);
            stack.emplace_back(i, worst);
        }
        s = e + 1;
    }
    std::vector<uint32_t> kept;
    for (size_t i = 0; i < n; ++i)
        if (keep[i]) kept.push_back(uint32_t(i));
    return kept;
}

namespace {

// Which sides of the widened viewport a point lies beyond (bits: left, right, bottom, top).
int outcode(glm::dvec2 px, glm::dvec2 sizePx, double reach) {
    return (px.x < -reach ? 1 : 0) | (px.x > sizePx.x + reach ? 2 : 0) | (px.y < -reach ? 4 : 0) |
           (px.y > sizePx.y + reach ? 8 : 0);
}

}  // namespace

std::vector<ViewPiece> viewPieces(std::span<const skeleton::SkeletonLine> lines, const core::Camera& camera,
                                  const core::Viewport& viewport, const SimplifyParams& p) {
    const glm::dvec2 sizePx(viewport.width, viewport.height);
    std::vector<ViewPiece> pieces;
    for (size_t l = 0; l < lines.size(); ++l) {
        const std::vector<ViewVertex> v = projectLine(lines[l].points, camera, viewport);
        const std::vector<uint32_t> kept = keptVertices(v, camera.orthographic(), p);
        for (size_t k = 0; k + 1 < kept.size(); ++k) {
            const ViewVertex &a = v[kept[k]], &b = v[kept[k + 1]];
            if (!a.inFront || !b.inFront) continue;
            if ((outcode(a.px, sizePx, p.reachPx) & outcode(b.px, sizePx, p.reachPx)) != 0) continue;
            pieces.push_back({uint32_t(l), kept[k > 0 ? k - 1 : k], kept[k], kept[k + 1],
                              kept[k + 2 < kept.size() ? k + 2 : k + 1]});
        }
    }
    return pieces;
}

}  // namespace flowsurf::methods
