// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT

#ifndef CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_JUMP_LAPLACE_H
#define CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_JUMP_LAPLACE_H

#include <CGAL/Surface_winding_numbers/internal/column_solves.h>
#include <CGAL/Surface_winding_numbers/internal/mesh_tables.h>
#include <CGAL/assertions.h>

#ifdef CGAL_EIGEN3_ENABLED
#include <Eigen/Core>
#include <Eigen/LU>
#endif

#include <algorithm>
#include <atomic>
#include <cmath>
#include <condition_variable>
#include <deque>
#include <exception>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <numeric>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace internal {

constexpr double chain_tolerance = 1e-9;

// Boundary 0-chain of a 1-chain (paper Sec. 2.2): arrivals minus departures at every vertex, summed
// as `Sum` (double for real chains; long for integer ones, chain_boundary<long>(m, G)).
template <class Sum = double, class Value>
std::vector<Sum> chain_boundary(const Mesh_tables& m, const std::vector<Value>& chain)
{
  std::vector<Sum> d(m.nv, Sum(0));
  for(std::size_t e = 0; e < m.ne; ++e)
  {
    d[m.ev[2 * e + 1]] += Sum(chain[e]);
    d[m.ev[2 * e]] -= Sum(chain[e]);
  }
  return d;
}

// Prescribed jumps, left minus right, per arc and per endpoint of the arc's edge: jump[2a + k] is
// the jump measured at vertex ev[2 * edge + k]. The first solve uses Gamma at both ends.
inline std::vector<double> arc_jumps_from_chain(const Mesh_tables& m, const std::vector<double>& chain)
{
  std::vector<double> jump(2 * m.arcs.size());
  for(std::size_t a = 0; a < m.arcs.size(); ++a) jump[2 * a] = jump[2 * a + 1] = chain[m.arcs[a].edge];
  return jump;
}

// Reduced coordinates c (paper Eq. 3): per-corner offsets that realise the prescribed jumps around
// every vertex. Corners of a vertex are visited across arcs from a root corner with c = 0; the
// root choice only shifts u0 at that vertex. Excluded vertices (interior endpoints) and nonmanifold
// vertices keep c = 0, and so do the vertices where no jump is measured (away from the curves: the
// visit would give 0 at each of their corners). With `defect`, each vertex also gets the largest
// amount by which the jumps around it fail to close (|dGamma| at that vertex on an oriented surface;
// on a nonorientable one the only way to tell the endpoints, since a dual chain has no global boundary).
inline std::vector<double> reduced_coordinates(const Mesh_tables& m, const std::vector<double>& arc_jump,
                                               const std::vector<char>& excluded,
                                               std::vector<double>* defect = nullptr)
{
  std::vector<double> c(3 * m.nf, 0.);
  std::vector<char> done(3 * m.nf, 0), jumps(m.nv, 0);
  for(std::size_t a = 0; a < m.arcs.size(); ++a)
    for(std::size_t k = 0; k < 2; ++k)
      if(arc_jump[2 * a + k] != 0) jumps[m.ev[2 * m.arcs[a].edge + k]] = 1;
  std::vector<std::size_t> stack;
  if(defect) defect->assign(m.nv, 0.);
  for(std::size_t v = 0; v < m.nv; ++v)
  {
    if(!jumps[v] || excluded[v] || m.is_nonmanifold(v)) continue;
    for(std::size_t i = m.vertex_corner_begin[v]; i < m.vertex_corner_begin[v + 1]; ++i)
    {
      const std::size_t root = m.vertex_corners[i];
      if(done[root]) continue;
      done[root] = 1;
      stack.assign(1, root);
      while(!stack.empty())
      {
        const std::size_t cr = stack.back();
        stack.pop_back();
        const std::size_t sides[2] = {cr, Mesh_tables::prev_in_face(cr)};   // the two sides of face(cr) at v
        for(std::size_t s : sides)
        {
          const std::size_t e = m.fe[s], a = m.edge_arc[e];
          if(a == npos) continue;
          const Arc& arc = m.arcs[a];
          const bool in_left = (s == arc.left_side);
          const std::size_t other = in_left ? arc.right_side : arc.left_side;
          const std::size_t nb = m.corner_at(other / 3, v);
          const double J = arc_jump[2 * a + (m.ev[2 * e] == v ? 0 : 1)];
          if(done[nb])
          {
            if(defect) (*defect)[v] = (std::max)((*defect)[v], std::abs(c[nb] - (in_left ? c[cr] - J : c[cr] + J)));
            continue;
          }
          c[nb] = in_left ? c[cr] - J : c[cr] + J;
          done[nb] = 1;
          stack.push_back(nb);
        }
      }
    }
  }
  return c;
}

// Interior endpoints: vertices off the border where the chain has a boundary. Curves may end on
// the border without creating a singularity (relative homology, paper Sec. 2.2.1). On a surface with
// nonorientable arcs the boundary is read from how the jumps close around each vertex.
inline std::vector<char> interior_endpoints(const Mesh_tables& m, const std::vector<double>& chain)
{
  std::vector<double> d;
  if(m.nonorientable_arcs > 0)
    reduced_coordinates(m, arc_jumps_from_chain(m, chain), std::vector<char>(m.nv, 0), &d);
  else
    d = chain_boundary(m, chain);
  std::vector<char> endpoint(m.nv, 0);
  for(std::size_t v = 0; v < m.nv; ++v)
    endpoint[v] = (std::abs(d[v]) > chain_tolerance && !m.vertex_on_border[v]) ? 1 : 0;
  return endpoint;
}


// The unknowns of the jump Laplacian on V* = vertices minus `excluded`: dof[v] is v's unknown, npos at
// excluded vertices, at vertices of no face and at one pinned vertex per connected component of V*
// (its representative in a union-find of V*'s edges). Unknowns follow `order` if given and not
// empty, else the vertices. Returns their number.
inline std::size_t number_jump_laplace_unknowns(const Mesh_tables& m, const std::vector<char>& excluded,
                                                const std::vector<std::size_t>* order, std::vector<std::size_t>& dof)
{
  Union_find sets(m.nv);
  for(std::size_t s = 0; s < 3 * m.nf; ++s)
    if(!excluded[m.tail(s)] && !excluded[m.head(s)]) sets.unite(m.tail(s), m.head(s));
  dof.assign(m.nv, npos);
  std::size_t n = 0;
  for(std::size_t k = 0; k < m.nv; ++k)
  {
    const std::size_t v = order && !order->empty() ? (*order)[k] : k;
    if(!excluded[v] && m.vertex_component[v] != npos && sets.find(v) != v) dof[v] = n++;   // roots are pinned
  }
  return n;
}

// The largest update of exclude_by_update(): its |T| columns must cost less than the factorization
// they replace.
constexpr std::size_t jump_laplacian_max_update_rank = 96;
// memory for the columns of the inverse that the updates keep for the next ones, with a factorization
// that offers no sparse forward solves (64 MB: 160 columns on a 100k-face mesh, 16 on a 1M-face one); an
// update whose own columns do not fit keeps none
constexpr std::size_t column_cache_bytes = std::size_t(64) << 20;

// The jump Laplace system (paper Eqs. 6-8, 10) on V* = vertices minus interior endpoints. The
// constant null space of every connected component of V* is removed exactly by pinning the
// component's first vertex (u0 = 0 there), so the matrix is positive definite and b needs no
// projection. One factorization serves both jump-Laplace solves (u, then w).
template <class LA>
class Jump_laplace_system
{
public:
  using Matrix = typename LA::Matrix;
  using Vector = typename LA::Vector;

