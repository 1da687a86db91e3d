// For the window test: whether two PNGs are the same, pixel for pixel, within a rectangle.
// usage: png_same_region A.png B.png X0 Y0 X1 Y1 (the pixels with X0 <= x < X1, Y0 <= y < Y1)
// Exit status 0: the same; 1: they differ (how many pixels is printed); 2: a file not read.
#include <stb_image.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>

int main(int argc, char** argv) {
  if (argc != 7) {
    std::fprintf(stderr, "usage: %s A.png B.png X0 Y0 X1 Y1\n", argv[0]);
    return 2;
  }
  int width[2], height[2], channels;
  unsigned char* pixels[2];
  for (int i = 0; i < 2; ++i) {
    pixels[i] = stbi_load(argv[1 + i], &width[i], &height[i], &channels, 4);
    if (!pixels[i]) {
      std::fprintf(stderr, "%s: cannot read the PNG\n", argv[1 + i]);
      return 2;
    }
  }
  if (width[0] != width[1] || height[0] != height[1]) {
    std::printf("the pictures differ in size\n");
    return 1;
  }
  const int x0 = std::atoi(argv[3]), y0 = std::atoi(argv[4]);
  const int x1 = std::min(std::atoi(argv[5]), width[0]), y1 = std::min(std::atoi(argv[6]), height[0]);
  if (x0 < 0 || y0 < 0 || x0 >= x1 || y0 >= y1) {  // nothing to compare: no answer
    std::fprintf(stderr, "the rectangle %d %d %d %d holds no pixel of the pictures\n", x0, y0, x1, y1);
    return 2;
  }
  long differing = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      const size_t at = 4 * (static_cast<size_t>(y) * width[0] + x);
      differing += std::memcmp(pixels[0] + at, pixels[1] + at, 4) != 0;
    }
  if (differing > 0) std::printf("%ld pixels differ\n", differing);
  stbi_image_free(pixels[0]);
  stbi_image_free(pixels[1]);
  return differing > 0 ? 1 : 0;
}
