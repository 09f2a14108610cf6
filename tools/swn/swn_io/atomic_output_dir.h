// Copyright (c) 2024 The CGAL Surface_winding_numbers contributors.
// SPDX-License-Identifier: MIT
//
// An output directory written all-or-nothing.

#ifndef CGAL_SWN_TOOL_IO_ATOMIC_OUTPUT_DIR_H
#define CGAL_SWN_TOOL_IO_ATOMIC_OUTPUT_DIR_H

#include <filesystem>
#include <fstream>
#include <ios>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace IO {

namespace internal {

// writes the file `path` through `writer(std::ostream&)`; `shown` is the name used in error messages
template <class Writer>
void write_to_path(const std::string& path, Writer&& writer, const std::string& shown = std::string())
{
  const std::string& name = shown.empty() ? path : shown;
  std::ofstream os(path, std::ios::binary | std::ios::trunc);
  if(!os)
    throw std::runtime_error("cannot open " + path + " for writing");
  writer(static_cast<std::ostream&>(os));
  os.flush();
  if(!os)
    throw std::runtime_error("write error on " + name);
  os.close();
  if(os.fail())
    throw std::runtime_error("write error on " + name);
}

} // namespace internal

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
    internal::write_to_path(temporary_path(name), writer, final_path(name));
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

} // namespace IO
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif // CGAL_SWN_TOOL_IO_ATOMIC_OUTPUT_DIR_H
