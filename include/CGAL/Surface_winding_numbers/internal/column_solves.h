// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT
//
// The sparse systems of the linear-algebra traits: their assembly from a list of entries, solves with
// a factorized system for many right-hand sides at once, and the sharing of such work with a second
// thread (the Hodge step's many-column solve).

#ifndef CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_COLUMN_SOLVES_H
#define CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_COLUMN_SOLVES_H

#ifdef CGAL_EIGEN3_ENABLED
#include <Eigen/Core>
#endif

#include <condition_variable>
#include <cstddef>
#include <functional>
#include <memory>
#include <mutex>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace internal {

// An entry of a sparse matrix (the accessors are those of Eigen::Triplet)
struct Matrix_entry
{
  int i, j;
  double v;
  int row() const { return i; }
  int col() const { return j; }
  double value() const { return v; }
};

// The n x n matrix of the traits with the given entries (duplicates summed); `entries` is emptied
// and its memory freed. A traits matrix that wraps an Eigen matrix (CGAL::Eigen_sparse_matrix) is
// filled directly: its own list of entries would otherwise keep the capacity it grew to for as long
// as the matrix lives (74 MB at 577k unknowns, next to the factorization); any other gets add_coef().
template <class Matrix>
void fill_matrix(Matrix& A, std::vector<Matrix_entry>& entries, long)
{
  for(const Matrix_entry& e : entries) A.add_coef(e.i, e.j, e.v);
}

#ifdef CGAL_EIGEN3_ENABLED
template <class Matrix>
auto fill_matrix(Matrix& A, std::vector<Matrix_entry>& entries, int)
  -> decltype(A.eigen_object().setFromTriplets(entries.begin(), entries.end()), void())
{
  A.eigen_object().setFromTriplets(entries.begin(), entries.end());
}
#endif

template <class Matrix>
std::unique_ptr<Matrix> assembled_matrix(std::size_t n, std::vector<Matrix_entry>& entries)
{
  std::unique_ptr<Matrix> A(new Matrix(static_cast<int>(n), static_cast<int>(n)));
  fill_matrix(*A, entries, 0);
  std::vector<Matrix_entry>().swap(entries);
  return A;
}

// X = A^-1 B for the k columns of B (n x k, column-major; X is resized to n x k) with a factorized
// `la`: one solve per column, or a single pass over the factorization for all of them when the traits
// expose an Eigen solver (CGAL::Eigen_solver_traits; CHOLMOD's supernodal solve then works on blocks
// of columns). X's memory is reused when it has the size already.
template <class LA>
bool solve_columns(LA& la, const std::vector<double>& B, std::size_t n, std::size_t k, std::vector<double>& X, long)
{
  typename LA::Vector b(static_cast<int>(n)), x(static_cast<int>(n));
  X.resize(n * k);
  for(std::size_t j = 0; j < k; ++j)
  {
    for(std::size_t i = 0; i < n; ++i) b[i] = B[j * n + i];
    if(!la.linear_solver(b, x)) return false;
    for(std::size_t i = 0; i < n; ++i) X[j * n + i] = x[i];
  }
  return true;
}

#ifdef CGAL_EIGEN3_ENABLED
template <class LA>
auto solve_columns(LA& la, const std::vector<double>& B, std::size_t n, std::size_t k, std::vector<double>& X, int)
  -> decltype(la.solver().solve(Eigen::MatrixXd()), bool())
{
  X.resize(n * k);
  const Eigen::Map<const Eigen::MatrixXd> b(B.data(), Eigen::Index(n), Eigen::Index(k));
  Eigen::Map<Eigen::MatrixXd> x(X.data(), Eigen::Index(n), Eigen::Index(k));
  x = la.solver().solve(b);   // evaluated into X, no temporary
  return la.solver().info() == Eigen::Success;
}
#endif

// The many-column solves of solve_vertex_laplace(): with a solver that offers them (the package's
// CHOLMOD class), into a result and workspace kept from block to block; otherwise solve_columns().
template <class LA, class = void>
struct Has_workspace_solve : std::false_type {};
template <class LA>
struct Has_workspace_solve<LA, std::void_t<typename std::remove_reference_t<decltype(std::declval<LA&>().solver())>::Solve_workspace>>
  : std::true_type {};

