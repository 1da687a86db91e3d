// The inspector's fonts: ImGui's own small one, with the captions' Greek and maths merged in,
// and a large one for presentations. Apart from the inspector so that the tests can check them
// without a window or a GPU.
#pragma once

namespace lloydscope {

// Call once after ImGui::CreateContext(), before the font texture is uploaded. Without
// DejaVu Sans (fonts-dejavu-core) only ImGui's own font is there.
void addInspectorFonts();

}  // namespace lloydscope
