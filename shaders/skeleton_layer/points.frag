// The flow topology layer, critical points: the type's shape (a signed distance, in half
// glyph sizes) filled with its colour inside a dark outline, anti-aliased.
uniform vec3 typeColour[6];  // SkeletonLayer's table, by skeleton::PointType
uniform int typeShape[6];    // 0 disc, 1 square, 2 cross, 3 ring, 4 triangle up, 5 triangle down
uniform float sizePx;
flat in vec2 centrePx;
flat in int type;
out vec4 outColor;

float triangle(vec2 p, float r) {
    const float k = 1.7320508;
    p.x = abs(p.x) - r;
    p.y = p.y + r / k;
    if (p.x + k * p.y > 0.0) p = vec2(p.x - k * p.y, -k * p.x - p.y) / 2.0;
    p.x -= clamp(p.x, -2.0 * r, 0.0);
    return -length(p) * sign(p.y);
}

float shapeDistance(int shape, vec2 q) {
    if (shape == 0) return length(q) - 0.8;
    if (shape == 1) { vec2 d = abs(q) - vec2(0.68); return length(max(d, 0.0)) + min(max(d.x, d.y), 0.0); }
    if (shape == 2) {
        vec2 r = abs(vec2(q.x + q.y, q.x - q.y) * 0.70710678);
        return min(max(r.x - 0.95, r.y - 0.24), max(r.y - 0.95, r.x - 0.24));
    }
    if (shape == 3) return abs(length(q) - 0.66) - 0.2;
    if (shape == 4) return triangle(q + vec2(0.0, 0.12), 0.8);
    return triangle(vec2(q.x, -q.y) + vec2(0.0, 0.12), 0.8);
}

void main() {
    float half_ = 0.5 * sizePx;
    float d = shapeDistance(typeShape[type], (gl_FragCoord.xy - centrePx) / half_) * half_;  // px
    const float outline = 1.5;
    float cover = clamp(outline + 0.5 - d, 0.0, 1.0);
    if (cover <= 0.0) discard;
    outColor = vec4(mix(vec3(0.04), typeColour[type], clamp(0.5 - d, 0.0, 1.0)), cover);
}
