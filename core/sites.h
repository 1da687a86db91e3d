// Where Lloyd relaxation starts: fixed sites on the border, movable sites inside.
#pragma once

#include "domain.h"
#include "parameterization.h"

#include <cstdint>
#include <string>
#include <vector>

namespace lloydscope {

struct SiteOptions {
  // true: one movable site per inside vertex, the border's own vertices as fixed sites (the
  // reference's choice, and what the relocate method needs).
  // false: `count` sites in all (0: as many as the input has vertices), the border resampled at
  // the spacing that count gives, the inside sampled from the density.
  bool fromInputVertices = false;
  int count = 0;
  std::uint64_t seed = 1;
  // A surface cut open (core/cut), per vertex: a node of the cut graph, and on a seam. The two
  // copies of a seam must get the same samples: nodes are always samples, and no other corner
  // is taken on a seam. Empty: no seams.
  std::vector<bool> seamNode, onSeam;
  // > 0: the border's samples this far apart (3D arc length) whatever `count` gives: charts of
  // one surface (core/charts) sample their shared borders alike.
  double spacing = 0;
  // > 0, on a surface cut open to one disk (both copies of each seam on it): as many inside
  // sites as leave this many vertices once each seam sample's two copies are stitched into one
  // (`count` still sets the spacing, and over the seams' copies it can only be estimated).
  int stitchedCount = 0;
  // Seams shared with another surface's samples (a chart's, with its spacing given): their
  // points must match exactly, so the border samples' points are InitialSites::fixedPoints.
  bool sharesSeams() const { return spacing > 0 && !onSeam.empty(); }
  // Points of the input's border that stay samples: a border vertex of the surface sampled
  // (the input, or its rough first remeshing) within a millionth of its diagonal of one is a
  // corner, as a corner of the surface is (the corners a result's border cut:
  // borderCornersCut in core/metrics, and the pipeline's BorderTrial). Not on a seam.
  std::vector<Vec3> keptBorderPoints;
};

struct InitialSites {
  std::vector<Vec2> fixed;      // along the border, counter-clockwise, in order
  // Each fixed site's point on the mesh's border, interpolated along its edge in 3D: exactly
  // where both copies of a seam sample are (lifting it through the map may land it on an
  // inside edge where the map is nearly flat at the border).
  std::vector<Vec3> fixedPoints;
  std::vector<Vec2> movable;
  std::vector<int> movableVertex;  // the input vertex each movable site started at, or -1
};

// The fewest vertices a surface is remeshed to: a handful leave its border a sample or two,
// nothing to triangulate (the camel head at 10 came out empty). And the most a run is asked
// for (ten times the 100,000 sites issue 5 times Lloyd's iterations at; the command line's
// limit): more is a slip of the keyboard that would run for hours.
constexpr int kSmallestRemeshedShare = 20, kMostRemeshedVertices = 1000000;
// The most border samples per vertex asked (kSmallestRemeshedShare at least): a border sampled
// at their spacing beyond that is a sliver's, or a slit's up a spike far longer than wide, and
// runs away with the run (a strip 10^6 to 1 took 16,751 vertices for 81 asked, in 31 s; a slit
// up a spike 10^6 tall and 1 wide took thousands for 9, in 55 s).
constexpr int kMostBorderPerVertex = 10;

// Where to sample a stretch of the border `length` long between two of its corners, as distances
// from its start (the first is 0, the corner itself): `pieces` evenly; but beside a corner of
// the surface under 30 degrees (`beginDegrees`, `endDegrees`: the sums of the angles at the two
// corners), graded towards it, each gap about the wedge's width, and evenly between.
std::vector<double> borderSamplePositions(double length, double spacing, int pieces, double beginDegrees,
                                          double endDegrees);

// Throws Error where the border takes over kMostBorderPerVertex times the vertices asked.
InitialSites initialSites(const Mesh& mesh, const Parameterization& param, const Domain& domain,
                          const SiteOptions& options, const std::string& name);

}  // namespace lloydscope
