// The flow topology layer, lines: a dark outline around a core of the kind's colour, both
// anti-aliased from the pixel's distance to the piece (to its line inside the polyline, so
// mitred pieces continue each other; to its end point at a round cap), hidden behind the
// surface. One pass: the core over the outline, premultiplied (blend ONE, 1 - alpha).
#include "skeleton_layer/depth.glsl"
uniform vec3 kindColour[2];  // separation, attachment (SkeletonLayer's table)
uniform float halfWidthPx;   // the outline's; the core is one pixel narrower on each side
flat in vec2 aPx, bPx;
flat in float depthA, depthB, kind;
flat in int depthTest;
flat in int caps;
out vec4 outColor;

void main() {
    vec2 p = gl_FragCoord.xy, ab = bPx - aPx;
    float len2 = dot(ab, ab);
    float t = len2 > 0.0 ? dot(p - aPx, ab) / len2 : 0.0;
    // beyond an end with a cap: the distance to that end; elsewhere to the piece's line
    if ((t < 0.0 && (caps & 1) != 0) || (t > 1.0 && (caps & 2) != 0)) t = clamp(t, 0.0, 1.0);
    float d = length(p - (aPx + t * ab));
    float outline = clamp(halfWidthPx + 0.5 - d, 0.0, 1.0);
    if (outline <= 0.0 || (depthTest == 1 && hiddenBySurface(p, mix(depthA, depthB, clamp(t, 0.0, 1.0))))) discard;
    float core = clamp(halfWidthPx - 0.5 - d, 0.0, 1.0);
    float under = 0.8 * outline * (1.0 - core);
    vec3 colour = kindColour[int(kind + 0.5)] * core + vec3(0.04) * under;
    outColor = vec4(colour, core + under);
}
