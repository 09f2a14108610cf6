// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT
//
// Curves off the mesh: 3D polylines from OBJ `v`/`l` records, and 2D polylines from a small subset of SVG
// (straight segments only), for the library's polylines_to_chain() and stamp_polylines().

#ifndef CGAL_SWN_TOOL_IO_READ_POLYLINES_H
#define CGAL_SWN_TOOL_IO_READ_POLYLINES_H

#include "swn_io/errors.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace IO {

/*!
  \brief 3D polylines read from an OBJ file, with the line of each `l` record.
*/
struct Obj_polylines
{
  /// the polylines; a closed one repeats its first point at the end
  std::vector<std::vector<std::array<double, 3> > > polylines;
  /// for each polyline, the 1-based line of its `l` record
  std::vector<std::size_t> lines;
};

/*!
  \brief reads 3D polylines from an OBJ stream: `v X Y Z` points and `l I J ...` polylines through them
  (1-based indices, negative ones counted back from the last point, `#offset K` honoured as in the curve
  files). Other records (`f`, `vn`, `vt`, `o`, `g`, ...) are ignored. A polyline whose last index repeats
  its first is closed. `file` names the stream in messages.
  \throws Input_error (file and line) on an unparsable or non-finite coordinate, an index out of range, and
  when the file holds no `l` record.
*/
inline Obj_polylines read_obj_polylines(std::istream& is, const std::string& file)
{
  internal::Line_reader lr(is, file);
  std::string line;
  std::vector<std::string_view> tok;
  long long offset = 0;
  std::vector<std::array<double, 3> > points;
  Obj_polylines result;
  while(internal::next_record(lr, line, tok, offset))
  {
    if(tok[0] == "v")
    {
      const std::array<double, 3> p = internal::vertex_coordinates(tok, 1, lr);
      for(double x : p)
        if(!std::isfinite(x)) lr.fail("vertex coordinate is not finite");
      points.push_back(p);
    }
    else if(tok[0] == "l")
    {
      std::vector<std::array<double, 3> > polyline;
      for(std::size_t k = 1; k < tok.size(); ++k)
      {
        long long i;
        // `l` entries may carry a texture index: `l 3/7 4/8`
        if(!internal::parse_int(tok[k].substr(0, tok[k].find('/')), i))
          lr.fail("cannot parse index " + internal::quote(tok[k]) + " in an `l` record");
        if(i >= 0 && !internal::add_index_offset(i - 1, offset, i)) i = -1;
        else if(i < 0) i = (long long)points.size() + i;
        if(i < 0 || i >= (long long)points.size())
          lr.fail("index " + internal::quote(tok[k]) + " does not name a point defined above (" +
                  std::to_string(points.size()) + " points)");
        polyline.push_back(points[std::size_t(i)]);
      }
      result.polylines.push_back(std::move(polyline));
      result.lines.push_back(lr.line_number());
    }
  }
  if(result.lines.empty()) throw Input_error(file, 0, "no polyline (`l` record) in the file");
  return result;
}

/// reads the 3D polylines of the OBJ file `file` (see the stream version)
inline Obj_polylines read_obj_polylines(const std::string& file)
{
  std::ifstream is = internal::open_input_file(file, "an OBJ polyline file");
  return read_obj_polylines(is, file);
}

/*!
  \brief 2D polylines read from an SVG file, with the warnings of the reader.
*/
struct Svg_drawing
{
  /// the polylines, in the SVG's user units (y down); a closed one repeats its first point at the end
  std::vector<std::vector<std::array<double, 2> > > polylines;
  /// for each polyline, the 1-based line of the element it comes from
  std::vector<std::size_t> lines;
  /// `FILE:LINE: element ignored` for every element that is not read
  std::vector<std::string> warnings;
};

