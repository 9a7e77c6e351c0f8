// flowsurf — colour and mask ranges from the data [docs/cfd.md, colour ranges]: an area-weighted summary of
// a scalar's values (over one mesh, the pieces of a parallel render, or every step of a
// series) and the two ranges made from it, the data range and the robust range.
//
// The robust rule: the ends of a box plot's whiskers on area-weighted quartiles, i.e. the
// most extreme values inside Tukey's fences
//   lo = smallest value >= Q1 - 1.5 IQR,  hi = largest value <= Q3 + 1.5 IQR,
// in log10 of the values for a log colour scale. Why not fixed percentiles: a clean field
// (a ramp, a Gaussian bulk) keeps its whole range (a uniform distribution's fences lie
// outside its ends, a normal one's at 2.7 sigma), while any number of outliers, 0.1 % or
// 10 %, leaves the quartiles, and so the range, where the bulk is. A fixed 1st-99th
// percentile is set by the outliers as soon as they exceed 1 % of the area; a fixed
// 5th-95th clips 10 % of a clean field. When half the area holds one value (IQR = 0) the
// fences collapse: the 1st-99th percentiles are used, then the data range.
// No GL: unit tests cover it.
#pragma once

#include "core/mesh.h"

#include <glm/glm.hpp>

#include <limits>
#include <span>
#include <utility>
#include <vector>

namespace flowsurf::core {

// Tukey's fence factor k of the robust rule (1.5: his "outer" fence, the usual choice).
inline constexpr float kRobustFence = 1.5f;

// Each vertex's share of the surface area: a third of every triangle around it. A vertex
// shared by pieces of a split surface gets its share in each piece; summed they are whole.
std::vector<float> vertexAreas(const SurfaceMesh& mesh);

// A bounded, weighted summary of values: the (value, weight) pairs of small inputs, at
// most kPoints quantile points per added batch of large ones (rank error 1 / (2 kPoints)
// per compression), and the exact minimum, maximum and smallest positive value.
class ValueDistribution {
public:
    static constexpr size_t kPoints = 4096;

    // Adds `values` weighted by `weights` (same length; empty: weight 1 each). Non-finite
    // values and non-positive weights are skipped.
    void add(std::span<const float> values, std::span<const float> weights = {});
    void merge(const ValueDistribution& other);
    bool empty() const { return points_.empty(); }
    // The weighted q-quantile (q in 0..1): the smallest value whose cumulative weight
    // reaches q of the total.
    float quantile(double q) const;
    // The largest value <= x (min() if none), the smallest value >= x (max() if none).
    float largestAtMost(float x) const;
    float smallestAtLeast(float x) const;
    float min() const { return min_; }
    float max() const { return max_; }
    float minPositive() const { return minPositive_; }  // +inf when no value is > 0

private:
    void compress(size_t points);
    void sort() const;

    mutable std::vector<std::pair<float, float>> points_;  // (value, weight)
    mutable bool sorted_ = true;
    float min_ = std::numeric_limits<float>::infinity();
    float max_ = -std::numeric_limits<float>::infinity();
    float minPositive_ = std::numeric_limits<float>::infinity();
};

// min .. max of the distribution; (1, 0) when empty.
glm::vec2 dataRange(const ValueDistribution& d);
// The robust range (see the top of this file); (1, 0) when empty. With `logScale` the
// fences are taken in log10 and the range is positive; (1, 0) when a quarter or more of
// the area is not positive (no log range shows the bulk: the caller refuses).
glm::vec2 robustRange(const ValueDistribution& d, bool logScale = false);

}  // namespace flowsurf::core
