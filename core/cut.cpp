#include "cut.h"

#include "cgal_types.h"
#include "parameterization.h"
#include "topology.h"

#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>

#include <algorithm>
#include <functional>
#include <limits>
#include <map>
#include <numeric>
#include <queue>
#include <set>

namespace lloydscope {

namespace {

using Edge = std::pair<int, int>;  // a < b
Edge edge(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

// Each undirected edge to the faces that have it (one on the border, two inside).
std::map<Edge, std::vector<int>> edgeFaces(const Mesh& mesh) {
  std::map<Edge, std::vector<int>> faces;
  for (int f = 0; f < mesh.faceCount(); ++f)
    for (int k = 0; k < 3; ++k)
      faces[edge(mesh.triangles[f][k], mesh.triangles[f][(k + 1) % 3])].push_back(f);
  return faces;
}

using Neighbours = std::vector<std::vector<int>>;

Neighbours neighboursOf(const Mesh& mesh) {
  Neighbours neighbours(mesh.vertexCount());
  for (const Triangle& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      neighbours[t[k]].push_back(t[(k + 1) % 3]);
      neighbours[t[(k + 1) % 3]].push_back(t[k]);
    }
  for (auto& n : neighbours) {
    std::sort(n.begin(), n.end());
    n.erase(std::unique(n.begin(), n.end()), n.end());
  }
  return neighbours;
}

// Shortest paths (by edge length) from `sources`: distance and predecessor of every vertex.
struct ShortestPaths {
  std::vector<double> distance;
  std::vector<int> previous;  // -1 at the sources
};

ShortestPaths dijkstra(const Mesh& mesh, const Neighbours& neighbours, const std::vector<int>& sources) {
  ShortestPaths paths{std::vector<double>(mesh.vertexCount(), std::numeric_limits<double>::infinity()),
                      std::vector<int>(mesh.vertexCount(), -1)};
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  for (int s : sources) {
    paths.distance[s] = 0;
    queue.push({0.0, s});
  }
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > paths.distance[v]) continue;
    for (int w : neighbours[v]) {
      const double through = d + (mesh.points[w] - mesh.points[v]).norm();
      if (through < paths.distance[w]) {
        paths.distance[w] = through;
        paths.previous[w] = v;
        queue.push({through, w});
      }
    }
  }
  return paths;
}

void addPath(const ShortestPaths& paths, int from, std::set<Edge>& cut) {
  for (int v = from; paths.previous[v] >= 0; v = paths.previous[v]) cut.insert(edge(v, paths.previous[v]));
}

std::vector<int> verticesOf(const std::set<Edge>& cut) {
  std::vector<int> vertices;
  for (const auto& [a, b] : cut) vertices.push_back(a), vertices.push_back(b);
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  return vertices;
}

// A tree of shortest paths joining three extremities of a closed genus-0 surface, each the
// vertex farthest from the ones before (a slit of one edge would not open).
std::set<Edge> slitThroughExtremities(const Mesh& mesh, const Neighbours& neighbours) {
  auto farthest = [](const ShortestPaths& paths) {
    return static_cast<int>(std::max_element(paths.distance.begin(), paths.distance.end()) -
                            paths.distance.begin());
  };
  std::vector<int> slit = {farthest(dijkstra(mesh, neighbours, {0}))};
  std::set<Edge> cut;
  for (int extremity = 1; extremity < 3; ++extremity) {
    const ShortestPaths paths = dijkstra(mesh, neighbours, slit);
    addPath(paths, farthest(paths), cut);
    slit = verticesOf(cut);
  }
  return cut;
}

// The border loops, joined one by one to the nearest loop not yet joined by a shortest path
// (Prim's order): one border once cut.
std::set<Edge> joinBorderLoops(const Mesh& mesh, const Neighbours& neighbours,
                               const std::vector<std::vector<int>>& loops) {
  std::set<Edge> cut;
  for (const auto& loop : loops)
    for (size_t i = 0; i < loop.size(); ++i) cut.insert(edge(loop[i], loop[(i + 1) % loop.size()]));
  std::vector<int> loopOf(mesh.vertexCount(), -1);
  for (size_t l = 0; l < loops.size(); ++l)
    for (int v : loops[l]) loopOf[v] = static_cast<int>(l);
  std::vector<bool> joined(loops.size(), false);
  std::vector<int> sources = loops.empty() ? std::vector<int>{} : loops[0];
  if (!loops.empty()) joined[0] = true;
  for (size_t count = 1; count < loops.size(); ++count) {
    const ShortestPaths paths = dijkstra(mesh, neighbours, sources);
    int nearest = -1;
    for (int v = 0; v < mesh.vertexCount(); ++v)
      if (loopOf[v] >= 0 && !joined[loopOf[v]] &&
          (nearest < 0 || paths.distance[v] < paths.distance[nearest]))
        nearest = v;
    joined[loopOf[nearest]] = true;
    for (int v = nearest; v >= 0; v = paths.previous[v]) sources.push_back(v);
    sources.insert(sources.end(), loops[loopOf[nearest]].begin(), loops[loopOf[nearest]].end());
    addPath(paths, nearest, cut);
  }
  return cut;
}

// Around each handle, the shortest loop the tree-cotree construction offers (Erickson and
// Whittlesey's greedy system of loops): a tree T of shortest paths from `base` (the cut so
// far, or one vertex), a dual spanning tree of the faces across the other edges, heaviest
// loops first; each edge left over closes one loop through T. Smooth, short loops instead of
// the jagged ones an arbitrary spanning tree leaves.
std::set<Edge> handleLoops(const Mesh& mesh, const Neighbours& neighbours,
                           const std::map<Edge, std::vector<int>>& faces, const std::set<Edge>& cut,
                           const std::vector<int>& base) {
  const ShortestPaths tree = dijkstra(mesh, neighbours, base);
  auto inTree = [&](const Edge& e) {
    return tree.previous[e.first] == e.second || tree.previous[e.second] == e.first;
  };
  struct Candidate {
    double loopLength;
    Edge edge;
  };
  std::vector<Candidate> candidates;
  for (const auto& [e, fs] : faces)
    if (fs.size() == 2 && !cut.count(e) && !inTree(e))
      candidates.push_back({tree.distance[e.first] + tree.distance[e.second] +
                                (mesh.points[e.first] - mesh.points[e.second]).norm(),
                            e});
  std::sort(candidates.begin(), candidates.end(),
            [](const Candidate& a, const Candidate& b) { return a.loopLength > b.loopLength; });
  std::vector<int> parent(mesh.faceCount());  // union-find over faces
  std::iota(parent.begin(), parent.end(), 0);
  std::function<int(int)> root = [&](int f) { return parent[f] == f ? f : parent[f] = root(parent[f]); };
  std::set<Edge> loops;
  for (const Candidate& c : candidates) {
    const auto& fs = faces.at(c.edge);
    const int a = root(fs[0]), b = root(fs[1]);
    if (a != b) {
      parent[a] = b;  // a dual tree edge: not cut
      continue;
    }
    loops.insert(c.edge);
    addPath(tree, c.edge.first, loops);
    addPath(tree, c.edge.second, loops);
  }
  // Two loops' paths to the base share their last stretch: a branch that leads nowhere.
  std::map<int, int> degree;
  for (const Edge& e : loops) ++degree[e.first], ++degree[e.second];
  for (const Edge& e : cut) ++degree[e.first], ++degree[e.second];
  for (bool pruned = true; pruned;) {
    pruned = false;
    for (auto it = loops.begin(); it != loops.end();)
      if (degree[it->first] == 1 || degree[it->second] == 1) {
        --degree[it->first];
        --degree[it->second];
        it = loops.erase(it);
        pruned = true;
      } else {
        ++it;
      }
  }
  return loops;
}

// Opens the mesh along `cut`: the corners around each vertex are grouped into the wedges that
// cut edges separate, and each wedge gets its own copy of the vertex.
CutResult cutAlong(const Mesh& mesh, const std::map<Edge, std::vector<int>>& faces,
                   const std::set<Edge>& cut) {
  std::vector<int> parent(3 * mesh.faceCount());  // union-find over corners (3 f + k)
  std::iota(parent.begin(), parent.end(), 0);
  std::function<int(int)> root = [&](int c) { return parent[c] == c ? c : parent[c] = root(parent[c]); };
  auto corner = [&](int f, int v) {
    for (int k = 0; k < 3; ++k)
      if (mesh.triangles[f][k] == v) return 3 * f + k;
    return -1;
  };
  for (const auto& [e, fs] : faces) {
    if (fs.size() != 2 || cut.count(e)) continue;
    for (int v : {e.first, e.second}) parent[root(corner(fs[0], v))] = root(corner(fs[1], v));
  }
  CutResult result;
  std::map<int, int> copyOf;  // root corner -> disk vertex
  result.disk.triangles = mesh.triangles;
  for (int f = 0; f < mesh.faceCount(); ++f)
    for (int k = 0; k < 3; ++k) {
      const auto [it, added] = copyOf.emplace(root(3 * f + k), result.disk.vertexCount());
      if (added) {
        result.disk.points.push_back(mesh.points[mesh.triangles[f][k]]);
        result.original.push_back(mesh.triangles[f][k]);
      }
      result.disk.triangles[f][k] = it->second;
    }
  for (const Edge& e : cut)
    if (faces.at(e).size() == 2) result.seam.push_back(e);
  return result;
}

}  // namespace