  // Assembles and factorizes L restricted to V* (paper Eq. 8). The unknowns are numbered in the
  // vertex order `order` if given and not empty (the elimination order of the factorization), else
  // by vertex.
  void jump_laplacian(const Mesh_tables& m, const std::vector<double>& weight, const std::vector<char>& excluded,
                      const std::vector<std::size_t>* order = nullptr)
  {
    m_ = &m;
    weight_ = &weight;
    excluded_ = excluded;
    update_.reset();
    const std::size_t n = number_jump_laplace_unknowns(m, excluded, order, dof_);
    n_ = n;
    la_.reset(new LA());
    cache_ = std::make_shared<Column_cache>();
    if(n == 0) return;
    // the side weights summed per edge first, so that every matrix entry is added once
    std::vector<double> edge_weight(m.ne, 0.), diagonal(n, 0.);
    for(std::size_t s = 0; s < 3 * m.nf; ++s)
      if(!excluded[m.tail(s)] && !excluded[m.head(s)]) edge_weight[m.fe[s]] += weight[s];
    std::vector<Matrix_entry> entries;
    entries.reserve(2 * m.ne + n);
    for(std::size_t e = 0; e < m.ne; ++e)
    {
      const double w = edge_weight[e];
      if(w == 0) continue;   // no side with both ends in V*
      const std::size_t i = dof_[m.ev[2 * e]], j = dof_[m.ev[2 * e + 1]];
      if(i != npos) diagonal[i] += w;
      if(j != npos) diagonal[j] += w;
      if(i != npos && j != npos)
      {
        entries.push_back({int(i), int(j), -w});
        entries.push_back({int(j), int(i), -w});
      }
    }
    for(std::size_t k = 0; k < n; ++k) entries.push_back({int(k), int(k), diagonal[k]});
    A_ = assembled_matrix<Matrix>(n, entries);
    double D = 1;
    if(!la_->factor(*A_, D)) throw Solver_failure("factorization of the jump Laplacian failed");
  }

  // Right-hand side b (paper Eq. 7, exact per-face form): minimises sum_sides w (u_head - u_tail)^2
  // over u0 with u = u0 + c at every corner.
  Vector jump_laplace_rhs(const std::vector<double>& c) const
  {
    const Mesh_tables& m = *m_;
    Vector b(static_cast<int>(n_));
    for(std::size_t k = 0; k < n_; ++k) b[k] = 0;
    for(std::size_t s = 0; s < 3 * m.nf; ++s)
    {
      const std::size_t vi = m.tail(s), vj = m.head(s);
      if(excluded_[vi] || excluded_[vj]) continue;
      const double d = (*weight_)[s] * (c[Mesh_tables::next_in_face(s)] - c[s]);
      if(dof_[vj] != npos) b[dof_[vj]] -= d;
      if(dof_[vi] != npos) b[dof_[vi]] += d;
    }
    return b;
  }

  // Solves L u0 = b (paper Eq. 10) and returns the corner values u = u0 + c (NaN at excluded vertices).
  std::vector<double> solve_jump_laplace(const std::vector<double>& c) const
  {
    const Mesh_tables& m = *m_;
    std::vector<double> u0(m.nv, 0.);
    if(n_ > 0)
    {
      Vector b = jump_laplace_rhs(c);
      Vector x(static_cast<int>(n_));
      if(!solve_by_halves(b, x)) solve_by_columns(b, x);
      for(std::size_t v = 0; v < m.nv; ++v)
        if(dof_[v] != npos)
        {
          u0[v] = x[dof_[v]];
          if(!std::isfinite(u0[v])) throw Solver_failure("jump Laplace solve produced non-finite values");
        }
    }
    std::vector<double> u(3 * m.nf);
    for(std::size_t k = 0; k < 3 * m.nf; ++k)
      u[k] = excluded_[m.fv[k]] ? std::numeric_limits<double>::quiet_NaN() : u0[m.fv[k]] + c[k];
    return u;
  }

