// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT

#ifndef CGAL_SURFACE_WINDING_NUMBERS_SINGLE_THREADED_BLAS_H
#define CGAL_SURFACE_WINDING_NUMBERS_SINGLE_THREADED_BLAS_H

#include <cstdlib>

#if defined(__GNUC__) && !defined(_WIN32)
// weak: null unless OpenBLAS is loaded in the process (for instance as the BLAS under CHOLMOD)
extern "C" void openblas_set_num_threads(int) __attribute__((weak));
#endif

namespace CGAL {
namespace Surface_winding_numbers {

/*!
\ingroup PkgSurfaceWindingNumbersRef
Asks OpenBLAS, when it is the BLAS under CHOLMOD in this process, to run each of its dense kernels
on the calling thread only, unless the environment variable `OPENBLAS_NUM_THREADS` is set (which
then wins). With the named parameter `concurrency` left at its default, the solver factorizes the
Laplacian of the Hodge projection on a second thread while it factorizes the jump Laplacian; with
OpenBLAS's own thread pool the two factorizations can fight over the cores of a small machine. The
setting is global to the process, which is why the library never changes it by itself: an
application opts in by calling this function. (`OPENBLAS_NUM_THREADS=1` and `OMP_THREAD_LIMIT=1`,
which the libraries read from the environment when they are loaded, do the same from outside the
process; the measured effect on 2 cores is in `benchmark/RESULTS.md` of the source tree.)

\returns `true` if OpenBLAS was found and set to one thread, `false` otherwise (another BLAS, a
platform without weak symbols, or `OPENBLAS_NUM_THREADS` set).
*/
inline bool use_single_threaded_openblas()
{
#if defined(__GNUC__) && !defined(_WIN32)
  if(openblas_set_num_threads == nullptr || std::getenv("OPENBLAS_NUM_THREADS") != nullptr) return false;
  openblas_set_num_threads(1);
  return true;
#else
  return false;
#endif
}

} // namespace Surface_winding_numbers
} // namespace CGAL

#endif
