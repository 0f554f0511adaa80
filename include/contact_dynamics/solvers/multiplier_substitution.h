// Rows of a Newton matrix with condensed contact multipliers substituted
// (internal to MultiplierCondensation).
#ifndef contact_dynamics_solvers_multiplier_substitution_h
#define contact_dynamics_solvers_multiplier_substitution_h

#include <deal.II/base/types.h>

#include <unordered_map>
#include <utility>
#include <vector>

class Epetra_CrsMatrix;

namespace ContactDynamics
{
  namespace internal
  {
    using Index     = dealii::types::global_dof_index;
    using SparseRow = std::vector<std::pair<Index, double>>;

    /** dlambda_m = -e - F du of one condensed multiplier. */
    struct MultiplierElimination
    {
      Index               multiplier = 0;
      double              e          = 0;
      std::vector<Index>  columns;
      std::vector<double> values;
    };

    /**
     * Rows of the matrix with the condensed multipliers substituted: in
     * 3-D a row collects some thirty eliminations of two hundred columns
     * each, merged in linear time in a dense accumulator over "slots" (the
     * matrix's local columns, then the columns of the eliminations it does
     * not hold) instead of sorted. Per Newton iteration it costs the
     * condensed entries, not the size of the matrix.
     */
    class Substitution
    {
    public:
      /** `all_eliminations` must hold every multiplier of `all_condensed`. */
      Substitution(const Epetra_CrsMatrix   &matrix,
                   const std::vector<Index> &all_condensed,
                   const std::unordered_map<Index, MultiplierElimination>
                     &all_eliminations);

      /** Whether the local column `c` is a condensed multiplier. */
      bool
      is_condensed_column(const int c) const
      {
        return elimination_of_column[c] >= 0;
      }

      /**
       * The locally owned `row` with dlambda = -e - F du substituted for
       * its condensed columns; their e terms are taken from `rhs_value`.
       * Zero entries (the contact pattern's reserved couplings) add
       * nothing and are skipped.
       */
      SparseRow
      operator()(const Index row, double &rhs_value);

    private:
      unsigned int
      slot(const Index column);

      void
      add_to_sum(const unsigned int s, const double value)
      {
        if (!touched[s])
          {
            touched[s] = true;
            touched_slots.push_back(s);
          }
        sum[s] += value;
      }

      const Epetra_CrsMatrix &matrix;
      // per local column: its elimination in `eliminations`, or -1
      std::vector<int> elimination_of_column;
      std::vector<
        std::pair<const MultiplierElimination *, std::vector<unsigned int>>>
                                              eliminations;
      std::unordered_map<Index, unsigned int> other_slot;
      std::vector<Index>                      slot_column;
      std::vector<double>                     sum;
      std::vector<bool>                       touched;
      std::vector<unsigned int>               touched_slots;
    };
  } // namespace internal
} // namespace ContactDynamics

#endif
