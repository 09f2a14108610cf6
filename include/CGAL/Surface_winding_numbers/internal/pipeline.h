// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT
//
// The whole method on flat tables: u (jump Laplace) -> omega (Darboux) -> gamma (Hodge) ->
// v (residual) -> w (second solve) -> W, G, bounding chain.

#ifndef CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_PIPELINE_H
#define CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_PIPELINE_H

#include <CGAL/config.h>
#include <CGAL/Surface_winding_numbers/Solve_report.h>
#include <CGAL/Surface_winding_numbers/internal/cotan_weights.h>
#include <CGAL/Surface_winding_numbers/internal/derivatives.h>
#include <CGAL/Surface_winding_numbers/internal/harmonic_part.h>
#include <CGAL/Surface_winding_numbers/internal/jump_laplace.h>
#include <CGAL/Surface_winding_numbers/internal/nested_dissection.h>
#include <CGAL/Surface_winding_numbers/internal/mesh_tables.h>
#include <CGAL/Surface_winding_numbers/internal/nonbounding_chain.h>
#include <CGAL/Surface_winding_numbers/internal/reduced_residual.h>
#include <CGAL/Surface_winding_numbers/internal/residual.h>
#include <CGAL/Surface_winding_numbers/internal/winding_number.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <future>
#include <iostream>
#include <limits>
#include <memory>
#include <string>
#include <system_error>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace internal {

// The default of the named parameter epsilon (Eq. 11's relative cost of residual jumps across the curve).
inline constexpr double default_epsilon = 0.01;

struct Solve_options
{
  double epsilon = default_epsilon;
  bool completed_class = false;     // gamma from the curve with its gaps closed by shortest paths; false: the paper's
  bool verbose = false;
  bool reduced_residual = false;   // paper Sec. 6 instead of the exact Eq. 11
  bool concurrent = true;   // a second thread (named parameter concurrency): the Hodge projection's per-mesh part, the residual solver's
  bool keep_hodge_factorization = true;    // false: freed after the harmonic part, before the residual
  bool filter_nonbounding = true;   // false: the labels contour u itself (paper Sec. 5.5, Fig. 27), no G
  std::size_t harmonic_basis_max_classes = internal::harmonic_basis_max_classes;   // else the 2-form Laplacian
  std::size_t anchor_face = npos;   // a table face whose label becomes 0 in its component (npos: largest area)
};

struct Core_result
{
  std::vector<int> labels;          // W per face (normalized)
  std::vector<double> w;            // per corner, shifted like the labels; NaN at interior endpoints
  std::vector<double> u, v;         // per corner: first jump-harmonic function and residual
  std::vector<double> g;            // per edge, J v
  std::vector<int> G, bounding;     // per edge
};

class Stopwatch
{
public:
  Stopwatch() : t0_(std::chrono::steady_clock::now()) {}
  double lap()
  {
    const auto t = std::chrono::steady_clock::now();
    const double s = std::chrono::duration<double>(t - t0_).count();
    t0_ = t;
    return s;
  }
private:
  std::chrono::steady_clock::time_point t0_;
};

template <class LA>
class Winding_number_core
{
public:
  // Per-mesh work: validation, cotan weights, Hodge star. The harmonic basis (or the 2-form
  // Laplacian) is computed the first time an open curve needs the Hodge projection, then kept.
  explicit Winding_number_core(Mesh_tables tables) : m_(std::move(tables))
  {
    if(m_.nf == 0) throw Invalid_input("the mesh has no face");
    check_geometry(m_);
    clamped_weights_ = cotan_weights(m_, weight_);
    star_ = edge_hodge_star(m_, weight_);
  }

  const Mesh_tables& tables() const { return m_; }

  // "N (vertices A, B)" in the input's numbering, for error messages
  std::string edge_name(std::size_t e) const
  {
    return std::to_string(m_.input_edge_index(e)) + " (vertices " + std::to_string(m_.input_vertex_index(m_.ev[2 * e])) +
           ", " + std::to_string(m_.input_vertex_index(m_.ev[2 * e + 1])) + ")";
  }
  std::size_t clamped_weights() const { return clamped_weights_; }

