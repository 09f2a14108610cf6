// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT

#ifndef CGAL_SURFACE_WINDING_NUMBERS_H
#define CGAL_SURFACE_WINDING_NUMBERS_H

#include <CGAL/Surface_winding_numbers/Solve_report.h>
#include <CGAL/Surface_winding_numbers/Surface_winding_numbers_solver.h>
#include <CGAL/Surface_winding_numbers/chain_helpers.h>
#include <CGAL/Surface_winding_numbers/parameters.h>

#include <CGAL/Named_function_parameters.h>

#include <functional>
#include <type_traits>

namespace CGAL {

/*!
\ingroup PkgSurfaceWindingNumbersRef

\brief computes the surface winding numbers of a curve on a surface mesh (Feng, Gillespie and
Crane, "Winding Numbers on Discrete Surfaces", SIGGRAPH 2023).

The curve is an integer 1-chain on the edges of `tm`: it may be broken (gaps), self-intersecting,
end on the border of the mesh, and mix loops that bound regions with loops around handles that bound
nothing. The function writes, for every face, the integer winding number W of the bounding part of
the curve: crossing an edge from its right to its left, W increases by the chain value there, so
the inside of a counter-clockwise loop is one higher than the outside. Gaps are closed and the
nonbounding loops (around handles, or between border components) are filtered out.

W is defined up to one integer per connected component; the normalization used is: in every
connected component, the label covering the largest area is 0, unless the named parameter
`label_anchor_face` names a face of the component, whose label is then 0.

\tparam TriangleMesh a model of `FaceListGraph`; faces of more than three sides are triangulated
        internally and every output stays on the mesh's own faces and edges (\ref SWNAPISoup)
\tparam ChainMap a model of `ReadablePropertyMap` with key `boost::graph_traits<TriangleMesh>::%edge_descriptor`
        and an integer value type: the signed number of times the curves traverse the edge,
        positive along `halfedge(e, tm)` (from its source to its target) for the descriptor `e` met while
        iterating over `edges(tm)`. Beware: with CGAL 5.5's `Surface_mesh`, `halfedge(edge(h, tm), tm)` returns
        `h` itself, whichever of the two halfedges `h` is, so `chain[edge(h)] += (halfedge(edge(h)) == h ? 1 : -1)`
        is wrong; use `Surface_winding_numbers::add_halfedges_to_chain()` or compare with the halfedge of the
        edge as met in `edges(tm)`.
\tparam LabelMap a model of `WritablePropertyMap` with key
        `boost::graph_traits<TriangleMesh>::%face_descriptor` and an integer value type
\tparam NamedParameters a sequence of named parameters

\param tm the mesh
\param chain the input curves
\param labels receives W for every face
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{a property map associating points to the vertices of `tm`}
    \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `%Point_3` as value type}
    \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
  \cgalParamNEnd
  \cgalParamNBegin{geom_traits}
    \cgalParamDescription{an instance of a geometric traits class}
    \cgalParamType{a model of `Kernel`}
    \cgalParamDefault{a \cgal Kernel deduced from the point type, using `CGAL::Kernel_traits`}
  \cgalParamNEnd
  \cgalParamNBegin{sparse_linear_solver}
    \cgalParamDescription{the solver type used for the symmetric positive definite systems (its instances are default-constructed)}
    \cgalParamType{a model of `SparseLinearAlgebraWithFactorTraits_d`}
    \cgalParamDefault{`CGAL::Eigen_solver_traits` over the package's supernodal Cholesky factorization on CHOLMOD's symbolic analysis (in the package's nested-dissection numbering of the unknowns above 150k of them, AMD ordering below; the dense blocks with Eigen's kernels on the calling thread, whatever the thread settings of the process's BLAS) when the package is built with CHOLMOD (`CGAL_SWN_USE_CHOLMOD`), `CGAL::Eigen_solver_traits<Eigen::SimplicialLDLT<CGAL::Eigen_sparse_matrix<double>::%EigenType> >` otherwise}
  \cgalParamNEnd
  \cgalParamNBegin{verbose}
    \cgalParamDescription{prints the steps and their timings to `std::cerr`}
    \cgalParamType{Boolean}
    \cgalParamDefault{`false`}
  \cgalParamNEnd
  \cgalParamNBegin{Surface_winding_numbers::parameters::nonbounding_chain_map}
    \cgalParamDescription{receives the integer nonbounding loops G (same sign convention as `chain`): closed loops, the rounding of g where that is closed (user manual, \ref SWNClosedG)}
    \cgalParamType{a model of `WritablePropertyMap`, key `edge_descriptor`, integer value}
    \cgalParamDefault{not written}
  \cgalParamNEnd
  \cgalParamNBegin{Surface_winding_numbers::parameters::nonbounding_chain_real_map}
    \cgalParamDescription{receives the real-valued nonbounding chain g, the jumps of the residual function}
    \cgalParamType{a model of `WritablePropertyMap`, key `edge_descriptor`, value `double`}
    \cgalParamDefault{not written}
  \cgalParamNEnd
  \cgalParamNBegin{Surface_winding_numbers::parameters::bounding_chain_map}
    \cgalParamDescription{receives the closed completion of the bounding curves, the jumps of W}
    \cgalParamType{a model of `WritablePropertyMap`, key `edge_descriptor`, integer value}
    \cgalParamDefault{not written}
  \cgalParamNEnd
  \cgalParamNBegin{Surface_winding_numbers::parameters::winding_number_map}
    \cgalParamDescription{receives w at the corner `(target(h), face(h))` of every halfedge `h` not on the border, shifted like the labels so that W is the rounded mean of w over a face; NaN at interior endpoints of the curve}
    \cgalParamType{a model of `WritablePropertyMap`, key `halfedge_descriptor`, value `double`}
    \cgalParamDefault{not written}
  \cgalParamNEnd
  \cgalParamNBegin{Surface_winding_numbers::parameters::label_confidence}
    \cgalParamDescription{receives the regions of the labels (faces connected across edges where the curves, G and the jump of W are all zero) with their flip costs: how much Eq. 11's objective on the integer loops grows when a region's label changes by one, everything else fixed, and which flip makes the second-best labeling (user manual, \ref SWNConfidence). Computed only when this or one of the three maps below is given}
    \cgalParamType{`std::reference_wrapper<CGAL::Surface_winding_numbers::Label_confidence>`}
    \cgalParamDefault{not written}
  \cgalParamNEnd
  \cgalParamNBegin{Surface_winding_numbers::parameters::confidence_map}
    \cgalParamDescription{receives for every face the flip cost of its region (`Label_region::flip_cost`): small means another labeling of that region explains the input almost as well; infinite when no flip of the region alone is feasible}
    \cgalParamType{a model of `WritablePropertyMap`, key `face_descriptor`, value `double`}
    \cgalParamDefault{not written}
  \cgalParamNEnd
  \cgalParamNBegin{Surface_winding_numbers::parameters::region_map}
    \cgalParamDescription{receives for every face its region, an index into `Label_confidence::regions`}
    \cgalParamType{a model of `WritablePropertyMap`, key `face_descriptor`, integer value}
    \cgalParamDefault{not written}
  \cgalParamNEnd
  \cgalParamNBegin{Surface_winding_numbers::parameters::second_best_label_map}
    \cgalParamDescription{receives the second-best labeling: the labels with the region `Label_confidence::second_best_region` changed by its `flip_delta` (not normalized again); the labels themselves where there is no such region}
    \cgalParamType{a model of `WritablePropertyMap`, key `face_descriptor`, integer value}
    \cgalParamDefault{not written}
  \cgalParamNEnd
  \cgalParamNBegin{Surface_winding_numbers::parameters::epsilon}
    \cgalParamDescription{relative cost of jumps of the residual function across the curve against jumps elsewhere (paper Eq. 11)}
    \cgalParamType{`double`, positive}
    \cgalParamDefault{`0.01`}
  \cgalParamNEnd
  \cgalParamNBegin{Surface_winding_numbers::parameters::lp_solver}
    \cgalParamDescription{the solver of the residual problem (Eq. 11), passed with `std::ref()`: either a direct residual solver, or the traits of a general linear program solver to which the problem is given as a linear program}
    \cgalParamType{a model of `SurfaceWindingNumbersResidualSolver` or of `SurfaceWindingNumbersLPTraits`}
    \cgalParamDefault{`CGAL::Surface_winding_numbers::LEMON_residual_solver` when the package is built with LEMON (`CGAL_SWN_USE_LEMON`), otherwise `CGAL::Surface_winding_numbers::GLPK_linear_program_traits` (`CGAL_USE_GLPK`)}
    \cgalParamExtra{only used when a component of the mesh is neither a disk nor a sphere}
  \cgalParamNEnd
  \cgalParamNBegin{Surface_winding_numbers::parameters::use_reduced_residual}
    \cgalParamDescription{approximates the residual function by the reduced problem of the paper's Sec. 6: the gaps are closed by shortest paths (by length, over edges off the curve), and one shift per region between the completed curves is optimized (Eq. 11's costs, without its bounds); much smaller than Eq. 11, but periods of the residual around handles inside a region are ignored}
    \cgalParamType{Boolean}
    \cgalParamDefault{`false`}
  \cgalParamNEnd
  \cgalParamNBegin{Surface_winding_numbers::parameters::completed_homology_class}
    \cgalParamDescription{`true`: for a curve with interior endpoints, the residual problem (Eq. 11) integrates the Darboux derivative of the jump-harmonic function of the curve with its gaps closed by shortest paths (as in `use_reduced_residual`), a closed 1-form with the integer periods of the completed curve, instead of the harmonic part of the broken curve's; the nonbounding loops G are then in the homology class of the completed curve. Costs and bounds of Eq. 11, the labels' second solve and everything else are unchanged; curves without interior endpoints and disks and spheres are not affected. Not the paper's method (\ref SWNBeyondEq11)}
    \cgalParamType{Boolean}
    \cgalParamDefault{`false` (the paper's Eq. 11 on the harmonic part)}
  \cgalParamNEnd
  \cgalParamNBegin{Surface_winding_numbers::parameters::filter_nonbounding_loops}
    \cgalParamDescription{`false`: the labels are the rounded jump-harmonic function u (with the shift of the paper's Sec. 3.5.1), without the filtering of the nonbounding part of the curves (the paper's Fig. 27): a loop around a handle then splits the surface along itself and along a contour of u that is not in the input; G and g are zero, and the solve is one jump-Laplace solve on any surface}
    \cgalParamType{Boolean}
    \cgalParamDefault{`true`}
  \cgalParamNEnd
  \cgalParamNBegin{Surface_winding_numbers::parameters::label_anchor_face}
    \cgalParamDescription{a face whose label is 0: fixes the additive constant of W on its connected component (for instance a face known to be outside, so that outside is 0 after a stamp); the other components keep the largest-area rule. The differences of labels, G, g and the bounding chain do not depend on it; `winding_number_map` is shifted with the labels. `boost::graph_traits<TriangleMesh>::%null_face()` keeps the default rule. A face that is neither in `faces(tm)` nor the null face makes the solve fail as on bad input}
    \cgalParamType{`boost::graph_traits<TriangleMesh>::%face_descriptor`}
    \cgalParamDefault{none: the label covering the largest area of each component is 0}
  \cgalParamNEnd
  \cgalParamNBegin{Surface_winding_numbers::parameters::concurrency}
    \cgalParamDescription{the one switch for the package's threads: with `CGAL::Parallel_tag()` (or `true`) one more thread (`std::async`) may compute the per-mesh part of the Hodge projection (the harmonic basis, or the factorized 2-form Laplacian on meshes with more than 24 homology classes) while the first jump-Laplace system is factorized and solved, and solve the second half of large bands in `LEMON_residual_solver`; with `CGAL::Sequential_tag()` (or `false`) everything runs on the calling thread, for instance if the sparse linear solver cannot run two factorizations at once (always so without `CGAL_HAS_THREADS`). Same results either way}
    \cgalParamType{`CGAL::Sequential_tag`, `CGAL::Parallel_tag` or a Boolean}
    \cgalParamDefault{`CGAL::Parallel_tag()`}
  \cgalParamNEnd
  \cgalParamNBegin{Surface_winding_numbers::parameters::keep_hodge_factorization}
    \cgalParamDescription{ignored here: this function solves once, and frees the per-mesh part of the Hodge projection as soon as the harmonic part is computed, before the residual step (lower peak memory). `Surface_winding_numbers_solver::solve()` keeps it by default for the next solve on the same mesh}
    \cgalParamType{Boolean}
    \cgalParamDefault{`false`}
  \cgalParamNEnd
  \cgalParamNBegin{Surface_winding_numbers::parameters::report}
    \cgalParamDescription{receives what the solve did (sizes, topology, LP size and objective, timings) and, on failure, why}
    \cgalParamType{`std::reference_wrapper<CGAL::Surface_winding_numbers::Solve_report>`}
    \cgalParamDefault{not written}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns `true` on success. On failure (a face with fewer than three vertices or a repeated one, empty mesh, non-finite coordinates,
zero-area face, nonzero chain value on a border edge, failed factorization or linear program),
no output map is written, and the named parameter `report` tells why.

\sa `CGAL::Surface_winding_numbers::Surface_winding_numbers_solver`
*/
template <class TriangleMesh, class ChainMap, class LabelMap,
          class NamedParameters = parameters::Default_named_parameters>
bool surface_winding_numbers(const TriangleMesh& tm, const ChainMap& chain, LabelMap labels,
                             const NamedParameters& np = parameters::default_values())
{
  using parameters::get_parameter;
  typedef typename internal_np::Lookup_named_param_def<internal_np::sparse_linear_solver_t, NamedParameters,
                                                       CGAL::Default>::type Solver_param;
  typedef std::conditional_t<std::is_same<Solver_param, CGAL::Default>::value, CGAL::Default,
                             std::remove_cv_t<std::remove_reference_t<Solver_param>>> LA;
  Surface_winding_numbers::Surface_winding_numbers_solver<TriangleMesh, LA> solver(tm, np);
  // one solve: the per-mesh part of the Hodge projection is freed before the residual step
  return solver.solve(chain, labels, Surface_winding_numbers::parameters::keep_hodge_factorization(false, np));
}

} // namespace CGAL

#include <CGAL/Surface_winding_numbers/polygon_soup_winding_numbers.h>

#endif
