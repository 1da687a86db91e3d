#include "text.h"

#include "report.h"

#include <imgui.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <tuple>
#include <utility>

namespace lloydscope {

void boxedText(ImDrawList* dl, ImVec2 where, const char* text) {
  const ImVec2 extent = ImGui::CalcTextSize(text);
  dl->AddRectFilled(ImVec2(where.x - 2, where.y), ImVec2(where.x + extent.x + 2, where.y + extent.y),
                    IM_COL32(255, 255, 255, 220));
  dl->AddText(where, IM_COL32(26, 26, 26, 255), text);
}

ImVec2 labelPlace(ImVec2 point, float gap, ImVec2 box, const ImVec4& pane, const std::vector<ImVec4>& placed) {
  const float x = point.x + gap + box.x + 2 > pane.z ? point.x - gap - box.x : point.x + gap;
  const auto free = [&](float y) {
    return y >= pane.y && y + box.y <= pane.w && std::none_of(placed.begin(), placed.end(), [&](const ImVec4& p) {
             return x < p.z && p.x < x + box.x && y < p.w && p.y < y + box.y;
           });
  };
  const float y = point.y - 0.5f * box.y;
  // Each shift tried, 0, +1, -1, +2, -2 ... lines, as far as twice as many lines each way as
  // there are boxes; where none is free, the label stays beside its point.
  for (int k = 0; k < 4 * static_cast<int>(placed.size()) + 1; ++k) {
    const float shifted = y + (k % 2 ? 1.0f : -1.0f) * ((k + 1) / 2) * (box.y + 1);
    if (free(shifted)) return ImVec2(x, shifted);
  }
  return ImVec2(x, y);
}

void addInspectorFonts(float pixelsPerUnit) {
  ImGuiIO& io = ImGui::GetIO();
  ImFontConfig small;  // as AddFontDefault() without one, but its size
  small.SizePixels = 13.0f * pixelsPerUnit;  // ImGui's own font is made for 13 px
  small.OversampleH = small.OversampleV = 1;
  small.PixelSnapH = true;
  io.Fonts->AddFontDefault(&small);
  // Greek, sub- and superscripts, arrows, maths: what the captions' formulas use beyond Latin-1.
  static const ImWchar maths[] = {0x0370, 0x03FF, 0x1D62, 0x1D62, 0x2070, 0x209F, 0x2190, 0x21FF,
                                  0x2200, 0x22FF, 0x2C7C, 0x2C7C, 0};
  static const ImWchar latin[] = {0x0020, 0x00FF, 0};
  const char* font = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";  // fonts-dejavu-core
  if (!std::ifstream(font).good()) return;
  // The maths go into the small default font too, whose own glyphs stop at Latin-1: a lesson's
  // caption outside presentation mode showed "c? = ? x ? dA".
  ImFontConfig merged;
  merged.MergeMode = true;
  io.Fonts->AddFontFromFileTTF(font, 13.0f * pixelsPerUnit, &merged, maths);
  for (float size : {21.0f, 42.0f}) {  // presentation mode's
    io.Fonts->AddFontFromFileTTF(font, size * pixelsPerUnit, nullptr, latin);
    io.Fonts->AddFontFromFileTTF(font, size * pixelsPerUnit, &merged, maths);
  }
}

float presentationTextSize(float height) { return 21.0f * std::max(1.0f, height / 800.0f); }

float numberColumnWidth(const std::string& header, const std::vector<std::string>& values) {
  float width = std::max(ImGui::CalcTextSize(header.c_str()).x, ImGui::CalcTextSize("00000").x);
  for (const std::string& value : values) width = std::max(width, ImGui::CalcTextSize(value.c_str()).x);
  return width;
}

bool steadyButton(const char* label, const std::vector<const char*>& labels) {
  float widest = 0;
  for (const char* each : labels) widest = std::max(widest, ImGui::CalcTextSize(each).x);
  return ImGui::Button(label, ImVec2(widest + 2 * ImGui::GetStyle().FramePadding.x, 0));
}

std::string wrappedLines(const std::string& text, float width, const std::string& gap) {
  const auto measure = [](const std::string& line) { return ImGui::CalcTextSize(line.c_str()).x; };
  std::string lines;
  for (const std::string& line : wrapAtSpaces(text, width, measure, gap)) lines += line + "\n";
  lines.pop_back();  // wrapAtSpaces gives one line at least
  return lines;
}

std::string inlineIndices(const std::string& text) {
  // The subscripts the captions use (UTF-8), and what each is written as.
  static const std::pair<const char*, char> kSubscripts[] = {
      {"\u1D62", 'i'}, {"\u2C7C", 'j'}, {"\u2096", 'k'}, {"\u2099", 'n'}, {"\u209B", 's'}, {"\u208A", '+'},
      {"\u208B", '-'}, {"\u2080", '0'}, {"\u2081", '1'}, {"\u2082", '2'}, {"\u2083", '3'}};
  const auto subscriptAt = [&](size_t at) -> std::pair<size_t, char> {
    for (const auto& [utf8, plain] : kSubscripts)
      if (text.compare(at, std::strlen(utf8), utf8) == 0) return {std::strlen(utf8), plain};
    return {0, 0};
  };
  std::string out;
  for (size_t at = 0; at < text.size();) {
    std::string run;  // the subscripts from here on
    for (auto [length, plain] = subscriptAt(at); length > 0; std::tie(length, plain) = subscriptAt(at)) {
      run += plain;
      at += length;
    }
    if (run.empty()) out += text[at++];
    else out += run.size() == 1 ? "_" + run : "_(" + run + ")";
  }
  return out;
}

void captionText(const std::string& title, const std::string& formula, const std::string& numbers) {
  ImGui::TextColored(ImVec4(0.6f, 0.15f, 0.0f, 1.0f), "%s", title.c_str());
  ImGui::SameLine();  // the formula's lines all start after the title
  ImGui::TextUnformatted(wrappedLines(formula, ImGui::GetContentRegionAvail().x).c_str());
  ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.0f, 0.15f, 0.5f, 1.0f));
  wrappedText(numbers);
  ImGui::PopStyleColor();
}

float captionTextHeight(const std::string& title, const std::string& formula, const std::string& numbers,
                        float width) {
  const ImGuiStyle& style = ImGui::GetStyle();
  const float formulaWidth = width - ImGui::CalcTextSize(title.c_str()).x - style.ItemSpacing.x;
  const float top = std::max(ImGui::CalcTextSize(wrappedLines(formula, formulaWidth).c_str()).y,
                             ImGui::CalcTextSize(title.c_str()).y);
  return top + style.ItemSpacing.y + ImGui::CalcTextSize(wrappedLines(numbers, width).c_str()).y;
}

void wrappedText(const std::string& text) {
  // One item of several lines: as tight as ImGui's own wrapped lines (an item a line would add
  // the spacing between items under each).
  ImGui::TextUnformatted(wrappedLines(text, ImGui::GetContentRegionAvail().x).c_str());
}

void wrappedTextInLines(const std::string& text, int lines) {
  const float top = ImGui::GetCursorPosY();
  wrappedText(text);
  // The cursor is now under the text and the spacing after it; it goes as far as the text
  // would go had it `lines` lines.
  const float rest = top + lines * ImGui::GetTextLineHeight() + ImGui::GetStyle().ItemSpacing.y - ImGui::GetCursorPosY();
  if (rest > 0) ImGui::SetCursorPosY(ImGui::GetCursorPosY() + rest);
}

void greyedText(const std::string& text) {
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  wrappedText(text);
  ImGui::PopStyleColor();
}

}  // namespace lloydscope
