#include "selection.h"

#include <algorithm>
#include <string>

namespace lloydscope {

namespace {

void toggle(std::vector<int>& pins, int index) {
  if (index < 0) return;
  const auto found = std::find(pins.begin(), pins.end(), index);
  if (found != pins.end()) pins.erase(found);
  else pins.push_back(index);
}

}  // namespace

ImU32 Selection::cellColor(float alpha) {
  return ImGui::ColorConvertFloat4ToU32(ImVec4(0.85f, 0.05f, 0.7f, alpha));
}
ImU32 Selection::triangleColor(float alpha) {
  return ImGui::ColorConvertFloat4ToU32(ImVec4(0.0f, 0.55f, 0.45f, alpha));
}

void Selection::toggleCell(int cell) { toggle(cells_, cell); }
void Selection::toggleTriangle(int triangle) { toggle(triangles_, triangle); }
void Selection::clear() {
  cells_.clear();
  triangles_.clear();
}

void Selection::draw2D(ImDrawList* dl, const Recording& recording, const IterationView& view,
                       const ScreenOfUV& screen, float scale) const {
  for (int cell : cells_) {
    if (cell >= static_cast<int>(view.cells.size())) continue;
    for (const CellPiece& piece : view.cells[cell].pieces) {
      std::vector<ImVec2> points;
      for (const Vec2& p : piece.polygon) points.push_back(screen(p));
      dl->AddConvexPolyFilled(points.data(), static_cast<int>(points.size()), cellColor(0.3f));
    }
    std::vector<ImVec2> path;
    for (const Vec2& p : siteTrajectory(recording, cell)) path.push_back(screen(p));
    dl->AddPolyline(path.data(), static_cast<int>(path.size()), cellColor(), 0, 1.5f);
    const float r = std::clamp(0.3f * scale / std::sqrt(float(view.sites.size()) + 1), 3.0f, 8.0f);
    dl->AddCircle(screen(view.sites[cell]), r, cellColor(), 0, 2.0f);
  }
  for (int triangle : triangles_) {
    if (triangle >= static_cast<int>(view.output.triangles.size())) continue;
    const Triangle& t = view.output.triangles[triangle];
    const ImVec2 corners[3] = {screen(view.outputUV[t[0]]), screen(view.outputUV[t[1]]),
                               screen(view.outputUV[t[2]])};
    dl->AddTriangleFilled(corners[0], corners[1], corners[2], triangleColor(0.35f));
    dl->AddPolyline(corners, 3, triangleColor(), ImDrawFlags_Closed, 2.5f);
  }
}

void Selection::draw3D(ImDrawList* dl, const Recording& recording, const Domain& domain,
                       const IterationView& view, const ScreenOf3D& screen,
                       bool resultShown) const {
  ImVec2 a, b;
  for (int cell : cells_) {
    if (cell >= static_cast<int>(view.cells.size())) continue;
    for (const auto& [p, q] : cellOutline(domain, view.cells[cell]))
      if (screen(lift(recording.input, domain, p), a) && screen(lift(recording.input, domain, q), b))
        dl->AddLine(a, b, cellColor(), 2.5f);
    if (screen(view.liftedSites[cell], a)) dl->AddCircleFilled(a, 4.0f, cellColor());
  }
  if (!resultShown) return;
  for (int triangle : triangles_) {
    if (triangle >= static_cast<int>(view.output.triangles.size())) continue;
    const Triangle& t = view.output.triangles[triangle];
    ImVec2 corners[3];
    bool visible = true;
    for (int k = 0; k < 3; ++k) visible = visible && screen(view.output.points[t[k]], corners[k]);
    if (!visible) continue;
    dl->AddTriangleFilled(corners[0], corners[1], corners[2], triangleColor(0.45f));
    dl->AddPolyline(corners, 3, triangleColor(), ImDrawFlags_Closed, 2.5f);
  }
}

void Selection::detailsPanel(const Recording& recording, const Domain& domain,
                             const IterationView& view) {
  if (empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("Click a cell (2D) or a triangle (3D) to pin it; click again to unpin, "
                       "Escape clears all.");
    ImGui::PopStyleColor();
    return;
  }
  int unpinCell = -1, unpinTriangle = -1;
  auto row = [](const char* label, const char* pattern, auto... values) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextWrapped("%s", label);
    ImGui::TableNextColumn();
    ImGui::Text(pattern, values...);
  };
  // The values keep the width of three coordinates and the labels wrap in what is left: in a
  // window 1280 pixels wide the values of "s, 3D" and "int x rho" were cut short.
  const ImGuiTableFlags table = ImGuiTableFlags_RowBg;
  auto columns = [] {
    ImGui::TableSetupColumn("label", ImGuiTableColumnFlags_WidthStretch);
    ImGui::TableSetupColumn("value", ImGuiTableColumnFlags_WidthFixed, ImGui::CalcTextSize("-0.000 -0.000 -0.000").x);
  };
  for (int cell : cells_) {
    const CellDetails d = describeCell(recording, domain, view, cell);
    if (d.index < 0) continue;
    ImGui::PushID(cell);
    ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(cellColor()), "Cell %d (%s)", cell,
                       d.fixed ? "fixed, border" : "movable");
    ImGui::SameLine();
    if (ImGui::SmallButton("unpin")) unpinCell = cell;
    if (ImGui::BeginTable("cell", 2, table)) {
      columns();
      row("site s", "%.5f %.5f", d.site.x(), d.site.y());
      row("centroid c", "%.5f %.5f", d.centroid.x(), d.centroid.y());
      row("s, 3D", "%.3f %.3f %.3f", d.site3D.x(), d.site3D.y(), d.site3D.z());
      row("c, 3D", "%.3f %.3f %.3f", d.centroid3D.x(), d.centroid3D.y(), d.centroid3D.z());
      row("area, UV", "%.4e", d.area);
      row("area, surface", "%.4e", d.surfaceArea);
      row("A = 1/2 sum c_i", "%.4e", d.shoelaceArea);
      row("sum (x_i+x_i+1)c_i", "%.4e", d.shoelaceSums.x());
      row("sum (y_i+y_i+1)c_i", "%.4e", d.shoelaceSums.y());
      row("M = int rho", "%.4e", d.mass);
      row("int x rho", "%.3e %.3e", d.moment.x(), d.moment.y());
      const Vec2 quotient = d.mass > 0 ? Vec2(d.moment / d.mass) : d.site;  // = centroid c, worked out
      row("c = int x rho/M", "%.5f %.5f", quotient.x(), quotient.y());
      row("E=int rho|x-s|^2", "%.3e", d.energy);
      row("|c - s|", "%.3e", d.toCentroid);
      row("moved since k-1", "%.3e", d.moved);
      row("neighbours", "%d", d.neighbours);
      row("valence, result", "%d", d.valence);
      row("param. triangles", "%d", d.pieces);
      ImGui::EndTable();
    }
    ImGui::PopID();
  }
  for (int triangle : triangles_) {
    const TriangleDetails d = describeTriangle(view, triangle);
    if (d.index < 0) continue;
    ImGui::PushID(-1 - triangle);
    ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(triangleColor()), "Triangle %d", triangle);
    ImGui::SameLine();
    if (ImGui::SmallButton("unpin")) unpinTriangle = triangle;
    if (ImGui::BeginTable("triangle", 2, table)) {
      columns();
      row("angles, 3D", "%.1f %.1f %.1f", d.angles3D[0], d.angles3D[1], d.angles3D[2]);
      row("angles, UV", "%.1f %.1f %.1f", d.anglesUV[0], d.anglesUV[1], d.anglesUV[2]);
      row("minimum angle", "%.1f", d.minAngle);
      row("area, 3D", "%.4e", d.area3D);
      row("area, UV", "%.4e", d.areaUV);
      row("area distortion", "%.3f", d.areaDistortion);
      // Retriangulate: every corner is a site. Relocate: the inside vertices moved to their
      // sites, the border ones stayed.
      for (int k = 0; k < 3; ++k) {
        const std::string label = "vertex " + std::to_string(d.corners[k]);
        if (d.sites[k] >= 0) row(label.c_str(), "site %d", d.sites[k]);
        else row(label.c_str(), "%s", "not moved");
      }
      ImGui::EndTable();
    }
    ImGui::PopID();
  }
  toggleCell(unpinCell);
  toggleTriangle(unpinTriangle);
}

}  // namespace lloydscope
