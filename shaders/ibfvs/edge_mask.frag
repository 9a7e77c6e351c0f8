// Background-coloured with high opacity over the composite: dims silhouettes.
uniform vec4 uColor;
out vec4 outColor;
void main() { outColor = uColor; }
