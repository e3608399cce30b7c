#include "spira/field/symmetric_sparse_matrix.h"

#include <algorithm>

namespace spira {

int SymmetricSparseMatrix::find(int row, int col) const
{
  const auto begin = rowIndex.begin() + columnStart[col];
  const auto end = rowIndex.begin() + columnStart[col + 1];
  const auto it = std::lower_bound(begin, end, row);
  return (it != end && *it == row) ? int(it - rowIndex.begin()) : -1;
}

std::vector<double> SymmetricSparseMatrix::multiply(const std::vector<double>& x) const
{
  std::vector<double> y(size, 0.0);
  for (int j = 0; j < size; ++j) {
    double sum = 0.0;
    for (int k = columnStart[j]; k < columnStart[j + 1]; ++k) {
      const int i = rowIndex[k];
      sum += values[k] * x[i];
      if (i != j) y[i] += values[k] * x[j];
    }
    y[j] += sum;
  }
  return y;
}

SymmetricSparseMatrix withFixedRows(const SymmetricSparseMatrix& m, const std::vector<char>& fixed,
                                    double diagonalValue)
{
  SymmetricSparseMatrix out = m;
  for (int j = 0; j < m.size; ++j) {
    for (int k = m.columnStart[j]; k < m.columnStart[j + 1]; ++k) {
      const int i = m.rowIndex[k];
      if (i == j) {
        if (fixed[j]) out.values[k] = diagonalValue;
      } else if (fixed[i] || fixed[j]) {
        out.values[k] = 0.0;
      }
    }
  }
  return out;
}

std::vector<double> fixedRowsLift(const SymmetricSparseMatrix& k, const std::vector<char>& fixed,
                                  const std::vector<double>& fixedValues, double diagonalValue)
{
  std::vector<double> r(k.size, 0.0);
  for (int j = 0; j < k.size; ++j) {
    for (int p = k.columnStart[j]; p < k.columnStart[j + 1]; ++p) {
      const int i = k.rowIndex[p];
      if (i == j) continue;
      if (fixed[j] && !fixed[i]) r[i] -= k.values[p] * fixedValues[j];
      if (fixed[i] && !fixed[j]) r[j] -= k.values[p] * fixedValues[i];
    }
  }
  for (int j = 0; j < k.size; ++j)
    if (fixed[j]) r[j] = diagonalValue * fixedValues[j];
  return r;
}

}  // namespace spira
