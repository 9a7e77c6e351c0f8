// flowsurf — sort-last parallel rendering: several processes each hold a piece of the
// surface and render the same view. Before any image-space stage the per-pixel buffers of
// all pieces are merged by depth — at every pixel the nearest fragment of any process wins
// — so each process's image-space stages see the whole surface and its image equals the
// one-process image, streaks running across the partition seams (the screen-space
// compositing of Loring, Karimabadi & Bethel, "A Screen Space GPGPU Surface LIC Algorithm
// for Distributed Memory Data Parallel Sort Last Rendering Infrastructures", LBNL 2014,
// done here over the whole image on every process instead of tiles with guard pixels).
//
// ProcessGroup is the message passing a front end provides (the ParaView plugin: ParaView's
// vtkMultiProcessController over MPI). Every call is collective: all processes of the
// group make the same calls in the same order with arrays of the same length.
//
// Cost per merge: one readback and upload of the merged textures and three element-wise
// reductions of W x H x (1 + 1 + channels) values; image-space stages are not divided
// between processes (each runs them on the whole image).
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
