// Histogram of per-pixel values in [0, 1] over HISTOGRAM_BINS bins [doc/contrast.md;
// present/percentile_range.h]. Included last by a shader that defines
//   bool histogramValue(ivec2 px, out float value)   // false: the pixel is not counted
// Each work group counts a HISTOGRAM_TILE^2-pixel block in shared memory, then adds its
// non-zero bins to the global counts: one atomic per bin and block, not per pixel.
layout(local_size_x = PIXEL_GROUP, local_size_y = PIXEL_GROUP) in;
layout(std430, binding = HISTOGRAM_BINDING) buffer Histogram { uint bins[HISTOGRAM_BINS]; };
shared uint blockBins[HISTOGRAM_BINS];
uniform ivec2 uOrigin;  // the pixels counted: [uOrigin, uEnd)
uniform ivec2 uEnd;

void main() {
    const uint invocations = gl_WorkGroupSize.x * gl_WorkGroupSize.y;
    for (uint b = gl_LocalInvocationIndex; b < HISTOGRAM_BINS; b += invocations) blockBins[b] = 0u;
    barrier();
    const int per = HISTOGRAM_TILE / PIXEL_GROUP;
    ivec2 block = uOrigin + ivec2(gl_WorkGroupID.xy) * HISTOGRAM_TILE + ivec2(gl_LocalInvocationID.xy);
    for (int j = 0; j < per; ++j) {
        for (int i = 0; i < per; ++i) {
            ivec2 px = block + ivec2(i, j) * PIXEL_GROUP;
            float v;
            if (all(lessThan(px, uEnd)) && histogramValue(px, v)) {
                uint b = uint(clamp(v, 0.0, 1.0) * float(HISTOGRAM_BINS));
                atomicAdd(blockBins[min(b, uint(HISTOGRAM_BINS - 1))], 1u);
            }
        }
    }
    barrier();
    for (uint b = gl_LocalInvocationIndex; b < HISTOGRAM_BINS; b += invocations)
        if (blockBins[b] != 0u) atomicAdd(bins[b], blockBins[b]);
}
