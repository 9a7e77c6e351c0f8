// Noise G of [L] §III-A / doc/algorithms.md §1: statistics and the periodic profile.
#include "core/noise.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace flowsurf::core;

TEST(Noise, HashIsTheFixedPcgPermutation) {
    // Pinned values: the GLSL mirror and every platform must agree.
    EXPECT_EQ(hashPcg(0u), 129708002u);
    EXPECT_NE(hashCell(1, 2, 3), hashCell(2, 1, 3));
    EXPECT_NE(hashCell(1, 2, 3), hashCell(1, 2, 4));
}

TEST(Noise, CellValuesAreBalancedAndPhasesUniform) {
    NoiseParams p;
    p.seed = 42;
    int on = 0, n = 0;
    std::vector<int> phaseHist(10, 0);
    for (int j = 0; j < 100; ++j)
        for (int i = 0; i < 100; ++i, ++n) {
            on += noiseCell(i, j, 5, p) > 0.5f;
            float phase = hashToUnit(hashCell(i, j, p.seed));
            phaseHist[std::min(9, int(phase * 10))]++;
        }
    EXPECT_NEAR(double(on) / n, 0.5, 0.03);  // square wave: half the cells are on
    for (int c : phaseHist) EXPECT_NEAR(c, n / 10, n / 10 * 0.15);  // uniform phases
}

TEST(Noise, InterpolatedNoiseMeanAndRange) {
    NoiseParams p;
    p.scale = 3.0f;
    double sum = 0, sum2 = 0;
    int n = 0;
    for (int y = 0; y < 200; ++y)
        for (int x = 0; x < 200; ++x, ++n) {
            float g = noiseAt(x + 0.5f, y + 0.5f, 11, p);
            ASSERT_GE(g, 0.0f);
            ASSERT_LE(g, 1.0f);
            sum += g;
            sum2 += g * g;
        }
    double mean = sum / n, sd = std::sqrt(sum2 / n - mean * mean);
    EXPECT_NEAR(mean, 0.5, 0.02);
    EXPECT_GT(sd, 0.2);  // bilinear smoothing keeps most of the binary contrast
}

TEST(Noise, ProfileIsPeriodic) {
    NoiseParams p;
    p.period = 16.0f;
    for (int i = 0; i < 50; ++i) EXPECT_EQ(noiseCell(i, 3, 2, p), noiseCell(i, 3, 2 + 16, p));
    p.profile = NoiseProfile::Sawtooth;
    EXPECT_FLOAT_EQ(noiseProfile(NoiseProfile::Sawtooth, 0.25f), 0.25f);
    EXPECT_FLOAT_EQ(noiseProfile(NoiseProfile::Square, 0.25f), 1.0f);
    EXPECT_FLOAT_EQ(noiseProfile(NoiseProfile::Square, 0.75f), 0.0f);
}

TEST(Noise, NeighbouringPixelsInOneCellAreSmooth) {
    NoiseParams p;
    p.scale = 8.0f;
    // Within a cell the value changes at most 1/s per pixel (bilinear).
    for (int x = 0; x < 100; ++x)
        EXPECT_LE(std::abs(noiseAt(x + 1.5f, 10.5f, 0, p) - noiseAt(x + 0.5f, 10.5f, 0, p)), 1.0f / 8.0f + 1e-5f);
}
