// Copyright (c) 2024 The CGAL Surface_winding_numbers contributors.
// SPDX-License-Identifier: MIT
//
// PLY reader: the header and ASCII data with their lines; binary data through CGAL::IO::read_PLY().

#ifndef CGAL_SWN_TOOL_IO_READ_PLY_H
#define CGAL_SWN_TOOL_IO_READ_PLY_H

#include "swn_io/errors.h"
#include "swn_io/mesh_soup.h"

#include <CGAL/IO/PLY.h>
#include <CGAL/Simple_cartesian.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <istream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace IO {


namespace internal {

// ------------------------------------------------------------------------------------------------ PLY

enum class Ply_type { NONE, INT8, UINT8, INT16, UINT16, INT32, UINT32, FLOAT32, FLOAT64 };

inline Ply_type ply_type(std::string_view s)
{
  if(s == "char" || s == "int8") return Ply_type::INT8;
  if(s == "uchar" || s == "uint8") return Ply_type::UINT8;
  if(s == "short" || s == "int16") return Ply_type::INT16;
  if(s == "ushort" || s == "uint16") return Ply_type::UINT16;
  if(s == "int" || s == "int32") return Ply_type::INT32;
  if(s == "uint" || s == "uint32") return Ply_type::UINT32;
  if(s == "float" || s == "float32") return Ply_type::FLOAT32;
  if(s == "double" || s == "float64") return Ply_type::FLOAT64;
  return Ply_type::NONE;
}

inline bool ply_is_integer(Ply_type t) { return t != Ply_type::FLOAT32 && t != Ply_type::FLOAT64; }

struct Ply_property
{
  std::string name;
  Ply_type type = Ply_type::NONE;
  bool is_list = false;
  Ply_type count_type = Ply_type::NONE;
};

struct Ply_element
{
  std::string name;
  long long count = 0;
  std::size_t line = 0;
  std::vector<Ply_property> props;
};

// The tokens of an ASCII PLY body, with their lines.
class Ply_ascii_body
{
public:
  Ply_ascii_body(const std::string& data, std::size_t pos, std::size_t first_line, const std::string& file)
    : data_(data), pos_(pos), line_(first_line), file_(file)
  {}

  // reads one scalar as double (exact for all integer types)
  double read(Ply_type t)
  {
    std::string_view tok;
    if(!next_token(tok))
      throw Input_error(file_, line_, "unexpected end of file in the PLY data");
    if(ply_is_integer(t))
    {
      long long i;
      if(!parse_int(tok, i))
        throw Input_error(file_, token_line_, "cannot parse integer " + quote(tok));
      return static_cast<double>(i);
    }
    double x;
    if(!parse_double(tok, x))
      throw Input_error(file_, token_line_, "cannot parse number " + quote(tok));
    return x;
  }

  // line of the last value read
  std::size_t line() const { return token_line_; }

  // fails if anything but whitespace remains
  void check_end()
  {
    std::string_view t;
    if(next_token(t))
      throw Input_error(file_, token_line_, "trailing junk " + quote(t) + " after the last PLY element");
  }

private:
  bool next_token(std::string_view& t)
  {
    while(pos_ < data_.size() && is_space(data_[pos_]))
    {
      if(data_[pos_] == '\n') ++line_;
      ++pos_;
    }
    if(pos_ >= data_.size()) return false;
    std::size_t b = pos_;
    while(pos_ < data_.size() && !is_space(data_[pos_]))
    {
      if(data_[pos_] == '\0')
        throw Input_error(file_, line_, "binary data (NUL byte) in an ASCII PLY file");
      ++pos_;
    }
    t = std::string_view(data_).substr(b, pos_ - b);
    token_line_ = line_;
    return true;
  }

