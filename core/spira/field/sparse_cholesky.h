#pragma once

#include <memory>
#include <vector>

#include "spira/field/symmetric_sparse_matrix.h"

namespace spira {

// How a CholeskyAnalysis orders the unknowns when no order is given.
enum class CholmodOrdering { Amd, Metis };

// The symbolic analysis of a sparse Cholesky factorisation (elimination order, elimination tree,
// supernodes) of one sparsity pattern. Computed once and shared by every numeric factorisation
// of a matrix with that pattern: the heat, Dirichlet and Poisson operators of a mesh all share it.
class CholeskyAnalysis {
 public:
  // Uses the given elimination order (order[k] = unknown eliminated k-th), for example from
  // geometricNestedDissection(). Values of `pattern` are ignored.
  CholeskyAnalysis(const SymmetricSparseMatrix& pattern, const std::vector<int>& order);
  // Lets CHOLMOD order the unknowns.
  CholeskyAnalysis(const SymmetricSparseMatrix& pattern, CholmodOrdering ordering);
  ~CholeskyAnalysis();
  CholeskyAnalysis(const CholeskyAnalysis&) = delete;
  CholeskyAnalysis& operator=(const CholeskyAnalysis&) = delete;

  int size() const;
  double factorNonZeros() const;  // entries of L
  double flops() const;           // of one numeric factorisation

 private:
  friend class CholeskyFactor;
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// A numeric supernodal Cholesky factorisation (CHOLMOD) of one symmetric positive definite
// matrix. Each factor has its own CHOLMOD workspace, so different factors can be computed and
// used on different threads at once; one factor solves on one thread at a time.
// BLAS runs single-threaded inside (see SingleThreadedBlas): parallelism comes from factorising
// independent matrices concurrently, which on surface meshes beats a threaded BLAS (whose
// fronts are small) and does not collapse when the cores are shared.
// Throws AlgorithmError if the matrix is not positive definite or memory runs out.
class CholeskyFactor {
 public:
  CholeskyFactor(const CholeskyAnalysis& analysis, const SymmetricSparseMatrix& matrix);
  ~CholeskyFactor();
  CholeskyFactor(const CholeskyFactor&) = delete;
  CholeskyFactor& operator=(const CholeskyFactor&) = delete;

  int size() const;
  std::vector<double> solve(const std::vector<double>& rhs) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// While one of these lives, BLAS runs on one thread (when the BLAS loaded is OpenBLAS, which
// Debian's CHOLMOD uses through the libblas alternative). Factorise on several threads at once
// only under it: OpenBLAS's own threads busy-wait, and two factorisations each with a BLAS team
// on two cores ran 5-10x slower than two single-threaded ones. Nests and may be shared by threads.
class SingleThreadedBlas {
 public:
  SingleThreadedBlas();
  ~SingleThreadedBlas();
  SingleThreadedBlas(const SingleThreadedBlas&) = delete;
  SingleThreadedBlas& operator=(const SingleThreadedBlas&) = delete;
};

}  // namespace spira