  // Solves L x_j = b_j for k right-hand sides given per vertex: rhs(j, b) adds b_j to b, a vector of
  // nv zeros; entries at pinned and excluded vertices are not used. Returns the x_j per vertex, one
  // after the other (nv x k, column-major), 0 at pinned and excluded vertices. The columns are solved
  // vertex_laplace_block at a time, in arrays reused from one block to the next. With `share`, and a
  // solver that allows two solves at once (Has_workspace_solve), the blocks are shared with a thread
  // that calls share->help() (rhs is then called from both threads). With no excluded vertex, L is
  // the 0-form Laplacian d0^T S1 d0 of the Hodge decomposition (its edge weights are the Hodge star S1).
  template <class Rhs>
  std::vector<double> solve_vertex_laplace(std::size_t k, const Rhs& rhs, Shared_work* share = nullptr) const
  {
    CGAL_precondition(!update_);   // the 0-form Laplacian, not an updated copy
    const Mesh_tables& m = *m_;
    std::vector<double> x(m.nv * k, 0.);
    if(n_ == 0 || k == 0) return x;
    const std::size_t blocks = (k + vertex_laplace_block - 1) / vertex_laplace_block;
    std::atomic<std::size_t> next(0);
    std::mutex failure_mutex;
    std::exception_ptr failure;
    // claims blocks until none is left; the right sides and the result in arrays of this thread
    const std::function<void()> work = [&] {
      try
      {
        std::vector<double> b(m.nv, 0.), B;
        Column_solver<LA> solver;
        for(std::size_t block; (block = next.fetch_add(1)) < blocks;)
          solve_vertex_laplace_block(block * vertex_laplace_block, (std::min)(vertex_laplace_block, k - block * vertex_laplace_block),
                                     rhs, b, B, solver, x);
      }
      catch(...)
      {
        next.store(blocks);   // the others stop after their block
        std::lock_guard<std::mutex> lock(failure_mutex);
        if(!failure) failure = std::current_exception();
      }
    };
    // two threads solve at once only with a solver known to allow it
    if(share != nullptr && Has_workspace_solve<LA>::value && blocks > 1) share->run(work);
    else work();
    if(failure) std::rethrow_exception(failure);
    return x;
  }

  std::size_t size() const { return n_; }
  bool factorized() const { return la_ != nullptr; }
  // true if the system was built with exactly these excluded vertices
  bool excludes(const std::vector<char>& excluded) const { return la_ != nullptr && excluded_ == excluded; }
  // |T| of exclude_by_update(), 0 if the system is factorized as it is
  std::size_t update_rank() const { return update_ ? update_->dofs.size() : 0; }
  // columns of A^-1 kept for the next updates (shared by the copies of one factorization)
  std::size_t cached_columns() const { return cache_->column.size(); }

  // Turns a copy of the factorized 0-form Laplacian (no vertex excluded) into the jump Laplacian of
  // V* = vertices minus `excluded` (paper Eq. 8) without a new factorization. With an identity row
  // for each excluded vertex, that system A* differs from the 0-form Laplacian A only on the rows and
  // columns T of the excluded vertices and of their neighbours: A* = A + P M P^T (P: the columns of
  // the identity at T), solved with A's factorization by the Woodbury identity: (I + Z_T M) q = (A^-1 b)_T,
  // then x = A^-1 (b - P M q), where Z_T = P^T A^-1 P.
  // Returns false, the system unchanged, when |T| > max_rank or when V* needs other pinned vertices
  // than A's (a component's pinned vertex excluded, or a component split by the excluded vertices).
  // With a factorization A = Q^T L L^T Q that offers sparse forward solves (Has_unit_forward: the
  // package's supernodal one), Z_T = G^T G with G = L^-1 Q P, whose columns reach only the supernodes
  // on the way from theirs to the root of the elimination tree, and every solve is one solve of A with
  // G applied between its halves (solve_by_halves()). Otherwise the columns Z = A^-1 P take |T| solves,
  // kept with the update (one solve per solve_jump_laplace() instead of two) and for the next updates
  // of copies of A, within `column_bytes`.
  bool exclude_by_update(const std::vector<char>& excluded, std::size_t max_rank = jump_laplacian_max_update_rank,
                         std::size_t column_bytes = column_cache_bytes)
  {
    CGAL_precondition(la_ != nullptr && !update_ && std::count(excluded_.begin(), excluded_.end(), char(1)) == 0);
    const Mesh_tables& m = *m_;
    std::vector<std::size_t> dof_star;
    const std::size_t n_star = number_jump_laplace_unknowns(m, excluded, nullptr, dof_star);
    std::size_t vertices = 0, vertices_star = 0;
    for(std::size_t v = 0; v < m.nv; ++v)
    {
      if(m.vertex_component[v] == npos) continue;
      ++vertices;
      if(excluded[v] && dof_[v] == npos) return false;   // a pinned vertex is excluded
      if(!excluded[v]) ++vertices_star;
    }
    if(vertices_star - n_star != vertices - n_) return false;   // not as many components of V* as of the mesh
    // T and M: the edges at excluded vertices removed, an identity row for each excluded vertex
    std::vector<double> edge_weight(m.ne, 0.);   // summed as in jump_laplacian(): the same bits
    for(std::size_t s = 0; s < 3 * m.nf; ++s)
      if(excluded[m.tail(s)] || excluded[m.head(s)]) edge_weight[m.fe[s]] += (*weight_)[s];
    std::vector<std::size_t> local(n_, npos), T;
    const auto index = [&](std::size_t v) {
      const std::size_t d = dof_[v];
      if(d == npos) return npos;
      if(local[d] == npos) { local[d] = T.size(); T.push_back(d); }
      return local[d];
    };
    struct Removed { std::size_t i, j; double w; };   // local indices of a removed edge's ends, its weight
    std::vector<Removed> removed;
    for(std::size_t e = 0; e < m.ne; ++e)
      if(edge_weight[e] != 0) removed.push_back({index(m.ev[2 * e]), index(m.ev[2 * e + 1]), edge_weight[e]});
    for(std::size_t v = 0; v < m.nv; ++v)
      if(excluded[v]) index(v);
    if(T.size() > max_rank) return false;
    const Eigen::Index t = Eigen::Index(T.size());
    std::shared_ptr<Update> update = std::make_shared<Update>();
    update->M.setZero(t, t);
    for(const Removed& r : removed)
    {
      const Eigen::Index i = Eigen::Index(r.i), j = Eigen::Index(r.j);
      if(r.i != npos) update->M(i, i) -= r.w;
      if(r.j != npos) update->M(j, j) -= r.w;
      if(r.i != npos && r.j != npos) { update->M(i, j) += r.w; update->M(j, i) += r.w; }
    }
    for(std::size_t v = 0; v < m.nv; ++v)
      if(excluded[v]) update->M(Eigen::Index(local[dof_[v]]), Eigen::Index(local[dof_[v]])) += 1;
    // Z_T = G^T G from the sparse G = L^-1 Q P when the factorization A = Q^T L L^T Q offers it (its
    // columns reach only the supernodes from theirs to the root); otherwise from the columns Z = A^-1 P:
    // kept (in the update, and in the cache of the factorization for the next updates) when they fit
    // in column_cache_bytes, otherwise only solved block by block
    Eigen::MatrixXd ZT(t, t);
    if(forward_columns(T, update->forward))
    {
      const std::vector<Sparse_column>& G = update->forward;
      for(std::size_t j = 0; j < T.size(); ++j)
        for(std::size_t i = 0; i <= j; ++i) ZT(Eigen::Index(i), Eigen::Index(j)) = ZT(Eigen::Index(j), Eigen::Index(i)) = dot(G[i], G[j]);
    }
    else if(T.size() * n_ * sizeof(double) <= column_bytes)
    {
      update->columns = columns_of_inverse(T, column_bytes);
      for(std::size_t j = 0; j < T.size(); ++j)
        for(std::size_t i = 0; i < T.size(); ++i) ZT(Eigen::Index(i), Eigen::Index(j)) = (*update->columns[j])[T[i]];
    }
    else
    {
      std::vector<std::size_t> all(T.size());
      std::iota(all.begin(), all.end(), std::size_t(0));
      solve_unit_columns(T, all, [&](std::size_t j, const double* z) {
        for(std::size_t i = 0; i < T.size(); ++i) ZT(Eigen::Index(i), Eigen::Index(j)) = z[T[i]];
      });
    }
    update->K.compute(Eigen::MatrixXd::Identity(t, t) + ZT * update->M);
    if(!(update->K.rcond() > 1e-12)) return false;   // A* singular or nearly: factorize V* anew
    update->dofs = std::move(T);
    update_ = std::move(update);
    excluded_ = excluded;
    return true;
  }

private:
  typedef std::shared_ptr<const std::vector<double>> Column;

  // G = L^-1 Q P (the unit vectors of the unknowns T after the forward half of a solve) with a
  // factorization A = Q^T L L^T Q that offers it (Has_unit_forward); false otherwise
  bool forward_columns(const std::vector<std::size_t>& T, std::vector<Sparse_column>& G) const
  {
    if constexpr(Has_unit_forward<LA>::value)
    {
      G.resize(T.size());
      std::vector<double> y;
      for(std::size_t j = 0; j < T.size(); ++j) la_->solver().unit_forward(T[j], G[j], y);
      return true;
    }
    else return false;
  }

