// Copyright (c) 2024 The CGAL Surface_winding_numbers contributors.
// SPDX-License-Identifier: MIT
//
// Writers for the outputs of the `swn` tool: labels, labelled PLY, the authors' w.obj, curve OBJ files, an
// all-or-nothing output directory and a tiny JSON writer.

#ifndef CGAL_SURFACE_WINDING_NUMBERS_IO_WRITE_OUTPUTS_H
#define CGAL_SURFACE_WINDING_NUMBERS_IO_WRITE_OUTPUTS_H

#include <CGAL/Surface_mesh.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <locale>
#include <ostream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <type_traits>
#include <utility>
#include <variant>
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

/// \cond SKIP_IN_MANUAL
namespace internal {

inline void check_stream(std::ostream& os, const char* what)
{
  if(!os)
    throw std::runtime_error(std::string("write error while writing ") + what);
}

template <class Mesh>
std::array<std::size_t, 3> face_vertices(const Mesh& m, typename Mesh::Face_index f)
{
  auto h = m.halfedge(f);
  std::array<std::size_t, 3> r;
  for(int k = 0; k < 3; ++k) { r[k] = std::size_t(m.target(h)); h = m.next(h); }
  return r;
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
// "-inf"), binary values little endian.
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
  template <class T>
  void put_le(T value)
  {
    unsigned char b[sizeof(T)];
    std::memcpy(b, &value, sizeof(T));
    const std::uint16_t probe = 1;   // host to little endian
    unsigned char first;
    std::memcpy(&first, &probe, 1);
    if(first == 0) std::reverse(b, b + sizeof(T));
    buf_.append(reinterpret_cast<const char*>(b), sizeof(T));
    spill();
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

template <class Mesh, class LabelMap>
std::vector<int> face_ints(const Mesh& m, const LabelMap& labels)
{
  if constexpr(is_std_vector<LabelMap>::value)
  {
    if(!labels.empty() && labels.size() != m.number_of_faces())
      throw std::invalid_argument("one label per face expected");
    return std::vector<int>(labels.begin(), labels.end());
  }
  else
  {
    std::vector<int> r;
    r.reserve(m.number_of_faces());
    for(auto f : m.faces()) r.push_back(static_cast<int>(value_at(labels, f)));
    return r;
  }
}

template <class Mesh, class ChainMap>
std::vector<int> edge_ints(const Mesh& m, const ChainMap& chain)
{
  if constexpr(is_std_vector<ChainMap>::value)
  {
    if(chain.size() != m.number_of_edges())
      throw std::invalid_argument("one chain value per edge expected");
    return std::vector<int>(chain.begin(), chain.end());
  }
  else
  {
    std::vector<int> r;
    r.reserve(m.number_of_edges());
    for(auto e : m.edges()) r.push_back(static_cast<int>(value_at(chain, e)));
    return r;
  }
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

template <class Writer>
void write_to_path(const std::string& path, Writer&& writer)
{
  std::ofstream os(path, std::ios::binary | std::ios::trunc);
  if(!os)
    throw std::runtime_error("cannot open " + path + " for writing");
  writer(static_cast<std::ostream&>(os));
  os.flush();
  if(!os)
    throw std::runtime_error("write error on " + path);
  os.close();
  if(os.fail())
    throw std::runtime_error("write error on " + path);
}

} // namespace internal
/// \endcond

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
  `uchar red, green, blue` (from `label_color()`), readable by MeshLab.

  Vertex coordinates are written as `double`. NaN winding numbers are written as NaN.
  \param os the stream written to (open it in binary mode for the binary format)
  \param mesh the mesh written
  \param label_map per-face labels: a `std::vector<int>` (may be empty: no label and colour properties), a
  readable property map (face descriptor -> integer) or a callable
  \param winding_map either a `std::vector<double>` of per-face values (may be empty: no `winding_number`
  property), or per-corner values (a readable property map or callable keyed by halfedge, the corner
  `(target(h), face(h))`), averaged over the defined (non-NaN) corners of each face
  \param binary `binary_little_endian` if true (the default: compact, exact NaN), ASCII otherwise; open the
  stream in binary mode. In ASCII, NaN is written as `nan`, which some readers (e.g. CGAL's) reject.
*/
template <class Point, class LabelMap, class WindingMap>
void write_labeled_ply(std::ostream& os, const CGAL::Surface_mesh<Point>& mesh, const LabelMap& label_map,
                       const WindingMap& winding_map, bool binary = true)
{
  internal::check_mesh_for_writing(mesh);
  const std::vector<int> labels = internal::face_ints(mesh, label_map);
  const std::vector<double> face_winding_numbers = internal::face_doubles(mesh, winding_map);
  const std::size_t nf = mesh.number_of_faces();
  if(!labels.empty() && labels.size() != nf)
    throw std::invalid_argument("write_labeled_ply: one label per face expected");
  if(!face_winding_numbers.empty() && face_winding_numbers.size() != nf)
    throw std::invalid_argument("write_labeled_ply: one winding number per face expected");
  const bool has_l = !labels.empty(), has_w = !face_winding_numbers.empty();
  os << "ply\nformat " << (binary ? "binary_little_endian" : "ascii") << " 1.0\n"
     << "comment written by CGAL Surface_winding_numbers\n"
     << "element vertex " << mesh.number_of_vertices() << "\n"
     << "property double x\nproperty double y\nproperty double z\n"
     << "element face " << nf << "\n"
     << "property list uchar int vertex_indices\n";
  if(has_l) os << "property int label\n";
  if(has_w) os << "property float winding_number\n";
  if(has_l) os << "property uchar red\nproperty uchar green\nproperty uchar blue\n";
  os << "end_header\n";
  internal::Output_buffer out(os);
  if(binary)
  {
    for(auto v : mesh.vertices())
    {
      const Point& p = mesh.point(v);
      out.put_le<double>(CGAL::to_double(p.x()));
      out.put_le<double>(CGAL::to_double(p.y()));
      out.put_le<double>(CGAL::to_double(p.z()));
    }
    for(auto f : mesh.faces())
    {
      auto t = internal::face_vertices(mesh, f);
      out.put_le<std::uint8_t>(3);
      for(std::size_t k : t) out.put_le<std::int32_t>(static_cast<std::int32_t>(k));
      if(has_l) out.put_le<std::int32_t>(labels[std::size_t(f)]);
      if(has_w) out.put_le<float>(static_cast<float>(face_winding_numbers[std::size_t(f)]));
      if(has_l)
      {
        auto c = label_color(labels[std::size_t(f)]);
        for(int k = 0; k < 3; ++k) out.put_le<std::uint8_t>(c[k]);
      }
    }
  }
  else
  {
    for(auto v : mesh.vertices())
    {
      const Point& p = mesh.point(v);
      out << CGAL::to_double(p.x()) << ' ' << CGAL::to_double(p.y()) << ' '
          << CGAL::to_double(p.z()) << '\n';
    }
    for(auto f : mesh.faces())
    {
      auto t = internal::face_vertices(mesh, f);
      out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2];
      if(has_l) out << ' ' << labels[std::size_t(f)];
      if(has_w)
      {
        out << ' ' << static_cast<float>(face_winding_numbers[std::size_t(f)]);
      }
      if(has_l)
      {
        auto c = label_color(labels[std::size_t(f)]);
        out << ' ' << int(c[0]) << ' ' << int(c[1]) << ' ' << int(c[2]);
      }
      out << '\n';
    }
  }
  out.flush();
  internal::check_stream(os, "PLY");
}

/*!
  \brief writes the PLY file `path`; see the stream overload.
*/
template <class Point, class LabelMap, class WindingMap>
void write_labeled_ply(const std::string& path, const CGAL::Surface_mesh<Point>& mesh, const LabelMap& labels,
                       const WindingMap& winding, bool binary = true)
{
  internal::write_to_path(path, [&](std::ostream& os) { write_labeled_ply(os, mesh, labels, winding, binary); });
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

/*!
  \brief an output directory written all-or-nothing.

  Every file is first written to a hidden temporary name inside the target directory (created, with its
  missing parents, by the constructor). `commit()` renames all of them into place. If the object is destroyed
  without `commit()` (an exception, an early return), the temporaries are removed, and so are the directories
  the constructor created if they are empty, so that a failed run leaves nothing behind. Renames within one
  directory are atomic per file; if a rename fails in `commit()`, the files renamed before it stay.
*/
class Atomic_output_dir
{
public:
  /// \brief prepares `dir`, creating it (and missing parents) if needed.
  /// \throws std::runtime_error if it cannot be created or is not a directory
  explicit Atomic_output_dir(const std::string& dir) : dir_(dir.empty() ? std::string(".") : dir)
  {
    namespace fs = std::filesystem;
    std::error_code ec;
    fs::path p = fs::absolute(dir_, ec);
    if(ec) p = dir_;
    std::vector<fs::path> missing;
    for(fs::path q = p; !q.empty() && !fs::exists(q, ec); q = q.parent_path())
    {
      missing.push_back(q);
      if(q == q.parent_path()) break;
    }
    for(auto it = missing.rbegin(); it != missing.rend(); ++it)
    {
      bool made = fs::create_directory(*it, ec);
      if(!made && !fs::is_directory(*it, ec))
      {
        cleanup_dirs();
        throw std::runtime_error("cannot create output directory " + it->string());
      }
      if(made) created_.push_back(*it);
    }
    if(!fs::is_directory(dir_, ec))
      throw std::runtime_error("output path " + dir_.string() + " is not a directory");
    std::random_device rd;
    std::uniform_int_distribution<unsigned long long> dist;
    std::ostringstream s;
    s << std::hex << (dist(rd) & 0xffffffffffffULL);
    tag_ = s.str();
  }

  Atomic_output_dir(const Atomic_output_dir&) = delete;
  Atomic_output_dir& operator=(const Atomic_output_dir&) = delete;

  /// \brief removes the temporaries if `commit()` was not called.
  ~Atomic_output_dir() { abort(); }

  /// \brief the target directory.
  std::string directory() const { return dir_.string(); }

  /// \brief the final path of file `name` (a plain file name) in the target directory.
  std::string final_path(const std::string& name) const { return (dir_ / name).string(); }

  /*!
    \brief registers file `name` and returns the temporary path to write it to.
    \throws std::invalid_argument if `name` is not a plain file name or is registered twice
  */
  std::string temporary_path(const std::string& name)
  {
    if(name.empty() || name == "." || name == ".." || name.find('/') != std::string::npos ||
       name.find('\\') != std::string::npos)
      throw std::invalid_argument("Atomic_output_dir: invalid file name '" + name + "'");
    for(const auto& f : files_)
      if(f.first == name)
        throw std::invalid_argument("Atomic_output_dir: file '" + name + "' registered twice");
    std::filesystem::path tmp = dir_ / ("." + name + ".swn-tmp-" + tag_);
    files_.emplace_back(name, tmp);
    return tmp.string();
  }

  /// \brief same as `temporary_path()`: write the file `name` to the returned path.
  std::string path(const std::string& name) { return temporary_path(name); }

  /*!
    \brief writes file `name` through `writer(std::ostream&)` into its temporary.
    \throws std::runtime_error if the file cannot be opened or the stream fails; exceptions of `writer` pass
  */
  template <class Writer>
  void write(const std::string& name, Writer&& writer)
  {
    std::string tmp = temporary_path(name);
    std::ofstream os(tmp, std::ios::binary | std::ios::trunc);
    if(!os)
      throw std::runtime_error("cannot open " + tmp + " for writing");
    writer(static_cast<std::ostream&>(os));
    os.flush();
    if(!os)
      throw std::runtime_error("write error on " + final_path(name));
    os.close();
    if(os.fail())
      throw std::runtime_error("write error on " + final_path(name));
  }

  /// \brief renames every temporary into place. \throws std::runtime_error on failure
  void commit()
  {
    for(auto& f : files_)
    {
      std::error_code ec;
      std::filesystem::rename(f.second, dir_ / f.first, ec);
      if(ec)
        throw std::runtime_error("cannot move " + f.second.string() + " to " + final_path(f.first) + ": " + ec.message());
      f.second.clear();
    }
    committed_ = true;
    files_.clear();
    created_.clear();
  }

  /// \brief removes the temporaries written so far (and directories created and left empty).
  void abort() noexcept
  {
    if(committed_) return;
    for(auto& f : files_)
    {
      std::error_code ec;
      if(!f.second.empty()) std::filesystem::remove(f.second, ec);
    }
    files_.clear();
    cleanup_dirs();
  }

  /// \brief the names registered so far (not yet committed).
  std::vector<std::string> names() const
  {
    std::vector<std::string> r;
    for(const auto& f : files_) r.push_back(f.first);
    return r;
  }

private:
  void cleanup_dirs() noexcept
  {
    for(auto it = created_.rbegin(); it != created_.rend(); ++it)
    {
      std::error_code ec;
      std::filesystem::remove(*it, ec);  // only removes empty directories
    }
    created_.clear();
  }

  std::filesystem::path dir_;
  std::string tag_;
  std::vector<std::pair<std::string, std::filesystem::path> > files_;
  std::vector<std::filesystem::path> created_;
  bool committed_ = false;
};

/*!
  \brief a minimal JSON value (null, bool, integer, number, string, array, object with insertion order) with
  a writer, for `summary.json`.

  Two ways to build a value:
  - as a tree: `Json j = Json::object(); j["vertices"] = 12; j["files"] = Json::array();
    j["files"].push_back("w.obj"); j.dump(std::cout);`
  - as a stream of events on an empty value: `Json j; j.begin_object().key("vertices").value(12)
    .key("files").begin_array().value("w.obj").end_array().end_object(); std::string s = j.str();`

  Non-finite numbers are written as `null`; strings are escaped (`"`, `\`, control characters); bytes >= 0x80
  are copied as is (UTF-8).
*/
class Json
{
public:
  /// the elements of an array
  typedef std::vector<Json> Array;
  /// the members of an object, in insertion order
  typedef std::vector<std::pair<std::string, Json> > Object;

  /// copies the value only, not the state of the streaming interface
  Json(const Json& o) : v_(o.v_) {}
  /// moves the value only, not the state of the streaming interface
  Json(Json&& o) noexcept : v_(std::move(o.v_)) {}
  /// assigns the value only, not the state of the streaming interface
  Json& operator=(const Json& o) { if(this != &o) v_ = o.v_; return *this; }
  /// move-assigns the value only, not the state of the streaming interface
  Json& operator=(Json&& o) noexcept { v_ = std::move(o.v_); return *this; }

  /// \brief null
  Json() : v_(std::monostate()) {}
  /// null
  Json(std::nullptr_t) : v_(std::monostate()) {}
  /// `true` or `false`
  Json(bool b) : v_(b) {}
  /// a number (`null` if not finite)
  Json(double d) : v_(d) {}
  /// a number (`null` if not finite)
  Json(float d) : v_(static_cast<double>(d)) {}
  /// a string
  Json(const char* s) : v_(std::string(s)) {}
  /// a string
  Json(const std::string& s) : v_(s) {}
  /// a string
  Json(std::string&& s) : v_(std::move(s)) {}
  /// an array
  Json(const Array& a) : v_(a) {}
  /// an object
  Json(const Object& o) : v_(o) {}
  /// integers (any integral type except bool)
  template <class T, typename std::enable_if<std::is_integral<T>::value && !std::is_same<T, bool>::value, int>::type = 0>
  Json(T i)
  {
    if(std::is_signed<T>::value) v_ = static_cast<long long>(i);
    else v_ = static_cast<unsigned long long>(i);
  }
  /// \brief an array of numbers or strings
  template <class T>
  Json(const std::vector<T>& values) : v_(Array())
  {
    for(const T& x : values) std::get<Array>(v_).push_back(Json(x));
  }

  /// \brief an empty object
  static Json object() { Json j; j.v_ = Object(); return j; }
  /// \brief an empty array
  static Json array() { Json j; j.v_ = Array(); return j; }

  /// true if the value is an object
  bool is_object() const { return std::holds_alternative<Object>(v_); }
  /// true if the value is an array
  bool is_array() const { return std::holds_alternative<Array>(v_); }

  /// \brief the member `key` of an object (created as null if missing; a null value becomes an object).
  Json& operator[](const std::string& key)
  {
    if(std::holds_alternative<std::monostate>(v_)) v_ = Object();
    if(!is_object()) throw std::logic_error("Json: operator[] on a non-object");
    for(auto& kv : std::get<Object>(v_))
      if(kv.first == key) return kv.second;
    std::get<Object>(v_).emplace_back(key, Json());
    return std::get<Object>(v_).back().second;
  }

  /// \brief appends to an array (a null value becomes an array).
  void push_back(const Json& j)
  {
    if(std::holds_alternative<std::monostate>(v_)) v_ = Array();
    if(!is_array()) throw std::logic_error("Json: push_back on a non-array");
    std::get<Array>(v_).push_back(j);
  }

  /// \name Streaming interface
  /// @{

  /// \brief opens an object: the root (if this value is null and nothing is open), or a member/element of
  /// the innermost open container.
  Json& begin_object() { open(Json::object()); return *this; }
  /// \brief opens an array (see `begin_object()`).
  Json& begin_array() { open(Json::array()); return *this; }
  /// \brief closes the innermost open object.
  Json& end_object() { close(true); return *this; }
  /// \brief closes the innermost open array.
  Json& end_array() { close(false); return *this; }
  /// \brief sets the key of the next member of the innermost open object.
  Json& key(const std::string& k)
  {
    if(stack_.empty() || !stack_.back()->is_object())
      throw std::logic_error("Json: key() outside of an object");
    key_ = k;
    has_key_ = true;
    return *this;
  }
  /// \brief adds a value (anything a `Json` can be built from) to the innermost open container.
  template <class T>
  Json& value(const T& x) { insert(Json(x)); return *this; }
  /// \brief the JSON text (see `dump()`).
  std::string str(int indent = 2) const
  {
    if(!stack_.empty()) throw std::logic_error("Json: str() with an unclosed container");
    return dump(indent);
  }
  /// @}

  /// \brief writes the value; `indent` < 0 writes everything on one line.
  void dump(std::ostream& os, int indent = 2) const
  {
    write(os, indent, 0);
    if(indent >= 0) os << '\n';
  }

  /// \brief returns the JSON text.
  std::string dump(int indent = 2) const
  {
    std::ostringstream s;
    dump(s, indent);
    return s.str();
  }

  /// \brief writes `s` as a JSON string literal.
  static void write_string(std::ostream& os, const std::string& s)
  {
    os << '"';
    for(char ch : s)
    {
      unsigned char c = static_cast<unsigned char>(ch);
      switch(c)
      {
        case '"': os << "\\\""; break;
        case '\\': os << "\\\\"; break;
        case '\b': os << "\\b"; break;
        case '\f': os << "\\f"; break;
        case '\n': os << "\\n"; break;
        case '\r': os << "\\r"; break;
        case '\t': os << "\\t"; break;
        default:
          if(c < 0x20 || c == 0x7f)
          {
            static const char* hex = "0123456789abcdef";
            os << "\\u00" << hex[c >> 4] << hex[c & 15];
          }
          else
            os << ch;
      }
    }
    os << '"';
  }

private:
  Json* insert(Json&& j)
  {
    if(stack_.empty())
    {
      if(!std::holds_alternative<std::monostate>(v_))
        throw std::logic_error("Json: a second root value");
      v_ = std::move(j.v_);
      return this;
    }
    Json* c = stack_.back();
    if(c->is_object())
    {
      if(!has_key_) throw std::logic_error("Json: object member without key()");
      has_key_ = false;
      std::get<Object>(c->v_).emplace_back(key_, std::move(j));
      return &std::get<Object>(c->v_).back().second;
    }
    std::get<Array>(c->v_).push_back(std::move(j));
    return &std::get<Array>(c->v_).back();
  }
  void open(Json&& j) { stack_.push_back(insert(std::move(j))); }
  void close(bool object)
  {
    if(stack_.empty() || stack_.back()->is_object() != object)
      throw std::logic_error(object ? "Json: end_object() without matching begin_object()"
                                    : "Json: end_array() without matching begin_array()");
    if(object && has_key_) throw std::logic_error("Json: key() without value");
    stack_.pop_back();
  }

  void newline(std::ostream& os, int indent, int depth) const
  {
    if(indent < 0) return;
    os << '\n';
    for(int i = 0; i < indent * depth; ++i) os << ' ';
  }

  void write(std::ostream& os, int indent, int depth) const
  {
    if(std::holds_alternative<std::monostate>(v_)) os << "null";
    else if(auto b = std::get_if<bool>(&v_)) os << (*b ? "true" : "false");
    else if(auto i = std::get_if<long long>(&v_)) os << *i;
    else if(auto u = std::get_if<unsigned long long>(&v_)) os << *u;
    else if(auto d = std::get_if<double>(&v_))
    {
      if(!std::isfinite(*d)) os << "null";
      else
      {
        char buf[64];
        auto r = std::to_chars(buf, buf + sizeof(buf), *d);
        std::string s(buf, r.ptr);
        os << s;
      }
    }
    else if(auto s = std::get_if<std::string>(&v_)) write_string(os, *s);
    else if(auto a = std::get_if<Array>(&v_))
    {
      if(a->empty()) { os << "[]"; return; }
      os << '[';
      for(std::size_t k = 0; k < a->size(); ++k)
      {
        if(k) os << ',';
        newline(os, indent, depth + 1);
        (*a)[k].write(os, indent, depth + 1);
      }
      newline(os, indent, depth);
      os << ']';
    }
    else if(auto o = std::get_if<Object>(&v_))
    {
      if(o->empty()) { os << "{}"; return; }
      os << '{';
      for(std::size_t k = 0; k < o->size(); ++k)
      {
        if(k) os << ',';
        newline(os, indent, depth + 1);
        write_string(os, (*o)[k].first);
        os << (indent >= 0 ? ": " : ":");
        (*o)[k].second.write(os, indent, depth + 1);
      }
      newline(os, indent, depth);
      os << '}';
    }
  }

  std::variant<std::monostate, bool, long long, unsigned long long, double, std::string, Array, Object> v_;
  // streaming interface state (root only)
  std::vector<Json*> stack_;
  std::string key_;
  bool has_key_ = false;
};

} // namespace IO
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif // CGAL_SURFACE_WINDING_NUMBERS_IO_WRITE_OUTPUTS_H