  template <class LP>
  Core_result solve(const std::vector<double>& chain, const Solve_options& options, LP& lp, Solve_report& rep)
  {
    if(chain.size() != m_.ne) throw Invalid_input("the chain has the wrong size");
    if(m_.nonmanifold_vertices == 0) return solve_on_edges(chain, options, lp, rep);
    // Edges at nonmanifold vertices carry no curve (paper Sec. 2.2): which side is which is not
    // defined there. The gaps this makes are closed like any other.
    std::vector<double> kept(chain);
    std::size_t dropped = 0;
    for(std::size_t e = 0; e < m_.ne; ++e)
      if(m_.jump_forbidden(e) && kept[e] != 0)
      {
        dropped += std::isfinite(kept[e]) ? 1 : 0;
        if(std::isfinite(kept[e])) kept[e] = 0;
      }
    Core_result r = solve_on_edges(kept, options, lp, rep);
    rep.dropped_curve_edges = dropped;
    return r;
  }

  template <class LP>
  Core_result solve_on_edges(const std::vector<double>& chain, const Solve_options& options, LP& lp, Solve_report& rep)
  {
    const double epsilon = options.epsilon;
    const bool verbose = options.verbose;
    if(chain.size() != m_.ne) throw Invalid_input("the chain has the wrong size");
    if(!(epsilon > 0) || !std::isfinite(epsilon)) throw Invalid_input("epsilon must be positive and finite");
    if(options.anchor_face != npos && options.anchor_face >= m_.nf) throw Invalid_input("the anchor face is out of range");
    Stopwatch clock, total;
    fill_mesh_report(rep);
    rep.dropped_curve_edges = 0;
    rep.curve_edges = 0;
    std::size_t bad_value = npos, on_border = npos;   // first offending edges, in the input's numbering
    for(std::size_t e = 0; e < m_.ne; ++e)
    {
      if(!std::isfinite(chain[e]))
      {
        bad_value = m_.first_edge_in_input(bad_value, e);
        continue;
      }
      if(std::abs(chain[e]) <= chain_tolerance) continue;
      ++rep.curve_edges;
      if(m_.edge_arc[e] == npos) on_border = m_.first_edge_in_input(on_border, e);
    }
    if(bad_value != npos)
      throw Invalid_input("edge " + std::to_string(m_.input_edge_index(bad_value)) + " has a non-finite chain value");
    if(on_border != npos)
      throw Invalid_input("edge " + edge_name(on_border) + " is on the border of the mesh and carries the chain value " +
                          std::to_string(chain[on_border]) + ": curves may end on the border but not run along it");
    const std::vector<char> endpoint = interior_endpoints(m_, chain);
    rep.interior_endpoints = 0;
    for(char c : endpoint) rep.interior_endpoints += c ? 1 : 0;
    rep.inconsistent_curve_vertices = m_.nonorientable_arcs > 0 ? inconsistent_curve_vertices(chain) : 0;
    rep.time_setup = clock.lap();
    if(verbose)
      std::cerr << "[swn] " << m_.nv << " vertices, " << m_.nf << " faces, " << m_.n_components << " component(s), "
                << rep.curve_edges << " curve edges, " << rep.interior_endpoints << " interior endpoints\n";

    Core_result r;
    // without the filtering of nonbounding loops, w = u as on disks and spheres (the paper's Fig. 27)
    rep.homology_correction = options.filter_nonbounding && !m_.all_components_disks_or_spheres();
    const bool open_curve = rep.interior_endpoints > 0;   // the homology correction needs the Hodge projection
    // The Hodge projection does not depend on the curve: when it will be needed, the harmonic basis
    // (or the 2-form Laplacian) is computed on a second thread while this one solves for u. Its time
    // counts in the Hodge step as far as it is waited for. For the basis, the second thread factorizes
    // the 0-form Laplacian while this one finds the cohomology generators, which the basis needs only
    // after that factorization (the second thread's work is the longer one); they count in the Hodge step.
    // Once this thread has solved for u, it takes its share of the basis's many-column solve.
    compute_vertex_order();   // read by both threads
    const bool keep = options.keep_hodge_factorization;
    Shared_work basis_solves;   // outlives the second thread (the future below joins it first)
    std::future<void> hodge_factorization;
    double time_order = 0, time_generators = 0;   // counted in the jump Laplace step and the Hodge step
#ifdef CGAL_HAS_THREADS
    if(options.concurrent && rep.homology_correction && open_curve && !hodge_ready())
    {
      const std::size_t max_classes = options.harmonic_basis_max_classes;
      const bool basis = expected_classes() <= max_classes;
      std::promise<Cohomology_generators> generators;
      std::shared_future<Cohomology_generators> pending = generators.get_future().share();
      try
      {
        hodge_factorization = std::async(std::launch::async, [this, max_classes, keep, pending, &basis_solves] {
          struct Finish   // whatever happens, this thread stops waiting for shared work
          {
            Shared_work& work;
            ~Finish() { work.finish(); }
          } finish{basis_solves};
          prepare_hodge_projection(max_classes, pending, keep, &basis_solves);
        });
      }
      catch(const std::system_error&) {}   // no thread available: computed when needed
      if(hodge_factorization.valid() && basis)
      {
        time_order = clock.lap();
        try { generators.set_value(cohomology_generators(m_)); }
        catch(...) { generators.set_exception(std::current_exception()); }   // the other thread rethrows it
        time_generators = clock.lap();
      }
    }
#endif
    // u: jump Laplace solve (Eq. 10) with jumps Gamma. Without interior endpoints the jump Laplacian
    // is the 0-form Laplacian, the same for every such curve: kept from an earlier solve if there is one.
    // (The second thread only reads laplacian_, and runs only for curves with interior endpoints.)
    // With interior endpoints and the solver class's kept factorizations, the kept 0-form Laplacian
    // with a low-rank update for the endpoints, unless the second thread is using it.
    bool kept = false;
    std::shared_ptr<Jump_laplace_system<LA>> Lp =
      open_curve ? updated_0form_laplacian(endpoint, options.keep_hodge_factorization && !hodge_factorization.valid(), kept)
                 : (laplacian_ && laplacian_->excludes(endpoint) ? laplacian_ : nullptr);
    rep.jump_laplacian_reused = open_curve ? kept : Lp != nullptr;
    if(!Lp) Lp = std::make_shared<Jump_laplace_system<LA>>();
    Jump_laplace_system<LA>& L = *Lp;
    r.u = first_jump_laplace_solve(chain, endpoint, L);
    rep.jump_laplacian_update_rank = L.update_rank();
    if(!open_curve) laplacian_ = options.keep_hodge_factorization ? Lp : nullptr;
    rep.time_jump_laplace = clock.lap() + time_order;
    if(verbose)
      std::cerr << "[swn] jump Laplace solve (" << L.size() << " unknowns"
                << (rep.jump_laplacian_update_rank ? ", kept 0-form Laplacian with a rank-" + std::to_string(L.update_rank()) +
                                                     " update for the endpoints"
                                                   : rep.jump_laplacian_reused ? ", factorization kept from an earlier solve" : "")
                << "): " << rep.time_jump_laplace << " s\n";

    rep.hodge_projection = false;
    rep.lp_ran = false;
    rep.reduced_residual = false;
    rep.lp_objective = 0;
    rep.lp_variables = rep.lp_rows = 0;
    if(!rep.homology_correction)
    {
      // Every relative 1-cycle bounds: w = u, v = 0 (one solve).
      r.w = r.u;
      r.v.assign(3 * m_.nf, 0.);
      r.g.assign(m_.ne, 0.);
    }
    else
    {
      // omega = D u (Eq. 5); gamma = harmonic part (Eq. 9) when the curve has interior endpoints
      if(hodge_factorization.valid())
      {
        basis_solves.help();
        hodge_factorization.get();   // rethrows a failed factorization
      }
      std::vector<double> gamma = harmonic_part_of(r.u, endpoint, open_curve, options.harmonic_basis_max_classes, keep);
      if(verbose && open_curve)
        std::cerr << "[swn] harmonic part: " << (basis_.assembled() ? "projection on " + std::to_string(basis_.size()) +
                                                 " harmonic 1-forms" : std::string("2-form Laplace solve")) << "\n";
      if(!options.keep_hodge_factorization) { basis_.release(); hodge_.release(); laplacian_.reset(); }
      if(open_curve && options.completed_class) gamma = completed_chain_form(chain, gamma);
      rep.hodge_projection = open_curve;
      rep.time_hodge = clock.lap() + time_generators;
      if(verbose) std::cerr << "[swn] Darboux derivative and harmonic part: " << rep.time_hodge << " s\n";

      // v: residual function (Eq. 11), or its reduced approximation (Sec. 6)
      if(options.reduced_residual && !m_.is_general())   // Sec. 6 assumes an oriented 2-manifold
        r.v = reduced_residual_function(m_, chain, gamma, epsilon, lp, options.concurrent, rep.lp_objective, rep.lp_variables, rep.lp_rows);
      else
      {
        const std::vector<double> v0 = local_integration(m_, gamma);
        const std::vector<double> sigma = residual_function(residual_problem(m_, v0, chain, epsilon), lp,
                                                            rep.lp_objective, rep.lp_variables, rep.lp_rows,
                                                            options.concurrent);
        r.v.resize(3 * m_.nf);
        for(std::size_t k = 0; k < 3 * m_.nf; ++k) r.v[k] = v0[k] + sigma[k / 3];
      }
      rep.lp_ran = true;
      rep.reduced_residual = options.reduced_residual && !m_.is_general();
      r.g = jump_derivative(m_, r.v);
      rep.time_residual = clock.lap();
      if(verbose)
        std::cerr << "[swn] residual LP (" << rep.lp_variables << " variables, " << rep.lp_rows
                  << " rows), objective " << rep.lp_objective << ": " << rep.time_residual << " s\n";

      // w: second jump Laplace solve with jumps Gamma - J v (Sec. 3.5), same factorization
      r.w = L.solve_jump_laplace(reduced_coordinates(m_, second_solve_jumps(m_, chain, r.v), endpoint));
      rep.time_second_solve = clock.lap();
      if(verbose) std::cerr << "[swn] second jump Laplace solve: " << rep.time_second_solve << " s\n";
    }

    // W: shift tau, rounding, normalization; G; bounding chain
    const std::vector<double> tau = shift_tau(m_, chain, r.w);
    r.labels = round_labels(m_, r.w, tau);
    const std::vector<int> offset = normalize_labels(m_, r.labels, options.anchor_face);
    for(std::size_t k = 0; k < 3 * m_.nf; ++k)
    {
      const std::size_t c = m_.face_component[k / 3];
      r.w[k] += tau[c] - offset[c];
    }
    r.G = nonbounding_chain(m_, r.g, chain, &rep.nonbounding_closing_units);
    r.bounding = bounding_chain(m_, r.labels);
    rep.nonmanifold_label_jumps = 0;
    for(std::size_t e : m_.unpaired_edges)
    {
      const std::size_t b = m_.edge_side_begin[e], n = m_.edge_side_begin[e + 1] - b;
      for(std::size_t i = 1; i < n; ++i)
        if(r.labels[m_.edge_sides[b + i] / 3] != r.labels[m_.edge_sides[b] / 3]) { ++rep.nonmanifold_label_jumps; break; }
    }
    rep.min_label = rep.max_label = r.labels.empty() ? 0 : r.labels[0];
    for(int l : r.labels) { rep.min_label = std::min(rep.min_label, l); rep.max_label = std::max(rep.max_label, l); }
    rep.time_labels = clock.lap();
    rep.time_total = total.lap();
    return r;
  }

