#include "plane_view.h"

#include <algorithm>
#include <cmath>

namespace lloydscope {

glm::vec2 PlaneView::toScreen(const Vec2& uv, const glm::vec2& fit, float base) const {
  const glm::vec2 m = middle(fit);
  const float scale = base * zoom;
  return glm::vec2(m.x + static_cast<float>(uv.x() - 0.5) * scale, m.y - static_cast<float>(uv.y() - 0.5) * scale);
}

Vec2 PlaneView::toDomain(const glm::vec2& screen, const glm::vec2& fit, float base) const {
  const glm::vec2 m = middle(fit);
  const float scale = base * zoom;
  return Vec2(0.5 + (screen.x - m.x) / scale, 0.5 - (screen.y - m.y) / scale);
}

void PlaneView::zoomAt(float clicks, const glm::vec2& cursor, const glm::vec2& fit) {
  const float before = zoom;
  zoom = std::clamp(zoom * std::pow(1.15f, clicks), 0.05f, 1e9f);
  // The cursor's offset from the domain's middle grows with the zoom; the middle moves so that
  // the cursor's point stays put.
  const glm::vec2 offset = cursor - middle(fit);
  pan += offset * (1.0f - zoom / before);
}

}  // namespace lloydscope
