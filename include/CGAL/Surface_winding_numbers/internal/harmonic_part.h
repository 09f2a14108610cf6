// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT

#ifndef CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_HARMONIC_PART_H
#define CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_HARMONIC_PART_H

#include <CGAL/Surface_winding_numbers/internal/mesh_tables.h>
#include <CGAL/Surface_winding_numbers/internal/nested_dissection.h>

#include <cmath>
#include <memory>
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
      if(m.component_border_edges[c] == 0 && m.component_first_face[c] == f) continue;   // pinned
      dof_[f] = n++;
    }
    n_ = n;
    la_.reset(new LA());
    if(n == 0) { m_ = &m; return; }
    // diagonal entries summed per face first, so that every matrix entry is added once
    std::vector<double> diagonal(n, 0.);
    A_.reset(new Matrix(static_cast<int>(n), static_cast<int>(n)));
    for(std::size_t e = 0; e < m.ne; ++e)
      for(std::size_t i = m.edge_side_begin[e]; i < m.edge_side_begin[e + 1]; ++i)
      {
        const std::size_t s = m.edge_sides[i], fi = dof_[s / 3];
        if(fi == npos) continue;
        diagonal[fi] += 1 / star[e];
        for(std::size_t j = m.edge_side_begin[e]; j < m.edge_side_begin[e + 1]; ++j)
        {
          const std::size_t t = m.edge_sides[j], fj = dof_[t / 3];
          if(j != i && fj != npos) A_->add_coef(fi, fj, m.fs[s] * m.fs[t] / star[e]);
        }
      }
    for(std::size_t k = 0; k < n; ++k) A_->add_coef(k, k, diagonal[k]);
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
