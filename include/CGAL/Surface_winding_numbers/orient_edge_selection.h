// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT

#ifndef CGAL_SURFACE_WINDING_NUMBERS_ORIENT_EDGE_SELECTION_H
#define CGAL_SURFACE_WINDING_NUMBERS_ORIENT_EDGE_SELECTION_H

#include <CGAL/Surface_winding_numbers/Solve_report.h>
#include <CGAL/Surface_winding_numbers/chain_helpers.h>
#include <CGAL/Surface_winding_numbers/internal/descriptor_checks.h>

#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Kernel/global_functions.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {

/*!
\ingroup PkgSurfaceWindingNumbersRef

\brief orients a selection of unoriented edges, as a selection tool gives it, and adds it to `chain`.

The selection is cut into pieces, the maximal paths of selected edges through vertices where exactly two
selected edges meet, and the pieces are grouped into clusters: two pieces whose ends are closer than five
mean lengths of the selected edges are in one cluster (the pieces of one loop broken by gaps), and so are
the pieces that end within that distance of one border cycle of the mesh (open curves that the border
closes into loops, such as the two sides of a band across a disk). Within a cluster, the pieces are joined
end to nearest end (nearest first) into groups that run head to tail: the pieces of one loop or one open
curve, however straight, take one direction along it. Each group is oriented in the sense that makes it
turn counter-clockwise, seen from the side the faces face, around the centroid of its cluster (the
length-weighted mean of the edges' midpoints): the orientation of a lasso drawn around a region. This is
right for the borders of regions that are roughly star-shaped from their centroids, with gaps shorter
than the clusters' reach; a single open curve across the mesh, straight through its own centroid, has
one direction along its whole length but either sense; isolated pieces, whose orientation is then
arbitrary, are what the surface winding numbers filter out.

Then `CGAL::surface_winding_numbers()` with a `bounding_chain_map` completes the selection: its labels
are the selected region (nonzero), and the bounding chain is the cleaned selection, the closed border of
the region, without the spurious pieces (user manual, \ref SWNExampleSelection).

\tparam TriangleMesh a model of `FaceListGraph`, `EdgeListGraph` and `VertexListGraph` whose faces are triangles
\tparam EdgeRange a range of `boost::graph_traits<TriangleMesh>::%edge_descriptor`; repeated edges count once
\tparam ChainMap a model of `ReadWritePropertyMap` with key `boost::graph_traits<TriangleMesh>::%edge_descriptor`
        and an integer value type (as for `CGAL::surface_winding_numbers()`)
\tparam NamedParameters a sequence of named parameters

\param tm the mesh
\param selection the selected edges
\param chain the chain the oriented selection is added to
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{a property map associating points to the vertices of `tm`}
    \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `%Point_3` as value type}
    \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\pre every element of `selection` is an edge of `tm`, and `chain` has a value for every edge of `tm`.
\returns the number of pieces
\throws Invalid_input, and leaves `chain` unchanged, if the precondition is found violated: an element of
`selection` that is null (or, with a `Surface_mesh`, out of range or removed), or a `Surface_mesh` property
map with fewer entries than the mesh has edges (a map of another mesh).
*/
template <class TriangleMesh, class EdgeRange, class ChainMap,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
std::size_t orient_edge_selection(const TriangleMesh& tm, const EdgeRange& selection, ChainMap chain,
                                  const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef boost::graph_traits<TriangleMesh> Traits;
  typedef typename Traits::halfedge_descriptor halfedge_descriptor;
  typedef typename Traits::vertex_descriptor vertex_descriptor;
  typedef typename GetGeomTraits<TriangleMesh, NamedParameters>::type GT;
  typedef typename GT::Vector_3 Vector;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;

  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));
  // the precondition, checked before anything is read or written
  std::size_t k = 0;
  for(auto e : selection)
  {
    if(!internal::is_halfedge_of(halfedge(e, tm), tm))
      throw Invalid_input("orient_edge_selection(): element " + std::to_string(k) +
                          " of the selection is not an edge of the mesh (null, out of range or removed)");
    ++k;
  }
  const std::string coverage = internal::map_coverage_error(chain, edges(tm), "orient_edge_selection(): the chain map", "edges");
  if(!coverage.empty()) throw Invalid_input(coverage);
  auto selected = get(CGAL::dynamic_edge_property_t<bool>(), tm);   // false by default
  auto degree = get(CGAL::dynamic_vertex_property_t<int>(), tm);    // 0 by default
  std::vector<halfedge_descriptor> edges_in;
  auto point = [&](vertex_descriptor v) { return get(vpm, v) - CGAL::ORIGIN; };
  auto length_of = [&](halfedge_descriptor h) {
    return std::sqrt(CGAL::to_double((point(target(h, tm)) - point(source(h, tm))).squared_length()));
  };
  double length = 0;
  for(auto e : selection)
  {
    if(get(selected, e)) continue;
    put(selected, e, true);
    const halfedge_descriptor h = halfedge(e, tm);
    edges_in.push_back(h);
    for(vertex_descriptor v : {source(h, tm), target(h, tm)}) put(degree, v, get(degree, v) + 1);
    length += length_of(h);
  }
  if(edges_in.empty()) return 0;
  const double link = 5 * length / double(edges_in.size());

  // the pieces, each along itself
  auto visited = get(CGAL::dynamic_edge_property_t<bool>(), tm);
  // the next selected halfedge after h through a vertex of degree 2 (none at other vertices)
  auto next_in_piece = [&](halfedge_descriptor h) {
    const vertex_descriptor v = target(h, tm);
    if(get(degree, v) != 2) return Traits::null_halfedge();
    for(halfedge_descriptor g : halfedges_around_source(v, tm))
      if(get(selected, edge(g, tm)) && edge(g, tm) != edge(h, tm)) return g;
    return Traits::null_halfedge();
  };
  std::vector<std::vector<halfedge_descriptor> > pieces;
  for(halfedge_descriptor start : edges_in)
  {
    if(get(visited, edge(start, tm))) continue;
    pieces.emplace_back();
    // back to the start of the piece (or once around a loop), then forward
    halfedge_descriptor h = start;
    for(halfedge_descriptor b = next_in_piece(opposite(h, tm)); b != Traits::null_halfedge() && edge(b, tm) != edge(start, tm);
        b = next_in_piece(b))
      h = opposite(b, tm);
    for(; h != Traits::null_halfedge() && !get(visited, edge(h, tm)); h = next_in_piece(h))
    {
      put(visited, edge(h, tm), true);
      pieces.back().push_back(h);
    }
  }

  // clusters: pieces whose ends are closer than five mean selected edge lengths (a loop broken by gaps),
  // and pieces that end within that distance of one border cycle of the mesh (sides of one region that the
  // border closes, such as the two sides of a band across a disk)
  const std::size_t n = pieces.size();
  std::vector<std::size_t> cluster(n);
  for(std::size_t i = 0; i < n; ++i) cluster[i] = i;
  auto find = [&](std::size_t i) { while(cluster[i] != i) i = cluster[i] = cluster[cluster[i]]; return i; };
  auto ends = [&](std::size_t i) {
    return std::array<Vector, 2>{point(source(pieces[i].front(), tm)), point(target(pieces[i].back(), tm))};
  };
  auto squared = [](const Vector& v) { return CGAL::to_double(v.squared_length()); };
  // for every end (2 i + s: s = 0 the start of piece i, 1 its end), the nearest end of another piece
  std::vector<std::size_t> nearest(2 * n, std::size_t(-1));
  std::vector<double> nearest_distance(2 * n, link * link);
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j = i + 1; j < n; ++j)
      for(std::size_t s = 0; s < 2; ++s)
        for(std::size_t t = 0; t < 2; ++t)
        {
          const double d = squared(ends(i)[s] - ends(j)[t]);
          if(d >= link * link) continue;
          cluster[find(i)] = find(j);
          if(d < nearest_distance[2 * i + s]) { nearest_distance[2 * i + s] = d; nearest[2 * i + s] = 2 * j + t; }
          if(d < nearest_distance[2 * j + t]) { nearest_distance[2 * j + t] = d; nearest[2 * j + t] = 2 * i + s; }
        }
  {
    std::vector<std::pair<Vector, std::size_t> > border;   // the border vertices and their cycles
    auto on_cycle = get(CGAL::dynamic_halfedge_property_t<bool>(), tm);
    std::size_t cycles = 0;
    for(halfedge_descriptor h : halfedges(tm))
    {
      if(!is_border(h, tm) || get(on_cycle, h)) continue;
      for(halfedge_descriptor g : halfedges_around_face(h, tm))
      {
        put(on_cycle, g, true);
        border.emplace_back(point(target(g, tm)), cycles);
      }
      ++cycles;
    }
    std::vector<std::size_t> first(cycles, std::size_t(-1));   // a piece near every cycle
    for(std::size_t i = 0; i < n; ++i)
      for(const Vector& p : ends(i))
        for(const auto& b : border)
          if(squared(p - b.first) < link * link)
          {
            if(first[b.second] == std::size_t(-1)) first[b.second] = i;
            cluster[find(i)] = find(first[b.second]);
          }
  }
  // the pieces of one loop go head to tail across its gaps: joined end to nearest end, nearest first,
  // into groups in which each piece is along (flip 0) or against (flip 1) the group's direction
  std::vector<std::size_t> group(n), flip(n, 0);   // flip relative to the parent in `group`
  for(std::size_t i = 0; i < n; ++i) group[i] = i;
  auto root = [&](std::size_t i, std::size_t& parity) {
    parity = 0;
    for(; group[i] != i; i = group[i]) parity ^= flip[i];
    return i;
  };
  std::vector<std::size_t> order;
  for(std::size_t e = 0; e < 2 * n; ++e) if(nearest[e] != std::size_t(-1)) order.push_back(e);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return nearest_distance[a] < nearest_distance[b]; });
  for(std::size_t e : order)
  {
    const std::size_t f = nearest[e];
    std::size_t pi, pj;
    const std::size_t ri = root(e / 2, pi), rj = root(f / 2, pj);
    if(ri == rj) continue;
    // two starts or two ends meet: the pieces run in opposite directions
    group[ri] = rj;
    flip[ri] = pi ^ pj ^ ((e % 2 == f % 2) ? 1 : 0);
  }
  // the length-weighted centroid of every cluster
  std::vector<Vector> centroid(n, NULL_VECTOR);
  std::vector<double> weight(n, 0.);
  for(std::size_t i = 0; i < n; ++i)
    for(halfedge_descriptor h : pieces[i])
    {
      const double l = length_of(h);
      centroid[find(i)] = centroid[find(i)] + (l / 2) * (point(source(h, tm)) + point(target(h, tm)));
      weight[find(i)] += l;
    }

  // the normal of an edge: the sum of its faces' (area-weighted) normals
  auto normal = [&](halfedge_descriptor h) {
    Vector nm = NULL_VECTOR;
    for(halfedge_descriptor g : {h, opposite(h, tm)})
      if(!is_border(g, tm))
      {
        const Vector a = point(source(g, tm)), b = point(target(g, tm)), c = point(target(next(g, tm), tm));
        nm = nm + CGAL::cross_product(b - a, c - a);
      }
    return nm;
  };
  // every group turns counter-clockwise around the centroid of its cluster
  std::vector<double> turn(n, 0.), group_turn(n, 0.);
  std::vector<std::size_t> parity(n);
  for(std::size_t i = 0; i < n; ++i)
  {
    const Vector c = centroid[find(i)] / weight[find(i)];
    for(halfedge_descriptor g : pieces[i])
    {
      const Vector p = point(source(g, tm)), q = point(target(g, tm));
      turn[i] += CGAL::to_double(CGAL::cross_product((p + q) / 2 - c, q - p) * normal(g));
    }
    const std::size_t r = root(i, parity[i]);
    group_turn[r] += parity[i] ? -turn[i] : turn[i];
  }
  std::vector<halfedge_descriptor> oriented;
  for(std::size_t i = 0; i < n; ++i)
  {
    std::size_t p;
    const bool reverse = (parity[i] == 1) != (group_turn[root(i, p)] < 0);
    for(halfedge_descriptor g : pieces[i]) oriented.push_back(reverse ? opposite(g, tm) : g);
  }
  add_halfedges_to_chain(tm, oriented, chain);
  return n;
}

} // namespace Surface_winding_numbers
} // namespace CGAL

#endif // CGAL_SURFACE_WINDING_NUMBERS_ORIENT_EDGE_SELECTION_H
