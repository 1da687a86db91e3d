#include "inspection.h"

#include "metrics.h"

#include <algorithm>
#include <cmath>

namespace lloydscope {

namespace {

// The angles of a 2D triangle, in degrees (the 3D formula with z = 0).
std::array<double, 3> cornerAnglesDeg(const Vec2& a, const Vec2& b, const Vec2& c) {
  auto flat = [](const Vec2& p) { return Vec3(p.x(), p.y(), 0.0); };
  return lloydscope::cornerAnglesDeg(flat(a), flat(b), flat(c));
}

}  // namespace

CellDetails describeCell(const Recording& recording, const Domain& domain,
                         const IterationView& view, int cell) {
  CellDetails d;
  if (cell < 0 || cell >= static_cast<int>(view.cells.size())) return d;
  const BoundedCell& c = view.cells[cell];
  d.index = cell;
  d.fixed = cell < static_cast<int>(recording.fixedSites.size());
  d.site = view.sites[cell];
  d.centroid = c.centroid;
  d.site3D = view.liftedSites[cell];
  d.centroid3D = lift(recording.input, domain, c.centroid);
  d.area = c.area;
  d.mass = c.mass;
  d.moment = c.mass * c.centroid;
  d.energy = c.energy;
  d.pieces = static_cast<int>(c.pieces.size());
  d.neighbours = static_cast<int>(c.neighbours.size());
  d.toCentroid = (c.centroid - d.site).norm();
  for (const CellPiece& piece : c.pieces) {
    const Triangle& t = domain.triangles()[piece.triangle];
    const Vec3* p = recording.input.points.data();
    const double stretch = triangleArea(p[t[0]], p[t[1]], p[t[2]]) /
                           triangleArea(domain.uv()[t[0]], domain.uv()[t[1]], domain.uv()[t[2]]);
    double pieceArea = 0;
    for (size_t i = 0; i < piece.polygon.size(); ++i) {
      const Vec2 &a = piece.polygon[i], &b = piece.polygon[(i + 1) % piece.polygon.size()];
      const double ci = cross(a, b);
      pieceArea += 0.5 * ci;
      d.shoelaceSums += (a + b) * ci;
    }
    d.shoelaceArea += pieceArea;
    d.surfaceArea += pieceArea * stretch;
  }
  d.moved = siteMoved(recording, view.index, cell);
  d.valence = siteValences(view)[cell].valence;
  return d;
}

std::vector<VertexValence> siteValences(const IterationView& view) {
  std::vector<VertexValence> valences(view.sites.size());
  const std::vector<VertexValence> ofVertices = vertexValences(view.measured());
  for (size_t v = 0; v < view.outputSite.size(); ++v)
    if (const int measured = view.measuredVertex(static_cast<int>(v)); view.outputSite[v] >= 0 && measured >= 0)
      valences[view.outputSite[v]] = ofVertices[measured];
  return valences;
}

IrregularCounts irregularCounts(const Mesh& mesh) {
  IrregularCounts counts;
  for (const VertexValence& v : vertexValences(mesh)) {
    if (!v.irregular()) continue;
    const int insideOffset = v.onBorder ? 0 : v.offset();  // -1 a 5, +1 a 7
    ++(insideOffset == -1 ? counts.fives : insideOffset == 1 ? counts.sevens : counts.others);
  }
  return counts;
}

double siteMoved(const Recording& recording, int k, size_t cell) {
  const size_t fixed = recording.fixedSites.size();
  if (cell < fixed || k <= 0) return 0;
  return (recording.iterations[k].sites[cell - fixed] - recording.iterations[k - 1].sites[cell - fixed]).norm();
}

std::vector<Vec2> siteTrajectory(const Recording& recording, int site) {
  std::vector<Vec2> path;
  const int fixedCount = static_cast<int>(recording.fixedSites.size());
  for (const IterationRecord& it : recording.iterations) {
    if (site < fixedCount) path.push_back(recording.fixedSites.at(site));
    else if (site - fixedCount < static_cast<int>(it.sites.size()))
      path.push_back(it.sites[site - fixedCount]);
  }
  return path;
}

int cellAt(const Domain& domain, const IterationView& view, const Vec2& p) {
  if (view.sites.empty() || !domain.locate(p).inside) return -1;
  int best = 0;
  for (int i = 1; i < static_cast<int>(view.sites.size()); ++i)
    if ((view.sites[i] - p).squaredNorm() < (view.sites[best] - p).squaredNorm()) best = i;
  return best;
}

TriangleDetails describeTriangle(const Mesh& mesh, int triangle) {
  TriangleDetails d;
  if (triangle < 0 || triangle >= static_cast<int>(mesh.triangles.size())) return d;
  d.index = triangle;
  d.corners = mesh.triangles[triangle];
  const Triangle& t = d.corners;
  d.angles3D = cornerAnglesDeg(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]]);
  d.area3D = triangleArea(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]]);
  d.minAngle = *std::min_element(d.angles3D.begin(), d.angles3D.end());
  const VertexEdges edges = vertexEdges(mesh);
  for (int k = 0; k < 3; ++k) {
    d.valences[k] = edges.valence[t[k]];
    d.onBorder[k] = edges.onBoundary[t[k]];
    d.sites[k] = -1;
  }
  return d;
}

