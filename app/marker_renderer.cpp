#include "marker_renderer.h"

#include <algorithm>
#include <cstdint>
// Generated from shaders/ by glslangValidator at build time.
#include "marker.frag.h"
#include "marker.vert.h"

namespace lloydscope {

Marker marker(const Vec3& at, float diameter, MarkerShape shape, uint32_t color) {
  return {{static_cast<float>(at.x()), static_cast<float>(at.y()), static_cast<float>(at.z())},
          diameter,
          static_cast<float>(shape),
          color};
}

MarkerRenderer::MarkerRenderer(gpu::Context& gpu, VkRenderPass renderPass, bool depthTest) : gpu_(gpu) {
  pipeline_ = gpu::createPipeline(gpu.device, renderPass,
                      {marker_vert, sizeof(marker_vert), marker_frag, sizeof(marker_frag),
                       {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Marker, position)},
                        {1, 0, VK_FORMAT_R32_SFLOAT, offsetof(Marker, diameter)},
                        {2, 0, VK_FORMAT_R32_SFLOAT, offsetof(Marker, shape)},
                        {3, 0, VK_FORMAT_R8G8B8A8_UNORM, offsetof(Marker, color)}},
                       sizeof(Marker), VK_PRIMITIVE_TOPOLOGY_POINT_LIST, depthTest,
                       sizeof(float) * 17});
}

MarkerRenderer::~MarkerRenderer() {
  vkDeviceWaitIdle(gpu_.device);
  gpu_.destroy(markers_);
  gpu_.destroy(pipeline_);
}

void MarkerRenderer::upload(const std::vector<Marker>& markers) {
  gpu::uploadVertices(gpu_, markers_, markers.data(), markers.size() * sizeof(Marker));
  count_ = static_cast<uint32_t>(markers.size());
}

void MarkerRenderer::draw(VkCommandBuffer cmd, const float (&viewport)[4],
                          const std::array<float, 16>& transform, float scale) const {
  if (count_ == 0) return;
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_.pipeline);
  gpu::setViewport(cmd, viewport);
  // The diameters are in units of the layout: on a denser screen, as many pixels more.
  std::array<float, 17> push;
  std::copy(transform.begin(), transform.end(), push.begin());
  push[16] = gpu::pixelsPerUnit() * scale;
  vkCmdPushConstants(cmd, pipeline_.layout, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                     sizeof(push), push.data());
  const VkDeviceSize offset = 0;
  vkCmdBindVertexBuffers(cmd, 0, 1, &markers_.buffer, &offset);
  vkCmdDraw(cmd, count_, 1, 0, 0);
}

}  // namespace lloydscope
