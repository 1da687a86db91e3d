// Who has the inspector's keys: a text field, an open list, or the inspector's own commands.
// ImGui's state as of the last frame's end: call between frames or before a frame's widgets.
#pragma once

namespace lloydscope {

// A text field has the keyboard. ImGui's io.WantTextInput tells so as of the frame before: an
// L tapped just after a click left a field was taken as typing, not as the lesson's key.
bool textFieldActive();

// A list (a combo's) or another popup is open.
bool listOpen();

// Keys are the inspector's commands, unless a text field takes them (F typed into a mesh's
// name reset the views) or a list is open (L over the cell fill list started the lesson).
bool keysAreCommands();

// Escape closes an open list; true if it did. ImGui 1.86 closes one with Escape only under
// keyboard navigation, which would take the arrow keys from the iterations.
bool closeListOnEscape();

}  // namespace lloydscope
