// Texture advection plus ISA edge blending [L §IV-E.1]: at edge advection points the
// advected value is replaced so texture is not carried across a geometric discontinuity:
// by gray (the noise mean, as in [L]) or by the noise history of eq. 9 (EDGE_FILL_NOISE,
// streaks start at the interior's contrast instead of needing ~1/alpha frames). A grid cell touching an edge vertex counts as edge: interpolating the
// flag would let half the upstream texture leak across at every edge cell. Then noise
// injection on the surface only [L eq. 9], in the same pass.
#include "common/resample.glsl"
#include "common/noise_injection.glsl"
layout(binding = 0) uniform sampler2D uPrevFlow;     // F_a(k-1), R32F, linear filtering
layout(binding = 2) uniform sampler2D uSurfaceDepth; // velocity image depth, 1 = background
uniform int uEdgeBlending;
uniform float uFillAlpha;  // alpha of the noise history at edge points (also while frozen)
#ifdef PER_PIXEL
layout(binding = 1) uniform sampler2D uMesh;
in vec2 vGridUv;
#else
in vec2 vTexcoord;
in float vEdge;
#endif
out vec4 outFlow;
void main() {
#ifdef PER_PIXEL
    vec4 m = texture(uMesh, vGridUv);
    vec2 vTexcoord = m.xy;
    float vEdge = m.z;
#endif
    // Off the surface F_a holds the noise mean (no stale texture where the surface was).
    if (texelFetch(uSurfaceDepth, ivec2(gl_FragCoord.xy), 0).r == 1.0) {
        outFlow = vec4(NOISE_MEAN, 0.0, 0.0, 1.0);
        return;
    }
    const vec2 motionPx = gl_FragCoord.xy - vTexcoord * vec2(textureSize(uPrevFlow, 0));
    float f = resampleFlow(uPrevFlow, vTexcoord);
    if (uEdgeBlending != 0 && vEdge > 1e-3) {
#if EDGE_FILL == EDGE_FILL_NOISE
        f = noiseHistory(gl_FragCoord.xy, motionPx, uFillAlpha);
#else
        f = NOISE_MEAN;
#endif
    }
    outFlow = vec4(injectNoise(f, gl_FragCoord.xy, motionPx), 0.0, 0.0, 1.0);
}
