#include "skeleton/separation_lines.h"

#include "skeleton/tangent_field.h"
#include "skeleton/parallel.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

namespace flowsurf::skeleton {

namespace {

uint64_t edgeKey(uint32_t a, uint32_t b) { return (uint64_t(std::min(a, b)) << 32) | std::max(a, b); }

// The Jacobian of vertex v as a 3x3 map of its tangent plane: F J F^T.
glm::mat3 jacobian3(const SurfaceGraph& graph, const FieldOnGraph& field, uint32_t v) {
    glm::vec3 u, w;
    tangentFrame(graph.normals[v], u, w);
    const glm::mat2& j = field.jacobians[v];
    glm::mat3 out(0.0f);
    // out * x = u (j00 x.u + j01 x.w) + w (j10 x.u + j11 x.w)
    const glm::vec3 col0 = j[0][0] * u + j[0][1] * w;  // image of u
    const glm::vec3 col1 = j[1][0] * u + j[1][1] * w;  // image of w
    out += glm::outerProduct(col0, u) + glm::outerProduct(col1, w);
    return out;
}

struct Crossing {
    glm::vec3 position, velocity;
    glm::mat3 jacobian;
};

struct Segment {
    uint64_t ends[2];
    glm::vec3 points[2];
    LineKind kind;
    float strength;
};

// A line's end: its tip and the direction it leaves by.
struct LineEnd {
    glm::vec3 position, outward;
};

LineEnd endOf(const std::vector<SkeletonLine>& lines, uint32_t line, int side) {
    const auto& p = lines[line].points;
    const glm::vec3 tip = side == 0 ? p.front() : p.back();
    const glm::vec3 before = side == 0 ? p[std::min<size_t>(p.size() - 1, 2)] : p[p.size() - 1 - std::min<size_t>(p.size() - 1, 2)];
    const glm::vec3 d = tip - before;
    return LineEnd{tip, glm::length(d) > 0.0f ? glm::normalize(d) : glm::vec3(0.0f)};
}

// The ends on a grid of cell `gap`, coordinates clamped to 21 bits each: far cells may share
// a key, never a wrong pair (each candidate's distance is checked).
struct EndGrid {
    float gap;
    std::unordered_map<uint64_t, std::vector<uint32_t>> cells;  // cell -> line * 2 + side

    glm::ivec3 coordOf(const glm::vec3& p) const {
        glm::ivec3 c;
        for (int a = 0; a < 3; ++a) c[a] = int(std::clamp(std::floor(double(p[a]) / gap), -1.0e6, 1.0e6));
        return c;
    }
    static uint64_t keyOf(const glm::ivec3& c) {
        return (uint64_t(uint32_t(c.x) & 0x1fffff) << 42) | (uint64_t(uint32_t(c.y) & 0x1fffff) << 21) |
               uint64_t(uint32_t(c.z) & 0x1fffff);
    }
};

struct EndPair {
    float distance;
    uint32_t a, b;  // line * 2 + side
};

// Every pair of ends of one kind within `gap` that continue each other, nearest first.
std::vector<EndPair> continuingEnds(const std::vector<SkeletonLine>& lines, float gap) {
    const float cos45 = 0.7071f;
    EndGrid grid{gap, {}};
    for (uint32_t i = 0; i < lines.size(); ++i)
        for (int side = 0; side < 2; ++side)
            grid.cells[EndGrid::keyOf(grid.coordOf(endOf(lines, i, side).position))].push_back(i * 2 + uint32_t(side));
    std::vector<EndPair> pairs;
    for (uint32_t i = 0; i < lines.size(); ++i)
        for (int side = 0; side < 2; ++side) {
            const LineEnd e = endOf(lines, i, side);
            const glm::ivec3 c = grid.coordOf(e.position);
            for (int dx = -1; dx <= 1; ++dx)
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dz = -1; dz <= 1; ++dz) {
                        auto it = grid.cells.find(EndGrid::keyOf(c + glm::ivec3(dx, dy, dz)));
                        if (it == grid.cells.end()) continue;
                        for (uint32_t other : it->second) {
                            const uint32_t j = other / 2;
                            if (j <= i || lines[j].kind != lines[i].kind) continue;
                            const LineEnd f = endOf(lines, j, int(other % 2));
                            const glm::vec3 d = f.position - e.position;
                            const float dist = glm::length(d);
                            if (dist > gap || glm::dot(e.outward, -f.outward) < cos45) continue;
                            if (dist > 0.0f && glm::dot(e.outward, d / dist) < cos45) continue;
                            pairs.push_back({dist, i * 2 + uint32_t(side), other});
                        }
                    }
        }
    std::sort(pairs.begin(), pairs.end(), [](const EndPair& x, const EndPair& y) {
        return x.distance < y.distance || (x.distance == y.distance && (x.a < y.a || (x.a == y.a && x.b < y.b)));
    });
    return pairs;
}

// The lines joined along `link` (end -> the end it joins, -1: none): chains from an end with
// no link, then the closed loops.
std::vector<SkeletonLine> joinLinked(const std::vector<SkeletonLine>& lines, const std::vector<int64_t>& link) {
    std::vector<uint8_t> done(lines.size(), 0);
    std::vector<SkeletonLine> out;
    auto follow = [&](uint32_t first, int enterSide) {
        SkeletonLine joined;
        joined.kind = lines[first].kind;
        uint32_t line = first;
        int side = enterSide;  // the end we enter by
        for (;;) {
            done[line] = 1;
            const auto& l = lines[line];
            if (side == 0) {
                joined.points.insert(joined.points.end(), l.points.begin(), l.points.end());
                joined.strength.insert(joined.strength.end(), l.strength.begin(), l.strength.end());
            } else {
                joined.points.insert(joined.points.end(), l.points.rbegin(), l.points.rend());
                joined.strength.insert(joined.strength.end(), l.strength.rbegin(), l.strength.rend());
            }
            const int64_t next = link[line * 2 + uint32_t(1 - side)];
            if (next < 0 || done[size_t(next) / 2]) break;
            line = uint32_t(next) / 2;
            side = int(next % 2);
        }
        out.push_back(std::move(joined));
    };
    for (uint32_t i = 0; i < lines.size(); ++i) {
        if (done[i]) continue;
        if (link[i * 2] < 0) follow(i, 0);
        else if (link[i * 2 + 1] < 0) follow(i, 1);
    }
    for (uint32_t i = 0; i < lines.size(); ++i)
        if (!done[i]) follow(i, 0);  // closed loops
    return out;
}

// Joins line ends of one kind closer than `gap` that continue each other (each end's
// outward direction within 45 degrees of the other's inward one and of the gap between
// them), nearest pairs first; each end joins at most once.
std::vector<SkeletonLine> bridgeGaps(std::vector<SkeletonLine> lines, float gap) {
    if (!(gap > 0.0f) || lines.size() < 2) return lines;
    std::vector<int64_t> link(lines.size() * 2, -1);
    for (const EndPair& p : continuingEnds(lines, gap))
        if (link[p.a] < 0 && link[p.b] < 0) {
            link[p.a] = p.b;
            link[p.b] = p.a;
        }
    return joinLinked(lines, link);
}

// (1) s = (v x Jv) / |v|^2 at each vertex (NaN where v vanishes). With v = a e1 + b e2 on
// the eigenvectors, s = a b (l2 - l1) / |v|^2: zero on either eigen-direction, and well
// conditioned where the rate along v is zero (Jv = 0 there), as on most open separation.
std::vector<float> parallelVectors(const SurfaceGraph& graph, const FieldOnGraph& field) {
    std::vector<float> s(graph.vertexCount());
    detail::parallelFor(s.size(), [&](size_t v) {
        const glm::vec2 a = toFrame(graph, uint32_t(v), field.smoothed[v]), b = field.jacobians[v] * a;
        const float la2 = glm::dot(a, a);
        s[v] = la2 > 0.0f ? (a.x * b.y - a.y * b.x) / la2 : std::numeric_limits<float>::quiet_NaN();
        // an exact zero counts as positive and the zero set passes beside the vertex
        if (s[v] == 0.0f) s[v] = std::numeric_limits<float>::min();
    });
    return s;
}

// The kind of a zero-set piece from `c0` to `c1` in a triangle of normal-ish `n`, by the
// rates along the flow and across it (Kenwright et al.: across converging faster than along
// is separation, diverging faster attachment); false for neither or a piece further than
// `cosMax` from the flow.
bool classifyPiece(const Crossing& c0, const Crossing& c1, const glm::vec3& n, float cosMax, LineKind& kind,
                   float& rateGap) {
    const glm::vec3 dir = c1.position - c0.position;
    const glm::vec3 vel = 0.5f * (c0.velocity + c1.velocity);
    const float ld = glm::length(dir), lv = glm::length(vel);
    if (!(ld > 0.0f) || !(lv > 0.0f) || std::abs(glm::dot(dir, vel)) < cosMax * ld * lv) return false;
    const glm::vec3 along = vel / lv, across = glm::normalize(glm::cross(n, along));
    const glm::mat3 j = 0.5f * (c0.jacobian + c1.jacobian);
    const float lambdaA = glm::dot(along, j * along);
    const float trace = lambdaA + glm::dot(across, j * across);
    const float lambdaB = trace - lambdaA;
    if (lambdaB < 0.0f && lambdaB < lambdaA) kind = LineKind::Separation;
    else if (lambdaB > 0.0f && lambdaB > lambdaA) kind = LineKind::Attachment;
    else return false;
    rateGap = std::abs(lambdaB - lambdaA);
    return true;
}

// (2) per triangle: the zero set's piece between two edge crossings, classified at its middle
std::vector<Segment> zeroSetPieces(const SurfaceGraph& graph, const FieldOnGraph& field, const std::vector<float>& s,
                                   const SkeletonParams& params) {
    const std::vector<glm::vec3>& f = field.smoothed;
    const float strengthScale = graph.diagonal / std::max(field.speed99, 1e-30f);
    const float cosMax = std::cos(glm::radians(std::clamp(params.lineAngle, 0.0f, 90.0f)));
    std::unordered_map<uint64_t, Crossing> crossings;
    auto crossingOn = [&](uint32_t a, uint32_t b) -> const Crossing& {
        const uint64_t key = edgeKey(a, b);
        auto it = crossings.find(key);
        if (it != crossings.end()) return it->second;
        const uint32_t lo = std::min(a, b), hi = std::max(a, b);
        const float t = s[lo] / (s[lo] - s[hi]);
        Crossing c{graph.positions[lo] + t * (graph.positions[hi] - graph.positions[lo]),
                   f[lo] + t * (f[hi] - f[lo]),
                   (1.0f - t) * jacobian3(graph, field, lo) + t * jacobian3(graph, field, hi)};
        return crossings.emplace(key, c).first->second;
    };
    std::vector<Segment> segments;
    for (const glm::uvec3& t : graph.triangles) {
        if (std::isnan(s[t.x]) || std::isnan(s[t.y]) || std::isnan(s[t.z])) continue;
        uint32_t ends[2][2];
        int found = 0;
        for (int k = 0; k < 3 && found <= 2; ++k) {
            const uint32_t a = t[k], b = t[(k + 1) % 3];
            if ((s[a] < 0.0f) != (s[b] < 0.0f)) {
                if (found < 2) { ends[found][0] = a; ends[found][1] = b; }
                ++found;
            }
        }
        if (found != 2) continue;
        const Crossing& c0 = crossingOn(ends[0][0], ends[0][1]);
        const Crossing& c1 = crossingOn(ends[1][0], ends[1][1]);
        const glm::vec3 n = glm::normalize(graph.normals[t.x] + graph.normals[t.y] + graph.normals[t.z]);
        LineKind kind;
        float rateGap = 0.0f;
        if (!classifyPiece(c0, c1, n, cosMax, kind, rateGap)) continue;
        segments.push_back({{edgeKey(ends[0][0], ends[0][1]), edgeKey(ends[1][0], ends[1][1])},
                            {c0.position, c1.position}, kind, rateGap * strengthScale});
    }
    return segments;
}

// (3) pieces of one kind that share a crossing joined into polylines (a crossing shared by
// more than two pieces ends them: a branching point)
std::vector<SkeletonLine> chainPieces(const std::vector<Segment>& segments) {
    std::unordered_map<uint64_t, std::vector<uint32_t>> atEnd;
    for (uint32_t i = 0; i < segments.size(); ++i)
        for (uint64_t e : segments[i].ends) atEnd[e].push_back(i);
    std::vector<uint8_t> used(segments.size(), 0);
    auto nextFrom = [&](uint32_t seg, uint64_t end) -> int64_t {
        const auto& list = atEnd[end];
        if (list.size() != 2) return -1;
        const uint32_t other = list[0] == seg ? list[1] : list[0];
        if (used[other] || segments[other].kind != segments[seg].kind) return -1;
        return other;
    };
    std::vector<SkeletonLine> pieces;
    for (uint32_t start = 0; start < segments.size(); ++start) {
        if (used[start]) continue;
        used[start] = 1;
        SkeletonLine halves[2];  // walked from the start piece's two ends
        for (int side = 0; side < 2; ++side) {
            uint32_t seg = start;
            uint64_t end = segments[start].ends[side];
            for (int64_t next; (next = nextFrom(seg, end)) >= 0;) {
                seg = uint32_t(next);
                used[seg] = 1;
                const int enter = segments[seg].ends[0] == end ? 0 : 1;
                halves[side].points.push_back(segments[seg].points[1 - enter]);
                halves[side].strength.push_back(segments[seg].strength);
                end = segments[seg].ends[1 - enter];
            }
        }
        SkeletonLine line;
        line.kind = segments[start].kind;
        line.points.assign(halves[0].points.rbegin(), halves[0].points.rend());
        line.strength.assign(halves[0].strength.rbegin(), halves[0].strength.rend());
        for (int k = 0; k < 2; ++k) {
            line.points.push_back(segments[start].points[k]);
            line.strength.push_back(segments[start].strength);
        }
        line.points.insert(line.points.end(), halves[1].points.begin(), halves[1].points.end());
        line.strength.insert(line.strength.end(), halves[1].strength.begin(), halves[1].strength.end());
        pieces.push_back(std::move(line));
    }
    return pieces;
}

}  // namespace

std::vector<SkeletonLine> findSeparationLines(const SurfaceGraph& graph, const FieldOnGraph& field,
                                              const SkeletonParams& params) {
    // (1) the parallel-vectors measure, (2) its zero set's pieces, (3) joined
    std::vector<SkeletonLine> pieces = chainPieces(zeroSetPieces(graph, field, parallelVectors(graph, field), params));

    // (4) bridge the gaps noise leaves (a zero set that branches or turns away for a triangle
    // or two), then (5) keep the lines long and strong enough
    std::vector<SkeletonLine> lines;
    const float minLength = params.lineLength * graph.diagonal;
    for (SkeletonLine& line : bridgeGaps(std::move(pieces), std::max(2.0f * field.scale, 1e-6f * graph.diagonal))) {
        float mean = 0.0f;
        for (size_t i = 1; i < line.points.size(); ++i) line.length += glm::length(line.points[i] - line.points[i - 1]);
        for (float v : line.strength) mean += v;
        mean /= float(line.strength.size());
        if (line.length < minLength || mean < params.lineStrength) continue;
        lines.push_back(std::move(line));
    }
    return lines;
}

}  // namespace flowsurf::skeleton