  static double dot(const Sparse_column& g, const Sparse_column& h)
  {
    double s = 0;
    for(std::size_t i = 0, j = 0; i < g.index.size() && j < h.index.size();)
    {
      if(g.index[i] < h.index[j]) ++i;
      else if(h.index[j] < g.index[i]) ++j;
      else s += g.value[i++] * h.value[j++];
    }
    return s;
  }

  // A* x = b for an update with the sparse G of forward_columns(): with w = L^-1 Q b,
  // x = Q^T L^-T (w - G M q) where (I + G^T G M) q = G^T w. False (x unchanged) if the update has no G.
  bool solve_by_halves(const Vector& b, Vector& x) const
  {
    if constexpr(Has_unit_forward<LA>::value)
    {
      if(!update_ || update_->forward.empty()) return false;
      const std::vector<Sparse_column>& G = update_->forward;
      std::vector<double> w, scratch;
      la_->solver().forward(b.data(), w, scratch);
      Eigen::VectorXd yT(Eigen::Index(G.size()));
      for(std::size_t j = 0; j < G.size(); ++j)
      {
        double s = 0;
        for(std::size_t k = 0; k < G[j].index.size(); ++k) s += G[j].value[k] * w[G[j].index[k]];
        yT[Eigen::Index(j)] = s;
      }
      const Eigen::VectorXd Mq = update_->M * update_->K.solve(yT);
      for(std::size_t j = 0; j < G.size(); ++j)
        for(std::size_t k = 0; k < G[j].index.size(); ++k) w[G[j].index[k]] -= Mq[Eigen::Index(j)] * G[j].value[k];
      la_->solver().backward(w, x.data(), scratch);
      return true;
    }
    else
    {
      (void)b;
      (void)x;
      return false;
    }
  }

  // A x = b, or A* x = b for an update without the sparse G of forward_columns(): with A* = A + P M P^T,
  // x = A^-1 b - Z M q where (I + Z_T M) q = (A^-1 b)_T, with the columns Z = A^-1 P kept by
  // exclude_by_update(), or x = A^-1 (b - P M q) when they were too large to keep (b is overwritten)
  void solve_by_columns(Vector& b, Vector& x) const
  {
    if(!la_->linear_solver(b, x)) throw Solver_failure("jump Laplace solve failed");
    if(!update_) return;
    const std::vector<std::size_t>& T = update_->dofs;
    Eigen::VectorXd yT(Eigen::Index(T.size()));
    for(std::size_t i = 0; i < T.size(); ++i) yT[Eigen::Index(i)] = x[T[i]];
    const Eigen::VectorXd Mq = update_->M * update_->K.solve(yT);
    for(std::size_t j = 0; j < update_->columns.size(); ++j)
    {
      const std::vector<double>& z = *update_->columns[j];
      const double c = Mq[Eigen::Index(j)];
      for(std::size_t i = 0; i < n_; ++i) x[i] -= c * z[i];
    }
    if(update_->columns.empty())
    {
      for(std::size_t i = 0; i < T.size(); ++i) b[T[i]] -= Mq[Eigen::Index(i)];
      if(!la_->linear_solver(b, x)) throw Solver_failure("jump Laplace solve failed");
    }
  }

  // Solves A z = e_d for the unknowns d = T[j], j in `which`, in blocks of columns; calls f(j, z) for each.
  template <class F>
  void solve_unit_columns(const std::vector<std::size_t>& T, const std::vector<std::size_t>& which, F f) const
  {
    Column_solver<LA> solver;
    std::vector<double> B;
    for(std::size_t j0 = 0; j0 < which.size(); j0 += vertex_laplace_block)
    {
      const std::size_t kb = (std::min)(vertex_laplace_block, which.size() - j0);
      B.assign(n_ * kb, 0.);
      for(std::size_t j = 0; j < kb; ++j) B[j * n_ + T[which[j0 + j]]] = 1;
      const double* X = solver.solve(*la_, B, n_, kb);
      if(X == nullptr) throw Solver_failure("jump Laplace solve failed");
      for(std::size_t j = 0; j < kb; ++j) f(which[j0 + j], X + j * n_);
    }
  }

