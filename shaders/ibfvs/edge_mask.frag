// Background-coloured with high opacity over the composite: dims silhouettes. Visibility
// is tested by hand against the surface depth with a tolerance: just inside an outline
// the surface is much nearer than the silhouette edge itself (grazing angle), so a plain
// depth test would drop the inner half of every outline.
layout(binding = EDGE_MASK_DEPTH_UNIT) uniform sampler2D uDepth;  // surface window depth, 1 = background
uniform vec4 uColor;
uniform float uNear;
uniform float uFar;
uniform int uOrtho;
uniform float uTolerance;  // fraction of the depth range
out vec4 outColor;
float linearDepth(float d) {
    return uOrtho != 0 ? uNear + d * (uFar - uNear) : uNear * uFar / (uFar - d * (uFar - uNear));
}
void main() {
    float surface = texelFetch(uDepth, ivec2(gl_FragCoord.xy), 0).r;
    if (surface < 1.0 && linearDepth(gl_FragCoord.z) > linearDepth(surface) + uTolerance * (uFar - uNear))
        discard;  // hidden behind a nearer part of the surface
    outColor = uColor;
}
