// Small meshes and helpers shared by the tests.
#pragma once

#include "domain.h"
#include "mesh.h"
#include "mesh_io.h"
#include "pipeline.h"
#include "topology.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

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

// grid(n) as a parameter domain (u, v = x, y), with the density rho(point) at each vertex.
template <class Rho>
inline Domain gridDomain(int n, Rho rho) {
  const Mesh g = grid(n);
  std::vector<Vec2> uv;
  std::vector<double> density;
  for (const Vec3& p : g.points) {
    uv.emplace_back(p.x(), p.y());
    density.push_back(rho(p));
  }
  return Domain(uv, g.triangles, vertexDensity(g.triangles, density));
}

// An n x m grid on the surface (u, v) -> point(u, v), u and v in [0, 1], closed up in u and/or
// v by reusing the first row or column.
template <class Point>
inline Mesh wrappedGrid(int n, int m, bool wrapU, bool wrapV, Point point) {
  const int columns = wrapU ? n : n + 1, rows = wrapV ? m : m + 1;
  Mesh mesh;
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns; ++i) mesh.points.push_back(point(double(i) / n, double(j) / m));
  auto at = [&](int i, int j) { return (j % rows) * columns + (i % columns); };
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i) {
      mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return mesh;
}

// A torus (radii 2 and 0.7) as a 24 x 12 grid of split squares: closed, genus 1.
inline Mesh torus() {
  return wrappedGrid(24, 12, true, true, [](double u, double v) {
    const double a = 2 * M_PI * u, b = 2 * M_PI * v;
    return Vec3((2 + 0.7 * std::cos(b)) * std::cos(a), (2 + 0.7 * std::cos(b)) * std::sin(a),
                0.7 * std::sin(b));
  });
}

// The cube [-1, 1]^3 as six n x n grids welded at its edges (closed, genus 0), or those grids
// pushed onto the unit sphere.
inline Mesh cube(int n, bool onSphere) {
  Mesh mesh;
  for (int axis = 0; axis < 3; ++axis)
    for (int sign : {-1, 1}) {
      Mesh face = grid(n, 2.0);
      for (Vec3& p : face.points) {
        Vec3 q;
        q[axis] = sign;
        q[(axis + 1) % 3] = p.x() - 1;
        q[(axis + 2) % 3] = (p.y() - 1) * sign;
        p = onSphere ? Vec3(q.normalized()) : q;
      }
      append(mesh, face);
    }
  // Weld the cube's edges: the same point, one vertex.
  std::vector<int> weld(mesh.vertexCount());
  std::vector<Vec3> unique;
  for (int v = 0; v < mesh.vertexCount(); ++v) {
    int found = -1;
    for (size_t u = 0; u < unique.size() && found < 0; ++u)
      if ((unique[u] - mesh.points[v]).norm() < 1e-9) found = static_cast<int>(u);
    if (found < 0) {
      found = static_cast<int>(unique.size());
      unique.push_back(mesh.points[v]);
    }
    weld[v] = found;
  }
  mesh.points = unique;
  for (Triangle& t : mesh.triangles)
    for (int& v : t) v = weld[v];
  return mesh;
}

// A run to look at, not to keep: `iterations` of Lloyd's at most, no clean-up on the surface, no
// distances measured (`sites`: 0, as many as the input has).
inline RemeshOptions shortRun(int sites, int iterations) {
  RemeshOptions o;
  o.sites.count = sites;
  o.lloyd.maxIterations = iterations;
  o.polish = -1;
  o.measureFidelity = false;
  return o;
}

// The text of the Error `call` throws; where it throws none, a test failure saying `expected`
// (what should have refused it), and "".
template <class Call>
std::string errorOf(Call call, const std::string& expected) {
  try {
    call();
  } catch (const Error& e) {
    return e.what();
  }
  ADD_FAILURE() << "no error: " << expected;
  return "";
}

// `mesh` scaled by `scale` and moved by `offset`: a second component to append() beside it.
inline Mesh moved(Mesh mesh, double scale, const Vec3& offset) {
  for (Vec3& p : mesh.points) p = scale * p + offset;
  return mesh;
}

inline std::string assetPath(const std::string& name) {
  return std::string(LLOYDSCOPE_SOURCE_DIR) + "/assets/" + name;
}

// CGAL's sample mesh `name` ("lion-head.off"), extracted by build.sh into data/cgal (never
// committed).
inline std::string cgalSample(const std::string& name) {
  return std::string(LLOYDSCOPE_SOURCE_DIR) + "/data/cgal/" + name;
}

