// Copyright (c) 2026 The CGAL Surface_winding_numbers contributors.
// SPDX-License-Identifier: MIT
//
// Writers for the outputs of the `swn` tool on a polygon soup (a mesh file that is not an oriented
// 2-manifold triangle mesh): the same files as for meshes, on the input's own faces and vertices.

#ifndef CGAL_SWN_TOOL_IO_WRITE_SOUP_OUTPUTS_H
#define CGAL_SWN_TOOL_IO_WRITE_SOUP_OUTPUTS_H

#include "swn_io/mesh_soup.h"
#include "swn_io/write_outputs.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <ostream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace IO {

/// a value per edge of a soup, keyed by its two vertices `(i, j)`, `i < j`, signed from `i` to `j`
typedef std::map<std::pair<std::size_t, std::size_t>, int> Soup_edge_chain;
/// a value per corner of a soup, keyed by (face, position of the corner in the face)
typedef std::map<std::pair<std::size_t, std::size_t>, double> Soup_corner_values;

namespace internal {

template <class T>
void write_little_endian(Output_buffer& out, T x)
{
  char b[sizeof(T)];
  std::memcpy(b, &x, sizeof(T));   // x86 and ARM Linux are little endian; PLY says so in its header
  out << std::string_view(b, sizeof(T));
}

} // namespace internal

/*!
  \brief writes one integer label per line, one line per face of the soup, in file order.
*/
inline void write_soup_labels(const std::string& path, const std::vector<int>& labels)
{
  internal::write_to_path(path, [&](std::ostream& os) {
    internal::Output_buffer out(os);
    for(int x : labels) out << x << '\n';
    out.flush();
    internal::check_stream(os, "labels");
  });
}

/*!
  \brief writes the soup as binary little-endian PLY with its own faces (polygons kept) and, per face,
  `int label`, `float winding_number` (the mean of its defined corner values) and `uchar red, green, blue,
  alpha` (`label_color()`), as `write_labeled_ply()` does for meshes; with `confidence` (per face, may be
  empty: not written) also `float confidence` and `int region` after `winding_number`.
*/
inline void write_soup_ply(const std::string& path, const Triangle_soup& soup, const std::vector<int>& labels,
                           const Soup_corner_values& w, const std::vector<double>& confidence = std::vector<double>(),
                           const std::vector<std::size_t>& region = std::vector<std::size_t>())
{
  const std::size_t nf = number_of_faces(soup);
  if(labels.size() != nf) throw std::invalid_argument("write_soup_ply: one label per face expected");
  if(!confidence.empty() && (confidence.size() != nf || region.size() != nf))
    throw std::invalid_argument("write_soup_ply: one confidence and one region per face expected");
  internal::write_to_path(path, [&](std::ostream& os) {
    internal::Output_buffer out(os);
    out << "ply\nformat binary_little_endian 1.0\ncomment written by CGAL Surface_winding_numbers\nelement vertex "
        << soup.points.size() << "\nproperty double x\nproperty double y\nproperty double z\nelement face " << nf
        << "\nproperty list uchar int vertex_indices\nproperty int label\nproperty float winding_number\n"
        << (confidence.empty() ? "" : "property float confidence\nproperty int region\n")
        << "property uchar red\nproperty uchar green\nproperty uchar blue\nproperty uchar alpha\nend_header\n";
    for(const auto& p : soup.points)
      for(int k = 0; k < 3; ++k) internal::write_little_endian(out, p[k]);
    for(std::size_t f = 0; f < nf; ++f)
    {
      const std::vector<std::size_t> face = internal::soup_face(soup, f);
      if(face.size() > 255) throw std::invalid_argument("write_soup_ply: a face with more than 255 vertices");
      internal::write_little_endian(out, static_cast<std::uint8_t>(face.size()));
      double sum = 0;
      int defined = 0;
      for(std::size_t k = 0; k < face.size(); ++k)
      {
        internal::write_little_endian(out, static_cast<std::int32_t>(face[k]));
        const auto it = w.find({f, k});
        if(it != w.end() && !std::isnan(it->second)) { sum += it->second; ++defined; }
      }
      internal::write_little_endian(out, static_cast<std::int32_t>(labels[f]));
      internal::write_little_endian(out, static_cast<float>(defined > 0 ? sum / defined : std::nan("")));
      if(!confidence.empty())
      {
        internal::write_little_endian(out, static_cast<float>(confidence[f]));
        internal::write_little_endian(out, static_cast<std::int32_t>(region[f]));
      }
      const auto rgb = label_color(labels[f]);
      for(unsigned char c : {rgb[0], rgb[1], rgb[2], static_cast<unsigned char>(255)}) internal::write_little_endian(out, c);
    }
    out.flush();
    internal::check_stream(os, "PLY");
  });
}

