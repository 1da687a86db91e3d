// Pinned cells and triangles: they stay selected while the user scrubs, so one cell can be
// watched as it evolves. A cell by its site's number; a triangle of an iteration's result by
// its corners' sites (its number changes with the triangulation), one of the final result by
// its number. Drawn in both views and described in a details panel.
#pragma once

#include "inspection.h"

#include <imgui.h>

#include <functional>
#include <vector>

namespace lloydscope {

// Where a point of the parameter domain, or of the surface, is on screen (false: behind the
// camera).
using ScreenOfUV = std::function<ImVec2(const Vec2&)>;
using ScreenOf3D = std::function<bool(const Vec3&, ImVec2&)>;

class Selection {
 public:
  // Pins the index (a triangle of `view`'s result), or unpins it if it was pinned.
  void toggleCell(int cell);
  void toggleTriangle(const IterationView& view, int triangle);
  // Pins the index, if it is not pinned already.
  void pinCell(int cell);
  void pinTriangle(const IterationView& view, int triangle);
  bool cellPinned(int cell) const;
  // Triangles of the final result, kept apart: it is another mesh, numbered anew, with no map.
  void toggleFinalTriangle(int triangle);
  void pinFinalTriangle(int triangle);
  void forgetFinal() { finalTriangles_.clear(); }  // a new run: its final result is another
  void clear();
  bool empty() const { return cells_.empty() && triangles_.empty() && finalTriangles_.empty(); }
  const std::vector<int>& cells() const { return cells_; }
  bool trianglesPinned() const { return !triangles_.empty(); }  // of the iterations' results

  // Highlights: each pinned cell filled, with its site's path over all iterations; each pinned
  // triangle outlined (in the parameter domain by its corners' UV positions). Each only where
  // the view shows its kind: the lesson's first stages show no cells and no result (a pinned
  // triangle's ring floated on the empty domain). Cells' labels keep off `keepClear` (boxes as
  // min x, min y, max x, max y: the pane's legend, drawn over them).
  void draw2D(ImDrawList* dl, const Recording& recording, const IterationView& view,
              const ScreenOfUV& screen, float scale, bool cellsShown, bool resultShown,
              const std::vector<ImVec4>& keepClear = {}) const;
  // The cells' outlines and sites lifted to the surface, the triangles' outlines (where the
  // surface hides one from `eye`, the camera, a dashed ring alone).
  void draw3D(ImDrawList* dl, const Recording& recording, const Domain& domain,
              const IterationView& view, const ScreenOf3D& screen, const Vec3& eye, bool cellsShown,
              bool resultShown) const;
  // The final result's pinned triangles, when it is the mesh shown.
  void drawFinal3D(ImDrawList* dl, const Mesh& final, const ScreenOf3D& screen, const Vec3& eye) const;
  // The numbers of each pinned element at this iteration, with the formulas they enter, then
  // those of the final result's pinned triangles.
  void detailsPanel(const Recording& recording, const Domain& domain, const IterationView& view,
                    const Mesh& final);

  static ImU32 cellColor(float alpha = 1.0f);
  static ImU32 triangleColor(float alpha = 1.0f);

 private:
  std::vector<int> cells_, finalTriangles_;
  std::vector<TriangleCorners> triangles_;
  // The pinned triangles that `view`'s result has, by their number in it.
  std::vector<int> trianglesIn(const IterationView& view) const;
};

}  // namespace lloydscope
