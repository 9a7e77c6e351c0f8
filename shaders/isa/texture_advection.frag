// Texture advection plus ISA edge blending [L §IV-E.1]: at edge advection points, gray
// (the noise mean) is blended in so texture is not carried across a geometric
// discontinuity. A grid cell touching an edge vertex counts as edge: interpolating the
// flag would let half the upstream texture leak across at every edge cell.
#include "common/resample.glsl"
layout(binding = 0) uniform sampler2D uPrevFlow;  // F_a(k-1), R32F, linear filtering
uniform int uEdgeBlending;
uniform float uGray;
#ifdef PER_PIXEL
layout(binding = 1) uniform sampler2D uMesh;
in vec2 vGridUv;
#else
in vec2 vTexcoord;
in float vEdge;
#endif
layout(location = 0) out vec4 outFlow;
layout(location = 1) out vec2 outMotion;  // d' in pixels, for swept noise injection
void main() {
#ifdef PER_PIXEL
    vec4 m = texture(uMesh, vGridUv);
    vec2 vTexcoord = m.xy;
    float vEdge = m.z;
#endif
    float f = resampleFlow(uPrevFlow, vTexcoord);
    if (uEdgeBlending != 0 && vEdge > 1e-3) f = uGray;
    outFlow = vec4(f, 0.0, 0.0, 1.0);
    outMotion = gl_FragCoord.xy - vTexcoord * vec2(textureSize(uPrevFlow, 0));
}
