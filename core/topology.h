// Connected components, boundary loops, Euler characteristic and genus of a manifold mesh.
#pragma once

#include "mesh.h"

#include <string>
#include <vector>

namespace lloydscope {

struct Topology {
  int components = 0;
  std::vector<std::vector<int>> boundaryLoops;  // vertex indices, in the faces' orientation
  int eulerCharacteristic = 0;                  // V - E + F
  int genus = 0;  // of the surface with its holes filled, for a single component

  bool isDisk() const { return components == 1 && boundaryLoops.size() == 1 && genus == 0; }
  // "a topological disk", "closed, genus 2", "genus 0 with 3 boundary loops", "4 components" ...
  std::string describe() const;
};

// The mesh must have passed validateMesh() (manifold).
Topology analyzeTopology(const Mesh& mesh);

// Each connected component as a mesh of its own, in the order of their first vertex; vertices
// keep their order, and those no face uses are left out.
std::vector<Mesh> splitComponents(const Mesh& mesh);

// Throws Error("<name>: not a topological disk (<describe()>); ...") unless the mesh is a disk.
void requireDisk(const Mesh& mesh, const std::string& name);

}  // namespace lloydscope
