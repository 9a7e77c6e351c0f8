#include "core/noise.h"

#include <cmath>

namespace flowsurf::core {

uint32_t hashPcg(uint32_t v) {
    uint32_t state = v * 747796405u + 2891336453u;
    uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

uint32_t hashCell(int32_t ix, int32_t iy, uint32_t seed) {
    return hashPcg(uint32_t(ix) + hashPcg(uint32_t(iy) + hashPcg(seed)));
}

float noiseProfile(NoiseProfile profile, float t) {
    t = t - std::floor(t);
    switch (profile) {
        case NoiseProfile::Square: return t < 0.5f ? 1.0f : 0.0f;
        case NoiseProfile::Sawtooth: return t;
    }
    return 0.0f;
}

float noiseCell(int32_t ix, int32_t iy, uint32_t frame, const NoiseParams& params) {
    float phase = hashToUnit(hashCell(ix, iy, params.seed));
    return noiseProfile(params.profile, float(frame) / params.period + phase);
}

float noiseAt(float xPx, float yPx, uint32_t frame, const NoiseParams& params) {
    // Cell values sit at cell centres; h(u) = max(0, 1-|u|) is bilinear interpolation.
    float u = xPx / params.scale - 0.5f, v = yPx / params.scale - 0.5f;
    float fu = std::floor(u), fv = std::floor(v);
    int32_t i = int32_t(fu), j = int32_t(fv);
    float a = u - fu, b = v - fv;
    float g00 = noiseCell(i, j, frame, params), g10 = noiseCell(i + 1, j, frame, params);
    float g01 = noiseCell(i, j + 1, frame, params), g11 = noiseCell(i + 1, j + 1, frame, params);
    return (1 - b) * ((1 - a) * g00 + a * g10) + b * ((1 - a) * g01 + a * g11);
}

}  // namespace flowsurf::core
