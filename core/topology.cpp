// Connected components, boundary loops, Euler characteristic and genus of a manifold mesh.
//
// Everything is derived from the triangles' directed edges: an edge a -> b whose reverse b -> a
// belongs to no triangle is on the boundary, and on a manifold, consistently oriented mesh the
// boundary edges chain into loops (exactly one boundary edge leaves each boundary vertex).

#include "topology.h"

#include <algorithm>
#include <numeric>
#include <utility>

namespace lloydscope {
namespace {

using Edge = std::pair<int, int>;

// Union-find over vertex indices.
class DisjointSets {
 public:
  explicit DisjointSets(int n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }

  int find(int x) {
    while (parent_[x] != x) {
      parent_[x] = parent_[parent_[x]];  // path halving keeps the trees flat
      x = parent_[x];
    }
    return x;
  }

  void unite(int a, int b) { parent_[find(a)] = find(b); }

 private:
  std::vector<int> parent_;
};

// All directed edges a -> b of the triangles, sorted.
std::vector<Edge> sortedHalfEdges(const Mesh& mesh) {
  std::vector<Edge> halfEdges;
  halfEdges.reserve(3 * mesh.triangles.size());
  for (const Triangle& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) halfEdges.emplace_back(t[k], t[(k + 1) % 3]);
  }
  std::sort(halfEdges.begin(), halfEdges.end());
  return halfEdges;
}

// Follows boundary half-edges from vertex to vertex. Each loop lists its vertices in the
// direction of the faces' orientation and starts at its smallest vertex.
std::vector<std::vector<int>> traceBoundaryLoops(const std::vector<Edge>& halfEdges) {
  std::vector<Edge> boundary;  // sorted, since halfEdges is
  for (const Edge& h : halfEdges) {
    if (!std::binary_search(halfEdges.begin(), halfEdges.end(), Edge(h.second, h.first))) boundary.push_back(h);
  }
  std::vector<bool> used(boundary.size(), false);
  const auto unusedEdgeFrom = [&](int vertex) {
    size_t e = std::lower_bound(boundary.begin(), boundary.end(), Edge(vertex, -1)) - boundary.begin();
    while (e < boundary.size() && boundary[e].first == vertex && used[e]) ++e;
    return (e < boundary.size() && boundary[e].first == vertex) ? e : boundary.size();
  };

  std::vector<std::vector<int>> loops;
  for (size_t first = 0; first < boundary.size(); ++first) {
    if (used[first]) continue;
    std::vector<int> loop;
    // Stops back at the start, or (only on a non-manifold input) where the chain breaks off.
    for (size_t e = first; e < boundary.size(); e = unusedEdgeFrom(boundary[e].second)) {
      used[e] = true;
      loop.push_back(boundary[e].first);
      if (boundary[e].second == loop.front()) break;
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

// Per vertex, its connected component (vertices joined through the faces, numbered in the
// order of their first vertex), or -1 for a vertex no face uses; `count` receives how many.
std::vector<int> vertexComponents(const Mesh& mesh, int& count) {
  const int n = mesh.vertexCount();
  DisjointSets sets(n);
  std::vector<bool> used(n, false);
  for (const Triangle& t : mesh.triangles) {
    sets.unite(t[0], t[1]);
    sets.unite(t[1], t[2]);
    for (int v : t) used[v] = true;
  }
  std::vector<int> componentOf(n, -1), rootComponent(n, -1);
  count = 0;
  for (int v = 0; v < n; ++v) {
    if (!used[v]) continue;
    int& c = rootComponent[sets.find(v)];
    if (c < 0) c = count++;
    componentOf[v] = c;
  }
  return componentOf;
}

std::string plural(long long n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

}  // namespace

std::string Topology::describe() const {
  if (components == 0) return "an empty mesh";
  if (components > 1) return std::to_string(components) + " connected components";
  const int loops = static_cast<int>(boundaryLoops.size());
  if (loops == 0) return "a closed surface of genus " + std::to_string(genus);
  if (loops == 1 && genus == 0) return "a topological disk";
  return "a genus " + std::to_string(genus) + " surface with " + plural(loops, "boundary loop", "boundary loops");
}

Topology analyzeTopology(const Mesh& mesh) {
  Topology topology;
  const int n = mesh.vertexCount();

  // Components: vertices joined through the faces; vertices used by no face do not count.
  const std::vector<int> componentOf = vertexComponents(mesh, topology.components);

  const std::vector<Edge> halfEdges = sortedHalfEdges(mesh);
  topology.boundaryLoops = traceBoundaryLoops(halfEdges);

  // V - E + F and the number of boundary loops, per component.
  std::vector<long long> chi(topology.components, 0), loops(topology.components, 0);
  for (int v = 0; v < n; ++v) {
    if (componentOf[v] >= 0) ++chi[componentOf[v]];
  }
  std::vector<Edge> edges;  // undirected, each once
  edges.reserve(halfEdges.size());
  for (const Edge& h : halfEdges) edges.emplace_back(std::min(h.first, h.second), std::max(h.first, h.second));
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  for (const Edge& e : edges) --chi[componentOf[e.first]];
  for (const Triangle& t : mesh.triangles) ++chi[componentOf[t[0]]];
  for (const std::vector<int>& loop : topology.boundaryLoops) ++loops[componentOf[loop.front()]];

  // chi = 2 - 2g - b for each component; with several components, genus is their sum.
  for (int c = 0; c < topology.components; ++c) {
    topology.eulerCharacteristic += static_cast<int>(chi[c]);
    topology.genus += static_cast<int>((2 - chi[c] - loops[c]) / 2);
  }
  return topology;
}

std::vector<Mesh> splitComponents(const Mesh& mesh) {
  int count = 0;
  const std::vector<int> componentOf = vertexComponents(mesh, count);
  std::vector<Mesh> parts(count);
  std::vector<int> renumbered(mesh.vertexCount(), -1);
  for (int v = 0; v < mesh.vertexCount(); ++v) {
    if (componentOf[v] < 0) continue;
    Mesh& part = parts[componentOf[v]];
    renumbered[v] = part.vertexCount();
    part.points.push_back(mesh.points[v]);
  }
  for (const Triangle& t : mesh.triangles)
    parts[componentOf[t[0]]].triangles.push_back({renumbered[t[0]], renumbered[t[1]], renumbered[t[2]]});
  return parts;
}

void requireDisk(const Mesh& mesh, const std::string& name) {
  const Topology topology = analyzeTopology(mesh);
  if (topology.isDisk()) return;
  // describe() gives "a closed surface of genus 1", "2 connected components", "an empty mesh" ...
  throw Error(name + ": not a topological disk: " + (topology.components > 1 ? "it has " : "it is ") +
              topology.describe());
}

}  // namespace lloydscope