namespace {

void markSeams(CutResult& cut, const Mesh& input, const std::map<Edge, std::vector<int>>& faces) {
  std::vector<bool>& node = cut.seamNode;
  std::vector<bool>& onSeam = cut.onSeam;
  std::vector<int> degree(input.vertexCount(), 0), seamDegree(input.vertexCount(), 0);
  for (const auto& [a, b] : cut.seam) ++seamDegree[a], ++seamDegree[b];
  for (const auto& [e, fs] : faces)
    if (fs.size() == 1) ++degree[e.first], ++degree[e.second];
  node.assign(cut.disk.vertexCount(), false);
  onSeam.assign(cut.disk.vertexCount(), false);
  for (int v = 0; v < cut.disk.vertexCount(); ++v) {
    const int o = cut.original[v];
    onSeam[v] = seamDegree[o] > 0;
    node[v] = onSeam[v] && degree[o] + seamDegree[o] != 2;
  }
}

}  // namespace

std::vector<int> firstCopies(const std::vector<Vec3>& points, const std::vector<bool>& among, double tolerance) {
  std::vector<int> order;
  for (int v = 0; v < static_cast<int>(points.size()); ++v)
    if (among.empty() || among[v]) order.push_back(v);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return points[a].x() < points[b].x(); });
  std::vector<int> target(points.size());
  std::iota(target.begin(), target.end(), 0);
  std::function<int(int)> root = [&](int v) { return target[v] == v ? v : target[v] = root(target[v]); };
  for (size_t i = 0; i < order.size(); ++i)
    for (size_t j = i + 1; j < order.size() && points[order[j]].x() - points[order[i]].x() <= tolerance; ++j)
      if ((points[order[j]] - points[order[i]]).norm() <= tolerance) {
        const int a = root(order[i]), b = root(order[j]);
        target[std::max(a, b)] = std::min(a, b);  // the first copy stays
      }
  for (size_t v = 0; v < points.size(); ++v) target[v] = root(static_cast<int>(v));
  return target;
}

