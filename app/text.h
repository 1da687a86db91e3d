// How the inspector writes: its fonts (ImGui's own small one, with the captions' Greek and maths
// merged in, and a large one for presentations) and its wrapped text. Apart from the inspector so
// that the tests can check them without a window or a GPU.
#pragma once

#include <string>

namespace lloydscope {

// Call once after ImGui::CreateContext(), before the font texture is uploaded. Without
// DejaVu Sans (fonts-dejavu-core) only ImGui's own font is there.
void addInspectorFonts();

// `text` wrapped to the room left on the line (a pane's or a table cell's), broken at spaces
// only (wrapAtSpaces): ImGui::TextWrapped broke numbers after their decimal point.
void wrappedText(const std::string& text);

}  // namespace lloydscope
