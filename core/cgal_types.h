// CGAL types shared by the core's implementation files (never included by public headers).
#pragma once

#include "mesh.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

namespace lloydscope {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point2 = Kernel::Point_2;
using Point3 = Kernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point3>;

// Vertex i of `mesh` is vertex i of the result, face j is face j.
SurfaceMesh toSurfaceMesh(const Mesh& mesh);
// Back, dropping removed elements (after CGAL collapses or refinements).
Mesh fromSurfaceMesh(const SurfaceMesh& sm);

}  // namespace lloydscope
