// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT

#ifndef CGAL_SURFACE_WINDING_NUMBERS_SURFACE_WINDING_NUMBERS_SOLVER_H
#define CGAL_SURFACE_WINDING_NUMBERS_SURFACE_WINDING_NUMBERS_SOLVER_H

#include <CGAL/Surface_winding_numbers/Solve_report.h>
#include <CGAL/Surface_winding_numbers/parameters.h>
#include <CGAL/Surface_winding_numbers/internal/confidence.h>
#include <CGAL/Surface_winding_numbers/internal/descriptor_checks.h>
#include <CGAL/Surface_winding_numbers/internal/locality_order.h>
#include <CGAL/Surface_winding_numbers/internal/pipeline.h>
#include <CGAL/Surface_winding_numbers/internal/polygon_tables.h>
#include <CGAL/Surface_winding_numbers/internal/unit_scale.h>
#ifdef CGAL_SWN_USE_CHOLMOD
#include <CGAL/Surface_winding_numbers/internal/supernodal_cholesky.h>
#endif
#ifdef CGAL_USE_GLPK
#include <CGAL/Surface_winding_numbers/GLPK_linear_program_traits.h>
#endif
#ifdef CGAL_SWN_USE_LEMON
#include <CGAL/Surface_winding_numbers/LEMON_residual_solver.h>
#endif

#include <CGAL/Default.h>
#include <CGAL/tags.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Eigen_solver_traits.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/graph/graph_traits.hpp>

#include <exception>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {

/// \cond SKIP_IN_MANUAL
namespace internal {

// Placeholder LP used when no LP backend is available and none was given.
struct No_linear_program_traits
{
  static const char* name() { return "none"; }
  static double infinity() { return std::numeric_limits<double>::infinity(); }
  void resize(std::size_t, std::size_t) {}
  void reserve_A(std::size_t) {}
  void set_q(std::size_t, double) {}
  void set_variable_bounds(std::size_t, double, double) {}
  void set_A(std::size_t, std::size_t, double) {}
  void set_l(std::size_t, double) {}
  void set_u(std::size_t, double) {}
  template <class OutputIterator>
  LP_status solve(OutputIterator)
  {
    throw Solver_failure("this surface needs the residual linear program, but no LP solver is available: "
                         "build with LEMON (CGAL_SWN_USE_LEMON) or GLPK (CGAL_USE_GLPK), or pass one with lp_solver(std::ref(lp))");
  }
};

// the value of the named parameter `concurrency`: a tag or a Boolean
template <class T>
bool allows_threads(const T& concurrency)
{
  if constexpr(std::is_same<T, CGAL::Sequential_tag>::value) return false;
  else if constexpr(std::is_same<T, CGAL::Parallel_tag>::value) return true;
  else return static_cast<bool>(concurrency);
}

#if defined(CGAL_SWN_USE_LEMON)
typedef LEMON_residual_solver Default_linear_program_traits;
#elif defined(CGAL_USE_GLPK)
typedef GLPK_linear_program_traits Default_linear_program_traits;
#else
typedef No_linear_program_traits Default_linear_program_traits;
#endif

typedef CGAL::Eigen_solver_traits<Eigen::SimplicialLDLT<CGAL::Eigen_sparse_matrix<double>::EigenType>>
  Eigen_LDLT_sparse_solver;
#ifdef CGAL_SWN_USE_CHOLMOD
// CHOLMOD's analysis, the package's numeric factorization and solves (internal/supernodal_cholesky.h)
typedef CGAL::Eigen_solver_traits<Supernodal_cholesky<CGAL::Eigen_sparse_matrix<double>::EigenType>>
  CHOLMOD_sparse_solver;
typedef CHOLMOD_sparse_solver Default_sparse_solver;
#else
typedef Eigen_LDLT_sparse_solver Default_sparse_solver;
#endif

// The residual solver a Surface_winding_numbers_solver keeps between its solves: with LEMON, one that
// starts each re-solve from the last answer (LEMON_residual_solver_options::warm_start).
inline std::unique_ptr<Default_linear_program_traits> kept_residual_solver()
{
#if defined(CGAL_SWN_USE_LEMON)
  LEMON_residual_solver::Options options;
  options.warm_start = true;
  return std::unique_ptr<Default_linear_program_traits>(new LEMON_residual_solver(options));
#else
  return std::unique_ptr<Default_linear_program_traits>(new Default_linear_program_traits());
#endif
}

template <class LP>
bool warm_started(const LP& lp)
{
#if defined(CGAL_SWN_USE_LEMON)
  if constexpr(std::is_same<LP, LEMON_residual_solver>::value) return lp.statistics().warm_started;
#endif
  (void)lp;
  return false;
}

// Runs `f` (which fills `rep`), and turns its exceptions into the report's error: Invalid_input is
// bad input, anything else a failed solve. Returns rep.success.
template <class F>
bool run_and_report(Solve_report& rep, F f)
{
  try
  {
    f();
    rep.success = true;
  }
  catch(const Invalid_input& e)
  {
    rep.success = false;
    rep.invalid_input = true;
    rep.error = e.what();
  }
  catch(const std::exception& e)
  {
    rep.success = false;
    rep.error = e.what();
  }
  return rep.success;
}

// One solve of `chain` (per table edge) with the settings of the named parameters: epsilon,
// verbose, use_reduced_residual, completed_homology_class, concurrency, keep_hodge_factorization,
// filter_nonbounding_loops and lp_solver.
// `anchor_face`: the table face of the named parameter label_anchor_face (npos: none), found by the caller.
// `kept_lp`: the residual solver to use when lp_solver is not given (one kept by the caller between
// solves); nullptr: a new one.
template <class LA, class NamedParameters>
Core_result solve_with_parameters(Winding_number_core<LA>& core, const std::vector<double>& chain,
                                  const NamedParameters& np, Solve_report& rep, std::size_t anchor_face = npos,
                                  Default_linear_program_traits* kept_lp = nullptr)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::get_parameter_reference;
  namespace snp = Surface_winding_numbers::internal_np;
  Solve_options options;
  options.epsilon = choose_parameter(get_parameter(np, snp::epsilon), default_epsilon);
  options.completed_class = choose_parameter(get_parameter(np, snp::completed_homology_class), false);
  options.verbose = choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false);
  options.reduced_residual = choose_parameter(get_parameter(np, snp::use_reduced_residual), false);
  options.concurrent = allows_threads(choose_parameter(get_parameter(np, snp::concurrency), CGAL::Parallel_tag()));
  options.keep_hodge_factorization = choose_parameter(get_parameter(np, snp::keep_hodge_factorization), true);
  options.filter_nonbounding = choose_parameter(get_parameter(np, snp::filter_nonbounding_loops), true);
  options.anchor_face = anchor_face;
  const auto run = [&](auto& lp) {
    Core_result r = core.solve(chain, options, lp, rep);
    rep.residual_warm_started = rep.lp_ran && warm_started(lp);
    return r;
  };
  if constexpr(CGAL::parameters::is_default_parameter<NamedParameters, snp::lp_solver_t>::value)
  {
    if(kept_lp) return run(*kept_lp);
    Default_linear_program_traits lp;
    return run(lp);
  }
  else
    return run(get_parameter_reference(np, snp::lp_solver));
}

