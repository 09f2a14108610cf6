// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT

#ifndef CGAL_SURFACE_WINDING_NUMBERS_PARAMETERS_H
#define CGAL_SURFACE_WINDING_NUMBERS_PARAMETERS_H

#include <CGAL/Named_function_parameters.h>

namespace CGAL {
namespace Surface_winding_numbers {

/// \cond SKIP_IN_MANUAL
namespace internal_np {
enum nonbounding_chain_map_t { nonbounding_chain_map };
enum nonbounding_chain_real_map_t { nonbounding_chain_real_map };
enum bounding_chain_map_t { bounding_chain_map };
enum winding_number_map_t { winding_number_map };
enum epsilon_t { epsilon };
enum completed_homology_class_t { completed_homology_class };
enum lp_solver_t { lp_solver };
enum use_reduced_residual_t { use_reduced_residual };
enum concurrency_t { concurrency };
enum keep_hodge_factorization_t { keep_hodge_factorization };
enum report_t { report };
enum refine_short_pieces_t { refine_short_pieces };
enum minimum_piece_edges_t { minimum_piece_edges };
enum projection_tolerance_t { projection_tolerance };
enum filter_nonbounding_loops_t { filter_nonbounding_loops };
enum dual_chain_t { dual_chain };
enum face_origin_map_t { face_origin_map };
enum label_anchor_face_t { label_anchor_face };
enum label_confidence_t { label_confidence };
enum confidence_map_t { confidence_map };
enum region_map_t { region_map };
enum second_best_label_map_t { second_best_label_map };
} // namespace internal_np
/// \endcond

/*!
\ingroup PkgSurfaceWindingNumbersRef
Named parameters of the package. CGAL 5.5 gives no way to add chaining members to its named
parameter packs, so every parameter of ours comes as a free function in two forms: `name(x)` starts a
pack, `name(x, np)` adds to the pack `np`. CGAL's own parameters chain as members after ours:
`epsilon(0.01).verbose(true)`, or come first: `epsilon(0.01, CGAL::parameters::verbose(true))`.
*/
namespace parameters {

#define CGAL_SWN_NAMED_PARAMETER(TAG, NAME)                                                          \
  template <class K>                                                                                 \
  CGAL::Named_function_parameters<K, internal_np::TAG> NAME(const K& k)                              \
  {                                                                                                  \
    return CGAL::Named_function_parameters<K, internal_np::TAG>(k);                                  \
  }                                                                                                  \
  template <class K, class T, class Tag, class Base>                                                 \
  CGAL::Named_function_parameters<K, internal_np::TAG, CGAL::Named_function_parameters<T, Tag, Base>> \
  NAME(const K& k, const CGAL::Named_function_parameters<T, Tag, Base>& np)                          \
  {                                                                                                  \
    return CGAL::Named_function_parameters<K, internal_np::TAG,                                      \
                                           CGAL::Named_function_parameters<T, Tag, Base>>(k, np);    \
  }

/// \name Output maps
/// @{

/// edge -> integer: the nonbounding loops G, signed along `halfedge(e, tm)`
CGAL_SWN_NAMED_PARAMETER(nonbounding_chain_map_t, nonbounding_chain_map)
/// edge -> double: the real-valued nonbounding chain g (jumps of the residual function)
CGAL_SWN_NAMED_PARAMETER(nonbounding_chain_real_map_t, nonbounding_chain_real_map)
/// edge -> integer: the closed completion of the bounding curves (jumps of the labels)
CGAL_SWN_NAMED_PARAMETER(bounding_chain_map_t, bounding_chain_map)
/// halfedge -> double: w at the corner `(target(h), face(h))`, NaN at interior curve endpoints
CGAL_SWN_NAMED_PARAMETER(winding_number_map_t, winding_number_map)
/// `std::ref(Solve_report)`: what the solve did, and why it failed
CGAL_SWN_NAMED_PARAMETER(report_t, report)
/// `std::ref(Label_confidence)`: the regions of the labels with their flip costs (\ref SWNConfidence)
CGAL_SWN_NAMED_PARAMETER(label_confidence_t, label_confidence)
/// face -> double: the flip cost of the face's region, its confidence (infinite: no flip of the region alone
/// is feasible)
CGAL_SWN_NAMED_PARAMETER(confidence_map_t, confidence_map)
/// face -> `std::size_t`: the face's region, an index into `Label_confidence::regions`
CGAL_SWN_NAMED_PARAMETER(region_map_t, region_map)
/// face -> integer: the second-best labeling, the labels with the region `Label_confidence::second_best_region`
/// flipped (the labels themselves where there is none)
CGAL_SWN_NAMED_PARAMETER(second_best_label_map_t, second_best_label_map)
/// @}
/// \name Settings
/// @{

/// relative cost of jumps of the residual function across the curve (paper: 0.01)
CGAL_SWN_NAMED_PARAMETER(epsilon_t, epsilon)
/// `true`: the residual problem of a broken curve integrates the closed 1-form of the curve with its gaps
/// closed by shortest paths (default `false`: the harmonic part of the broken curve's, the paper's;
/// \ref SWNBeyondEq11)
CGAL_SWN_NAMED_PARAMETER(completed_homology_class_t, completed_homology_class)
/// `std::ref(lp)` of a model of `SurfaceWindingNumbersLPTraits`
CGAL_SWN_NAMED_PARAMETER(lp_solver_t, lp_solver)

/// `true`: approximate the residual function by the reduced problem of the paper's Sec. 6 (gaps
/// closed by shortest paths, one shift per region); default `false` (the exact Eq. 11)
CGAL_SWN_NAMED_PARAMETER(use_reduced_residual_t, use_reduced_residual)
/// `CGAL::Sequential_tag()` or `false`: the whole solve runs on the calling thread; `CGAL::Parallel_tag()`
/// or `true` (the default): the package may start one more thread, for the
/// Hodge projection's per-mesh part during the first jump-Laplace solve and for the halves of large
/// bands in `LEMON_residual_solver`. The one switch for every thread the package starts; same results
/// either way. (`CGAL::Parallel_if_available_tag` is whichever of the two CGAL makes it; the package's
/// threads are `std::thread`s and need no TBB.)
CGAL_SWN_NAMED_PARAMETER(concurrency_t, concurrency)
/// `true` (the default of `Surface_winding_numbers_solver::solve()`): the per-mesh part of the Hodge
/// projection (the harmonic basis, or the factorized 2-form Laplacian) and the factorized 0-form Laplacian
/// (the jump Laplacian of every curve without interior endpoints) are kept for the next solve on the same
/// mesh; `false` (what `CGAL::surface_winding_numbers()` passes, its solver serving one solve): it is
/// freed as soon as the harmonic part is computed, before the residual step, whose arrays then reuse
/// its memory. Same results either way
CGAL_SWN_NAMED_PARAMETER(keep_hodge_factorization_t, keep_hodge_factorization)
/// `true` (the default): the curves' nonbounding part is filtered out (Hodge projection, residual problem)
/// and returned as G; `false`: the labels are the rounded jump-harmonic function u of the curves, with the
/// shift of the paper's Sec. 3.5.1 (the paper's Fig. 27): a loop around a handle then splits the surface
/// along itself and along a contour of u that does not belong to the input, G and g are zero, and the solve
/// is one jump-Laplace solve on any surface
CGAL_SWN_NAMED_PARAMETER(filter_nonbounding_loops_t, filter_nonbounding_loops)
/// a face (a `face_descriptor`; for `CGAL::polygon_soup_winding_numbers()`, a polygon index) whose label is
/// 0: it fixes the additive constant of the labels of its connected component (the other components keep
/// the default rule, the label covering the largest area is 0). `null_face()` (for soups `std::size_t(-1)`)
/// keeps the default rule everywhere. A face that is not a face of the mesh is refused as bad input
CGAL_SWN_NAMED_PARAMETER(label_anchor_face_t, label_anchor_face)
/// @}
/// \name Settings of `conforming_cut()`
/// @{

/// `true` (the default): split the edges of short chain pieces that end at an interior endpoint
CGAL_SWN_NAMED_PARAMETER(refine_short_pieces_t, refine_short_pieces)
/// chain pieces with fewer edges than this (default 8) that end at an interior endpoint are refined
CGAL_SWN_NAMED_PARAMETER(minimum_piece_edges_t, minimum_piece_edges)
CGAL_SWN_NAMED_PARAMETER(dual_chain_t, dual_chain)
/// face -> face: written for every face after the cut, the face of the input it is a piece of (faces not
/// cut: themselves)
CGAL_SWN_NAMED_PARAMETER(face_origin_map_t, face_origin_map)
/// @}
/// \name Settings of `polylines_to_chain()`
/// @{

/// points of a polyline farther than this from the surface make gaps (default: the mean edge length)
CGAL_SWN_NAMED_PARAMETER(projection_tolerance_t, projection_tolerance)
/// @}

#undef CGAL_SWN_NAMED_PARAMETER

} // namespace parameters
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif
