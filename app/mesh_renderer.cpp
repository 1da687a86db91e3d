#include "mesh_renderer.h"

#include <cstdint>
// Generated from shaders/ by glslangValidator at build time.
#include "mesh.frag.h"
#include "mesh.vert.h"

#include <cstring>

namespace lloydscope {

namespace {

struct Vertex {
  float position[3], normal[3], barycentric[3], color[3];
};

struct Push {
  float viewProjection[16];
  float options[4];
};

}  // namespace

MeshRenderer::MeshRenderer(gpu::Context& gpu, VkRenderPass renderPass)
    : gpu_(gpu), markers_(gpu, renderPass, true) {
  pipeline_ = gpu::createPipeline(
      gpu.device, renderPass,
      {mesh_vert, sizeof(mesh_vert), mesh_frag, sizeof(mesh_frag),
       {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, position)},
        {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, normal)},
        {2, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, barycentric)},
        {3, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, color)}},
       sizeof(Vertex), VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST, true, sizeof(Push)});
}

MeshRenderer::~MeshRenderer() {
  vkDeviceWaitIdle(gpu_.device);
  gpu_.destroy(vertices_);
  gpu_.destroy(pipeline_);
}

void MeshRenderer::upload(const Mesh& mesh, const std::vector<std::array<float, 3>>& colors, const Vec3& origin,
                          double scale) {
  std::vector<Vertex> vertices;
  vertices.reserve(3 * mesh.triangles.size());
  for (size_t f = 0; f < mesh.triangles.size(); ++f) {
    const Triangle& t = mesh.triangles[f];
    const Vec3 n = (mesh.points[t[1]] - mesh.points[t[0]])
                       .cross(mesh.points[t[2]] - mesh.points[t[0]])
                       .normalized();
    for (int k = 0; k < 3; ++k) {
      const Vec3 p = (mesh.points[t[k]] - origin) / scale;
      Vertex v{};
      for (int i = 0; i < 3; ++i) {
        v.position[i] = static_cast<float>(p[i]);
        v.normal[i] = static_cast<float>(n[i]);
        v.barycentric[i] = i == k ? 1.0f : 0.0f;
        v.color[i] = colors.empty() ? 0.8f : colors[f][i];
      }
      vertices.push_back(v);
    }
  }
  gpu::uploadVertices(gpu_, vertices_, vertices.data(), vertices.size() * sizeof(Vertex));
  vertexCount_ = static_cast<uint32_t>(vertices.size());
}

namespace {

// `viewProjection` with every depth a little nearer the eye: the sites lie on the surface, and
// a site's mark must pass the depth test against its own triangles (a point sprite takes its
// centre's depth throughout) but not against the surface in front of it. Depth is 0..1 with
// the near plane at a hundredth of the camera's distance (OrbitCamera): 2.5e-5 there is about
// 0.25% of that distance. (It was 5e-5 of a depth the projection made as OpenGL's, -1..1,
// GLM's default, which the same nudge halves.)
std::array<float, 16> nudgedTowardsTheEye(std::array<float, 16> viewProjection, float markerScale) {
  const float nudge = 2.5e-5f * markerScale;
  for (int column = 0; column < 4; ++column)  // z' = z - nudge w, column-major
    viewProjection[4 * column + 2] -= nudge * viewProjection[4 * column + 3];
  return viewProjection;
}

}  // namespace

void MeshRenderer::draw(VkCommandBuffer cmd, const MeshDraw& d) const {
  // The pane's background and a clean depth buffer: clears, cheaper than drawing a rectangle.
  VkClearAttachment clear[2] = {{VK_IMAGE_ASPECT_COLOR_BIT, 0, {}}, {VK_IMAGE_ASPECT_DEPTH_BIT, 1, {}}};
  clear[0].clearValue.color = d.background;
  clear[1].clearValue.depthStencil = {1.0f, 0};
  gpu::clearRect(cmd, clear, d.viewport);
  if (vertexCount_ == 0) return;
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_.pipeline);
  gpu::setViewport(cmd, d.viewport);
  Push push{};
  std::memcpy(push.viewProjection, d.viewProjection.data(), sizeof(push.viewProjection));
  push.options[0] = d.wireframe ? 1.0f : 0.0f;
  push.options[1] = d.wireWidth * gpu::pixelsPerUnit();
  vkCmdPushConstants(cmd, pipeline_.layout, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                     sizeof(Push), &push);
  const VkDeviceSize offset = 0;
  vkCmdBindVertexBuffers(cmd, 0, 1, &vertices_.buffer, &offset);
  vkCmdDraw(cmd, vertexCount_, 1, 0, 0);
  markers_.draw(cmd, d.viewport, nudgedTowardsTheEye(d.viewProjection, d.markerScale), d.markerScale);
}

}  // namespace lloydscope
