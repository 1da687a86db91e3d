// Small meshes and helpers shared by the tests.
#pragma once

#include "mesh.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include <unistd.h>

namespace lloydscope::test {

// A flat n x n grid of unit-spaced squares, each split along its diagonal, scaled by `size`.
inline Mesh grid(int n, double size = 1.0) {
  Mesh m;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.points.emplace_back(size * i / n, size * j / n, 0.0);
  auto at = [n](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return m;
}

inline std::string assetPath(const std::string& name) {
  return std::string(LLOYDSCOPE_SOURCE_DIR) + "/assets/" + name;
}

// CTest runs test processes in parallel: every process gets names of its own.
inline std::string tempPath(const std::string& name) {
  return ::testing::TempDir() + "lloydscope_" + std::to_string(getpid()) + "_" + name;
}

inline void writeText(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

inline std::string readText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace lloydscope::test
