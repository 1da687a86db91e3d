// Every character the inspector's lesson captions use has a glyph in both of its fonts: the
// small one it draws with outside presentation mode, and the presentation one. (Outside
// presentation mode a caption read "c? = ? x ? dA": the small font stopped at Latin-1.)
#include "text.h"
#include "lesson.h"

#include <gtest/gtest.h>
#include <imgui.h>

#include <fstream>
#include <string>
#include <vector>

using namespace lloydscope;

namespace {

// The code points of UTF-8 text.
std::vector<unsigned> codePoints(const std::string& text) {
  std::vector<unsigned> points;
  for (size_t i = 0; i < text.size();) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    const int length = c < 0x80 ? 1 : c < 0xE0 ? 2 : c < 0xF0 ? 3 : 4;
    unsigned point = length == 1 ? c : c & (0x3F >> (length - 1));
    for (int k = 1; k < length && i + k < text.size(); ++k) point = point << 6 | (text[i + k] & 0x3F);
    points.push_back(point);
    i += length;
  }
  return points;
}

// Every caption of every stage, for each solver, with and without a pinned cell.
std::vector<std::string> everyCaption() {
  std::vector<std::string> texts;
  CaptionFacts facts;
  facts.iterations = 10;
  facts.iteration = 2;
  CellDetails cell;
  cell.index = 4;
  for (const char* solver : {"lloyd", "lbfgs", "newton"})
    for (bool pinned : {false, true})
      for (bool firstPass : {false, true}) {
        facts.solver = solver;
        facts.firstPass = firstPass;
        if (pinned) facts.cell = cell;
        else facts.cell.reset();
        for (Stage stage : {Stage::Load, Stage::Parameterize, Stage::Voronoi, Stage::Centroids, Stage::Move,
                            Stage::Lift, Stage::Result, Stage::Valence}) {
          const Caption c = caption(stage, facts);
          texts.insert(texts.end(), {c.title, c.formula, c.numbers});
        }
      }
  return texts;
}

// An ImGui context of that display size, its default font built, for laying out without a
// window (ImGui::DestroyContext() after).
void startImGui(ImVec2 display) {
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;
  io.DisplaySize = display;
  io.DeltaTime = 1.0f / 60.0f;
  unsigned char* pixels = nullptr;
  int atlasWidth = 0, atlasHeight = 0;
  io.Fonts->GetTexDataAsRGBA32(&pixels, &atlasWidth, &atlasHeight);
}

}  // namespace

TEST(Fonts, EveryCaptionCharacterHasAGlyphInBothFonts) {
  if (!std::ifstream("/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf").good())
    GTEST_SKIP() << "fonts-dejavu-core is not installed (./build.sh installs it)";
  ImGui::CreateContext();
  addInspectorFonts();
  ImFontAtlas* atlas = ImGui::GetIO().Fonts;
  unsigned char* pixels = nullptr;
  int width = 0, height = 0;
  atlas->GetTexDataAsRGBA32(&pixels, &width, &height);  // builds the glyphs, on the CPU
  ASSERT_EQ(atlas->Fonts.Size, 3);
  int nonAscii = 0;
  for (const std::string& text : everyCaption())
    for (unsigned point : codePoints(text)) {
      if (point < 0x20) continue;
      nonAscii += point > 0x7F;
      for (ImFont* font : {atlas->Fonts[0], atlas->Fonts[1], atlas->Fonts[2]})
        EXPECT_NE(font->FindGlyphNoFallback(static_cast<ImWchar>(point)), nullptr)
            << "U+" << std::hex << point << " in \"" << text << "\"";
    }
  EXPECT_GT(nonAscii, 0);  // the captions do use Greek and maths
  ImGui::DestroyContext();
}

