// Draws the 2D pane's many lines, dots and cell fills with a pipeline of its own, from
// vertex buffers rebuilt only when the iteration or a display switch changes: thousands of
// ImDrawList primitives per frame were the inspector's largest cost on lavapipe.
#pragma once

#include "gpu.h"
#include "marker_renderer.h"
#include "mesh.h"

#include <cstdint>
#include <vector>

namespace lloydscope {

struct CanvasVertex {
  float position[2];     // in the parameter domain
  float pixelOffset[2];  // added on screen, in pixels
  uint32_t color;        // RGBA8, as ImGui's IM_COL32
};

// Geometry in the parameter domain, drawn in four layers: fills, then lines, then marks
// (arrow heads), then dots, rings and squares on top.
struct CanvasGeometry {
  std::vector<CanvasVertex> fills, lines, marks;
  std::vector<Marker> points;
  void line(const Vec2& a, const Vec2& b, uint32_t color);
  void fill(const Vec2& a, const Vec2& b, const Vec2& c, uint32_t color);
  // A mark at `at`: a triangle whose corners are offsets in pixels.
  void markTriangle(const Vec2& at, const float (&offsets)[6], uint32_t color);
  // A line `width` pixels wide, whatever the zoom (drawn with the marks).
  void thickLine(const Vec2& a, const Vec2& b, float width, uint32_t color);
  // Pixel-sized, whatever the zoom.
  void point(const Vec2& at, float radius, MarkerShape shape, uint32_t color);
};

struct CanvasDraw {
  float viewport[4];  // pane: x, y, width, height in units of the layout
  // Screen = centre + (uv - 0.5) * scale, v pointing up.
  float centerX, centerY, scale;
  VkClearColorValue background = {{1.0f, 1.0f, 1.0f, 1.0f}};  // the pane is cleared to it
  float lineWidth = 1.0f;  // units of the layout, where the device has wide lines
};

class CanvasRenderer {
 public:
  CanvasRenderer(gpu::Context& gpu, VkRenderPass renderPass);
  ~CanvasRenderer();
  void upload(const CanvasGeometry& geometry);
  void draw(VkCommandBuffer cmd, const CanvasDraw& draw) const;

 private:
  gpu::Context& gpu_;
  gpu::Pipeline linePipeline_, trianglePipeline_;
  gpu::Buffer fills_, lines_, marks_;
  MarkerRenderer points_;
  uint32_t fillCount_ = 0, lineCount_ = 0, markCount_ = 0;  // vertices
};

}  // namespace lloydscope
