#include "canvas_renderer.h"

#include <cstdint>
// Generated from shaders/ by glslangValidator at build time.
#include "canvas.frag.h"
#include "canvas.vert.h"

#include <array>
#include <tuple>

namespace lloydscope {

namespace {

struct Push {
  float transform[4];
  float pixel[4];
};

CanvasVertex vertex(const Vec2& p, float dx, float dy, uint32_t color) {
  return {{static_cast<float>(p.x()), static_cast<float>(p.y())}, {dx, dy}, color};
}

}  // namespace

void CanvasGeometry::line(const Vec2& a, const Vec2& b, uint32_t color) {
  lines.push_back(vertex(a, 0, 0, color));
  lines.push_back(vertex(b, 0, 0, color));
}

void CanvasGeometry::fill(const Vec2& a, const Vec2& b, const Vec2& c, uint32_t color) {
  fills.push_back(vertex(a, 0, 0, color));
  fills.push_back(vertex(b, 0, 0, color));
  fills.push_back(vertex(c, 0, 0, color));
}

void CanvasGeometry::markTriangle(const Vec2& at, const float (&o)[6], uint32_t color) {
  for (int k = 0; k < 3; ++k) marks.push_back(vertex(at, o[2 * k], o[2 * k + 1], color));
}

void CanvasGeometry::thickLine(const Vec2& a, const Vec2& b, float width, uint32_t color) {
  const Vec2 d = (b - a).normalized();  // v points up, screen y down
  const float ox = -0.5f * width * static_cast<float>(d.y()), oy = -0.5f * width * static_cast<float>(d.x());
  for (const auto& [p, sx, sy] : {std::tuple{a, ox, oy}, std::tuple{a, -ox, -oy}, std::tuple{b, ox, oy},
                                  std::tuple{b, ox, oy}, std::tuple{a, -ox, -oy}, std::tuple{b, -ox, -oy}})
    marks.push_back(vertex(p, sx, sy, color));
}

void CanvasGeometry::point(const Vec2& at, float radius, MarkerShape shape, uint32_t color) {
  points.push_back(marker(Vec3(at.x(), at.y(), 0.0), 2.0f * radius, shape, color));
}

CanvasRenderer::CanvasRenderer(gpu::Context& gpu, VkRenderPass renderPass)
    : gpu_(gpu), points_(gpu, renderPass, false) {
  const std::vector<VkVertexInputAttributeDescription> attributes = {
      {0, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(CanvasVertex, position)},
      {1, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(CanvasVertex, pixelOffset)},
      {2, 0, VK_FORMAT_R8G8B8A8_UNORM, offsetof(CanvasVertex, color)}};
  for (auto [topology, pipeline] :
       {std::pair{VK_PRIMITIVE_TOPOLOGY_LINE_LIST, &linePipeline_},
        std::pair{VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST, &trianglePipeline_}})
    *pipeline = gpu::createPipeline(gpu.device, renderPass,
                                    {canvas_vert, sizeof(canvas_vert), canvas_frag,
                                     sizeof(canvas_frag), attributes, sizeof(CanvasVertex),
                                     topology, false, sizeof(Push)});
}

CanvasRenderer::~CanvasRenderer() {
  vkDeviceWaitIdle(gpu_.device);
  for (gpu::Buffer* b : {&fills_, &lines_, &marks_}) gpu_.destroy(*b);
  for (gpu::Pipeline* p : {&linePipeline_, &trianglePipeline_}) gpu_.destroy(*p);
}

void CanvasRenderer::upload(const CanvasGeometry& g) {
  for (auto [buffer, count, vertices] :
       {std::tuple{&fills_, &fillCount_, &g.fills}, std::tuple{&lines_, &lineCount_, &g.lines},
        std::tuple{&marks_, &markCount_, &g.marks}}) {
    gpu::uploadVertices(gpu_, *buffer, vertices->data(), vertices->size() * sizeof(CanvasVertex));
    *count = static_cast<uint32_t>(vertices->size());
  }
  points_.upload(g.points);
}

void CanvasRenderer::draw(VkCommandBuffer cmd, const CanvasDraw& d) const {
  // Screen x = centerX + (u - 0.5) scale; clip = 2 (x - left) / width - 1. Likewise for y,
  // which points down on screen while v points up.
  const float w = d.viewport[2], h = d.viewport[3];
  Push push{};
  push.transform[0] = 2.0f * d.scale / w;
  push.transform[1] = -2.0f * d.scale / h;
  push.transform[2] = 2.0f * (d.centerX - 0.5f * d.scale - d.viewport[0]) / w - 1.0f;
  push.transform[3] = 2.0f * (d.centerY + 0.5f * d.scale - d.viewport[1]) / h - 1.0f;
  push.pixel[0] = 2.0f / w;
  push.pixel[1] = 2.0f / h;
  VkClearAttachment clear[1] = {{VK_IMAGE_ASPECT_COLOR_BIT, 0, {}}};
  clear[0].clearValue.color = d.background;
  gpu::clearRect(cmd, clear, d.viewport);
  gpu::setViewport(cmd, d.viewport);
  const VkDeviceSize offset = 0;
  for (auto [pipeline, buffer, count] :
       {std::tuple{&trianglePipeline_, fills_.buffer, fillCount_},
        std::tuple{&linePipeline_, lines_.buffer, lineCount_},
        std::tuple{&trianglePipeline_, marks_.buffer, markCount_}}) {
    if (count == 0) continue;
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline->pipeline);
    vkCmdPushConstants(cmd, pipeline->layout, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT,
                       0, sizeof(Push), &push);
    vkCmdBindVertexBuffers(cmd, 0, 1, &buffer, &offset);
    if (pipeline == &linePipeline_) vkCmdSetLineWidth(cmd, gpu_.wideLines ? d.lineWidth * gpu::pixelsPerUnit() : 1.0f);
    vkCmdDraw(cmd, count, 1, 0, 0);
  }
  // The same map as a matrix: clip = transform.xy * uv + transform.zw.
  const std::array<float, 16> transform = {push.transform[0], 0, 0, 0, 0, push.transform[1], 0, 0,
                                           0, 0, 1, 0, push.transform[2], push.transform[3], 0, 1};
  points_.draw(cmd, d.viewport, transform);
}

}  // namespace lloydscope
