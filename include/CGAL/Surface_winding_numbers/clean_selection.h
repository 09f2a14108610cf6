// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT

#ifndef CGAL_SURFACE_WINDING_NUMBERS_CLEAN_SELECTION_H
#define CGAL_SURFACE_WINDING_NUMBERS_CLEAN_SELECTION_H

#include <CGAL/surface_winding_numbers.h>
#include <CGAL/Surface_winding_numbers/chain_helpers.h>
#include <CGAL/Surface_winding_numbers/orient_edge_selection.h>

#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cstddef>
#include <map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {

/// \cond SKIP_IN_MANUAL
namespace internal {

// The connected components of the faces of tm across its interior edges, numbered from 0 (face ->
// component in `component`); returns their number.
template <class TriangleMesh, class ComponentMap>
std::size_t face_components_across_edges(const TriangleMesh& tm, ComponentMap component)
{
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  const std::size_t none = std::size_t(-1);
  for(face_descriptor f : faces(tm)) put(component, f, none);
  std::size_t n = 0;
  std::vector<face_descriptor> stack;
  for(face_descriptor f0 : faces(tm))
  {
    if(get(component, f0) != none) continue;
    put(component, f0, n);
    stack.assign(1, f0);
    while(!stack.empty())
    {
      const face_descriptor f = stack.back();
      stack.pop_back();
      for(auto h : halfedges_around_face(halfedge(f, tm), tm))
      {
        if(is_border(opposite(h, tm), tm)) continue;
        const face_descriptor g = face(opposite(h, tm), tm);
        if(get(component, g) == none) { put(component, g, n); stack.push_back(g); }
      }
    }
    ++n;
  }
  return n;
}

// cleaned(f) = labels(f) is above the reference label of f's component: per component, the label that
// covers the most faces among those for which `counts(f)` is true (ties: the smallest label), and where
// no face counts, the smallest label of the component minus `below_smallest`; the named parameter
// `bounding_chain_map`, if given, receives the border of the cleaned region
template <class TriangleMesh, class LabelMap, class Counts, class CleanedMap, class NamedParameters>
void faces_above_reference_label(const TriangleMesh& tm, const LabelMap& labels, const Counts& counts,
                                 int below_smallest, CleanedMap cleaned, const NamedParameters& np)
{
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  auto component = get(CGAL::dynamic_face_property_t<std::size_t>(), tm);
  const std::size_t n = face_components_across_edges(tm, component);
  std::vector<std::map<int, std::size_t>> histogram(n);
  std::vector<int> smallest(n, 0);
  std::vector<char> seen(n, 0);
  for(face_descriptor f : faces(tm))
  {
    const std::size_t c = get(component, f);
    const int W = int(get(labels, f));
    if(!seen[c] || W < smallest[c]) smallest[c] = W;
    seen[c] = 1;
    if(counts(f)) ++histogram[c][W];
  }
  std::vector<int> reference(n);
  for(std::size_t c = 0; c < n; ++c)
  {
    reference[c] = smallest[c] - below_smallest;
    std::size_t best = 0;
    for(const auto& kv : histogram[c])
      if(kv.second > best) { best = kv.second; reference[c] = kv.first; }   // ties: the smallest label
  }
  auto inside = [&](face_descriptor f) { return int(get(labels, f)) > reference[get(component, f)]; };
  for(face_descriptor f : faces(tm)) put(cleaned, f, inside(f));
  // the bounding chain: the border of the region (the solve's jumps of W also run around faces of a
  // higher label inside it)
  namespace snp = Surface_winding_numbers::internal_np;
  if constexpr(!CGAL::parameters::is_default_parameter<NamedParameters, snp::bounding_chain_map_t>::value)
  {
    auto border = CGAL::parameters::get_parameter(np, snp::bounding_chain_map);
    typedef typename boost::property_traits<decltype(border)>::value_type V;
    for(auto e : edges(tm))
    {
      const auto h = halfedge(e, tm);
      const int jump = is_border(e, tm) ? 0 : int(inside(face(h, tm))) - int(inside(face(opposite(h, tm), tm)));
      put(border, e, static_cast<V>(jump));
    }
  }
}

} // namespace internal
/// \endcond

/*!
\ingroup PkgSurfaceWindingNumbersRef

\brief turns a noisy selection of faces into a clean region: the boundary of the selection as a chain,
its surface winding numbers, and the faces they put inside (the paper's Sec. 5.5).

A selection made with a brush or a lasso in screen space has noise: faces left out inside the region,
faces picked outside it, a ragged border. Taken as it is, the boundary of the selection (every interior
halfedge with a selected face on its left and an unselected face on its right) is a closed chain that
bounds exactly the selection, noise included, and its winding numbers would give the selection back
unchanged. The function therefore first marks as noise every face whose selection state differs from
that of more than half of the faces around its vertices and from that of more than half of its
neighbours across edges: an isolated face selected or left out, a small cluster of them, a spike or a
notch of the border (a face along a straight border, or at the border of the mesh, differs from one
neighbour across edges only and is not noise). A tooth, a noise face with all sides but one on the
border of the selection and joined by the last one to a face of its state that is not noise (a spike, a
notch, or a corner of the region), is kept where no face within two rings of it is noise other than
teeth: where the selection has no noise to clean, its corners and its ragged border stay. The
halfedges of the boundary at noise faces are left out of the chain, which leaves gaps: the surface
winding numbers close the gaps of the large loops along short paths and filter out what remains of the
small ones (short open pieces). The boundary of the selection along the border of the mesh is not part
of the chain. The cleaned selection is the set of faces whose label is above the reference label of
their connected component (faces joined across edges): the label that covers the most unselected faces
of the component (where every face of a component is selected, they all stay selected).

An exact selection (no noise) comes back unchanged, but for what looks like noise wherever it is:
isolated faces (a face at the border of the mesh whose neighbours are all of the other state included),
small clusters of them, and spikes or notches of two faces or more. A cluster of noise large enough that its faces see mostly their own state is kept as a
region of its own, and the border of the cleaned region follows the kept part of the selection's
border and short paths across its gaps, not a smoothed curve. On a sphere of 1,280 faces with a cap of
294 faces selected and 11 % of all faces flipped at random, 125-150 wrong faces become 7-21, 12 on
average over 12 random draws; on a 20 x 20 grid disk (800 faces) with a band of 10 rows across it and
8 % of the faces flipped, 52-79 wrong faces become 1-14, 6 on average over 20 draws (user manual,
\ref SWNExampleSelection).

\tparam TriangleMesh a model of `FaceListGraph`, `EdgeListGraph` and `HalfedgeListGraph` (faces of more
        than three sides are accepted, as by `CGAL::surface_winding_numbers()`)
\tparam SelectionMap a model of `ReadablePropertyMap` with key
        `boost::graph_traits<TriangleMesh>::%face_descriptor` and value type convertible to `bool`
\tparam CleanedMap a model of `WritablePropertyMap` with key
        `boost::graph_traits<TriangleMesh>::%face_descriptor` and value type `bool`
\tparam NamedParameters a sequence of named parameters

\param tm the mesh
\param selection the selected faces (`true`)
\param cleaned receives the cleaned selection: `true` for the faces of the region, `false` elsewhere
\param np an optional sequence of the named parameters of `CGAL::surface_winding_numbers()`, passed on
       to it: `report` tells what the solve did (its `curve_edges` are the boundary halfedges kept,
       `interior_endpoints` the ends of the gaps), `bounding_chain_map` receives the border of the cleaned
       region as a chain, `vertex_point_map` and the solver settings are used for the solve

\returns `true` on success; `false` if the solve fails (the named parameter `report` tells why), and
         then `cleaned` is not written.

\sa `CGAL::Surface_winding_numbers::clean_edge_selection()`
*/
template <class TriangleMesh, class SelectionMap, class CleanedMap,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
bool clean_face_selection(const TriangleMesh& tm, SelectionMap selection, CleanedMap cleaned,
                          const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  auto selected = [&](face_descriptor f) { return bool(get(selection, f)); };

  // noise: faces whose state differs from that of most of the faces around their vertices and from that
  // of most of their neighbours across edges (a face along the border of the selection differs from one)
  auto noise = get(CGAL::dynamic_face_property_t<bool>(), tm);
  auto sides_differing = [&](face_descriptor f, std::size_t& sides) {
    std::size_t d = 0;
    sides = 0;
    for(halfedge_descriptor h : halfedges_around_face(halfedge(f, tm), tm))
      if(!is_border(opposite(h, tm), tm)) { ++sides; d += selected(face(opposite(h, tm), tm)) != selected(f) ? 1 : 0; }
    return d;
  };
  // the faces sharing a vertex with f (f left out)
  std::vector<face_descriptor> ring;
  auto ring_of = [&](face_descriptor f, std::vector<face_descriptor>& out) {
    out.clear();
    for(halfedge_descriptor h : halfedges_around_face(halfedge(f, tm), tm))
      for(face_descriptor g : faces_around_target(h, tm))
        if(g != boost::graph_traits<TriangleMesh>::null_face() && g != f && std::find(out.begin(), out.end(), g) == out.end())
          out.push_back(g);
  };
  for(face_descriptor f : faces(tm))
  {
    ring_of(f, ring);
    std::size_t differ = 0, sides = 0;
    for(face_descriptor g : ring) differ += selected(g) != selected(f) ? 1 : 0;
    put(noise, f, 2 * differ > ring.size() && 2 * sides_differing(f, sides) > sides);
  }
  // a tooth, a noise face joined by one edge only to a face of its state that is not noise (a corner of
  // the region, a spike or a notch of its border), is kept where no face within two rings of it is noise
  // other than teeth: the selection there has no noise to clean, and its corners and ragged border stay
  auto is_tooth = [&](face_descriptor f) {
    std::size_t sides = 0;
    if(!get(noise, f) || sides_differing(f, sides) + 1 != sides) return false;
    for(halfedge_descriptor h : halfedges_around_face(halfedge(f, tm), tm))
      if(!is_border(opposite(h, tm), tm) && selected(face(opposite(h, tm), tm)) == selected(f))
        return !get(noise, face(opposite(h, tm), tm));
    return false;
  };
  std::vector<face_descriptor> teeth, ring2;
  for(face_descriptor f : faces(tm))
  {
    if(!is_tooth(f)) continue;
    ring_of(f, ring);
    bool alone = true;
    for(std::size_t k = 0; alone && k < ring.size(); ++k)
    {
      ring_of(ring[k], ring2);
      for(face_descriptor g : ring2) if(g != f && get(noise, g) && !is_tooth(g)) { alone = false; break; }
    }
    if(alone) teeth.push_back(f);
  }
  for(face_descriptor f : teeth) put(noise, f, false);
  // the boundary of the selection, without the sides of noise faces
  std::vector<halfedge_descriptor> boundary;
  for(face_descriptor f : faces(tm))
  {
    if(!selected(f) || get(noise, f)) continue;
    for(halfedge_descriptor h : halfedges_around_face(halfedge(f, tm), tm))
    {
      if(is_border(opposite(h, tm), tm)) continue;
      const face_descriptor g = face(opposite(h, tm), tm);
      if(!selected(g) && !get(noise, g)) boundary.push_back(h);
    }
  }
  auto chain = get(CGAL::dynamic_edge_property_t<int>(), tm);
  for(auto e : edges(tm)) put(chain, e, 0);
  if(!add_halfedges_to_chain(tm, boundary, chain)) return false;

  auto labels = get(CGAL::dynamic_face_property_t<int>(), tm);
  if(!CGAL::surface_winding_numbers(tm, chain, labels, np)) return false;
  internal::faces_above_reference_label(tm, labels, [&](face_descriptor f) { return !selected(f); }, 1, cleaned, np);
  return true;
}

/*!
\ingroup PkgSurfaceWindingNumbersRef

\brief turns a noisy selection of unoriented edges (the border of a region, with gaps and spurious
pieces) into a clean region: `orient_edge_selection()`, the surface winding numbers, and the faces they
put inside (the paper's Fig. 25).

The selection is oriented by `orient_edge_selection()` (the pieces of one loop head to tail, each loop
counter-clockwise around the centroid of its cluster; open curves that end on the border of the mesh,
such as the two sides of a band across a disk, form one cluster, which the border closes); the surface
winding numbers close its gaps and filter out the spurious pieces. The
region is the set of faces whose label is above the smallest label of their connected component (faces
joined across edges): the inside of the selection's loops, whether it covers less or more than half of
the surface.

\tparam TriangleMesh a model of `FaceListGraph`, `EdgeListGraph` and `VertexListGraph` whose faces are triangles
\tparam EdgeRange a range of `boost::graph_traits<TriangleMesh>::%edge_descriptor`; repeated edges count once
\tparam CleanedMap a model of `WritablePropertyMap` with key
        `boost::graph_traits<TriangleMesh>::%face_descriptor` and value type `bool`
\tparam NamedParameters a sequence of named parameters

\param tm the mesh
\param selection the selected edges
\param cleaned receives the region: `true` for its faces, `false` elsewhere
\param np an optional sequence of the named parameters of `CGAL::surface_winding_numbers()`, passed on
       to `orient_edge_selection()` (`vertex_point_map`) and to the solve (`report`, `bounding_chain_map`:
       the cleaned selection as a closed chain, ...)

\returns `true` on success; `false` if the solve fails (the named parameter `report` tells why), and
         then `cleaned` is not written.

\sa `CGAL::Surface_winding_numbers::clean_face_selection()`
*/
template <class TriangleMesh, class EdgeRange, class CleanedMap,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
bool clean_edge_selection(const TriangleMesh& tm, const EdgeRange& selection, CleanedMap cleaned,
                          const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  auto chain = get(CGAL::dynamic_edge_property_t<int>(), tm);
  for(auto e : edges(tm)) put(chain, e, 0);
  orient_edge_selection(tm, selection, chain, np);
  auto labels = get(CGAL::dynamic_face_property_t<int>(), tm);
  if(!CGAL::surface_winding_numbers(tm, chain, labels, np)) return false;
  // the reference label of every component: its smallest
  internal::faces_above_reference_label(tm, labels, [](face_descriptor) { return false; }, 0, cleaned, np);
  return true;
}

} // namespace Surface_winding_numbers
} // namespace CGAL

#endif
