// Contrast enhancement [doc/contrast.md]: the flow texture stretched so that the range uRange
// (its smoothed robust percentiles) spans [0, 1], clamped; the background as it was.
layout(local_size_x = PIXEL_GROUP, local_size_y = PIXEL_GROUP) in;
layout(binding = CONTRAST_FLOW_UNIT) uniform sampler2D uFlow;    // F_a or I, channel r
layout(binding = CONTRAST_DEPTH_UNIT) uniform sampler2D uDepth;  // window depth, 1 = background
layout(binding = CONTRAST_IMAGE_UNIT, r32f) writeonly uniform image2D uStretched;
uniform vec2 uRange;  // lo < hi
uniform ivec2 uEnd;

void main() {
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(px, uEnd))) return;
    float v = texelFetch(uFlow, px, 0).r;
    if (texelFetch(uDepth, px, 0).r < 1.0) v = clamp((v - uRange.x) / (uRange.y - uRange.x), 0.0, 1.0);
    imageStore(uStretched, px, vec4(v, 0.0, 0.0, 0.0));
}
