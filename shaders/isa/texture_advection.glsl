// Texture advection plus ISA edge blending [L §IV-E.1], shared by texture_advection.frag
// (mesh and pixel warps) and texture_advection.comp (pixel warp): at edge advection points
// the advected value is replaced so texture is not carried across a geometric
// discontinuity: by gray (the noise mean, as in [L]) or by the noise history of eq. 9
// (EDGE_FILL_NOISE, streaks start at the interior's contrast instead of needing ~1/alpha
// frames). A grid cell touching an edge vertex counts as edge: interpolating the flag would
// let half the upstream texture leak across at every edge cell. Then noise injection on
// the surface only [L eq. 9], in the same pass.
#include "image_space/resample.glsl"
#include "image_space/noise_injection.glsl"
layout(binding = ISA_PREV_FLOW_UNIT) uniform sampler2D uPrevFlow;  // F_a(k-1), R32F, linear filtering
layout(binding = ISA_MESH_UNIT) uniform sampler2D uMesh;           // (R+1)^2: texcoord xy, edge flag z; linear
layout(binding = ISA_SURFACE_DEPTH_UNIT) uniform sampler2D uSurfaceDepth; // velocity image depth, 1 = background
uniform int uGridRes;
uniform int uEdgeBlending;
uniform float uFillAlpha;  // alpha of the noise history at edge points (also while frozen)

// Pixel warp: the advection mesh at pixel centre `px` (pixels), interpolated bilinearly by
// the texture filter between the (R+1)^2 vertices, which sit at the image's cell corners.
vec4 meshAtPixel(vec2 px) {
    vec2 image01 = px / vec2(textureSize(uSurfaceDepth, 0));
    return textureLod(uMesh, (image01 * float(uGridRes) + 0.5) / float(uGridRes + 1), 0.0);
}

// The next F_a at pixel centre `px`, given its backward texture coordinate and edge flag.
float advectedFlow(vec2 px, vec2 texcoord, float edge) {
    // Off the surface F_a holds the noise mean (no stale texture where the surface was).
    if (texelFetch(uSurfaceDepth, ivec2(px), 0).r == 1.0) return NOISE_MEAN;
    const vec2 motionPx = px - texcoord * vec2(textureSize(uPrevFlow, 0));
    float f = resampleFlow(uPrevFlow, texcoord);
    if (uEdgeBlending != 0 && edge > 1e-3) {
#if EDGE_FILL == EDGE_FILL_NOISE
        f = noiseHistory(px, motionPx, uFillAlpha);
#else
        f = NOISE_MEAN;
#endif
    }
    return injectNoise(f, px, motionPx);
}
