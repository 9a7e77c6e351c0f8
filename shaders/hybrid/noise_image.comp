// Hybrid noise image: the solid noise N(r, t) [W §5] on the visible surface at twice the
// image resolution, so that the particle tracing reads the noise with one bilinear 2D
// lookup per step. Texel 2i+1 of a row sits on pixel i's centre (its seed position),
// texel 2i on the edge between pixels i-1 and i (the mean of their positions). One
// invocation per pixel writes the 2x2 texels whose odd corner is its centre, all four
// with the pixel's own octave mix (log2 is costly on a CPU rasteriser; the mix is
// continuous in the distance, and the four lie within a pixel).
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
layout(binding = 0) uniform sampler2D uPosObj;  // RGBA32F seed positions, w = coverage
layout(binding = 3) uniform sampler3D uNoise;   // solid noise, wrapped, trilinear
layout(binding = 0, r32f) writeonly uniform image2D uNoiseImage;  // 2W x 2H
uniform vec3 uEye;
uniform int uOrtho;
uniform float uFreqAtUnit;      // noise texels per P-space unit at distance 1 (ortho: absolute)
uniform vec4 uLayerDepthRow;    // layer depth of a P-space point (methods::layerDepthRow)
uniform float uDepthTolerance;  // fraction of the depth range
// A fixed oblique rotation of the lookup: flat data lying in an axis plane (a CFD slice)
// would otherwise sample the lattice along a texel plane and show its grid.
// 0.7 rad about (1, 2, 3), columns.
const mat3 kNoiseRotation = mat3(0.781639, 0.550117, -0.293958,
                                 -0.482929, 0.832030, 0.272956,
                                 0.394740, -0.071392, 0.916015);
// Constant image-space frequency [W §5]: two octave-snapped scales mixed by the fractional
// part f of log2 of the distance; x: the finer octave's frequency, y: f (orthographic
// views: one scale, f = 0).
vec2 octavesAt(vec3 posObj) {
    if (uOrtho != 0) return vec2(uFreqAtUnit, 0.0);
    float l = log2(max(length(posObj - uEye), 1e-6));
    return vec2(uFreqAtUnit * exp2(-floor(l)), fract(l));
}
float noiseAt(vec3 posObj, vec2 octaves) {
    vec3 q = kNoiseRotation * posObj * octaves.x;
    float fine = texture(uNoise, q).r;
    return octaves.y == 0.0 ? fine : mix(fine, texture(uNoise, 0.5 * q).r, octaves.y);
}
// The layer depth of a covered position; off the surface a depth no layer has.
float layerOf(vec4 p) { return p.w >= 0.5 ? dot(uLayerDepthRow, vec4(p.xyz, 1.0)) : 1e30; }
// The mean position of those of the covered neighbours a, b, c, d that lie on the nearest
// one's layer (a sample on an occluding edge takes the front side); w = 0: none covered.
vec4 meanPosition(vec4 a, vec4 b, vec4 c, vec4 d) {
    vec4 layer = vec4(layerOf(a), layerOf(b), layerOf(c), layerOf(d));
    float nearest = min(min(layer.x, layer.y), min(layer.z, layer.w));
    vec4 w = vec4(lessThanEqual(layer - nearest, vec4(uDepthTolerance))) * vec4(nearest < 1e30);
    float n = dot(w, vec4(1.0));
    return vec4((w.x * a.xyz + w.y * b.xyz + w.z * c.xyz + w.w * d.xyz) / max(n, 1.0), min(n, 1.0));
}
vec4 positionAt(ivec2 px) {
    return any(lessThan(px, ivec2(0))) ? vec4(0.0) : texelFetch(uPosObj, px, 0);
}
void main() {
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(px, textureSize(uPosObj, 0)))) return;
    vec4 own = positionAt(px);
    vec4 left = positionAt(px - ivec2(1, 0)), below = positionAt(px - ivec2(0, 1)),
         corner = positionAt(px - ivec2(1, 1));
    vec4 leftEdge = meanPosition(own, left, own, left), belowEdge = meanPosition(own, below, own, below),
         cornerMean = meanPosition(own, left, below, corner);
    ivec2 t = 2 * px;
    vec2 octaves = octavesAt(own.w >= 0.5 ? own.xyz : cornerMean.xyz);
    imageStore(uNoiseImage, t + ivec2(1, 1), vec4(own.w >= 0.5 ? noiseAt(own.xyz, octaves) : NOISE_MEAN));
    imageStore(uNoiseImage, t + ivec2(0, 1), vec4(leftEdge.w > 0.0 ? noiseAt(leftEdge.xyz, octaves) : NOISE_MEAN));
    imageStore(uNoiseImage, t + ivec2(1, 0), vec4(belowEdge.w > 0.0 ? noiseAt(belowEdge.xyz, octaves) : NOISE_MEAN));
    imageStore(uNoiseImage, t, vec4(cornerMean.w > 0.0 ? noiseAt(cornerMean.xyz, octaves) : NOISE_MEAN));
}
