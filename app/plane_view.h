// The 2D pane's view of the parameter domain: the domain's bounding box centred in the pane's
// fitted area and as large as it allows (PaneFit), then moved by `pan` pixels and magnified by
// `zoom`. The domain's v points up, the screen's y down.
#pragma once

#include "mesh.h"

#include <glm/vec2.hpp>

namespace lloydscope {

// Where the domain is drawn at zoom 1 with no pan.
struct PaneFit {
  glm::vec2 at{0.0f, 0.0f};  // the fitted area's centre, pixels: the box's centre is drawn there
  float base = 1.0f;         // pixels per unit of the domain
  Vec2 centre{0.5, 0.5};     // the box's centre, in the domain
};

// The box `lo`-`hi` of the domain fitted in an area `width` x `height` pixels centred at `at`,
// 4% of the area left free on each side of its longer fit. A map is scaled to the unit square,
// which a strip's (a helicoid's, 1:9) fills along its length only: framing that square, not the
// map's own box, drew it as a thin band against the pane's edge.
PaneFit fitBox(const Vec2& lo, const Vec2& hi, const glm::vec2& at, float width, float height);

struct PlaneView {
  float zoom = 1.0f;
  glm::vec2 pan{0.0f, 0.0f};

  // Where the box's centre is drawn.
  glm::vec2 middle(const PaneFit& fit) const { return fit.at + pan; }
  glm::vec2 toScreen(const Vec2& uv, const PaneFit& fit) const;
  Vec2 toDomain(const glm::vec2& screen, const PaneFit& fit) const;
  // The wheel's `clicks` with the cursor at `cursor`: the point of the domain under it stays
  // under it (zoomed about the pane's middle, the cell a student pointed at slid out of view).
  // From a twentieth of the fitted size up (sites 10^-7 of the domain apart, as on a long limb's
  // map, are still drawn apart), and never 0 or infinite.
  void zoomAt(float clicks, const glm::vec2& cursor, const PaneFit& fit);
};

}  // namespace lloydscope
