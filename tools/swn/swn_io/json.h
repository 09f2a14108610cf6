// Copyright (c) 2024 The CGAL Surface_winding_numbers contributors.
// SPDX-License-Identifier: MIT
//
// A minimal JSON value with a writer, for summary.json.

#ifndef CGAL_SWN_TOOL_IO_JSON_H
#define CGAL_SWN_TOOL_IO_JSON_H

#include <charconv>
#include <cmath>
#include <cstddef>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace IO {

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

#endif // CGAL_SWN_TOOL_IO_JSON_H