TriangleDetails describeTriangle(const IterationView& view, int triangle) {
  TriangleDetails d = describeTriangle(view.output, triangle);
  if (d.index < 0) return d;
  const Triangle& t = d.corners;
  d.anglesUV = cornerAnglesDeg(view.outputUV[t[0]], view.outputUV[t[1]], view.outputUV[t[2]]);
  d.areaUV = std::abs(triangleArea(view.outputUV[t[0]], view.outputUV[t[1]], view.outputUV[t[2]]));
  const double total3D = surfaceArea(view.output);
  const double totalUV = mapArea(view.output, view.outputUV);
  d.areaDistortion = d.areaUV > 0 ? (d.area3D / total3D) / (d.areaUV / totalUV) : INFINITY;
  for (int k = 0; k < 3; ++k) {
    d.sites[k] = view.outputSite[t[k]];
    d.atSite[k] = d.sites[k] >= 0 && view.outputUV[t[k]] == view.sites[d.sites[k]];
  }
  return d;
}

TriangleCorners cornersOf(const IterationView& view, int triangle) {
  TriangleCorners corners;
  for (int k = 0; k < 3; ++k) {
    const int v = view.output.triangles[triangle][k];
    corners[k] = view.outputSite[v] >= 0 ? view.outputSite[v] : -1 - v;
  }
  std::sort(corners.begin(), corners.end());
  return corners;
}

int triangleWithCorners(const IterationView& view, const TriangleCorners& corners) {
  for (int f = 0; f < static_cast<int>(view.output.triangles.size()); ++f)
    if (cornersOf(view, f) == corners) return f;
  return -1;
}

int triangleAtUV(const IterationView& view, const Vec2& p) {
  for (size_t f = 0; f < view.output.triangles.size(); ++f) {
    const Triangle& t = view.output.triangles[f];
    const Vec2 &a = view.outputUV[t[0]], &b = view.outputUV[t[1]], &c = view.outputUV[t[2]];
    const double s = triangleArea(a, b, c);
    const double w[3] = {triangleArea(p, b, c) / s, triangleArea(a, p, c) / s,
                         triangleArea(a, b, p) / s};
    if (w[0] >= 0 && w[1] >= 0 && w[2] >= 0) return static_cast<int>(f);
  }
  return -1;
}

int triangleOnRay(const Mesh& mesh, const Vec3& origin, const Vec3& direction) {
  // Möller-Trumbore, both sides, nearest hit in front of the origin.
  int best = -1;
  double nearest = INFINITY;
  for (size_t f = 0; f < mesh.triangles.size(); ++f) {
    const Triangle& t = mesh.triangles[f];
    const Vec3 &a = mesh.points[t[0]], e1 = mesh.points[t[1]] - a, e2 = mesh.points[t[2]] - a;
    const Vec3 p = direction.cross(e2);
    const double det = e1.dot(p);
    if (std::abs(det) < 1e-300) continue;
    const Vec3 s = origin - a;
    const double u = s.dot(p) / det;
    if (u < 0 || u > 1) continue;
    const Vec3 q = s.cross(e1);
    const double v = direction.dot(q) / det;
    if (v < 0 || u + v > 1) continue;
    const double distance = e2.dot(q) / det;
    if (distance > 0 && distance < nearest) {
      nearest = distance;
      best = static_cast<int>(f);
    }
  }
  return best;
}

}  // namespace lloydscope