std::vector<int> seamPartners(const Mesh& disk, double tolerance) {
  return firstCopies(disk.points, vertexEdges(disk).onBoundary, tolerance);
}

std::vector<std::pair<int, int>> seamEdges(const Mesh& disk, double tolerance) {
  const std::vector<int> partner = seamPartners(disk, tolerance);
  std::vector<std::pair<int, int>> border;  // each border edge once, as its triangle has it
  std::map<Edge, int> stitched;             // how many border edges stitch into each
  for (const auto& [e, fs] : edgeFaces(disk)) {
    if (fs.size() != 1) continue;
    for (int k = 0; k < 3; ++k) {
      const int a = disk.triangles[fs[0]][k], b = disk.triangles[fs[0]][(k + 1) % 3];
      if (edge(a, b) == e) border.emplace_back(a, b);
    }
    ++stitched[edge(partner[e.first], partner[e.second])];
  }
  std::vector<std::pair<int, int>> seams;
  for (const auto& [a, b] : border)
    if (partner[a] != partner[b] && stitched[edge(partner[a], partner[b])] > 1) seams.emplace_back(a, b);
  return seams;
}

double seamTolerance(const Mesh& mesh) {
  const auto [lo, hi] = boundingBox(mesh);  // its corners hold the largest coordinate too
  const double largest = std::max(lo.cwiseAbs().maxCoeff(), hi.cwiseAbs().maxCoeff());
  constexpr double kRoundingSteps = 64;
  return std::max(kSeamTolerance * (hi - lo).norm(), kRoundingSteps * std::numeric_limits<double>::epsilon() * largest);
}

namespace {

// Flat, or so nearly that a sine of 1e-9 at `at` says so.
bool isFlat(const Vec3& at, const Vec3& a, const Vec3& b) {
  const Vec3 u = a - at, w = b - at;
  return u.cross(w).norm() <= 1e-9 * u.norm() * w.norm();
}

// A flat triangle on the border whose middle vertex has no other triangle (three border samples
// in a row on a straight border, that a map with a round border bent into an ear) goes, and its
// middle vertex with it; repeated, as the next sample may then be one.
bool dropFlatEars(std::vector<Triangle>& triangles, const std::vector<Vec3>& points) {
  bool any = false;
  for (bool dropped = true; dropped;) {
    dropped = false;
    std::vector<int> uses(points.size(), 0);
    for (const Triangle& t : triangles)
      for (int v : t) ++uses[v];
    for (size_t f = 0; f < triangles.size(); ++f) {
      const Triangle& t = triangles[f];
      for (int k = 0; k < 3; ++k) {
        if (uses[t[k]] == 1 && isFlat(points[t[k]], points[t[(k + 1) % 3]], points[t[(k + 2) % 3]])) {
          triangles.erase(triangles.begin() + f);
          dropped = any = true;
          break;
        }
      }
      if (dropped) break;
    }
  }
  return any;
}

// Flips each flat triangle's longest edge where a triangle that is not flat lies beyond it: its
// middle vertex then joins that triangle's far corner, and both new triangles have area (the
// middle vertex lies between the edge's ends). Repeated, as the flat triangles of a fan along a
// straight border each lie beyond the next (the border samples a round map bent into a pocket,
// without the polish that would flip them). Returns whether any was flipped.
bool flipFlatTriangles(std::vector<Triangle>& triangles, const std::vector<Vec3>& points) {
  const auto flat = [&](const Triangle& t) { return isFlat(points[t[0]], points[t[1]], points[t[2]]); };
  std::map<std::pair<int, int>, int> across;  // directed edge -> its triangle
  for (size_t f = 0; f < triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) across[{triangles[f][k], triangles[f][(k + 1) % 3]}] = static_cast<int>(f);
  bool any = false;
  // Each flip leaves one flat triangle fewer: as many rounds as there are flat triangles at most.
  for (bool flipped = true; flipped;) {
    flipped = false;
    for (size_t f = 0; f < triangles.size(); ++f) {
      const Triangle t = triangles[f];
      if (!flat(t)) continue;
      // Turned so that (c, a) is the longest edge and b the middle vertex.
      int k = 0;
      for (int j = 1; j < 3; ++j)
        if ((points[t[(j + 2) % 3]] - points[t[(j + 1) % 3]]).squaredNorm() >
            (points[t[(k + 2) % 3]] - points[t[(k + 1) % 3]]).squaredNorm())
          k = j;
      const int b = t[k], c = t[(k + 1) % 3], a = t[(k + 2) % 3];
      const auto beyond = across.find({a, c});
      if (beyond == across.end() || points[b] == points[a] || points[b] == points[c]) continue;
      const int g = beyond->second;
      const Triangle& u = triangles[g];
      const int d = u[0] != a && u[0] != c ? u[0] : u[1] != a && u[1] != c ? u[1] : u[2];
      if (flat(u) || across.count({b, d}) || across.count({d, b})) continue;
      for (const Triangle* old : {&triangles[f], &triangles[g]})
        for (int j = 0; j < 3; ++j) across.erase({(*old)[j], (*old)[(j + 1) % 3]});
      triangles[f] = {b, c, d};
      triangles[g] = {b, d, a};
      for (size_t h : {f, static_cast<size_t>(g)})
        for (int j = 0; j < 3; ++j) across[{triangles[h][j], triangles[h][(j + 1) % 3]}] = static_cast<int>(h);
      flipped = any = true;
    }
  }
  return any;
}

}  // namespace

void dropFlatTriangles(Mesh& mesh) {
  std::vector<Triangle> triangles = mesh.triangles;
  // The ears first: an ear flipped would keep its middle vertex, a sample no triangle needs.
  const bool dropped = dropFlatEars(triangles, mesh.points);
  if (flipFlatTriangles(triangles, mesh.points) || dropped) mesh = assemble(triangles, mesh.points);
}