// The confidence outputs (label_confidence, confidence_map, region_map, second_best_label_map), computed only
// when one of them is asked for; the maps are written for every key of `keys`, which stands for the polygon
// `polygon_of(key)` of the tables. The triangles of a polygon share its region (no curve, G or label jump on
// its diagonals): a polygon's values are those of its first triangle.
template <class NamedParameters, class KeyRange, class PolygonOf>
void write_confidence(const Mesh_tables& m, const Core_result& r, const std::vector<double>& chain,
                      const NamedParameters& np, const KeyRange& keys, PolygonOf polygon_of)
{
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;
  namespace snp = Surface_winding_numbers::internal_np;
  constexpr bool conf = !is_default_parameter<NamedParameters, snp::label_confidence_t>::value;
  constexpr bool cmap = !is_default_parameter<NamedParameters, snp::confidence_map_t>::value;
  constexpr bool rmap = !is_default_parameter<NamedParameters, snp::region_map_t>::value;
  constexpr bool smap = !is_default_parameter<NamedParameters, snp::second_best_label_map_t>::value;
  if constexpr(conf || cmap || rmap || smap)
  {
    const double epsilon = CGAL::parameters::choose_parameter(get_parameter(np, snp::epsilon), default_epsilon);
    const Confidence c = label_confidence(m, chain, r.G, r.labels, epsilon);
    auto triangle = [&](const auto& key) { return m.polygon_triangle(polygon_of(key)); };
    if constexpr(conf)
      CGAL::parameters::get_parameter_reference(np, snp::label_confidence) = public_confidence(m, c, r.labels);
    if constexpr(cmap)
    {
      auto map = get_parameter(np, snp::confidence_map);
      typedef typename boost::property_traits<decltype(map)>::value_type V;
      for(const auto& k : keys) put(map, k, static_cast<V>(c.flips[c.regions.of_face[triangle(k)]].cost));
    }
    if constexpr(rmap)
    {
      auto map = get_parameter(np, snp::region_map);
      typedef typename boost::property_traits<decltype(map)>::value_type V;
      for(const auto& k : keys) put(map, k, static_cast<V>(c.regions.of_face[triangle(k)]));
    }
    if constexpr(smap)
    {
      auto map = get_parameter(np, snp::second_best_label_map);
      typedef typename boost::property_traits<decltype(map)>::value_type V;
      for(const auto& k : keys)
      {
        const std::size_t t = triangle(k), region = c.regions.of_face[t];
        const int flip = region == c.second_best ? c.flips[region].delta : 0;
        put(map, k, static_cast<V>(r.labels[t] + flip));
      }
    }
  }
}

// writes the report to the named parameter `report`, if given
template <class NamedParameters>
void write_report(const NamedParameters& np, const Solve_report& rep)
{
  if constexpr(!CGAL::parameters::is_default_parameter<NamedParameters, Surface_winding_numbers::internal_np::report_t>::value)
    CGAL::parameters::get_parameter_reference(np, Surface_winding_numbers::internal_np::report) = rep;
}

} // namespace internal
/// \endcond

/*!
\ingroup PkgSurfaceWindingNumbersRef

\brief computes surface winding numbers for many curves on one surface mesh.

The constructor extracts the mesh into flat index tables (renumbered for memory locality when the
mesh's own numbering is scattered; results and error messages use the mesh's own order), checks it (faces of at least three distinct
vertices, triangulated internally if they have more, finite coordinates, no zero-area face) and computes the cotan weights. The Hodge projection's per-mesh part
(a basis of the harmonic 1-forms; the factorized 2-form Laplacian on meshes with more than 24
homology classes) is computed the first time a curve with interior endpoints needs it and then
kept (unless `solve()` gets `keep_hodge_factorization(false)`). The jump Laplacian depends on the curve's
interior endpoints: for curves without them (closed loops, and curves that end on the border) it is the
mesh's 0-form Laplacian, whose factorization is kept, so that such curves after the first cost only
solves (`Solve_report::jump_laplacian_reused`). For a curve with interior endpoints (a broken stroke),
the kept factorization serves too, with a low-rank update for the endpoints and their neighbours
(`Solve_report::jump_laplacian_update_rank`, at most 96; beyond that, or where taking the endpoints out
splits a component, the jump Laplacian is factorized for that curve).
The residual step (paper Eq. 11) of each solve after the first starts from the last solve's answer
(with its default residual solver, `LEMON_residual_solver` with `Options::warm_start`;
`Solve_report::residual_warm_started`): only what changed near the changed curve is repaired, and the
answer is certified optimal as a fresh solve's is. Where Eq. 11 has several optima (ties, on very
regular meshes) it may be another one than the free function's; pass `lp_solver(std::ref(s))` with a
solver of your own to choose.

The mesh must not be modified while the solver is in use.

\tparam TriangleMesh a model of `FaceListGraph`; faces of more than three sides are triangulated
        internally (\ref SWNAPISoup)
\tparam SparseLinearSolver a model of `SparseLinearAlgebraWithFactorTraits_d` for symmetric positive
        definite systems; its instances are default-constructed (one per factorization).
        Default: `CGAL::Eigen_solver_traits` over the package's supernodal Cholesky factorization on CHOLMOD's symbolic analysis (nested-dissection numbering above 150k unknowns, AMD below; the dense blocks with Eigen's kernels on the calling thread, not with the process's BLAS)
        when the package is built with CHOLMOD (`CGAL_SWN_USE_CHOLMOD`), otherwise
        `CGAL::Eigen_solver_traits<Eigen::SimplicialLDLT<CGAL::Eigen_sparse_matrix<double>::%EigenType> >`.
*/
template <class TriangleMesh, class SparseLinearSolver = CGAL::Default>
class Surface_winding_numbers_solver
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::edge_descriptor edge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename CGAL::Default::Get<SparseLinearSolver, internal::Default_sparse_solver>::type LA;
  typedef typename boost::property_map<TriangleMesh, CGAL::dynamic_vertex_property_t<std::size_t>>::const_type VIM;
  typedef typename boost::property_map<TriangleMesh, CGAL::dynamic_edge_property_t<std::size_t>>::const_type EIM;
  typedef typename boost::property_map<TriangleMesh, CGAL::dynamic_face_property_t<std::size_t>>::const_type FIM;

