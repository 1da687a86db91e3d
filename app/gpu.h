// The Vulkan device the inspector draws with: lavapipe (software) on machines without a GPU.
#pragma once

#include <vulkan/vulkan.h>

#include <algorithm>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace lloydscope::gpu {

struct GpuError : std::runtime_error {
  explicit GpuError(const std::string& what, bool outOfMemory = false)
      : std::runtime_error(what), outOfMemory(outOfMemory) {}
  bool outOfMemory;  // the host's or the device's: a smaller picture may fit
};
inline void check(VkResult result, const char* what) {
  if (result == VK_SUCCESS) return;
  const bool outOfMemory = result == VK_ERROR_OUT_OF_HOST_MEMORY || result == VK_ERROR_OUT_OF_DEVICE_MEMORY;
  throw GpuError(std::string("Vulkan: ") + what + " failed" + (outOfMemory ? ": out of memory" : "") +
                     " (VkResult " + std::to_string(result) + ")",
                 outOfMemory);
}
// What vkAcquireNextImageKHR or vkQueuePresentKHR says of a window's swapchain: true where it
// no longer fits the window and is to be made again (out of date; or suboptimal, which still
// shows the frame), false where it fits. Any other failure (the surface or the device lost)
// throws: ignored, it left the next frame waiting on a semaphore that nothing would signal.
inline bool swapchainOutOfDate(VkResult result, const char* what) {
  if (result == VK_ERROR_OUT_OF_DATE_KHR || result == VK_SUBOPTIMAL_KHR) return true;
  check(result, what);
  return false;
}

struct Buffer {
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkDeviceSize size = 0;
  void* mapped = nullptr;  // host-visible buffers stay mapped
};

// A pipeline and its layout (push constants only), made and destroyed together.
struct Pipeline {
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkPipeline pipeline = VK_NULL_HANDLE;
};

struct Image {
  VkImage image = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkImageView view = VK_NULL_HANDLE;
};

class Context {
 public:
  // instanceExtensions: what a window surface needs (none when headless). With `validation`,
  // the Khronos validation layer is enabled and every message it reports is counted and printed.
  Context(const std::vector<const char*>& instanceExtensions, bool swapchain, bool validation);
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  VkInstance instance = VK_NULL_HANDLE;
  VkPhysicalDevice physical = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  uint32_t queueFamily = 0;
  VkQueue queue = VK_NULL_HANDLE;
  VkCommandPool commandPool = VK_NULL_HANDLE;
  VkDescriptorPool descriptorPool = VK_NULL_HANDLE;  // for ImGui's font texture
  bool wideLines = false;  // line widths other than 1 (lavapipe has them)
  int validationMessages = 0;

  Buffer createBuffer(VkDeviceSize size, VkBufferUsageFlags usage);  // host-visible, mapped
  void destroy(Buffer& buffer);
  void destroy(Pipeline& pipeline);
  Image createImage(uint32_t width, uint32_t height, VkFormat format, VkImageUsageFlags usage,
                    VkImageAspectFlags aspect);
  void destroy(Image& image);
  // Records commands into a fresh command buffer, submits them and waits.
  void submitNow(const std::function<void(VkCommandBuffer)>& record);
  // The same without waiting: the CPU can go on while lavapipe renders. The next submit, or
  // waitSubmitted(), waits for it first.
  void submit(const std::function<void(VkCommandBuffer)>& record);
  void waitSubmitted();

 private:
  VkDeviceMemory allocate(const VkMemoryRequirements& req, VkMemoryPropertyFlags properties);
  uint32_t memoryType(uint32_t bits, VkMemoryPropertyFlags properties) const;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  VkFence submitted_ = VK_NULL_HANDLE;
  VkCommandBuffer submittedCommands_ = VK_NULL_HANDLE;  // until its fence signals
};

// What differs between the inspector's pipelines; everything else (dynamic viewport and
// scissor, no culling, one colour attachment, alpha blending) is shared.
struct PipelineDescription {
  const uint32_t* vertexCode;
  size_t vertexBytes;
  const uint32_t* fragmentCode;
  size_t fragmentBytes;
  std::vector<VkVertexInputAttributeDescription> attributes;  // all in binding 0
  uint32_t stride;
  VkPrimitiveTopology topology;
  bool depthTest;
  uint32_t pushConstantBytes;  // visible to both stages
};
// Creates the layout (push constants only) and the pipeline.
Pipeline createPipeline(VkDevice device, VkRenderPass renderPass, const PipelineDescription& d);

// Dear ImGui's Vulkan backend on this device and render pass, fonts uploaded (the ImGui
// context must exist).
void initImGuiRenderer(Context& gpu, VkRenderPass renderPass, uint32_t imageCount);

// Copies `bytes` into `buffer` (a host-visible vertex buffer), growing it when needed.
void uploadVertices(Context& gpu, Buffer& buffer, const void* data, size_t bytes);
// The render pass's area, which a pane's scissor and clear must lie in: set as each frame's
// pass begins. A pane beyond it (a window shrunk to 200x150 in a lesson, whose panes were laid
// out below its foot) was cleared outside the framebuffer, and lavapipe crashed.
// `pixelsPerUnit`: framebuffer pixels per unit of ImGui's layout (ImGuiIO's
// DisplayFramebufferScale, 2 on a screen of twice the usual density): the panes are laid out in
// units, and the functions below take their rectangles in units.
void setRenderArea(VkExtent2D extent, float pixelsPerUnit);
// The frame's pixels per unit of layout (setRenderArea): what sizes given in pixels (a dot's
// diameter, a wire's width) are multiplied by to look the same on a denser screen.
float pixelsPerUnit();
// `rect` (x, y, width, height in framebuffer pixels) within `area`; empty (zero extent)
// where they do not meet.
inline VkRect2D clipped(const float (&rect)[4], VkExtent2D area) {
  const double x0 = std::clamp<double>(rect[0], 0, area.width), y0 = std::clamp<double>(rect[1], 0, area.height);
  const double x1 = std::clamp<double>(double(rect[0]) + rect[2], x0, area.width),
               y1 = std::clamp<double>(double(rect[1]) + rect[3], y0, area.height);
  return {{static_cast<int32_t>(x0), static_cast<int32_t>(y0)},
          {static_cast<uint32_t>(x1) - static_cast<uint32_t>(x0), static_cast<uint32_t>(y1) - static_cast<uint32_t>(y0)}};
}
// The same within the render area.
VkRect2D withinRenderArea(const float (&rect)[4]);
// Viewport and scissor to a pane: x, y, width, height in units of the layout. The viewport may
// reach past the framebuffer (a pane cut by the window's edge); the scissor does not.
void setViewport(VkCommandBuffer cmd, const float (&rect)[4]);
// Clears a pane (in a render pass) to the given values: colour, depth or both; the part of it
// in the render area.
template <size_t N>
void clearRect(VkCommandBuffer cmd, const VkClearAttachment (&clears)[N], const float (&rect)[4]) {
  const VkClearRect area{withinRenderArea(rect), 0, 1};
  if (area.rect.extent.width > 0 && area.rect.extent.height > 0) vkCmdClearAttachments(cmd, N, clears, 1, &area);
}

// A render pass with one colour and one depth attachment; the colour ends in `finalLayout`
// (TRANSFER_SRC to read it back, PRESENT_SRC for a swapchain).
VkRenderPass createRenderPass(VkDevice device, VkFormat color, VkImageLayout finalLayout);
constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

}  // namespace lloydscope::gpu
