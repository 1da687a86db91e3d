#include "frame_pacing.h"

#include <algorithm>

namespace lloydscope {

double FramePacer::wait(bool busy) {
  if (busy) return 0;
  if (settle_ > 0) {
    --settle_;
    return 0;
  }
  return kIdleWaitSeconds;
}

std::vector<InputEvent> InputQueue::takeFrame() {
  std::vector<InputEvent> frame;
  std::vector<int> changed;  // keys pressed or released in this frame
  bool pressed = false;      // a key press was taken in this frame
  while (!queue_.empty()) {
    const InputEvent& next = queue_.front();
    if (next.action == InputAction::Character) {
      if (pressed) break;
    } else if (next.action != InputAction::Repeat) {
      if (std::find(changed.begin(), changed.end(), next.key) != changed.end()) break;
      changed.push_back(next.key);
      pressed = pressed || next.action == InputAction::Press;
    }
    frame.push_back(next);
    queue_.pop_front();
  }
  return frame;
}

}  // namespace lloydscope