Mesh stitchSeams(const Mesh& disk, double tolerance, std::vector<bool>* seamVertex, std::vector<int>* vertexOf) {
  const std::vector<int> target = seamPartners(disk, tolerance);
  // A triangle with two corners on the two copies of one sample (the ear at the tip of a slit)
  // collapses: it goes. So do two triangles that become one back to back (a slit tip with a
  // single inside neighbour): its tip vertex goes with them.
  std::map<Triangle, int> count;  // by sorted corners
  auto key = [](Triangle t) {
    std::sort(t.begin(), t.end());
    return t;
  };
  std::vector<Triangle> triangles;
  for (Triangle t : disk.triangles) {
    for (int& v : t) v = target[v];
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) continue;
    triangles.push_back(t);
    ++count[key(t)];
  }
  triangles.erase(std::remove_if(triangles.begin(), triangles.end(),
                                 [&](const Triangle& t) { return count[key(t)] > 1; }),
                  triangles.end());
  dropFlatEars(triangles, disk.points);
  std::vector<int> kept;
  Mesh stitched = assemble(triangles, disk.points, &kept);
  if (seamVertex) {
    std::vector<bool> merged(disk.vertexCount(), false);
    for (int v = 0; v < disk.vertexCount(); ++v)
      if (target[v] != v) merged[v] = merged[target[v]] = true;
    seamVertex->clear();
    for (int v : kept) seamVertex->push_back(merged[v]);
  }
  if (vertexOf) {
    std::vector<int> keptAs(disk.vertexCount(), -1);
    for (size_t i = 0; i < kept.size(); ++i) keptAs[kept[i]] = static_cast<int>(i);
    vertexOf->resize(disk.vertexCount());
    for (int v = 0; v < disk.vertexCount(); ++v) (*vertexOf)[v] = keptAs[target[v]];
  }
  return stitched;
}

namespace {

int countFlat(const Mesh& mesh) {
  int flat = 0;
  for (const Triangle& t : mesh.triangles) flat += isFlat(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]]);
  return flat;
}

}  // namespace

int removeFlatTriangles(Mesh& mesh) {
  if (countFlat(mesh) == 0) return 0;
  SurfaceMesh sm = toSurfaceMesh(mesh);
  CGAL::Polygon_mesh_processing::experimental::remove_almost_degenerate_faces(
      sm, std::cos(179.5 * M_PI / 180.0), 1e4, 1e-3 * boundingBoxDiagonal(mesh));
  sm.collect_garbage();
  mesh = fromSurfaceMesh(sm);
  return countFlat(mesh);
}

namespace {

// Per input vertex, the conformal map's area scale around it: the UV area of its faces over
// their 3D area, each as a share of the total. 1 everywhere for an area-preserving map.
std::vector<double> areaScale(const Mesh& mesh, const Mesh& disk, const std::vector<Vec2>& uv) {
  std::vector<double> area3(mesh.vertexCount(), 0), area2(mesh.vertexCount(), 0);
  double total3 = 0, total2 = 0;
  for (int f = 0; f < mesh.faceCount(); ++f) {
    const Triangle& t = mesh.triangles[f];
    const Triangle& d = disk.triangles[f];
    const double a3 = triangleArea(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]]);
    const double a2 = std::abs(triangleArea(uv[d[0]], uv[d[1]], uv[d[2]]));
    total3 += a3;
    total2 += a2;
    for (int v : t) area3[v] += a3, area2[v] += a2;
  }
  std::vector<double> scale(mesh.vertexCount(), 1);
  for (int v = 0; v < mesh.vertexCount(); ++v)
    if (area3[v] > 0) scale[v] = (area2[v] / total2) / (area3[v] / total3);
  return scale;
}

// The 99th percentile of the area scale over the 1st: one odd vertex (a sliver next to a cut
// node) does not decide where to cut.
double spreadOf(std::vector<double> scale) {
  std::sort(scale.begin(), scale.end());
  return scale[scale.size() * 99 / 100] / std::max(scale[scale.size() / 100], 1e-300);
}

// `mesh` opened along `cut`, with its seams marked; throws unless that is a disk.
CutResult openAlong(const Mesh& mesh, const std::map<Edge, std::vector<int>>& faces, const std::set<Edge>& cut,
                    const std::string& name) {
  CutResult result = cutAlong(mesh, faces, cut);
  markSeams(result, mesh, faces);
  if (!analyzeTopology(result.disk).isDisk())
    throw Error(name + ": cutting it open did not give a disk (it is " +
                analyzeTopology(result.disk).describe() + ")");
  return result;
}

}  // namespace