  // On a nonorientable surface (Sec. 3.7, Fig. 9): the vertices where a curve passes through (two
  // curve edges of equal multiplicity) but its jumps add up instead of cancelling, i.e. where the
  // curve's normal flips: the curve is not orientable there and the labels near it mean little.
  std::size_t inconsistent_curve_vertices(const std::vector<double>& chain) const
  {
    std::vector<double> defect;
    reduced_coordinates(m_, arc_jumps_from_chain(m_, chain), std::vector<char>(m_.nv, 0), &defect);
    std::vector<int> degree(m_.nv, 0);
    std::vector<double> size(m_.nv, 0.);
    for(std::size_t e = 0; e < m_.ne; ++e)
      if(std::abs(chain[e]) > chain_tolerance)
        for(int k = 0; k < 2; ++k)
        {
          ++degree[m_.ev[2 * e + k]];
          size[m_.ev[2 * e + k]] += std::abs(chain[e]);
        }
    std::size_t n = 0;
    for(std::size_t v = 0; v < m_.nv; ++v)
      if(degree[v] == 2 && !m_.vertex_on_border[v] && std::abs(defect[v] - size[v]) < 1e-6 * size[v]) ++n;
    return n;
  }

  // The jump Laplacian of a curve with interior endpoints as the kept 0-form Laplacian with a low-rank
  // update (Jump_laplace_system::exclude_by_update), or nullptr (then factorized anew). With `keep`,
  // the 0-form Laplacian is factorized and kept if it is not there yet: the next curves need it too.
  // `kept`: the update used a factorization from an earlier solve.
  std::shared_ptr<Jump_laplace_system<LA>> updated_0form_laplacian(const std::vector<char>& endpoint, bool keep, bool& kept)
  {
    kept = false;
    if(!keep) return nullptr;
    const bool earlier = laplacian_ != nullptr;
    if(!earlier)
    {
      compute_vertex_order();
      laplacian_ = std::make_shared<Jump_laplace_system<LA>>();
      laplacian_->jump_laplacian(m_, weight_, std::vector<char>(m_.nv, 0), &vertex_order_);
    }
    std::shared_ptr<Jump_laplace_system<LA>> L = std::make_shared<Jump_laplace_system<LA>>(*laplacian_);
    if(!L->exclude_by_update(endpoint)) return nullptr;
    kept = earlier;
    return L;
  }

  // u of the first jump Laplace solve (Eq. 10); factorizes L (unless it is factorized already for
  // these endpoints), which the second solve reuses
  std::vector<double> first_jump_laplace_solve(const std::vector<double>& chain, const std::vector<char>& endpoint,
                                               Jump_laplace_system<LA>& L) const
  {
    compute_vertex_order();
    if(!L.excludes(endpoint)) L.jump_laplacian(m_, weight_, endpoint, &vertex_order_);
    return L.solve_jump_laplace(reduced_coordinates(m_, arc_jumps_from_chain(m_, chain), endpoint));
  }

  // gamma: the Darboux derivative of u (Eq. 5), projected to its harmonic part (Eq. 9) when the curve
  // has interior endpoints; `keep` as for prepare_hodge_projection()
  std::vector<double> harmonic_part_of(const std::vector<double>& u, const std::vector<char>& endpoint, bool open_curve,
                                       std::size_t max_classes = harmonic_basis_max_classes, bool keep = false)
  {
    std::vector<double> gamma = darboux_derivative(m_, u, endpoint);
    if(!open_curve) return gamma;
    prepare_hodge_projection(max_classes,
                             std::async(std::launch::deferred, [this] { return cohomology_generators(m_); }).share(), keep);
    return basis_.assembled() ? basis_.harmonic_part(gamma) : hodge_.harmonic_part(gamma);
  }

  // Beyond Eq. 11 (issue 46; named parameter completed_homology_class): the closed 1-form that the
  // residual problem integrates, taken from the curve with its gaps closed by shortest paths that follow
  // the curve's direction at both ends (directed_completion(); the Darboux derivative of its
  // jump-harmonic function, Eq. 5; closed, with the integer periods of the completed curve) instead of
  // the harmonic part of the broken curve's. `gamma` is returned where the completion leaves endpoints.
  std::vector<double> completed_chain_form(const std::vector<double>& chain, const std::vector<double>& gamma)
  {
    std::vector<double> completed = directed_completion(m_, chain);
    for(std::size_t e = 0; e < m_.ne; ++e) completed[e] += chain[e];
    const std::vector<char> endpoint = interior_endpoints(m_, completed);
    if(std::find(endpoint.begin(), endpoint.end(), 1) != endpoint.end()) return gamma;
    Jump_laplace_system<LA> L;
    return darboux_derivative(m_, first_jump_laplace_solve(completed, endpoint, L), endpoint);
  }

  // The per-mesh part of the Hodge projection: the harmonic basis when the mesh has at most
  // `max_classes` cohomology classes, else the factorized 2-form Laplacian. Nothing if either is there.
  // The basis is built with the 0-form Laplacian, the one kept from a curve without interior endpoints
  // if there is one, and the cohomology `generators` (read once the 0-form Laplacian is factorized:
  // they may still be computed by the other thread). A new 0-form Laplacian is kept only with `keep`
  // (the solve keeps its factorizations): held through the residual step, its memory slowed that step
  // down (the 380-case benchmark: residual +15 %, peak +15 %, 2026-12-03).
  void prepare_hodge_projection(std::size_t max_classes, std::shared_future<Cohomology_generators> generators, bool keep,
                                Shared_work* share = nullptr)
  {
    if(hodge_ready()) return;
    if(expected_classes() <= max_classes)
    {
      std::shared_ptr<Jump_laplace_system<LA>> L0 = laplacian_;
      if(!L0)
      {
        compute_vertex_order();
        L0 = std::make_shared<Jump_laplace_system<LA>>();
        L0->jump_laplacian(m_, weight_, std::vector<char>(m_.nv, 0), &vertex_order_);
        if(keep) laplacian_ = L0;   // the solving thread does not read it meanwhile
      }
      const Cohomology_generators& gen = generators.get();
      if(gen.complete && gen.size() <= max_classes)
      {
        basis_.assemble(m_, star_, gen, *L0, share);
        return;
      }
    }
    hodge_.assemble(m_, star_);
  }

  // the number of cohomology classes of the mesh, from the Euler characteristics (what a complete
  // tree-cotree finds)
  std::size_t expected_classes() const
  {
    // the tree-cotree generators assume an oriented 2-manifold: elsewhere the 2-form Laplacian
    if(m_.is_general()) return std::numeric_limits<std::size_t>::max();
    std::size_t K = 0;
    for(std::size_t c = 0; c < m_.n_components; ++c) K += std::size_t((std::max)(m_.component_cohomology_classes(c), 0L));
    return K;
  }
  bool hodge_ready() const { return basis_.assembled() || hodge_.assembled(); }

  // The residual problem (Eq. 11) of a chain, as solve() builds it (for tests and benchmarks).
  Residual_problem residual_problem_of(const std::vector<double>& chain, double epsilon,
                                       std::size_t max_classes = harmonic_basis_max_classes)
  {
    const std::vector<char> endpoint = interior_endpoints(m_, chain);
    Jump_laplace_system<LA> L;
    const std::vector<double> u = first_jump_laplace_solve(chain, endpoint, L);
    const bool open_curve = std::find(endpoint.begin(), endpoint.end(), 1) != endpoint.end();
    return residual_problem(m_, local_integration(m_, harmonic_part_of(u, endpoint, open_curve, max_classes)), chain,
                            epsilon);
  }

