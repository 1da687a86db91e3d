// What the inspector tells about one cell or one triangle of an iteration: the numbers behind
// the pictures, computed from a replay's view of that iteration.
#pragma once

#include "replay.h"

#include <array>
#include <vector>

namespace lloydscope {

struct CellDetails {
  int index = -1;        // the site: fixed sites first, then movable ones
  bool fixed = false;    // a border sample, which never moves
  Vec2 site = Vec2::Zero(), centroid = Vec2::Zero();      // in the parameter domain
  Vec3 site3D = Vec3::Zero(), centroid3D = Vec3::Zero();  // lifted to the surface
  double area = 0;         // of cell ∩ domain in the parameter domain
  double surfaceArea = 0;  // of the same piece of surface, in 3D
  double mass = 0;         // ∫ rho over the cell
  Vec2 moment = Vec2::Zero();  // ∫ x rho: the centroid is moment / mass
  double energy = 0;           // ∫ rho |x - site|^2
  // The shoelace formulas over the cell's pieces, with c_i = x_i y_{i+1} - x_{i+1} y_i:
  // area = Σ c_i / 2 and sums = Σ (x_i + x_{i+1}) c_i, Σ (y_i + y_{i+1}) c_i, so that the
  // unweighted centroid is sums / (6 area).
  double shoelaceArea = 0;
  Vec2 shoelaceSums = Vec2::Zero();
  int pieces = 0;          // parameter triangles the cell overlaps
  int neighbours = 0;      // cells it shares an edge with
  double moved = 0;        // |site_k - site_k-1|; 0 at iteration 0
  double toCentroid = 0;   // |centroid - site|
  int valence = -1;        // of the site's vertex in the result; -1 if it is not a vertex
};

CellDetails describeCell(const Recording& recording, const Domain& domain,
                         const IterationView& view, int cell);

// Each site's vertex in the view's result, stitched where it was cut open (valence -1 where the
// site is no vertex of it: one on top of another, or outside the border samples' polygon).
// Together they make the result's irregularity: the "valence" fill.
std::vector<VertexValence> siteValences(const IterationView& view);

// The irregular vertices of `mesh` (QualityMetrics::irregularBoundaryAware's): fives and sevens
// inside, the others (inside or on the border).
struct IrregularCounts {
  int fives = 0, sevens = 0, others = 0;
};
IrregularCounts irregularCounts(const Mesh& mesh);

// Where site i was at every recorded iteration.
std::vector<Vec2> siteTrajectory(const Recording& recording, int site);
// How far site `cell` (of all sites, fixed first) moved from iteration k - 1 to k: 0 for a
// fixed site, and at iteration 0.
double siteMoved(const Recording& recording, int k, size_t cell);

// The cell that holds p (its nearest site), or -1 when p is outside the domain.
int cellAt(const Domain& domain, const IterationView& view, const Vec2& p);

struct TriangleDetails {
  int index = -1;
  Triangle corners{};                   // output vertices
  std::array<double, 3> angles3D{}, anglesUV{};  // degrees, at each corner
  double area3D = 0, areaUV = 0;
  // (area3D / total 3D area) / (areaUV / total UV area): 1 where the map keeps areas.
  double areaDistortion = 0;
  double minAngle = 0;                  // in 3D, degrees
  std::array<int, 3> valences{};        // of each corner, in the whole mesh
  std::array<bool, 3> onBorder{};       // regular: 4 on the border, 6 inside
  std::array<int, 3> sites{};           // the site each corner is, or -1 (not moved)
  // Whether the corner is at its site: relocate stops a vertex short where it would fold.
  std::array<bool, 3> atSite{};
};

// A triangle of an iteration's result: in 3D, in the parameter domain, and its corners' sites.
TriangleDetails describeTriangle(const IterationView& view, int triangle);
// A triangle of a mesh with no map (the final result, cleaned up in 3D): the 3D numbers only,
// no UV ones, every corner "not moved".
TriangleDetails describeTriangle(const Mesh& mesh, int triangle);

// A triangle of an iteration's result by what makes it: its corners' sites, sorted (a corner
// that is no site by -1 - its vertex's number). The sites' triangulation changes from iteration
// to iteration and the triangles' numbers with it: a pin that holds a triangle's corners finds
// it again in each iteration (triangleWithCorners), or finds none where they make no triangle.
using TriangleCorners = std::array<int, 3>;
TriangleCorners cornersOf(const IterationView& view, int triangle);
int triangleWithCorners(const IterationView& view, const TriangleCorners& corners);  // -1: none

// The output triangle whose parameter-domain image holds p, or -1.
int triangleAtUV(const IterationView& view, const Vec2& p);
// The output triangle the ray from `origin` along `direction` hits first, or -1.
int triangleOnRay(const Mesh& mesh, const Vec3& origin, const Vec3& direction);

}  // namespace lloydscope
