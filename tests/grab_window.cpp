// For the window test: an X window's pixels as the screen shows them, saved as a PNG. A picture
// the inspector saves itself (Ctrl+S) leaves out what is only for the screen, as messages are.
// usage: grab_window WINDOW_ID OUT.png
// Exit status 0: saved; 2: no display, no such window, or the file not written.
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <stb_image_write.h>

#include <cstdio>
#include <cstdlib>
#include <vector>

namespace {
// The 8 bits of a channel from a pixel, by the visual's mask for it (0xff0000 for red, say).
unsigned char channel(unsigned long pixel, unsigned long mask) {
  if (mask == 0) return 0;
  int shift = 0;
  while (!((mask >> shift) & 1)) ++shift;
  const unsigned long value = (pixel & mask) >> shift, most = mask >> shift;
  return static_cast<unsigned char>(value * 255 / most);
}
}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s WINDOW_ID OUT.png\n", argv[0]);
    return 2;
  }
  Display* display = XOpenDisplay(nullptr);
  if (!display) {
    std::fprintf(stderr, "grab_window: no display\n");
    return 2;
  }
  const Window window = std::strtoul(argv[1], nullptr, 0);
  XWindowAttributes attributes;
  XImage* image = XGetWindowAttributes(display, window, &attributes)
                      ? XGetImage(display, window, 0, 0, attributes.width, attributes.height, AllPlanes, ZPixmap)
                      : nullptr;
  if (!image) {
    std::fprintf(stderr, "grab_window: cannot read window %s\n", argv[1]);
    return 2;
  }
  std::vector<unsigned char> rgba(4 * static_cast<size_t>(image->width) * image->height);
  for (int y = 0; y < image->height; ++y)
    for (int x = 0; x < image->width; ++x) {
      const unsigned long pixel = XGetPixel(image, x, y);
      unsigned char* out = &rgba[4 * (static_cast<size_t>(y) * image->width + x)];
      out[0] = channel(pixel, image->red_mask);
      out[1] = channel(pixel, image->green_mask);
      out[2] = channel(pixel, image->blue_mask);
      out[3] = 255;
    }
  const bool written = stbi_write_png(argv[2], image->width, image->height, 4, rgba.data(), 4 * image->width);
  XDestroyImage(image);
  XCloseDisplay(display);
  if (!written) std::fprintf(stderr, "grab_window: cannot write %s\n", argv[2]);
  return written ? 0 : 2;
}