// Skips the test where ./build.sh has not extracted `path` (a CGAL sample).
#define SKIP_UNLESS_EXTRACTED(path) \
  if (!std::ifstream(path).good()) GTEST_SKIP() << (path) << " not extracted (run ./build.sh)"

// The lower half of a mesh along `axis` (triangles wholly below the middle of its range, or
// below `fraction` of it), its largest piece.
inline Mesh lowerHalf(const Mesh& mesh, int axis = 2, double fraction = 0.5) {
  double low = INFINITY, high = -INFINITY;
  for (const Vec3& p : mesh.points) low = std::min(low, p[axis]), high = std::max(high, p[axis]);
  Mesh half;
  half.points = mesh.points;
  for (const Triangle& t : mesh.triangles)
    if (std::max({mesh.points[t[0]][axis], mesh.points[t[1]][axis], mesh.points[t[2]][axis]}) <
        low + fraction * (high - low))
      half.triangles.push_back(t);
  std::vector<Mesh> pieces = splitComponents(half);
  return *std::max_element(pieces.begin(), pieces.end(),
                           [](const Mesh& a, const Mesh& b) { return a.faceCount() < b.faceCount(); });
}

// The mesh at `path` (a CGAL sample) simplified to `vertices` and remeshed with the defaults,
// not measured against the input.
inline RemeshResult remeshSimplified(const std::string& path, int vertices) {
  RemeshOptions options;
  options.simplifyTo = vertices;
  options.measureFidelity = false;
  return remesh(readMesh(path).mesh, options, path);
}

// A centre joined to `rings` rings of `columns` vertices each, `point`(k, i) placing ring k's
// column i (k from 1): all the way round (`closed`: the last column joins the first) or across a
// sector (its first and last columns its two straight sides).
inline Mesh polarGrid(int rings, int columns, bool closed, const Vec3& centre,
                      const std::function<Vec3(int, int)>& point) {
  Mesh m;
  m.points.push_back(centre);
  for (int k = 1; k <= rings; ++k)
    for (int i = 0; i < columns; ++i) m.points.push_back(point(k, i));
  const auto at = [&](int k, int i) { return 1 + (k - 1) * columns + (i % columns); };
  const int spans = closed ? columns : columns - 1;
  for (int i = 0; i < spans; ++i) m.triangles.push_back({0, at(1, i), at(1, i + 1)});
  for (int k = 1; k < rings; ++k)
    for (int i = 0; i < spans; ++i) {
      m.triangles.push_back({at(k, i), at(k + 1, i), at(k + 1, i + 1)});
      m.triangles.push_back({at(k, i), at(k + 1, i + 1), at(k, i + 1)});
    }
  return m;
}

// A disk: `sectors` vertices on each of `rings` circles around its centre, the last of radius
// 1, the first at angle `phase`, lifted to z = height(r, angle) (flat without one).
inline Mesh polarDisk(int sectors, int rings, double phase = 0,
                      const std::function<double(double, double)>& height = {}) {
  return polarGrid(rings, sectors, true, Vec3(0, 0, height ? height(0, 0) : 0), [&](int k, int i) {
    const double a = phase + 2 * M_PI * i / sectors, r = double(k) / rings;
    return Vec3(r * std::cos(a), r * std::sin(a), height ? height(r, a) : 0);
  });
}

// How far the nearest of `points` is from `p` (a corner or a tip the result should have as a
// vertex, a sample that should lie on a point).
inline double nearestDistance(const std::vector<Vec3>& points, const Vec3& p) {
  double nearest = INFINITY;
  for (const Vec3& q : points) nearest = std::min(nearest, (q - p).norm());
  return nearest;
}

// A flat star of `points` points: its rim alternates between radius 1 (the points, rim vertex
// 0 first) and `inner` (the reflex corners between them), vertex i at starRim(); `rings` rings
// of a polar grid inside, the centre raised to `centreHeight`.
inline Vec3 starRim(int points, double inner, int i) {
  const double a = M_PI / points * i, r = i % 2 ? inner : 1.0;
  return Vec3(r * std::cos(a), r * std::sin(a), 0);
}
inline Mesh starDisk(int points, double inner, int rings, double centreHeight = 0) {
  return polarGrid(rings, 2 * points, true, Vec3(0, 0, centreHeight),
                   [&](int k, int i) -> Vec3 { return starRim(points, inner, i) * k / rings; });
}

// A sector of `degrees` and radius 1, finely triangulated: the apex, then rings of a polar grid
// between its two straight sides; flat, or at `height`(x, y) (the apex stays at 0).
inline Mesh sector(double degrees, const std::function<double(double, double)>& height = {}, int sectors = 12,
                   int rings = 30) {
  return polarGrid(rings, sectors + 1, false, Vec3::Zero(), [&](int k, int i) {
    const double a = degrees * M_PI / 180 * i / sectors, r = double(k) / rings;
    const double x = r * std::cos(a), y = r * std::sin(a);
    return Vec3(x, y, height ? height(x, y) : 0);
  });
}

// The folder a test process writes in: its own, as CTest runs test processes in parallel. It is
// removed when the process ends with no test failed; a failed test's files stay for a look.
inline const std::string& processFolder() {
  struct Folder {
    std::string path = ::testing::TempDir() + "lloydscope_" + std::to_string(getpid()) + "/";
    Folder() { std::filesystem::create_directories(path); }
    ~Folder() {
      std::error_code ignored;
      if (!::testing::UnitTest::GetInstance()->Failed()) std::filesystem::remove_all(path, ignored);
    }
  };
  static const Folder folder;
  return folder.path;
}

inline std::string tempPath(const std::string& name) { return processFolder() + name; }

// A folder of this process's own, made empty: what a write leaves in it can be listed.
inline std::string emptyFolder(const std::string& name) {
  const std::string folder = tempPath(name);
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  return folder;
}

// The names of the files in `folder`, sorted.
inline std::vector<std::string> filesIn(const std::string& folder) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

inline void writeText(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

inline std::string readText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Flips edge (a, b) of m: its two triangles (a, b, c) and (b, a, d) become (c, a, d), (d, b, c).
inline void flip(Mesh& m, int a, int b) {
  std::vector<size_t> faces;
  for (size_t f = 0; f < m.triangles.size(); ++f)
    if (std::count(m.triangles[f].begin(), m.triangles[f].end(), a) && std::count(m.triangles[f].begin(), m.triangles[f].end(), b))
      faces.push_back(f);
  ASSERT_EQ(faces.size(), 2u);
  auto third = [&](size_t f) {
    for (int v : m.triangles[f])
      if (v != a && v != b) return v;
    return -1;
  };
  // Which of the two has the edge as a -> b decides the orientation.
  const Triangle& t = m.triangles[faces[0]];
  const bool forward = (t[0] == a && t[1] == b) || (t[1] == a && t[2] == b) || (t[2] == a && t[0] == b);
  const int c = third(forward ? faces[0] : faces[1]), d = third(forward ? faces[1] : faces[0]);
  m.triangles[faces[0]] = {c, a, d};
  m.triangles[faces[1]] = {d, b, c};
}

// A 7 x 7 patch of equilateral triangles: vertex 7 i + j at (i + j / 2, j sqrt(3) / 2).
inline Mesh equilateralPatch() {
  Mesh m;
  auto at = [](int i, int j) { return 7 * i + j; };
  for (int i = 0; i < 7; ++i)
    for (int j = 0; j < 7; ++j) m.points.emplace_back(i + 0.5 * j, j * std::sqrt(3.0) / 2, 0.0);
  for (int j = 0; j < 6; ++j)
    for (int i = 0; i < 6; ++i) {
      m.triangles.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
      m.triangles.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return m;
}

// A strip that winds twice round an axis (a helicoid: radius 0.2 to 1, rising 0.25 a radian),
// `across` by `along` cells: its LSCM map winds round twice too and overlaps itself.
inline Mesh helicoidStrip(int across = 30, int along = 160) {
  Mesh strip;
  for (int j = 0; j <= along; ++j)
    for (int i = 0; i <= across; ++i) {
      const double r = 0.2 + 0.8 * i / across, t = 4 * M_PI * j / along;
      strip.points.emplace_back(r * std::cos(t), r * std::sin(t), 0.25 * t);
    }
  for (int j = 0; j < along; ++j)
    for (int i = 0; i < across; ++i) {
      const int a = j * (across + 1) + i, b = a + 1, c = b + across + 1, d = a + across + 1;
      strip.triangles.push_back({a, b, c});
      strip.triangles.push_back({a, c, d});
    }
  return strip;
}

// The equilateral patch with `edges` flipped, one after the other.
inline Mesh patchWithFlips(std::initializer_list<std::pair<int, int>> edges) {
  Mesh m = equilateralPatch();
  for (auto [a, b] : edges) flip(m, a, b);
  EXPECT_NO_THROW(validateMesh(m, "patch"));
  return m;
}

// The patch with edges (8, 14) and (9, 15) flipped: inside, vertex 9 is left with valence 5
// and 16 with 7; on the border 7 with 5 and 14 with 3. The one flip left that lowers the
// valences' squared deviation from regular (by 2) makes one more vertex irregular; flipping
// both back makes the patch regular again.
inline Mesh patchWithTwoFlips() { return patchWithFlips({{8, 14}, {9, 15}}); }

}  // namespace lloydscope::test
