// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT

#ifndef CGAL_SURFACE_WINDING_NUMBERS_CHAIN_HELPERS_H
#define CGAL_SURFACE_WINDING_NUMBERS_CHAIN_HELPERS_H

#include <CGAL/Dynamic_property_map.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <iterator>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {

/// \cond SKIP_IN_MANUAL
namespace internal {

// halfedge -> bool: true on the reference halfedge of every edge, `halfedge(e, tm)` for the descriptor
// `e` met while iterating over `edges(tm)`, false on its opposite
template <class TriangleMesh>
auto reference_halfedge_marks(const TriangleMesh& tm)
{
  auto reference = get(CGAL::dynamic_halfedge_property_t<bool>(), tm);
  for(auto e : edges(tm))
  {
    put(reference, halfedge(e, tm), true);
    put(reference, opposite(halfedge(e, tm), tm), false);
  }
  return reference;
}

} // namespace internal
/// \endcond

/*!
\ingroup PkgSurfaceWindingNumbersRef
adds `multiplicity` to the chain for every halfedge of `halfedges`: `+multiplicity` on `edge(h, tm)` if
`h` is the reference halfedge of its edge, `-multiplicity` otherwise. Repeated halfedges accumulate,
opposite halfedges cancel.

The reference halfedge of an edge is `halfedge(e, tm)` for the descriptor `e` met while iterating over
`edges(tm)`. (With CGAL 5.5's `Surface_mesh`, `halfedge(edge(h, tm), tm)` returns `h` itself, so it
cannot serve as the reference; this function does not rely on it.) Linear in the size of `tm`.
\tparam HalfedgeRange a range of `halfedge_descriptor`
\tparam ChainMap a model of `ReadWritePropertyMap`, key `edge_descriptor`, integer value
*/
template <class TriangleMesh, class HalfedgeRange, class ChainMap>
void add_halfedges_to_chain(const TriangleMesh& tm, const HalfedgeRange& halfedges, ChainMap& chain,
                            int multiplicity = 1)
{
  typedef typename boost::property_traits<ChainMap>::value_type V;
  const auto reference = internal::reference_halfedge_marks(tm);
  for(auto h : halfedges)
  {
    const auto e = edge(h, tm);
    const int s = get(reference, h) ? multiplicity : -multiplicity;
    put(chain, e, static_cast<V>(get(chain, e) + s));
  }
}

/*!
\ingroup PkgSurfaceWindingNumbersRef
adds the open polyline through the vertices of `polyline` (in order) to the chain: one traversal of
each edge between consecutive vertices. Repeat the first vertex at the end to close a loop.
\tparam VertexRange a range of `vertex_descriptor`
\tparam ChainMap a model of `ReadWritePropertyMap`, key `edge_descriptor`, integer value
\returns `false`, and leaves the chain unchanged, if two consecutive vertices are not joined by an edge.
*/
template <class TriangleMesh, class VertexRange, class ChainMap>
bool add_vertex_polyline_to_chain(const TriangleMesh& tm, const VertexRange& polyline, ChainMap& chain,
                                  int multiplicity = 1)
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  std::vector<halfedge_descriptor> hs;
  auto it = std::begin(polyline), end = std::end(polyline);
  if(it == end) return true;
  auto prev = *it;
  for(++it; it != end; ++it)
  {
    const std::pair<halfedge_descriptor, bool> h = halfedge(prev, *it, tm);
    if(!h.second) return false;
    hs.push_back(h.first);
    prev = *it;
  }
  add_halfedges_to_chain(tm, hs, chain, multiplicity);
  return true;
}

} // namespace Surface_winding_numbers
} // namespace CGAL

#endif
