#include "parallel/piece_seams.h"

#include <glm/gtc/type_precision.hpp>

#include <algorithm>
#include <cstring>
#include <map>
#include <tuple>
#include <unordered_map>

namespace flowsurf::methods {

namespace {

// Representatives of `points`: points within `eps` of an earlier one (per axis) share its
// index. The same list gives the same answer on every process.
std::vector<uint32_t> weld(const std::vector<glm::vec3>& points, float eps) {
    const auto cellOf = [eps](const glm::vec3& p) { return glm::i64vec3(glm::floor(glm::dvec3(p) / double(eps))); };
    const auto hash = [](const glm::i64vec3& c) {
        return uint64_t(c.x) * 73856093u ^ uint64_t(c.y) * 19349663u ^ uint64_t(c.z) * 83492791u;
    };
    std::unordered_multimap<uint64_t, uint32_t> grid;  // cell hash -> representative point
    std::vector<uint32_t> rep(points.size());
    for (size_t i = 0; i < points.size(); ++i) {
        const glm::i64vec3 c = cellOf(points[i]);
        int64_t found = -1;
        for (int dz = -1; dz <= 1 && found < 0; ++dz)
            for (int dy = -1; dy <= 1 && found < 0; ++dy)
                for (int dx = -1; dx <= 1 && found < 0; ++dx) {
                    const auto [lo, hi] = grid.equal_range(hash(c + glm::i64vec3(dx, dy, dz)));
                    for (auto it = lo; it != hi; ++it) {
                        const glm::vec3 d = glm::abs(points[it->second] - points[i]);
                        if (std::max(d.x, std::max(d.y, d.z)) <= eps) {
                            found = it->second;
                            break;
                        }
                    }
                }
        if (found >= 0) {
            rep[i] = rep[size_t(found)];
        } else {
            rep[i] = uint32_t(i);
            grid.emplace(hash(c), uint32_t(i));
        }
    }
    return rep;
}

// Whether two of `points` are the same point (a seam within one process needs that).
bool anyTwice(const std::vector<glm::vec3>& points) {
    std::vector<uint32_t> order(points.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = uint32_t(i);
    const auto key = [&](uint32_t i) { return std::tie(points[i].x, points[i].y, points[i].z); };
    std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return key(a) < key(b); });
    for (size_t i = 1; i < order.size(); ++i)
        if (key(order[i - 1]) == key(order[i])) return true;
    return false;
}

struct OneSided {
    uint32_t v0, v1, a;  // local vertices: v0 -> v1 in the winding of triangle (v0, v1, a)
};

}  // namespace

PieceSeams pieceSeams(ProcessGroup* group, const core::SurfaceMesh& piece) {
    if (!group && !anyTwice(piece.positions)) return {};
    // The piece's edges with one triangle.
    std::unordered_map<uint64_t, std::pair<OneSided, int>> count;
    count.reserve(piece.triangles.size() * 2);
    for (const glm::uvec3& t : piece.triangles)
        for (int e = 0; e < 3; ++e) {
            const uint32_t a = t[e], b = t[(e + 1) % 3], c = t[(e + 2) % 3];
            auto [it, fresh] = count.try_emplace((uint64_t(std::min(a, b)) << 32) | std::max(a, b), OneSided{a, b, c}, 0);
            ++it->second.second;
        }
    std::vector<OneSided> mine;
    for (const auto& [key, entry] : count)
        if (entry.second == 1) mine.push_back(entry.first);
    std::sort(mine.begin(), mine.end(), [](const OneSided& x, const OneSided& y) {
        return std::tie(x.v0, x.v1) < std::tie(y.v0, y.v1);
    });

    std::vector<uint8_t> bytes(mine.size() * sizeof(AdjacentEdge));
    for (size_t i = 0; i < mine.size(); ++i) {
        const AdjacentEdge e{piece.positions[mine[i].v0], piece.positions[mine[i].v1], piece.positions[mine[i].a],
                             piece.positions[mine[i].a]};
        std::memcpy(bytes.data() + i * sizeof(AdjacentEdge), &e, sizeof e);
    }
    const std::vector<std::vector<uint8_t>> all =
        group ? allGather(*group, std::move(bytes)) : std::vector<std::vector<uint8_t>>{std::move(bytes)};
    const int rank = group ? group->rank() : 0;

    // Every process's one-sided edges, in (rank, order), their end points welded within a
    // millionth of their extent (a piece's end may be computed apart from its neighbour's:
    // cos 2 pi against cos 0); the first two at the same pair of points are the two sides
    // of a seam (a piece's own duplicated vertices included).
    std::vector<AdjacentEdge> edges;
    std::vector<int> rankOf;
    for (int q = 0; q < int(all.size()); ++q) {
        const std::vector<uint8_t>& msg = all[size_t(q)];
        for (size_t i = 0; i + sizeof(AdjacentEdge) <= msg.size(); i += sizeof(AdjacentEdge)) {
            edges.emplace_back();
            std::memcpy(&edges.back(), msg.data() + i, sizeof(AdjacentEdge));
            rankOf.push_back(q);
        }
    }
    std::vector<glm::vec3> ends;
    core::Bounds box;
    for (const AdjacentEdge& e : edges) {
        ends.push_back(e.v0);
        ends.push_back(e.v1);
        box.extend(e.v0);
        box.extend(e.v1);
    }
    const glm::vec3 size = box.valid() ? box.hi - box.lo : glm::vec3(0.0f);
    const float extent = std::max(size.x, std::max(size.y, size.z));
    const std::vector<uint32_t> rep = weld(ends, std::max(extent * 1e-6f, 1e-30f));
    std::map<uint64_t, std::vector<size_t>> sides;  // welded edge -> indices into edges
    for (size_t i = 0; i < edges.size(); ++i) {
        const uint32_t r0 = rep[2 * i], r1 = rep[2 * i + 1];
        sides[(uint64_t(std::min(r0, r1)) << 32) | std::max(r0, r1)].push_back(i);
    }
    size_t first = 0;  // this process's first edge in `edges`
    while (first < edges.size() && rankOf[first] != rank) ++first;
    PieceSeams seams;
    for (size_t k = 0; k < mine.size(); ++k) {
        const size_t i = first + k;
        const uint32_t r0 = rep[2 * i], r1 = rep[2 * i + 1];
        const std::vector<size_t>& list = sides.at((uint64_t(std::min(r0, r1)) << 32) | std::max(r0, r1));
        if (list.size() < 2) continue;  // a boundary of the surface
        const OneSided& s = mine[k];
        seams.edges.push_back((uint64_t(std::min(s.v0, s.v1)) << 32) | std::max(s.v0, s.v1));
        if (list[0] == i) seams.drawn.push_back({edges[i].v0, edges[i].v1, edges[i].a, edges[list[1]].a});
    }
    std::sort(seams.edges.begin(), seams.edges.end());
    return seams;
}

}  // namespace flowsurf::methods
