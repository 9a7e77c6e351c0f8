// IBFVS stage 1, object-space mesh projection [L §IV-C.2, eq. 13]: the texture
// coordinate of vertex x_i is T(x_i - v_i dt), the projection of the previous point on
// its 3D pathline. The 3D field is integrated, not the projected one.
// `prevViewProj` is the camera of the previous frame: with the `translate` remedy it
// differs from the current one, so the texture follows the surface's image motion.
vec2 pathlineTexcoord(vec3 posObj, vec3 velObj, float dt, mat4 prevViewProj) {
    vec4 c = prevViewProj * vec4(posObj - velObj * dt, 1.0);
    return (c.xy / max(c.w, 1e-6)) * 0.5 + 0.5;
}
