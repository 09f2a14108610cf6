// Copyright (c) 2024 The CGAL Surface_winding_numbers contributors.
// SPDX-License-Identifier: MIT
//
// Writers for the outputs of the `swn` tool: labels, labelled PLY, the authors' w.obj, curve OBJ files.

#ifndef CGAL_SWN_TOOL_IO_WRITE_OUTPUTS_H
#define CGAL_SWN_TOOL_IO_WRITE_OUTPUTS_H

#include "swn_io/atomic_output_dir.h"

#include <CGAL/IO/Color.h>
#include <CGAL/IO/io.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh/IO/PLY.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <limits>
#include <ostream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

/*!
  \file write_outputs.h

  Conventions shared by the writers:
  - faces are written in face-index order, and the vertices of face `f` in the order of
    `vertices_around_face(halfedge(f, mesh), mesh)` (for meshes from `read_mesh()` this is the file order);
  - a corner (vertex v in face f) is identified with the halfedge `h` such that `face(h) == f` and
    `target(h) == v`;
  - a chain is a `std::vector<int>` per edge index, signed w.r.t. the halfedge `2*e` (the halfedge of the
    descriptors of `edges(mesh)`).
  Writers throw `std::runtime_error` when the stream fails, and `std::invalid_argument` on inconsistent sizes.
*/

namespace CGAL {
namespace Surface_winding_numbers {
namespace IO {


namespace internal {

inline void check_stream(std::ostream& os, const char* what)
{
  if(!os)
    throw std::runtime_error(std::string("write error while writing ") + what);
}

template <class Mesh>
void check_mesh_for_writing(const Mesh& m)
{
  if(m.has_garbage())
    throw std::invalid_argument("the mesh has garbage (call collect_garbage() before writing)");
  for(auto f : m.faces())
    if(m.degree(f) != 3)
      throw std::invalid_argument("only triangle meshes can be written");
}

// Gathers output in a 64 KiB buffer and hands it to the stream in large blocks: one `ostream` call per
// number costs more than formatting the number. Numbers are written locale independently, doubles as the
// shortest decimal that reads back to the same value (std::to_chars; "nan" whatever the sign bit, "inf",
// "-inf").
class Output_buffer
{
public:
  explicit Output_buffer(std::ostream& os) : os_(os) { buf_.reserve(capacity + 64); }
  Output_buffer(const Output_buffer&) = delete;
  Output_buffer& operator=(const Output_buffer&) = delete;
  ~Output_buffer() { flush(); }

