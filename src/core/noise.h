// flowsurf — deterministic noise G of §1 item 4: a grid of random values of spatial
// scale s, each cycling in time with a random phase and a periodic profile w.
// shaders/core/noise.glsl mirrors these functions bit for bit in the hash.
#pragma once

#include <cstdint>

namespace flowsurf::core {

enum class NoiseProfile { Square, Sawtooth };

// Mean of G for both profiles: F_a's value where no texture is (background, gray edge
// fill, the initial texture). The one name for it, also in GLSL (NOISE_MEAN).
inline constexpr float kNoiseMean = 0.5f;

struct NoiseParams {
    float scale = 2.0f;        // s: noise cell size in pixels, [L] 1..10
    float period = 64.0f;      // f_rate: frames per cycle of the profile w
    NoiseProfile profile = NoiseProfile::Square;
    uint32_t seed = 1;
};

// Our own integer hash (PCG output permutation): identical on every platform and in GLSL.
uint32_t hashPcg(uint32_t v);
// Hash of a grid cell and the seed.
uint32_t hashCell(int32_t ix, int32_t iy, uint32_t seed);
// Uniform in [0,1).
inline float hashToUnit(uint32_t h) { return float(h >> 8) * (1.0f / 16777216.0f); }

// Periodic profile w on [0,1) -> [0,1].
float noiseProfile(NoiseProfile profile, float t);
// G_{i,j;k} = w(k / f_rate + phi_{i,j}).
float noiseCell(int32_t ix, int32_t iy, uint32_t frame, const NoiseParams& params);
// G(x; k): bilinear (triangular pulse h) interpolation of the cell values; x in pixels.
float noiseAt(float xPx, float yPx, uint32_t frame, const NoiseParams& params);

}  // namespace flowsurf::core