  void fill_mesh_report(Solve_report& rep) const
  {
    rep.vertices = m_.nv;
    // the input's edges and faces (polygons), not the diagonals and triangles of their triangulation
    rep.edges = m_.ne - std::size_t(std::count(m_.edge_virtual.begin(), m_.edge_virtual.end(), char(1)));
    rep.faces = m_.number_of_polygons();
    rep.components = m_.n_components;
    rep.border_edges = 0;
    for(char b : m_.edge_on_border) rep.border_edges += b ? 1 : 0;
    rep.genus = 0;
    rep.border_loops = 0;
    rep.euler_characteristic = 0;
    if(orientable_.empty()) orientable_ = component_orientable(m_);   // once per mesh: a search over its faces
    const std::vector<char>& orientable = orientable_;
    rep.orientable = std::find(orientable.begin(), orientable.end(), char(0)) == orientable.end();
    // the genus is defined on orientable 2-manifolds only (with or without border)
    std::vector<char> manifold(m_.n_components, 1);
    for(std::size_t v = 0; v < m_.nv; ++v)
      if(m_.is_nonmanifold(v) && m_.vertex_component[v] != npos) manifold[m_.vertex_component[v]] = 0;
    for(std::size_t c = 0; c < m_.n_components; ++c)
    {
      rep.border_loops += border_loops(c);
      rep.euler_characteristic += m_.component_euler_characteristic[c];
      if(rep.genus < 0 || !manifold[c] || !orientable[c]) rep.genus = -1;
      else rep.genus += int((2 - m_.component_euler_characteristic[c] - long(border_loops(c))) / 2);
    }
    rep.degenerate_weights = clamped_weights_;
    rep.nonmanifold_vertices = m_.nonmanifold_vertices;
    rep.nonmanifold_edges = m_.unpaired_edges.size();
    rep.nonorientable_edges = m_.nonorientable_arcs;
  }

  // number of border loops of component c (border edges chained through their vertices)
  std::size_t border_loops(std::size_t c) const
  {
    if(border_loops_.empty()) count_border_loops();
    return border_loops_[c];
  }

private:
  void compute_vertex_order() const
  {
    if(vertex_order_computed_) return;   // once per mesh
    vertex_order_ = vertex_elimination_order(m_);
    vertex_order_computed_ = true;
  }

  // border loops: the connected sets of border edges (through their vertices), which does not depend on
  // how the faces are oriented (a soup's faces need not be)
  void count_border_loops() const
  {
    border_loops_.assign(m_.n_components, 0);
    Union_find sets(m_.nv);
    std::vector<char> on_border(m_.nv, 0);
    for(std::size_t e = 0; e < m_.ne; ++e)
      if(m_.edge_on_border[e])
      {
        sets.unite(m_.ev[2 * e], m_.ev[2 * e + 1]);
        on_border[m_.ev[2 * e]] = on_border[m_.ev[2 * e + 1]] = 1;
      }
    for(std::size_t v = 0; v < m_.nv; ++v)
      if(on_border[v] && sets.find(v) == v) ++border_loops_[m_.vertex_component[v]];
  }

  Mesh_tables m_;
  std::vector<double> weight_, star_;
  std::size_t clamped_weights_ = 0;
  Harmonic_basis<LA> basis_;
  Two_form_laplacian<LA> hodge_;
  // the factorized 0-form Laplacian: the jump Laplacian of every curve without interior endpoints
  // (and then the one the harmonic basis is built with); kept between solves unless
  // keep_hodge_factorization is false
  std::shared_ptr<Jump_laplace_system<LA>> laplacian_;
  mutable std::vector<std::size_t> border_loops_;
  mutable std::vector<char> orientable_;   // component -> orientable (fill_mesh_report())
  mutable std::vector<std::size_t> vertex_order_;   // elimination order of the jump Laplacian (empty: by vertex)
  mutable bool vertex_order_computed_ = false;
};

} // namespace internal
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif
