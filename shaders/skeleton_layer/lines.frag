// The flow topology layer, lines: coverage from the pixel's distance to the piece (round
// ends, so pieces join smoothly), hidden behind the surface; the outline pass is dark.
#include "skeleton_layer/depth.glsl"
uniform vec3 kindColour[2];  // separation, attachment (SkeletonLayer's table)
uniform int outlinePass;
uniform float halfWidthPx;
flat in vec2 aPx, bPx;
flat in float depthA, depthB, kind;
flat in int depthTest;
out vec4 outColor;

void main() {
    vec2 p = gl_FragCoord.xy, ab = bPx - aPx;
    float len2 = dot(ab, ab);
    float t = len2 > 0.0 ? clamp(dot(p - aPx, ab) / len2, 0.0, 1.0) : 0.0;
    float cover = clamp(halfWidthPx + 0.5 - length(p - (aPx + t * ab)), 0.0, 1.0);
    if (cover <= 0.0 || (depthTest == 1 && hiddenBySurface(p, mix(depthA, depthB, t)))) discard;
    outColor = outlinePass == 1 ? vec4(vec3(0.04), 0.8 * cover) : vec4(kindColour[int(kind + 0.5)], cover);
}
