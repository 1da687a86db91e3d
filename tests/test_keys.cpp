// Who has the inspector's keys, checked on ImGui frames without a window or a GPU.
#include "keys.h"

#include <gtest/gtest.h>
#include <imgui.h>

#include <functional>

using namespace lloydscope;

namespace {

constexpr int kEscape = 256;  // GLFW's key code, as the inspector's window maps it

// ImGui frames of one pane with a text field and a list (a combo) at its top.
struct Frames {
  char field[64] = "";
  int choice = 0;
  ImVec2 fieldAt{-1, -1}, listAt{-1, -1};
  Frames() {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = ImVec2(400, 300);
    io.DeltaTime = 1.0f / 60.0f;
    io.KeyMap[ImGuiKey_Escape] = kEscape;
    unsigned char* pixels = nullptr;
    int width = 0, height = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
    frame();  // the layout: where the field and the list are
  }
  ~Frames() { ImGui::DestroyContext(); }
  static ImVec2 middle() {
    return ImVec2((ImGui::GetItemRectMin().x + ImGui::GetItemRectMax().x) / 2,
                  (ImGui::GetItemRectMin().y + ImGui::GetItemRectMax().y) / 2);
  }
  // One frame: the pointer at `at`, the left button and Escape down or not. `before` runs
  // where the inspector reads its keys, before the widgets.
  void frame(ImVec2 at = ImVec2(-1, -1), bool down = false, bool escape = false,
             const std::function<void()>& before = {}) {
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = at;
    io.MouseDown[0] = down;
    io.KeysDown[kEscape] = escape;
    ImGui::NewFrame();
    if (before) before();
    ImGui::SetNextWindowPos(ImVec2(0, 0));
    ImGui::SetNextWindowSize(ImVec2(400, 300));
    ImGui::Begin("pane");
    ImGui::InputText("name", field, sizeof field);
    fieldAt = middle();
    ImGui::Combo("fill", &choice, "none\0mass\0area\0");
    listAt = middle();
    ImGui::End();
    ImGui::Render();
  }
  void click(ImVec2 at) {
    frame(at, true);
    frame(at, false);
  }
};

}  // namespace

// ImGui's io.WantTextInput tells a frame late that a field was left: a key tapped in the frame
// after a click left the field was typed, and the field's letters (L, P, F) were lost as
// commands.
TEST(Keys, ATextFieldLosesTheKeysInTheFrameItIsLeft) {
  Frames frames;
  frames.click(frames.fieldAt);
  EXPECT_TRUE(textFieldActive());
  EXPECT_FALSE(keysAreCommands());
  frames.frame(ImVec2(200, 250), true);  // a click below it, on the pane
  bool commands = false, wantTextInput = false;
  frames.frame(ImVec2(200, 250), false, false, [&] {  // the next frame, where keys are read
    commands = keysAreCommands();
    wantTextInput = ImGui::GetIO().WantTextInput;
  });
  EXPECT_TRUE(commands);
  EXPECT_TRUE(wantTextInput);  // what the inspector read before: still typing
}

// ImGui 1.86 closes a list with Escape only under keyboard navigation: the inspector does, and
// the Escape is not also a command (it would clear the pinned cells).
TEST(Keys, EscapeClosesAnOpenList) {
  Frames frames;
  frames.click(frames.listAt);
  EXPECT_TRUE(listOpen());
  EXPECT_FALSE(keysAreCommands());
  bool closed = true;
  frames.frame(ImVec2(-1, -1), false, false, [&] { closed = closeListOnEscape(); });
  EXPECT_FALSE(closed);  // no Escape, no closing
  frames.frame(ImVec2(-1, -1), false, true, [&] { closed = closeListOnEscape(); });
  EXPECT_TRUE(closed);
  frames.frame();
  EXPECT_FALSE(listOpen());
  EXPECT_TRUE(keysAreCommands());
  frames.frame(ImVec2(-1, -1), false, true, [&] { closed = closeListOnEscape(); });
  EXPECT_FALSE(closed);  // no list open: Escape is the inspector's
}
