// The density that weights Lloyd relaxation in the parameter domain: per triangle, a value at
// each of its corners, interpolated linearly inside it. The corners of neighbouring triangles
// agree in the densities made here (a value per vertex: areaDensity), but need not.
#pragma once

#include "mesh.h"

#include <string>
#include <vector>

namespace lloydscope {

enum class DensityKind {
  Uniform,    // 1 everywhere: equal cells in the parameter domain (the reference's choice)
  Area,       // compensates the map's area distortion: equal cells on the surface
  Curvature,  // more sites where the surface is curved
};

struct DensityOptions {
  DensityKind kind = DensityKind::Area;
  // Curvature: psi(v) = 1 / (alpha |K(v)| + beta H(v)^2) is the reference's local size;
  // the density is 1 / psi, plus `floor` times its mean so that flat regions keep sites.
  double alpha = 1.0, beta = 1.0, floor = 0.1;
  bool curvatureTimesArea = true;  // multiply the curvature density by the area term
};

// Per triangle, the density at corners 0, 1, 2.
using Density = std::vector<std::array<double, 3>>;

// A density that is continuous across triangles: `values` per vertex at every corner.
Density vertexDensity(const std::vector<Triangle>& triangles, const std::vector<double>& values);

// Scaled to an area-weighted mean of 1 over the parameter domain.
Density computeDensity(const Mesh& mesh, const std::vector<Vec2>& uv,
                       const DensityOptions& options);

// The area term alone: at each vertex, the square of its triangles' 3D area / UV area ratios
// averaged (weighted by their 3D areas), interpolated across each triangle. Why squared: a 2D
// CVT with density rho gives cells of area proportional to rho^(-1/2) (Gersho), so rho =
// ratio^2 makes every cell cover the same area of the surface.
Density areaDensity(const Mesh& mesh, const std::vector<Vec2>& uv);

// What `density` asks of the surface itself: density / areaDensity (1 everywhere for the
// area density). The 3D polish weights its centres with it.
Density surfaceDensity(const Mesh& mesh, const std::vector<Vec2>& uv, const Density& density);

// The density inside triangle t at barycentric `weights`.
double densityAt(const Density& density, int t, const Eigen::Vector3d& weights);

// Discrete curvatures per vertex: Gaussian K by the angle defect over a third of the incident
// area, mean H from the cotangent Laplacian. Boundary vertices take the mean of their interior
// neighbours (their angle defect is not a curvature).
struct Curvature {
  std::vector<double> gaussian, mean;
};
Curvature computeCurvature(const Mesh& mesh);

const char* toString(DensityKind kind);
DensityKind parseDensityKind(const std::string& text);  // throws Error on unknown names

}  // namespace lloydscope
