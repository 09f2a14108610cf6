// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT

#ifndef CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_COTAN_WEIGHTS_H
#define CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_COTAN_WEIGHTS_H

#include <CGAL/Surface_winding_numbers/internal/mesh_tables.h>
#include <CGAL/Surface_winding_numbers/internal/unit_scale.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace internal {

// Lower and upper clamp of the half-cotangent weights (dimensionless, so scale invariant).
constexpr double min_cotan_weight = 1e-3;
constexpr double max_cotan_weight = 1e3;

// Rejects what no weight can be computed for: non-finite coordinates and zero-area faces (tested on
// the points brought to a unit box by the table builders, so independently of the unit). Reports the
// first offending element in the input's numbering.
inline void check_geometry(const Mesh_tables& m)
{
  std::size_t bad = npos;
  for(std::size_t v = 0; v < m.nv; ++v)
    for(int k = 0; k < 3; ++k)
      if(!std::isfinite(m.points[3 * v + k])) bad = std::min(bad, m.input_vertex_index(v));
  if(bad != npos) throw Invalid_input("vertex " + std::to_string(bad) + " has a non-finite coordinate");
  for(std::size_t f = 0; f < m.nf; ++f)
  {
    if(zero_area_triangle(m.point(m.fv[3 * f]), m.point(m.fv[3 * f + 1]), m.point(m.fv[3 * f + 2])))
      bad = std::min(bad, m.input_face_index(f));
  }
  if(bad != npos) throw Invalid_input("face " + std::to_string(bad) + " has zero area (degenerate triangle)");
}

// Cotan weights per side (paper Eq. 6): the weight of side ij of face ijk is cot(angle at k) / 2.
// Deliberate choice, shared with the authors' code: every weight is clamped to
// [min_cotan_weight, max_cotan_weight], so that the jump Laplacian is an M-matrix (discrete maximum
// principle: no overshoot of w near obtuse triangles) and the Hodge star on edges is positive.
// Returns the number of clamped weights.
inline std::size_t cotan_weights(const Mesh_tables& m, std::vector<double>& weight)
{
  weight.assign(3 * m.nf, 0.);
  std::size_t clamped = 0;
  for(std::size_t s = 0; s < 3 * m.nf; ++s)
  {
    const double* p = m.point(m.fv[s]);
    const double* q = m.point(m.fv[Mesh_tables::next_in_face(s)]);
    const double* r = m.point(m.fv[Mesh_tables::prev_in_face(s)]);   // opposite corner
    const double a[3] = {p[0] - r[0], p[1] - r[1], p[2] - r[2]};
    const double b[3] = {q[0] - r[0], q[1] - r[1], q[2] - r[2]};
    const double dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    const double n[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    double w = 0.5 * dot / std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if(!std::isfinite(w)) { w = 1.; ++clamped; }
    else if(w < min_cotan_weight) { w = min_cotan_weight; ++clamped; }
    else if(w > max_cotan_weight) { w = max_cotan_weight; ++clamped; }
    weight[s] = w;
  }
  return clamped;
}

// Diagonal Hodge star on edges: the sum of the weights of the edge's sides (always positive).
inline std::vector<double> edge_hodge_star(const Mesh_tables& m, const std::vector<double>& side_weight)
{
  std::vector<double> star(m.ne, 0.);
  for(std::size_t s = 0; s < 3 * m.nf; ++s) star[m.fe[s]] += side_weight[s];
  for(double& x : star) if(!(x > 0)) x = min_cotan_weight;   // edges without faces
  return star;
}

} // namespace internal
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif
