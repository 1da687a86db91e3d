#include "cut.h"

#include "remesh.h"
#include "topology.h"

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

// The edges a breadth-first walk over the faces from face 0 does not cross, pruned of
// dangling branches (border edges are never pruned).
std::set<Edge> cutGraph(const Mesh& mesh, const std::map<Edge, std::vector<int>>& faces) {
  std::vector<bool> reached(mesh.faceCount(), false);
  std::set<Edge> crossed;
  std::queue<int> queue;
  queue.push(0);
  reached[0] = true;
  while (!queue.empty()) {
    const int f = queue.front();
    queue.pop();
    for (int k = 0; k < 3; ++k) {
      const Edge e = edge(mesh.triangles[f][k], mesh.triangles[f][(k + 1) % 3]);
      for (int g : faces.at(e))
        if (!reached[g]) {
          reached[g] = true;
          crossed.insert(e);
          queue.push(g);
        }
    }
  }
  std::set<Edge> graph;
  std::map<int, int> degree;
  for (const auto& [e, fs] : faces)
    if (!crossed.count(e)) {
      graph.insert(e);
      ++degree[e.first];
      ++degree[e.second];
    }
  // Prune: an inside edge with an end of degree 1 leads nowhere.
  bool pruned = true;
  while (pruned) {
    pruned = false;
    for (auto it = graph.begin(); it != graph.end();) {
      const bool border = faces.at(*it).size() == 1;
      if (!border && (degree[it->first] == 1 || degree[it->second] == 1)) {
        --degree[it->first];
        --degree[it->second];
        it = graph.erase(it);
        pruned = true;
      } else {
        ++it;
      }
    }
  }
  return graph;
}

// Shortest paths (by edge length) from `sources`: distance and predecessor of every vertex.
void dijkstra(const Mesh& mesh, const std::vector<std::vector<int>>& neighbours,
              const std::vector<int>& sources, std::vector<double>& distance,
              std::vector<int>& previous) {
  distance.assign(mesh.vertexCount(), std::numeric_limits<double>::infinity());
  previous.assign(mesh.vertexCount(), -1);
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  for (int s : sources) {
    distance[s] = 0;
    queue.push({0.0, s});
  }
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > distance[v]) continue;
    for (int w : neighbours[v]) {
      const double through = d + (mesh.points[w] - mesh.points[v]).norm();
      if (through < distance[w]) {
        distance[w] = through;
        previous[w] = v;
        queue.push({through, w});
      }
    }
  }
}

// A tree of shortest paths joining three extremities of a closed genus-0 surface.
std::set<Edge> slit(const Mesh& mesh) {
  std::vector<std::vector<int>> neighbours(mesh.vertexCount());
  for (const Triangle& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) neighbours[t[k]].push_back(t[(k + 1) % 3]);
  std::vector<double> distance;
  std::vector<int> previous;
  auto farthest = [&] {
    return static_cast<int>(std::max_element(distance.begin(), distance.end()) - distance.begin());
  };
  dijkstra(mesh, neighbours, {0}, distance, previous);
  std::vector<int> tree = {farthest()};  // the vertices of the slit so far
  std::set<Edge> cut;
  for (int extremity = 1; extremity < 3; ++extremity) {
    dijkstra(mesh, neighbours, tree, distance, previous);
    for (int v = farthest(); previous[v] >= 0; v = previous[v]) {
      cut.insert(edge(v, previous[v]));
      tree.push_back(v);
    }
  }
  return cut;
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

std::vector<int> seamPartners(const Mesh& disk, double tolerance) {
  const std::vector<bool> border = vertexEdges(disk).onBoundary;
  std::vector<int> order;
  for (int v = 0; v < disk.vertexCount(); ++v)
    if (border[v]) order.push_back(v);
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return disk.points[a].x() < disk.points[b].x(); });
  std::vector<int> target(disk.vertexCount());
  std::iota(target.begin(), target.end(), 0);
  std::function<int(int)> root = [&](int v) { return target[v] == v ? v : target[v] = root(target[v]); };
  for (size_t i = 0; i < order.size(); ++i)
    for (size_t j = i + 1;
         j < order.size() && disk.points[order[j]].x() - disk.points[order[i]].x() <= tolerance; ++j)
      if ((disk.points[order[j]] - disk.points[order[i]]).norm() <= tolerance) {
        const int a = root(order[i]), b = root(order[j]);
        target[std::max(a, b)] = std::min(a, b);  // the first copy stays
      }
  for (int v = 0; v < disk.vertexCount(); ++v) target[v] = root(v);
  return target;
}

Mesh stitchSeams(const Mesh& disk, double tolerance) {
  const std::vector<int> target = seamPartners(disk, tolerance);
  auto root = [&](int v) { return target[v]; };
  // A triangle with two corners on the two copies of one sample (the ear at the tip of a slit)
  // collapses: it goes.
  std::vector<Triangle> triangles;
  for (Triangle t : disk.triangles) {
    for (int& v : t) v = root(v);
    if (t[0] != t[1] && t[1] != t[2] && t[0] != t[2]) triangles.push_back(t);
  }
  return assemble(triangles, disk.points);
}

CutResult cutToDisk(const Mesh& mesh, const std::string& name) {
  const Topology topology = analyzeTopology(mesh);
  if (topology.components != 1)
    throw Error(name + ": cannot cut to a disk: it has " + topology.describe() +
                " (remesh each on its own)");
  if (topology.isDisk()) {
    CutResult unchanged;
    unchanged.disk = mesh;
    unchanged.original.resize(mesh.vertexCount());
    std::iota(unchanged.original.begin(), unchanged.original.end(), 0);
    return unchanged;
  }
  const auto faces = edgeFaces(mesh);
  const bool closedSphere = topology.boundaryLoops.empty() && topology.genus == 0;
  CutResult result = cutAlong(mesh, faces, closedSphere ? slit(mesh) : cutGraph(mesh, faces));
  markSeams(result, mesh, faces);
  if (!analyzeTopology(result.disk).isDisk())
    throw Error(name + ": cutting it open did not give a disk (it is " +
                analyzeTopology(result.disk).describe() + ")");
  return result;
}

}  // namespace lloydscope
