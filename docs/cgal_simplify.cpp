// An outside harness's way to bring a model to N vertices, for docs/bench.md ("The face and the
// camel head, simplified by CGAL's own edge collapse"): CGAL's edge_collapse with its border
// free to move, unlike `lloydscope simplify`, which keeps the border in place. Not part of the
// build:
//   g++ -O2 -std=c++17 -I/usr/include/eigen3 docs/cgal_simplify.cpp -o cgal_simplify -lgmp -lmpfr
//   ./cgal_simplify MODEL OUT.off N gh|lt
// gh: Garland-Heckbert plane quadrics; lt: Lindstrom-Turk (edge_collapse's default).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/GarlandHeckbert_plane_policies.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <string>

namespace SMS = CGAL::Surface_mesh_simplification;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;

int main(int argc, char** argv) {
  if (argc != 5) {
    std::cerr << "usage: cgal_simplify MODEL OUT.off N gh|lt\n";
    return 1;
  }
  SurfaceMesh model;
  if (!CGAL::Polygon_mesh_processing::IO::read_polygon_mesh(argv[1], model)) {
    std::cerr << argv[1] << ": cannot read\n";
    return 1;
  }
  CGAL::Polygon_mesh_processing::triangulate_faces(model);
  const int vertices = std::atoi(argv[3]);
  const std::string policy = argv[4];
  // The stop counts edges, about three a vertex: lowered until the vertices are at most N.
  for (int edges = 3 * vertices; edges > 0; edges -= std::max(1, edges / 200)) {
    SurfaceMesh simplified = model;
    SMS::Count_stop_predicate<SurfaceMesh> stop(edges);
    if (policy == "gh") {
      SMS::GarlandHeckbert_plane_policies<SurfaceMesh, Kernel> quadrics(simplified);
      SMS::edge_collapse(simplified, stop,
                         CGAL::parameters::get_cost(quadrics.get_cost()).get_placement(quadrics.get_placement()));
    } else {
      SMS::edge_collapse(simplified, stop);
    }
    simplified.collect_garbage();
    if (static_cast<int>(simplified.number_of_vertices()) <= vertices) {
      CGAL::IO::write_OFF(argv[2], simplified);
      std::cout << simplified.number_of_vertices() << " vertices\n";
      return 0;
    }
  }
  return 1;
}
