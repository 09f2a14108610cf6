// Copyright (c) 2026 The CGAL Surface_winding_numbers contributors.
// SPDX-License-Identifier: MIT
//
// Curves on a polygon soup (a mesh file that is not an oriented 2-manifold triangle mesh): the curve files
// and OBJ records of read_curves.h, by vertices and by pairs of faces only, checked against the soup and
// turned into the input of CGAL::polygon_soup_winding_numbers().

#ifndef CGAL_SWN_TOOL_IO_SOUP_CURVES_H
#define CGAL_SWN_TOOL_IO_SOUP_CURVES_H

#include "swn_io/curve_set.h"
#include "swn_io/errors.h"
#include "swn_io/mesh_soup.h"
#include "swn_io/read_curves.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <fstream>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace IO {

/*!
  \brief the edges of a soup as sorted vertex pairs `(i, j)`, `i < j`, each once.
*/
inline std::vector<std::pair<std::size_t, std::size_t> > soup_edges(const Triangle_soup& soup)
{
  std::vector<std::pair<std::size_t, std::size_t> > edges;
  auto add = [&](const auto& face) {
    for(std::size_t k = 0; k < face.size(); ++k)
    {
      const std::size_t a = face[k], b = face[(k + 1) % face.size()];
      edges.emplace_back((std::min)(a, b), (std::max)(a, b));
    }
  };
  for(const auto& t : soup.triangles) add(t);
  for(const auto& p : soup.polygons) add(p);
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

/*!
  \brief the faces at the edges of a soup: one entry `{i, j, f}` (`i < j`) per side of a face `f` along the
  edge `(i, j)`, sorted.
*/
inline std::vector<std::array<std::size_t, 3> > soup_edge_faces(const Triangle_soup& soup)
{
  std::vector<std::array<std::size_t, 3> > sides;
  const std::size_t nf = number_of_faces(soup);
  for(std::size_t f = 0; f < nf; ++f)
  {
    const auto face = internal::soup_face(soup, f);
    for(std::size_t k = 0; k < face.size(); ++k)
    {
      const std::size_t a = face[k], b = face[(k + 1) % face.size()];
      sides.push_back({(std::min)(a, b), (std::max)(a, b), f});
    }
  }
  std::sort(sides.begin(), sides.end());
  return sides;
}

namespace internal {

// the sides along the edge (a, b) in the sorted table of soup_edge_faces()
inline std::pair<std::vector<std::array<std::size_t, 3> >::const_iterator, std::vector<std::array<std::size_t, 3> >::const_iterator>
sides_along(const std::vector<std::array<std::size_t, 3> >& sides, std::size_t a, std::size_t b)
{
  const std::array<std::size_t, 3> lo = {(std::min)(a, b), (std::max)(a, b), 0},
                                   hi = {(std::min)(a, b), (std::max)(a, b), std::size_t(-1)};
  return {std::lower_bound(sides.begin(), sides.end(), lo), std::upper_bound(sides.begin(), sides.end(), hi)};
}

// Each pair of faces of a dual chain must share an edge: the first pair that does not is refused at the
// line of its record, with the faces numbered as in the file.
inline void check_dual_pairs_adjacent(const Curve_set& cs, const Triangle_soup& soup)
{
  if(cs.dual_pairs.empty()) return;
  const auto sides = soup_edge_faces(soup);
  for(const Curve_dual_pair& d : cs.dual_pairs)
  {
    const auto face = soup_face(soup, d.face_a);
    bool adjacent = false;
    for(std::size_t k = 0; k < face.size() && !adjacent; ++k)
    {
      const auto range = sides_along(sides, face[k], face[(k + 1) % face.size()]);
      for(auto it = range.first; it != range.second; ++it) adjacent = adjacent || (*it)[2] == d.face_b;
    }
    if(!adjacent)
      throw Input_error(cs.file, d.line, "the faces " + std::to_string((long long)(d.face_a) - d.index_offset) + " and " +
                                            std::to_string((long long)(d.face_b) - d.index_offset) +
                                            " of this dual chain record (numbered as in the file) share no edge: "
                                            "consecutive faces of a dual chain must be adjacent");
  }
}

inline bool has_soup_edge(const std::vector<std::pair<std::size_t, std::size_t> >& edges, std::size_t a, std::size_t b)
{
  return std::binary_search(edges.begin(), edges.end(), std::make_pair((std::min)(a, b), (std::max)(a, b)));
}

/// Checks a curve read against a soup: vertex points in range, segments along edges of the soup, dual pairs
/// between faces in range, not empty.
inline void validate_soup_curve_set(const Curve_set& cs, const Triangle_soup& soup,
                                    const std::vector<std::pair<std::size_t, std::size_t> >& edges)
{
  const std::size_t nv = soup.points.size(), nf = number_of_faces(soup);
  for(const Curve_point& p : cs.points)
    if(p.kind != Curve_point::VERTEX || p.element >= nv)
      throw Input_error(cs.file, p.line, p.kind != Curve_point::VERTEX
                                           ? std::string("edge points need an oriented 2-manifold triangle mesh")
                                           : "vertex index " + std::to_string(p.element) + " is out of range (" +
                                               std::to_string(nv) + " vertices)");
  for(const Curve_dual_pair& d : cs.dual_pairs)
    if(d.face_a >= nf || d.face_b >= nf)
      throw Input_error(cs.file, d.line, "face index " + std::to_string((std::max)(d.face_a, d.face_b)) +
                                            " is out of range (" + std::to_string(nf) + " faces)");
  for(const Curve_segment& s : cs.segments)
  {
    const std::size_t a = cs.points[s.a].element, b = cs.points[s.b].element;
    if(a != b && !has_soup_edge(edges, a, b))
      throw Input_error(cs.file, s.line, "the segment from vertex " + std::to_string(a) + " to vertex " +
                                            std::to_string(b) + " is not an edge of the mesh (no face has these "
                                            "two vertices as consecutive corners)");
  }
  check_dual_pairs_adjacent(cs, soup);
  if(cs.segments.empty() && cs.dual_pairs.empty())
    throw Input_error(cs.file, 0, "the curve is empty (no segment)");
}

} // namespace internal

/*!
  \brief reads a curve file (formats as in `read_curve_file()` for meshes) against a polygon soup: vertex
  points, polylines, halfedges and dual chains (`c` records); edge points are an error.
  \throws Input_error on a missing file or any invalid input, with the file's line
*/
inline Curve_set read_curve_file(const std::string& filename, const Triangle_soup& soup,
                                 Curve_file_format format = Curve_file_format::AUTO)
{
  std::ifstream is = internal::open_input_file(filename, "a curve file");
  std::istringstream ss = internal::detect_curve_format(is, filename, format);
  const auto edges = soup_edges(soup);
  const std::size_t nv = soup.points.size();
  Curve_set cs;
  if(format == Curve_file_format::POLYLINES) cs = internal::read_polyline_curves(ss, filename, nv);
  else if(format == Curve_file_format::HALFEDGES)
    cs = internal::read_halfedge_curves(ss, filename, nv, edges.size(),
                                        [&](std::size_t a, std::size_t b) { return internal::has_soup_edge(edges, a, b); });
  else
    cs = internal::read_authors_curves(ss, filename, nv, number_of_faces(soup), 0,
                                       [](std::size_t, int) { return std::size_t(0); });
  internal::validate_soup_curve_set(cs, soup, edges);
  return cs;
}

/*!
  \brief the inline `l` and `c` records of an OBJ file read as a soup, as a `Curve_set` checked against the soup
  (empty if there are none).
*/
inline Curve_set curve_set_from_obj(const Mesh_read_info& info, const Triangle_soup& soup)
{
  Curve_set cs = internal::obj_curve_records(info);
  if(!cs.segments.empty() || !cs.dual_pairs.empty()) internal::validate_soup_curve_set(cs, soup, soup_edges(soup));
  return cs;
}

/*!
  \brief the input of `CGAL::polygon_soup_winding_numbers()`: directed edges (one per traversal) and pairs of
  faces of the dual chain.
*/
struct Soup_curve
{
  /// directed edges (source, target), one entry per traversal
  std::vector<std::pair<std::size_t, std::size_t> > edges;
  /// pairs (a, b) of faces: +1 from a into b
  std::vector<std::pair<std::size_t, std::size_t> > dual_pairs;
};

/*!
  \brief concatenates curve sets checked against a soup into a `Soup_curve` (segments between a vertex and
  itself are skipped).
  \throws Input_error when the curves run along the border of the soup (an edge of one face) with a nonzero
  sum of traversals, at the line of the first segment along that edge: curves may end on the border, not
  run along it
*/
inline Soup_curve soup_curve(const std::vector<Curve_set>& curves, const Triangle_soup& soup)
{
  Soup_curve c;
  std::map<std::pair<std::size_t, std::size_t>, std::pair<long long, std::pair<const Curve_set*, std::size_t> > > on_edge;
  for(const Curve_set& cs : curves)
  {
    for(const Curve_segment& s : cs.segments)
    {
      const std::size_t a = cs.points[s.a].element, b = cs.points[s.b].element;
      if(a == b) continue;
      c.edges.emplace_back(a, b);
      auto& e = on_edge.emplace(std::make_pair((std::min)(a, b), (std::max)(a, b)),
                                std::make_pair(0LL, std::make_pair(&cs, s.line))).first->second;
      e.first += a < b ? 1 : -1;
    }
    for(const Curve_dual_pair& d : cs.dual_pairs) c.dual_pairs.emplace_back(d.face_a, d.face_b);
  }
  const auto sides = soup_edge_faces(soup);
  for(const auto& e : on_edge)
  {
    if(e.second.first == 0) continue;
    const auto range = internal::sides_along(sides, e.first.first, e.first.second);
    if(range.second - range.first == 1)
      throw Input_error(e.second.second.first->file, e.second.second.second,
                        "the curve runs along the edge from vertex " + std::to_string(e.first.first) + " to vertex " +
                            std::to_string(e.first.second) + ", on the border of the mesh (it has one face): curves "
                            "may end on the border but not run along it");
  }
  return c;
}

} // namespace IO
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif // CGAL_SWN_TOOL_IO_SOUP_CURVES_H