public:
  /*!
  builds the solver for `tm`.
  \tparam NamedParameters a sequence of named parameters
  \param tm the mesh; it must outlive the solver and must not be modified while the solver is in use
  \param np optional: `vertex_point_map` (default: the internal point map of `tm`) and `geom_traits`
         (default: the kernel of the point type), as everywhere in CGAL.

  If the mesh is invalid, `is_valid()` is `false`, `report().error` says why, and `solve()` fails.
  */
  template <class NamedParameters = CGAL::parameters::Default_named_parameters>
  explicit Surface_winding_numbers_solver(const TriangleMesh& tm,
                                          const NamedParameters& np = CGAL::parameters::default_values())
    : tm_(tm), vim_(get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm)),
      eim_(get(CGAL::dynamic_edge_property_t<std::size_t>(), tm)),
      fim_(get(CGAL::dynamic_face_property_t<std::size_t>(), tm))
  {
    using CGAL::parameters::choose_parameter;
    using CGAL::parameters::get_parameter;
    typedef typename GetVertexPointMap<TriangleMesh, NamedParameters>::const_type VPM;
    typedef typename GetGeomTraits<TriangleMesh, NamedParameters>::type Traits;
    VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                               get_const_property_map(CGAL::vertex_point, tm));
    Traits traits = choose_parameter<Traits>(get_parameter(np, CGAL::internal_np::geom_traits));
    try
    {
      internal::Stopwatch clock;
      core_.reset(new internal::Winding_number_core<LA>(mesh_tables(vpm, traits)));
      core_->fill_mesh_report(report_);
      report_.time_mesh = clock.lap();
    }
    catch(const Invalid_input& e)
    {
      report_.error = e.what();
      report_.invalid_input = true;
    }
    catch(const std::exception& e)
    {
      report_.error = e.what();
    }
  }

  /// `true` if the mesh passed the checks of the constructor
  bool is_valid() const { return core_ != nullptr; }

  /// what the last `solve()` (or the constructor) did
  const Solve_report& report() const { return report_; }

  /*!
  computes the winding number labels of the curve `chain_map` and writes them to `label_map`.
  \tparam ChainMap a model of `ReadablePropertyMap`, key `edge_descriptor`, integer value: the signed
          number of times the curves traverse the edge, positive along `halfedge(e, tm)`
  \tparam LabelMap a model of `WritablePropertyMap`, key `face_descriptor`, integer value
  \tparam NamedParameters a sequence of named parameters
  \param chain_map the input curves, as an integer 1-chain on the edges
  \param label_map receives the winding number label W of every face
  \param np optional named parameters among `nonbounding_chain_map`, `nonbounding_chain_real_map`,
         `bounding_chain_map`, `winding_number_map`, `epsilon`, `lp_solver`, `use_reduced_residual`,
         `completed_homology_class`, `filter_nonbounding_loops`, `label_anchor_face`, `label_confidence`, `confidence_map`, `region_map`,
         `second_best_label_map`, `concurrency`, `keep_hodge_factorization`, `report`, `verbose` (see
         `CGAL::surface_winding_numbers()`).
  \pre `chain_map`, `label_map` and the output maps of `np` have a value for every element of `tm` they
       are keyed by. A `Surface_mesh` property map with fewer entries (a map of another mesh) is detected:
       the solve fails as on bad input, before any map is read or written.
  \returns `true` on success. On failure no output map is written and `report().error` says why.
  */
  template <class ChainMap, class LabelMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
  bool solve(const ChainMap& chain_map, LabelMap label_map,
             const NamedParameters& np = CGAL::parameters::default_values())
  {
    const std::string construction_error = report_.error;
    Solve_report rep;
    if(core_) core_->fill_mesh_report(rep);
    rep.time_mesh = report_.time_mesh;   // every report carries the construction's time
    internal::run_and_report(rep, [&] {
      if(!core_) throw Invalid_input(construction_error);   // the mesh was rejected by the constructor
      check_maps(chain_map, label_map, np);
      std::vector<double> chain(core_->tables().ne, 0.);
      for(edge_descriptor e : edges(tm_)) chain[get(eim_, e)] = double(get(chain_map, e));
      if(!lp_) lp_ = internal::kept_residual_solver();
      const internal::Core_result r = internal::solve_with_parameters(*core_, chain, np, rep, anchor_face(np), lp_.get());
      internal::Stopwatch clock;
      write_outputs(r, label_map, np);
      write_confidence(r, chain, np);
      rep.time_output_maps = clock.lap();
    });
    report_ = rep;
    internal::write_report(np, rep);
    return rep.success;
  }

  /// \cond SKIP_IN_MANUAL
  const internal::Mesh_tables& tables() const { return core_->tables(); }
  internal::Winding_number_core<LA>& core() { return *core_; }
  std::size_t vertex_index(vertex_descriptor v) const { return get(vim_, v); }
  std::size_t edge_index(edge_descriptor e) const { return get(eim_, e); }
  std::size_t face_index(face_descriptor f) const { return get(fim_, f); }
  /// \endcond

