// Sparse direct solvers for one process on the compressed rows of a
// Trilinos matrix, read as the columns of its transpose (solved transposed):
// - SuiteSparse UMFPACK (multifrontal, BLAS-3 on dense frontal matrices),
//   the symbolic analysis (ordering, elimination tree) kept while the
//   nonzero entries stay inside the pattern it was made for;
// - SuiteSparse KLU (left-looking, no BLAS: the fastest for a few thousand
//   unknowns), the analysis and the pivot order of the last full
//   factorization reused (klu_refactor) while the pivots stay sound.
// Both can leave out the entries that the sparsity pattern holds for
// couplings that may come and are zero (contact: 62 % of the 3-D ironing's
// entries); a Newton iteration whose nonzeros fit the analysed pattern then
// pays for the numerical factorization only.
#ifndef contact_dynamics_solvers_direct_factorization_h
#define contact_dynamics_solvers_direct_factorization_h

#include <contact_dynamics/solvers/trilinos_forward.h>

#include <cstdint>
#include <vector>

namespace ContactDynamics
{
  using namespace dealii;

  class DirectFactorization
  {
  public:
    enum class Method
    {
      klu,
      umfpack
    };

    // UMFPACK's fill-reducing ordering (KLU always orders with AMD)
    enum class Ordering
    {
      amd,
      metis
    };

    explicit DirectFactorization(const Method method);
    ~DirectFactorization();
    DirectFactorization(const DirectFactorization &) = delete;
    DirectFactorization &
    operator=(const DirectFactorization &) = delete;

    /**
     * Factorizes `matrix` (on one process only). Throws ExcMessage if the
     * matrix is singular.
     */
    void
    factorize(const TrilinosWrappers::SparseMatrix &matrix);

    /** solution = matrix^-1 rhs with the last factorization. */
    void
    solve(const TrilinosWrappers::MPI::Vector &rhs,
          TrilinosWrappers::MPI::Vector       &solution) const;

    /**
     * Symbolic analyses done: one per new sparsity pattern or nonzero
     * entry outside the analysed ones.
     */
    unsigned int
    n_symbolic_analyses() const
    {
      return n_symbolic;
    }

    /** KLU: factorizations with a new pivot order (the others reuse one). */
    unsigned int
    n_pivoting_factorizations() const
    {
      return n_pivoting;
    }

    /**
     * UMFPACK: the fill-reducing ordering of the next symbolic analysis
     * (AMD by default); a change forgets the analysis.
     */
    void
    set_ordering(const Ordering new_ordering);

    /**
     * Whether the analysis leaves out the entries that are zero when it is
     * made (false by default: every stored entry is factorized); a change
     * forgets the analysis.
     */
    void
    set_skip_zeros(const bool skip);

    /** UMFPACK: the entries of L and U of the last factorization. */
    double
    n_entries_of_factors() const
    {
      return n_factor_entries;
    }

    /** Forgets the factorization and the analysis. */
    void
    clear();

    /**
     * KLU: the next factorization searches its pivots anew (after a failed
     * Newton solve: the values may have moved far from the last pivoting).
     */
    void
    pivot_anew()
    {
      rcond_after_pivoting = 0;
    }

  private:
    void
    free_numeric();
    void
    free_symbolic();
    // the entries to factorize from the matrix's: false if they need a new
    // analysis
    bool
    select_entries();
    // UMFPACK or KLU on the stored rows; `new_pattern`: analyze first
    void
    factorize_umfpack(const bool new_pattern);
    void
    factorize_klu(const bool new_pattern);

    const Method method;
    Ordering     ordering   = Ordering::amd;
    bool         skip_zeros = false;
    // the rows of the matrix, column indices sorted
    std::vector<std::int64_t> matrix_start, matrix_columns;
    std::vector<double>       matrix_values;
    // the analysed pattern (the matrix's nonzeros when it was made) and
    // where each entry of the matrix goes in it
    std::vector<std::int64_t> row_start, columns, position;
    std::vector<double>       values;
    static constexpr std::int64_t invalid_position = -1;
    // the Trilinos matrix's row offsets and local columns, and where each
    // stored value sits in its value array: a Newton iteration with the
    // same pattern only gathers
    std::vector<int>          epetra_offsets, epetra_columns;
    std::vector<std::int64_t> source;
    // workspace of the solves, allocated once: fresh pages cost more than
    // a substitution
    mutable std::vector<std::int64_t> work_indices;
    mutable std::vector<double>       work;
    void                             *symbolic = nullptr;
    void                             *numeric  = nullptr;
    // KLU's settings and statistics (klu_l_common), and the reciprocal
    // condition estimate of the last full factorization
    void        *klu_common           = nullptr;
    double       rcond_after_pivoting = 0;
    unsigned int n_symbolic           = 0;
    unsigned int n_pivoting           = 0;
    double       n_factor_entries     = 0;
  };
} // namespace ContactDynamics

#endif
