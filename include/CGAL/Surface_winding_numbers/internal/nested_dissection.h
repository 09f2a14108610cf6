// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT

#ifndef CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_NESTED_DISSECTION_H
#define CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_NESTED_DISSECTION_H

#include <CGAL/Surface_winding_numbers/internal/mesh_tables.h>

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace internal {

// from this many unknowns on, the Laplacians are numbered by nested dissection and the default
// CHOLMOD traits factorize in that numbering (below, the mesh's numbering and AMD)
constexpr std::size_t nested_dissection_unknowns = 150000;

// Elimination order for the sparse Cholesky factorizations of the two Laplacians (jump Laplacian on
// vertices, 2-form Laplacian on faces), by geometric nested dissection: the nodes of a part are split
// at the median of their coordinate along the longest side of their bounding box; the nodes of the
// upper half that have a neighbour in the lower half form the separator, numbered after both halves,
// which are ordered the same way down to parts of `leaf` nodes. A plane cuts a surface mesh along
// curves, so the separators have O(sqrt n) nodes on well-shaped meshes, the fill of nested dissection.
// On the vertex graph of a 1.15M-face mesh of genus 10 (benchmark/RESULTS.md, Speed): 28 % fewer
// flops and 7 % less fill than CHOLMOD's AMD, found in half of AMD's time; on small meshes AMD's fill
// is lower (see the CHOLMOD traits in Surface_winding_numbers_solver.h).
// Used from nested_dissection_unknowns unknowns on: below, AMD's fill is lower and its analysis cheap.
// `first`/`adjacent`: the graph in compressed rows; `xyz`: 3 coordinates per node. Returns the order
// (order[k] is the k-th node to eliminate).
inline std::vector<std::size_t> nested_dissection_order(const std::vector<std::size_t>& first,
                                                        const std::vector<std::size_t>& adjacent,
                                                        const std::vector<double>& xyz, std::size_t leaf = 16)
{
  const std::size_t n = first.size() - 1;
  std::vector<std::size_t> order(n);
  for(std::size_t v = 0; v < n; ++v) order[v] = v;
  std::vector<std::size_t> stamp(n, 0);   // the split that last put the node in a lower half
  std::size_t splits = 0;
  std::vector<std::pair<std::size_t, std::size_t>> parts(1, std::make_pair(std::size_t(0), n));   // [begin, end)
  while(!parts.empty())
  {
    const std::size_t b = parts.back().first, e = parts.back().second;
    parts.pop_back();
    if(e - b <= leaf) continue;
    double lo[3], hi[3];
    for(int k = 0; k < 3; ++k) lo[k] = hi[k] = xyz[3 * order[b] + k];
    for(std::size_t i = b; i < e; ++i)
      for(int k = 0; k < 3; ++k)
      {
        lo[k] = (std::min)(lo[k], xyz[3 * order[i] + k]);
        hi[k] = (std::max)(hi[k], xyz[3 * order[i] + k]);
      }
    int axis = 0;
    for(int k = 1; k < 3; ++k)
      if(hi[k] - lo[k] > hi[axis] - lo[axis]) axis = k;
    const std::size_t mid = b + (e - b) / 2;
    std::nth_element(order.begin() + b, order.begin() + mid, order.begin() + e, [&](std::size_t x, std::size_t y) {
      return xyz[3 * x + axis] < xyz[3 * y + axis];
    });
    ++splits;
    for(std::size_t i = b; i < mid; ++i) stamp[order[i]] = splits;
    // the upper half's nodes next to the lower half go last
    auto off_separator = [&](std::size_t v) {
      for(std::size_t k = first[v]; k < first[v + 1]; ++k)
        if(stamp[adjacent[k]] == splits) return false;
      return true;
    };
    const std::size_t upper_end = std::size_t(std::stable_partition(order.begin() + mid, order.begin() + e, off_separator) -
                                              order.begin());
    parts.emplace_back(b, mid);
    parts.emplace_back(mid, upper_end);
  }
  return order;
}

// the order above on the vertices of the mesh (joined by its edges); empty below
// nested_dissection_unknowns vertices
inline std::vector<std::size_t> vertex_elimination_order(const Mesh_tables& m)
{
  if(m.nv < nested_dissection_unknowns) return {};
  std::vector<std::size_t> first(m.nv + 1, 0), adjacent(2 * m.ne);
  for(std::size_t e = 0; e < m.ne; ++e) { ++first[m.ev[2 * e] + 1]; ++first[m.ev[2 * e + 1] + 1]; }
  for(std::size_t v = 0; v < m.nv; ++v) first[v + 1] += first[v];
  std::vector<std::size_t> fill(first.begin(), first.end() - 1);
  for(std::size_t e = 0; e < m.ne; ++e)
  {
    adjacent[fill[m.ev[2 * e]]++] = m.ev[2 * e + 1];
    adjacent[fill[m.ev[2 * e + 1]]++] = m.ev[2 * e];
  }
  return nested_dissection_order(first, adjacent, m.points);
}

// the order above on the faces of the mesh (joined across their edges), placed at their centroids;
// empty below nested_dissection_unknowns faces
inline std::vector<std::size_t> face_elimination_order(const Mesh_tables& m)
{
  if(m.nf < nested_dissection_unknowns) return {};
  std::vector<std::size_t> first(m.nf + 1, 0), adjacent;
  for(std::size_t e = 0; e < m.ne; ++e)
    for(std::size_t i = m.edge_side_begin[e]; i < m.edge_side_begin[e + 1]; ++i)
      first[m.edge_sides[i] / 3 + 1] += m.edge_side_begin[e + 1] - m.edge_side_begin[e] - 1;
  for(std::size_t f = 0; f < m.nf; ++f) first[f + 1] += first[f];
  adjacent.resize(first[m.nf]);
  std::vector<std::size_t> fill(first.begin(), first.end() - 1);
  for(std::size_t e = 0; e < m.ne; ++e)
    for(std::size_t i = m.edge_side_begin[e]; i < m.edge_side_begin[e + 1]; ++i)
      for(std::size_t j = m.edge_side_begin[e]; j < m.edge_side_begin[e + 1]; ++j)
        if(i != j) adjacent[fill[m.edge_sides[i] / 3]++] = m.edge_sides[j] / 3;
  std::vector<double> centroid(3 * m.nf, 0.);
  for(std::size_t c = 0; c < 3 * m.nf; ++c)
    for(int k = 0; k < 3; ++k) centroid[3 * (c / 3) + k] += m.points[3 * m.fv[c] + k] / 3;
  return nested_dissection_order(first, adjacent, centroid);
}

} // namespace internal
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif
