// A sparse direct solver for one process: SuiteSparse UMFPACK (multifrontal,
// BLAS-3 on dense frontal matrices) on the compressed rows of a Trilinos
// matrix. The symbolic analysis (ordering, elimination tree) is kept while
// the sparsity pattern does not change, so a Newton iteration pays for the
// numerical factorization only.
#ifndef contact_dynamics_solvers_umfpack_factorization_h
#define contact_dynamics_solvers_umfpack_factorization_h

#include <contact_dynamics/solvers/trilinos_forward.h>

#include <cstdint>
#include <vector>

namespace ContactDynamics
{
  using namespace dealii;

  class UmfpackFactorization
  {
  public:
    UmfpackFactorization() = default;
    ~UmfpackFactorization();
    UmfpackFactorization(const UmfpackFactorization &) = delete;
    UmfpackFactorization &
    operator=(const UmfpackFactorization &) = delete;

    /**
     * Factorizes `matrix` (on one process). Throws ExcMessage if the
     * matrix is singular or the run has more than one process.
     */
    void
    factorize(const TrilinosWrappers::SparseMatrix &matrix);

    /** solution = matrix^-1 rhs with the last factorization. */
    void
    solve(const TrilinosWrappers::MPI::Vector &rhs,
          TrilinosWrappers::MPI::Vector       &solution) const;

    /** Symbolic analyses done (one per new sparsity pattern). */
    unsigned int
    n_symbolic_analyses() const
    {
      return n_symbolic;
    }

  private:
    void
    free_numeric();
    void
    free_symbolic();

    // the rows of the matrix, column indices sorted: UMFPACK reads them as
    // the columns of the transpose
    std::vector<std::int64_t> row_start, columns;
    std::vector<double>       values;
    void                     *symbolic   = nullptr;
    void                     *numeric    = nullptr;
    unsigned int              n_symbolic = 0;
  };
} // namespace ContactDynamics

#endif