/// \cond SKIP_IN_MANUAL
namespace internal {

// the numbers of an SVG attribute (`points`, or the arguments of path commands), separated by blanks
// and commas or only by a sign or a second decimal point ("10-5", "1.5.5")
class Svg_numbers
{
public:
  Svg_numbers(std::string_view s, const std::string& file, std::size_t line) : s_(s), file_(file), line_(line) {}
  void skip() { while(i_ < s_.size() && (is_space(s_[i_]) || s_[i_] == ',')) ++i_; }
  bool at_end() { skip(); return i_ >= s_.size(); }
  bool at_number() { skip(); return i_ < s_.size() && (std::isdigit((unsigned char)s_[i_]) || s_[i_] == '-' || s_[i_] == '+' || s_[i_] == '.'); }
  char peek() { skip(); return i_ < s_.size() ? s_[i_] : '\0'; }
  char take() { skip(); return s_[i_++]; }
  double number()
  {
    if(!at_number()) fail("a number was expected" + (i_ < s_.size() ? " at " + quote(s_.substr(i_, 12)) : std::string(" at the end")));
    std::size_t j = i_;
    if(s_[j] == '-' || s_[j] == '+') ++j;
    bool dot = false;
    while(j < s_.size() && (std::isdigit((unsigned char)s_[j]) || (s_[j] == '.' && !dot))) { dot = dot || s_[j] == '.'; ++j; }
    if(j < s_.size() && (s_[j] == 'e' || s_[j] == 'E'))
    {
      std::size_t k = j + 1;
      if(k < s_.size() && (s_[k] == '-' || s_[k] == '+')) ++k;
      if(k < s_.size() && std::isdigit((unsigned char)s_[k]))
      {
        while(k < s_.size() && std::isdigit((unsigned char)s_[k])) ++k;
        j = k;
      }
    }
    double x;
    if(!parse_double(s_.substr(i_, j - i_), x) || !std::isfinite(x)) fail("cannot parse number " + quote(s_.substr(i_, j - i_)));
    i_ = j;
    return x;
  }
  [[noreturn]] void fail(const std::string& reason) const { throw Input_error(file_, line_, reason); }

private:
  std::string_view s_;
  std::size_t i_ = 0;
  const std::string& file_;
  std::size_t line_;
};

// the polylines of a path's `d`: M/L/H/V/Z, absolute and relative
inline void read_svg_path(std::string_view d, const std::string& file, std::size_t line,
                          std::vector<std::vector<std::array<double, 2> > >& out)
{
  Svg_numbers in(d, file, line);
  std::array<double, 2> at = {0, 0}, start = {0, 0};
  char command = '\0';
  std::vector<std::array<double, 2> > current;
  auto flush = [&] { if(current.size() > 1) out.push_back(current); current.clear(); };
  while(!in.at_end())
  {
    if(!in.at_number())
    {
      command = in.take();
      if(std::string("MmLlHhVvZz").find(command) == std::string::npos)
        in.fail(std::string("path command '") + command + "' is not supported (only straight segments: M, L, H, V, Z; "
                "flatten the curves first)");
      if(command == 'Z' || command == 'z')
      {
        if(!current.empty()) { current.push_back(start); at = start; }
        flush();
        continue;
      }
    }
    else if(command == '\0' || command == 'Z' || command == 'z') in.fail("path data must start with a command (M)");
    const bool relative = std::islower((unsigned char)command) != 0;
    const char c = char(std::toupper((unsigned char)command));
    std::array<double, 2> p = at;
    if(c == 'H') p[0] = in.number() + (relative ? at[0] : 0);
    else if(c == 'V') p[1] = in.number() + (relative ? at[1] : 0);
    else
    {
      p[0] = in.number() + (relative ? at[0] : 0);
      p[1] = in.number() + (relative ? at[1] : 0);
    }
    if(!std::isfinite(p[0]) || !std::isfinite(p[1]))
      in.fail("the path's coordinates add up to a number that is not finite (relative moves overflow)");
    if(c == 'M')
    {
      flush();
      start = p;
      command = relative ? 'l' : 'L';   // further pairs are line-tos
    }
    if(current.empty()) current.push_back(at = (c == 'M' ? p : at));
    if(c != 'M') current.push_back(p);
    at = p;
  }
  flush();
}

} // namespace internal
/// \endcond

