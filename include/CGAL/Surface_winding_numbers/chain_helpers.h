// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT

#ifndef CGAL_SURFACE_WINDING_NUMBERS_CHAIN_HELPERS_H
#define CGAL_SURFACE_WINDING_NUMBERS_CHAIN_HELPERS_H

#include <CGAL/Surface_winding_numbers/internal/descriptor_checks.h>

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
\pre every halfedge of `halfedges` is a halfedge of `tm`, and `chain` has a value for every edge of `tm`.
     What can be checked cheaply is: a null descriptor, and with a `Surface_mesh` a halfedge index out of
     range or removed, and a property map with fewer entries than `tm` has edges (a map of another mesh).
\returns `false`, and leaves the chain unchanged, if one of these checks fails; `true` otherwise.
*/
template <class TriangleMesh, class HalfedgeRange, class ChainMap>
bool add_halfedges_to_chain(const TriangleMesh& tm, const HalfedgeRange& halfedges, ChainMap chain,
                            int multiplicity = 1)
{
  typedef typename boost::property_traits<ChainMap>::value_type V;
  for(auto h : halfedges)
    if(!internal::is_halfedge_of(h, tm)) return false;
  if(!internal::map_coverage_error(chain, edges(tm), "", "").empty()) return false;
  const auto reference = internal::reference_halfedge_marks(tm);
  for(auto h : halfedges)
  {
    const auto e = edge(h, tm);
    const int s = get(reference, h) ? multiplicity : -multiplicity;
    put(chain, e, static_cast<V>(get(chain, e) + s));
  }
  return true;
}

/*!
\ingroup PkgSurfaceWindingNumbersRef
adds the open polyline through the vertices of `polyline` (in order) to the chain: one traversal of
each edge between consecutive vertices. Repeat the first vertex at the end to close a loop.
\tparam VertexRange a range of `vertex_descriptor`
\tparam ChainMap a model of `ReadWritePropertyMap`, key `edge_descriptor`, integer value
\pre every vertex of `polyline` is a vertex of `tm`, and `chain` has a value for every edge of `tm`
     (checked as far as `add_halfedges_to_chain()` checks its halfedges: null descriptors, and with a
     `Surface_mesh` indices out of range or removed and maps of another mesh).
\returns `false`, and leaves the chain unchanged, if two consecutive vertices are not joined by an edge
         or a check of the precondition fails; `true` otherwise.
*/
template <class TriangleMesh, class VertexRange, class ChainMap>
bool add_vertex_polyline_to_chain(const TriangleMesh& tm, const VertexRange& polyline, ChainMap chain,
                                  int multiplicity = 1)
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  std::vector<halfedge_descriptor> hs;
  auto it = std::begin(polyline), end = std::end(polyline);
  if(it == end) return true;
  auto prev = *it;
  if(!internal::is_vertex_of(prev, tm)) return false;
  for(++it; it != end; ++it)
  {
    if(!internal::is_vertex_of(*it, tm)) return false;
    const std::pair<halfedge_descriptor, bool> h = halfedge(prev, *it, tm);
    if(!h.second) return false;
    hs.push_back(h.first);
    prev = *it;
  }
  return add_halfedges_to_chain(tm, hs, chain, multiplicity);
}

} // namespace Surface_winding_numbers
} // namespace CGAL

#endif
