#include "window.h"

#include "keys.h"
#include "text.h"
#include "ui_scale.h"
#include "frame_pacing.h"
#include "gpu.h"
#include "inspector.h"
#include "png.h"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_vulkan.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <vector>

namespace lloydscope {

namespace {

std::vector<const char*> surfaceExtensions() {
  uint32_t count = 0;
  const char** names = glfwGetRequiredInstanceExtensions(&count);
  if (!names) throw Error("Vulkan cannot present to this display (no surface extension)");
  return std::vector<const char*>(names, names + count);
}

// The swapchain and everything sized like it; rebuilt when the window changes size.
struct Swapchain {
  VkSwapchainKHR swapchain = VK_NULL_HANDLE;
  VkExtent2D extent{};
  std::vector<VkImage> images;
  std::vector<VkImageView> views;
  std::vector<VkFramebuffer> framebuffers;
  // Signalled when an image's frame is drawn, waited on by its presentation: one per image,
  // because a present holds its semaphore until the image comes back, which may be after the
  // next frame is submitted (one for all was signalled again while still waited on).
  std::vector<VkSemaphore> rendered;
  gpu::Image depth;
  bool readable = false;  // frames can be copied out (for exports)

  void create(gpu::Context& gpu, VkSurfaceKHR surface, VkRenderPass pass, VkFormat format,
              GLFWwindow* window) {
    VkSurfaceCapabilitiesKHR caps;
    vkGetPhysicalDeviceSurfaceCapabilitiesKHR(gpu.physical, surface, &caps);
    int w, h;
    glfwGetFramebufferSize(window, &w, &h);
    extent = caps.currentExtent.width != UINT32_MAX
                 ? caps.currentExtent
                 : VkExtent2D{static_cast<uint32_t>(w), static_cast<uint32_t>(h)};
    VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
    info.surface = surface;
    info.minImageCount = std::max(2u, caps.minImageCount);
    if (caps.maxImageCount) info.minImageCount = std::min(info.minImageCount, caps.maxImageCount);
    info.imageFormat = format;
    info.imageColorSpace = VK_COLOR_SPACE_SRGB_NONLINEAR_KHR;
    info.imageExtent = extent;
    info.imageArrayLayers = 1;
    // TRANSFER_SRC: exports read the frame back (lavapipe offers it; other drivers may not).
    info.imageUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT |
                      (caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
    readable = caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.preTransform = caps.currentTransform;
    info.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
    info.presentMode = VK_PRESENT_MODE_FIFO_KHR;
    info.clipped = VK_TRUE;
    gpu::check(vkCreateSwapchainKHR(gpu.device, &info, nullptr, &swapchain), "creating the swapchain");
    uint32_t count = 0;
    vkGetSwapchainImagesKHR(gpu.device, swapchain, &count, nullptr);
    images.resize(count);
    vkGetSwapchainImagesKHR(gpu.device, swapchain, &count, images.data());
    depth = gpu.createImage(extent.width, extent.height, gpu::kDepthFormat,
                            VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, VK_IMAGE_ASPECT_DEPTH_BIT);
    for (VkImage image : images) {
      VkImageViewCreateInfo v{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
      v.image = image;
      v.viewType = VK_IMAGE_VIEW_TYPE_2D;
      v.format = format;
      v.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
      VkImageView view;
      gpu::check(vkCreateImageView(gpu.device, &v, nullptr, &view), "creating a swapchain view");
      views.push_back(view);
      const VkImageView attachments[2] = {view, depth.view};
      VkFramebufferCreateInfo fb{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
      fb.renderPass = pass;
      fb.attachmentCount = 2;
      fb.pAttachments = attachments;
      fb.width = extent.width;
      fb.height = extent.height;
      fb.layers = 1;
      VkFramebuffer framebuffer;
      gpu::check(vkCreateFramebuffer(gpu.device, &fb, nullptr, &framebuffer), "creating a framebuffer");
      framebuffers.push_back(framebuffer);
      VkSemaphoreCreateInfo semaphoreInfo{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
      VkSemaphore semaphore;
      gpu::check(vkCreateSemaphore(gpu.device, &semaphoreInfo, nullptr, &semaphore), "creating a semaphore");
      rendered.push_back(semaphore);
    }
  }

  void destroy(gpu::Context& gpu) {
    vkDeviceWaitIdle(gpu.device);
    for (VkFramebuffer f : framebuffers) vkDestroyFramebuffer(gpu.device, f, nullptr);
    for (VkImageView v : views) vkDestroyImageView(gpu.device, v, nullptr);
    for (VkSemaphore s : rendered) vkDestroySemaphore(gpu.device, s, nullptr);
    gpu.destroy(depth);
    if (swapchain) vkDestroySwapchainKHR(gpu.device, swapchain, nullptr);
    *this = Swapchain{};
  }
};

// Copies the rendered swapchain image (in PRESENT_SRC layout) into `pixels`, growing it as
// needed, and gives the image back for presenting.
void copyToBuffer(gpu::Context& gpu, VkCommandBuffer cmd, VkImage image, VkExtent2D extent,
                  gpu::Buffer& pixels) {
  const VkDeviceSize bytes = VkDeviceSize(extent.width) * extent.height * 4;
  if (pixels.size < bytes) {
    gpu.destroy(pixels);
    pixels = gpu.createBuffer(bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  }
  VkImageMemoryBarrier barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
  barrier.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  barrier.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
  barrier.oldLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
  barrier.newLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  barrier.srcQueueFamilyIndex = barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.image = image;
  barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                       VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0, nullptr, 1, &barrier);
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {extent.width, extent.height, 1};
  vkCmdCopyImageToBuffer(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, pixels.buffer, 1,
                         &region);
  barrier.srcAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
  barrier.dstAccessMask = 0;
  barrier.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  barrier.newLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT,
                       0, 0, nullptr, 0, nullptr, 1, &barrier);
}

// Writes the frame just read back, or tells the inspector why it could not.
void saveExport(Inspector& inspector, const Swapchain& chain, const gpu::Buffer& pixels) {
  if (!chain.readable) {
    inspector.exported("this display cannot read frames back: use inspect --screenshot");
    return;
  }
  const ExportRequest& r = *inspector.exportRequest();
  try {
    inspector.savePicture(encodePng(r.path, static_cast<const unsigned char*>(pixels.mapped),
                                    static_cast<int>(chain.extent.width), static_cast<int>(chain.extent.height),
                                    true, r.crop));
  } catch (const Error& e) {
    inspector.exported(e.what());
  }
}

// What the window's callbacks collect between frames (the window's user pointer).
struct WindowEvents {
  FramePacer pacer;
  InputQueue input;
  bool mouseDown[ImGuiMouseButton_COUNT] = {};  // as the queue has delivered the buttons
  std::optional<ImVec2> clickedAt;  // where the pointer was at this frame's last button event
};

WindowEvents& eventsOf(GLFWwindow* window) {
  return *static_cast<WindowEvents*>(glfwGetWindowUserPointer(window));
}

// Installed before ImGui's backend, which calls those it installs too (focus, the cursor
// entering) before its own. Any of them wakes the window.
void noteInput(GLFWwindow* window) { eventsOf(window).pacer.input(); }
void watchInput(GLFWwindow* window) {
  glfwSetWindowFocusCallback(window, [](GLFWwindow* w, int) { noteInput(w); });
  glfwSetCursorEnterCallback(window, [](GLFWwindow* w, int) { noteInput(w); });
  glfwSetCursorPosCallback(window, [](GLFWwindow* w, double, double) { noteInput(w); });
  glfwSetFramebufferSizeCallback(window, [](GLFWwindow* w, int, int) { noteInput(w); });
  glfwSetWindowRefreshCallback(window, noteInput);
}

// Replaces ImGui's key, character, mouse button and wheel callbacks (after its backend is set
// up): they reach it through the queue, frame by frame and in order (InputQueue). GLFW sends
// the buttons' releases when the window loses focus, through the queue too.
void queueKeys(GLFWwindow* window) {
  static_assert(GLFW_RELEASE == int(InputAction::Release) && GLFW_PRESS == int(InputAction::Press) &&
                GLFW_REPEAT == int(InputAction::Repeat));
  glfwSetKeyCallback(window, [](GLFWwindow* w, int key, int scancode, int action, int mods) {
    eventsOf(w).input.push({static_cast<InputAction>(action), key, scancode, mods});
    noteInput(w);
  });
  glfwSetCharCallback(window, [](GLFWwindow* w, unsigned int c) {
    eventsOf(w).input.push({InputAction::Character, 0, 0, 0, c});
    noteInput(w);
  });
  glfwSetMouseButtonCallback(window, [](GLFWwindow* w, int button, int action, int mods) {
    if (button < 0 || button >= ImGuiMouseButton_COUNT) return;
    InputEvent click{action == GLFW_PRESS ? InputAction::Press : InputAction::Release, mouseKey(button), 0, mods};
    glfwGetCursorPos(w, &click.x, &click.y);  // where it was clicked, not where it is when delivered
    eventsOf(w).input.push(click);
    noteInput(w);
  });
  glfwSetScrollCallback(window, [](GLFWwindow* w, double x, double y) {
    InputEvent wheel{InputAction::Scroll};
    wheel.x = x;
    wheel.y = y;
    eventsOf(w).input.push(wheel);
    noteInput(w);
  });
}

void deliverInput(GLFWwindow* window) {
  WindowEvents& events = eventsOf(window);
  events.clickedAt.reset();
  for (const InputEvent& e : events.input.takeFrame(textFieldActive())) {
    if (e.action == InputAction::Character) {
      ImGui_ImplGlfw_CharCallback(window, e.character);
    } else if (e.action == InputAction::Scroll) {
      ImGui_ImplGlfw_ScrollCallback(window, e.x, e.y);
    } else if (isMouseKey(e.key)) {
      events.mouseDown[mouseKey(0) - e.key] = e.action == InputAction::Press;
      events.clickedAt = ImVec2(static_cast<float>(e.x), static_cast<float>(e.y));
    } else {
      ImGui_ImplGlfw_KeyCallback(window, e.key, e.scancode, static_cast<int>(e.action), e.mods);
    }
  }
}

// After ImGui_ImplGlfw_NewFrame(), which reads the buttons and the pointer as they are now:
// the buttons as the queue has delivered them, and the pointer where the last was clicked.
void holdMouseButtons(GLFWwindow* window) {
  const WindowEvents& events = eventsOf(window);
  ImGuiIO& io = ImGui::GetIO();
  std::copy(std::begin(events.mouseDown), std::end(events.mouseDown), io.MouseDown);
  if (events.clickedAt) io.MousePos = *events.clickedAt;
}

// A key held other than a modifier: ImGui repeats it by its own clock, between events (a held
// mouse button or Shift changes nothing until the pointer moves).
bool keyHeld() {
  const ImGuiIO& io = ImGui::GetIO();
  for (int key = 0; key < IM_ARRAYSIZE(io.KeysDown); ++key)
    if (io.KeysDown[key] && !(key >= GLFW_KEY_LEFT_SHIFT && key <= GLFW_KEY_RIGHT_SUPER)) return true;
  return false;
}

// Draws at once while a run goes on or input is settling; otherwise sleeps until an event (a
// thread's glfwPostEmptyEvent too) or the picture's next change (playback's next iteration,
// the lesson's next step, a message's going), which gets a frame more to settle. Minimized, there is nothing to
// draw until it is shown again.
void awaitNextFrame(GLFWwindow* window, const Inspector& inspector) {
  WindowEvents& events = eventsOf(window);
  int w, h;
  glfwGetFramebufferSize(window, &w, &h);
  const double change = inspector.secondsToChange();
  const bool busy = change == 0 || !events.input.empty() || keyHeld();
  const double wait = w == 0 || h == 0
                          ? FramePacer::kUntilInput
                          : std::min(events.pacer.wait(busy, textFieldActive()), change);
  if (wait == FramePacer::kUntilInput) {
    glfwWaitEvents();
  } else if (wait > 0) {
    glfwWaitEventsTimeout(wait);
    if (wait == change) events.pacer.input(1);
  } else {
    glfwPollEvents();
  }
}

// Runs `undo` when the scope ends, however it ends: what was made is unmade in reverse order,
// after an error too.
template <class Undo>
struct OnExit {
  Undo undo;
  ~OnExit() { undo(); }
};
template <class Undo>
OnExit(Undo) -> OnExit<Undo>;

// The primary monitor's content scale (its Xft.dpi over 96), within 1 to 4.
float screenScale() {
  float scale = 1, unused;
  if (GLFWmonitor* monitor = glfwGetPrimaryMonitor()) glfwGetMonitorContentScale(monitor, &scale, &unused);
  return std::clamp(scale, 1.0f, 4.0f);
}

// The window's Vulkan surface, the render pass that draws into it, and its swapchain. open()
// makes them one after the other; whatever it made is gone with the Screen, before the
// instance is, whether open() or a frame failed.
struct Screen {
  static constexpr VkFormat kFormat = VK_FORMAT_B8G8R8A8_UNORM;  // UNORM: ImGui's colours are already sRGB
  gpu::Context& gpu;
  GLFWwindow* window;
  VkSurfaceKHR surface = VK_NULL_HANDLE;
  VkRenderPass pass = VK_NULL_HANDLE;
  Swapchain chain;
  bool outOfDate = false;  // the swapchain no longer fits the window

  void open() {
    gpu::check(glfwCreateWindowSurface(gpu.instance, window, nullptr, &surface), "creating the surface");
    VkBool32 supported = VK_FALSE;
    vkGetPhysicalDeviceSurfaceSupportKHR(gpu.physical, gpu.queueFamily, surface, &supported);
    if (!supported) throw Error("the Vulkan device cannot present to this window");
    pass = gpu::createRenderPass(gpu.device, kFormat, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR);
    chain.create(gpu, surface, pass, kFormat, window);
  }
  // The swapchain made again where it no longer fits the window's w x h pixels.
  void fit(int w, int h) {
    if (!outOfDate && static_cast<uint32_t>(w) == chain.extent.width &&
        static_cast<uint32_t>(h) == chain.extent.height)
      return;
    chain.destroy(gpu);
    chain.create(gpu, surface, pass, kFormat, window);
    outOfDate = false;
  }
  ~Screen() {
    chain.destroy(gpu);
    if (pass) vkDestroyRenderPass(gpu.device, pass, nullptr);
    if (surface) vkDestroySurfaceKHR(gpu.instance, surface, nullptr);
  }
};

// ImGui on the window: its context and its GLFW and Vulkan backends, each shut down with the
// WindowImGui if start() got as far as starting it.
struct WindowImGui {
  bool glfwBackend = false, vulkanBackend = false;

  void start(GLFWwindow* window, gpu::Context& gpu, const Screen& screen, float pixelsPerUnit) {
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;
    ImGui::StyleColorsLight();
    glfwBackend = ImGui_ImplGlfw_InitForVulkan(window, true);
    queueKeys(window);
    addInspectorFonts(pixelsPerUnit);
    vulkanBackend = true;  // initImGuiRenderer's font upload may fail after the backend started
    gpu::initImGuiRenderer(gpu, screen.pass, static_cast<uint32_t>(screen.chain.images.size()));
  }
  ~WindowImGui() {
    if (vulkanBackend) ImGui_ImplVulkan_Shutdown();
    if (glfwBackend) ImGui_ImplGlfw_Shutdown();
    if (ImGui::GetCurrentContext()) ImGui::DestroyContext();
  }
};

// What the one frame in flight needs: a semaphore for the image acquired, a fence for the
// frame drawn, its command buffer, and a buffer for frames read back (exports). create()
// makes them; whatever it made is gone with the FrameSync, once the device is idle.
struct FrameSync {
  gpu::Context& gpu;
  VkSemaphore acquired = VK_NULL_HANDLE;
  VkFence done = VK_NULL_HANDLE;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  gpu::Buffer pixels;

  void create() {
    VkSemaphoreCreateInfo semaphoreInfo{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    gpu::check(vkCreateSemaphore(gpu.device, &semaphoreInfo, nullptr, &acquired), "creating a semaphore");
    VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    gpu::check(vkCreateFence(gpu.device, &fenceInfo, nullptr, &done), "creating a fence");
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = gpu.commandPool;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    gpu::check(vkAllocateCommandBuffers(gpu.device, &alloc, &cmd), "allocating a command buffer");
  }
  ~FrameSync() {
    vkDeviceWaitIdle(gpu.device);
    gpu.destroy(pixels);
    if (cmd) vkFreeCommandBuffers(gpu.device, gpu.commandPool, 1, &cmd);
    if (done) vkDestroyFence(gpu.device, done, nullptr);
    if (acquired) vkDestroySemaphore(gpu.device, acquired, nullptr);
  }
};

// One frame: the inspector built and recorded into the next swapchain image, submitted and
// presented; the next iteration prepared while lavapipe renders; an export's picture saved.
void drawFrame(GLFWwindow* window, Screen& screen, FrameSync& sync, Inspector& inspector,
               float pixelsPerUnit) {
  int w, h;
  glfwGetFramebufferSize(window, &w, &h);
  if (w == 0 || h == 0) return;  // minimized
  screen.fit(w, h);
  gpu::Context& gpu = screen.gpu;
  Swapchain& chain = screen.chain;
  uint32_t index;
  const VkResult acquiredResult =
      vkAcquireNextImageKHR(gpu.device, chain.swapchain, UINT64_MAX, sync.acquired, VK_NULL_HANDLE, &index);
  screen.outOfDate = gpu::swapchainOutOfDate(acquiredResult, "acquiring a swapchain image");
  // Suboptimal gives an image still, drawn and shown before the chain is made again.
  if (acquiredResult == VK_ERROR_OUT_OF_DATE_KHR) return;  // no image to draw into
  deliverInput(window);
  ImGui_ImplVulkan_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  holdMouseButtons(window);
  layOutInUnits(pixelsPerUnit);
  ImGui::NewFrame();
  inspector.frame();
  if (inspector.closeRequested()) glfwSetWindowShouldClose(window, GLFW_TRUE);
  ImGui::Render();
  VkCommandBuffer cmd = sync.cmd;
  vkResetCommandBuffer(cmd, 0);
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  vkBeginCommandBuffer(cmd, &begin);
  Inspector::recordFrame(cmd, screen.pass, chain.framebuffers[index], chain.extent);
  const bool exporting = inspector.exportRequest().has_value();
  if (exporting && chain.readable) copyToBuffer(gpu, cmd, chain.images[index], chain.extent, sync.pixels);
  vkEndCommandBuffer(cmd);
  const VkPipelineStageFlags wait = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.waitSemaphoreCount = 1;
  submit.pWaitSemaphores = &sync.acquired;
  submit.pWaitDstStageMask = &wait;
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &cmd;
  submit.signalSemaphoreCount = 1;
  submit.pSignalSemaphores = &chain.rendered[index];
  gpu::check(vkQueueSubmit(gpu.queue, 1, &submit, sync.done), "submitting a frame");
  VkPresentInfoKHR present{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
  present.waitSemaphoreCount = 1;
  present.pWaitSemaphores = &chain.rendered[index];
  present.swapchainCount = 1;
  present.pSwapchains = &chain.swapchain;
  present.pImageIndices = &index;
  screen.outOfDate |= gpu::swapchainOutOfDate(vkQueuePresentKHR(gpu.queue, &present), "presenting a frame");
  inspector.prepare();  // while lavapipe renders: the iteration the slider chose
  vkWaitForFences(gpu.device, 1, &sync.done, VK_TRUE, UINT64_MAX);  // one frame in flight
  vkResetFences(gpu.device, 1, &sync.done);
  if (exporting) saveExport(inspector, chain, sync.pixels);
}

}  // namespace

void requireDisplay() {
  const char* display = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  if ((!display || !*display) && (!wayland || !*wayland))
    throw Error("no display to open a window on: use 'lloydscope inspect MESH --screenshot "
                "OUT.png' for a picture, 'lloydscope remesh MESH -o OUT' for the result, or run "
                "under xvfb-run");
}

int runWindow(const std::string& meshName, const RemeshOptions& options, RemeshResult result,
              bool validation, std::optional<Mesh> input,
              const OpeningView& view, double uiScale) {
  requireDisplay();
  if (!glfwInit()) throw Error("cannot open a window (GLFW could not start on this display)");
  const OnExit endGlfw{[] { glfwTerminate(); }};
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
  const float pixelsPerUnit = uiScale > 0 ? static_cast<float>(uiScale) : screenScale();
  WindowEvents events;  // the callbacks', until the window is gone
  GLFWwindow* window = glfwCreateWindow(static_cast<int>(std::lround(1280 * pixelsPerUnit)),
                                        static_cast<int>(std::lround(800 * pixelsPerUnit)), "Lloydscope", nullptr, nullptr);
  if (!window) throw Error("cannot open a window on this display");
  // No smaller than the layout reads in (the pictures' least --size): at 640x400 the plots'
  // titles and the legends were cut off, and a note covered the 2D legend.
  glfwSetWindowSizeLimits(window, static_cast<int>(std::lround(kSmallestLayoutWidth * pixelsPerUnit)),
                          static_cast<int>(std::lround(kSmallestLayoutHeight * pixelsPerUnit)), GLFW_DONT_CARE,
                          GLFW_DONT_CARE);
  const OnExit closeWindow{[&] { glfwDestroyWindow(window); }};
  glfwSetWindowUserPointer(window, &events);
  gpu::Context gpu(surfaceExtensions(), true, validation);
  {
    Screen screen{gpu, window};
    screen.open();
    watchInput(window);
    WindowImGui imgui;
    imgui.start(window, gpu, screen, pixelsPerUnit);
    FrameSync sync{gpu};
    sync.create();
    Inspector inspector(gpu, screen.pass, meshName, options, std::move(result), std::move(input));
    const OnExit settle{[&] { vkDeviceWaitIdle(gpu.device); }};  // before the inspector's buffers go
    inspector.setWake(glfwPostEmptyEvent);  // thread-safe: ends the wait for events
    view.applyTo(inspector);
    while (!glfwWindowShouldClose(window)) {
      awaitNextFrame(window, inspector);
      drawFrame(window, screen, sync, inspector, pixelsPerUnit);
    }
  }
  if (gpu.validationMessages > 0)
    throw Error("the Vulkan validation layer reported " + std::to_string(gpu.validationMessages) +
                " problems");
  return 0;
}

}  // namespace lloydscope
