// ParaView plugin: the method's image into ParaView's framebuffer by depth
// (src/paraview/representation/vtkFlowSurfMapper.cxx). Drawn over the renderer's
// viewport with depth test LEQUAL against ParaView's depth, so what lies in front of the
// surface keeps its colour. Blend overlay: multiplied onto ParaView's colour of the
// surface; the other overlays replace it. ParaView's colour is either already in the
// framebuffer (its own surface pass; the blend state multiplies) or, with HOST_LOOK,
// computed here from the method's G-buffer as ParaView's mapper would (host_look.h): a
// solid colour or the colour value through its lookup table, ambient + diffuse under its
// directional lights, two-sided; the surface is then rasterised once per frame.
layout(binding = COMPOSITE_COLOR_UNIT) uniform sampler2D uImage;  // the method's composite, RGBA8
layout(binding = COMPOSITE_DEPTH_UNIT) uniform sampler2D uDepth;  // the method's surface depth, 1 = background
uniform ivec2 uOrigin;                         // the viewport's lower-left pixel
uniform float uDepthBias;                      // window depth: rounding between VTK's and our matrices
out vec4 outColor;
#ifdef HOST_LOOK
layout(binding = COMPOSITE_SHADE_UNIT) uniform sampler2D uShade;  // xyz: eye-space normal, w: colour value 0..1 over uValueRange
layout(binding = COMPOSITE_TABLE_UNIT) uniform sampler2D uTable;  // 256 x 1 lookup table colours over uTableRange
uniform int uMultiply;          // blend overlay: image x ParaView's colour; else the image
uniform int uScalars;           // 0: uSolid
uniform vec2 uValueRange, uTableRange;
uniform vec3 uSolid, uNanColor;
uniform int uLighting;
uniform float uAmbient, uDiffuse;
uniform int uLightCount;
uniform vec3 uLightDir[MAX_LIGHTS];    // eye space, the direction the light travels
uniform vec3 uLightColor[MAX_LIGHTS];  // colour x intensity

vec3 hostColor(ivec2 px) {
    vec4 shade = texelFetch(uShade, px, 0);
    vec3 c = uSolid;
    if (uScalars != 0) {
        if (isnan(shade.w)) {
            c = uNanColor;
        } else {
            float v = mix(uValueRange.x, uValueRange.y, shade.w);
            float span = uTableRange.y - uTableRange.x;
            float t = clamp(span > 0.0 ? (v - uTableRange.x) / span : 0.0, 0.0, 1.0);
            c = texture(uTable, vec2(t * (255.0 / 256.0) + 0.5 / 256.0, 0.5)).rgb;
        }
    }
    if (uLighting == 0) return c * (uAmbient + uDiffuse);
    vec3 n = normalize(shade.xyz);
    if (n.z < 0.0) n = -n;  // two-sided: the side facing the eye
    vec3 light = vec3(0.0);
    for (int i = 0; i < uLightCount; ++i) light += max(dot(n, -uLightDir[i]), 0.0) * uLightColor[i];
    return c * uAmbient + c * uDiffuse * light;
}
#endif

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy) - uOrigin;
    float depth = texelFetch(uDepth, px, 0).r;
    if (depth >= 1.0) discard;
    vec3 image = texelFetch(uImage, px, 0).rgb;
#ifdef HOST_LOOK
    if (uMultiply != 0) image *= hostColor(px);
#endif
    outColor = vec4(clamp(image, 0.0, 1.0), 1.0);
    gl_FragDepth = max(depth - uDepthBias, 0.0);
}