  // The columns A^-1 e_d of the unknowns d in T: those of the cache (the unknowns of the latest
  // updates: a kept stroke's endpoints cost nothing the next time), the others solved in blocks and
  // added to it. The cache holds at most column_cache_bytes; the oldest columns leave it first.
  std::vector<Column> columns_of_inverse(const std::vector<std::size_t>& T, std::size_t column_bytes)
  {
    Column_cache& cache = *cache_;
    std::vector<Column> z(T.size());
    std::vector<std::size_t> missing;
    for(std::size_t j = 0; j < T.size(); ++j)
    {
      const auto it = cache.column.find(T[j]);
      if(it != cache.column.end()) z[j] = it->second;
      else missing.push_back(j);
    }
    solve_unit_columns(T, missing, [&](std::size_t j, const double* x) {
      z[j] = std::make_shared<const std::vector<double>>(x, x + n_);
    });
    const std::size_t room = column_bytes / (sizeof(double) * (std::max)(n_, std::size_t(1)));
    for(std::size_t j : missing)
    {
      cache.column[T[j]] = z[j];
      cache.age.push_back(T[j]);
    }
    while(cache.column.size() > room)   // the oldest first (a column used again is not renewed: cheap, and rare)
    {
      cache.column.erase(cache.age.front());
      cache.age.pop_front();
    }
    return z;
  }

  // columns j0 .. j0 + kb - 1 of solve_vertex_laplace() into x; b: nv zeros (kept so), B: scratch
  template <class Rhs>
  void solve_vertex_laplace_block(std::size_t j0, std::size_t kb, const Rhs& rhs, std::vector<double>& b,
                                  std::vector<double>& B, Column_solver<LA>& solver, std::vector<double>& x) const
  {
    const Mesh_tables& m = *m_;
    B.resize(n_ * kb);
    for(std::size_t j = 0; j < kb; ++j)
    {
      rhs(j0 + j, b);
      for(std::size_t v = 0; v < m.nv; ++v)
      {
        if(dof_[v] != npos) B[j * n_ + dof_[v]] = b[v];
        b[v] = 0;
      }
    }
    const double* X = solver.solve(*la_, B, n_, kb);
    if(X == nullptr) throw Solver_failure("0-form Laplace solve failed");
    for(std::size_t j = 0; j < kb; ++j)
    {
      double* xj = x.data() + (j0 + j) * m.nv;
      for(std::size_t v = 0; v < m.nv; ++v)
        if(dof_[v] != npos)
        {
          xj[v] = X[j * n_ + dof_[v]];
          if(!std::isfinite(xj[v])) throw Solver_failure("0-form Laplace solve produced non-finite values");
        }
    }
  }

  const Mesh_tables* m_ = nullptr;
  const std::vector<double>* weight_ = nullptr;
  std::vector<char> excluded_;
  std::vector<std::size_t> dof_;
  std::size_t n_ = 0;
  // shared by the copies that exclude_by_update() turns into other systems
  std::shared_ptr<Matrix> A_;   // LA::factor keeps a pointer to the matrix: keep it alive
  std::shared_ptr<LA> la_;
  // the low-rank update of exclude_by_update(): the unknowns T it touches, M, and the LU of I + Z_T M
  struct Update
  {
    std::vector<std::size_t> dofs;
    std::vector<Column> columns;   // A^-1 e_d for d in dofs
    std::vector<Sparse_column> forward;   // or L^-1 Q e_d (forward_columns())
    Eigen::MatrixXd M;
    Eigen::PartialPivLU<Eigen::MatrixXd> K;
  };
  std::shared_ptr<const Update> update_;
  // the columns of A^-1 solved by the updates of the copies of this factorization (shared with them)
  struct Column_cache
  {
    std::map<std::size_t, Column> column;
    std::deque<std::size_t> age;   // unknowns in the order their columns came
  };
  std::shared_ptr<Column_cache> cache_ = std::make_shared<Column_cache>();
};

} // namespace internal
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif
