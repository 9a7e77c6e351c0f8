// flowsurf — the machine's speed, measured with a workload that no change to flowsurf
// touches: scripts/bench-check.sh divides each row's ratio to its baseline by this one's,
// so a machine (or a moment of load) twice as slow as the baseline's is not a regression.
#pragma once

namespace flowsurf::bench {

// ms per frame of a fixed GL frame at 512x512 (needs a current GL context): 80,000 small
// triangles rasterised with depth (a surface pass), then a full-screen pass of 16
// dependent bilinear fetches per pixel (an image-space pass, like a LIC). Median of
// `repeats` timings of `frames` frames each, after 3 warm-up frames.
double calibrationMs(int frames, int repeats);

}  // namespace flowsurf::bench
