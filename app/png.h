// Writes frames (or a part of one) as PNG files, whole or not at all.
#pragma once

#include <string>
#include <vector>

namespace lloydscope {

// A part of a picture, in pixels.
struct PixelRect {
  int x = 0, y = 0, width = 0, height = 0;
};

// `pixels`: width x height, 4 bytes each, rows packed; `bgra` when the frame's format stores
// blue first (a swapchain). The PNG file of `crop` of it. Throws Error naming `path`, the file
// it is for, where there is nothing to encode or no memory to encode it.
std::vector<unsigned char> encodePng(const std::string& path, const unsigned char* pixels, int width, int height,
                                     bool bgra, PixelRect crop);

// Throws Error unless `path` names a PNG file (ends in .png) that can be written (requireWritable):
// checked before the frames are rendered, and before the run they show.
void requirePngPath(const std::string& path);

}  // namespace lloydscope
