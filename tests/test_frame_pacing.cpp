#include "frame_pacing.h"

#include <gtest/gtest.h>

namespace lloydscope {
namespace {

InputEvent press(int key) { return {InputAction::Press, key}; }
InputEvent release(int key) { return {InputAction::Release, key}; }
InputEvent character(unsigned c) { return {InputAction::Character, 0, 0, 0, c}; }

std::vector<std::pair<int, InputAction>> keysOf(const std::vector<InputEvent>& events) {
  std::vector<std::pair<int, InputAction>> keys;
  for (const InputEvent& e : events) keys.emplace_back(e.key, e.action);
  return keys;
}

using Keys = std::vector<std::pair<int, InputAction>>;

TEST(InputQueue, ATapBetweenTwoFramesIsSeenPressedThenReleased) {
  InputQueue queue;
  queue.push(press(262));
  queue.push(release(262));
  EXPECT_EQ(keysOf(queue.takeFrame()), (Keys{{262, InputAction::Press}}));
  EXPECT_FALSE(queue.empty());
  EXPECT_EQ(keysOf(queue.takeFrame()), (Keys{{262, InputAction::Release}}));
  EXPECT_TRUE(queue.empty());
  EXPECT_TRUE(queue.takeFrame().empty());
}

TEST(InputQueue, AModifierIsStillHeldWhenTheKeyItChangesIsSeen) {
  // Shift+Right tapped between two frames: the frame that sees Right pressed sees Shift held.
  InputQueue queue;
  for (const InputEvent& e : {press(340), press(262), release(262), release(340)}) queue.push(e);
  EXPECT_EQ(keysOf(queue.takeFrame()), (Keys{{340, InputAction::Press}}));
  EXPECT_EQ(keysOf(queue.takeFrame()), (Keys{{262, InputAction::Press}}));
  EXPECT_EQ(keysOf(queue.takeFrame()), (Keys{{262, InputAction::Release}, {340, InputAction::Release}}));
}

TEST(InputQueue, AModifierReleasedFirstIsStillHeldWhenTheKeyIsSeen) {
  // Shift let go before Right, all between two frames: Right read as a plain Right before.
  InputQueue queue;
  for (const InputEvent& e : {press(340), press(262), release(340), release(262)}) queue.push(e);
  EXPECT_EQ(keysOf(queue.takeFrame()), (Keys{{340, InputAction::Press}}));
  EXPECT_EQ(keysOf(queue.takeFrame()), (Keys{{262, InputAction::Press}}));
  EXPECT_EQ(keysOf(queue.takeFrame()), (Keys{{340, InputAction::Release}, {262, InputAction::Release}}));
}

TEST(InputQueue, TwoTapsOfOneKeyTakeFourFrames) {
  InputQueue queue;
  for (const InputEvent& e : {press(32), release(32), press(32), release(32)}) queue.push(e);
  int frames = 0, presses = 0;
  while (!queue.empty()) {
    ++frames;
    for (const InputEvent& e : queue.takeFrame()) presses += e.action == InputAction::Press;
  }
  EXPECT_EQ(frames, 4);  // press | release | press | release: each frame sees the key change
  // once, so ImGui sees the second press too
  EXPECT_EQ(presses, 2);
}

TEST(InputQueue, ATapArrivingWhileTheLastOneIsReleasedWaitsForTheNextFrame) {
  // The first press was seen by an earlier frame; its release and the next press arrive
  // together: one frame sees the key up, the next sees it down again.
  InputQueue queue;
  queue.push(press(262));
  queue.takeFrame();
  for (const InputEvent& e : {release(262), press(262), release(262)}) queue.push(e);
  EXPECT_EQ(keysOf(queue.takeFrame()), (Keys{{262, InputAction::Release}}));
  EXPECT_EQ(keysOf(queue.takeFrame()), (Keys{{262, InputAction::Press}}));
  EXPECT_EQ(keysOf(queue.takeFrame()), (Keys{{262, InputAction::Release}}));
}

TEST(InputQueue, AReleaseOfAKeyPressedEarlierAndRepeatsPassAtOnce) {
  InputQueue queue;
  queue.push(press(65));
  EXPECT_EQ(queue.takeFrame().size(), 1u);
  queue.push({InputAction::Repeat, 65});
  queue.push({InputAction::Repeat, 65});
  queue.push(release(65));
  EXPECT_EQ(queue.takeFrame().size(), 3u);
  EXPECT_TRUE(queue.empty());
}

// A text field applies a frame's characters before its keys: typed "Backspace, Backspace, x"
// in one frame, the x was written, then deleted.
TEST(InputQueue, ACharacterAfterAKeyPressWaitsForTheNextFrame) {
  InputQueue queue;
  for (const InputEvent& e : {character('a'), press(259), release(259), press(259), release(259), character('x')})
    queue.push(e);
  EXPECT_EQ(keysOf(queue.takeFrame()), (Keys{{0, InputAction::Character}, {259, InputAction::Press}}));
  EXPECT_EQ(keysOf(queue.takeFrame()), (Keys{{259, InputAction::Release}}));
  EXPECT_EQ(keysOf(queue.takeFrame()), (Keys{{259, InputAction::Press}}));
  // No key pressed before it in this frame: the x may come with the release.
  const std::vector<InputEvent> last = queue.takeFrame();
  EXPECT_EQ(keysOf(last), (Keys{{259, InputAction::Release}, {0, InputAction::Character}}));
  EXPECT_EQ(last.at(1).character, unsigned('x'));
  EXPECT_TRUE(queue.empty());
}

// Typed into a text field, a name comes in one frame, however fast: a click right after it
// no longer overtakes the characters still queued. Backspace still waits its turn.
TEST(InputQueue, TypingTakesTheCharactersOfAWholeWordInOneFrame) {
  InputQueue queue;
  for (unsigned c : {'a', 'a', 'b'}) {
    const int key = static_cast<int>(c - 'a' + 65);
    for (const InputEvent& e : {press(key), character(c), release(key)}) queue.push(e);
  }
  queue.push(press(259));
  queue.push(release(259));
  const std::vector<InputEvent> frame = queue.takeFrame(true);
  EXPECT_EQ(frame.size(), 10u);  // the three letters' nine events and Backspace's press
  EXPECT_EQ(frame.back().key, 259);
  EXPECT_EQ(keysOf(queue.takeFrame(true)), (Keys{{259, InputAction::Release}}));
  // Not typing, the letters are commands (L, P, F): a frame each.
  for (const InputEvent& e : {press(76), character('l'), release(76), press(80)}) queue.push(e);
  EXPECT_EQ(keysOf(queue.takeFrame(false)), (Keys{{76, InputAction::Press}}));
  // Ctrl+A typed selects all: a command, not a letter.
  InputQueue chord;
  chord.push(press(341));
  chord.push({InputAction::Press, 65, 0, 0x2});
  chord.push({InputAction::Release, 65, 0, 0x2});
  EXPECT_EQ(keysOf(chord.takeFrame(true)), (Keys{{341, InputAction::Press}}));
  EXPECT_EQ(keysOf(chord.takeFrame(true)), (Keys{{65, InputAction::Press}}));
}

// A click right after editing keys typed fast (the mouse buttons go through the queue as keys
// below GLFW's): it came before the last character, which then went to the next field.
TEST(InputQueue, AClickWaitsForTheKeysTypedBeforeIt) {
  InputQueue queue;
  const int left = 263, s = 83, mouse = mouseKey(0);
  for (const InputEvent& e : {press(left), release(left), press(s), character('S'), release(s),
                              press(mouse), release(mouse)})
    queue.push(e);
  EXPECT_EQ(keysOf(queue.takeFrame(true)), (Keys{{left, InputAction::Press}}));
  // The press waits for a frame of its own: a field clicked in a frame takes its characters.
  EXPECT_EQ(keysOf(queue.takeFrame(true)),
            (Keys{{left, InputAction::Release}, {s, InputAction::Press}, {0, InputAction::Character},
                  {s, InputAction::Release}}));
  EXPECT_EQ(keysOf(queue.takeFrame(true)), (Keys{{mouse, InputAction::Press}}));
  EXPECT_EQ(keysOf(queue.takeFrame(true)), (Keys{{mouse, InputAction::Release}}));
}

// The wheel goes through the queue too, in order with the clicks, and ends no frame.
TEST(InputQueue, TheWheelKeepsItsPlaceAfterAClick) {
  InputQueue queue;
  for (const InputEvent& e : {press(mouseKey(0)), release(mouseKey(0)), InputEvent{InputAction::Scroll}})
    queue.push(e);
  EXPECT_EQ(keysOf(queue.takeFrame()), (Keys{{mouseKey(0), InputAction::Press}}));
  EXPECT_EQ(keysOf(queue.takeFrame()), (Keys{{mouseKey(0), InputAction::Release}, {0, InputAction::Scroll}}));
}

TEST(FramePacer, DrawsWhileBusyAndAFewFramesAfterInputThenWaits) {
  FramePacer pacer;
  for (int k = 0; k < FramePacer::kSettleFrames; ++k) EXPECT_EQ(pacer.wait(false, false), 0);
  EXPECT_EQ(pacer.wait(false, false), FramePacer::kUntilInput);
  EXPECT_EQ(pacer.wait(true, false), 0);
  EXPECT_EQ(pacer.wait(false, true), FramePacer::kCaretBlinkSeconds);  // a caret blinks
  pacer.input();
  for (int k = 0; k < FramePacer::kSettleFrames; ++k) EXPECT_EQ(pacer.wait(false, false), 0);
  EXPECT_EQ(pacer.wait(false, false), FramePacer::kUntilInput);
}

}  // namespace
}  // namespace lloydscope
