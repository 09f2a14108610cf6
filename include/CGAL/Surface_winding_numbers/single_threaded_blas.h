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
then wins). The solver factorizes the Laplacian of the Hodge projection (vertex or 2-form) on a
second thread while it factorizes the jump Laplacian (named parameter `concurrent_factorizations`); with
OpenBLAS's own thread pool the two factorizations fight over the same cores, with one thread each
they run side by side. Measured on 2 cores: the whole `swn` run on DoubleTorusWithLoops 0.48 s instead
of 0.58 s, the first solve and the Hodge step of a 1.15M-face genus-10 mesh 10.5 s instead of
14-16 s (`benchmark/residual_solvers.md`). The setting is global to the process, which is why
the library never changes it by itself; the `swn` tool calls this function at startup.

Two limits cannot be set from inside a running process, because the libraries read them from the
environment when they are loaded: `OPENBLAS_NUM_THREADS=1` (no OpenBLAS thread pool at all) and
`OMP_THREAD_LIMIT=1` (CHOLMOD 3 of SuiteSparse 5 runs parts of its supernodal factorization in
OpenMP regions of a fixed four threads). With both set, the first solve and the Hodge step together
took 0.14-0.18 s instead of 0.19-0.39 s on DoubleTorusWithLoops (six runs each), and 0.69-0.89 s
instead of 0.92-1.26 s at 188k faces (three runs each), 2 cores. Set them in the environment of
programs that solve on a machine with few cores; the `swn` tool restarts itself once with them on
Linux unless they are set.

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
