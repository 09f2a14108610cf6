// Soup-level chains and FaceListGraphs built from the soups of soup_generators.h, for the Surface
// Winding Numbers oracle tests. Meshes are built with CGAL::Polygon_mesh_processing::
// polygon_soup_to_polygon_mesh into any FaceListGraph (Surface_mesh, Polyhedron_3); Built_mesh keeps the
// soup index <-> descriptor maps.

#ifndef SWN_TEST_MESH_GENERATORS_H
#define SWN_TEST_MESH_GENERATORS_H

#include "soup_generators.h"

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

namespace swn_test {

// ------------------------------------------------------------------------------------------
// Soup-level chains: integer 1-chains keyed by the undirected soup edge {a,b}, a < b, with the
// value counted along a -> b. They are independent of the mesh data structure and of its
// edge orientation, so expected and computed chains can be compared directly.
// ------------------------------------------------------------------------------------------

using Edge_key = std::pair<Index, Index>;
using Soup_chain = std::map<Edge_key, int>;

inline Edge_key edge_key(Index a, Index b) { return a < b ? Edge_key(a, b) : Edge_key(b, a); }

inline void add_segment(Soup_chain& c, Index a, Index b, int m = 1)
{
  if(a == b) throw std::invalid_argument("add_segment: degenerate segment");
  int& v = c[edge_key(a, b)];
  v += (a < b) ? m : -m;
  if(v == 0) c.erase(edge_key(a, b));
}

// Open polyline p0 -> p1 -> ... -> p_{n-1}.
inline void add_path(Soup_chain& c, const std::vector<Index>& path, int m = 1)
{
  for(std::size_t k = 0; k + 1 < path.size(); ++k) add_segment(c, path[k], path[k + 1], m);
}

// Closed loop l0 -> l1 -> ... -> l_{n-1} -> l0 (first vertex not repeated).
inline void add_loop(Soup_chain& c, const std::vector<Index>& loop, int m = 1)
{
  for(std::size_t k = 0; k < loop.size(); ++k) add_segment(c, loop[k], loop[(k + 1) % loop.size()], m);
}

// The loop with `gap` consecutive edges removed, starting with the edge (l[start], l[start+1]):
// returned as the open path l[start+gap] -> ... -> l[start] (indices mod n).
inline std::vector<Index> loop_with_gap(const std::vector<Index>& loop, std::size_t start, std::size_t gap)
{
  const std::size_t n = loop.size();
  std::vector<Index> p;
  for(std::size_t k = 0; k + gap <= n; ++k) p.push_back(loop[(start + gap + k) % n]);
  return p;
}

// The path with `gap` consecutive edges removed, starting with edge (p[start], p[start+1]):
// returned as two open paths.
inline std::pair<std::vector<Index>, std::vector<Index>> path_with_gap(const std::vector<Index>& path,
                                                                       std::size_t start, std::size_t gap)
{
  std::vector<Index> a(path.begin(), path.begin() + start + 1);
  std::vector<Index> b(path.begin() + start + gap, path.end());
  return {a, b};
}

inline std::vector<Index> reversed(std::vector<Index> p) { std::reverse(p.begin(), p.end()); return p; }

inline Soup_chain scaled(const Soup_chain& c, int m)
{
  Soup_chain r;
  if(m == 0) return r;
  for(const auto& kv : c) r[kv.first] = kv.second * m;
  return r;
}

inline Soup_chain sum(const Soup_chain& a, const Soup_chain& b)
{
  Soup_chain r = a;
  for(const auto& kv : b)
  {
    int& v = r[kv.first];
    v += kv.second;
    if(v == 0) r.erase(kv.first);
  }
  return r;
}

inline Soup_chain difference(const Soup_chain& a, const Soup_chain& b) { return sum(a, scaled(b, -1)); }

// Boundary 0-chain: arrivals minus departures, per vertex (only nonzero entries).
inline std::map<Index, int> boundary(const Soup_chain& c)
{
  std::map<Index, int> d;
  for(const auto& kv : c) { d[kv.first.second] += kv.second; d[kv.first.first] -= kv.second; }
  for(auto it = d.begin(); it != d.end();) it = (it->second == 0) ? d.erase(it) : std::next(it);
  return d;
}

inline std::string to_string(const Soup_chain& c)
{
  std::string s = "{";
  for(const auto& kv : c)
    s += " (" + std::to_string(kv.first.first) + "->" + std::to_string(kv.first.second) + "):" + std::to_string(kv.second);
  return s + " }";
}

// ------------------------------------------------------------------------------------------
// Building a FaceListGraph from a soup, with soup index <-> descriptor maps.
// ------------------------------------------------------------------------------------------

template <class TM>
struct Built_mesh
{
  using GT = boost::graph_traits<TM>;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using edge_descriptor = typename GT::edge_descriptor;
  using face_descriptor = typename GT::face_descriptor;

  TM tm;
  Soup soup;
  std::vector<vertex_descriptor> vertex;                // soup vertex -> descriptor
  std::vector<face_descriptor> face;                    // soup triangle -> descriptor
  std::unordered_map<vertex_descriptor, Index> vindex;  // descriptor -> soup vertex
  std::unordered_map<face_descriptor, Index> findex;    // descriptor -> soup triangle
  bool vertex_order_preserved = false;                  // soup order == vertices(tm) order
  bool face_order_preserved = false;                    // soup order == faces(tm) order
  // Reference halfedge of each edge: halfedge(e, tm) for the descriptor e met while iterating
  // over edges(tm). (CGAL 5.5's Surface_mesh::Edge_index stores a halfedge, so
  // halfedge(edge(h, tm), tm) == h for both halfedges of an edge: only descriptors coming from
  // edges(tm) give the reference direction.)
  std::unordered_map<halfedge_descriptor, bool> is_reference;

