// Splitting a surface into charts (issue 6): where one cut to a disk leaves a map that no
// parameterization holds (a part with many handles: CGAL's anchor, coupling and turbine; a
// closed animal whose conformal map folds), each chart, nearly flat, is mapped on its own and
// remeshed on its own; the charts' shared borders are seams whose samples both sides place
// alike (the same 3D spacing from the same nodes), stitched back afterwards.
#pragma once

#include "mesh.h"

#include <utility>
#include <vector>

namespace lloydscope {

struct ChartOptions {
  // A chart's face normals stay within this angle of its seed face's: nearly a height field,
  // which a conformal map flattens with little distortion and no fold, and the sharp edges of
  // a CAD part become seams, sampled exactly. On 10 of CGAL's samples that need charts, 45
  // degrees met issue 6's bars on all (60: the coupling at 2.04%, the anchor at 2.57%).
  double coneDegrees = 45;
  // A chart with fewer than this many of the result's vertices (by its share of the area) is
  // merged into the neighbour it shares the longest border with.
  int smallestShare = 20;
};

struct Chart {
  Mesh mesh;                  // manifold, connected; may have several border loops or handles
  std::vector<int> original;  // per chart vertex, the surface's vertex
  // Per chart vertex: on a border shared with another chart, and a node there (where three
  // charts or a chart border and the surface's border meet; one vertex of a border loop that
  // meets none): what SiteOptions needs to sample the two sides of a seam alike.
  std::vector<bool> onSeam, seamNode;
  // The sites to add to the chart's share for the nodes where k > 2 charts meet: stitching
  // merges a node's k copies into one, where a seam sample's two copies count half in each
  // chart; (k - 2) / 2k per node and chart makes the result's count come out as asked.
  double nodeSamples = 0;
  // The length of its border on seams (edges with both ends on a seam): half its samples there
  // are another chart's.
  double seamLength = 0;
  // Per chart vertex, its projection onto the plane normal to the chart's mean normal: a map to
  // try where a conformal one folds (ParamOptions::fallback: its own folds repaired as LSCM's
  // are, or the next map tried).
  std::vector<Vec2> uv;
};

struct Charts {
  std::vector<Chart> charts;
  int seamEdges = 0;  // edges of the surface between two charts
};

// The charts of a valid manifold mesh of one component, each a topological disk: grown from the
// first face not yet taken over its neighbours within the normal cone, then the small ones
// merged into a neighbour where the union is a disk (one that stays within 75 degrees of its
// mean normal first). `resultVertices`: the size the result
// will have (smallestShare).
Charts splitIntoCharts(const Mesh& mesh, int resultVertices, const ChartOptions& options = {});

// The border edges of `surface` (a chart's mesh, or its resampling) whose two ends lie on the
// chart's seams (its border edges with both ends `onSeam`): where it meets the other charts.
std::vector<std::pair<int, int>> sharedSeamEdges(const Mesh& surface, const Mesh& chart,
                                                 const std::vector<bool>& onSeam);

}  // namespace lloydscope
