// ParaView plugin: the flow topology's layer blended over ParaView's framebuffer after the
// method's composite (src/paraview/representation/mapper_topology.cxx), premultiplied:
// the layer drawn over black is its colour x coverage, over white that plus (1 - coverage).
// Depth: the method's surface depth where the surface is (what lies in front of it hides
// the layer), the far plane elsewhere (a glyph's rim over the background). Under MPI the
// layer is drawn in two parts: over this process's surface (depth not written), then over
// its background, written just short of the far plane, since IceT's composite takes a pixel
// at the far plane for empty and would drop the layer there.
layout(binding = COMPOSITE_COLOR_UNIT) uniform sampler2D uOverBlack;  // the layer over black, RGBA8
layout(binding = COMPOSITE_SHADE_UNIT) uniform sampler2D uOverWhite;  // the layer over white, RGBA8
layout(binding = COMPOSITE_DEPTH_UNIT) uniform sampler2D uDepth;      // the method's surface depth, 1 = background
uniform ivec2 uOrigin;   // the viewport's lower-left pixel
uniform float uDepthBias;
uniform int uPart;       // 0: everywhere, 1: over the surface only, 2: over the background only
const float kBackgroundDepth = 1.0 - 1.0 / 1048576.0;
out vec4 outColor;

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy) - uOrigin;
    vec3 overBlack = texelFetch(uOverBlack, px, 0).rgb;
    vec3 overWhite = texelFetch(uOverWhite, px, 0).rgb;
    float cover = clamp(1.0 - dot(overWhite - overBlack, vec3(1.0 / 3.0)), 0.0, 1.0);
    if (cover < 0.5 / 255.0) discard;
    float depth = texelFetch(uDepth, px, 0).r;
    if ((uPart == 1 && depth >= 1.0) || (uPart == 2 && depth < 1.0)) discard;
    outColor = vec4(overBlack, cover);
    gl_FragDepth = depth >= 1.0 ? (uPart == 2 ? kBackgroundDepth : 1.0) : max(depth - uDepthBias, 0.0);
}
