// The window on a dense screen: GLFW's frame (window coordinates, the pointer in them) laid out
// in units of the screen's scale, which ImGui's Vulkan backend draws with that many pixels each.
#include "ui_scale.h"

#include <gtest/gtest.h>
#include <imgui.h>

#include <cfloat>

using namespace lloydscope;

namespace {

struct ImGuiContextForTest {
  ImGuiContextForTest() { ImGui::CreateContext(); }
  ~ImGuiContextForTest() { ImGui::DestroyContext(); }
};

// As GLFW's backend leaves the frame of a 2560x1600 window on X11: one pixel per coordinate.
void beginFrame(float pointerX, float pointerY) {
  ImGuiIO& io = ImGui::GetIO();
  io.DisplaySize = ImVec2(2560, 1600);
  io.DisplayFramebufferScale = ImVec2(1, 1);
  io.MousePos = ImVec2(pointerX, pointerY);
}

}  // namespace

TEST(UiScale, TheLayoutAndThePointerAreInUnitsOfTheScreensScale) {
  ImGuiContextForTest context;
  beginFrame(600, 300);
  layOutInUnits(2.0f);
  const ImGuiIO& io = ImGui::GetIO();
  EXPECT_FLOAT_EQ(io.DisplaySize.x, 1280);
  EXPECT_FLOAT_EQ(io.DisplaySize.y, 800);
  EXPECT_FLOAT_EQ(io.DisplayFramebufferScale.x, 2);  // the backend draws a unit with 2 pixels
  EXPECT_FLOAT_EQ(io.MousePos.x, 300);  // where the pointer is in the layout
  EXPECT_FLOAT_EQ(io.MousePos.y, 150);
  // Every frame starts from GLFW's numbers again: nothing compounds.
  beginFrame(600, 300);
  layOutInUnits(2.0f);
  EXPECT_FLOAT_EQ(ImGui::GetIO().DisplaySize.x, 1280);
}

TEST(UiScale, APointerOutsideTheWindowStaysOutside) {
  ImGuiContextForTest context;
  beginFrame(-FLT_MAX, -FLT_MAX);
  layOutInUnits(1.5f);
  EXPECT_EQ(ImGui::GetIO().MousePos.x, -FLT_MAX);
  EXPECT_FLOAT_EQ(ImGui::GetIO().DisplaySize.y, 1600 / 1.5f);
}
