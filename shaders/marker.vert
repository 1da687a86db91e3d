#version 450
// Dots, rings and squares of a fixed size on screen, one point sprite each: lavapipe pays per
// primitive, and a point is one where a hexagon was six.
layout(location = 0) in vec3 inPosition;
layout(location = 1) in float inDiameter;  // units of the layout
layout(location = 2) in float inShape;     // 0 dot, 1 ring, 2 square
layout(location = 3) in vec4 inColor;

layout(push_constant) uniform Push {
  mat4 transform;  // to clip space
  float pixelsPerUnit;  // framebuffer pixels per unit of the layout (2 on a screen twice as dense)
} push;

layout(location = 0) out vec4 color;
layout(location = 1) flat out float shape;
layout(location = 2) flat out float diameter;

void main() {
  gl_Position = push.transform * vec4(inPosition, 1.0);
  diameter = inDiameter * push.pixelsPerUnit;
  gl_PointSize = diameter;
  color = inColor;
  shape = inShape;
}
