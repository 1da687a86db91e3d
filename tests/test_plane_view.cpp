#include "plane_view.h"

#include <gtest/gtest.h>

#include <cmath>

namespace lloydscope {
namespace {

const glm::vec2 kFit(400, 300);  // the fitted area's centre, in pixels
constexpr float kBase = 500;     // the unit square's size at zoom 1

TEST(PlaneView, TheDomainFitsThePaneWithVUp) {
  const PlaneView view;
  const glm::vec2 middle = view.toScreen(Vec2(0.5, 0.5), kFit, kBase);
  EXPECT_EQ(middle, kFit);
  const glm::vec2 corner = view.toScreen(Vec2(1, 1), kFit, kBase);
  EXPECT_FLOAT_EQ(corner.x, 650);
  EXPECT_FLOAT_EQ(corner.y, 50);  // up the screen
  const Vec2 back = view.toDomain(glm::vec2(123, 456), kFit, kBase);
  const glm::vec2 again = view.toScreen(back, kFit, kBase);
  EXPECT_NEAR(again.x, 123, 1e-3);
  EXPECT_NEAR(again.y, 456, 1e-3);
}

// The point under the cursor stays under it, zooming in or out, with a pan before: the cell a
// student pointed at slid away when the zoom was about the pane's middle.
TEST(PlaneView, ZoomingKeepsThePointUnderTheCursor) {
  PlaneView view;
  view.pan = glm::vec2(-40, 25);
  const glm::vec2 cursor(610, 140);
  const Vec2 under = view.toDomain(cursor, kFit, kBase);
  for (float clicks : {3.0f, 10.0f, -2.0f, 1.0f}) {
    view.zoomAt(clicks, cursor, kFit);
    const Vec2 now = view.toDomain(cursor, kFit, kBase);
    EXPECT_NEAR(now.x(), under.x(), 2e-4 / view.zoom) << clicks;
    EXPECT_NEAR(now.y(), under.y(), 2e-4 / view.zoom) << clicks;
  }
  EXPECT_FLOAT_EQ(view.zoom, std::pow(1.15f, 12.0f));
  // At the domain's middle the view only magnifies.
  PlaneView centred;
  centred.zoomAt(5, kFit, kFit);
  EXPECT_EQ(centred.pan, glm::vec2(0, 0));
}

TEST(PlaneView, ZoomStaysWithinItsRangeAndTheCursorsPointStill) {
  PlaneView view;
  const glm::vec2 cursor(100, 500);
  const Vec2 under = view.toDomain(cursor, kFit, kBase);
  view.zoomAt(-100, cursor, kFit);
  EXPECT_FLOAT_EQ(view.zoom, 0.05f);
  const Vec2 out = view.toDomain(cursor, kFit, kBase);
  EXPECT_NEAR(out.x(), under.x(), 1e-4 / view.zoom);
  EXPECT_NEAR(out.y(), under.y(), 1e-4 / view.zoom);
  view.zoomAt(1000, cursor, kFit);
  EXPECT_FLOAT_EQ(view.zoom, 1e9f);
}

}  // namespace
}  // namespace lloydscope
