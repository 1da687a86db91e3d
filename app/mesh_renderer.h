// Draws a triangle mesh, shaded with a one-pass wireframe, inside an ImGui pane: an ImDrawList
// callback binds this pipeline with the pane's viewport (ImGui 1.86's Vulkan backend cannot
// show a texture of ours).
#pragma once

#include "gpu.h"
#include "marker_renderer.h"
#include "mesh.h"

#include <array>
#include <vector>

namespace lloydscope {

struct MeshDraw {
  std::array<float, 16> viewProjection;  // column-major, Vulkan clip space
  float viewport[4];                     // x, y, width, height in units of the layout
  bool wireframe = true;
  float wireWidth = 1.2f;                // units of the layout
  // How much larger than their size the markers are drawn; their depth is nudged towards the
  // eye as much more, or a large dot on a slope sinks half into the surface (a point sprite has
  // its centre's depth throughout).
  float markerScale = 1.0f;
  VkClearColorValue background = {{0.93f, 0.94f, 0.96f, 1.0f}};  // the pane is cleared to it
};

class MeshRenderer {
 public:
  MeshRenderer(gpu::Context& gpu, VkRenderPass renderPass);
  ~MeshRenderer();

  // One colour per triangle (linear RGB, 0..1).
  // Each point p goes to the GPU as (p - origin) / scale, in single precision: near the origin
  // and of size 1 (a mesh 1e8 units off the origin was a line of dots, one of size 1e19 nothing).
  void upload(const Mesh& mesh, const std::vector<std::array<float, 3>>& colors, const Vec3& origin, double scale);
  // Marks on the surface (the lifted sites), drawn over the mesh where they are in sight (sites
  // on the far side showed through it: a ring of dots across the mushroom's cap).
  void uploadMarkers(const std::vector<Marker>& markers) { markers_.upload(markers); }
  void draw(VkCommandBuffer cmd, const MeshDraw& draw) const;

 private:
  gpu::Context& gpu_;
  gpu::Pipeline pipeline_;
  gpu::Buffer vertices_;
  uint32_t vertexCount_ = 0;
  MarkerRenderer markers_;
};

}  // namespace lloydscope
