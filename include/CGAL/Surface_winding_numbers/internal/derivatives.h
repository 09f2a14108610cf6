// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT

#ifndef CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_DERIVATIVES_H
#define CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_DERIVATIVES_H

#include <CGAL/Surface_winding_numbers/internal/mesh_tables.h>

#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace internal {

// Darboux derivative omega = D f (paper Eq. 5) of a corner function: on each edge, the difference
// along the reference direction inside each incident face, averaged over the faces. Zero on edges
// touching an excluded vertex (interior endpoints, where f is undefined).
inline std::vector<double> darboux_derivative(const Mesh_tables& m, const std::vector<double>& f,
                                              const std::vector<char>& excluded)
{
  std::vector<double> omega(m.ne, 0.);
  for(std::size_t e = 0; e < m.ne; ++e)
  {
    if(excluded[m.ev[2 * e]] || excluded[m.ev[2 * e + 1]]) continue;
    const std::size_t b = m.edge_side_begin[e], n = m.edge_side_begin[e + 1] - b;
    if(n == 0) continue;
    double sum = 0;
    for(std::size_t i = b; i < b + n; ++i)
    {
      const std::size_t s = m.edge_sides[i];
      sum += m.fs[s] * (f[Mesh_tables::next_in_face(s)] - f[s]);
    }
    omega[e] = sum / double(n);
  }
  return omega;
}

// Jump of a corner function across arc a, left minus right, measured at endpoint k (0 or 1) of
// the arc's edge (paper Sec. 2.4.1, J).
inline double corner_jump_at(const Mesh_tables& m, const std::vector<double>& f, std::size_t a, int k)
{
  const Arc& arc = m.arcs[a];
  const std::size_t v = m.ev[2 * arc.edge + k];
  return f[m.corner_at(arc.left_side / 3, v)] - f[m.corner_at(arc.right_side / 3, v)];
}

// Jump derivative J f (paper Sec. 2.4.1, Sec. 3.6): per edge, the jump across the edge averaged
// over its two endpoints; zero on border edges and where no jump is allowed (jump_forbidden).
inline std::vector<double> jump_derivative(const Mesh_tables& m, const std::vector<double>& f)
{
  std::vector<double> g(m.ne, 0.);
  for(std::size_t a = 0; a < m.arcs.size(); ++a)
    if(!m.jump_forbidden(m.arcs[a].edge)) g[m.arcs[a].edge] = 0.5 * (corner_jump_at(m, f, a, 0) + corner_jump_at(m, f, a, 1));
  return g;
}

} // namespace internal
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif
