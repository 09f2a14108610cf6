// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT
//
// Step of conforming_cut(): the edges of short chain pieces that end at an interior endpoint are split, so
// that the piece keeps jumps once its endpoints are taken out of the jump-Laplace system.

#ifndef CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_REFINE_SHORT_PIECES_H
#define CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_REFINE_SHORT_PIECES_H

#include <CGAL/Dynamic_property_map.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace internal {

// The chain is kept as `flow` (halfedge -> integer): the chain along `h` is flow[h] - flow[opposite(h)],
// so that splitting an edge needs no knowledge of which halfedge is the reference one.

// Splits the edge of `h` at its midpoint, joins the new vertex to the opposite vertex of each incident
// face, and does the same, `rounds - 1` times, to both halves (2^rounds pieces in the end). The halves
// carry the chain of the edge. The faces made by a split get the `origin` (face -> face) of the face split.
template <class TriangleMesh, class VertexPointMap, class FlowMap, class OriginMap>
void split_chain_edge(TriangleMesh& tm, VertexPointMap vpm, FlowMap flow, OriginMap origin,
                      typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h, std::size_t rounds)
{
  typedef typename boost::property_traits<VertexPointMap>::value_type Point;
  if(rounds == 0) return;
  if(is_border(h, tm)) h = opposite(h, tm);
  const Point pu = get(vpm, source(h, tm)), pv = get(vpm, target(h, tm));
  const auto hnew = CGAL::Euler::split_edge(h, tm);   // hnew: u -> w, h: w -> v
  put(vpm, target(hnew, tm), Point((pu.x() + pv.x()) / 2, (pu.y() + pv.y()) / 2, (pu.z() + pv.z()) / 2));
  put(flow, hnew, get(flow, h));
  put(flow, opposite(hnew, tm), get(flow, opposite(h, tm)));
  auto split = [&](typename boost::graph_traits<TriangleMesh>::halfedge_descriptor a,
                   typename boost::graph_traits<TriangleMesh>::halfedge_descriptor b) {
    const auto from = get(origin, face(a, tm));
    const auto d = CGAL::Euler::split_face(a, b, tm);
    put(origin, face(d, tm), from);
    put(origin, face(opposite(d, tm), tm), from);
  };
  if(!is_border(hnew, tm))
    split(hnew, next(h, tm));
  const auto oh = opposite(h, tm), ohn = opposite(hnew, tm);   // v -> w, w -> u
  if(!is_border(oh, tm))
    split(oh, next(ohn, tm));
  split_chain_edge(tm, vpm, flow, origin, hnew, rounds - 1);
  split_chain_edge(tm, vpm, flow, origin, h, rounds - 1);
}

// The chain is cut into pieces at every vertex where its boundary is nonzero or where a number of chain
// edges other than 2 meet; a piece with fewer than `min_edges` edges and an end at an interior endpoint
// (nonzero boundary, not on the mesh border) has each edge split into 2^k edges,
// k = max(1, floor(log2(floor(min_edges / n)))). Returns the number of refined pieces.
template <class TriangleMesh, class VertexPointMap, class FlowMap, class OriginMap>
std::size_t refine_short_pieces(TriangleMesh& tm, VertexPointMap vpm, FlowMap flow, OriginMap origin, std::size_t min_edges)
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  auto value = [&](halfedge_descriptor h) { return get(flow, h) - get(flow, opposite(h, tm)); };

  auto boundary = get(CGAL::dynamic_vertex_property_t<long long>(), tm);   // dynamic maps start at 0 / false
  auto degree = get(CGAL::dynamic_vertex_property_t<int>(), tm);
  for(auto e : edges(tm))
  {
    const halfedge_descriptor h = halfedge(e, tm);
    const long long c = value(h);
    if(c == 0) continue;
    put(boundary, target(h, tm), get(boundary, target(h, tm)) + c);
    put(boundary, source(h, tm), get(boundary, source(h, tm)) - c);
    put(degree, target(h, tm), get(degree, target(h, tm)) + 1);
    put(degree, source(h, tm), get(degree, source(h, tm)) + 1);
  }
  auto is_break = [&](vertex_descriptor v) { return get(boundary, v) != 0 || get(degree, v) != 2; };
  auto interior_endpoint = [&](vertex_descriptor v) { return get(boundary, v) != 0 && !is_border(v, tm); };

  auto visited = get(CGAL::dynamic_halfedge_property_t<bool>(), tm);
  auto visit = [&](halfedge_descriptor h) { put(visited, h, true); put(visited, opposite(h, tm), true); };
  std::vector<std::vector<halfedge_descriptor> > short_pieces;
  for(vertex_descriptor v : vertices(tm))
  {
    if(get(degree, v) == 0 || !is_break(v)) continue;
    for(halfedge_descriptor h0 : CGAL::halfedges_around_source(v, tm))
    {
      if(value(h0) == 0 || get(visited, h0)) continue;
      std::vector<halfedge_descriptor> piece;
      for(halfedge_descriptor h = h0;;)
      {
        visit(h);
        piece.push_back(h);
        if(is_break(target(h, tm))) break;
        halfedge_descriptor after = boost::graph_traits<TriangleMesh>::null_halfedge();
        for(halfedge_descriptor g : CGAL::halfedges_around_source(opposite(h, tm), tm))
          if(g != opposite(h, tm) && value(g) != 0) { after = g; break; }
        if(after == boost::graph_traits<TriangleMesh>::null_halfedge() || get(visited, after)) break;
        h = after;
      }
      if(piece.size() < min_edges && (interior_endpoint(v) || interior_endpoint(target(piece.back(), tm))))
        short_pieces.push_back(std::move(piece));
    }
  }
  for(const auto& piece : short_pieces)
  {
    const std::size_t q = min_edges / piece.size();
    std::size_t k = 0;
    while(k + 1 < 8 * sizeof(std::size_t) && (std::size_t(1) << (k + 1)) <= q) ++k;   // no shift past the width
    k = (std::max<std::size_t>)(k, 1);   // every edge of a short piece is split at least once
    for(halfedge_descriptor h : piece)
      split_chain_edge(tm, vpm, flow, origin, h, k);
  }
  return short_pieces.size();
}

} // namespace internal
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif // CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_REFINE_SHORT_PIECES_H
