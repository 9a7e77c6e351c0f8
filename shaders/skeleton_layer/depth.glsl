// The flow topology layer's depth test: a point of the layer is hidden where the method's
// surface lies in front of it by more than 1 % of its distance (the layer lies on the
// surface, so its own depth equals the surface's up to rasterisation).
layout(binding = SKELETON_DEPTH_UNIT) uniform sampler2D uSurfaceDepth;  // window depth, 1 = background
uniform vec3 depthPlanes;  // near, far, 1 for an orthographic camera

float eyeDistance(float windowDepth) {
    float n = depthPlanes.x, f = depthPlanes.y, z = windowDepth * 2.0 - 1.0;
    if (depthPlanes.z > 0.5) return n + (z + 1.0) * 0.5 * (f - n);
    return 2.0 * n * f / (f + n - z * (f - n));
}

bool hiddenBySurface(vec2 px, float windowDepth) {
    ivec2 size = textureSize(uSurfaceDepth, 0);
    ivec2 p = clamp(ivec2(px), ivec2(0), size - 1);
    float surface = texelFetch(uSurfaceDepth, p, 0).r;
    if (surface >= 1.0) return false;
    return eyeDistance(windowDepth) > eyeDistance(surface) * 1.01;
}
