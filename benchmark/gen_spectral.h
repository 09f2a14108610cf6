// Benchmark generator: low-frequency eigenfunctions of the intrinsic Laplace-Beltrami operator
// (cotan Laplacian L and lumped mass matrix M, from edge lengths only), L phi = lambda M phi, for the
// "paper" suite's regions (the paper's Sec. 5.2 draws regions as sublevel sets of such functions).
//
// Subspace iteration on the factorization of L + s M (s a small shift that makes it definite), the
// constant removed in the M inner product at every step, Rayleigh-Ritz at the end. Low accuracy is
// enough: the functions only have to be smooth and of low frequency, not exact eigenvectors.
//
// The cases must not move with round-off (another compiler, other SIMD kernels, another machine):
// the generator's own linear algebra (Eigen's SimplicialLDLT with its AMD ordering, a fixed number of
// steps from a seeded start), nothing from the package's solvers; and a fixed choice of basis in
// each eigenspace. A dense eigensolver returns every eigenvector with an arbitrary sign and, where
// eigenvalues (nearly) coincide, an arbitrary basis of their eigenspace; both follow round-off (a
// -march=native build flipped signs on most meshes and changed 132 of the 285 paper cases). So the
// Ritz values are grouped into clusters (relative gap below cluster_gap), and each cluster's basis
// is the Gram-Schmidt (M inner product) of the projections of fixed seeded vectors onto it; for a
// lone eigenvector this is the sign that makes its M inner product with its seeded vector positive.

#ifndef SWN_BENCH_GEN_SPECTRAL_H
#define SWN_BENCH_GEN_SPECTRAL_H

#include "gen_common.h"

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace swn_bench {

// Relative gap under which two Ritz values count as one eigenspace (fix_eigenspace_bases())
constexpr double cluster_gap = 1e-3;

// Replaces the basis of every cluster of `V`'s columns (M-orthonormal Ritz vectors, `lambda` ascending)
// by the Gram-Schmidt, in the M inner product, of the projections of seeded random vectors r_j onto the
// cluster's span, so that the result depends on the span only: new_j is M-orthogonal to r_1..r_{j-1}'s
// projections and has a positive M inner product with r_j.
inline void fix_eigenspace_bases(Eigen::MatrixXd& V, const Eigen::VectorXd& lambda, const Eigen::VectorXd& mass, Rng rng)
{
  const Eigen::Index n = V.rows(), p = V.cols();
  Eigen::MatrixXd R(n, p);
  for(Eigen::Index i = 0; i < n; ++i)
    for(Eigen::Index k = 0; k < p; ++k) R(i, k) = rng.uniform(-1, 1);
  for(Eigen::Index b = 0; b < p;)
  {
    Eigen::Index e = b + 1;   // the cluster is columns b..e-1
    while(e < p && lambda[e] - lambda[e - 1] < cluster_gap * std::abs(lambda[e])) ++e;
    // C(i, j): coordinate of r_j's projection on V's column b + i; V is M-orthonormal, so Gram-Schmidt
    // of the projections in the M inner product is Gram-Schmidt of C's columns in the plain one
    Eigen::MatrixXd C = V.middleCols(b, e - b).transpose() * mass.asDiagonal() * R.middleCols(b, e - b);
    for(Eigen::Index j = 0; j < C.cols(); ++j)
    {
      for(Eigen::Index i = 0; i < j; ++i) C.col(j) -= C.col(i).dot(C.col(j)) * C.col(i);
      C.col(j) /= C.col(j).norm();
    }
    V.middleCols(b, e - b) = V.middleCols(b, e - b) * C;
    b = e;
  }
}

// The `count` lowest nonconstant eigenfunctions per vertex (each M-normalized), lowest first;
// `eigenvalues` receives their Ritz values.
inline std::vector<std::vector<double>> low_frequency_eigenfunctions(const Mesh& m, int count,
                                                                     std::vector<double>* eigenvalues = nullptr)
{
  const Eigen::Index n = Eigen::Index(m.number_of_vertices());
  std::vector<Eigen::Triplet<double>> tl;
  Eigen::VectorXd mass = Eigen::VectorXd::Zero(n);
  for(FI f : m.faces())
  {
    const HI h0 = m.halfedge(f);
    const HI hs[3] = {h0, m.next(h0), m.next(m.next(h0))};
    double l[3];   // l[k]: length of the edge of hs[k]
    for(int k = 0; k < 3; ++k) l[k] = std::sqrt(CGAL::squared_distance(m.point(m.source(hs[k])), m.point(m.target(hs[k]))));
    const double s = 0.5 * (l[0] + l[1] + l[2]);
    const double area = std::sqrt(std::max(0., s * (s - l[0]) * (s - l[1]) * (s - l[2])));   // Heron: intrinsic
    if(area <= 0) throw std::runtime_error("eigenfunctions: zero-area face");
    for(int k = 0; k < 3; ++k)
    {
      // the angle opposite edge k is at the vertex not on it; cot = (a^2 + b^2 - c^2) / (4 area)
      const double a = l[(k + 1) % 3], b = l[(k + 2) % 3], c = l[k];
      const double w = 0.5 * (a * a + b * b - c * c) / (4 * area);
      const Eigen::Index i = Eigen::Index(m.source(hs[k])), j = Eigen::Index(m.target(hs[k]));
      tl.emplace_back(i, j, -w);
      tl.emplace_back(j, i, -w);
      tl.emplace_back(i, i, w);
      tl.emplace_back(j, j, w);
      mass[Eigen::Index(m.target(hs[k]))] += area / 3;
    }
  }
  Eigen::SparseMatrix<double> L(n, n);
  L.setFromTriplets(tl.begin(), tl.end());
  const double shift = 1e-6 * L.diagonal().sum() / mass.sum();
  Eigen::SparseMatrix<double> A = L;
  for(Eigen::Index i = 0; i < n; ++i) A.coeffRef(i, i) += shift * mass[i];
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::AMDOrdering<int>> solver(A);
  if(solver.info() != Eigen::Success) throw std::runtime_error("eigenfunctions: factorization failed");

  const int p = count + 6;   // block size: a few more than wanted speeds up the convergence
  Rng rng(hash_string("eigen", std::uint64_t(n)));
  Eigen::MatrixXd X(n, p);
  for(Eigen::Index i = 0; i < n; ++i)
    for(int k = 0; k < p; ++k) X(i, k) = rng.uniform(-1, 1);
  const double total_mass = mass.sum();
  auto remove_constant_and_orthonormalize = [&](Eigen::MatrixXd& Y) {
    for(int k = 0; k < p; ++k) Y.col(k).array() -= mass.dot(Y.col(k)) / total_mass;
    const Eigen::MatrixXd G = Y.transpose() * mass.asDiagonal() * Y;
    const Eigen::LLT<Eigen::MatrixXd> llt(G);
    Y = llt.matrixU().solve<Eigen::OnTheRight>(Y);   // Y R^-1: M-orthonormal columns
  };
  remove_constant_and_orthonormalize(X);
  for(int it = 0; it < 40; ++it)
  {
    const Eigen::MatrixXd B = mass.asDiagonal() * X;
    X = solver.solve(B);
    remove_constant_and_orthonormalize(X);
  }
  // Rayleigh-Ritz: X is M-orthonormal, so the small problem is an ordinary symmetric one
  const Eigen::MatrixXd K = X.transpose() * (L * X);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(0.5 * (K + K.transpose()));
  Eigen::MatrixXd V = X * es.eigenvectors();
  fix_eigenspace_bases(V, es.eigenvalues(), mass, Rng(hash_string("eigen/basis", std::uint64_t(n))));
  std::vector<std::vector<double>> phi(static_cast<std::size_t>(count), std::vector<double>(static_cast<std::size_t>(n)));
  for(int k = 0; k < count; ++k)
    for(Eigen::Index i = 0; i < n; ++i) phi[std::size_t(k)][std::size_t(i)] = V(i, k);
  if(eigenvalues)
  {
    eigenvalues->clear();
    for(int k = 0; k < count; ++k) eigenvalues->push_back(es.eigenvalues()[k]);
  }
  return phi;
}

} // namespace swn_bench

#endif // SWN_BENCH_GEN_SPECTRAL_H
