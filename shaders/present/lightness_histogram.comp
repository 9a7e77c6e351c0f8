// Contrast enhancement of the colour [doc/contrast.md]: the histogram of the HSL lightness of the
// overlay's surface colour (before its stretch) over the surface's pixels.
#include "present/overlay.glsl"

bool histogramValue(ivec2 px, out float value) {
    if (texelFetch(uDepth, px, 0).r >= 1.0) return false;
    value = lightness(surfaceColor(px));
    return true;
}

#include "present/histogram.glsl"
