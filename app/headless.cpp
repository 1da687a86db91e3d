#include "headless.h"

#include "text.h"
#include "gpu.h"
#include "inspector.h"
#include "png.h"
#include "report.h"
#include "stopwatch.h"

#include <backends/imgui_impl_vulkan.h>
#include <imgui.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>

namespace lloydscope {

namespace {

// An offscreen frame: colour and depth images, the render pass, ImGui on top, a read-back
// buffer for the pixels.
class OffscreenRenderer {
 public:
  // `pixelsPerUnit`: the inspector laid out in width x height over it (ImGuiIO's
  // DisplayFramebufferScale), as on a screen that many times as dense.
  OffscreenRenderer(int width, int height, bool validation, float pixelsPerUnit = 1.0f)
      : OffscreenRenderer(width, height, validation, Empty{}) {
    // Constructed by now (the constructor delegated to has returned): where what follows
    // throws (out of memory for a large picture), the destructor frees what was made.
    renderPass_ = gpu::createRenderPass(gpu_.device, VK_FORMAT_R8G8B8A8_UNORM,
                                        VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    color_ = gpu_.createImage(width, height, VK_FORMAT_R8G8B8A8_UNORM,
                              VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                              VK_IMAGE_ASPECT_COLOR_BIT);
    depth_ = gpu_.createImage(width, height, gpu::kDepthFormat,
                              VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, VK_IMAGE_ASPECT_DEPTH_BIT);
    const VkImageView views[2] = {color_.view, depth_.view};
    VkFramebufferCreateInfo fb{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    fb.renderPass = renderPass_;
    fb.attachmentCount = 2;
    fb.pAttachments = views;
    fb.width = width;
    fb.height = height;
    fb.layers = 1;
    gpu::check(vkCreateFramebuffer(gpu_.device, &fb, nullptr, &framebuffer_), "creating a framebuffer");
    pixels_ = gpu_.createBuffer(static_cast<VkDeviceSize>(width) * height * 4,
                                VK_BUFFER_USAGE_TRANSFER_DST_BIT);

    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // reproducible pictures: no saved layout
    io.DisplaySize = ImVec2(width / pixelsPerUnit, height / pixelsPerUnit);
    io.DisplayFramebufferScale = ImVec2(pixelsPerUnit, pixelsPerUnit);
    io.DeltaTime = 1.0f / 60.0f;
    ImGui::StyleColorsLight();
    addInspectorFonts(pixelsPerUnit);
    imguiRenderer_ = true;  // its font upload may fail after the backend started
    gpu::initImGuiRenderer(gpu_, renderPass_, 2);
  }

  ~OffscreenRenderer() {
    vkDeviceWaitIdle(gpu_.device);
    if (imguiRenderer_) ImGui_ImplVulkan_Shutdown();
    if (ImGui::GetCurrentContext()) ImGui::DestroyContext();
    gpu_.destroy(pixels_);
    vkDestroyFramebuffer(gpu_.device, framebuffer_, nullptr);
    gpu_.destroy(depth_);
    gpu_.destroy(color_);
    vkDestroyRenderPass(gpu_.device, renderPass_, nullptr);
  }

  gpu::Context& gpu() { return gpu_; }
  VkRenderPass renderPass() const { return renderPass_; }

  // One frame of `build`, rendered and (with readBack) copied to the pixel buffer. Without
  // readBack it returns while the frame renders; the next frame waits for it.
  void frame(const std::function<void()>& build, bool readBack) {
    gpu_.waitSubmitted();  // the frame before may still read buffers that build() refills
    ImGui_ImplVulkan_NewFrame();
    ImGui::NewFrame();
    build();
    ImGui::Render();
    gpu_.submit([&](VkCommandBuffer cmd) {
      Inspector::recordFrame(cmd, renderPass_, framebuffer_,
                             {static_cast<uint32_t>(width_), static_cast<uint32_t>(height_)});
      if (readBack) {
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {static_cast<uint32_t>(width_), static_cast<uint32_t>(height_), 1};
        vkCmdCopyImageToBuffer(cmd, color_.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                               pixels_.buffer, 1, &region);
      }
    });
    if (readBack) gpu_.waitSubmitted();
  }

  // The part `crop` of the last frame read back, as a PNG file for `path`.
  std::vector<unsigned char> encodePng(const std::string& path, const PixelRect& crop) const {
    return lloydscope::encodePng(path, static_cast<const unsigned char*>(pixels_.mapped), width_, height_, false, crop);
  }

  void finish() { gpu_.waitSubmitted(); }
  int validationMessages() const { return gpu_.validationMessages; }

 private:
  struct Empty {};
  OffscreenRenderer(int width, int height, bool validation, Empty)
      : width_(width), height_(height), gpu_({}, false, validation) {}

  int width_, height_;
  gpu::Context gpu_;
  VkRenderPass renderPass_ = VK_NULL_HANDLE;
  gpu::Image color_, depth_;
  VkFramebuffer framebuffer_ = VK_NULL_HANDLE;
  gpu::Buffer pixels_;
  bool imguiRenderer_ = false;  // ImGui's Vulkan backend started
};

}  // namespace

namespace {
// A picture smaller than the inspector's layout (kSmallestLayoutWidth) is a larger one scaled.
// 8192 is a side every Vulkan device can render.
constexpr long long kSmallestWidth = kSmallestLayoutWidth, kSmallestHeight = kSmallestLayoutHeight, kLargestSide = 8192;
}  // namespace

std::string pictureSizes() {
  const std::string largest = std::to_string(kLargestSide);
  return "between " + std::to_string(kSmallestWidth) + "x" + std::to_string(kSmallestHeight) + " and " + largest + "x" +
         largest;
}

bool pictureSizeAllowed(long long width, long long height) {
  return width >= kSmallestWidth && height >= kSmallestHeight && width <= kLargestSide && height <= kLargestSide;
}

void requirePictureSize(long long width, long long height, double uiScale) {
  if (!pictureSizeAllowed(width, height))
    throw Error("--size must be " + pictureSizes() + ", not '" + std::to_string(width) + "x" +
                std::to_string(height) + "'");
  if (width / uiScale < kSmallestWidth || height / uiScale < kSmallestHeight)
    throw Error("--size " + std::to_string(width) + "x" + std::to_string(height) + " at --ui-scale " + format("%g", uiScale) +
                " leaves the inspector less than " + std::to_string(kSmallestWidth) + "x" +
                std::to_string(kSmallestHeight) + " to lay out in: a larger --size or a smaller --ui-scale");
}

namespace {
void render(const std::string& meshName, const RemeshOptions& options, RemeshResult result,
            const ScreenshotOptions& shot, std::optional<Mesh> input) {
  OffscreenRenderer renderer(shot.width, shot.height, shot.validation, static_cast<float>(shot.uiScale));
  {
    Inspector inspector(renderer.gpu(), renderer.renderPass(), meshName, options, std::move(result),
                        std::move(input));
    shot.view.applyTo(inspector);
    // ImGui settles its layout over the first frames; the pictures come after them.
    for (int i = 0; i < 2; ++i) renderer.frame([&] { inspector.frame(); }, false);
    inspector.startExport(shot.picture);
    while (inspector.exporting()) {
      renderer.frame([&] { inspector.frame(); }, true);
      inspector.savePicture(renderer.encodePng(inspector.exportRequest()->path, inspector.exportRequest()->crop));
    }
  }
  if (renderer.validationMessages() > 0)
    throw Error("the Vulkan validation layer reported " +
                std::to_string(renderer.validationMessages()) + " problems");
}

Error notEnoughMemory(const ScreenshotOptions& shot) {
  return Error(shot.picture.path + ": not enough memory to render a " + std::to_string(shot.width) + "x" +
               std::to_string(shot.height) + " picture: a smaller --size needs less");
}
}  // namespace

void renderScreenshot(const std::string& meshName, const RemeshOptions& options,
                      RemeshResult result, const ScreenshotOptions& shot, std::optional<Mesh> input) {
  requirePictureSize(shot.width, shot.height, shot.uiScale);
  try {
    render(meshName, options, std::move(result), shot, std::move(input));
  } catch (const gpu::GpuError& e) {
    if (!e.outOfMemory) throw;
    throw notEnoughMemory(shot);
  } catch (const std::bad_alloc&) {  // the picture's images and buffers hold most of it
    throw notEnoughMemory(shot);
  }
}

FrameTimes benchmarkScrub(const std::string& meshName, const RemeshOptions& options,
                          RemeshResult result, int width, int height, int frames, bool scrub) {
  requirePictureSize(width, height);
  OffscreenRenderer renderer(width, height, false);
  Inspector inspector(renderer.gpu(), renderer.renderPass(), meshName, options, std::move(result));
  FrameTimes times;
  const int count = static_cast<int>(inspector.iteration()) + 1;
  // As the window does: the next iteration is prepared while the last frame renders, and a
  // frame's time is from one frame's start to the next one's.
  Stopwatch frame;
  for (int i = 0; i <= frames; ++i) {
    if (scrub) inspector.setIteration((i * 7) % count);  // jump around, as a dragged slider
    inspector.prepare();
    renderer.frame([&] { inspector.frame(); }, false);
    const double ms = frame.lap();
    if (i > 0) times.milliseconds.push_back(ms);
  }
  renderer.finish();
  return times;
}

}  // namespace lloydscope