  Built_mesh() = default;
  Built_mesh(const Built_mesh&) = delete;               // descriptors point into tm
  Built_mesh& operator=(const Built_mesh&) = delete;

  // The soup edge key of a mesh edge, and the sign that converts a value along halfedge(e)
  // into a value along key.first -> key.second.
  std::pair<Edge_key, int> key(edge_descriptor e) const
  {
    halfedge_descriptor h = reference_halfedge(e);
    const Index s = vindex.at(source(h, tm)), t = vindex.at(target(h, tm));
    return {edge_key(s, t), s < t ? 1 : -1};
  }

  halfedge_descriptor reference_halfedge(edge_descriptor e) const
  {
    halfedge_descriptor h = halfedge(e, tm);
    return is_reference.at(h) ? h : opposite(h, tm);
  }

  // +1 if h is the reference halfedge of its edge, -1 otherwise
  int sign(halfedge_descriptor h) const { return is_reference.at(h) ? 1 : -1; }

  halfedge_descriptor halfedge_of(Index a, Index b) const
  {
    auto r = halfedge(vertex.at(a), vertex.at(b), tm);   // halfedge a -> b
    if(!r.second) throw std::invalid_argument("soup vertices " + std::to_string(a) + " and " + std::to_string(b) + " are not adjacent");
    return r.first;
  }
};

// Builds `out` from `soup`. Throws std::runtime_error if the soup is not a valid polygon mesh
// or if the soup <-> mesh correspondence cannot be established.
template <class TM>
void build(const Soup& soup, Built_mesh<TM>& out)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  using BM = Built_mesh<TM>;
  using vertex_descriptor = typename BM::vertex_descriptor;
  using face_descriptor = typename BM::face_descriptor;

  out.soup = soup;
  std::vector<std::vector<Index>> polys = soup.polygons();
  if(!PMP::is_polygon_soup_a_polygon_mesh(polys)) throw std::runtime_error("soup is not a polygon mesh");
  PMP::polygon_soup_to_polygon_mesh(soup.points, polys, out.tm);
  if(num_vertices(out.tm) != soup.points.size() || num_faces(out.tm) != soup.triangles.size())
    throw std::runtime_error("polygon_soup_to_polygon_mesh changed the element counts");

  auto vpm = get(CGAL::vertex_point, out.tm);
  // vertices: insertion order is expected to be preserved; verify on coordinates, fall back
  // to a coordinate lookup (all soup points are distinct in our generators) otherwise.
  out.vertex.clear();
  out.vertex_order_preserved = true;
  {
    Index i = 0;
    for(vertex_descriptor v : vertices(out.tm))
    {
      if(i >= soup.points.size() || get(vpm, v) != soup.points[i]) out.vertex_order_preserved = false;
      out.vertex.push_back(v);
      ++i;
    }
  }
  if(!out.vertex_order_preserved)
  {
    std::map<Point_3, Index> by_point;
    for(Index i = 0; i < soup.points.size(); ++i)
      if(!by_point.emplace(soup.points[i], i).second) throw std::runtime_error("duplicate soup points");
    std::vector<vertex_descriptor> vs(soup.points.size());
    for(vertex_descriptor v : vertices(out.tm)) vs.at(by_point.at(get(vpm, v))) = v;
    out.vertex = vs;
  }
  out.vindex.clear();
  for(Index i = 0; i < out.vertex.size(); ++i) out.vindex[out.vertex[i]] = i;

  out.is_reference.clear();
  for(auto e : edges(out.tm))
  {
    out.is_reference[halfedge(e, out.tm)] = true;
    out.is_reference[opposite(halfedge(e, out.tm), out.tm)] = false;
  }

  // faces: match on the cyclic vertex sequence (this also checks the orientation).
  std::map<std::array<Index, 3>, Index> by_cycle;
  auto canonical = [](std::array<Index, 3> t) {
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    return t;
  };
  for(Index f = 0; f < soup.triangles.size(); ++f) by_cycle[canonical(soup.triangles[f])] = f;
  out.face.assign(soup.triangles.size(), face_descriptor());
  out.findex.clear();
  out.face_order_preserved = true;
  Index count = 0;
  for(face_descriptor f : faces(out.tm))
  {
    std::array<Index, 3> t;
    int k = 0;
    for(vertex_descriptor v : vertices_around_face(halfedge(f, out.tm), out.tm))
    {
      if(k == 3) throw std::runtime_error("non-triangle face");
      t[k++] = out.vindex.at(v);
    }
    auto it = by_cycle.find(canonical(t));
    if(it == by_cycle.end()) throw std::runtime_error("mesh face not found in soup (orientation flipped?)");
    if(it->second != count) out.face_order_preserved = false;
    out.face[it->second] = f;
    out.findex[f] = it->second;
    ++count;
  }
  if(out.findex.size() != soup.triangles.size()) throw std::runtime_error("face correspondence incomplete");
}

} // namespace swn_test

#endif // SWN_TEST_MESH_GENERATORS_H
