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

VkShaderModule shaderModule(VkDevice device, const uint32_t* code, size_t bytes) {
  VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  info.codeSize = bytes;
  info.pCode = code;
  VkShaderModule module;
  gpu::check(vkCreateShaderModule(device, &info, nullptr, &module), "creating a shader module");
  return module;
}

}  // namespace

MeshRenderer::MeshRenderer(gpu::Context& gpu, VkRenderPass renderPass) : gpu_(gpu) {
  VkPushConstantRange range{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                            sizeof(Push)};
  VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layoutInfo.pushConstantRangeCount = 1;
  layoutInfo.pPushConstantRanges = &range;
  gpu::check(vkCreatePipelineLayout(gpu.device, &layoutInfo, nullptr, &layout_),
             "creating the mesh pipeline layout");

  const VkShaderModule vert = shaderModule(gpu.device, mesh_vert, sizeof(mesh_vert));
  const VkShaderModule frag = shaderModule(gpu.device, mesh_frag, sizeof(mesh_frag));
  VkPipelineShaderStageCreateInfo stages[2] = {};
  stages[0] = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO, nullptr, 0,
               VK_SHADER_STAGE_VERTEX_BIT, vert, "main", nullptr};
  stages[1] = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO, nullptr, 0,
               VK_SHADER_STAGE_FRAGMENT_BIT, frag, "main", nullptr};

  VkVertexInputBindingDescription binding{0, sizeof(Vertex), VK_VERTEX_INPUT_RATE_VERTEX};
  VkVertexInputAttributeDescription attributes[4] = {
      {0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, position)},
      {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, normal)},
      {2, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, barycentric)},
      {3, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, color)}};
  VkPipelineVertexInputStateCreateInfo input{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  input.vertexBindingDescriptionCount = 1;
  input.pVertexBindingDescriptions = &binding;
  input.vertexAttributeDescriptionCount = 4;
  input.pVertexAttributeDescriptions = attributes;
  VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
  assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
  viewport.viewportCount = 1;
  viewport.scissorCount = 1;
  VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  raster.cullMode = VK_CULL_MODE_NONE;
  raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  raster.lineWidth = 1.0f;
  VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
  VkPipelineDepthStencilStateCreateInfo depth{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  depth.depthTestEnable = VK_TRUE;
  depth.depthWriteEnable = VK_TRUE;
  depth.depthCompareOp = VK_COMPARE_OP_LESS;
  VkPipelineColorBlendAttachmentState blendAttachment{};
  blendAttachment.colorWriteMask = 0xF;
  VkPipelineColorBlendStateCreateInfo blend{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
  blend.attachmentCount = 1;
  blend.pAttachments = &blendAttachment;
  const VkDynamicState dynamicStates[2] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
  VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
  dynamic.dynamicStateCount = 2;
  dynamic.pDynamicStates = dynamicStates;

  VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
  info.stageCount = 2;
  info.pStages = stages;
  info.pVertexInputState = &input;
  info.pInputAssemblyState = &assembly;
  info.pViewportState = &viewport;
  info.pRasterizationState = &raster;
  info.pMultisampleState = &multisample;
  info.pDepthStencilState = &depth;
  info.pColorBlendState = &blend;
  info.pDynamicState = &dynamic;
  info.layout = layout_;
  info.renderPass = renderPass;
  gpu::check(vkCreateGraphicsPipelines(gpu.device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline_),
             "creating the mesh pipeline");
  vkDestroyShaderModule(gpu.device, vert, nullptr);
  vkDestroyShaderModule(gpu.device, frag, nullptr);
}

MeshRenderer::~MeshRenderer() {
  vkDeviceWaitIdle(gpu_.device);
  gpu_.destroy(vertices_);
  vkDestroyPipeline(gpu_.device, pipeline_, nullptr);
  vkDestroyPipelineLayout(gpu_.device, layout_, nullptr);
}

void MeshRenderer::upload(const Mesh& mesh, const std::vector<std::array<float, 3>>& colors) {
  std::vector<Vertex> vertices;
  vertices.reserve(3 * mesh.triangles.size());
  for (size_t f = 0; f < mesh.triangles.size(); ++f) {
    const Triangle& t = mesh.triangles[f];
    const Vec3 n = (mesh.points[t[1]] - mesh.points[t[0]])
                       .cross(mesh.points[t[2]] - mesh.points[t[0]])
                       .normalized();
    for (int k = 0; k < 3; ++k) {
      const Vec3& p = mesh.points[t[k]];
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
  const VkDeviceSize bytes = std::max<VkDeviceSize>(sizeof(Vertex), vertices.size() * sizeof(Vertex));
  if (vertices_.size < bytes) {
    vkDeviceWaitIdle(gpu_.device);  // the old buffer may still be in use by a frame
    gpu_.destroy(vertices_);
    vertices_ = gpu_.createBuffer(bytes, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
  }
  std::memcpy(vertices_.mapped, vertices.data(), vertices.size() * sizeof(Vertex));
  vertexCount_ = static_cast<uint32_t>(vertices.size());
}

void MeshRenderer::draw(VkCommandBuffer cmd, const MeshDraw& d) const {
  if (vertexCount_ == 0) return;
  const VkViewport viewport{d.viewport[0], d.viewport[1], d.viewport[2], d.viewport[3], 0.0f, 1.0f};
  const VkRect2D scissor{{static_cast<int32_t>(d.viewport[0]), static_cast<int32_t>(d.viewport[1])},
                         {static_cast<uint32_t>(d.viewport[2]), static_cast<uint32_t>(d.viewport[3])}};
  // A clean depth buffer for this pane only.
  VkClearAttachment clear{VK_IMAGE_ASPECT_DEPTH_BIT, 1, {}};
  clear.clearValue.depthStencil = {1.0f, 0};
  const VkClearRect rect{scissor, 0, 1};
  vkCmdClearAttachments(cmd, 1, &clear, 1, &rect);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
  Push push{};
  std::memcpy(push.viewProjection, d.viewProjection.data(), sizeof(push.viewProjection));
  push.options[0] = d.wireframe ? 1.0f : 0.0f;
  push.options[1] = d.wireWidth;
  vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                     sizeof(Push), &push);
  const VkDeviceSize offset = 0;
  vkCmdBindVertexBuffers(cmd, 0, 1, &vertices_.buffer, &offset);
  vkCmdDraw(cmd, vertexCount_, 1, 0, 0);
}

}  // namespace lloydscope
