#version 450
// The 3D view's triangles, de-indexed so that each corner carries its barycentric coordinate:
// the fragment shader draws the wireframe in the same pass (2-3x cheaper than a LINE pass on
// lavapipe, see shared notes).
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec3 inBarycentric;
layout(location = 3) in vec3 inColor;

layout(push_constant) uniform Push {
  mat4 viewProjection;
  vec4 options;  // x: wireframe on (1) or off (0), y: wire width in pixels
} push;

layout(location = 0) out vec3 normal;
layout(location = 1) out vec3 barycentric;
layout(location = 2) out vec3 color;

void main() {
  gl_Position = push.viewProjection * vec4(inPosition, 1.0);
  normal = inNormal;
  barycentric = inBarycentric;
  color = inColor;
}
