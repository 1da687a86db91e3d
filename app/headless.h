// Renders the inspector offscreen (no window, no X server) and writes a PNG.
#pragma once

#include "inspector.h"
#include "pipeline.h"

#include <optional>
#include <string>

namespace lloydscope {

// The picture sizes taken: "between 960x600 and 8192x8192".
std::string pictureSizes();

// Whether a picture of that size is taken (within pictureSizes()).
bool pictureSizeAllowed(long long width, long long height);

// Throws Error("--size must be between 960x600 and 8192x8192, not 'WxH'") for a picture size outside
// them (renderScreenshot() and benchmarkScrub() take no other), or where the picture over
// `uiScale` leaves less than 960x600 to lay the inspector out in.
void requirePictureSize(long long width, long long height, double uiScale = 1.0);

struct ScreenshotOptions {
  ExportJob picture;  // the PNG (or numbered PNGs), the pane, the iterations
  int width = 1280, height = 800;
  OpeningView view;  // iteration, pinned cells and triangles, camera
  bool validation = false;
  double uiScale = 1.0;  // pixels per unit of the layout: the picture as on a screen that many times as dense
};

struct FrameTimes {
  std::vector<double> milliseconds;
};

// Throws Error (or gpu::GpuError) with a one-line message on failure; the PNG is written to a
// temporary file and renamed, so an existing picture is replaced whole or not at all.
// `input`: the mesh the result was made of, as the window has it (the lesson's first stage and
// "show the input instead" show it); none for a recording.
void renderScreenshot(const std::string& meshName, const RemeshOptions& options,
                      RemeshResult result, const ScreenshotOptions& shot, std::optional<Mesh> input = {});

// Renders `frames` frames, timing each: jumping to another iteration every frame (a scrub), or
// staying on the last one.
FrameTimes benchmarkScrub(const std::string& meshName, const RemeshOptions& options,
                          RemeshResult result, int width, int height, int frames, bool scrub);

}  // namespace lloydscope
