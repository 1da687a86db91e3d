#version 450
layout(location = 0) in vec4 color;
layout(location = 1) flat in float shape;
layout(location = 2) flat in float diameter;
layout(location = 0) out vec4 outColor;

layout(push_constant) uniform Push {
  mat4 transform;
  float pixelsPerUnit;  // framebuffer pixels per unit of the layout
} push;

void main() {
  // Distance from the centre in framebuffer pixels; the edge is smoothed over one pixel.
  const float radius = 0.5 * diameter;
  const float r = length(gl_PointCoord - vec2(0.5)) * diameter;
  float coverage = 1.0;
  if (shape < 0.5) {
    coverage = clamp(radius - r, 0.0, 1.0);
  } else if (shape < 1.5) {
    coverage = clamp(radius - r, 0.0, 1.0) * clamp(r - (radius - 2.0 * push.pixelsPerUnit), 0.0, 1.0);  // 1.5 units wide
  }
  if (coverage <= 0.0) discard;
  outColor = vec4(color.rgb, color.a * coverage);
}
