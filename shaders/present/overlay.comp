// Overlay [L eq. 10], compute path: one invocation per pixel of the composite (RGBA8).
#include "present/overlay.glsl"
layout(local_size_x = PIXEL_GROUP, local_size_y = PIXEL_GROUP) in;
layout(binding = OVERLAY_IMAGE_UNIT, rgba8) writeonly uniform image2D uComposite;
uniform ivec2 uOrigin;  // the pixels written: [uOrigin, uEnd) (a parallel render's own piece)
uniform ivec2 uEnd;
void main() {
    ivec2 px = uOrigin + ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(px, uEnd))) return;
    imageStore(uComposite, px, vec4(overlayColor(px), 1.0));
}
