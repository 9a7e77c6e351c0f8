// ISA stage 2, advection mesh [L §IV-D.1, eq. 12] with edge detection (eq. 14):
// for each vertex x' of the R x R image grid on the surface, v' = T(x + v dt) - T(x)
// and the texture coordinate x' - v' (backward integration). Output per vertex:
// (texcoord in [0,1]^2, edge flag, 0) in an (R+1)^2 RGBA32F image that the static
// case reuses.
#include "isa/edge_detection.glsl"
layout(local_size_x = 16, local_size_y = 16) in;
layout(binding = 0) uniform sampler2D uVelocity;  // RGBA32F, xyz P-space velocity
layout(binding = 1) uniform sampler2D uDepth;     // window depth, 1 = background
layout(binding = 0, rgba32f) writeonly uniform image2D uMesh;  // (R+1)^2 vertices
uniform mat4 uViewProj;
uniform mat4 uInvViewProj;
uniform vec2 uViewport;    // pixels
uniform int uGridRes;      // R: cells per side
uniform float uDt;         // object-space time step
uniform float uEdgeEps;
uniform float uNear;
uniform float uFar;
uniform int uOrtho;

vec2 toPixels(vec3 posObj) {
    vec4 c = uViewProj * vec4(posObj, 1.0);
    return (c.xy / c.w * 0.5 + 0.5) * uViewport;
}

void main() {
    ivec2 g = ivec2(gl_GlobalInvocationID.xy);
    if (g.x > uGridRes || g.y > uGridRes) return;
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
        vec2 velPx = toPixels(posObj + velObj * uDt) - toPixels(posObj);  // v' dt
        pPrev = pK - velPx;
        ivec2 prevTexel = clamp(ivec2(floor(pPrev)), ivec2(0), ivec2(uViewport) - 1);
        float depthPrev = texelFetch(uDepth, prevTexel, 0).r;
        edge = edgeFlag(depthK, depthPrev, pK, pPrev, uEdgeEps, uNear, uFar, uOrtho != 0);
    }
    imageStore(uMesh, g, vec4(pPrev / uViewport, edge, 0.0));
}
