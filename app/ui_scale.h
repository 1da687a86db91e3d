// The inspector on a dense screen: laid out in units of several framebuffer pixels each, as
// ImGui's Vulkan backend draws (ImGuiIO::DisplayFramebufferScale), so that its type and panes
// keep their size. The renderers take their panes in these units (gpu::setRenderArea).
#pragma once

namespace lloydscope {

// After GLFW's backend has begun ImGui's frame: the frame laid out in units of `pixelsPerUnit`
// framebuffer pixels, the pointer with it. GLFW gives window coordinates and the framebuffer's
// pixels per window coordinate (1 on X11, where a dense screen has more of both).
void layOutInUnits(float pixelsPerUnit);

}  // namespace lloydscope
