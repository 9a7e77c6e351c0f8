// ISA stage 2, advection mesh [L §IV-D.1, eq. 12] with edge detection (eq. 14), shared by
// advection_mesh.comp and advection_mesh.frag: for each vertex x' of the R x R image grid
// on the surface, the surface point x is recovered from depth and the texture coordinate
// is x'_src - v' with v' = T_src(x + v dt) - T_src(x) (backward integration). T_src is the
// view the source texture was made in: the current one, or the previous one when the
// translate remedy reprojects under camera motion. Output per vertex: (texcoord in
// [0,1]^2, edge flag, 0) in an (R+1)^2 RGBA32F image that the static case reuses.
#include "isa/edge_detection.glsl"
layout(binding = MESH_VELOCITY_UNIT) uniform sampler2D uVelocity;         // RGBA32F, xyz P-space velocity
layout(binding = MESH_DEPTH_UNIT) uniform sampler2D uDepth;               // window depth, 1 = background
layout(binding = MESH_SOURCE_DEPTH_UNIT) uniform sampler2D uSourceDepth;  // depth where the source texture was made
uniform mat4 uInvViewProj;     // current view, to recover x from depth
uniform mat4 uSourceViewProj;  // T_src
uniform vec2 uViewport;        // pixels
uniform int uGridRes;          // R: cells per side
uniform float uDt;             // object-space time step
uniform float uEdgeEps;
uniform float uNear;           // of the source view
uniform float uFar;
uniform int uOrtho;

vec3 toSourcePixels(vec3 posObj) {
    vec4 c = uSourceViewProj * vec4(posObj, 1.0);
    vec3 ndc = c.xyz / max(c.w, 1e-6);
    return vec3((ndc.xy * 0.5 + 0.5) * uViewport, ndc.z * 0.5 + 0.5);
}

// The mesh vertex of grid point g (0..R per side).
vec4 meshVertex(ivec2 g) {
    vec2 pK = vec2(g) / float(uGridRes) * uViewport;  // grid vertex, pixels
    ivec2 texel = clamp(ivec2(pK), ivec2(0), ivec2(uViewport) - 1);
    float depthK = texelFetch(uDepth, texel, 0).r;
    vec2 pPrev = pK;
    float edge = 0.0;
    if (depthK < 1.0) {
        vec3 velObj = texelFetch(uVelocity, texel, 0).xyz;
        vec4 ndc = vec4((vec2(texel) + 0.5) / uViewport * 2.0 - 1.0, depthK * 2.0 - 1.0, 1.0);
        vec4 h = uInvViewProj * ndc;
        vec3 posObj = h.xyz / h.w;
        vec3 src = toSourcePixels(posObj);
        vec2 velPx = toSourcePixels(posObj + velObj * uDt).xy - src.xy;  // v' dt
        // The grid vertex sits at a pixel corner, the sample at the pixel centre.
        pPrev = src.xy + (pK - (vec2(texel) + 0.5)) - velPx;
        ivec2 prevTexel = clamp(ivec2(floor(pPrev)), ivec2(0), ivec2(uViewport) - 1);
        float depthPrev = texelFetch(uSourceDepth, prevTexel, 0).r;
        edge = edgeFlag(src.z, depthPrev, src.xy, pPrev, uEdgeEps, uNear, uFar, uOrtho != 0);
    }
    return vec4(pPrev / uViewport, edge, 0.0);
}
