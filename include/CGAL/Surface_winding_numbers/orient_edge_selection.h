// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT

#ifndef CGAL_SURFACE_WINDING_NUMBERS_ORIENT_EDGE_SELECTION_H
#define CGAL_SURFACE_WINDING_NUMBERS_ORIENT_EDGE_SELECTION_H

#include <CGAL/Surface_winding_numbers/chain_helpers.h>

#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Kernel/global_functions.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {

/*!
\ingroup PkgSurfaceWindingNumbersRef

\brief orients a selection of unoriented edges, as a selection tool gives it, and adds it to `chain`.

The selection is cut into pieces, the maximal paths of selected edges through vertices where exactly two
selected edges meet. Each piece is oriented along itself, in the sense that makes it turn counter-clockwise,
seen from the side the faces face, around the centroid of the whole selection (the length-weighted mean of
the edges' midpoints): the orientation of a lasso drawn around a region. This is right for selections of
the border of one region that is roughly star-shaped from its centroid; pieces far from the region, whose
orientation is then arbitrary, are what the surface winding numbers filter out.

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

\returns the number of pieces
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
  auto selected = get(CGAL::dynamic_edge_property_t<bool>(), tm);   // false by default
  auto degree = get(CGAL::dynamic_vertex_property_t<int>(), tm);    // 0 by default
  std::vector<halfedge_descriptor> edges_in;
  Vector centroid = NULL_VECTOR;
  double length = 0;
  for(auto e : selection)
  {
    if(get(selected, e)) continue;
    put(selected, e, true);
    const halfedge_descriptor h = halfedge(e, tm);
    edges_in.push_back(h);
    for(vertex_descriptor v : {source(h, tm), target(h, tm)}) put(degree, v, get(degree, v) + 1);
    const auto &p = get(vpm, source(h, tm)), &q = get(vpm, target(h, tm));
    const double l = std::sqrt(CGAL::to_double((q - p).squared_length()));
    centroid = centroid + (l / 2) * ((p - CGAL::ORIGIN) + (q - CGAL::ORIGIN));
    length += l;
  }
  if(edges_in.empty()) return 0;
  centroid = centroid / length;

  // the normal of an edge: the sum of its faces' (area-weighted) normals
  auto normal = [&](halfedge_descriptor h) {
    Vector n = NULL_VECTOR;
    for(halfedge_descriptor g : {h, opposite(h, tm)})
      if(!is_border(g, tm))
      {
        const auto &a = get(vpm, source(g, tm)), &b = get(vpm, target(g, tm)), &c = get(vpm, target(next(g, tm), tm));
        n = n + CGAL::cross_product(b - a, c - a);
      }
    return n;
  };
  auto visited = get(CGAL::dynamic_edge_property_t<bool>(), tm);
  // the next selected halfedge after h through a vertex of degree 2 (none at other vertices)
  auto next_in_piece = [&](halfedge_descriptor h) {
    const vertex_descriptor v = target(h, tm);
    if(get(degree, v) != 2) return Traits::null_halfedge();
    for(halfedge_descriptor g : halfedges_around_source(v, tm))
      if(get(selected, edge(g, tm)) && edge(g, tm) != edge(h, tm)) return g;
    return Traits::null_halfedge();
  };
  std::size_t pieces = 0;
  std::vector<halfedge_descriptor> oriented;
  auto add_piece = [&](halfedge_descriptor start) {
    std::vector<halfedge_descriptor> piece;
    // back to the start of the piece (or once around a loop), then forward
    halfedge_descriptor h = start;
    for(halfedge_descriptor b = next_in_piece(opposite(h, tm)); b != Traits::null_halfedge() && edge(b, tm) != edge(start, tm);
        b = next_in_piece(b))
      h = opposite(b, tm);
    for(; h != Traits::null_halfedge() && !get(visited, edge(h, tm)); h = next_in_piece(h))
    {
      put(visited, edge(h, tm), true);
      piece.push_back(h);
    }
    double turn = 0;
    for(halfedge_descriptor g : piece)
    {
      const auto &p = get(vpm, source(g, tm)), &q = get(vpm, target(g, tm));
      const Vector mid = ((p - CGAL::ORIGIN) + (q - CGAL::ORIGIN)) / 2;
      turn += CGAL::to_double(CGAL::cross_product(mid - centroid, q - p) * normal(g));
    }
    for(halfedge_descriptor g : piece) oriented.push_back(turn < 0 ? opposite(g, tm) : g);
    ++pieces;
  };
  for(halfedge_descriptor h : edges_in)
    if(!get(visited, edge(h, tm))) add_piece(h);
  add_halfedges_to_chain(tm, oriented, chain);
  return pieces;
}

} // namespace Surface_winding_numbers
} // namespace CGAL

#endif // CGAL_SURFACE_WINDING_NUMBERS_ORIENT_EDGE_SELECTION_H
