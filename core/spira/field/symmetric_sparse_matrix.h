#pragma once

#include <vector>

namespace spira {

// The lower triangle (diagonal included) of a symmetric n x n matrix in compressed sparse
// columns: column j holds the rows i >= j in increasing order, so its diagonal entry comes first.
// This is CHOLMOD's "stype = -1" layout, so a factorisation reads it without a copy.
struct SymmetricSparseMatrix {
  int size = 0;
  std::vector<int> columnStart;  // size + 1 entries
  std::vector<int> rowIndex;
  std::vector<double> values;

  int nonZeros() const { return columnStart.empty() ? 0 : columnStart.back(); }
  double diagonal(int j) const { return values[columnStart[j]]; }
  // Position of entry (row, col) with row >= col in rowIndex/values, or -1 if not stored.
  int find(int row, int col) const;
  // y = M x, using both triangles.
  std::vector<double> multiply(const std::vector<double>& x) const;
};

// Dirichlet conditions on a symmetric system: rows and columns of the fixed vertices become
// those of `diagonalValue` times the identity (same pattern, so a symbolic analysis is reused).
SymmetricSparseMatrix withFixedRows(const SymmetricSparseMatrix& m, const std::vector<char>& fixed,
                                    double diagonalValue);

// Right-hand side that moves the known values of fixed vertices to the free rows of K u = 0:
// r_i = -sum_{j fixed} K_ij u_j for free i, and r_j = diagonalValue * u_j for fixed j, so that
// withFixedRows(K, fixed, diagonalValue) u = r reproduces u_j on the fixed vertices.
std::vector<double> fixedRowsLift(const SymmetricSparseMatrix& k, const std::vector<char>& fixed,
                                  const std::vector<double>& fixedValues, double diagonalValue);

}  // namespace spira