  Output_buffer& operator<<(std::string_view s) { buf_.append(s.data(), s.size()); return spill(); }
  Output_buffer& operator<<(char c) { buf_ += c; return spill(); }
  template <class Number, class = std::enable_if_t<std::is_arithmetic<Number>::value> >
  Output_buffer& operator<<(Number x)
  {
    if constexpr(std::is_floating_point<Number>::value)
      if(std::isnan(x)) return *this << std::string_view("nan");
    char b[48];
    auto r = std::to_chars(b, b + sizeof(b), x);
    buf_.append(b, r.ptr);
    return spill();
  }
  void flush()
  {
    if(!buf_.empty()) os_.write(buf_.data(), std::streamsize(buf_.size()));
    buf_.clear();
  }

private:
  static constexpr std::size_t capacity = std::size_t(1) << 16;
  Output_buffer& spill() { if(buf_.size() >= capacity) flush(); return *this; }
  std::ostream& os_;
  std::string buf_;
};

// ---- value adapters: a std::vector indexed by the descriptor's index, a callable, or a readable property map
template <class T> struct is_std_vector : std::false_type {};
template <class T, class A> struct is_std_vector<std::vector<T, A> > : std::true_type {};

template <class Map, class Key>
auto value_at(const Map& map, Key k)
{
  if constexpr(is_std_vector<Map>::value)
  {
    if(std::size_t(k) >= map.size())
      throw std::invalid_argument("value vector too short for the mesh");
    return map[std::size_t(k)];
  }
  else if constexpr(std::is_invocable<const Map&, Key>::value)
    return map(k);
  else
    return get(map, k);
}

// the values of `map` on `range` (the faces or the edges of `m`) as ints; a std::vector is taken as is
// (an empty one too, if `empty_ok`)
template <class Range, class Map>
std::vector<int> ints_on(const Range& range, std::size_t size, const Map& map, bool empty_ok, const char* expected)
{
  if constexpr(is_std_vector<Map>::value)
  {
    if(map.size() != size && !(empty_ok && map.empty()))
      throw std::invalid_argument(expected);
    return std::vector<int>(map.begin(), map.end());
  }
  else
  {
    std::vector<int> r;
    r.reserve(size);
    for(auto k : range) r.push_back(static_cast<int>(value_at(map, k)));
    return r;
  }
}

template <class Mesh, class LabelMap>
std::vector<int> face_ints(const Mesh& m, const LabelMap& labels)
{
  return ints_on(m.faces(), m.number_of_faces(), labels, true, "one label per face expected");
}

template <class Mesh, class ChainMap>
std::vector<int> edge_ints(const Mesh& m, const ChainMap& chain)
{
  return ints_on(m.edges(), m.number_of_edges(), chain, false, "one chain value per edge expected");
}

// per-face winding numbers: a std::vector is taken as per-face values; anything else is read per corner
// (halfedge) and averaged over the defined (non-NaN) corners of each face (NaN if none is defined)
template <class Mesh, class WindingMap>
std::vector<double> face_doubles(const Mesh& m, const WindingMap& w)
{
  if constexpr(is_std_vector<WindingMap>::value)
  {
    if(!w.empty() && w.size() != m.number_of_faces())
      throw std::invalid_argument("one winding number per face expected");
    return std::vector<double>(w.begin(), w.end());
  }
  else
  {
    std::vector<double> r;
    r.reserve(m.number_of_faces());
    for(auto f : m.faces())
    {
      double sum = 0;
      int n = 0;
      for(auto h : CGAL::halfedges_around_face(m.halfedge(f), m))
      {
        double x = static_cast<double>(value_at(w, h));
        if(!std::isnan(x)) { sum += x; ++n; }
      }
      r.push_back(n > 0 ? sum / n : std::numeric_limits<double>::quiet_NaN());
    }
    return r;
  }
}

} // namespace internal


/*!
  \brief writes `text` to the file `path` (binary mode, no newline translation).
  \throws std::runtime_error if the file cannot be written
*/
inline void write_text_file(const std::string& path, const std::string& text)
{
  internal::write_to_path(path, [&](std::ostream& os) { os << text; });
}

/*!
  \brief writes one integer label per line, in face-index order.
  \param os the stream written to
  \param mesh the mesh whose faces are labelled
  \param labels the labels per face: a `std::vector<int>` indexed by face index, a readable property map
  (face descriptor -> integer) or a callable `int(face_descriptor)`
*/
template <class Point, class LabelMap>
void write_labels(std::ostream& os, const CGAL::Surface_mesh<Point>& mesh, const LabelMap& labels)
{
  std::vector<int> l = internal::face_ints(mesh, labels);
  if(l.size() != mesh.number_of_faces())
    throw std::invalid_argument("write_labels: one label per face expected");
  internal::Output_buffer out(os);
  for(int x : l) out << x << '\n';
  out.flush();
  internal::check_stream(os, "labels");
}

/*!
  \brief writes the labels file `path`; see the stream overload.
*/
template <class Point, class LabelMap>
void write_labels(const std::string& path, const CGAL::Surface_mesh<Point>& mesh, const LabelMap& labels)
{
  internal::write_to_path(path, [&](std::ostream& os) { write_labels(os, mesh, labels); });
}

/*!
  \brief returns the colour of a label in a fixed qualitative palette (ten colours, cycled; label `l` and
  `l+1` always differ; the colour of a label never depends on the other labels).
*/
inline std::array<unsigned char, 3> label_color(int label)
{
  static const unsigned char palette[10][3] = {
    {78, 121, 167}, {242, 142, 43}, {225, 87, 89}, {118, 183, 178}, {89, 161, 79},
    {237, 201, 72}, {176, 122, 161}, {255, 157, 167}, {156, 117, 95}, {186, 176, 172}};
  long long m = static_cast<long long>(label) % 10;
  if(m < 0) m += 10;
  return {palette[m][0], palette[m][1], palette[m][2]};
}

/*!
  \brief writes the mesh as PLY with per-face `int label`, `float winding_number` and
  `uchar red, green, blue, alpha` (from `label_color()`), readable by MeshLab, with `CGAL::IO::write_PLY()`.

  Vertex coordinates are written as `double`. NaN winding numbers are written as NaN.
  \param os the stream written to (open it in binary mode for the binary format)
  \param mesh the mesh written
  \param label_map per-face labels: a `std::vector<int>` (may be empty: no label and colour properties), a
  readable property map (face descriptor -> integer) or a callable
  \param winding_map either a `std::vector<double>` of per-face values (may be empty: no `winding_number`
  property), or per-corner values (a readable property map or callable keyed by halfedge, the corner
  `(target(h), face(h))`), averaged over the defined (non-NaN) corners of each face
  \param binary `binary_little_endian` if true (the default: compact, exact NaN), ASCII otherwise (17
  significant digits); open the stream in binary mode. In ASCII, NaN is written as `nan`, which some readers
  (e.g. CGAL's) reject.
  \param confidence per face index (may be empty: not written): the per-face properties `float confidence`
  (the flip cost of the face's region, `inf` where no flip is feasible) and `int region` (its region)
  \param region per face index, the region (written with `confidence`)
*/
template <class Point, class LabelMap, class WindingMap>
void write_labeled_ply(std::ostream& os, const CGAL::Surface_mesh<Point>& mesh, const LabelMap& label_map,
                       const WindingMap& winding_map, bool binary = true,
                       const std::vector<double>& confidence = std::vector<double>(),
                       const std::vector<std::size_t>& region = std::vector<std::size_t>())
{
  typedef CGAL::Surface_mesh<Point> Mesh;
  typedef typename Mesh::Face_index Face_index;
  internal::check_mesh_for_writing(mesh);
  const std::vector<int> labels = internal::face_ints(mesh, label_map);
  const std::vector<double> winding_numbers = internal::face_doubles(mesh, winding_map);
  const std::size_t nf = mesh.number_of_faces();
  if(!labels.empty() && labels.size() != nf)
    throw std::invalid_argument("write_labeled_ply: one label per face expected");
  if(!winding_numbers.empty() && winding_numbers.size() != nf)
    throw std::invalid_argument("write_labeled_ply: one winding number per face expected");
  if(!confidence.empty() && (confidence.size() != nf || region.size() != nf))
    throw std::invalid_argument("write_labeled_ply: one confidence and one region per face expected");
  // write_PLY() writes every property of a Surface_mesh whose type it knows: a copy keeps the connectivity
  // and the points only (CGAL 5.5's assign() does not compile) and gets the face properties, in the
  // order of the header
  Mesh out(mesh);
  out.remove_all_property_maps();
  if(!labels.empty())
  {
    auto l = out.template add_property_map<Face_index, std::int32_t>("f:label", 0).first;
    for(Face_index f : out.faces()) l[f] = labels[std::size_t(f)];
  }
  if(!winding_numbers.empty())
  {
    auto w = out.template add_property_map<Face_index, float>("f:winding_number", 0.f).first;
    for(Face_index f : out.faces()) w[f] = static_cast<float>(winding_numbers[std::size_t(f)]);
  }
  if(!confidence.empty())
  {
    auto c = out.template add_property_map<Face_index, float>("f:confidence", 0.f).first;
    auto r = out.template add_property_map<Face_index, std::int32_t>("f:region", 0).first;
    for(Face_index f : out.faces())
    {
      c[f] = static_cast<float>(confidence[std::size_t(f)]);
      r[f] = static_cast<std::int32_t>(region[std::size_t(f)]);
    }
  }
  if(!labels.empty())
  {
    auto c = out.template add_property_map<Face_index, CGAL::IO::Color>("f:color").first;
    for(Face_index f : out.faces())
    {
      const auto rgb = label_color(labels[std::size_t(f)]);
      c[f] = CGAL::IO::Color(rgb[0], rgb[1], rgb[2]);
    }
  }
  const CGAL::IO::Mode mode = CGAL::IO::get_mode(os);
  const std::streamsize precision = os.precision();
  CGAL::IO::set_mode(os, binary ? CGAL::IO::BINARY : CGAL::IO::ASCII);
  const bool ok = CGAL::IO::write_PLY(os, out, "written by CGAL Surface_winding_numbers",
                                      CGAL::parameters::stream_precision(17));
  CGAL::IO::set_mode(os, mode);
  os.precision(precision);
  if(!ok)
    throw std::runtime_error("write error while writing PLY");
  internal::check_stream(os, "PLY");
}

/*!
  \brief writes the PLY file `path`; see the stream overload.
*/
template <class Point, class LabelMap, class WindingMap>
void write_labeled_ply(const std::string& path, const CGAL::Surface_mesh<Point>& mesh, const LabelMap& labels,
                       const WindingMap& winding, bool binary = true,
                       const std::vector<double>& confidence = std::vector<double>(),
                       const std::vector<std::size_t>& region = std::vector<std::size_t>())
{
  internal::write_to_path(path, [&](std::ostream& os) {
    write_labeled_ply(os, mesh, labels, winding, binary, confidence, region);
  });
}

/*!
  \brief writes the authors' winding-number OBJ (notes section 5.4): a comment header with the counts,
  `v x y z` lines (shortest decimals that read back to the same doubles), one `vt w 1` line per corner (`vt 0 0` where w is NaN, i.e.
  undefined), and `f i/t/ j/t/ k/t/` lines (1-based vertex and corner indices). Corners are numbered in face
  order and, within a face, in the order of `vertices_around_face(halfedge(f))`.

  \param os the stream written to
  \param mesh the mesh written
  \param corner_value w at the corner `(target(h), face(h))` of halfedge `h`: a `std::vector<double>` indexed by
  halfedge index, a readable property map (halfedge descriptor -> double) or a callable `double(halfedge)`
*/
template <class Point, class CornerMap>
void write_w_obj(std::ostream& os, const CGAL::Surface_mesh<Point>& mesh, const CornerMap& corner_value)
{
  if constexpr(internal::is_std_vector<CornerMap>::value)
    if(corner_value.size() < mesh.number_of_halfedges())
      throw std::invalid_argument("write_w_obj: one value per halfedge expected");
  internal::check_mesh_for_writing(mesh);
  os << "# Mesh exported from CGAL Surface_winding_numbers\n"
     << "#  vertices: " << mesh.number_of_vertices() << "\n"
     << "#     edges: " << mesh.number_of_edges() << "\n"
     << "#     faces: " << mesh.number_of_faces() << "\n"
     << "# texture coordinates: YES\n";
  internal::Output_buffer out(os);
  for(auto v : mesh.vertices())
  {
    const Point& p = mesh.point(v);
    out << "v " << CGAL::to_double(p.x()) << ' ' << CGAL::to_double(p.y()) << ' '
        << CGAL::to_double(p.z()) << '\n';
  }
  // one walk around the faces (the halfedges of a large mesh are scattered in memory): the corner
  // values are written at once, the corners' vertices kept for the face lines
  std::vector<std::size_t> corner_vertex;
  corner_vertex.reserve(3 * std::size_t(mesh.number_of_faces()));
  for(auto f : mesh.faces())
  {
    auto h = mesh.halfedge(f);
    for(int k = 0; k < 3; ++k, h = mesh.next(h))
    {
      corner_vertex.push_back(std::size_t(mesh.target(h)));
      const double w = static_cast<double>(internal::value_at(corner_value, h));
      if(std::isnan(w)) out << "vt 0 0\n";
      else out << "vt " << w << " 1\n";
    }
  }
  for(std::size_t c = 0; c < corner_vertex.size(); c += 3)
  {
    out << 'f';
    for(std::size_t k = c; k < c + 3; ++k) out << ' ' << corner_vertex[k] + 1 << '/' << k + 1 << '/';
    out << '\n';
  }
  out.flush();
  internal::check_stream(os, "w.obj");
}

/*!
  \brief writes the w.obj file `path`; see the stream overload.
*/
template <class Point, class CornerMap>
void write_w_obj(const std::string& path, const CGAL::Surface_mesh<Point>& mesh, const CornerMap& corner_value)
{
  internal::write_to_path(path, [&](std::ostream& os) { write_w_obj(os, mesh, corner_value); });
}

/*!
  \brief decomposes an integer edge chain into long directed polylines (vertex index lists).

  The chain is a `std::vector<int>` indexed by edge index, a readable property map (edge descriptor -> int) or
  a callable, signed w.r.t. the halfedge `2*e`.

  Every edge `e` is traversed |chain[e]| times, in the direction of its sign. Open trails are started, in
  vertex-index order, at the vertices with more outgoing than incoming chain and followed greedily (first
  outgoing halfedge with chain left, in `halfedges_around_source` order) until they get stuck; the remaining
  (balanced) chain is then decomposed into closed circuits (Hierholzer), each spliced into an earlier polyline
  through a shared vertex when there is one. Closed polylines repeat their first vertex at the end.
*/
template <class Point, class ChainMap>
std::vector<std::vector<std::size_t> > chain_to_polylines(const CGAL::Surface_mesh<Point>& mesh,
                                                          const ChainMap& chain_map)
{
  const std::vector<int> chain = internal::edge_ints(mesh, chain_map);
  typedef CGAL::Surface_mesh<Point> Mesh;
  typedef typename Mesh::Halfedge_index Halfedge_index;
  typedef typename Mesh::Vertex_index Vertex_index;
  if(chain.size() != mesh.number_of_edges())
    throw std::invalid_argument("chain_to_polylines: one chain value per edge expected");
  const std::size_t nv = mesh.number_of_vertices();
  std::vector<long long> rem(mesh.number_of_halfedges(), 0);
  std::vector<long long> out(nv, 0), in(nv, 0);
  for(auto e : mesh.edges())
  {
    int c = chain[std::size_t(e)];
    if(c == 0) continue;
    Halfedge_index h = mesh.halfedge(typename Mesh::Edge_index(static_cast<typename Mesh::size_type>(std::size_t(e))));
    if(c < 0) h = mesh.opposite(h);
    long long m = c < 0 ? -static_cast<long long>(c) : c;
    rem[std::size_t(h)] = m;
    out[std::size_t(mesh.source(h))] += m;
    in[std::size_t(mesh.target(h))] += m;
  }
  auto next_out = [&](std::size_t v) -> Halfedge_index {
    if(out[v] == 0) return Halfedge_index();
    for(Halfedge_index h : CGAL::halfedges_around_source(Vertex_index(static_cast<typename Mesh::size_type>(v)), mesh))
      if(rem[std::size_t(h)] > 0) return h;
    return Halfedge_index();
  };
  auto take = [&](Halfedge_index h) {
    --rem[std::size_t(h)];
    --out[std::size_t(mesh.source(h))];
    --in[std::size_t(mesh.target(h))];
    return std::size_t(mesh.target(h));
  };
  auto circuit = [&](std::size_t v) {
    std::vector<std::size_t> stack{v}, cyc;
    while(!stack.empty())
    {
      Halfedge_index h = next_out(stack.back());
      if(h != Halfedge_index()) stack.push_back(take(h));
      else { cyc.push_back(stack.back()); stack.pop_back(); }
    }
    std::reverse(cyc.begin(), cyc.end());
    return cyc;
  };
  std::vector<std::vector<std::size_t> > pieces;
  for(std::size_t v = 0; v < nv; ++v)
    while(out[v] > in[v])
    {
      std::vector<std::size_t> trail{v};
      std::size_t u = v;
      for(Halfedge_index h = next_out(u); h != Halfedge_index(); h = next_out(u))
        trail.push_back(u = take(h));
      pieces.push_back(std::move(trail));
    }
  auto splice_all = [&](std::vector<std::size_t>& piece) {
    for(std::size_t i = 0; i < piece.size(); ++i)
      if(out[piece[i]] > 0)
      {
        std::vector<std::size_t> c = circuit(piece[i]);
        piece.insert(piece.begin() + static_cast<std::ptrdiff_t>(i) + 1, c.begin() + 1, c.end());
      }
  };
  for(auto& piece : pieces) splice_all(piece);
  for(std::size_t v = 0; v < nv; ++v)
    if(out[v] > 0)
    {
      pieces.push_back(circuit(v));
      splice_all(pieces.back());
    }
  return pieces;
}

/*!
  \brief writes an integer edge chain as an OBJ curve file: `v` lines, then one `l` line per polyline of
  `chain_to_polylines()` (1-based; multiplicity kept: an edge with value 2 is traversed twice).

  Coordinates are written in the shortest form that reads back exactly.
  \param os the stream written to
  \param mesh the mesh the chain lives on
  \param chain the integer value per edge (see `chain_to_polylines()` for the accepted kinds of maps)
  \param all_vertices if true every mesh vertex is written, so that `l` indices are the mesh's 1-based vertex
  indices; if false (default) only the vertices used by the chain are written, in increasing mesh index order,
  and a comment line `# mesh vertices: i1 i2 ...` gives their 0-based mesh indices.
*/
template <class Point, class ChainMap>
void write_chain_obj(std::ostream& os, const CGAL::Surface_mesh<Point>& mesh, const ChainMap& chain,
                     bool all_vertices = false)
{
  auto pieces = chain_to_polylines(mesh, chain);
  const std::size_t nv = mesh.number_of_vertices();
  std::vector<std::size_t> index(nv, 0);
  std::size_t count = 0;
  if(all_vertices)
    for(std::size_t v = 0; v < nv; ++v) index[v] = ++count;
  else
  {
    std::vector<char> used(nv, 0);
    for(const auto& p : pieces) for(std::size_t v : p) used[v] = 1;
    for(std::size_t v = 0; v < nv; ++v) if(used[v]) index[v] = ++count;
  }
  std::size_t nedges = 0;
  for(const auto& p : pieces) nedges += p.size() - 1;
  internal::Output_buffer out(os);
  out << "# curve written by CGAL Surface_winding_numbers: " << pieces.size() << " polylines, " << nedges
      << " edges (with multiplicity)\n";
  if(!all_vertices)
  {
    out << "# mesh vertices:";
    for(std::size_t v = 0; v < nv; ++v) if(index[v] != 0) out << ' ' << v;
    out << '\n';
  }
  for(auto v : mesh.vertices())
  {
    if(index[std::size_t(v)] == 0) continue;
    const Point& p = mesh.point(v);
    out << "v " << CGAL::to_double(p.x()) << ' ' << CGAL::to_double(p.y()) << ' ' << CGAL::to_double(p.z()) << '\n';
  }
  for(const auto& p : pieces)
  {
    out << 'l';
    for(std::size_t v : p) out << ' ' << index[v];
    out << '\n';
  }
  out.flush();
  internal::check_stream(os, "curve OBJ");
}

/*!
  \brief writes the curve OBJ file `path`; see the stream overload.
*/
template <class Point, class ChainMap>
void write_chain_obj(const std::string& path, const CGAL::Surface_mesh<Point>& mesh, const ChainMap& chain,
                     bool all_vertices = false)
{
  internal::write_to_path(path, [&](std::ostream& os) { write_chain_obj(os, mesh, chain, all_vertices); });
}

} // namespace IO
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif // CGAL_SWN_TOOL_IO_WRITE_OUTPUTS_H
