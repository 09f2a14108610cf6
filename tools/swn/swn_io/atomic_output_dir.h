// Copyright (c) 2024 The CGAL Surface_winding_numbers contributors.
// SPDX-License-Identifier: MIT
//
// An output directory written all-or-nothing.

#ifndef CGAL_SWN_TOOL_IO_ATOMIC_OUTPUT_DIR_H
#define CGAL_SWN_TOOL_IO_ATOMIC_OUTPUT_DIR_H

#include <atomic>
#include <csignal>
#include <cstring>
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

#include <signal.h>
#include <unistd.h>

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

// The temporary files and created directories of every live Atomic_output_dir, for the signal handler
// of Atomic_output_dir::remove_temporaries_on_signals(): a fixed array (no allocation, no lock), each
// slot free (0), being filled (1), a file (2) or a directory (3). Zero-initialized before main().
struct Signal_cleanup_registry
{
  static constexpr int slots = 64;
  static constexpr std::size_t path_size = 4096;
  std::atomic<int> state[slots];
  char path[slots][path_size];
};
inline Signal_cleanup_registry signal_cleanup_registry;

enum Signal_cleanup_kind { SLOT_FREE = 0, SLOT_FILLING = 1, SLOT_FILE = 2, SLOT_DIRECTORY = 3 };

// Registers `p` (a file or a directory to remove on a signal); returns its slot, or -1 when the array is
// full or the path too long (the object still removes it on destruction, only not on a signal).
inline int register_for_signal_cleanup(const std::string& p, Signal_cleanup_kind kind)
{
  Signal_cleanup_registry& r = signal_cleanup_registry;
  if(p.size() >= Signal_cleanup_registry::path_size) return -1;
  for(int i = 0; i < Signal_cleanup_registry::slots; ++i)
  {
    int expected = SLOT_FREE;
    if(!r.state[i].compare_exchange_strong(expected, SLOT_FILLING)) continue;
    std::memcpy(r.path[i], p.c_str(), p.size() + 1);
    r.state[i].store(kind);
    return i;
  }
  return -1;
}

inline void unregister_for_signal_cleanup(int& slot) noexcept
{
  if(slot >= 0) signal_cleanup_registry.state[slot].store(SLOT_FREE);
  slot = -1;
}

// async-signal-safe: unlink() and rmdir() on the registered paths (files first, directories deepest
// first: they were registered parent first), then the signal's default action (SA_RESETHAND)
extern "C" inline void remove_temporaries_and_reraise(int sig)
{
  Signal_cleanup_registry& r = signal_cleanup_registry;
  for(int i = 0; i < Signal_cleanup_registry::slots; ++i)
    if(r.state[i].load() == SLOT_FILE) ::unlink(r.path[i]);
  for(int i = Signal_cleanup_registry::slots - 1; i >= 0; --i)
    if(r.state[i].load() == SLOT_DIRECTORY) ::rmdir(r.path[i]);
  ::raise(sig);   // delivered when the handler returns, with the default action restored
}

} // namespace internal

/*!
  \brief an output directory written all-or-nothing.

  Every file is first written to a hidden temporary name inside the target directory (created, with its
  missing parents, by the constructor). `commit()` renames all of them into place. If the object is destroyed
  without `commit()` (an exception, an early return), the temporaries are removed, and so are the directories
  the constructor created if they are empty, so that a failed run leaves nothing behind. Renames within one
  directory are atomic per file; if a rename fails in `commit()`, the files renamed before it stay.

  A signal that ends the process skips the destructor: after `remove_temporaries_on_signals()`, SIGINT,
  SIGTERM and SIGHUP remove the temporaries (and the directories created) of every live object first,
  then end the process by the same signal.
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
      if(made) created_.push_back(Directory{*it, internal::register_for_signal_cleanup(it->string(), internal::SLOT_DIRECTORY)});
    }
    if(!fs::is_directory(dir_, ec))
      throw std::runtime_error("output path " + dir_.string() + " is not a directory");
    std::random_device rd;
    std::uniform_int_distribution<unsigned long long> dist;
    std::ostringstream s;
    s << std::hex << (dist(rd) & 0xffffffffffffULL);
    tag_ = s.str();
  }

  /*!
    \brief installs, once per process, the handler of SIGINT, SIGTERM and SIGHUP that removes the
    temporaries and created directories of every live `Atomic_output_dir`, restores the signal's default
    action and raises the signal again (so the process ends as it would have, a shell reporting 128 + the
    signal number). A signal that is ignored stays ignored (`nohup`). Meant for programs (the swn tool),
    not libraries: it replaces the process's handlers of these signals.
  */
  static void remove_temporaries_on_signals()
  {
    for(int sig : {SIGINT, SIGTERM, SIGHUP})
    {
      struct sigaction old_action;
      if(::sigaction(sig, nullptr, &old_action) != 0 || old_action.sa_handler == SIG_IGN) continue;
      struct sigaction action;
      std::memset(&action, 0, sizeof(action));
      action.sa_handler = &internal::remove_temporaries_and_reraise;
      sigemptyset(&action.sa_mask);
      for(int other : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&action.sa_mask, other);
      action.sa_flags = SA_RESETHAND;
      ::sigaction(sig, &action, nullptr);
    }
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
      if(f.name == name)
        throw std::invalid_argument("Atomic_output_dir: file '" + name + "' registered twice");
    std::filesystem::path tmp = dir_ / ("." + name + ".swn-tmp-" + tag_);
    files_.push_back(File{name, tmp, internal::register_for_signal_cleanup(tmp.string(), internal::SLOT_FILE)});
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
      std::filesystem::rename(f.temporary, dir_ / f.name, ec);
      if(ec)
        throw std::runtime_error("cannot move " + f.temporary.string() + " to " + final_path(f.name) + ": " + ec.message());
      f.temporary.clear();
      internal::unregister_for_signal_cleanup(f.slot);
    }
    committed_ = true;
    files_.clear();
    for(Directory& d : created_) internal::unregister_for_signal_cleanup(d.slot);
    created_.clear();
  }

  /// \brief removes the temporaries written so far (and directories created and left empty).
  void abort() noexcept
  {
    if(committed_) return;
    for(auto& f : files_)
    {
      std::error_code ec;
      if(!f.temporary.empty()) std::filesystem::remove(f.temporary, ec);
      internal::unregister_for_signal_cleanup(f.slot);
    }
    files_.clear();
    cleanup_dirs();
  }

  /// \brief the names registered so far (not yet committed).
  std::vector<std::string> names() const
  {
    std::vector<std::string> r;
    for(const auto& f : files_) r.push_back(f.name);
    return r;
  }

private:
  void cleanup_dirs() noexcept
  {
    for(auto it = created_.rbegin(); it != created_.rend(); ++it)
    {
      std::error_code ec;
      std::filesystem::remove(it->path, ec);  // only removes empty directories
      internal::unregister_for_signal_cleanup(it->slot);
    }
    created_.clear();
  }

  struct File { std::string name; std::filesystem::path temporary; int slot; };
  struct Directory { std::filesystem::path path; int slot; };

  std::filesystem::path dir_;
  std::string tag_;
  std::vector<File> files_;
  std::vector<Directory> created_;
  bool committed_ = false;
};

} // namespace IO
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif // CGAL_SWN_TOOL_IO_ATOMIC_OUTPUT_DIR_H
