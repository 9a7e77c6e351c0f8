#include "core/value_range.h"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace flowsurf::core {

std::vector<float> vertexAreas(const SurfaceMesh& mesh) {
    std::vector<float> area(mesh.vertexCount(), 0.0f);
    for (const glm::uvec3& t : mesh.triangles) {
        const glm::vec3 &a = mesh.positions[t.x], &b = mesh.positions[t.y], &c = mesh.positions[t.z];
        const float third = glm::length(glm::cross(b - a, c - a)) / 6.0f;
        area[t.x] += third;
        area[t.y] += third;
        area[t.z] += third;
    }
    return area;
}

void ValueDistribution::sort() const {
    if (sorted_) return;
    std::sort(points_.begin(), points_.end());
    sorted_ = true;
}

void ValueDistribution::add(std::span<const float> values, std::span<const float> weights) {
    // A large batch is summarised on its own first, so that memory stays at kPoints per
    // batch (a time step) however many vertices it has.
    ValueDistribution batch;
    ValueDistribution& into = values.size() > kPoints ? batch : *this;
    for (size_t i = 0; i < values.size(); ++i) {
        const float v = values[i], w = weights.empty() ? 1.0f : weights[i];
        if (!std::isfinite(v) || !(w > 0.0f)) continue;
        into.points_.emplace_back(v, w);
        into.min_ = std::min(into.min_, v);
        into.max_ = std::max(into.max_, v);
        if (v > 0.0f) into.minPositive_ = std::min(into.minPositive_, v);
    }
    into.sorted_ = false;
    if (&into == &batch) {
        batch.compress(kPoints);
        merge(batch);
    } else if (points_.size() > 16 * kPoints) {
        compress(4 * kPoints);
    }
}

void ValueDistribution::merge(const ValueDistribution& other) {
    points_.insert(points_.end(), other.points_.begin(), other.points_.end());
    sorted_ = false;
    min_ = std::min(min_, other.min_);
    max_ = std::max(max_, other.max_);
    minPositive_ = std::min(minPositive_, other.minPositive_);
    if (points_.size() > 16 * kPoints) compress(4 * kPoints);
}

float ValueDistribution::quantile(double q) const {
    if (points_.empty()) return std::numeric_limits<float>::quiet_NaN();
    sort();
    double total = 0.0;
    for (const auto& [v, w] : points_) total += w;
    // The smallest value whose cumulative weight reaches q (the inverse of the CDF).
    const double target = std::clamp(q, 0.0, 1.0) * total;
    double below = 0.0;
    for (const auto& [v, w] : points_) {
        below += w;
        if (below >= target) return v;
    }
    return points_.back().first;
}

float ValueDistribution::largestAtMost(float x) const {
    if (x >= max_) return max_;
    sort();
    auto it = std::upper_bound(points_.begin(), points_.end(), std::make_pair(x, std::numeric_limits<float>::infinity()));
    return it == points_.begin() ? min_ : std::prev(it)->first;
}

float ValueDistribution::smallestAtLeast(float x) const {
    if (x <= min_) return min_;
    sort();
    auto it = std::lower_bound(points_.begin(), points_.end(), std::make_pair(x, -std::numeric_limits<float>::infinity()));
    return it == points_.end() ? max_ : it->first;
}

void ValueDistribution::compress(size_t points) {
    if (points_.size() <= points) return;
    sort();
    double total = 0.0;
    for (const auto& [v, w] : points_) total += w;
    // One walk: point i takes the value where the cumulative weight reaches (i + 1/2) / points.
    std::vector<std::pair<float, float>> out;
    out.reserve(points);
    double below = 0.0;
    size_t j = 0;
    for (size_t i = 0; i < points; ++i) {
        const double target = (double(i) + 0.5) / double(points) * total;
        while (j + 1 < points_.size() && below + points_[j].second < target) below += points_[j++].second;
        out.emplace_back(points_[j].first, float(total / double(points)));
    }
    points_ = std::move(out);
    sorted_ = true;
}

glm::vec2 dataRange(const ValueDistribution& d) {
    return d.empty() ? glm::vec2(1.0f, 0.0f) : glm::vec2(d.min(), d.max());
}

glm::vec2 robustRange(const ValueDistribution& d, bool logScale) {
    if (d.empty()) return {1.0f, 0.0f};
    const float q1 = d.quantile(0.25), q3 = d.quantile(0.75);
    if (logScale && !(q1 > 0.0f)) return {1.0f, 0.0f};
    // The fences, in log10 for a log scale, then the whiskers' ends: the most extreme
    // values inside them (what a box plot draws).
    float lo, hi;
    if (logScale) {
        const double a = std::log10(double(q1)), b = std::log10(double(q3)), iqr = b - a;
        lo = float(std::pow(10.0, a - kRobustFence * iqr));
        hi = float(std::pow(10.0, b + kRobustFence * iqr));
        lo = std::max(d.smallestAtLeast(lo), d.minPositive());
    } else {
        const double iqr = double(q3) - double(q1);
        lo = d.smallestAtLeast(float(double(q1) - kRobustFence * iqr));
    }
    hi = logScale ? d.largestAtMost(hi) : d.largestAtMost(float(double(q3) + kRobustFence * (double(q3) - double(q1))));
    if (!(hi > lo)) {  // the bulk is one value: the 1st-99th percentiles, then the data
        lo = d.quantile(0.01);
        hi = d.quantile(0.99);
        if (logScale) lo = std::max(lo, d.minPositive());
        if (!(hi > lo)) { lo = logScale ? d.minPositive() : d.min(); hi = d.max(); }
    }
    return {lo, hi};
}

}  // namespace flowsurf::core
