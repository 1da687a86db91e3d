// Global 2D parameterization of a disk-topology mesh (CGAL Surface_mesh_parameterization).
#pragma once

#include "mesh.h"

#include <string>
#include <vector>

namespace lloydscope {

enum class ParamMethod {
  Auto,  // LSCM; where it folds, ParamOptions::fallback, then mean value, then Tutte (on `border`)
  Authalic, Conformal, MeanValue, Tutte, Lscm,
  Given  // ParamOptions::fallback, taken as it is (what Auto reports when it used it)
};
enum class Border { Square, Circle, Rectangle };  // ignored by LSCM, whose border is free

// LSCM's map, or one given: conformal, its border free. The others have a fixed border; the
// automatic choice falls back to one (mean value, Tutte) where no conformal map held.
inline bool isFreeBorder(ParamMethod m) { return m == ParamMethod::Lscm || m == ParamMethod::Given; }

struct ParamOptions {
  // Free-border LSCM keeps the border's own shape: no corner of the input is squeezed onto a
  // circle or spread along a square's side, which measured best. It can fold, and then the
  // mean-value map, one-to-one on any convex border, takes over: on a rectangle where the
  // border has four corners (rectangleCorners), else on `border`.
  ParamMethod method = ParamMethod::Auto;
  Border border = Border::Circle;  // for the fixed-border methods
  // Per vertex, a map that Auto tries after LSCM and before mean value, if not empty: for a
  // resampled surface, its points in the input's own map (one-to-one by construction, and as
  // little distorted as that map), far better than a circle where LSCM folds.
  std::vector<Vec2> fallback;
};

struct Distortion {
  // Per triangle, r = (3D area share) / (UV area share); 1 everywhere for an area-preserving map.
  double minAreaRatio = 1, maxAreaRatio = 1;
  double meanLogAreaRatio = 0;  // area-weighted mean of |ln r|
  double meanAngleErrorDeg = 0;  // mean |3D corner angle - UV corner angle|, degrees
};

struct Parameterization {
  ParamMethod method = ParamMethod::Lscm;  // the one used (Auto resolved)
  Border border = Border::Circle;          // and its border, where it is fixed
  std::vector<Vec2> uv;           // per vertex, scaled uniformly to fit the unit square
  std::vector<int> boundaryLoop;  // the border's vertices, counter-clockwise in UV
  std::vector<bool> onBoundary;   // per vertex
  Distortion distortion;
};

// The mesh must be a validated topological disk. Throws Error("<name>: ...") when CGAL fails
// or when the result is not one-to-one (some UV triangles flipped or collapsed).
Parameterization parameterize(const Mesh& mesh, const ParamOptions& options,
                              const std::string& name);

Distortion measureDistortion(const Mesh& mesh, const std::vector<Vec2>& uv);

// LSCM's map of a disk as it comes out of the solver, folds and all (neither repaired nor
// refused): what cutToDisk measures a cut's distortion on. CGAL's equations and pins, solved
// here 2.5-3 times as fast. Throws Error when the solve fails.
std::vector<Vec2> conformalMap(const Mesh& disk, const std::string& name);

const char* toString(ParamMethod method);
const char* toString(Border border);
// The border of the map `used` made: "free border" (LSCM), "border of the input's map" (Given),
// else "circle border" or "square border" as `border` says. (The inspector called LSCM's map
// "circle border", its setting for the other methods, beside a map that is no circle.)
std::string borderPhrase(ParamMethod used, Border border);
ParamMethod parseParamMethod(const std::string& text);  // throws Error on unknown names
Border parseBorder(const std::string& text);

}  // namespace lloydscope