/*!
  \brief reads the straight-segment drawing of an SVG file: `path` (commands M, L, H, V, Z, absolute and
  relative), `polyline`, `polygon` and `line` elements, in the document's user units.

  Containers and metadata (`svg`, `g`, `defs`, `title`, `desc`, `metadata`, `style`) are passed over; any
  other element (`circle`, `rect`, `text`, ...) is ignored with a warning naming it and its line.
  `file` names the stream in messages.
  \throws Input_error (file and line) on a curved path command (C, S, Q, T, A), a `transform` attribute
  (not supported: apply the transforms first), a malformed or infinite number (also a coordinate that
  overflows when relative moves are added up), or a file without any polyline.
*/
inline Svg_drawing read_svg_polylines(std::istream& is, const std::string& file)
{
  std::stringstream buffer;
  buffer << is.rdbuf();
  const std::string text = buffer.str();
  Svg_drawing drawing;
  std::size_t i = 0, line = 1;
  auto advance_to = [&](std::size_t j) {
    for(; i < j && i < text.size(); ++i) line += text[i] == '\n';
  };
  while(true)
  {
    const std::size_t lt = text.find('<', i);
    if(lt == std::string::npos) break;
    advance_to(lt);
    const std::size_t element_line = line;
    auto skip_past = [&](const char* end) {
      const std::size_t e = text.find(end, i);
      if(e == std::string::npos) throw Input_error(file, element_line, std::string("unterminated markup (no '") + end + "')");
      advance_to(e + std::string(end).size());
    };
    if(text.compare(i, 4, "<!--") == 0) { skip_past("-->"); continue; }
    if(text.compare(i, 9, "<![CDATA[") == 0) { skip_past("]]>"); continue; }
    if(text.compare(i, 2, "<?") == 0 || text.compare(i, 2, "<!") == 0 || text.compare(i, 2, "</") == 0) { skip_past(">"); continue; }
    // an element: its name and its attributes
    std::size_t j = i + 1;
    while(j < text.size() && !internal::is_space(text[j]) && text[j] != '>' && text[j] != '/') ++j;
    const std::string name = text.substr(i + 1, j - i - 1);
    std::vector<std::pair<std::string, std::string> > attributes;
    while(true)
    {
      while(j < text.size() && internal::is_space(text[j])) ++j;
      if(j >= text.size()) throw Input_error(file, element_line, "unterminated element <" + name + ">");
      if(text[j] == '>' || text[j] == '/') break;
      std::size_t k = j;
      while(k < text.size() && text[k] != '=' && !internal::is_space(text[k]) && text[k] != '>') ++k;
      std::string key = text.substr(j, k - j);
      while(k < text.size() && internal::is_space(text[k])) ++k;
      if(k >= text.size() || text[k] != '=') throw Input_error(file, element_line, "attribute '" + key + "' of <" + name + "> has no value");
      ++k;
      while(k < text.size() && internal::is_space(text[k])) ++k;
      if(k >= text.size() || (text[k] != '"' && text[k] != '\''))
        throw Input_error(file, element_line, "attribute '" + key + "' of <" + name + "> is not quoted");
      const std::size_t close = text.find(text[k], k + 1);
      if(close == std::string::npos) throw Input_error(file, element_line, "unterminated attribute '" + key + "' of <" + name + ">");
      attributes.emplace_back(key, text.substr(k + 1, close - k - 1));
      j = close + 1;
    }
    advance_to(j);   // past the attributes: a '>' inside a quoted value does not end the element
    skip_past(">");
    auto attribute = [&](const std::string& key) -> const std::string* {
      for(const auto& a : attributes)
        if(a.first == key) return &a.second;
      return nullptr;
    };
    if(attribute("transform"))
      throw Input_error(file, element_line, "<" + name + ">: transform attributes are not supported (apply them to the coordinates first)");
    if(name == "path")
    {
      const std::string* d = attribute("d");
      if(!d) throw Input_error(file, element_line, "<path> without a 'd' attribute");
      internal::read_svg_path(*d, file, element_line, drawing.polylines);
      drawing.lines.resize(drawing.polylines.size(), element_line);
    }
    else if(name == "polyline" || name == "polygon")
    {
      const std::string* pts = attribute("points");
      if(!pts) throw Input_error(file, element_line, "<" + name + "> without a 'points' attribute");
      internal::Svg_numbers in(*pts, file, element_line);
      std::vector<std::array<double, 2> > p;
      while(!in.at_end())
      {
        const double x = in.number();
        if(in.at_end()) in.fail("odd number of coordinates in 'points'");
        p.push_back({x, in.number()});
      }
      if(name == "polygon" && p.size() > 2) p.push_back(p.front());
      if(p.size() > 1) { drawing.polylines.push_back(p); drawing.lines.push_back(element_line); }
    }
    else if(name == "line")
    {
      std::array<double, 4> c = {0, 0, 0, 0};
      const char* keys[] = {"x1", "y1", "x2", "y2"};
      for(int k = 0; k < 4; ++k)
        if(const std::string* v = attribute(keys[k])) c[k] = internal::Svg_numbers(*v, file, element_line).number();
      drawing.polylines.push_back({{c[0], c[1]}, {c[2], c[3]}});
      drawing.lines.push_back(element_line);
    }
    else if(name != "svg" && name != "g" && name != "defs" && name != "title" && name != "desc" &&
            name != "metadata" && name != "style")
      drawing.warnings.push_back(Input_error::format(file, element_line, "<" + name + "> is not supported and is ignored "
                                                     "(only path, polyline, polygon and line)"));
  }
  if(drawing.polylines.empty()) throw Input_error(file, 0, "no polyline in the SVG file (path, polyline, polygon or line)");
  // the drawing's extent and centre must be finite, for the stamp to place it (coordinates near +-1e308 overflow)
  std::array<double, 2> lo = drawing.polylines[0][0], hi = lo;
  for(std::size_t k = 0; k < drawing.polylines.size(); ++k)
    for(const auto& q : drawing.polylines[k])
      for(int c = 0; c < 2; ++c)
      {
        lo[c] = (std::min)(lo[c], q[c]);
        hi[c] = (std::max)(hi[c], q[c]);
        if(!std::isfinite(hi[c] - lo[c]) || !std::isfinite(hi[c] + lo[c]))
          throw Input_error(file, drawing.lines[k], "the drawing's extent or centre is not a finite number (coordinates too large)");
      }
  return drawing;
}

