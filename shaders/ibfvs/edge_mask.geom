// Keeps boundary edges (both opposite vertices equal: one triangle) and edges between a
// front- and a back-facing triangle; expands each kept edge to a quad `uWidthPx` wide.
// uCapture: also writes each quad's four corners (clip space) to the capture buffer, for the
// other processes of a parallel render (ibfvs/edge_mask.h).
layout(lines_adjacency) in;
layout(triangle_strip, max_vertices = 4) out;
uniform vec2 uViewport;
uniform float uWidthPx;
uniform int uCapture;
uniform uint uCapacity;  // quads the capture buffer holds
layout(std430, binding = EDGE_CAPTURE_BINDING) buffer Captured {
    uint capturedCount;  // quads written (may exceed uCapacity: then the buffer grows)
    uint capturedPad[3];
    vec4 captured[];     // 4 corners per quad, in strip order
};
vec2 toPx(vec4 c) { return (c.xy / c.w * 0.5 + 0.5) * uViewport; }
float signedArea(vec2 a, vec2 b, vec2 c) { return (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y); }
void main() {
    vec4 c0 = gl_in[0].gl_Position, c1 = gl_in[1].gl_Position;
    vec4 ca = gl_in[2].gl_Position, cb = gl_in[3].gl_Position;
    if (c0.w <= 0.0 || c1.w <= 0.0 || ca.w <= 0.0 || cb.w <= 0.0) return;
    vec2 p0 = toPx(c0), p1 = toPx(c1), pa = toPx(ca), pb = toPx(cb);
    bool boundary = ca == cb;
    // Triangle A is (v0, v1, a) and B is (v1, v0, b) in consistent winding.
    bool frontA = signedArea(p0, p1, pa) > 0.0;
    bool frontB = signedArea(p1, p0, pb) > 0.0;
    if (!boundary && frontA == frontB) return;
    vec2 d = p1 - p0;
    if (dot(d, d) < 1e-12) return;
    vec2 n = normalize(vec2(-d.y, d.x)) * (0.5 * uWidthPx) / uViewport * 2.0;  // in NDC
    vec2 n0 = n * c0.w, n1 = n * c1.w;
    vec4 q[4] = vec4[4](c0 + vec4(n0, 0.0, 0.0), c0 - vec4(n0, 0.0, 0.0), c1 + vec4(n1, 0.0, 0.0),
                        c1 - vec4(n1, 0.0, 0.0));
    if (uCapture != 0) {
        uint i = atomicAdd(capturedCount, 1u);
        if (i < uCapacity)
            for (int k = 0; k < 4; ++k) captured[4u * i + uint(k)] = q[k];
    }
    for (int k = 0; k < 4; ++k) {
        gl_Position = q[k];
        EmitVertex();
    }
    EndPrimitive();
}
