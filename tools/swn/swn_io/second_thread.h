// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT
//
// The tool's own second thread (its one switch is --sequential, the library's named parameter
// `concurrency` from Python).

#ifndef CGAL_SWN_TOOL_IO_SECOND_THREAD_H
#define CGAL_SWN_TOOL_IO_SECOND_THREAD_H

#include <future>
#include <system_error>

namespace CGAL {
namespace Surface_winding_numbers {
namespace IO {
namespace internal {

// runs `task` on a second thread, or, when `sequential` (or when no thread can be started), in get()
template <class Task>
std::future<void> start_task(bool sequential, Task task)
{
  if(!sequential)
  {
    try { return std::async(std::launch::async, task); }
    catch(const std::system_error&) {}
  }
  return std::async(std::launch::deferred, task);
}

} // namespace internal
} // namespace IO
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif // CGAL_SWN_TOOL_IO_SECOND_THREAD_H
