#version 450
// The 2D pane's lines, dots and fills: positions in the parameter domain, plus an offset in
// pixels so that dots keep their size on screen whatever the zoom.
layout(location = 0) in vec2 inPosition;
layout(location = 1) in vec2 inPixelOffset;
layout(location = 2) in vec4 inColor;

layout(push_constant) uniform Push {
  vec4 transform;  // xy: scale, zw: offset, from the domain to clip space
  vec4 pixel;      // xy: clip-space size of one pixel
} push;

layout(location = 0) out vec4 color;

void main() {
  gl_Position = vec4(inPosition * push.transform.xy + push.transform.zw +
                     inPixelOffset * push.pixel.xy, 0.0, 1.0);
  color = inColor;
}
