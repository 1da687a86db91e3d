// Mesh quality (the reference's Table II and more) and fidelity to another surface (Metro-style).
#pragma once

#include "mesh.h"

#include <array>
#include <vector>

namespace lloydscope {

struct SearchableSurface;

// A vertex of the border, the sum of its triangles' angles, how many they are, and its
// shorter border edge (the scale to tell whether two corners are the same place).
struct BorderCorner {
  Vec3 at = Vec3::Zero();
  double degrees = 0;
  int triangles = 0;
  double shorterEdge = 0;
};

// A vertex's valence (-1: no vertex) and whether it is on its mesh's border.
struct VertexValence {
  int valence = -1;
  bool onBorder = false;
  bool isVertex() const { return valence >= 0; }
  // Less a regular vertex's, 6 inside and 4 on the border: -1 for a 5 inside, +1 for a 7.
  int offset() const { return valence - (onBorder ? 4 : 6); }
  bool irregular() const { return isVertex() && offset() != 0; }  // what irregularBoundaryAware counts
};
// Every vertex's, from vertexEdges().
std::vector<VertexValence> vertexValences(const Mesh& mesh);

struct QualityMetrics {
  int vertices = 0, faces = 0, boundaryVertices = 0;
  double irregularPercent = 0;       // vertices of valence != 6, all of them (the reference)
  double irregularBoundaryAware = 0; // interior valence != 6 and boundary valence != 4
  double minAngle = 0, maxAngle = 0; // degrees, over all triangles
  double avgMinAngle = 0;            // mean of each triangle's smallest angle
  double percentUnder30 = 0;         // triangles whose smallest angle is under 30 degrees
  // How much the surface curves at the mesh's size, in valence defects per 100 vertices: the
  // angles at an inside vertex sum to 360 degrees less its angle defect (the curvature around
  // it), at a border vertex to 180 less its turn; each |defect| in units of 60 degrees,
  // summed. With every angle 60 degrees a vertex of valence d has a defect of exactly
  // |6 - d| (|4 - d| on the border) such units, so this is the irregularity (%) a mesh of the
  // same vertices with equilateral triangles would have where each irregular vertex is one
  // off (a 5 or a 7 inside).
  // A remesher goes under it only by bending angles away from 60 degrees; more vertices
  // share the same curvature and lower it. It depends on where the vertices are, not on how
  // they are joined (a flat region adds nothing, whatever its valences).
  double curvatureDefects = 0;
  // The part of it from the border's vertices (their turns), in the same units: all of it on a
  // flat disk with a jagged rim (a flat gear of 40 teeth at 400 vertices: 59.9 units, said to
  // be the surface curving).
  double curvatureDefectsOnBorder = 0;
  std::array<int, 18> angleHistogram{};  // all corner angles in 10-degree bins, 0..180
  // Inside edges whose two triangles' normals turn more than kFoldDegrees: the surface folds
  // back on itself there (a fin, or a result's triangles bridging the two sides of a thin flap:
  // no angle shows it). Each one's ends: folds of the result the input has there too are its
  // own, not the remeshing's.
  struct Fold {
    Vec3 from = Vec3::Zero(), to = Vec3::Zero();
    Vec3 middle() const { return 0.5 * (from + to); }
    double length() const { return (to - from).norm(); }
  };
  std::vector<Fold> folds;
  int foldedEdges() const { return static_cast<int>(folds.size()); }
  // The smallest sum of the angles at a border vertex, degrees (360 with no border).
  double sharpestBorderCorner = 360;
  // The border's corners sharper than kSharpCornerDegrees, by sharpness: a remesher that keeps
  // the border's corners (this one does, as CGAL's does) cannot raise the angle of the one
  // triangle that fills one (a clipped surface whose cut grazes a hole's rim: 13 degrees).
  std::vector<BorderCorner> sharpCorners;
  // The smallest angle but those at a sharp corner that one triangle fills: the angles a
  // remesher has a say in.
  double minAngleOffSharpCorners = 180;
  // Under 30 degrees: where the smallest angle is (its corner's vertex, of worstTriangle()); and
  // where its triangle touches a border loop shorter than kPinholeOfMeanEdge of the mean edge,
  // that loop's edges and length, and the mean edge (of every triangle's sides: an inside edge
  // counts twice): a pinhole the border keeps, ringed by needles no remeshing widens (a sphere
  // with a hole 10^-6 across: 0.0001 degrees, said nowhere). Zeros where not.
  Vec3 minAngleAt = Vec3::Zero();
  int minAngleHoleEdges = 0;
  double minAngleHoleLength = 0, meanEdge = 0;
  // Where that corner's vertex is inside and its angles sum to under 90 degrees (three of 30):
  // the sum, at a tip of the surface (a spike's apex, on which a vertex is put to stay close to
  // it) where no triangles around a vertex can all reach 30. 0 where not.
  double minAngleTipSum = 0;
};
constexpr double kFoldDegrees = 150.0;
constexpr double kPinholeOfMeanEdge = 0.5;
// Border corners kept in QualityMetrics::sharpCorners: those under 30 degrees, and those a
// little wider that a result's corner at the same place may be a little sharper than (the
// first border samples along two sides that curve outward cut the corner's chords inward).
constexpr double kCornerSlackDegrees = 0.5;
constexpr double kSharpCornerDegrees = 30.0 + kCornerSlackDegrees;

QualityMetrics measureQuality(const Mesh& mesh);

// The quality bars a remesher is held to (issue 5): irregular vertices, boundary-aware, at
// most 15%; no angle under 30 degrees; an average smallest angle of 53 degrees or more. (The
// fourth, the Hausdorff distance no larger than CGAL's remesher's, needs that run.)
constexpr double kMostIrregularPercent = 15.0;
constexpr double kLeastMinAngle = 30.0;
constexpr double kLeastAvgMinAngle = 53.0;
// The smallest-angle bar within the input's reach: no angle under 30 degrees but at the
// result's sharp corners that one triangle fills, each at a corner of the input's border no
// more than kCornerSlackDegrees wider.
bool meetsMinAngleBar(const QualityMetrics& result, const QualityMetrics& input);
// A corner of the border under 30 degrees that one triangle fills: that triangle's angle there is
// the corner's.
inline bool filledByOneTriangle(const BorderCorner& c) { return c.triangles == 1 && c.degrees < kLeastMinAngle; }
// The input's own sharp corner that the result's `corner` keeps: at the same place, and no more
// than kCornerSlackDegrees wider; else null.
const BorderCorner* inputCornerKept(const QualityMetrics& input, const BorderCorner& corner);
// How many of the three a result of `input` meets.
int barsMet(const QualityMetrics& result, const QualityMetrics& input);
// The result's folded edges (QualityMetrics::folds) where `input` folds nowhere that much: none
// of its folded edges within twice the result's edge's length of the result edge's middle.
// (The counts were compared: one fold of the dino's anywhere hid the result's 30 at its legs
// and neck.)
int foldsAnew(const QualityMetrics& result, const QualityMetrics& input);

struct Fidelity {
  // Two-sided distances between the surfaces, in % of the reference's bounding-box diagonal.
  double hausdorffPercent = 0;
  double rmsPercent = 0;
  int samples = 0;
  // Where the Hausdorff distance is reached: the point farthest from the other surface, and
  // on which surface it lies (to show a user where the result strays most).
  Vec3 farthestPoint = Vec3::Zero();
  bool farthestOnReference = false;
};

// Samples each surface (vertices, edge midpoints and area-weighted random points, fixed seed:
// 10,000 and ten per triangle, but twenty per triangle of the other surface at most)
// and measures the distance to the other with an AABB tree, in both directions, as Metro does;
// then searches the triangles of the farthest samples for the farthest point between them.
// The Hausdorff distance is the larger of the two one-sided ones, the RMS distance the larger
// of the two one-sided RMS distances over the area (the random points).
Fidelity measureFidelity(const Mesh& mesh, const Mesh& reference);
// The same against a reference whose search is built already (several meshes measured
// against one: the trials of a run).
Fidelity measureFidelity(const Mesh& mesh, const SearchableSurface& reference);

// Where the result's border cuts corners of the input's border, the input's border vertices
// where its border is coarse (both border edges at least 0.7 of the result's mean border edge):
// the corners to keep as samples. Cut: an input border vertex (a convex corner cut off), or the
// midpoint of a border edge of the result (its chord across a reflex corner), farther from the
// other mesh than kCutOffBy times the farthest of the input's other vertices and of the
// result's triangle centroids and inside edge midpoints from the input, and than 0.03 of the
// result's mean border edge. Where the input's border is coarser than the result's and bends
// at its vertices (a saddle over a polar grid, its rim a 48-gon; a part's rim clipped by a
// plane), the result's border edge between two samples cuts each corner between them, and that
// is the Hausdorff distance; CGAL's remesher keeps the input's border vertices. Empty where
// none is cut. The reflex corners' chords, once counted, brought 9 of 287 disks clipped from
// CGAL's samples at 1000 vertices under CGAL's distance (the six caps of a coarse sphere:
// 0.19-0.25% of the diagonal, CGAL's 0.11-0.17%; 0.09-0.13% with the rim's vertices kept).
// 1.25 rather than 1.5 brought a CAD part's cap under it too (0.043 -> 0.034%, CGAL's 0.040;
// its creases inside strayed 0.78 times as far as its border), the trial made on 38 of the
// 287 instead of 22, and no result farther.
constexpr double kCutOffBy = 1.25;
std::vector<Vec3> borderCornersCut(const Mesh& result, const SearchableSurface& input);

// The three corner angles of a triangle, in degrees.
std::array<double, 3> cornerAnglesDeg(const Vec3& a, const Vec3& b, const Vec3& c);
// The smallest of them, with one arctangent instead of three: the last steps' searches measure
// millions of triangles (10-15% of their time at 1000 vertices).
double smallestAngleDeg(const Vec3& a, const Vec3& b, const Vec3& c);

// The triangle with the smallest angle of the mesh (the first of equals), -1 for none: the one
// to look at first when a result is worse than it should be.
int worstTriangle(const Mesh& mesh);

}  // namespace lloydscope
