// When the window draws a frame, and which input events each frame sees. Idle (no input,
// nothing moving) the window waits for events instead of drawing: an inspector left open
// beside a lecture's slides costs no CPU.
#pragma once

#include <algorithm>
#include <deque>
#include <limits>
#include <vector>

namespace lloydscope {

class FramePacer {
 public:
  // ImGui shows a click's effect (a button's action, a header opening, a hover's highlight) a
  // frame or two after the event: so many frames are drawn after any input before waiting.
  static constexpr int kSettleFrames = 3;
  // While a text field takes typing, a frame at least so often: its caret blinks.
  static constexpr double kCaretBlinkSeconds = 0.5;
  static constexpr double kUntilInput = std::numeric_limits<double>::infinity();

  // Draws `frames` more before waiting again (at least).
  void input(int frames = kSettleFrames) { settle_ = std::max(settle_, frames); }
  // How long to wait for events before the next frame: 0 to draw it at once, kUntilInput for
  // as long as none comes. `busy`: the next frame differs without input (a run, playback, a
  // lesson, an export); `typing`: a text field is active.
  double wait(bool busy, bool typing);

 private:
  int settle_ = kSettleFrames;  // the first frames draw the window
};

// GLFW's key actions (for keys and mouse buttons), which the window forwards to ImGui as they
// are, a typed character and a turn of the mouse wheel.
enum class InputAction { Release = 0, Press = 1, Repeat = 2, Character = 3, Scroll = 4 };

// The window's mouse buttons are keys below GLFW's (-1 is its unknown key): the queue's rules
// for keys keep their presses and releases in order with the keys'.
constexpr int mouseKey(int button) { return -2 - button; }
constexpr bool isMouseKey(int key) { return key <= mouseKey(0); }

struct InputEvent {
  InputAction action = InputAction::Press;
  int key = 0, scancode = 0, mods = 0;  // of a key or mouse button
  unsigned character = 0;               // a Unicode code point, of a Character
  double x = 0, y = 0;  // where the pointer was, of a mouse button; the wheel's turn, of a Scroll
};

// ImGui 1.86 reads each key as held or not once a frame, so a key pressed and released between
// two frames (a quick tap: under 60 ms, a frame's time under lavapipe) was never seen, nor a
// release and the next press of a key tapped again, nor a chord whose modifier was released
// in the frame that saw the key pressed (Shift+Right read as Right); and a text field applies
// a frame's characters before its keys (Backspace, Backspace, x typed in one frame deleted the
// x). Queued here, each frame takes the events in order up to the first key press, which ends
// it, or the second change of one key (pressed, released), which waits for the next frame; a
// click after characters waits too (a field clicked in a frame takes that frame's characters,
// and the end of a name typed fast went to the next field clicked).
class InputQueue {
 public:
  void push(const InputEvent& event) { queue_.push_back(event); }
  // `typing`: a text field takes the characters, and their keys (letters, digits, punctuation
  // without Ctrl, Alt or Super) pass with no frame of their own: one a character, typing ran
  // behind a fast typist.
  std::vector<InputEvent> takeFrame(bool typing = false);
  bool empty() const { return queue_.empty(); }

 private:
  std::deque<InputEvent> queue_;
};

}  // namespace lloydscope