/*!
  \brief writes the authors' winding-number OBJ for a soup: `v` lines, one `vt w 1` per corner (`vt 0 0`
  where w is undefined), faces in file order with their own vertices (`f i/t/ j/t/ ...`, 1-based).
*/
inline void write_soup_w_obj(const std::string& path, const Triangle_soup& soup, const Soup_corner_values& w)
{
  const std::size_t nf = number_of_faces(soup);
  internal::write_to_path(path, [&](std::ostream& os) {
    internal::Output_buffer out(os);
    out << "# Mesh exported from CGAL Surface_winding_numbers\n#  vertices: " << soup.points.size()
        << "\n#     faces: " << nf << "\n# texture coordinates: YES\n";
    for(const auto& p : soup.points) out << "v " << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
    for(std::size_t f = 0; f < nf; ++f)
      for(std::size_t k = 0; k < internal::soup_face(soup, f).size(); ++k)
      {
        const auto it = w.find({f, k});
        if(it == w.end() || std::isnan(it->second)) out << "vt 0 0\n";
        else out << "vt " << it->second << " 1\n";
      }
    std::size_t corner = 0;
    for(std::size_t f = 0; f < nf; ++f)
    {
      out << 'f';
      for(std::size_t v : internal::soup_face(soup, f)) out << ' ' << v + 1 << '/' << ++corner << '/';
      out << '\n';
    }
    out.flush();
    internal::check_stream(os, "w.obj");
  });
}

/*!
  \brief writes an integer chain on the edges of a soup as an OBJ curve file: the vertices it uses (with a
  `# mesh vertices:` comment giving their 0-based indices, as `write_chain_obj()`), then `l` lines: each
  edge traversed |value| times in the direction of its sign, consecutive traversals joined into polylines
  where one ends at the vertex the next starts from.
*/
inline void write_soup_chain_obj(const std::string& path, const Triangle_soup& soup, const Soup_edge_chain& chain)
{
  std::map<std::size_t, std::vector<std::size_t> > out_edges;   // vertex -> targets, one per traversal
  std::size_t traversals = 0;
  for(const auto& kv : chain)
    for(int m = 0; m < std::abs(kv.second); ++m, ++traversals)
    {
      if(kv.second > 0) out_edges[kv.first.first].push_back(kv.first.second);
      else out_edges[kv.first.second].push_back(kv.first.first);
    }
  std::vector<std::vector<std::size_t> > pieces;
  while(!out_edges.empty())
  {
    std::vector<std::size_t> piece{out_edges.begin()->first};
    for(auto it = out_edges.find(piece.back()); it != out_edges.end(); it = out_edges.find(piece.back()))
    {
      piece.push_back(it->second.back());
      it->second.pop_back();
      if(it->second.empty()) out_edges.erase(it);
    }
    pieces.push_back(std::move(piece));
  }
  std::map<std::size_t, std::size_t> index;   // used vertex -> 1-based index in the file
  for(const auto& p : pieces) for(std::size_t v : p) index.emplace(v, 0);
  std::size_t count = 0;
  for(auto& kv : index) kv.second = ++count;
  internal::write_to_path(path, [&](std::ostream& os) {
    internal::Output_buffer out(os);
    out << "# curve written by CGAL Surface_winding_numbers: " << pieces.size() << " polylines, " << traversals
        << " edges (with multiplicity)\n# mesh vertices:";
    for(const auto& kv : index) out << ' ' << kv.first;
    out << '\n';
    for(const auto& kv : index)
      out << "v " << soup.points[kv.first][0] << ' ' << soup.points[kv.first][1] << ' ' << soup.points[kv.first][2] << '\n';
    for(const auto& p : pieces)
    {
      out << 'l';
      for(std::size_t v : p) out << ' ' << index[v];
      out << '\n';
    }
    out.flush();
    internal::check_stream(os, "curve OBJ");
  });
}

} // namespace IO
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif // CGAL_SWN_TOOL_IO_WRITE_SOUP_OUTPUTS_H
