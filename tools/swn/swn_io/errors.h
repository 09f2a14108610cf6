// Copyright (c) 2024 The CGAL Surface_winding_numbers contributors.
// SPDX-License-Identifier: MIT
//
// Error type of the file-format layer, and the small text-parsing helpers shared by the readers.

#ifndef CGAL_SWN_TOOL_IO_ERRORS_H
#define CGAL_SWN_TOOL_IO_ERRORS_H

#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <istream>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace IO {

/*!
  \ingroup PkgSurfaceWindingNumbersIO
  \brief exception thrown by every reader of this layer on bad input.

  `what()` is a single line of the form `FILE:LINE: reason`, or `FILE: reason` when the problem is not
  attached to a line (`line == 0`: missing file, binary data, empty curve, ...). Line numbers are 1-based.
*/
struct Input_error : std::runtime_error
{
  /// the file being read (as given by the caller)
  std::string file;
  /// 1-based line number, 0 if the error is not attached to a line
  std::size_t line;
  /// the reason, without file and line
  std::string reason;

  /// \brief builds the error; `what()` is `file:line: reason`.
  Input_error(const std::string& file_, std::size_t line_, const std::string& reason_)
    : std::runtime_error(format(file_, line_, reason_)), file(file_), line(line_), reason(reason_)
  {}

  /// \brief formats the one-line message used by `what()`.
  static std::string format(const std::string& file, std::size_t line, const std::string& reason)
  {
    std::string s = file.empty() ? std::string("<input>") : file;
    if(line != 0)
      s += ":" + std::to_string(line);
    s += ": ";
    // keep the message on one line
    for(char c : reason)
      s += (c == '\n' || c == '\r') ? ' ' : c;
    return s;
  }
};


namespace internal {

inline bool is_space(char c)
{
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f';
}

/// Splits `s` on whitespace; the views point into `s`.
inline void split_tokens(std::string_view s, std::vector<std::string_view>& out)
{
  out.clear();
  std::size_t i = 0, n = s.size();
  while(i < n)
  {
    while(i < n && is_space(s[i])) ++i;
    if(i >= n) break;
    std::size_t j = i;
    while(j < n && !is_space(s[j])) ++j;
    out.push_back(s.substr(i, j - i));
    i = j;
  }
}

/// Parses a whole token as a double (locale independent; accepts a leading '+', "nan", "inf").
inline bool parse_double(std::string_view tok, double& x)
{
  if(tok.empty()) return false;
  const char* b = tok.data();
  const char* e = b + tok.size();
  if(*b == '+') { ++b; if(b == e || *b == '-' || *b == '+') return false; }
  auto r = std::from_chars(b, e, x, std::chars_format::general);
  if(r.ec == std::errc::result_out_of_range)
  {
    // denormal underflow or overflow: fall back to strtod for a saturated value
    std::string tmp(b, e);
    char* end = nullptr;
    x = std::strtod(tmp.c_str(), &end);
    return end == tmp.c_str() + tmp.size();
  }
  return r.ec == std::errc() && r.ptr == e;
}

/// Parses a whole token as a signed integer (no overflow).
inline bool parse_int(std::string_view tok, long long& x)
{
  if(tok.empty()) return false;
  const char* b = tok.data();
  const char* e = b + tok.size();
  if(*b == '+') { ++b; if(b == e || *b == '-' || *b == '+') return false; }
  auto r = std::from_chars(b, e, x, 10);
  return r.ec == std::errc() && r.ptr == e;
}

/// `idx + offset` as a 0-based index: false if the sum is negative or overflows (hostile `#offset` values).
inline bool add_index_offset(long long idx, long long offset, long long& r)
{
  return !__builtin_add_overflow(idx, offset, &r) && r >= 0;
}

/// Quotes a token for an error message (truncated, non-printable bytes escaped).
inline std::string quote(std::string_view tok)
{
  std::string s = "'";
  std::size_t n = 0;
  for(char c : tok)
  {
    if(++n > 40) { s += "..."; break; }
    unsigned char u = static_cast<unsigned char>(c);
    if(u < 32 || u >= 127)
    {
      static const char* hex = "0123456789abcdef";
      s += "\\x"; s += hex[u >> 4]; s += hex[u & 15];
    }
    else
      s += c;
  }
  s += "'";
  return s;
}

/// Reads an istream line by line, counting lines, stripping a final CR and a UTF-8 BOM on line 1.
class Line_reader
{
public:
  Line_reader(std::istream& is, const std::string& file) : is_(is), file_(file) {}