/// reads the drawing of the SVG file `file` (see the stream version)
inline Svg_drawing read_svg_polylines(const std::string& file)
{
  std::ifstream is = internal::open_input_file(file, "an SVG file");
  return read_svg_polylines(is, file);
}

// Why no curve is left on the surface once polylines are put on it (polylines_to_chain()'s counts, summed
// over the files): the points, those farther from the surface than `tolerance` (its wording), the pieces
// along the border, the curves put on the mesh and the failed walks. The tool's and Python's message.
inline std::string no_curve_left_reason(std::size_t points, std::size_t off_surface, std::size_t border_pieces,
                                        std::size_t curves, std::size_t failed_walks, const std::string& tolerance)
{
  if(off_surface == points)
    return "no curve on the surface (every point is farther than " + tolerance + " from it)";
  if(curves == 0 && border_pieces > 0)
    return "no curve left on the surface: it runs along the border of the mesh (" + std::to_string(border_pieces) +
           (border_pieces == 1 ? " piece" : " pieces") + " dropped), and curves may end on the border, not run along it";
  if(curves == 0 && failed_walks > 0)
    return "no curve left on the surface: the walk along the surface could not follow any segment between points on "
           "it (" + std::to_string(failed_walks) + " failed: the segments leave the surface or reach its border)";
  if(curves == 0)
    return "no curve left on the surface: the polylines cross no edge of the mesh (each stays inside one face); "
           "draw longer strokes or refine the mesh";
  return "no curve left on the surface: what was put on it cancels out (the polylines run back along themselves, "
         "every edge as often in one direction as in the other)";
}

} // namespace IO
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif // CGAL_SWN_TOOL_IO_READ_POLYLINES_H
