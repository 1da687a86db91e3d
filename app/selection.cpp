#include "selection.h"

#include "report.h"
#include "text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

namespace lloydscope {

namespace {

template <class Pin>
bool pinned(const std::vector<Pin>& pins, const Pin& pin) {
  return std::find(pins.begin(), pins.end(), pin) != pins.end();
}

template <class Pin>
void toggle(std::vector<Pin>& pins, const Pin& pin) {
  const auto found = std::find(pins.begin(), pins.end(), pin);
  if (found != pins.end()) pins.erase(found);
  else pins.push_back(pin);
}

template <class Pin>
void pin(std::vector<Pin>& pins, const Pin& pin) {
  if (!pinned(pins, pin)) toggle(pins, pin);
}

// "site 12, site 40 and site 41" (a corner that is no site: "vertex 7").
std::string cornersText(const TriangleCorners& corners) {
  std::string text;
  for (int k = 0; k < 3; ++k)
    text += std::string(k == 0 ? "" : k == 1 ? ", " : " and ") +
            (corners[k] >= 0 ? "site " + std::to_string(corners[k]) : "vertex " + std::to_string(-1 - corners[k]));
  return text;
}

// A pinned triangle, filled and outlined, and ringed: a sliver of the result is a few pixels,
// and the worst triangle pinned could not be found in either view.
// `behind`: the surface hides it; its ring alone is drawn, dashed, where it would be.
void drawPinnedTriangle(ImDrawList* dl, const ImVec2 (&corners)[3], float fillAlpha, bool behind = false) {
  const ImVec2 centre((corners[0].x + corners[1].x + corners[2].x) / 3,
                      (corners[0].y + corners[1].y + corners[2].y) / 3);
  float radius = 14.0f;
  for (const ImVec2& c : corners) radius = std::max(radius, std::hypot(c.x - centre.x, c.y - centre.y) + 6.0f);
  if (behind) {
    constexpr int kDashes = 12;
    for (int k = 0; k < kDashes; ++k) {
      const float pi = static_cast<float>(M_PI), a0 = 2 * pi * k / kDashes, a1 = a0 + pi / kDashes;
      dl->PathArcTo(centre, radius, a0, a1, 6);
      dl->PathStroke(Selection::triangleColor(), 0, 2.5f);
    }
    return;
  }
  dl->AddTriangleFilled(corners[0], corners[1], corners[2], Selection::triangleColor(fillAlpha));
  dl->AddPolyline(corners, 3, Selection::triangleColor(), ImDrawFlags_Closed, 2.5f);
  dl->AddCircle(centre, radius, Selection::triangleColor(), 32, 2.5f);
}

// Whether another triangle of `mesh` lies between the eye and `triangle`'s centre.
bool hiddenFrom(const Mesh& mesh, int triangle, const Vec3& eye) {
  const Triangle& t = mesh.triangles[triangle];
  const Vec3 centre = (mesh.points[t[0]] + mesh.points[t[1]] + mesh.points[t[2]]) / 3.0;
  const int first = triangleOnRay(mesh, eye, centre - eye);
  return first >= 0 && first != triangle;
}

// The pins' marks are drawn over the mesh, with no depth test: one behind the surface (the
// mushroom's worst triangle, under its cap) is a dashed ring, not filled as if on top.
void drawPinnedTriangles3D(ImDrawList* dl, const Mesh& mesh, const std::vector<int>& pins,
                           const ScreenOf3D& screen, const Vec3& eye) {
  for (int triangle : pins) {
    if (triangle >= static_cast<int>(mesh.triangles.size())) continue;
    const Triangle& t = mesh.triangles[triangle];
    ImVec2 corners[3];
    bool visible = true;
    for (int k = 0; k < 3; ++k) visible = visible && screen(mesh.points[t[k]], corners[k]);
    if (visible) drawPinnedTriangle(dl, corners, 0.45f, hiddenFrom(mesh, triangle, eye));
  }
}

// The radius of the ring around a pinned cell's site, in pixels: smaller as the sites crowd.
float siteRing(const IterationView& view, float scale) {
  return std::clamp(0.3f * scale / std::sqrt(float(view.sites.size()) + 1), 3.0f, 8.0f);
}

}  // namespace

ImU32 Selection::cellColor(float alpha) {
  return ImGui::ColorConvertFloat4ToU32(ImVec4(0.85f, 0.05f, 0.7f, alpha));
}
ImU32 Selection::triangleColor(float alpha) {
  return ImGui::ColorConvertFloat4ToU32(ImVec4(0.0f, 0.55f, 0.45f, alpha));
}

// Index -1: the click hit nothing.
void Selection::toggleCell(int cell) {
  if (cell >= 0) toggle(cells_, cell);
}
void Selection::toggleTriangle(const IterationView& view, int triangle) {
  if (triangle >= 0) toggle(triangles_, cornersOf(view, triangle));
}
void Selection::pinCell(int cell) { pin(cells_, cell); }
void Selection::pinTriangle(const IterationView& view, int triangle) { pin(triangles_, cornersOf(view, triangle)); }
bool Selection::cellPinned(int cell) const { return pinned(cells_, cell); }
void Selection::toggleFinalTriangle(int triangle) {
  if (triangle >= 0) toggle(finalTriangles_, triangle);
}
void Selection::pinFinalTriangle(int triangle) { pin(finalTriangles_, triangle); }

std::vector<int> Selection::trianglesIn(const IterationView& view) const {
  std::vector<int> found;
  for (const TriangleCorners& corners : triangles_)
    if (const int triangle = triangleWithCorners(view, corners); triangle >= 0) found.push_back(triangle);
  return found;
}
void Selection::clear() {
  cells_.clear();
  triangles_.clear();
  finalTriangles_.clear();
}

void Selection::draw2D(ImDrawList* dl, const Recording& recording, const IterationView& view,
                       const ScreenOfUV& screen, float scale, bool cellsShown, bool resultShown,
                       const std::vector<ImVec4>& keepClear) const {
  for (int cell : cellsShown ? cells_ : std::vector<int>{}) {
    if (cell >= static_cast<int>(view.cells.size())) continue;
    for (const CellPiece& piece : view.cells[cell].pieces) {
      std::vector<ImVec2> points;
      for (const Vec2& p : piece.polygon) points.push_back(screen(p));
      dl->AddConvexPolyFilled(points.data(), static_cast<int>(points.size()), cellColor(0.3f));
    }
    std::vector<ImVec2> path;
    for (const Vec2& p : siteTrajectory(recording, cell)) path.push_back(screen(p));
    dl->AddPolyline(path.data(), static_cast<int>(path.size()), cellColor(), 0, 1.5f);
    dl->AddCircle(screen(view.sites[cell]), siteRing(view, scale), cellColor(), 0, 2.0f);
  }
  // With two cells pinned or more, each is labelled with its number beside its site: the
  // selection panel and the lesson's caption (the cell pinned last) name them by number, and
  // two magenta cells could not be told apart. After every fill, which would cover a label.
  if (cellsShown && cells_.size() > 1) {
    // The boxes labels may not cover (min x, min y, max x, max y): those kept clear, the pinned
    // sites' rings, then each label placed.
    std::vector<ImVec4> placed = keepClear;
    const float ring = siteRing(view, scale);
    const ImVec2 low = dl->GetClipRectMin(), high = dl->GetClipRectMax();
    for (int cell : cells_)
      if (cell < static_cast<int>(view.cells.size())) {
        const ImVec2 site = screen(view.sites[cell]);
        placed.emplace_back(site.x - ring, site.y - ring, site.x + ring, site.y + ring);
      }
    for (int cell : cells_) {
      if (cell >= static_cast<int>(view.cells.size())) continue;
      const std::string label = "cell " + std::to_string(cell);
      const ImVec2 box = ImGui::CalcTextSize(label.c_str()), site = screen(view.sites[cell]);
      const ImVec2 at = labelPlace(site, ring + 4, box, ImVec4(low.x, low.y, high.x, high.y), placed);
      placed.emplace_back(at.x, at.y, at.x + box.x, at.y + box.y);
      // A leader from the ring to the label: a label moved a line off names its site still.
      const bool onTheRight = at.x > site.x;
      const ImVec2 from(site.x + (onTheRight ? ring : -ring), site.y),
          to(onTheRight ? at.x - 2 : at.x + box.x + 2, at.y + 0.5f * box.y);
      dl->AddLine(from, to, IM_COL32(255, 255, 255, 220), 4.0f);  // on a halo: over the cells' lines
      dl->AddLine(from, to, cellColor(), 2.0f);
      boxedText(dl, at, label.c_str());
    }
  }
  for (int triangle : resultShown ? trianglesIn(view) : std::vector<int>{}) {
    const Triangle& t = view.output.triangles[triangle];
    const ImVec2 corners[3] = {screen(view.outputUV[t[0]]), screen(view.outputUV[t[1]]),
                               screen(view.outputUV[t[2]])};
    drawPinnedTriangle(dl, corners, 0.35f);
  }
}

void Selection::draw3D(ImDrawList* dl, const Recording& recording, const Domain& domain,
                       const IterationView& view, const ScreenOf3D& screen, const Vec3& eye,
                       bool cellsShown, bool resultShown) const {
  ImVec2 a, b;
  for (int cell : cellsShown ? cells_ : std::vector<int>{}) {
    if (cell >= static_cast<int>(view.cells.size())) continue;
    for (const auto& [p, q] : cellOutline(domain, view.cells[cell]))
      if (screen(lift(recording.input, domain, p), a) && screen(lift(recording.input, domain, q), b))
        dl->AddLine(a, b, cellColor(), 2.5f);
    if (screen(view.liftedSites[cell], a)) dl->AddCircleFilled(a, 4.0f, cellColor());
  }
  if (resultShown) drawPinnedTriangles3D(dl, view.output, trianglesIn(view), screen, eye);
}

void Selection::drawFinal3D(ImDrawList* dl, const Mesh& final, const ScreenOf3D& screen, const Vec3& eye) const {
  drawPinnedTriangles3D(dl, final, finalTriangles_, screen, eye);
}

void Selection::detailsPanel(const Recording& recording, const Domain& domain,
                             const IterationView& view, const Mesh& final) {
  if (empty()) {
    greyedText("Click a cell (2D) or a triangle (3D) to pin it; click again to unpin, Escape clears all.");
    return;
  }
  int unpinCell = -1;
  std::optional<TriangleCorners> unpinTriangle;
  // Each table's rows are formatted first: the value column takes the widest value (at most
  // two thirds of the pane) and the labels wrap in what is left. A fixed width cut the 3D
  // coordinates of a model in millimetres short.
  auto table = [](const char* id, const DetailRows& rows) {
    float widest = 0;
    for (const auto& r : rows) widest = std::max(widest, ImGui::CalcTextSize(r.second.c_str()).x);
    if (ImGui::BeginTable(id, 2, ImGuiTableFlags_RowBg)) {
      ImGui::TableSetupColumn("label", ImGuiTableColumnFlags_WidthStretch);
      ImGui::TableSetupColumn("value", ImGuiTableColumnFlags_WidthFixed,
                              std::min(widest, 2.0f / 3.0f * ImGui::GetContentRegionAvail().x));
      for (const auto& [label, value] : rows) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        wrappedText(label);
        ImGui::TableNextColumn();
        wrappedText(value);
      }
      ImGui::EndTable();
    }
  };
  for (int cell : cells_) {
    const CellDetails d = describeCell(recording, domain, view, cell);
    if (d.index < 0) continue;
    ImGui::PushID(cell);
    ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(cellColor()), "Cell %d (%s)", cell,
                       d.fixed ? "fixed, border" : "movable");
    ImGui::SameLine();
    if (ImGui::SmallButton("unpin")) unpinCell = cell;
    table("cell", cellRows(d));
    ImGui::PopID();
  }
  // A pinned triangle's table: of an iteration's result (`mapped`: with its UV numbers and its
  // corners' sites) or of the final result (3D only). True where its unpin was clicked.
  auto triangleTable = [&](const TriangleDetails& d, const char* scope, const std::string& heading, bool mapped) {
    ImGui::PushID(scope);
    ImGui::PushID(d.index);
    ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(triangleColor()), "%s", heading.c_str());
    ImGui::SameLine();
    const bool unpin = ImGui::SmallButton("unpin");
    table(scope, triangleRows(d, mapped));
    ImGui::PopID();
    ImGui::PopID();
    return unpin;
  };
  // Each pinned triangle as this iteration has it, under its number here; where its corners make
  // no triangle here, said (scrubbing on shows it again). Its number changed from iteration to
  // iteration, and a pin by number showed another triangle at each.
  std::string notTriangles;
  for (const TriangleCorners& corners : triangles_)
    if (const int triangle = triangleWithCorners(view, corners); triangle >= 0) {
      if (triangleTable(describeTriangle(view, triangle), "triangle", "Triangle " + std::to_string(triangle), true))
        unpinTriangle = corners;
    } else {
      notTriangles += (notTriangles.empty() ? "" : " ") + ("The pinned triangle of " + cornersText(corners) +
                                                          " is not one of this iteration's.");
    }
  int unpinFinal = -1;
  for (int triangle : finalTriangles_)
    if (const TriangleDetails d = describeTriangle(final, triangle); d.index >= 0)
      if (triangleTable(d, "final triangle", "Final result, triangle " + std::to_string(triangle), false))
        unpinFinal = triangle;
  // Pins this view cannot show (a cell of a run with more sites, corners that make no triangle
  // here, a final triangle of another run) are said, not dropped: scrubbing back shows them again.
  const std::string notShown[] = {pinsNotShown(cells_, view.cells.size(), "cell", "this iteration"), notTriangles,
                                  pinsNotShown(finalTriangles_, final.triangles.size(), "triangle", "the final result")};
  bool anyNotShown = false;
  for (const std::string& note : notShown)
    if (!note.empty()) {
      greyedText(note);
      anyNotShown = true;
    }
  if (anyNotShown) greyedText("Escape unpins every cell and triangle.");
  toggleCell(unpinCell);
  if (unpinTriangle) toggle(triangles_, *unpinTriangle);
  toggleFinalTriangle(unpinFinal);
}

}  // namespace lloydscope
