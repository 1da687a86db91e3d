#include "plane_view.h"

#include <gtest/gtest.h>

#include <cmath>

namespace lloydscope {
namespace {

// The unit square fitted in an area 543.5 pixels wide and tall centred at (400, 300): 500
// pixels across at zoom 1.
const PaneFit kFit = fitBox(Vec2(0, 0), Vec2(1, 1), glm::vec2(400, 300), 500 / 0.92f, 500 / 0.92f);

TEST(PlaneView, TheDomainFitsThePaneWithVUp) {
  const PlaneView view;
  EXPECT_FLOAT_EQ(kFit.base, 500);
  const glm::vec2 middle = view.toScreen(Vec2(0.5, 0.5), kFit);
  EXPECT_EQ(middle, kFit.at);
  const glm::vec2 corner = view.toScreen(Vec2(1, 1), kFit);
  EXPECT_FLOAT_EQ(corner.x, 650);
  EXPECT_FLOAT_EQ(corner.y, 50);  // up the screen
  const Vec2 back = view.toDomain(glm::vec2(123, 456), kFit);
  const glm::vec2 again = view.toScreen(back, kFit);
  EXPECT_NEAR(again.x, 123, 1e-3);
  EXPECT_NEAR(again.y, 456, 1e-3);
}

// The point under the cursor stays under it, zooming in or out, with a pan before: the cell a
// student pointed at slid away when the zoom was about the pane's middle.
TEST(PlaneView, ZoomingKeepsThePointUnderTheCursor) {
  PlaneView view;
  view.pan = glm::vec2(-40, 25);
  const glm::vec2 cursor(610, 140);
  const Vec2 under = view.toDomain(cursor, kFit);
  for (float clicks : {3.0f, 10.0f, -2.0f, 1.0f}) {
    view.zoomAt(clicks, cursor, kFit);
    const Vec2 now = view.toDomain(cursor, kFit);
    EXPECT_NEAR(now.x(), under.x(), 2e-4 / view.zoom) << clicks;
    EXPECT_NEAR(now.y(), under.y(), 2e-4 / view.zoom) << clicks;
  }
  EXPECT_FLOAT_EQ(view.zoom, std::pow(1.15f, 12.0f));
  // At the domain's middle the view only magnifies.
  PlaneView centred;
  centred.zoomAt(5, kFit.at, kFit);
  EXPECT_EQ(centred.pan, glm::vec2(0, 0));
}

TEST(PlaneView, ZoomStaysWithinItsRangeAndTheCursorsPointStill) {
  PlaneView view;
  const glm::vec2 cursor(100, 500);
  const Vec2 under = view.toDomain(cursor, kFit);
  view.zoomAt(-100, cursor, kFit);
  EXPECT_FLOAT_EQ(view.zoom, 0.05f);
  const Vec2 out = view.toDomain(cursor, kFit);
  EXPECT_NEAR(out.x(), under.x(), 1e-4 / view.zoom);
  EXPECT_NEAR(out.y(), under.y(), 1e-4 / view.zoom);
  view.zoomAt(1000, cursor, kFit);
  EXPECT_FLOAT_EQ(view.zoom, 1e9f);
}

// A map is scaled to the unit square, which a strip's fills along its length only: its own box
// is centred in the pane and fills it as far as the pane's shape allows (the unit square's
// frame drew the helicoid's strip, 1:9, as a band against the pane's right edge).
TEST(PlaneView, ANarrowDomainIsCentredAndFillsThePane) {
  const glm::vec2 centre(400, 300);
  const PlaneView view;
  // A strip along u, low: it fills a wide area's width.
  const PaneFit wide = fitBox(Vec2(0, 0), Vec2(1, 0.1), centre, 800, 200);
  EXPECT_FLOAT_EQ(wide.base, 0.92f * 800);
  EXPECT_EQ(view.toScreen(Vec2(0.5, 0.05), wide), centre);
  EXPECT_FLOAT_EQ(view.toScreen(Vec2(1, 0.1), wide).x - view.toScreen(Vec2(0, 0), wide).x, 0.92f * 800);
  // A strip along v, against u = 1 (a mirrored map): centred, as tall as the area allows.
  const PaneFit tall = fitBox(Vec2(0.9, 0), Vec2(1, 1), centre, 600, 500);
  EXPECT_FLOAT_EQ(tall.base, 0.92f * 500);
  const glm::vec2 lo = view.toScreen(Vec2(0.9, 0), tall), hi = view.toScreen(Vec2(1, 1), tall);
  EXPECT_FLOAT_EQ((lo.x + hi.x) / 2, centre.x);
  EXPECT_FLOAT_EQ((lo.y + hi.y) / 2, centre.y);
  // Points and segments fit too, drawn at a finite place.
  for (const auto& [a, b] : {std::pair(Vec2(0.3, 0.2), Vec2(0.3, 0.2)), std::pair(Vec2(0.3, 0.2), Vec2(0.3, 0.7))}) {
    const PaneFit fit = fitBox(a, b, centre, 600, 500);
    EXPECT_TRUE(std::isfinite(fit.base) && fit.base > 0);
    EXPECT_EQ(view.toScreen(a, fit).x, centre.x);
  }
}

}  // namespace
}  // namespace lloydscope