// In ImGui's small font the subscripts were smudges four pixels high: written inline there.
TEST(Text, SubscriptsAreWrittenInlineForTheSmallFont) {
  EXPECT_EQ(inlineIndices("gradient 2 Mᵢ (sᵢ − cᵢ)"), "gradient 2 M_i (s_i − c_i)");
  EXPECT_EQ(inlineIndices("½ Σ (xⱼ yⱼ₊₁ − xⱼ₊₁ yⱼ)"), "½ Σ (x_j y_(j+1) − x_(j+1) y_j)");
  EXPECT_EQ(inlineIndices("ρ |x − s|² dA, 30°"), "ρ |x − s|² dA, 30°");  // nothing else changes
  EXPECT_EQ(inlineIndices(""), "");
}

// The caption pane is as tall as its caption: laid out in a pane, the caption ends where
// captionTextHeight says, at every width (the pane was three lines tall whatever the caption,
// and a caption of four lost its last line at 960x600).
TEST(Text, TheCaptionTakesTheHeightItIsGiven) {
  startImGui(ImVec2(1200, 600));
  CaptionFacts facts;
  facts.solver = "lbfgs";
  facts.iteration = 2;
  facts.iterations = 191;
  facts.arrowScale = 10;
  CellDetails cell;
  cell.index = 100;
  facts.cell = cell;
  const Caption c = caption(Stage::Move, facts);
  float lastHeight = 0;
  for (float width : {1100.0f, 600.0f, 300.0f}) {
    ImGui::NewFrame();
    ImGui::SetNextWindowPos(ImVec2(0, 0));
    ImGui::SetNextWindowSize(ImVec2(width, 600));
    ImGui::Begin("caption", nullptr, ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar);
    const float room = ImGui::GetContentRegionAvail().x, top = ImGui::GetCursorPosY();
    captionText(c.title, c.formula, c.numbers);
    const float taken = ImGui::GetCursorPosY() - ImGui::GetStyle().ItemSpacing.y - top;
    const float given = captionTextHeight(c.title, c.formula, c.numbers, room);
    ImGui::End();
    ImGui::EndFrame();
    EXPECT_NEAR(taken, given, 0.5f) << width;
    EXPECT_GT(given, lastHeight) << width;  // narrower, taller
    lastHeight = given;
  }
  EXPECT_GT(lastHeight, 4 * ImGui::GetTextLineHeight());
  ImGui::DestroyContext();
}

// The run's state line took one line or two as the run went on ("Running: 9 iterations so far",
// "Stopped after 120 iterations: Step or Run goes on"), and every control under it moved. In
// two lines at least, one line of text ends where two do, and three go on.
TEST(Text, TextInTwoLinesEndsWhereTwoLinesDo) {
  startImGui(ImVec2(800, 600));
  const auto bottom = [](const std::string& text, bool inLines) {
    ImGui::NewFrame();
    ImGui::SetNextWindowPos(ImVec2(0, 0));
    ImGui::SetNextWindowSize(ImVec2(280, 600));
    ImGui::Begin("controls", nullptr, ImGuiWindowFlags_NoTitleBar);
    if (inLines) wrappedTextInLines(text, 2);
    else wrappedText(text);
    const float y = ImGui::GetCursorPosY();
    ImGui::End();
    ImGui::EndFrame();
    return y;
  };
  const std::string one = "Running: 9 iterations so far", two = "Stopped after 120 iterations: Step or Run goes on, "
                                                                   "and so on and so on",
                    three = two + ", and on and on, and on and on and on";
  ASSERT_LT(bottom(one, false), bottom(two, false));  // one line, two lines
  EXPECT_FLOAT_EQ(bottom(one, true), bottom(two, false));
  EXPECT_FLOAT_EQ(bottom(two, true), bottom(two, false));
  EXPECT_GT(bottom(three, true), bottom(two, true));
  ImGui::DestroyContext();
}

