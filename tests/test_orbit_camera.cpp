#include "orbit_camera.h"

#include <gtest/gtest.h>

#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>

namespace lloydscope {
namespace {

// Where `p` (the mesh's frame) lands in normalised device coordinates, -1..1 across the pane.
glm::vec2 onScreen(const OrbitCamera& camera, const GpuFrame& gpu, float width, float height, float top,
                   const Vec3& p) {
  const glm::vec4 c = camera.matrices(gpu, width, height, top).first * glm::vec4(glmOf(gpu.to(p)), 1.0f);
  EXPECT_GT(c.w, 0) << "behind the eye";
  return glm::vec2(c.x / c.w, c.y / c.w);
}

TEST(OrbitCamera, TextRoundTrips) {
  OrbitCamera c;
  c.yaw = 0.25f;
  c.pitch = -0.5f;
  c.distance = 12.5f;
  c.target = Vec3(1, -2, 300.5);
  const OrbitCamera back = OrbitCamera::parse(c.text());
  EXPECT_EQ(c.text(), "0.2500 -0.5000 12.5 1 -2 300.5");
  EXPECT_FLOAT_EQ(back.yaw, c.yaw);
  EXPECT_FLOAT_EQ(back.pitch, c.pitch);
  EXPECT_FLOAT_EQ(back.distance, c.distance);
  EXPECT_EQ(back.target, c.target);
}

TEST(OrbitCamera, ParseRefusesAnythingButSixFiniteNumbers) {
  for (const char* bad : {"", "1 2 3 4 5", "1 2 3 4 5 6 7", "1 2 0 4 5 6", "1 2 -3 4 5 6", "nan 0 1 0 0 0",
                          "0 0 1e308 0 0 0", "0 0 1 0 inf 0", "a b c d e f"}) {
    try {
      OrbitCamera::parse(bad);
      ADD_FAILURE() << "accepted \"" << bad << "\"";
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()), std::string("camera \"") + bad +
                                           "\": expected \"yaw pitch distance x y z\" (six finite numbers, the "
                                           "angles and the distance in single precision, distance > 0)");
    }
  }
}

TEST(OrbitCamera, NeverGoesOverThePole) {
  EXPECT_FLOAT_EQ(OrbitCamera::parse("0 3 1 0 0 0").pitch, 1.5f);
  EXPECT_FLOAT_EQ(OrbitCamera::parse("0 -3 1 0 0 0").pitch, -1.5f);
  OrbitCamera c;
  c.orbit(0, 1000);  // dragged far down: the view from above
  EXPECT_FLOAT_EQ(c.pitch, 1.5f);
  c.orbit(50, -10000);
  EXPECT_FLOAT_EQ(c.pitch, -1.5f);
  EXPECT_FLOAT_EQ(c.yaw, -1.2f - 0.5f);
}

TEST(OrbitCamera, ZoomStaysWithinTheMeshsSizes) {
  OrbitCamera c;
  c.distance = 5;
  c.zoom(1, 10);  // a tenth nearer a click
  EXPECT_FLOAT_EQ(c.distance, 4.5f);
  c.zoom(100, 10);
  EXPECT_FLOAT_EQ(c.distance, 3);  // 0.3 times the mesh's size
  c.zoom(-1000, 10);
  EXPECT_FLOAT_EQ(c.distance, 200);  // 20 times
  // A view pasted from outside the range: not pushed farther out, nor made to jump into it.
  c.distance = 1000;
  c.zoom(-1, 10);
  EXPECT_FLOAT_EQ(c.distance, 1000);
  c.zoom(1, 10);
  EXPECT_FLOAT_EQ(c.distance, 900);
  c.distance = 2;
  c.zoom(1, 10);
  EXPECT_FLOAT_EQ(c.distance, 2);
  c.zoom(-1, 10);
  EXPECT_FLOAT_EQ(c.distance, 2 / 0.9f);
}

