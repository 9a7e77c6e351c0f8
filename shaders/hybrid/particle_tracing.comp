// Hybrid particle tracing as a compute pass: one invocation per pixel runs the LIC loop
// (hybrid/particle_tracing.glsl) and stores I into the R32F image; background pixels get
// the noise mean, as the fragment pass's clear leaves them.
#include "hybrid/particle_tracing.glsl"
layout(local_size_x = LOCAL_X, local_size_y = LOCAL_Y, local_size_z = 1) in;
layout(binding = LIC_IMAGE_UNIT, r32f) writeonly uniform image2D uLic;
uniform ivec2 uOrigin;  // the pixels traced: [uOrigin, uEnd) (a parallel render's tile)
uniform ivec2 uEnd;
void main() {
    ivec2 px = uOrigin + ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(px, uEnd))) return;
    float lic;
    imageStore(uLic, px, vec4(licAt(px, lic) ? lic : NOISE_MEAN));
}
