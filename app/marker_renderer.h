// Many small marks of a fixed size on screen (the sites and centroids of the 2D pane, the
// lifted sites of the 3D view), drawn as point sprites: one primitive per mark, where lavapipe's
// cost is per primitive.
#pragma once

#include "gpu.h"
#include "mesh.h"

#include <array>
#include <cstdint>
#include <vector>

namespace lloydscope {

enum class MarkerShape { Dot, Ring, Square };

struct Marker {
  float position[3];
  float diameter;  // units of the layout (pixels at ImGui's usual scale)
  float shape;     // MarkerShape, as the shader reads it
  uint32_t color;  // RGBA8, as ImGui's IM_COL32
};

Marker marker(const Vec3& at, float diameter, MarkerShape shape, uint32_t color);

class MarkerRenderer {
 public:
  // `depthTest`: marks behind what was drawn before them are hidden (the 3D view's, behind the
  // surface); without it every mark shows (the 2D pane's).
  MarkerRenderer(gpu::Context& gpu, VkRenderPass renderPass, bool depthTest);
  ~MarkerRenderer();
  MarkerRenderer(const MarkerRenderer&) = delete;
  MarkerRenderer& operator=(const MarkerRenderer&) = delete;

  void upload(const std::vector<Marker>& markers);
  // `transform` (column-major) takes positions to clip space; the viewport is the pane. Each
  // marker is drawn `scale` times its size (presentation mode's marks, which grow with its type).
  void draw(VkCommandBuffer cmd, const float (&viewport)[4],
            const std::array<float, 16>& transform, float scale = 1.0f) const;

 private:
  gpu::Context& gpu_;
  gpu::Pipeline pipeline_;
  gpu::Buffer markers_;
  uint32_t count_ = 0;
};

}  // namespace lloydscope
