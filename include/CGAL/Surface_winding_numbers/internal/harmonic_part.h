// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT

#ifndef CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_HARMONIC_PART_H
#define CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_HARMONIC_PART_H

#include <CGAL/Surface_winding_numbers/internal/jump_laplace.h>
#include <CGAL/Surface_winding_numbers/internal/mesh_tables.h>
#include <CGAL/Surface_winding_numbers/internal/nested_dissection.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace internal {

// The 2-form Laplacian B = d1 S1^-1 d1^T on faces (paper Sec. 2.5.1, App. A), assembled and
// factorized once per mesh. Its null space, the constant 2-form of every closed component, is
// removed exactly by pinning that component's first face; components with a border have none.
// This keeps d1 gamma at round-off level (the residual LP relies on a closed gamma).
template <class LA>
class Two_form_laplacian
{
public:
  using Matrix = typename LA::Matrix;
  using Vector = typename LA::Vector;

  // assembled() becomes true only after a successful factorization
  void assemble(const Mesh_tables& m, const std::vector<double>& star)
  {
    m_ = nullptr;
    star_ = &star;
    dof_.assign(m.nf, npos);
    std::size_t n = 0;
    // unknowns numbered in the elimination order of the factorization (large meshes), else by face
    const std::vector<std::size_t> order = face_elimination_order(m);
    for(std::size_t k = 0; k < m.nf; ++k)
    {
      const std::size_t f = order.empty() ? k : order[k];
      const std::size_t c = m.face_component[f];
      if(!m.is_general() && m.component_border_edges[c] == 0 && m.component_first_face[c] == f) continue;   // pinned
      dof_[f] = n++;
    }
    n_ = n;
    la_.reset(new LA());
    if(n == 0) { m_ = &m; return; }
    // diagonal entries summed per face first, so that every matrix entry is added once
    std::vector<double> diagonal(n, 0.);
    std::vector<Matrix_entry> entries;
    entries.reserve(m.edge_sides.size() + n);   // an estimate (exact on manifold meshes)
    for(std::size_t e = 0; e < m.ne; ++e)
      for(std::size_t i = m.edge_side_begin[e]; i < m.edge_side_begin[e + 1]; ++i)
      {
        const std::size_t s = m.edge_sides[i], fi = dof_[s / 3];
        if(fi == npos) continue;
        diagonal[fi] += 1 / star[e];
        for(std::size_t j = m.edge_side_begin[e]; j < m.edge_side_begin[e + 1]; ++j)
        {
          const std::size_t t = m.edge_sides[j], fj = dof_[t / 3];
          if(j != i && fj != npos) entries.push_back({int(fi), int(fj), m.fs[s] * m.fs[t] / star[e]});
        }
      }
    // A nonmanifold surface may hold several 2-cycles per component, a nonorientable one none: no
    // face is pinned there; a shift of 1e-10 of the mean diagonal makes B definite, as in the authors'
    // code (d1 omega is orthogonal to every 2-cycle, so beta only moves along them).
    double shift = 0;
    if(m.is_general())
    {
      for(double d : diagonal) shift += d;
      shift *= 1e-10 / double(n);
    }
    for(std::size_t k = 0; k < n; ++k) entries.push_back({int(k), int(k), diagonal[k] + shift});
    A_ = assembled_matrix<Matrix>(n, entries);
    double D = 1;
    if(!la_->factor(*A_, D)) throw Solver_failure("factorization of the 2-form Laplacian failed");
    m_ = &m;
  }

  // Harmonic part gamma of omega (paper Eq. 9, Sec. 3.3): the coexact part delta beta is removed by
  // solving B beta = d1 omega, then gamma = omega - S1^-1 d1^T beta. The exact part vanishes for a
  // Darboux derivative of a jump harmonic function (App. A), so it is not computed.
  std::vector<double> harmonic_part(const std::vector<double>& omega) const
  {
    const Mesh_tables& m = *m_;
    std::vector<double> beta(m.nf, 0.);
    if(n_ > 0)
    {
      Vector rhs(static_cast<int>(n_));
      for(std::size_t k = 0; k < n_; ++k) rhs[k] = 0;
      for(std::size_t s = 0; s < 3 * m.nf; ++s)
        if(dof_[s / 3] != npos) rhs[dof_[s / 3]] += m.fs[s] * omega[m.fe[s]];
      Vector x(static_cast<int>(n_));
      if(!la_->linear_solver(rhs, x)) throw Solver_failure("2-form Laplace solve failed");
      for(std::size_t f = 0; f < m.nf; ++f)
        if(dof_[f] != npos)
        {
          beta[f] = x[dof_[f]];
          if(!std::isfinite(beta[f])) throw Solver_failure("2-form Laplace solve produced non-finite values");
        }
    }
    std::vector<double> gamma(omega);
    for(std::size_t s = 0; s < 3 * m.nf; ++s) gamma[m.fe[s]] -= m.fs[s] * beta[s / 3] / (*star_)[m.fe[s]];
    return gamma;
  }

  bool assembled() const { return m_ != nullptr; }

  // frees the matrix and its factorization (assemble() builds them again when needed)
  void release()
  {
    m_ = nullptr;
    la_.reset();
    A_.reset();
    std::vector<std::size_t>().swap(dof_);
    n_ = 0;
  }

private:
  const Mesh_tables* m_ = nullptr;
  const std::vector<double>* star_ = nullptr;
  std::vector<std::size_t> dof_;
  std::size_t n_ = 0;
  std::unique_ptr<Matrix> A_;
  std::unique_ptr<LA> la_;
};

// Up to this many cohomology classes (2g + b - 1 summed over the components), the harmonic part is
// projected on a harmonic basis (once per mesh: a factorization of the vertex Laplacian and one solve
// per class); beyond, the coexact part is removed with the 2-form Laplacian on the faces. Measured
// with CHOLMOD (2026-12-03): the face factorization costs about 1.4 times the vertex one, and one
// column of a many-column solve about 1/50 of the vertex factorization (577k vertices: 56 ms against
// 2.8 s; 17k vertices: 1.1 ms against 48 ms), so the basis is cheaper up to about 20 classes.
constexpr std::size_t harmonic_basis_max_classes = 24;

// Tree-cotree generators of the first cohomology H^1 of every component: 2g classes for a closed
// component, 2g + b - 1 for one with b border loops. T is a spanning tree of the component's
// vertices; C is a spanning tree of its faces across the edges outside T, rooted at a face (closed
// component) or at a virtual node behind the border edges outside T (bordered component). Each edge
// outside T and C, a generator edge, defines a closed integer 1-form zeta: 1 on that edge, 0 on T and
// on the other generator edges, and on C the values that close every face. A nonzero combination of
// the zetas vanishes on T but not everywhere, so it is not exact: the zetas are a basis of H^1.
struct Cohomology_generators
{
  std::vector<std::size_t> edges;         // the generator edge of each class
  std::vector<std::size_t> parent_side;   // per face: its side on the C edge towards the root (npos: root face)
  bool complete = false;                  // C reached every face and every component has its 2g + b - 1 classes

  std::size_t size() const { return edges.size(); }

  // zeta_k as (edge, value) pairs sorted by edge, values +-1. The curl that the generator edge puts
  // on each of its faces is carried along C to the root, where the two paths cancel (closed
  // component) or leave through the border (bordered component).
  std::vector<std::pair<std::size_t, double>> closed_form(const Mesh_tables& m, std::size_t k) const
  {
    const std::size_t g = edges[k];
    std::vector<std::pair<std::size_t, double>> zeta(1, std::make_pair(g, 1.));
    for(std::size_t i = m.edge_side_begin[g]; i < m.edge_side_begin[g + 1]; ++i)
    {
      const double curl = m.fs[m.edge_sides[i]];   // of zeta on the face of this side, before C is set
      std::size_t f = m.edge_sides[i] / 3;
      for(std::size_t p = parent_side[f]; p != npos; p = parent_side[f])
      {
        const std::size_t e = m.fe[p];
        zeta.emplace_back(e, -curl * m.fs[p]);   // closes f; the parent face then sees the same curl
        if(m.edge_arc[e] == npos) break;          // a border edge: C's root is the virtual node
        const Arc& a = m.arcs[m.edge_arc[e]];
        f = (a.left_side == p ? a.right_side : a.left_side) / 3;
      }
    }
    std::sort(zeta.begin(), zeta.end());
    std::size_t n = 0;   // merge repeated edges, drop the cancelled ones
    for(std::size_t i = 0; i < zeta.size();)
    {
      std::size_t j = i;
      double value = 0;
      for(; j < zeta.size() && zeta[j].first == zeta[i].first; ++j) value += zeta[j].second;
      if(value != 0) zeta[n++] = std::make_pair(zeta[i].first, value);
      i = j;
    }
    zeta.resize(n);
    return zeta;
  }
};

inline Cohomology_generators cohomology_generators(const Mesh_tables& m)
{
  Cohomology_generators gen;
  std::vector<char> in_tree(m.ne, 0), in_cotree(m.ne, 0), seen(m.nv, 0);
  std::vector<std::size_t> queue;
  // T: breadth-first spanning tree of the vertices of every component
  for(std::size_t root = 0; root < m.nv; ++root)
  {
    if(seen[root] || m.vertex_component[root] == npos) continue;
    seen[root] = 1;
    queue.assign(1, root);
    for(std::size_t q = 0; q < queue.size(); ++q)
    {
      const std::size_t v = queue[q];
      for(std::size_t i = m.vertex_corner_begin[v]; i < m.vertex_corner_begin[v + 1]; ++i)
      {
        const std::size_t c = m.vertex_corners[i];
        for(std::size_t s : {c, Mesh_tables::prev_in_face(c)})   // the two sides of the face at v
        {
          const std::size_t e = m.fe[s], x = m.ev[2 * e] == v ? m.ev[2 * e + 1] : m.ev[2 * e];
          if(seen[x]) continue;
          seen[x] = 1;
          in_tree[e] = 1;
          queue.push_back(x);
        }
      }
    }
  }
  // C: breadth-first spanning tree of the faces across edges outside T, from the virtual border
  // node of every bordered component and from the first face of every closed one
  gen.parent_side.assign(m.nf, npos);
  std::vector<char> reached(m.nf, 0);
  queue.clear();
  for(std::size_t e = 0; e < m.ne; ++e)
    if(m.edge_on_border[e] && !in_tree[e])
    {
      const std::size_t s = m.edge_sides[m.edge_side_begin[e]], f = s / 3;
      if(reached[f]) continue;
      reached[f] = 1;
      gen.parent_side[f] = s;
      in_cotree[e] = 1;
      queue.push_back(f);
    }
  for(std::size_t c = 0; c < m.n_components; ++c)
    if(m.component_border_edges[c] == 0)
    {
      reached[m.component_first_face[c]] = 1;
      queue.push_back(m.component_first_face[c]);
    }
  for(std::size_t q = 0; q < queue.size(); ++q)
    for(std::size_t s = 3 * queue[q]; s < 3 * queue[q] + 3; ++s)
    {
      const std::size_t e = m.fe[s];
      if(in_tree[e] || m.edge_arc[e] == npos) continue;
      const Arc& a = m.arcs[m.edge_arc[e]];
      const std::size_t other = a.left_side == s ? a.right_side : a.left_side;
      if(reached[other / 3]) continue;
      reached[other / 3] = 1;
      gen.parent_side[other / 3] = other;
      in_cotree[e] = 1;
      queue.push_back(other / 3);
    }
  // the generator edges, counted per component against the Euler characteristic
  std::vector<long> classes(m.n_components, 0);
  for(std::size_t e = 0; e < m.ne; ++e)
    if(!in_tree[e] && !in_cotree[e] && m.edge_side_begin[e] < m.edge_side_begin[e + 1])
    {
      gen.edges.push_back(e);
      ++classes[m.face_component[m.edge_sides[m.edge_side_begin[e]] / 3]];
    }
  gen.complete = queue.size() == m.nf;
  for(std::size_t c = 0; c < m.n_components; ++c)
    if(classes[c] != m.component_cohomology_classes(c))
      gen.complete = false;
  return gen;
}

// The harmonic 1-forms of the mesh (paper Sec. 2.5.1, App. A), per mesh: h_k = zeta_k - d0 phi_k with
// L0 phi_k = d0^T S1 zeta_k, L0 = d0^T S1 d0 the 0-form Laplacian on all vertices, so that h_k is
// closed and co-closed; and the Cholesky factor of their Gram matrix <h_j, h_k> in the S1 inner
// product. With 2g + b - 1 classes this costs a factorization of the size of the jump Laplacian and
// one solve per class, instead of the 2-form Laplacian on the (twice as many) faces.
template <class LA>
class Harmonic_basis
{
public:
  // assembled() becomes true only after success. L0: the factorized 0-form Laplacian, a
  // Jump_laplace_system with no vertex excluded (the jump Laplacian of a curve without interior
  // endpoints), whose edge weights are S1 = `star`. `share`: the solves of phi may be shared with a
  // thread that waits for the basis (Jump_laplace_system::solve_vertex_laplace()).
  void assemble(const Mesh_tables& m, const std::vector<double>& star, const Cohomology_generators& gen,
                const Jump_laplace_system<LA>& L0, Shared_work* share = nullptr)
  {
    m_ = nullptr;
    star_ = &star;
    const std::size_t K = gen.size();
    zeta_.assign(K, {});
    for(std::size_t k = 0; k < K; ++k) zeta_[k] = gen.closed_form(m, k);
    phi_ = L0.solve_vertex_laplace(K, [&](std::size_t k, std::vector<double>& b) {
      for(const auto& z : zeta_[k]) add_codifferential(m, z.first, star[z.first] * z.second, b);
    }, share);
    // Gram matrix: <h_j, h_k> = <zeta_j, h_k> because h_k is S1-orthogonal to the exact forms
    gram_.assign(K * K, 0.);
    std::vector<double> zk(m.ne, 0.);
    for(std::size_t k = 0; k < K; ++k)
    {
      for(const auto& z : zeta_[k]) zk[z.first] = z.second;
      const double* phik = phi_.data() + k * m.nv;
      for(std::size_t j = 0; j < K; ++j)
      {
        double sum = 0;
        for(const auto& z : zeta_[j])
        {
          const std::size_t e = z.first;
          sum += star[e] * z.second * (zk[e] - (phik[m.ev[2 * e + 1]] - phik[m.ev[2 * e]]));
        }
        gram_[j * K + k] = sum;
      }
      for(const auto& z : zeta_[k]) zk[z.first] = 0;
    }
    for(std::size_t j = 0; j < K; ++j)
      for(std::size_t k = 0; k < j; ++k) gram_[j * K + k] = gram_[k * K + j] = 0.5 * (gram_[j * K + k] + gram_[k * K + j]);
    // Cholesky factor in place (lower triangle)
    for(std::size_t j = 0; j < K; ++j)
    {
      double d = gram_[j * K + j];
      for(std::size_t i = 0; i < j; ++i) d -= gram_[j * K + i] * gram_[j * K + i];
      if(!(d > 0)) throw Solver_failure("the Gram matrix of the harmonic 1-forms is not positive definite");
      gram_[j * K + j] = std::sqrt(d);
      for(std::size_t r = j + 1; r < K; ++r)
      {
        double x = gram_[r * K + j];
        for(std::size_t i = 0; i < j; ++i) x -= gram_[r * K + i] * gram_[j * K + i];
        gram_[r * K + j] = x / gram_[j * K + j];
      }
    }
    m_ = &m;
  }

  // Harmonic part gamma of omega (paper Eq. 9, Sec. 3.3): the S1-orthogonal projection onto the
  // harmonic forms, gamma = sum_k c_k h_k with Gram c = (<h_j, omega>)_j. It differs from omega by
  // the exact and the coexact part; the exact part of a Darboux derivative of a jump harmonic
  // function is zero (App. A) up to the accuracy of the solve, and the residual problem does not
  // see exact forms anyway (they only move sigma).
  std::vector<double> harmonic_part(const std::vector<double>& omega) const
  {
    const Mesh_tables& m = *m_;
    const std::vector<double>& star = *star_;
    const std::size_t K = zeta_.size();
    std::vector<double> div(m.nv, 0.), c(K, 0.);
    for(std::size_t e = 0; e < m.ne; ++e) add_codifferential(m, e, star[e] * omega[e], div);
    for(std::size_t j = 0; j < K; ++j)   // <h_j, omega> = <zeta_j, omega> - <phi_j, d0^T S1 omega>
    {
      double r = 0;
      for(const auto& z : zeta_[j]) r += star[z.first] * z.second * omega[z.first];
      const double* phij = phi_.data() + j * m.nv;
      for(std::size_t v = 0; v < m.nv; ++v) r -= phij[v] * div[v];
      c[j] = r;
    }
    for(std::size_t j = 0; j < K; ++j)   // forward and back substitution with the Cholesky factor
    {
      for(std::size_t i = 0; i < j; ++i) c[j] -= gram_[j * K + i] * c[i];
      c[j] /= gram_[j * K + j];
    }
    for(std::size_t j = K; j-- > 0;)
    {
      for(std::size_t i = j + 1; i < K; ++i) c[j] -= gram_[i * K + j] * c[i];
      c[j] /= gram_[j * K + j];
    }
    std::vector<double> psi(m.nv, 0.), gamma(m.ne, 0.);   // sum_k c_k phi_k
    for(std::size_t k = 0; k < K; ++k)
    {
      const double* phik = phi_.data() + k * m.nv;
      for(std::size_t v = 0; v < m.nv; ++v) psi[v] += c[k] * phik[v];
    }
    for(std::size_t e = 0; e < m.ne; ++e) gamma[e] = psi[m.ev[2 * e]] - psi[m.ev[2 * e + 1]];
    for(std::size_t k = 0; k < K; ++k)
      for(const auto& z : zeta_[k]) gamma[z.first] += c[k] * z.second;
    return gamma;
  }

  bool assembled() const { return m_ != nullptr; }
  std::size_t size() const { return zeta_.size(); }

  void release()
  {
    m_ = nullptr;
    std::vector<std::vector<std::pair<std::size_t, double>>>().swap(zeta_);
    std::vector<double>().swap(phi_);
    std::vector<double>().swap(gram_);
  }

private:
  // adds d0^T of the 1-form that is `value` on edge e (and 0 elsewhere) to x: +value at the edge's
  // head, -value at its tail
  static void add_codifferential(const Mesh_tables& m, std::size_t e, double value, std::vector<double>& x)
  {
    x[m.ev[2 * e + 1]] += value;
    x[m.ev[2 * e]] -= value;
  }

  const Mesh_tables* m_ = nullptr;
  const std::vector<double>* star_ = nullptr;
  std::vector<std::vector<std::pair<std::size_t, double>>> zeta_;   // per class, sparse
  std::vector<double> phi_;                                         // per class, per vertex (nv x K)
  std::vector<double> gram_;                                        // K x K, Cholesky factor (lower)
};

// Curl d1 gamma per face (used by checks and tests).
inline std::vector<double> face_curl(const Mesh_tables& m, const std::vector<double>& form)
{
  std::vector<double> curl(m.nf, 0.);
  for(std::size_t s = 0; s < 3 * m.nf; ++s) curl[s / 3] += m.fs[s] * form[m.fe[s]];
  return curl;
}

} // namespace internal
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif
