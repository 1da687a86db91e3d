// Generates the bundled meshes in assets/. Run: build/assets/make_assets assets
// The meshes are deliberately poor triangulations (Delaunay of unevenly scattered points) so
// that remeshing them visibly helps. Deterministic: a test checks the committed files match.
#include "mesh_io.h"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <cmath>
#include <functional>
#include <iostream>
#include <random>

using namespace lloydscope;

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;
using Delaunay =
    CGAL::Delaunay_triangulation_2<Kernel, CGAL::Triangulation_data_structure_2<VertexBase>>;

double round6(double x) { return std::round(x * 1e6) / 1e6; }

class Random {
 public:
  explicit Random(std::uint64_t seed) : rng_(seed) {}
  double uniform() { return (rng_() >> 11) * 0x1.0p-53; }

 private:
  std::mt19937_64 rng_;
};

// Delaunay triangulation of 2D points (the convex hull must be the intended border), lifted
// by `height` (or mapped by `embed`).
Mesh triangulate(const std::vector<Vec2>& points, const std::function<Vec3(const Vec2&)>& embed) {
  std::vector<std::pair<Kernel::Point_2, int>> input;
  for (int i = 0; i < static_cast<int>(points.size()); ++i)
    input.emplace_back(Kernel::Point_2(points[i].x(), points[i].y()), i);
  Delaunay dt(input.begin(), input.end());
  Mesh mesh;
  for (const Vec2& p : points) {
    const Vec3 q = embed(p);
    mesh.points.emplace_back(round6(q.x()), round6(q.y()), round6(q.z()));
  }
  for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f)
    mesh.triangles.push_back({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
  return mesh;
}

// Points in the unit disk: a ring of `border` points and `inside` points whose density grows
// towards +x (so that the triangles are uneven, as in a simplified scan).
std::vector<Vec2> unevenDisk(int border, int inside, Random& random) {
  std::vector<Vec2> points;
  for (int i = 0; i < border; ++i) {
    const double a = 2 * M_PI * (i + 0.3 * random.uniform()) / border;
    points.emplace_back(round6(std::cos(a)), round6(std::sin(a)));
  }
  while (static_cast<int>(points.size()) < border + inside) {
    const Vec2 p(2 * random.uniform() - 1, 2 * random.uniform() - 1);
    if (p.norm() > 0.97) continue;
    if (random.uniform() > 0.25 + 0.75 * (p.x() + 1) / 2) continue;
    points.emplace_back(round6(p.x()), round6(p.y()));
  }
  return points;
}

Mesh bumpyDisk() {  // the default mesh: a disk with three bumps and a dent, 1000 vertices
  Random random(2);
  const auto bump = [](const Vec2& p, const Vec2& c, double r) {
    return std::exp(-(p - c).squaredNorm() / (r * r));
  };
  return triangulate(unevenDisk(90, 910, random), [&](const Vec2& p) {
    const double z = 0.35 * bump(p, {-0.35, 0.3}, 0.3) + 0.25 * bump(p, {0.4, 0.35}, 0.25) +
                     0.3 * bump(p, {0.1, -0.45}, 0.35) - 0.15 * bump(p, {-0.5, -0.4}, 0.2);
    return Vec3(p.x(), p.y(), z);
  });
}

Mesh sphereCap() {  // the reference's figure 1: a patch of a unit sphere, 60 degrees wide
  Random random(3);
  const double maxPolar = 60.0 * M_PI / 180.0;
  return triangulate(unevenDisk(60, 440, random), [&](const Vec2& p) {
    const double polar = p.norm() * maxPolar, azimuth = std::atan2(p.y(), p.x());
    return Vec3(std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth),
                std::cos(polar));
  });
}

Mesh jitteredGrid() {  // a flat square, 21 x 21 vertices, inside ones jittered
  Random random(4);
  const int n = 20;
  std::vector<Vec2> points;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      Vec2 p(static_cast<double>(i) / n, static_cast<double>(j) / n);
      if (i > 0 && i < n && j > 0 && j < n)
        p += 0.35 / n * Vec2(2 * random.uniform() - 1, 2 * random.uniform() - 1);
      points.emplace_back(round6(p.x()), round6(p.y()));
    }
  return triangulate(points, [](const Vec2& p) { return Vec3(p.x(), p.y(), 0.0); });
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: make_assets OUTPUT_FOLDER\n";
    return 2;
  }
  const std::string folder = argv[1];
  try {
    for (const auto& [name, mesh] : {std::pair{"bumpy_disk.off", bumpyDisk()},
                                     std::pair{"sphere_cap.off", sphereCap()},
                                     std::pair{"jittered_grid.off", jitteredGrid()}}) {
      validateMesh(mesh, name);
      writeMesh(mesh, folder + "/" + name);
    }
  } catch (const Error& e) {
    std::cerr << "make_assets: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
