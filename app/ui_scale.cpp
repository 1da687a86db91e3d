#include "ui_scale.h"

#include <imgui.h>

#include <cfloat>

namespace lloydscope {

void layOutInUnits(float pixelsPerUnit) {
  ImGuiIO& io = ImGui::GetIO();
  const ImVec2 pixels = io.DisplayFramebufferScale;  // per window coordinate
  io.DisplaySize = ImVec2(io.DisplaySize.x * pixels.x / pixelsPerUnit, io.DisplaySize.y * pixels.y / pixelsPerUnit);
  if (io.MousePos.x != -FLT_MAX)  // (-FLT_MAX: the pointer is outside)
    io.MousePos = ImVec2(io.MousePos.x * pixels.x / pixelsPerUnit, io.MousePos.y * pixels.y / pixelsPerUnit);
  io.DisplayFramebufferScale = ImVec2(pixelsPerUnit, pixelsPerUnit);
}

}  // namespace lloydscope