CutResult cutToDisk(const Mesh& mesh, const std::string& name, const CutOptions& options) {
  const Topology topology = analyzeTopology(mesh);
  if (topology.components != 1)
    throw Error(name + ": cannot cut to a disk: it has " + topology.describe() +
                " (remesh each on its own)");
  const auto faces = edgeFaces(mesh);
  const Neighbours neighbours = neighboursOf(mesh);
  // The topological cut: the border loops joined into one, then a loop around every handle.
  std::set<Edge> cut = joinBorderLoops(mesh, neighbours, topology.boundaryLoops);
  if (topology.genus > 0) {
    const std::vector<int> base = cut.empty() ? std::vector<int>{0} : verticesOf(cut);
    const std::set<Edge> loops = handleLoops(mesh, neighbours, faces, cut, base);
    cut.insert(loops.begin(), loops.end());
  }
  if (cut.empty()) cut = slitThroughExtremities(mesh, neighbours);  // closed, genus 0
  // The geometric cut (Gu, Gortler and Hoppe's geometry images): while the conformal map
  // shrinks some part of the surface far more than the rest (a protrusion, the far side of a
  // nearly closed shape), slit from the most shrunken vertex to the cut by a shortest path.
  CutResult best = openAlong(mesh, faces, cut, name);
  std::vector<double> scale = areaScale(mesh, best.disk, conformalMap(best.disk, name));
  best.summary.areaSpread = spreadOf(scale);
  const bool slit = !topology.isDisk() || best.summary.areaSpread > options.slitDisksAbove;
  if (slit && topology.isDisk() && options.slittingDisk) options.slittingDisk();
  const CutSummary whole = best.summary;
  // While a disk's spread is over keepDiskSlitsUnder (its slits would be left out), a slit that
  // does not lower it is set aside and the next tried from elsewhere, up to kSlitsSetAside in a
  // row: on CGAL's camel clipped in half (legs and a tail), the third and fourth slits tried
  // raised it from 3 10^4 to 2 10^5, the next three brought it to 3 10^3. Otherwise the first such
  // slit ends the search (on a closed surface, setting it aside made a map of CGAL's femur collapse).
  constexpr int kSlitsSetAside = 3;
  int setAside = 0;
  while (slit && best.summary.areaSpread > options.maxAreaSpread && best.summary.extremityCuts < options.maxExtremityCuts) {
    const std::vector<int> onCut = verticesOf(cut);
    for (int v : onCut) scale[v] = std::numeric_limits<double>::infinity();  // slit to elsewhere
    const int shrunken = static_cast<int>(std::min_element(scale.begin(), scale.end()) - scale.begin());
    const ShortestPaths toCut = dijkstra(mesh, neighbours, onCut);
    std::set<Edge> longer = cut;
    addPath(toCut, shrunken, longer);
    CutResult tried = openAlong(mesh, faces, longer, name);
    std::vector<double> triedScale = areaScale(mesh, tried.disk, conformalMap(tried.disk, name));
    tried.summary.areaSpread = spreadOf(triedScale);
    tried.summary.extremityCuts = best.summary.extremityCuts + 1;
    // A slit that does not lower the spread by a tenth stays out: each costs a seam.
    if (tried.summary.areaSpread > 0.9 * best.summary.areaSpread) {
      const bool wouldBeLeftOut = topology.isDisk() && best.summary.areaSpread > options.keepDiskSlitsUnder;
      if (!wouldBeLeftOut || ++setAside > kSlitsSetAside) break;
      for (int v = shrunken; v >= 0; v = toCut.previous[v])  // its path and the vertices beside it
        for (int w : neighbours[v]) scale[v] = scale[w] = std::numeric_limits<double>::infinity();
      continue;
    }
    setAside = 0;
    cut = std::move(longer);
    best = std::move(tried);
    scale = std::move(triedScale);
  }
  // A disk's slits must bring its spread under keepDiskSlitsUnder, or they are left out: the
  // protrusions of a terrain (CGAL's three peaks as it comes: 2 10^4 after 4 slits) are better
  // whole; but not where the whole disk's map would collapse (keepDiskSlitsOver).
  if (topology.isDisk() && best.summary.areaSpread > options.keepDiskSlitsUnder &&
      whole.areaSpread <= options.keepDiskSlitsOver) {
    best.seam.clear();
    best.summary = whole;
  }
  best.summary.seamEdges = static_cast<int>(best.seam.size());
  best.topology = topology;
  if (best.seam.empty()) {  // a disk that needed no slit: as it came, vertex order and all
    best.disk = mesh;
    best.original.resize(mesh.vertexCount());
    std::iota(best.original.begin(), best.original.end(), 0);
    best.onSeam.clear();
    best.seamNode.clear();
  }
  return best;
}

}  // namespace lloydscope
