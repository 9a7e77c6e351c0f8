#include "dye/dye_shared.h"

#include "core/errors.h"

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <string>

namespace flowsurf::methods {

namespace {

template <class T>
void put(std::vector<uint8_t>& out, const T& v) {
    const size_t at = out.size();
    out.resize(at + sizeof(T));
    std::memcpy(out.data() + at, &v, sizeof(T));
}

template <class T>
T get(const uint8_t*& in) {
    T v;
    std::memcpy(&v, in, sizeof(T));
    in += sizeof(T);
    return v;
}

// One candidate of the band: a cell, its closest point on a piece and how near.
struct Candidate {
    uint32_t cell;
    float distance2;
    uint32_t key;
    glm::vec3 closest;
};
constexpr size_t kCandidateBytes = 3 * 4 + sizeof(glm::vec3);

}  // namespace

SharedDyeBand::SharedDyeBand(ProcessGroup& group, const core::SurfaceMesh& piece, const DyeGrid& grid)
    : group_(group), local_(buildDyeBand(piece, grid)), into_(size_t(group.size())) {
    std::vector<uint8_t> mine;
    mine.reserve(local_.size() * kCandidateBytes);
    std::vector<uint32_t> cellOf(local_.size());
    for (size_t c = 0; c < local_.index.size(); ++c)
        if (local_.index[c] >= 0) cellOf[size_t(local_.index[c])] = uint32_t(c);
    for (size_t i = 0; i < local_.size(); ++i) {
        put(mine, cellOf[i]);
        put(mine, local_.distance2[i]);
        put(mine, local_.tieKey[i]);
        put(mine, local_.closest[i]);
    }
    const std::vector<std::vector<uint8_t>> all = allGather(group, std::move(mine));

    // At each cell the nearest candidate; ranks in order, so a full tie keeps the lower one.
    band_.grid = grid;
    band_.index.assign(grid.voxelCount(), -1);
    std::vector<int32_t> owner, ownerVoxel;  // per whole-band voxel: the winning process and its voxel
    for (int r = 0; r < group.size(); ++r) {
        const std::vector<uint8_t>& msg = all[size_t(r)];
        const uint8_t* in = msg.data();
        for (size_t i = 0; i < msg.size() / kCandidateBytes; ++i) {
            Candidate c;
            c.cell = get<uint32_t>(in);
            c.distance2 = get<float>(in);
            c.key = get<uint32_t>(in);
            c.closest = get<glm::vec3>(in);
            if (c.cell >= band_.index.size()) throw Error("dye: a process sent a band cell outside the grid");
            int32_t& idx = band_.index[c.cell];
            if (idx < 0) {
                idx = int32_t(band_.closest.size());
                band_.closest.push_back(c.closest);
                band_.distance2.push_back(c.distance2);
                band_.tieKey.push_back(c.key);
                owner.push_back(r);
                ownerVoxel.push_back(int32_t(i));
            } else if (nearer(c.distance2, c.key, band_.distance2[size_t(idx)], band_.tieKey[size_t(idx)])) {
                band_.closest[size_t(idx)] = c.closest;
                band_.distance2[size_t(idx)] = c.distance2;
                band_.tieKey[size_t(idx)] = c.key;
                owner[size_t(idx)] = r;
                ownerVoxel[size_t(idx)] = int32_t(i);
            }
        }
    }
    const std::vector<uint32_t> order = orderByBrick(band_);
    size_ = band_.size();
    std::vector<int32_t> ownerAt(size_), voxelAt(size_);
    for (size_t i = 0; i < size_; ++i) {
        ownerAt[order[i]] = owner[i];
        voxelAt[order[i]] = ownerVoxel[i];
    }
    // Each process sends the values of the voxels it won in whole-band order.
    for (size_t m = 0; m < size_; ++m) {
        into_[size_t(ownerAt[m])].push_back(uint32_t(m));
        if (ownerAt[m] == group.rank()) won_.push_back(uint32_t(voxelAt[m]));
    }

    // The bricks each piece's band touches: the cells of its own band, on the same grid.
    const size_t bricks = band_.brickStart.size() - 1;
    std::vector<uint8_t> touched(bricks, 0);
    for (size_t c = 0; c < local_.index.size(); ++c)
        if (local_.index[c] >= 0) touched[band_.brick[size_t(band_.index[c])]] = 1;
    pieceBricks_ = allGather(group, std::move(touched));
    keeper_.assign(bricks, -1);
    for (int r = group.size() - 1; r >= 0; --r) {
        if (pieceBricks_[size_t(r)].size() != bricks) throw Error("dye: process " + std::to_string(r) + " sent another brick grid");
        for (size_t b = 0; b < bricks; ++b)
            if (pieceBricks_[size_t(r)][b]) keeper_[b] = r;
    }
}

std::vector<uint8_t> dilateBoth(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b, glm::ivec3 dims, int reach) {
    std::vector<uint8_t> out(a.size());
    for (size_t i = 0; i < a.size(); ++i) out[i] = a[i] && b[i];
    if (reach <= 0) return out;
    // Separable: a run of 2 reach + 1 along x, then y, then z.
    const size_t strides[3] = {1, size_t(dims.x), size_t(dims.x) * size_t(dims.y)};
    std::vector<uint8_t> in;
    for (int axis = 0; axis < 3; ++axis) {
        in = out;
        const int n = dims[axis];
        const size_t stride = strides[axis];
        for (size_t i = 0; i < in.size(); ++i) {
            if (!in[i]) continue;
            const int at = int((i / stride) % size_t(n));
            for (int k = std::max(0, at - reach); k <= std::min(n - 1, at + reach); ++k)
                out[size_t(ptrdiff_t(i) + ptrdiff_t(k - at) * ptrdiff_t(stride))] = 1;
        }
    }
    return out;
}

std::vector<glm::vec3> SharedDyeBand::velocity(const core::SurfaceMesh& piece, const std::string& field) {
    const std::vector<glm::vec3> local = bandVelocity(local_, piece, field);
    std::vector<uint8_t> mine;
    mine.reserve(won_.size() * sizeof(glm::vec3));
    for (uint32_t v : won_) put(mine, local[v]);
    const std::vector<std::vector<uint8_t>> all = allGather(group_, std::move(mine));
    std::vector<glm::vec3> out(size_, glm::vec3(0.0f));
    for (int r = 0; r < group_.size(); ++r) {
        const std::vector<uint32_t>& to = into_[size_t(r)];
        if (all[size_t(r)].size() != to.size() * sizeof(glm::vec3))
            throw Error("dye: process " + std::to_string(r) + " sent velocities for another band");
        const uint8_t* in = all[size_t(r)].data();
        for (uint32_t m : to) out[m] = get<glm::vec3>(in);
    }
    return out;
}

glm::vec3 closestOnWholeSurface(ProcessGroup* group, const core::SurfaceMesh& piece, const glm::vec3& p) {
    const SurfacePoint mine = closestOnSurface(piece, p);
    if (!group || group->size() < 2) return mine.position;
    std::vector<uint8_t> bytes;
    put(bytes, uint32_t(mine.found));
    put(bytes, mine.distance2);
    put(bytes, mine.key);
    put(bytes, mine.position);
    SurfacePoint best;
    best.position = p;
    for (const std::vector<uint8_t>& msg : allGather(*group, std::move(bytes))) {
        const uint8_t* in = msg.data();
        SurfacePoint s;
        s.found = get<uint32_t>(in) != 0;
        s.distance2 = get<float>(in);
        s.key = get<uint32_t>(in);
        s.position = get<glm::vec3>(in);
        if (s.found && (!best.found || nearer(s.distance2, s.key, best.distance2, best.key))) best = s;
    }
    return best.position;
}

}  // namespace flowsurf::methods
