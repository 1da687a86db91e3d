#include "keys.h"

#include <imgui.h>
#include <imgui_internal.h>

namespace lloydscope {

bool textFieldActive() {
  const ImGuiContext& g = *ImGui::GetCurrentContext();
  return g.ActiveId != 0 && g.ActiveId == g.InputTextState.ID;
}

bool listOpen() { return ImGui::IsPopupOpen(nullptr, ImGuiPopupFlags_AnyPopupId | ImGuiPopupFlags_AnyPopupLevel); }

bool keysAreCommands() { return !textFieldActive() && !listOpen(); }

bool closeListOnEscape() {
  if (!listOpen() || !ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false)) return false;
  ImGui::ClosePopupToLevel(0, true);
  return true;
}

}  // namespace lloydscope
