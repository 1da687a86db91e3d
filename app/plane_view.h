// The 2D pane's view of the parameter domain: the unit square fitted in the pane, `base` pixels
// across at zoom 1 around the fitted area's centre, then moved by `pan` pixels and magnified
// by `zoom`. The domain's v points up, the screen's y down.
#pragma once

#include "mesh.h"

#include <glm/vec2.hpp>

namespace lloydscope {

struct PlaneView {
  float zoom = 1.0f;
  glm::vec2 pan{0.0f, 0.0f};

  // Where the domain's middle (0.5, 0.5) is drawn, for a pane whose fitted area centres at `fit`.
  glm::vec2 middle(const glm::vec2& fit) const { return fit + pan; }
  glm::vec2 toScreen(const Vec2& uv, const glm::vec2& fit, float base) const;
  Vec2 toDomain(const glm::vec2& screen, const glm::vec2& fit, float base) const;
  // The wheel's `clicks` with the cursor at `cursor`: the point of the domain under it stays
  // under it (zoomed about the pane's middle, the cell a student pointed at slid out of view).
  // From a twentieth of the fitted size up (sites 10^-7 of the domain apart, as on a long limb's
  // map, are still drawn apart), and never 0 or infinite.
  void zoomAt(float clicks, const glm::vec2& cursor, const glm::vec2& fit);
};

}  // namespace lloydscope
