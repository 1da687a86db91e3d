// The indexed triangle mesh every stage of the pipeline reads and writes.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <stdexcept>
#include <string>
#include <vector>

namespace lloydscope {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using Triangle = std::array<int, 3>;

// The sizes double precision remeshes: beyond them CGAL's exact predicates crashed (GMP on the
// NaN of an overflowed product: coordinates of 1e80), its triangulation looped (a strip 10^9
// times as long as wide, or one vertex 10^10 away from a unit grid), or the result lost its
// shape to rounding (a unit grid 10^15 from the origin came out with 0-degree angles; 10^12
// was fine). Every command refuses a mesh outside them (requireExactPredicatesRange); the
// reader, which refuses what it cannot even measure, quotes them too.
constexpr double kLargestCoordinate = 1e30, kSmallestDiagonal = 1e-30, kFarthestPerSize = 1e12;

// The one exception type of the core. Its message is a single line meant for the user,
// starting with the file it is about when there is one ("face.off: 3 faces use vertex 12 ...").
struct Error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Mesh {
  std::vector<Vec3> points;
  std::vector<Triangle> triangles;  // counter-clockwise seen from the front side

  int vertexCount() const { return static_cast<int>(points.size()); }
  int faceCount() const { return static_cast<int>(triangles.size()); }
};

// Per vertex: the number of distinct neighbours, and whether an edge with a single face
// touches it (the vertex is on a boundary). No triangle may repeat a corner (validateMesh()
// refuses such faces).
struct VertexEdges {
  std::vector<int> valence;
  std::vector<bool> onBoundary;
};
VertexEdges vertexEdges(const Mesh& mesh);

// Each edge once, the border's too, its smaller end first, in order, with the first triangle
// that has it.
struct MeshEdge {
  int from, to, triangle;
};
std::vector<MeshEdge> uniqueEdges(const Mesh& mesh);

// The mesh of `triangles` over `points`, keeping only the points some triangle uses (a site on
// top of another, outside the domain, or a vertex of no face in a file, has none), numbered in
// order. `kept`, if given, receives for each output vertex the index of its point.
Mesh assemble(const std::vector<Triangle>& triangles, const std::vector<Vec3>& points,
              std::vector<int>* kept = nullptr);

// Each vertex's triangles: faces[offset[v]] .. faces[offset[v + 1] - 1].
struct Rings {
  std::vector<int> offset, faces;
  explicit Rings(const Mesh& m);
};

// Lowest and highest corner of the axis-aligned bounding box (zeros for an empty mesh).
std::pair<Vec3, Vec3> boundingBox(const Mesh& mesh);
std::pair<Vec3, Vec3> boundingBox(const std::vector<Vec3>& points);
std::pair<Vec2, Vec2> boundingBox(const std::vector<Vec2>& points);
// Length of its diagonal.
double boundingBoxDiagonal(const Mesh& mesh);
double triangleArea(const Vec3& a, const Vec3& b, const Vec3& c);
// The angle at `a` of the triangle a, b, c, in radians (atan2 of the cross and dot products:
// exact near 0 and 180 degrees, where acos is not).
double cornerAngle(const Vec3& a, const Vec3& b, const Vec3& c);
double cornerAngle(const Vec2& a, const Vec2& b, const Vec2& c);
// Zero area up to rounding, as readMesh() refuses a face: the sine of the angle at a is
// negligible. Exact comparison with 0 would let through collinear corners whose coordinates are
// not exactly representable.
bool hasZeroArea(const Vec3& a, const Vec3& b, const Vec3& c);
double distanceToSegment(const Vec3& p, const Vec3& a, const Vec3& b);
double distanceToSegment(const Vec2& p, const Vec2& a, const Vec2& b);
Vec3 faceNormal(const Mesh& mesh, const Triangle& t);  // not unit: its length is twice the area
double surfaceArea(const Mesh& mesh);  // the sum of its triangles' areas
// The area its triangles cover in the plane of `uv` (a map of it), each counted unsigned.
double mapArea(const Mesh& mesh, const std::vector<Vec2>& uv);
double loopLength(const Mesh& mesh, const std::vector<int>& loop);  // closed: last to first too
// The edge length of an equilateral mesh of `vertices` vertices covering `area`: it has about
// 2 `vertices` triangles of area (sqrt 3 / 4) h^2.
double equilateralEdgeLength(double area, int vertices);
// Appends `part`'s vertices and triangles to `to` (as another component).
void append(Mesh& to, const Mesh& part);
double triangleArea(const Vec2& a, const Vec2& b, const Vec2& c);  // signed, > 0 if CCW
// The z of the cross product of two vectors of the plane: the signed area of their parallelogram.
inline double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }
// A point of triangle (a, b, c) uniformly at random, from two independent uniform numbers in
// [0, 1) (a point past the diagonal is reflected back into the triangle).
template <class Point>
Point pointInTriangle(const Point& a, const Point& b, const Point& c, double s, double t) {
  if (s + t > 1) {
    s = 1 - s;
    t = 1 - t;
  }
  return a + s * (b - a) + t * (c - a);
}
// The index of the first of the running totals `cumulative` over `at` (the last where none is):
// `at` uniform up to the last total picks each index by its share of the total.
size_t pickByShare(const std::vector<double>& cumulative, double at);
// A parameter triangle with no more than this share of its map's whole area is flat: an ear of
// a straight border (which covers none of the domain), or a triangle squeezed to nothing.
constexpr double kFlatAreaShare = 1e-14;

}  // namespace lloydscope
