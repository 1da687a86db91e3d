#include "plane_view.h"

#include <algorithm>
#include <cmath>

namespace lloydscope {

PaneFit fitBox(const Vec2& lo, const Vec2& hi, const glm::vec2& at, float width, float height) {
  // A side of no length (a map squeezed to a segment, or one point) fits by the other, or is
  // drawn as the unit square would be.
  const double longer = std::max((hi - lo).maxCoeff(), 0.0);
  const double floor = longer > 0 ? 1e-9 * longer : 1.0;
  const double across = std::max(hi.x() - lo.x(), floor), up = std::max(hi.y() - lo.y(), floor);
  PaneFit fit;
  fit.at = at;
  fit.base = 0.92f * static_cast<float>(std::min(width / across, height / up));
  fit.centre = (lo + hi) / 2;
  return fit;
}

glm::vec2 PlaneView::toScreen(const Vec2& uv, const PaneFit& fit) const {
  const glm::vec2 m = middle(fit);
  const float scale = fit.base * zoom;
  return glm::vec2(m.x + static_cast<float>(uv.x() - fit.centre.x()) * scale,
                   m.y - static_cast<float>(uv.y() - fit.centre.y()) * scale);
}

Vec2 PlaneView::toDomain(const glm::vec2& screen, const PaneFit& fit) const {
  const glm::vec2 m = middle(fit);
  const float scale = fit.base * zoom;
  return Vec2(fit.centre.x() + (screen.x - m.x) / scale, fit.centre.y() - (screen.y - m.y) / scale);
}

void PlaneView::zoomAt(float clicks, const glm::vec2& cursor, const PaneFit& fit) {
  const float before = zoom;
  zoom = std::clamp(zoom * std::pow(1.15f, clicks), 0.05f, 1e9f);
  // The cursor's offset from the box's middle grows with the zoom; the middle moves so that
  // the cursor's point stays put.
  const glm::vec2 offset = cursor - middle(fit);
  pan += offset * (1.0f - zoom / before);
}

}  // namespace lloydscope