template <class LA, bool = Has_workspace_solve<LA>::value>
class Column_solver
{
public:
  // X = A^-1 B for the k columns of B (n x k): a pointer to X, valid until the next call; nullptr on failure
  const double* solve(LA& la, const std::vector<double>& B, std::size_t n, std::size_t k)
  {
    return solve_columns(la, B, n, k, X_, 0) ? X_.data() : nullptr;
  }

private:
  std::vector<double> X_;
};

template <class LA>
class Column_solver<LA, true>
{
public:
  const double* solve(LA& la, const std::vector<double>& B, std::size_t n, std::size_t k)
  {
    return la.solver().solve_with_workspace(B.data(), n, k, ws_);
  }

private:
  typename std::remove_reference_t<decltype(std::declval<LA&>().solver())>::Solve_workspace ws_;
};

// A sparse vector: its nonzero entries, by increasing index
struct Sparse_column
{
  std::vector<std::size_t> index;
  std::vector<double> value;
};

// Solvers whose factorization A = P^T L L^T P offers the halves of a solve and the sparse forward
// solves of unit vectors (Supernodal_cholesky: forward(), backward(), unit_forward())
template <class LA, class = void>
struct Has_unit_forward : std::false_type {};
template <class LA>
struct Has_unit_forward<LA, std::void_t<decltype(std::declval<LA&>().solver().unit_forward(
                              std::size_t(0), std::declval<Sparse_column&>(), std::declval<std::vector<double>&>()))>>
  : std::true_type {};

// Work that a thread (the owner) shares with one that would otherwise wait for it (a helper): the
// owner publishes a function that claims and does pieces of the work until none is left, does it
// itself, and returns once every helper that joined is done; a helper joins if the work is published
// before the owner says it has finished everything it could share. Used by the Hodge step's
// many-column solve: the solving thread waits for the harmonic basis once it has solved for u.
class Shared_work
{
public:
  // owner: publishes `work`, does it, waits for the helpers; `work` must not throw
  void run(const std::function<void()>& work)
  {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      work_ = &work;
    }
    changed_.notify_all();
    work();
    std::unique_lock<std::mutex> lock(mutex_);
    work_ = nullptr;
    changed_.wait(lock, [this] { return helpers_ == 0; });
  }

  // owner: nothing (more) will be published
  void finish()
  {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      finished_ = true;
    }
    changed_.notify_all();
  }

  // helper: waits until work is published or finish() is called; does the work if it is published
  void help()
  {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [this] { return work_ != nullptr || finished_; });
    if(work_ == nullptr) return;
    const std::function<void()>& work = *work_;
    ++helpers_;
    lock.unlock();
    work();
    lock.lock();
    --helpers_;
    lock.unlock();
    changed_.notify_all();
  }

private:
  std::mutex mutex_;
  std::condition_variable changed_;
  const std::function<void()>* work_ = nullptr;
  std::size_t helpers_ = 0;
  bool finished_ = false;
};

// Right-hand sides per solve of solve_vertex_laplace(). A many-column solve reads the factorization
// once for all its columns, but each column's right side and solution are arrays of the system's size,
// and on the virtual machines of the benchmark every first touch of a 4 KiB page costs about 10
// microseconds (benchmark/RESULTS.md, Speed): 22 columns at once on 11,800 vertices touched 3,200
// new pages in the Hodge step of a whole solve (0.043 s for the solve), in blocks of 8 1,100 (0.027-
// 0.030 s), in blocks of two 400 (0.020 s). But measured alone with CHOLMOD, in blocks of 8 the
// columns cost 1.0-1.4 times as much as all at once, in blocks of 1, 2 or 4 up to 3.5 times (47k and
// 94k vertices), which larger meshes feel more than the page faults.
constexpr std::size_t vertex_laplace_block = 8;
} // namespace internal
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif
