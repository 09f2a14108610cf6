// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT
//
// The package's sparse Cholesky factorization: CHOLMOD's symbolic analysis (ordering, supernodes,
// the pattern of L), then a left-looking supernodal numeric factorization and its solves on the
// calling thread with Eigen's dense kernels. CHOLMOD's own numeric factorization and solves run
// their dense work through the process's BLAS, whose threads (OpenBLAS starts one per core) fought
// with the package's second thread and with any other load on the machine: on 2 cores a 17k-unknown
// Laplacian took 0.7 s with two BLAS threads against 0.13 s with one (benchmark/RESULTS.md, Speed).
// How many threads the process's BLAS uses is the application's setting; the package needs none of
// them.

#ifndef CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_SUPERNODAL_CHOLESKY_H
#define CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_SUPERNODAL_CHOLESKY_H

#include <CGAL/Surface_winding_numbers/internal/column_solves.h>
#include <CGAL/Surface_winding_numbers/internal/nested_dissection.h>

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <cholmod.h>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace internal {

// A = L L^T of a sparse symmetric positive definite matrix (both triangles stored), as an Eigen
// sparse solver (compute(), info(), solve()) for CGAL::Eigen_solver_traits. The unknowns are
// eliminated in the matrix's own order above nested_dissection_unknowns (the package numbers them
// by geometric nested dissection), else in CHOLMOD's AMD order; should the given order's fill be far
// above what a surface mesh gives (more than 32 entries of L per entry of A; about 8 there), AMD's.
template <class EigenMatrix>
class Supernodal_cholesky
{
public:
  typedef double Scalar;
  typedef Eigen::Index Index;
  typedef Eigen::Map<Eigen::MatrixXd, 0, Eigen::OuterStride<>> Block;
  typedef Eigen::Map<const Eigen::MatrixXd, 0, Eigen::OuterStride<>> Const_block;

  Supernodal_cholesky& compute(const EigenMatrix& A)
  {
    ok_ = A.rows() == A.cols() && analyze(A) && factorize(A);
    return *this;
  }
  Eigen::ComputationInfo info() const { return ok_ ? Eigen::Success : Eigen::NumericalIssue; }
  Index rows() const { return Index(n_); }
  Index cols() const { return Index(n_); }
  // entries of L (with the explicit zeros of relaxed supernodes)
  std::size_t factor_entries() const { return Lx_.size(); }

  // The scratch arrays of solves, kept from one solve to the next; one per thread that solves.
  class Solve_workspace
  {
    friend class Supernodal_cholesky;
    std::vector<double> y_, x_, t_;
  };

  // A^-1 B for the k columns of B (n x k, column-major): a pointer to the n x k solution, held by `ws`
  // until its next solve; nullptr if there is no factorization. May be called by several threads at
  // once with different workspaces.
  const double* solve_with_workspace(const double* B, std::size_t n, std::size_t k, Solve_workspace& ws) const
  {
    if(!ok_ || n != n_) return nullptr;
    ws.y_.resize(n * k);
    ws.x_.resize(n * k);
    for(std::size_t j = 0; j < k; ++j)
      for(std::size_t i = 0; i < n; ++i) ws.y_[j * n + i] = B[j * n + perm_[i]];
    solve_in_place(ws.y_.data(), k, ws.t_);
    for(std::size_t j = 0; j < k; ++j)
      for(std::size_t i = 0; i < n; ++i) ws.x_[j * n + perm_[i]] = ws.y_[j * n + i];
    return ws.x_.data();
  }

  // The two halves of a solve with one right-hand side b (n values): w = L^-1 P b, in the factor's
  // order, then x = P^T L^-T w (w is overwritten); t: scratch
  void forward(const double* b, std::vector<double>& w, std::vector<double>& t) const
  {
    w.resize(n_);
    for(std::size_t i = 0; i < n_; ++i) w[i] = b[perm_[i]];
    forward_in_place(w.data(), 1, t);
  }
  void backward(std::vector<double>& w, double* x, std::vector<double>& t) const
  {
    backward_in_place(w.data(), 1, t);
    for(std::size_t i = 0; i < n_; ++i) x[perm_[i]] = w[i];
  }

  // g = L^-1 P e_d, the forward half for the unit vector of unknown d: nonzero only on the columns of
  // the supernodes from d's to the root of the elimination tree, the only ones visited. y: n zeros
  // (sized here the first time), left so.
  void unit_forward(std::size_t d, Sparse_column& g, std::vector<double>& y) const
  {
    y.resize(n_, 0.);
    g.index.clear();
    g.value.clear();
    std::vector<double> t;
    const std::size_t k = inverse_[d];
    y[k] = 1;
    for(std::size_t s = supernode_of_[k]; s != none_; s = parent_[s])
    {
      forward_supernode<Column>(s, y.data(), 1, t);
      const std::size_t k1 = super_[s], ncol = super_[s + 1] - k1;
      for(std::size_t i = k1; i < k1 + ncol; ++i)
      {
        if(y[i] != 0) { g.index.push_back(i); g.value.push_back(y[i]); }
        y[i] = 0;
      }
    }
  }

  template <class Rhs>
  Eigen::MatrixXd solve(const Eigen::MatrixBase<Rhs>& b) const
  {
    const Eigen::MatrixXd B = b;
    Eigen::MatrixXd X(B.rows(), B.cols());
    Solve_workspace ws;
    const double* x = B.rows() == Index(n_) ? solve_with_workspace(B.data(), n_, std::size_t(B.cols()), ws) : nullptr;
    if(x == nullptr) return Eigen::MatrixXd::Constant(B.rows(), B.cols(), std::numeric_limits<double>::quiet_NaN());
    std::copy(x, x + n_ * std::size_t(B.cols()), X.data());
    return X;
  }

private:
  // The symbolic factorization: permutation, supernodes (their columns super_[s] .. super_[s+1]-1),
  // the rows of each (rows_[row_begin_[s] ..], its own columns first) and where its dense
  // column-major block of L starts in Lx_.
  bool analyze(const EigenMatrix& A)
  {
    n_ = std::size_t(A.rows());
    cholmod_common c;
    cholmod_start(&c);
    c.nmethods = 1;
    c.supernodal = CHOLMOD_SUPERNODAL;
    c.method[0].ordering = n_ >= nested_dissection_unknowns ? CHOLMOD_NATURAL : CHOLMOD_AMD;
    // the pattern of the lower triangle (symmetric: CHOLMOD reads the upper part of the transpose)
    std::vector<int> p(n_ + 1, 0), i;
    i.reserve(std::size_t(A.nonZeros()));
    for(Index j = 0; j < A.outerSize(); ++j)
    {
      for(typename EigenMatrix::InnerIterator it(A, j); it; ++it)
        if(it.row() >= j) i.push_back(int(it.row()));
      p[std::size_t(j) + 1] = int(i.size());
    }
    cholmod_sparse S;
    S.nrow = S.ncol = n_;
    S.nzmax = i.size();
    S.p = p.data();
    S.i = i.data();
    S.nz = nullptr;
    S.x = S.z = nullptr;
    S.stype = -1;   // lower triangle
    S.itype = CHOLMOD_INT;
    S.xtype = CHOLMOD_PATTERN;
    S.dtype = CHOLMOD_DOUBLE;
    S.sorted = 1;
    S.packed = 1;
    cholmod_factor* L = cholmod_analyze(&S, &c);
    if(L != nullptr && c.method[0].ordering == CHOLMOD_NATURAL && c.lnz > 32. * double(A.nonZeros()) + 1000.)
    {
      cholmod_free_factor(&L, &c);
      c.method[0].ordering = CHOLMOD_AMD;
      L = cholmod_analyze(&S, &c);
    }
    const bool ok = L != nullptr && c.status == CHOLMOD_OK && L->is_super;
    if(ok)
    {
      const int* Perm = static_cast<const int*>(L->Perm);
      const int* super = static_cast<const int*>(L->super);
      const int* pi = static_cast<const int*>(L->pi);
      const int* px = static_cast<const int*>(L->px);
      const int* s = static_cast<const int*>(L->s);
      perm_.assign(Perm, Perm + n_);
      super_.assign(super, super + L->nsuper + 1);
      row_begin_.assign(pi, pi + L->nsuper + 1);
      block_begin_.assign(px, px + L->nsuper + 1);
      rows_.assign(s, s + pi[L->nsuper]);
      Lx_.assign(std::size_t(px[L->nsuper]), 0.);
      // the elimination tree of the supernodes: a supernode's parent holds its first row below its columns
      inverse_.resize(n_);
      supernode_of_.resize(n_);
      parent_.assign(L->nsuper, none_);
      for(std::size_t k = 0; k < n_; ++k) inverse_[perm_[k]] = k;
      for(std::size_t q = 0; q + 1 < super_.size(); ++q)
        for(std::size_t k = super_[q]; k < super_[q + 1]; ++k) supernode_of_[k] = q;
      for(std::size_t q = 0; q + 1 < super_.size(); ++q)
      {
        const std::size_t first_row = row_begin_[q] + (super_[q + 1] - super_[q]);
        if(first_row < row_begin_[q + 1]) parent_[q] = supernode_of_[rows_[first_row]];
      }
    }
    cholmod_free_factor(&L, &c);
    cholmod_finish(&c);
    return ok;
  }

  // Left-looking: each supernode gathers its columns of A and the updates of the supernodes below it
  // that reach its rows (linked in a list per supernode, as in CHOLMOD), then factorizes its diagonal
  // block and solves for the rest of its rows.
  bool factorize(const EigenMatrix& A)
  {
    const std::size_t ns = super_.size() - 1;
    std::vector<std::size_t> map(n_), next(ns, none_), head(ns, none_), position(ns, 0);
    std::vector<std::size_t> relative;
    Eigen::MatrixXd C;
    for(std::size_t s = 0; s < ns; ++s)
    {
      const std::size_t k1 = super_[s], k2 = super_[s + 1], ncol = k2 - k1;
      const std::size_t r0 = row_begin_[s], nrow = row_begin_[s + 1] - r0;
      for(std::size_t r = 0; r < nrow; ++r) map[rows_[r0 + r]] = r;
      double* X = Lx_.data() + block_begin_[s];
      std::fill(X, X + nrow * ncol, 0.);
      for(std::size_t k = k1; k < k2; ++k)
        for(typename EigenMatrix::InnerIterator it(A, Index(perm_[k])); it; ++it)
        {
          const std::size_t i = inverse_[std::size_t(it.row())];
          if(i >= k) X[map[i] + (k - k1) * nrow] += it.value();
        }
      for(std::size_t d = head[s]; d != none_;)
      {
        const std::size_t d_next = next[d];
        const std::size_t d0 = row_begin_[d], d_end = row_begin_[d + 1], d_nrow = d_end - d0, d_ncol = super_[d + 1] - super_[d];
        const std::size_t first = d0 + position[d];
        std::size_t last = first;
        while(last < d_end && rows_[last] < k2) ++last;
        const std::size_t n1 = last - first, n2 = d_end - first;
        const Const_block Ld(Lx_.data() + block_begin_[d] + position[d], Index(n2), Index(d_ncol), Eigen::OuterStride<>(Index(d_nrow)));
        C.resize(Index(n2), Index(n1));
        C.noalias() = Ld * Ld.topRows(Index(n1)).transpose();
        relative.resize(n2);
        for(std::size_t r = 0; r < n2; ++r) relative[r] = map[rows_[first + r]];
        for(std::size_t j = 0; j < n1; ++j)
        {
          double* Xj = X + relative[j] * nrow;
          const double* Cj = C.data() + j * n2;
          for(std::size_t r = j; r < n2; ++r) Xj[relative[r]] -= Cj[r];
        }
        position[d] = last - d0;
        if(last < d_end)
        {
          const std::size_t t = supernode_of_[rows_[last]];
          next[d] = head[t];
          head[t] = d;
        }
        d = d_next;
      }
      Block Ls(X, Index(nrow), Index(ncol), Eigen::OuterStride<>(Index(nrow)));
      Eigen::Ref<Eigen::MatrixXd, 0, Eigen::OuterStride<>> diagonal_block = Ls.topRows(Index(ncol));
      Eigen::LLT<Eigen::Ref<Eigen::MatrixXd, 0, Eigen::OuterStride<>>> llt(diagonal_block);   // in place
      if(llt.info() != Eigen::Success) return false;
      if(nrow > ncol)
      {
        Ls.topRows(Index(ncol)).template triangularView<Eigen::Lower>().transpose().template solveInPlace<Eigen::OnTheRight>(
          Ls.bottomRows(Index(nrow - ncol)));
        position[s] = ncol;
        const std::size_t t = supernode_of_[rows_[r0 + ncol]];
        next[s] = head[t];
        head[t] = s;
      }
    }
    return true;
  }

  // L L^T Y = Y for the k columns of Y (n x k, in the factor's order); t: scratch
  void solve_in_place(double* Y, std::size_t k, std::vector<double>& t) const
  {
    forward_in_place(Y, k, t);
    backward_in_place(Y, k, t);
  }

  // L Z = Y, Z in place of Y (one column as a vector: Eigen's kernels for vectors)
  void forward_in_place(double* Y, std::size_t k, std::vector<double>& t) const
  {
    if(k == 1) forward_pass<Column>(Y, k, t);
    else forward_pass<Block>(Y, k, t);
  }

  // L^T X = Y, X in place of Y
  void backward_in_place(double* Y, std::size_t k, std::vector<double>& t) const
  {
    if(k == 1) backward_pass<Column>(Y, k, t);
    else backward_pass<Block>(Y, k, t);
  }

  typedef Eigen::Map<Eigen::VectorXd> Column;
  // rows .. rows + r - 1 of the k columns of Y (n x k): a block, or a vector when k = 1
  Block rows_of(double* Y, std::size_t r, std::size_t k, const Block*) const
  {
    return Block(Y, Index(r), Index(k), Eigen::OuterStride<>(Index(n_)));
  }
  Column rows_of(double* Y, std::size_t r, std::size_t, const Column*) const { return Column(Y, Index(r)); }

  template <class Rhs>
  void forward_pass(double* Y, std::size_t k, std::vector<double>& t) const
  {
    for(std::size_t s = 0; s + 1 < super_.size(); ++s) forward_supernode<Rhs>(s, Y, k, t);
  }

  // the forward pass's work at supernode s: its columns of Z, and their updates of the rows below
  template <class Rhs>
  void forward_supernode(std::size_t s, double* Y, std::size_t k, std::vector<double>& t) const
  {
    const std::size_t k1 = super_[s], ncol = super_[s + 1] - k1, r0 = row_begin_[s], nrow = row_begin_[s + 1] - r0;
    const Const_block Ls(Lx_.data() + block_begin_[s], Index(nrow), Index(ncol), Eigen::OuterStride<>(Index(nrow)));
    Rhs Y1 = rows_of(Y + k1, ncol, k, static_cast<const Rhs*>(nullptr));
    Ls.topRows(Index(ncol)).template triangularView<Eigen::Lower>().solveInPlace(Y1);
    if(nrow == ncol) return;
    const std::size_t m = nrow - ncol;
    t.resize(m * k);
    Eigen::Map<typename Rhs::PlainObject> T(t.data(), Index(m), Index(k));
    T.noalias() = Ls.bottomRows(Index(m)) * Y1;
    for(std::size_t j = 0; j < k; ++j)
      for(std::size_t r = 0; r < m; ++r) Y[j * n_ + rows_[r0 + ncol + r]] -= t[j * m + r];
  }

  template <class Rhs>
  void backward_pass(double* Y, std::size_t k, std::vector<double>& t) const
  {
    const std::size_t ns = super_.size() - 1;
    for(std::size_t s = ns; s-- > 0;)
    {
      const std::size_t k1 = super_[s], ncol = super_[s + 1] - k1, r0 = row_begin_[s], nrow = row_begin_[s + 1] - r0;
      const Const_block Ls(Lx_.data() + block_begin_[s], Index(nrow), Index(ncol), Eigen::OuterStride<>(Index(nrow)));
      Rhs Y1 = rows_of(Y + k1, ncol, k, static_cast<const Rhs*>(nullptr));
      if(nrow > ncol)
      {
        const std::size_t m = nrow - ncol;
        t.resize(m * k);
        for(std::size_t j = 0; j < k; ++j)
          for(std::size_t r = 0; r < m; ++r) t[j * m + r] = Y[j * n_ + rows_[r0 + ncol + r]];
        const Eigen::Map<const typename Rhs::PlainObject> T(t.data(), Index(m), Index(k));
        Y1.noalias() -= Ls.bottomRows(Index(m)).transpose() * T;
      }
      Ls.topRows(Index(ncol)).template triangularView<Eigen::Lower>().transpose().solveInPlace(Y1);
    }
  }

  static constexpr std::size_t none_ = std::size_t(-1);
  bool ok_ = false;
  std::size_t n_ = 0;
  std::vector<std::size_t> perm_, super_, row_begin_, block_begin_, rows_;
  std::vector<std::size_t> inverse_, supernode_of_, parent_;   // by unknown: position in the factor; by position: supernode; by supernode
  std::vector<double> Lx_;
};

} // namespace internal
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif
