#include "png.h"

#include "files.h"
#include "mesh.h"

#include <stb_image_write.h>

#include <algorithm>
#include <filesystem>
#include <vector>

namespace lloydscope {

std::vector<unsigned char> encodePng(const std::string& path, const unsigned char* pixels, int width, int height,
                                     bool bgra, PixelRect crop) {
  crop.x = std::clamp(crop.x, 0, width);
  crop.y = std::clamp(crop.y, 0, height);
  crop.width = std::clamp(crop.width, 0, width - crop.x);
  crop.height = std::clamp(crop.height, 0, height - crop.y);
  if (crop.width == 0 || crop.height == 0) throw Error(path + ": nothing to write (empty picture)");
  std::vector<unsigned char> rgba(static_cast<size_t>(crop.width) * crop.height * 4);
  for (int row = 0; row < crop.height; ++row) {
    const unsigned char* from = pixels + (static_cast<size_t>(crop.y + row) * width + crop.x) * 4;
    unsigned char* to = rgba.data() + static_cast<size_t>(row) * crop.width * 4;
    for (int i = 0; i < crop.width; ++i, from += 4, to += 4) {
      to[0] = from[bgra ? 2 : 0];
      to[1] = from[1];
      to[2] = from[bgra ? 0 : 2];
      to[3] = 255;  // the frame is opaque
    }
  }
  std::vector<unsigned char> png;
  const auto append = [](void* out, void* data, int size) {
    auto* bytes = static_cast<std::vector<unsigned char>*>(out);
    bytes->insert(bytes->end(), static_cast<unsigned char*>(data), static_cast<unsigned char*>(data) + size);
  };
  // stb fails only where its buffers cannot be allocated.
  if (!stbi_write_png_to_func(append, &png, crop.width, crop.height, 4, rgba.data(), crop.width * 4))
    throw Error(path + ": not enough memory to encode a " + std::to_string(crop.width) + "x" +
                std::to_string(crop.height) + " picture as PNG");
  return png;
}

void requirePngPath(const std::string& path) {
  if (lowercaseExtension(path) != ".png") {  // .png or .PNG, as meshes take .off or .OFF
    // ".png" alone is a name with no extension, not an extension with no name
    const bool nameMissing = lowercaseExtension("x" + std::filesystem::path(path).filename().string()) == ".png";
    throw Error(path + (nameMissing ? ": a picture needs a name before its .png"
                                    : ": exports are PNG files (end the name with .png)"));
  }
  requireWritable(path);
}

}  // namespace lloydscope
