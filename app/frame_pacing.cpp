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

std::vector<KeyEvent> KeyQueue::takeFrame() {
  std::vector<KeyEvent> frame;
  std::vector<int> changed;  // keys pressed or released in this frame
  while (!queue_.empty()) {
    const KeyEvent& next = queue_.front();
    if (next.action != KeyAction::Repeat) {
      if (std::find(changed.begin(), changed.end(), next.key) != changed.end()) break;
      changed.push_back(next.key);
    }
    frame.push_back(next);
    queue_.pop_front();
  }
  return frame;
}

}  // namespace lloydscope