  bool next(std::string& line)
  {
    if(!std::getline(is_, line))
      return false;
    ++line_no_;
    if(!line.empty() && line.back() == '\r')
      line.pop_back();
    if(line_no_ == 1 && line.size() >= 3 && line.compare(0, 3, "\xEF\xBB\xBF") == 0)
      line.erase(0, 3);
    if(line.find('\0') != std::string::npos)
      throw Input_error(file_, line_no_, "binary data (NUL byte) in a text file");
    return true;
  }

  std::size_t line_number() const { return line_no_; }
  const std::string& file() const { return file_; }

  [[noreturn]] void fail(const std::string& reason) const { throw Input_error(file_, line_no_, reason); }

private:
  std::istream& is_;
  std::string file_;
  std::size_t line_no_ = 0;
};

/// Strips a '#' comment (everything from the first '#').
inline std::string_view strip_comment(std::string_view s)
{
  std::size_t p = s.find('#');
  return p == std::string_view::npos ? s : s.substr(0, p);
}

/// Parses the directive `#offset K` (its tokens), failing on the reader's line if it is malformed.
inline long long offset_directive(const std::vector<std::string_view>& tok, const Line_reader& lr)
{
  long long k;
  if(tok.size() != 2 || !parse_int(tok[1], k))
    lr.fail("malformed '#offset' directive (expected '#offset INTEGER')");
  return k;
}

/// Reads the next record of an OBJ-like file into `tok` (a keyword and its arguments), skipping blank lines
/// and comments and applying the `#offset K` directives to `offset`. Returns false at the end of the file.
inline bool next_record(Line_reader& lr, std::string& line, std::vector<std::string_view>& tok, long long& offset)
{
  while(lr.next(line))
  {
    split_tokens(line, tok);
    if(tok.empty()) continue;
    if(tok[0][0] != '#') return true;
    if(tok[0] == "#offset") offset = offset_directive(tok, lr);
  }
  return false;
}

/// Parses the coordinates of a vertex record, `tok[first]` and on: the first three are returned, the others
/// (colours, weights) must be numbers too.
inline std::array<double, 3> vertex_coordinates(const std::vector<std::string_view>& tok, std::size_t first,
                                                const Line_reader& lr)
{
  if(tok.size() < first + 3)
    lr.fail("vertex record with fewer than 3 coordinates");
  std::array<double, 3> p;
  for(std::size_t k = first; k < tok.size(); ++k)
  {
    double x;
    if(!parse_double(tok[k], x))
      lr.fail("cannot parse number " + quote(tok[k]) + " in vertex record");
    if(k < first + 3) p[k - first] = x;
  }
  return p;
}

/// Opens an input file in binary mode; `what` names the kind of file ("a mesh file"). Only regular files
/// (or symbolic links to one) are read: a device such as /dev/zero would be read forever and a FIFO
/// without a writer would block, so both are refused before they are opened.
inline std::ifstream open_input_file(const std::string& filename, const std::string& what)
{
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status st = fs::status(filename, ec);
  if(!fs::exists(st))
    throw Input_error(filename, 0, "no such file");
  if(fs::is_directory(st))
    throw Input_error(filename, 0, "is a directory, not " + what);
  if(!fs::is_regular_file(st))
    throw Input_error(filename, 0, std::string("is not a regular file (") +
                                       (fs::is_fifo(st) ? "a FIFO" : fs::is_socket(st) ? "a socket" : "a device") +
                                       "): only regular files are read as " + what);
  std::ifstream is(filename, std::ios::binary);
  if(!is)
    throw Input_error(filename, 0, "cannot open file for reading");
  return is;
}

inline std::string lower(std::string_view s)
{
  std::string r(s);
  for(char& c : r)
    if(c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return r;
}

} // namespace internal


} // namespace IO
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif // CGAL_SWN_TOOL_IO_ERRORS_H