TEST(OrbitCamera, TheTargetIsAtTheCentreOfThePaneUnderItsBand) {
  OrbitCamera c;
  c.target = Vec3(1000, 2000, -5);  // far from the origin, where single precision would blur it
  c.distance = 0.01f;
  const GpuFrame gpu = GpuFrame::ofBox(Vec3(999.99, 1999.99, -5.01), Vec3(1000.01, 2000.01, -4.99));
  const float width = 800, height = 600, top = 60;
  const glm::vec2 at = onScreen(c, gpu, width, height, top, c.target);
  EXPECT_NEAR(at.x, 0, 1e-5);
  // Halfway down the 540 pixels under the band: 60 + 270 = 330 of 600 pixels.
  EXPECT_NEAR((at.y * 0.5f + 0.5f) * height, top + 0.5f * (height - top), 1e-3);
  // Up on the surface (z) is up on the screen (y down in Vulkan).
  EXPECT_LT(onScreen(c, gpu, width, height, top, c.target + Vec3(0, 0, 0.001)).y, at.y);
}

// Vulkan's depth runs from 0 at the near plane to 1 at the far one: with OpenGL's (-1 to 1, GLM's
// default) the nearest part of the view, twice the near plane's distance, was cut off.
TEST(OrbitCamera, DepthIsVulkansFromZeroToOne) {
  OrbitCamera c;
  c.distance = 10;
  const GpuFrame gpu;
  const auto [viewProjection, eye] = c.matrices(gpu, 800, 600, 0);
  const glm::vec3 forward = -c.towardsEye();
  const auto depth = [&, &m = viewProjection](float along) {
    const glm::vec4 p = m * glm::vec4(eye + along * forward, 1.0f);
    return p.z / p.w;
  };
  EXPECT_NEAR(depth(0.1f), 0, 1e-5);  // the near plane, a hundredth of the distance
  EXPECT_NEAR(depth(100), 1, 1e-5);   // the far plane, ten times the distance
  EXPECT_GT(depth(0.15f), 0);
  EXPECT_LT(depth(10), 1);
}

TEST(OrbitCamera, AFittedViewShowsEveryPointWithinTheMargin) {
  // A long shape seen across and from above: a box's diagonal alone did not fit it.
  std::vector<Vec3> points;
  for (int i = 0; i <= 20; ++i)
    for (double y : {-0.3, 0.3})
      for (double z : {0.0, 0.5}) points.emplace_back(10.0 * i - 100, y, z);
  const auto [lo, hi] = std::pair(Vec3(-100, -0.3, 0), Vec3(100, 0.3, 0.5));
  const GpuFrame gpu = GpuFrame::ofBox(lo, hi);
  for (const auto& [width, height] : {std::pair(1000.0f, 500.0f), std::pair(400.0f, 900.0f)})
    for (float yaw : {-1.2f, 0.0f, 0.8f}) {
      OrbitCamera c;
      c.lookAtBox(lo, hi);
      c.yaw = yaw;
      const float top = 40;
      c.distance = c.fittingDistance(points, width, height - top);
      float farthest = 0;
      for (const Vec3& p : points) {
        const glm::vec2 at = onScreen(c, gpu, width, height, top, p);
        // In the pane under the band: x in -1..1, y below the band's edge.
        EXPECT_LE(std::abs(at.x), 1.0f) << width << "x" << height << " yaw " << yaw;
        EXPECT_GE((at.y * 0.5f + 0.5f) * height, top) << width << "x" << height << " yaw " << yaw;
        EXPECT_LE(at.y, 1.0f);
        farthest = std::max({farthest, std::abs(at.x), std::abs(at.y)});
      }
      EXPECT_GT(farthest, 0.75f) << "not fitted closely: " << width << "x" << height << " yaw " << yaw;
    }
}

TEST(OrbitCamera, TheGpuFrameCentresTheBoxAtAUnitDiagonal) {
  const GpuFrame gpu = GpuFrame::ofBox(Vec3(1e6, 1e6, 0), Vec3(1e6 + 3, 1e6 + 4, 0));
  EXPECT_EQ(gpu.origin, Vec3(1e6 + 1.5, 1e6 + 2, 0));
  EXPECT_DOUBLE_EQ(gpu.scale, 5);
  const Vec3 corner = gpu.to(Vec3(1e6 + 3, 1e6 + 4, 0));
  EXPECT_NEAR((corner - Vec3(0.3, 0.4, 0)).norm(), 0, 1e-12);
  EXPECT_NEAR((gpu.from(glmOf(corner)) - Vec3(1e6 + 3, 1e6 + 4, 0)).norm(), 0, 1e-6);
  EXPECT_DOUBLE_EQ(GpuFrame::ofBox(Vec3(2, 2, 2), Vec3(2, 2, 2)).scale, 1);  // a single point
}

}  // namespace
}  // namespace lloydscope
