#include "methods/common/piece_seams.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <map>
#include <unordered_map>

namespace flowsurf::methods {

namespace {

using EdgeKey = std::array<uint32_t, 6>;  // the bits of both end points, in lexicographic order

EdgeKey keyOf(const glm::vec3& p, const glm::vec3& q) {
    const EdgeKey a{std::bit_cast<uint32_t>(p.x), std::bit_cast<uint32_t>(p.y), std::bit_cast<uint32_t>(p.z),
                    std::bit_cast<uint32_t>(q.x), std::bit_cast<uint32_t>(q.y), std::bit_cast<uint32_t>(q.z)};
    const EdgeKey b{a[3], a[4], a[5], a[0], a[1], a[2]};
    return std::min(a, b);
}

struct OneSided {
    uint32_t v0, v1, a;  // local vertices: v0 -> v1 in the winding of triangle (v0, v1, a)
};

}  // namespace

PieceSeams pieceSeams(ProcessGroup& group, const core::SurfaceMesh& piece) {
    // The piece's edges with one triangle.
    std::unordered_map<uint64_t, std::pair<OneSided, int>> count;
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
    std::vector<std::vector<uint8_t>> sends(size_t(group.size()), bytes);
    sends[size_t(group.rank())].clear();
    const std::vector<std::vector<uint8_t>> received = group.exchange(sends);

    // The other processes' one-triangle edges by position (the first process to hold each).
    std::map<EdgeKey, std::pair<int, glm::vec3>> others;
    for (int q = 0; q < group.size(); ++q) {
        if (q == group.rank()) continue;
        const std::vector<uint8_t>& msg = received[size_t(q)];
        for (size_t i = 0; i + sizeof(AdjacentEdge) <= msg.size(); i += sizeof(AdjacentEdge)) {
            AdjacentEdge e;
            std::memcpy(&e, msg.data() + i, sizeof e);
            others.try_emplace(keyOf(e.v0, e.v1), q, e.a);
        }
    }
    PieceSeams seams;
    for (const OneSided& s : mine) {
        const glm::vec3 p0 = piece.positions[s.v0], p1 = piece.positions[s.v1];
        auto it = others.find(keyOf(p0, p1));
        if (it == others.end()) continue;  // a boundary of the surface
        seams.edges.push_back((uint64_t(std::min(s.v0, s.v1)) << 32) | std::max(s.v0, s.v1));
        if (group.rank() < it->second.first) seams.drawn.push_back({p0, p1, piece.positions[s.a], it->second.second});
    }
    std::sort(seams.edges.begin(), seams.edges.end());
    return seams;
}

}  // namespace flowsurf::methods