private:
  // the table face of the named parameter label_anchor_face (npos if none or null_face()); a face not in faces(tm_) is refused
  template <class NamedParameters>
  std::size_t anchor_face(const NamedParameters& np) const
  {
    namespace snp = Surface_winding_numbers::internal_np;
    if constexpr(CGAL::parameters::is_default_parameter<NamedParameters, snp::label_anchor_face_t>::value)
      return internal::npos;
    else
    {
      const face_descriptor a = CGAL::parameters::get_parameter(np, snp::label_anchor_face);
      if(a == GT::null_face()) return internal::npos;
      for(face_descriptor f : faces(tm_))
        if(f == a) return core_->tables().polygon_triangle(get(fim_, f));
      throw Invalid_input("label_anchor_face: the face is not a face of the mesh");
    }
  }

  template <class VPM, class Traits>
  internal::Mesh_tables mesh_tables(const VPM& vpm, const Traits& traits)
  {
    internal::Mesh_tables m;
    auto x = traits.compute_x_3_object();
    auto y = traits.compute_y_3_object();
    auto z = traits.compute_z_3_object();
    std::size_t i = 0;
    for(vertex_descriptor v : vertices(tm_))
    {
      put(vim_, v, i++);
      const auto& p = get(vpm, v);
      m.points.push_back(CGAL::to_double(x(p)));
      m.points.push_back(CGAL::to_double(y(p)));
      m.points.push_back(CGAL::to_double(z(p)));
    }
    m.nv = i;
    i = 0;
    for(edge_descriptor e : edges(tm_))
    {
      put(eim_, e, i++);
      const halfedge_descriptor h = halfedge(e, tm_);
      m.ev.push_back(get(vim_, source(h, tm_)));
      m.ev.push_back(get(vim_, target(h, tm_)));
    }
    m.ne = i;
    bool triangles = true;
    for(face_descriptor f : faces(tm_)) triangles = triangles && degree(f, tm_) == 3;
    if(!triangles) return polygon_mesh_tables(std::move(m.points));   // scaled there
    m.point_scale = internal::scale_to_unit(m.points);   // exact; the method is scale invariant
    i = 0;
    for(face_descriptor f : faces(tm_))
    {
      put(fim_, f, i++);
      halfedge_descriptor h = halfedge(f, tm_);
      for(int k = 0; k < 3; ++k)
      {
        m.fv.push_back(get(vim_, source(h, tm_)));
        m.fe.push_back(get(eim_, edge(h, tm_)));
        h = next(h, tm_);
      }
    }
    m.nf = i;
    if(m.nf == 0) throw Invalid_input("the mesh has no face");
    // a scattered numbering is replaced by a cache-friendly one, which the index maps follow
    if(!internal::numbering_is_scattered(m))
    {
      internal::finalize_mesh_tables(m);
      return m;
    }
    const internal::Table_numbering n = internal::locality_numbering(m);
    for(vertex_descriptor v : vertices(tm_)) put(vim_, v, n.vertex[get(vim_, v)]);
    for(edge_descriptor e : edges(tm_)) put(eim_, e, n.edge[get(eim_, e)]);
    for(face_descriptor f : faces(tm_)) put(fim_, f, n.face[get(fim_, f)]);
    return internal::renumbered_mesh_tables(m, n);
  }

  // A mesh with faces of more than three sides: every face is triangulated (polygon_tables.h), the
  // faces keep their order (the polygons), the edges are mapped to the tables' input edges.
  internal::Mesh_tables polygon_mesh_tables(std::vector<double> xyz)
  {
    std::vector<std::vector<std::size_t>> polygons;
    std::size_t i = 0;
    for(face_descriptor f : faces(tm_))
    {
      put(fim_, f, i++);
      polygons.emplace_back();
      for(halfedge_descriptor h : halfedges_around_face(halfedge(f, tm_), tm_)) polygons.back().push_back(get(vim_, source(h, tm_)));
    }
    if(polygons.empty()) throw Invalid_input("the mesh has no face");
    internal::Mesh_tables m = internal::polygon_mesh_tables(std::move(xyz), polygons);
    std::map<std::pair<std::size_t, std::size_t>, std::size_t> table_edge;
    for(std::size_t e = 0; e < m.ne; ++e)
      table_edge[std::make_pair((std::min)(m.ev[2 * e], m.ev[2 * e + 1]), (std::max)(m.ev[2 * e], m.ev[2 * e + 1]))] = e;
    for(edge_descriptor e : edges(tm_))
    {
      const std::size_t a = get(vim_, source(halfedge(e, tm_), tm_)), b = get(vim_, target(halfedge(e, tm_), tm_));
      const auto it = table_edge.find(std::make_pair((std::min)(a, b), (std::max)(a, b)));
      if(it == table_edge.end()) throw Invalid_input("edge (" + std::to_string(a) + ", " + std::to_string(b) + ") bounds no face");
      // the table edge must run along halfedge(e): its values are signed that way
      if(m.ev[2 * it->second] != a) std::swap(m.ev[2 * it->second], m.ev[2 * it->second + 1]);
      put(eim_, e, it->second);
    }
    internal::finalize_mesh_tables(m);   // again: the edges' directions may have changed
    return m;
  }

  // writes per-edge values to the edge map given for `tag`, if one was given
  // maps of another (smaller) Surface_mesh are refused before anything is read or written
  template <class Map, class KeyRange>
  static void check_map(const Map& map, const KeyRange& keys, const char* what, const char* elements)
  {
    const std::string error = internal::map_coverage_error(map, keys, what, elements);
    if(!error.empty()) throw Invalid_input(error);
  }
  template <class Tag, class NamedParameters, class KeyRange>
  static void check_map(const NamedParameters& np, Tag tag, const KeyRange& keys, const char* what, const char* elements)
  {
    if constexpr(!CGAL::parameters::is_default_parameter<NamedParameters, Tag>::value)
      check_map(CGAL::parameters::get_parameter(np, tag), keys, what, elements);
  }
  template <class ChainMap, class LabelMap, class NamedParameters>
  void check_maps(const ChainMap& chain_map, const LabelMap& label_map, const NamedParameters& np) const
  {
    namespace snp = Surface_winding_numbers::internal_np;
    check_map(chain_map, edges(tm_), "the chain map", "edges");
    check_map(label_map, faces(tm_), "the label map", "faces");
    check_map<snp::nonbounding_chain_map_t>(np, snp::nonbounding_chain_map, edges(tm_), "nonbounding_chain_map", "edges");
    check_map<snp::nonbounding_chain_real_map_t>(np, snp::nonbounding_chain_real_map, edges(tm_), "nonbounding_chain_real_map", "edges");
    check_map<snp::bounding_chain_map_t>(np, snp::bounding_chain_map, edges(tm_), "bounding_chain_map", "edges");
    check_map<snp::winding_number_map_t>(np, snp::winding_number_map, halfedges(tm_), "winding_number_map", "halfedges");
    check_map<snp::confidence_map_t>(np, snp::confidence_map, faces(tm_), "confidence_map", "faces");
    check_map<snp::region_map_t>(np, snp::region_map, faces(tm_), "region_map", "faces");
    check_map<snp::second_best_label_map_t>(np, snp::second_best_label_map, faces(tm_), "second_best_label_map", "faces");
  }

  // the confidence outputs, per face of tm_ (its polygon of the tables)
  template <class NamedParameters>
  void write_confidence(const internal::Core_result& r, const std::vector<double>& chain, const NamedParameters& np) const
  {
    internal::write_confidence(core_->tables(), r, chain, np, faces(tm_), [&](face_descriptor f) { return std::size_t(get(fim_, f)); });
  }

  template <class Tag, class NamedParameters, class Values>
  void write_edge_values(const NamedParameters& np, Tag tag, const Values& values) const
  {
    if constexpr(!CGAL::parameters::is_default_parameter<NamedParameters, Tag>::value)
    {
      auto map = CGAL::parameters::get_parameter(np, tag);
      typedef typename boost::property_traits<decltype(map)>::value_type V;
      for(edge_descriptor e : edges(tm_)) put(map, e, static_cast<V>(values[get(eim_, e)]));
    }
  }

  template <class LabelMap, class NamedParameters>
  void write_outputs(const internal::Core_result& r, LabelMap& label_map, const NamedParameters& np) const
  {
    using CGAL::parameters::get_parameter;
    using CGAL::parameters::is_default_parameter;
    namespace snp = Surface_winding_numbers::internal_np;
    typedef typename boost::property_traits<LabelMap>::value_type Label;
    const internal::Mesh_tables& m = core_->tables();
    for(face_descriptor f : faces(tm_)) put(label_map, f, static_cast<Label>(r.labels[m.polygon_triangle(get(fim_, f))]));

    write_edge_values<snp::nonbounding_chain_map_t>(np, snp::nonbounding_chain_map, r.G);
    write_edge_values<snp::nonbounding_chain_real_map_t>(np, snp::nonbounding_chain_real_map, r.g);
    write_edge_values<snp::bounding_chain_map_t>(np, snp::bounding_chain_map, r.bounding);
    if constexpr(!is_default_parameter<NamedParameters, snp::winding_number_map_t>::value)
    {
      auto map = get_parameter(np, snp::winding_number_map);
      typedef typename boost::property_traits<decltype(map)>::value_type V;
      for(face_descriptor f : faces(tm_))
      {
        // side k of the face is the halfedge from corner k to corner k+1: its target is corner k+1
        const std::size_t fi = get(fim_, f), d = degree(f, tm_);
        std::size_t k = 0;
        for(halfedge_descriptor h : halfedges_around_face(halfedge(f, tm_), tm_))
          put(map, h, static_cast<V>(r.w[m.polygon_corner_at(fi, ++k % d)]));
      }
    }
  }

  const TriangleMesh& tm_;
  VIM vim_;
  EIM eim_;
  FIM fim_;
  std::unique_ptr<internal::Winding_number_core<LA>> core_;
  std::unique_ptr<internal::Default_linear_program_traits> lp_;   // kept between solves (warm starts)
  Solve_report report_;
};

} // namespace Surface_winding_numbers
} // namespace CGAL

#endif
