// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT

#ifndef CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_DESCRIPTOR_CHECKS_H
#define CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_DESCRIPTOR_CHECKS_H

#include <CGAL/Surface_mesh/Surface_mesh_fwd.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <cstddef>
#include <string>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace Properties {
template <class I, class T, class CRTP_derived_class> class Property_map_base;
}
namespace Surface_winding_numbers {
namespace internal {

// The checks of API misuse that cost next to nothing: a descriptor that is not an element of the mesh
// (null, out of range or removed, where the graph type tells), and a property map of a Surface_mesh
// that has fewer entries than the elements it is used for (a map of another, smaller mesh). What the
// graph type does not tell (a Polyhedron_3 handle of another polyhedron) stays a documented
// precondition.

// a descriptor of `g`? Generic graphs: not null
template <class Descriptor, class Graph>
bool is_element_of(Descriptor d, const Graph&, Descriptor null)
{
  return d != null;
}

// Surface_mesh: in range and not removed
template <class Index, class P>
bool is_element_of(Index d, const CGAL::Surface_mesh<P>& sm, Index)
{
  const std::size_t i = std::size_t(d);
  if constexpr(std::is_same<Index, typename CGAL::Surface_mesh<P>::Vertex_index>::value)
    return d.is_valid() && i < sm.num_vertices() && !sm.is_removed(d);
  else if constexpr(std::is_same<Index, typename CGAL::Surface_mesh<P>::Halfedge_index>::value)
    return d.is_valid() && i < sm.num_halfedges() && !sm.is_removed(d);
  else
    return true;
}

template <class Graph>
bool is_vertex_of(typename boost::graph_traits<Graph>::vertex_descriptor v, const Graph& g)
{
  return is_element_of(v, g, boost::graph_traits<Graph>::null_vertex());
}

template <class Graph>
bool is_halfedge_of(typename boost::graph_traits<Graph>::halfedge_descriptor h, const Graph& g)
{
  return is_element_of(h, g, boost::graph_traits<Graph>::null_halfedge());
}

// Surface_mesh property maps (keyed by indices, with a size) and the others
template <class I, class T, class C>
std::true_type is_surface_mesh_property_map_test(const CGAL::Properties::Property_map_base<I, T, C>*);
std::false_type is_surface_mesh_property_map_test(const void*);
template <class Map>
using is_surface_mesh_property_map = decltype(is_surface_mesh_property_map_test(static_cast<const Map*>(nullptr)));

// Empty if `map` has an entry for every key of `keys` (always, unless it is a Surface_mesh property map),
// else the message that says it has not; `what` names the map ("the chain map") and `elements` the keys
// ("edges").
template <class Map, class KeyRange>
std::string map_coverage_error(const Map& map, const KeyRange& keys, const std::string& what, const std::string& elements)
{
  if constexpr(!is_surface_mesh_property_map<Map>::value)
    return std::string();
  else
  {
    const std::size_t entries = map ? std::size_t(map.end() - map.begin()) : 0;
    std::size_t needed = 0, count = 0;
    for(auto k : keys)
    {
      needed = (std::max)(needed, std::size_t(k) + 1);
      ++count;
    }
    if(entries >= needed) return std::string();
    return what + " has " + std::to_string(entries) + " entries but the mesh has " + std::to_string(count) + " " +
           elements + " (indices up to " + std::to_string(needed - 1) + "): is it a property map of another mesh?";
  }
}

} // namespace internal
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif
