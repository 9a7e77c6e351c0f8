// flowsurf — sort-last parallel rendering: several processes each hold a piece of the
// surface and render the same view, and together make the one-process image. Each process
// draws its piece into its per-pixel buffers; before any image-space stage the buffers are
// merged by depth (at every pixel the nearest fragment of any process wins), so the stages
// see the whole surface and streaks run across the partition seams. Where the stages run
// is CommonParams::parallel: `tiles` (screen_tiles.h: each process runs them on its own
// screen tile plus a guard band, merged there only) or `replicate` (mergeByDepth below: every
// process merges the whole image and runs every stage on all of it; the reference the tiles
// are tested against). The screen-space compositing is that of Loring, Karimabadi & Bethel,
// "A Screen Space GPGPU Surface LIC Algorithm for Distributed Memory Data Parallel Sort Last
// Rendering Infrastructures", LBNL 2014.
//
// ProcessGroup is the message passing a front end provides (the ParaView plugin: ParaView's
// vtkMultiProcessController over MPI; tests and `flowsurf bench --ranks`: thread_group.h).
// Every call is collective: all processes of the group make the same calls in the same order
// with arrays of the same length.
//
// Cost of a replicated merge: one readback and upload of the merged textures and three
// element-wise reductions of W x H x (1 + 1 + channels) values.
#pragma once

#include "gl/objects.h"

#include <cstdint>
#include <initializer_list>
#include <span>
#include <vector>

namespace flowsurf::methods {

class ProcessGroup {
public:
    virtual ~ProcessGroup() = default;
    virtual int rank() const = 0;
    virtual int size() const = 0;
    // Element-wise over all processes, the result in place on every process.
    virtual void minInPlace(std::span<float> values) = 0;
    virtual void minInPlace(std::span<int32_t> values) = 0;
    virtual void sumInPlace(std::span<float> values) = 0;
    // Every process's values concatenated in rank order, on every process.
    virtual std::vector<float> gather(std::span<const float> values) = 0;
    // Personalised all-to-all: `sends[q]` goes to process q (sends[rank()] is not sent; an
    // empty message is allowed); returns what every process sent to this one, indexed by
    // sender (the own slot empty). `sends` has size() entries.
    virtual std::vector<std::vector<uint8_t>> exchange(const std::vector<std::vector<uint8_t>>& sends) = 0;
};

// Collective: `bytes` from every process of `group`, in rank order (this one's included),
// over ProcessGroup::exchange.
std::vector<std::vector<uint8_t>> allGather(ProcessGroup& group, std::vector<uint8_t> bytes);

// Replaces `depth` (DEPTH_COMPONENT32F) and each of `layers` (float or half formats with
// 1-4 channels, the size of `depth`) by their merge over `group`: at each pixel the values
// of the process whose depth is smallest (on a tie, the lowest rank). Exact: the winning
// process's values arrive unchanged (a sum with zeros from the others).
void mergeByDepth(ProcessGroup& group, const gl::Texture2D& depth, std::initializer_list<const gl::Texture2D*> layers);

// The same merge on CPU arrays (depth per pixel, `channels` values per pixel per layer);
// what mergeByDepth runs between readback and upload.
void mergeByDepth(ProcessGroup& group, std::vector<float>& depth, std::span<std::vector<float>* const> layers);

}  // namespace flowsurf::methods
