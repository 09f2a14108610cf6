// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT

#ifndef CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_WINDING_NUMBER_H
#define CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_WINDING_NUMBER_H

#include <CGAL/Surface_winding_numbers/internal/derivatives.h>
#include <CGAL/Surface_winding_numbers/internal/jump_laplace.h>
#include <CGAL/Surface_winding_numbers/internal/mesh_tables.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace internal {

// Rounds half away from zero, as the paper's round().
inline long round_half_away(double x) { return std::lround(x); }

// Jumps for the second jump Laplace solve (paper Sec. 3.5): Lambda = Gamma - J v. As in the
// authors' code, at every vertex touching the curve the jump of v is subtracted on all incident
// arcs (not only curve arcs), measured at that vertex, so that the jumps around the vertex sum to
// zero exactly (the telescoping sum of Sec. 3.6); other vertices get no jump.
inline std::vector<double> second_solve_jumps(const Mesh_tables& m, const std::vector<double>& chain,
                                              const std::vector<double>& v)
{
  std::vector<char> curve_vertex(m.nv, 0);
  for(std::size_t e = 0; e < m.ne; ++e)
    if(std::abs(chain[e]) > chain_tolerance) curve_vertex[m.ev[2 * e]] = curve_vertex[m.ev[2 * e + 1]] = 1;
  std::vector<double> jump(2 * m.arcs.size(), 0.);
  for(std::size_t a = 0; a < m.arcs.size(); ++a)
    for(int k = 0; k < 2; ++k)
      if(curve_vertex[m.ev[2 * m.arcs[a].edge + k]])
        jump[2 * a + k] = chain[m.arcs[a].edge] - corner_jump_at(m, v, a, k);
  return jump;
}

// Shift tau (paper Sec. 3.5.1), one per connected component. On each curve edge, w+ is the mean of
// w on the edge's higher side. Deliberate deviation: the paper averages round(w+) - w+, which
// cancels out when the w+ straddle a half-integer, and the authors' code averages |round(w+) - w+|,
// which always shifts upwards; we take the circular mean of w+ modulo 1 (weighted by edge length),
// which agrees with the paper's mean when the w+ are close to integers and has no wrap-around.
inline std::vector<double> shift_tau(const Mesh_tables& m, const std::vector<double>& chain, const std::vector<double>& w)
{
  const double two_pi = 6.283185307179586;
  std::vector<double> sx(m.n_components, 0.), sy(m.n_components, 0.);
  for(const Arc& arc : m.arcs)
  {
    const double G = chain[arc.edge];
    if(std::abs(G) <= chain_tolerance) continue;
    const std::size_t side = G > 0 ? arc.left_side : arc.right_side;
    const double wp = 0.5 * (w[side] + w[Mesh_tables::next_in_face(side)]);
    if(!std::isfinite(wp)) continue;
    const double len = m.edge_length(arc.edge);
    const std::size_t c = m.face_component[side / 3];
    sx[c] += len * std::cos(two_pi * wp);
    sy[c] += len * std::sin(two_pi * wp);
  }
  std::vector<double> tau(m.n_components, 0.);
  for(std::size_t c = 0; c < m.n_components; ++c)
    if(sx[c] != 0 || sy[c] != 0) tau[c] = -std::atan2(sy[c], sx[c]) / two_pi;
  return tau;
}

// One label per input polygon: the rounded area-weighted mean over its triangles of the mean of their
// defined corner values plus tau (triangles without a defined corner do not count).
inline void polygon_labels(const Mesh_tables& m, const std::vector<double>& w, const std::vector<double>& tau,
                           std::vector<int>& W, const std::vector<char>& known)
{
  std::size_t np = 0;
  for(std::size_t q : m.face_polygon) np = (std::max)(np, q + 1);
  std::vector<double> sum(np, 0.), area(np, 0.);
  for(std::size_t f = 0; f < m.nf; ++f)
  {
    if(!known[f]) continue;
    double s = 0;
    int n = 0;
    for(int k = 0; k < 3; ++k)
      if(std::isfinite(w[3 * f + k])) { s += w[3 * f + k]; ++n; }
    const double a = m.face_area(f);
    sum[m.face_polygon[f]] += a * (s / n + tau[m.face_component[f]]);
    area[m.face_polygon[f]] += a;
  }
  for(std::size_t f = 0; f < m.nf; ++f)
    if(known[f] && area[m.face_polygon[f]] > 0)
      W[f] = int(round_half_away(sum[m.face_polygon[f]] / area[m.face_polygon[f]]));
}

// Integer labels W (paper Sec. 3.5.1): the rounded mean of the defined corner values plus tau. A face
// whose three corners are all interior endpoints takes the label of a neighbour. The triangles of an
// input polygon (m.face_polygon) share one label: the rounded area-weighted mean of their means.
inline std::vector<int> round_labels(const Mesh_tables& m, const std::vector<double>& w, const std::vector<double>& tau)
{
  std::vector<int> W(m.nf, 0);
  std::vector<char> known(m.nf, 0);
  std::size_t unknown = 0;
  for(std::size_t f = 0; f < m.nf; ++f)
  {
    double sum = 0;
    int n = 0;
    for(int k = 0; k < 3; ++k)
      if(std::isfinite(w[3 * f + k])) { sum += w[3 * f + k]; ++n; }
    if(n > 0) { W[f] = int(round_half_away(sum / n + tau[m.face_component[f]])); known[f] = 1; }
    else ++unknown;
  }
  if(!m.face_polygon.empty())
    polygon_labels(m, w, tau, W, known);
  while(unknown > 0)
  {
    std::size_t fixed = 0;
    for(const Arc& arc : m.arcs)
    {
      const std::size_t L = arc.left_side / 3, R = arc.right_side / 3;
      if(known[L] != known[R])
      {
        const std::size_t from = known[L] ? L : R, to = known[L] ? R : L;
        W[to] = W[from];
        known[to] = 1;
        ++fixed;
      }
    }
    if(fixed == 0) break;   // isolated faces stay at 0
    unknown -= fixed;
  }
  return W;
}

// Label normalization: in every component the label covering the largest area becomes 0 (ties:
// the label of smallest magnitude, then the smallest); in the component of the face `anchor` (npos:
// none), the label of that face becomes 0 instead. Returns the per-component offset subtracted.
inline std::vector<int> normalize_labels(const Mesh_tables& m, std::vector<int>& W, std::size_t anchor = npos)
{
  std::vector<std::map<int, double>> area(m.n_components);
  for(std::size_t f = 0; f < m.nf; ++f) area[m.face_component[f]][W[f]] += m.face_area(f);
  std::vector<int> offset(m.n_components, 0);
  for(std::size_t c = 0; c < m.n_components; ++c)
  {
    bool first = true;
    double best = 0;
    for(const auto& la : area[c])
    {
      const bool better = first || la.second > best ||
                          (la.second == best && std::abs(la.first) < std::abs(offset[c]));
      if(better) { offset[c] = la.first; best = la.second; first = false; }
    }
  }
  if(anchor != npos) offset[m.face_component[anchor]] = W[anchor];
  for(std::size_t f = 0; f < m.nf; ++f) W[f] -= offset[m.face_component[f]];
  return offset;
}

// Bounding chain: the jump J W of the labels across every interior edge (paper Sec. 3.6), closed by
// construction. Zero on border edges.
inline std::vector<int> bounding_chain(const Mesh_tables& m, const std::vector<int>& W)
{
  std::vector<int> B(m.ne, 0);
  for(const Arc& arc : m.arcs) B[arc.edge] = W[arc.left_side / 3] - W[arc.right_side / 3];
  return B;
}

} // namespace internal
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif
