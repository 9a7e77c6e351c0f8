// Texture advection plus ISA edge blending [L §IV-E.1]: at edge advection points, gray
// (the noise mean) is blended in so texture is not carried across a geometric
// discontinuity. A grid cell touching an edge vertex counts as edge: interpolating the
// flag would let half the upstream texture leak across at every edge cell. Then noise
// injection on the surface only [L eq. 9], in the same pass.
#include "common/resample.glsl"
#include "common/noise_injection.glsl"
layout(binding = 0) uniform sampler2D uPrevFlow;     // F_a(k-1), R32F, linear filtering
layout(binding = 2) uniform sampler2D uSurfaceDepth; // velocity image depth, 1 = background
uniform int uEdgeBlending;
uniform float uGray;
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
    float f = resampleFlow(uPrevFlow, vTexcoord);
    if (uEdgeBlending != 0 && vEdge > 1e-3) f = uGray;
    if (texelFetch(uSurfaceDepth, ivec2(gl_FragCoord.xy), 0).r < 1.0)  // gamma = 0 off the surface
        f = injectNoise(f, gl_FragCoord.xy, gl_FragCoord.xy - vTexcoord * vec2(textureSize(uPrevFlow, 0)));
    outFlow = vec4(f, 0.0, 0.0, 1.0);
}