// Table II's number columns were five digits wide: "100000" (vertices at 100,000 sites) was cut
// short.
TEST(Text, ANumberColumnFitsItsWidestNumber) {
  startImGui(ImVec2(800, 600));
  ImGui::NewFrame();
  const float fiveDigits = ImGui::CalcTextSize("00000").x;
  EXPECT_FLOAT_EQ(numberColumnWidth("It. 5", {"500", "73.2"}), fiveDigits);  // steady while scrubbing
  EXPECT_FLOAT_EQ(numberColumnWidth("It. 1000", {"500"}), ImGui::CalcTextSize("It. 1000").x);
  EXPECT_FLOAT_EQ(numberColumnWidth("It. 5", {"100000", "199801"}), ImGui::CalcTextSize("100000").x);
  EXPECT_GT(ImGui::CalcTextSize("100000").x, fiveDigits);
  ImGui::EndFrame();
  ImGui::DestroyContext();
}

// In presentation mode's proportional font "Play " was narrower than "Pause": the buttons after
// it moved at each press. The next control stands at the same place whichever label it shows.
TEST(Text, ASteadyButtonKeepsTheNextControlInPlace) {
  startImGui(ImVec2(800, 600));
  const auto nextControlAt = [](const char* label) {
    ImGui::NewFrame();
    ImGui::SetNextWindowPos(ImVec2(0, 0));
    ImGui::Begin("timeline");
    steadyButton(label, {"Lesson", "End lesson"});
    ImGui::SameLine();
    const float x = ImGui::GetCursorPosX();
    ImGui::End();
    ImGui::EndFrame();
    return x;
  };
  EXPECT_FLOAT_EQ(nextControlAt("Lesson"), nextControlAt("End lesson"));
  EXPECT_GT(ImGui::CalcTextSize("End lesson").x, ImGui::CalcTextSize("Lesson").x);  // plain buttons would move it
  ImGui::DestroyContext();
}

// Presentation mode's type was 21 px whatever the window: a hundredth of a 2560x1600 picture.
TEST(Text, PresentationTypeGrowsWithTheWindow) {
  EXPECT_FLOAT_EQ(presentationTextSize(600), 21.0f);  // never smaller
  EXPECT_FLOAT_EQ(presentationTextSize(800), 21.0f);
  EXPECT_FLOAT_EQ(presentationTextSize(1600), 42.0f);
}

// A pinned cell's label goes on its site's right, or its left at the pane's right edge; where it
// would cover another site or a label placed before, a line lower, then higher: two cells side
// by side had their labels one over the other ("cell 420 300"), and a label covered the next
// pinned site.
TEST(Text, ALabelGoesWhereItCoversNothingPlacedBefore) {
  const ImVec2 box(60, 13);
  const ImVec4 pane(0, 0, 500, 400);
  EXPECT_EQ(labelPlace(ImVec2(100, 100), 8, box, pane, {}).x, 108);
  EXPECT_EQ(labelPlace(ImVec2(100, 100), 8, box, pane, {}).y, 93.5f);
  EXPECT_EQ(labelPlace(ImVec2(480, 100), 8, box, pane, {}).x, 412);  // on the left
  // A label there already: the next goes a line lower; with a second below it, a line higher.
  std::vector<ImVec4> placed = {ImVec4(108, 93.5f, 168, 106.5f)};
  EXPECT_EQ(labelPlace(ImVec2(110, 100), 8, box, pane, placed).y, 93.5f + 14);
  placed.push_back(ImVec4(118, 107.5f, 178, 120.5f));
  EXPECT_EQ(labelPlace(ImVec2(110, 100), 8, box, pane, placed).y, 93.5f - 14);
  // Another site's ring on the right (5 px across): the label moves off it too.
  const ImVec2 at = labelPlace(ImVec2(100, 100), 8, box, pane, {ImVec4(130, 95, 140, 105)});
  EXPECT_TRUE(at.y + box.y <= 95 || at.y >= 105) << at.y;
  // At the pane's top, the line above is out of it: two lines lower.
  EXPECT_EQ(labelPlace(ImVec2(100, 8), 8, box, pane, {ImVec4(108, 1.5f, 168, 14.5f), ImVec4(108, 15.5f, 168, 28.5f)}).y,
            1.5f + 28);
}
