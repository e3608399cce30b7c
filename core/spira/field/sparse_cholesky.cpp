#include "spira/field/sparse_cholesky.h"

#include <cholmod.h>
#include <dlfcn.h>

#include <mutex>
#include <string>

#include "spira/base/error.h"

namespace spira {
namespace {

void configure(cholmod_common& c)
{
  cholmod_start(&c);
  c.print = 0;  // errors are reported by exception, not on stdout
  c.supernodal = CHOLMOD_SUPERNODAL;
  c.nmethods = 1;
  c.postorder = 1;
}

// A view of our matrix in CHOLMOD's layout, without copying (CHOLMOD does not write to inputs).
cholmod_sparse view(const SymmetricSparseMatrix& m)
{
  cholmod_sparse a{};
  a.nrow = a.ncol = size_t(m.size);
  a.nzmax = size_t(m.nonZeros());
  a.p = const_cast<int*>(m.columnStart.data());
  a.i = const_cast<int*>(m.rowIndex.data());
  a.x = const_cast<double*>(m.values.data());
  a.stype = -1;
  a.itype = CHOLMOD_INT;
  a.xtype = CHOLMOD_REAL;
  a.dtype = CHOLMOD_DOUBLE;
  a.sorted = 1;
  a.packed = 1;
  return a;
}

[[noreturn]] void fail(const cholmod_common& c, const std::string& what)
{
  if (c.status == CHOLMOD_OUT_OF_MEMORY || c.status == CHOLMOD_TOO_LARGE)
    throw AlgorithmError(what + ": out of memory", "use a coarser mesh or free memory");
  throw AlgorithmError(what + " failed (CHOLMOD status " + std::to_string(c.status) + ")",
                       "check the mesh for degenerate or inverted faces");
}

void checkPattern(const SymmetricSparseMatrix& m)
{
  if (int(m.columnStart.size()) != m.size + 1 || int(m.rowIndex.size()) != m.nonZeros() ||
      int(m.values.size()) != m.nonZeros())
    throw InternalError("malformed sparse matrix given to the Cholesky solver");
}

// OpenBLAS's thread controls, looked up at run time: the BLAS behind CHOLMOD is chosen by the
// system (Debian alternatives), so it may be another library that has no such functions.
struct BlasThreads {
  using Get = int (*)();
  using Set = void (*)(int);
  Get get = reinterpret_cast<Get>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
  Set set = reinterpret_cast<Set>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
  std::mutex mutex;
  int depth = 0;
  int saved = 0;
};

BlasThreads& blasThreads()
{
  static BlasThreads b;
  return b;
}

}  // namespace

SingleThreadedBlas::SingleThreadedBlas()
{
  BlasThreads& b = blasThreads();
  if (!b.get || !b.set) return;
  const std::lock_guard<std::mutex> lock(b.mutex);
  if (b.depth++ == 0) {
    b.saved = b.get();
    b.set(1);
  }
}

SingleThreadedBlas::~SingleThreadedBlas()
{
  BlasThreads& b = blasThreads();
  if (!b.get || !b.set) return;
  const std::lock_guard<std::mutex> lock(b.mutex);
  if (--b.depth == 0) b.set(b.saved);
}

struct CholeskyAnalysis::Impl {
  cholmod_common common;
  cholmod_factor* symbolic = nullptr;
  double lnz = 0.0, fl = 0.0;
  ~Impl()
  {
    if (symbolic) cholmod_free_factor(&symbolic, &common);
    cholmod_finish(&common);
  }
};

CholeskyAnalysis::CholeskyAnalysis(const SymmetricSparseMatrix& pattern, const std::vector<int>& order)
    : impl_(std::make_unique<Impl>())
{
  checkPattern(pattern);
  if (int(order.size()) != pattern.size) throw InternalError("elimination order does not match the matrix");
  configure(impl_->common);
  impl_->common.method[0].ordering = CHOLMOD_GIVEN;
  cholmod_sparse a = view(pattern);
  impl_->symbolic = cholmod_analyze_p(&a, const_cast<int*>(order.data()), nullptr, 0, &impl_->common);
  if (!impl_->symbolic) fail(impl_->common, "sparse Cholesky analysis");
  impl_->lnz = impl_->common.lnz;
  impl_->fl = impl_->common.fl;
}

CholeskyAnalysis::CholeskyAnalysis(const SymmetricSparseMatrix& pattern, CholmodOrdering ordering)
    : impl_(std::make_unique<Impl>())
{
  checkPattern(pattern);
  configure(impl_->common);
  impl_->common.method[0].ordering = ordering == CholmodOrdering::Metis ? CHOLMOD_METIS : CHOLMOD_AMD;
  cholmod_sparse a = view(pattern);
  impl_->symbolic = cholmod_analyze(&a, &impl_->common);
  if (!impl_->symbolic) fail(impl_->common, "sparse Cholesky analysis");
  impl_->lnz = impl_->common.lnz;
  impl_->fl = impl_->common.fl;
}

CholeskyAnalysis::~CholeskyAnalysis() = default;
int CholeskyAnalysis::size() const
{
  return int(impl_->symbolic->n);
}
double CholeskyAnalysis::factorNonZeros() const
{
  return impl_->lnz;
}
double CholeskyAnalysis::flops() const
{
  return impl_->fl;
}

struct CholeskyFactor::Impl {
  mutable cholmod_common common;
  cholmod_factor* factor = nullptr;
  ~Impl()
  {
    if (factor) cholmod_free_factor(&factor, &common);
    cholmod_finish(&common);
  }
};

CholeskyFactor::CholeskyFactor(const CholeskyAnalysis& analysis, const SymmetricSparseMatrix& matrix)
    : impl_(std::make_unique<Impl>())
{
  checkPattern(matrix);
  if (matrix.size != analysis.size()) throw InternalError("matrix does not match its Cholesky analysis");
  configure(impl_->common);
  impl_->factor = cholmod_copy_factor(analysis.impl_->symbolic, &impl_->common);
  if (!impl_->factor) fail(impl_->common, "copying the Cholesky analysis");
  cholmod_sparse a = view(matrix);
  const SingleThreadedBlas oneThread;
  const int ok = cholmod_factorize(&a, impl_->factor, &impl_->common);
  if (!ok || impl_->common.status == CHOLMOD_NOT_POSDEF || impl_->factor->minor < impl_->factor->n) {
    if (impl_->common.status == CHOLMOD_NOT_POSDEF || (ok && impl_->factor->minor < impl_->factor->n))
      throw AlgorithmError("the linear system is not positive definite (pivot " +
                               std::to_string(impl_->factor->minor) + " of " +
                               std::to_string(impl_->factor->n) + ")",
                           "check the mesh for degenerate, duplicate or inverted faces");
    fail(impl_->common, "sparse Cholesky factorisation");
  }
}

CholeskyFactor::~CholeskyFactor() = default;
int CholeskyFactor::size() const
{
  return int(impl_->factor->n);
}

std::vector<double> CholeskyFactor::solve(const std::vector<double>& rhs) const
{
  const size_t n = impl_->factor->n;
  if (rhs.size() != n) throw InternalError("right-hand side does not match the factorised matrix");
  cholmod_dense b{};
  b.nrow = n;
  b.ncol = 1;
  b.nzmax = n;
  b.d = n;
  b.x = const_cast<double*>(rhs.data());
  b.xtype = CHOLMOD_REAL;
  b.dtype = CHOLMOD_DOUBLE;
  const SingleThreadedBlas oneThread;
  cholmod_dense* x = cholmod_solve(CHOLMOD_A, impl_->factor, &b, &impl_->common);
  if (!x) fail(impl_->common, "sparse Cholesky solve");
  const double* xs = static_cast<const double*>(x->x);
  std::vector<double> out(xs, xs + n);
  cholmod_free_dense(&x, &impl_->common);
  return out;
}

}  // namespace spira
