#include "frame_pacing.h"

#include <algorithm>

namespace lloydscope {

double FramePacer::wait(bool busy, bool typing) {
  if (busy) return 0;
  if (settle_ > 0) {
    --settle_;
    return 0;
  }
  return typing ? kCaretBlinkSeconds : kUntilInput;
}

namespace {

// GLFW's printable keys (space to the grave accent) and its Ctrl, Alt and Super bits.
constexpr int kFirstPrintableKey = 32, kLastPrintableKey = 96, kCommandMods = 0x2 | 0x4 | 0x8;

bool typedKey(const InputEvent& e) {
  return e.action != InputAction::Character && e.key >= kFirstPrintableKey &&
         e.key <= kLastPrintableKey && !(e.mods & kCommandMods);
}

}  // namespace

std::vector<InputEvent> InputQueue::takeFrame(bool typing) {
  std::vector<InputEvent> frame;
  std::vector<int> changed;  // keys pressed or released in this frame
  bool characters = false;   // typed characters taken in this frame
  while (!queue_.empty()) {
    const InputEvent next = queue_.front();
    if (typing && typedKey(next)) {
      frame.push_back(next);
      queue_.pop_front();
      continue;
    }
    if (isMouseKey(next.key) && next.action == InputAction::Press && characters) break;
    if (next.action == InputAction::Release || next.action == InputAction::Press) {
      if (std::find(changed.begin(), changed.end(), next.key) != changed.end()) break;
      changed.push_back(next.key);
    }
    frame.push_back(next);
    queue_.pop_front();
    characters = characters || next.action == InputAction::Character;
    if (next.action == InputAction::Press) break;  // the last of its frame
  }
  return frame;
}

}  // namespace lloydscope