  const std::string& data_;
  std::size_t pos_;
  std::size_t line_;
  std::size_t token_line_ = 0;
  const std::string& file_;
};

struct Ply_header
{
  int format = -1;                  // 0 ascii, 1 binary little endian, 2 binary big endian
  std::vector<Ply_element> elements;
  std::size_t body = 0;             // offset of the data after 'end_header'
  std::size_t lines = 0;            // lines of the header
  int vertex = -1, face = -1;       // the 'vertex' and 'face' elements
  int x = -1, y = -1, z = -1;       // properties of the vertex element
  int indices = -1;                 // the list property of the face element
};

inline Ply_header read_ply_header(const std::string& data, const std::string& file)
{
  Ply_header header;
  std::size_t& pos = header.body;
  std::size_t& line_no = header.lines;
  auto header_line = [&](std::string& out) -> bool {
    if(pos >= data.size()) return false;
    std::size_t e = data.find('\n', pos);
    if(e == std::string::npos) e = data.size();
    out = data.substr(pos, e - pos);
    pos = (e < data.size()) ? e + 1 : e;
    ++line_no;
    if(!out.empty() && out.back() == '\r') out.pop_back();
    if(out.size() > 4096 || out.find('\0') != std::string::npos)
      throw Input_error(file, line_no, "malformed PLY header line");
    return true;
  };
  std::string line;
  std::vector<std::string_view> tok;
  if(!header_line(line) || line != "ply")
    throw Input_error(file, 1, "missing 'ply' magic line");
  bool ended = false;
  while(header_line(line))
  {
    split_tokens(line, tok);
    if(tok.empty()) continue;
    if(tok[0] == "end_header") { ended = true; break; }
    if(tok[0] == "comment" || tok[0] == "obj_info") continue;
    if(tok[0] == "format")
    {
      if(tok.size() != 3 || tok[2] != "1.0")
        throw Input_error(file, line_no, "malformed 'format' line");
      if(tok[1] == "ascii") header.format = 0;
      else if(tok[1] == "binary_little_endian") header.format = 1;
      else if(tok[1] == "binary_big_endian") header.format = 2;
      else throw Input_error(file, line_no, "unknown PLY format " + quote(tok[1]));
    }
    else if(tok[0] == "element")
    {
      Ply_element el;
      if(tok.size() != 3 || !parse_int(tok[2], el.count) || el.count < 0)
        throw Input_error(file, line_no, "malformed 'element' line");
      el.name = std::string(tok[1]);
      el.line = line_no;
      header.elements.push_back(el);
    }
    else if(tok[0] == "property")
    {
      if(header.elements.empty())
        throw Input_error(file, line_no, "'property' before any 'element'");
      Ply_property pr;
      if(tok.size() == 5 && tok[1] == "list")
      {
        pr.is_list = true;
        pr.count_type = ply_type(tok[2]);
        pr.type = ply_type(tok[3]);
        pr.name = std::string(tok[4]);
        if(pr.count_type == Ply_type::NONE || !ply_is_integer(pr.count_type) || pr.type == Ply_type::NONE)
          throw Input_error(file, line_no, "malformed list property");
      }
      else if(tok.size() == 3)
      {
        pr.type = ply_type(tok[1]);
        pr.name = std::string(tok[2]);
        if(pr.type == Ply_type::NONE)
          throw Input_error(file, line_no, "unknown property type " + quote(tok[1]));
      }
      else
        throw Input_error(file, line_no, "malformed 'property' line");
      header.elements.back().props.push_back(pr);
    }
    else
      throw Input_error(file, line_no, "unknown PLY header keyword " + quote(tok[0]));
  }
  if(!ended)
    throw Input_error(file, line_no, "unexpected end of file in the PLY header (no 'end_header')");
  if(header.format < 0)
    throw Input_error(file, line_no, "PLY header without 'format' line");

  for(std::size_t i = 0; i < header.elements.size(); ++i)
  {
    const Ply_element& el = header.elements[i];
    if(el.name == "vertex")
    {
      if(header.vertex >= 0) throw Input_error(file, el.line, "second 'vertex' element");
      header.vertex = int(i);
      for(std::size_t k = 0; k < el.props.size(); ++k)
      {
        const Ply_property& p = el.props[k];
        if(p.is_list) continue;
        if(p.name == "x") header.x = int(k);
        else if(p.name == "y") header.y = int(k);
        else if(p.name == "z") header.z = int(k);
      }
      if(header.x < 0 || header.y < 0 || header.z < 0)
        throw Input_error(file, el.line, "the 'vertex' element lacks an x, y or z property");
    }
    else if(el.name == "face")
    {
      if(header.face >= 0) throw Input_error(file, el.line, "second 'face' element");
      header.face = int(i);
      for(std::size_t k = 0; k < el.props.size(); ++k)
        if(el.props[k].is_list && (el.props[k].name == "vertex_indices" || el.props[k].name == "vertex_index"))
          header.indices = int(k);
      if(header.indices < 0)
        throw Input_error(file, el.line, "the 'face' element lacks a 'vertex_indices' list property");
      const Ply_type t = el.props[header.indices].type;
      if(!ply_is_integer(t))
        throw Input_error(file, el.line, "face vertex indices must have an integer type");
      if(header.format != 0 && t != Ply_type::INT32 && t != Ply_type::UINT32)
        throw Input_error(file, el.line, "binary PLY: face vertex indices must be 'int' or 'uint' (32 bits)");
    }
  }
  if(header.vertex < 0)
    throw Input_error(file, 0, "PLY file without a 'vertex' element");
  return header;
}

inline void read_ply_ascii_body(const std::string& data, const Ply_header& header, const std::string& file,
                                Triangle_soup& soup)
{
  Ply_ascii_body body(data, header.body, header.lines + 1, file);
  for(std::size_t i = 0; i < header.elements.size(); ++i)
  {
    const Ply_element& el = header.elements[i];
    const bool is_vertex = int(i) == header.vertex, is_face = int(i) == header.face;
    if(is_vertex) soup.points.reserve(reserve_cap(el.count));
    if(is_face) soup.triangles.reserve(reserve_cap(el.count));
    std::vector<std::size_t> t;   // the current face's vertices (reused)
    for(long long n = 0; n < el.count; ++n)
    {
      std::array<double, 3> p{0, 0, 0};
      std::size_t first_line = 0;
      for(std::size_t k = 0; k < el.props.size(); ++k)
      {
        const Ply_property& pr = el.props[k];
        if(!pr.is_list)
        {
          const double x = body.read(pr.type);
          if(k == 0) first_line = body.line();
          if(is_vertex && int(k) == header.x) p[0] = x;
          else if(is_vertex && int(k) == header.y) p[1] = x;
          else if(is_vertex && int(k) == header.z) p[2] = x;
          continue;
        }
        const double c = body.read(pr.count_type);
        if(k == 0) first_line = body.line();
        if(c < 0)
          throw Input_error(file, body.line(), "negative list length");
        const std::size_t size = static_cast<std::size_t>(c);
        const bool indices = is_face && int(k) == header.indices;
        if(indices && size < 3)
          throw Input_error(file, body.line(), face_arity_message(number_of_faces(soup), size));
        if(indices) t.clear();
        for(std::size_t m = 0; m < size; ++m)
        {
          const double x = body.read(pr.type);
          if(!indices) continue;
          if(x < 0)
            throw Input_error(file, body.line(), "negative face index " + std::to_string(static_cast<long long>(x)));
          t.push_back(static_cast<std::size_t>(x));
        }
      }
      if(is_vertex)
      {
        check_finite_point(p, file, first_line, soup.points.size());
        soup.points.push_back(p);
        soup.point_lines.push_back(first_line);
      }
      else if(is_face)
      {
        add_face(soup, t, first_line);
      }
    }
  }
  body.check_end();
}

// Binary data has no lines to report: CGAL's reader serves (the header was checked above, with its lines).
inline void read_ply_binary_body(const std::string& data, const std::string& file, Triangle_soup& soup)
{
  std::istringstream in(data, std::ios::in | std::ios::binary);
  std::vector<CGAL::Simple_cartesian<double>::Point_3> points;
  std::vector<std::vector<std::size_t> > polygons;
  if(!CGAL::IO::read_PLY(in, points, polygons))
    throw Input_error(file, 0, in.eof() ? "unexpected end of binary PLY data"
                                        : "CGAL::IO::read_PLY() cannot read the binary PLY data");
  in.clear();
  if(in.peek() != std::char_traits<char>::eof())
    throw Input_error(file, 0, "trailing junk after the binary PLY data (" +
                                   std::to_string(data.size() - static_cast<std::size_t>(in.tellg())) + " bytes)");
  soup_from_points_and_polygons(points, polygons, file, soup);
}

inline void read_PLY_soup(std::istream& is, const std::string& file, Triangle_soup& soup, Mesh_read_info&)
{
  const std::string data = read_whole_stream(is);
  if(is.bad())
    throw Input_error(file, 0, "read error");
  const Ply_header header = read_ply_header(data, file);
  if(header.format == 0) read_ply_ascii_body(data, header, file, soup);
  else read_ply_binary_body(data, file, soup);
}

} // namespace internal


} // namespace IO
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif // CGAL_SWN_TOOL_IO_READ_PLY_H
