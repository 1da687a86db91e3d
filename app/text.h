// How the inspector writes: its fonts (ImGui's own small one, with the captions' Greek and maths
// merged in, and a large one for presentations) and its wrapped text. Apart from the inspector so
// that the tests can check them without a window or a GPU.
#pragma once

#include <imgui.h>

#include <string>
#include <vector>

namespace lloydscope {

// Dark text on a light box: over the 2D cells or a zoomed 3D mesh, a dark label on dark
// triangles could not be read.
void boxedText(ImDrawList* dl, ImVec2 where, const char* text);

// Where a label `box` big goes beside a point (a pinned cell's site): on its right, `gap`
// away, or on its left where the `pane` would cut it (a border cell's), and a line lower, then
// higher, and so on, where it would cover one of the `placed` boxes or leave the pane (boxes as
// min x, min y, max x, max y; placed: other sites, labels placed before).
ImVec2 labelPlace(ImVec2 point, float gap, ImVec2 box, const ImVec4& pane, const std::vector<ImVec4>& placed);

// Call once after ImGui::CreateContext(), before the font texture is uploaded. Without
// DejaVu Sans (fonts-dejavu-core) only ImGui's own font is there.
// Fonts[0] the small one, [1] and [2] presentation mode's at 21 and 42 px (where DejaVu Sans is
// there): the larger for large windows, so that a projector's type is drawn, not magnified.
// Each is drawn `pixelsPerUnit` times as large (on a screen of twice the usual density, 2: see
// ImGuiIO::DisplayFramebufferScale), and ImGuiIO::FontGlobalScale brings it back to its size in
// the layout: sharp, not magnified.
void addInspectorFonts(float pixelsPerUnit = 1.0f);

// The size of presentation mode's type in a window `height` pixels tall: 21 px up to 800, and
// the same part of the height above (at 2560x1600 it was a hundredth of the picture).
float presentationTextSize(float height);

// `text` in lines no wider than `width` pixels in the current font, joined by line breaks,
// broken at `gap`s only (wrapAtSpaces).
std::string wrappedLines(const std::string& text, float width, const std::string& gap = " ");

// A table column of numbers in the current font: as wide as its header, its widest value or
// five digits (steady while scrubbing), whichever is widest. Five digits alone cut "100000"
// short at 100,000 sites.
float numberColumnWidth(const std::string& header, const std::vector<std::string>& values);

// A button showing `label`, as wide as the widest of `labels` (the labels it changes between):
// the controls after it stay where they are when its label changes. ("Play " padded to Pause's
// width in ImGui's fixed-width font; in presentation mode's proportional font the buttons after
// it moved 10 px at each press.) True when pressed.
bool steadyButton(const char* label, const std::vector<const char*>& labels);

// `text` with its subscripts written inline for ImGui's small font, which draws them as smudges a
// few pixels high: "sᵢ" as "s_i", "yⱼ₊₁" as "y_(j+1)". Other characters stay as they are.
std::string inlineIndices(const std::string& text);

// A lesson caption as its pane shows it: the title (dark red), the formula wrapped beside it,
// the numbers (blue) wrapped under both, in the room left on the line.
void captionText(const std::string& title, const std::string& formula, const std::string& numbers);
// The height captionText takes in `width` pixels (the pane is made that tall: a caption of
// four lines in a pane of three lost its last line).
float captionTextHeight(const std::string& title, const std::string& formula, const std::string& numbers,
                        float width);

// `text` wrapped to the room left on the line (a pane's or a table cell's), broken at spaces
// only (wrapAtSpaces): ImGui::TextWrapped broke numbers after their decimal point.
void wrappedText(const std::string& text);
// The same, greyed: a hint or a note beside the numbers.
void greyedText(const std::string& text);
// wrappedText taking `lines` lines at least: a line whose text changes as a run goes on
// ("Running: 9 iterations so far", then "Stopped after ...: Step or Run goes on" over two)
// moved every control under it, and a click aimed at one landed on its neighbour.
void wrappedTextInLines(const std::string& text, int lines);

}  // namespace lloydscope
