#version 450
layout(location = 0) in vec3 normal;
layout(location = 1) in vec3 barycentric;
layout(location = 2) in vec3 color;

layout(push_constant) uniform Push {
  mat4 viewProjection;
  vec4 options;
} push;

layout(location = 0) out vec4 outColor;

void main() {
  // Two-sided headlight-ish shading: a surface patch may be seen from either side.
  float shade = 0.35 + 0.65 * abs(dot(normalize(normal), normalize(vec3(0.3, 0.5, 0.8))));
  vec3 c = color * shade;
  if (push.options.x > 0.5) {
    vec3 perPixel = fwidth(barycentric);
    vec3 width = perPixel * push.options.y;
    vec3 edge = smoothstep(vec3(0.0), width, barycentric);
    // Triangles a few pixels across would be all wire (a dense input was a black silhouette):
    // the wire fades from a triangle 7 pixels high down to 3.
    float pixelsAcross = 1.0 / max(max(perPixel.x, perPixel.y), max(perPixel.z, 1e-6));
    float wire = smoothstep(3.0, 7.0, pixelsAcross);
    c = mix(vec3(0.08, 0.08, 0.1), c, mix(1.0, min(min(edge.x, edge.y), edge.z), wire));
  }
  outColor = vec4(c, 1.0);
}
