#include <deal.II/base/exceptions.h>

#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <contact_dynamics/solvers/multiplier_substitution.h>

namespace ContactDynamics
{
  namespace internal
  {
    Substitution::Substitution(
      const Epetra_CrsMatrix                                 &matrix,
      const std::vector<Index>                               &all_condensed,
      const std::unordered_map<Index, MultiplierElimination> &all_eliminations)
      : matrix(matrix)
      , elimination_of_column(matrix.NumMyCols(), -1)
      , slot_column(matrix.NumMyCols())
    {
      for (int c = 0; c < matrix.NumMyCols(); ++c)
        slot_column[c] = static_cast<Index>(matrix.GCID(c));
      for (const Index m : all_condensed)
        {
          const int c = matrix.LCID(static_cast<int>(m));
          if (c < 0)
            continue;
          const auto it = all_eliminations.find(m);
          Assert(it != all_eliminations.end(), dealii::ExcInternalError());
          elimination_of_column[c] = eliminations.size();
          eliminations.emplace_back(&it->second, std::vector<unsigned int>());
          for (const Index column : it->second.columns)
            eliminations.back().second.push_back(slot(column));
        }
      sum.assign(slot_column.size(), 0.);
      touched.assign(slot_column.size(), false);
    }

    SparseRow
    Substitution::operator()(const Index row, double &rhs_value)
    {
      int     n       = 0;
      double *values  = nullptr;
      int    *indices = nullptr;
      Assert(matrix.LRID(static_cast<int>(row)) >= 0,
             dealii::ExcInternalError());
      matrix.ExtractMyRowView(matrix.LRID(static_cast<int>(row)),
                              n,
                              values,
                              indices);
      for (int k = 0; k < n; ++k)
        if (values[k] == 0)
          continue;
        else if (elimination_of_column[indices[k]] < 0)
          add_to_sum(indices[k], values[k]);
        else
          {
            const auto &[elimination, slots] =
              eliminations[elimination_of_column[indices[k]]];
            rhs_value -= values[k] * elimination->e;
            for (unsigned int c = 0; c < slots.size(); ++c)
              add_to_sum(slots[c], -values[k] * elimination->values[c]);
          }
      SparseRow result;
      for (const unsigned int s : touched_slots)
        {
          if (sum[s] != 0)
            result.emplace_back(slot_column[s], sum[s]);
          sum[s]     = 0;
          touched[s] = false;
        }
      touched_slots.clear();
      return result;
    }

    unsigned int
    Substitution::slot(const Index column)
    {
      const int local = matrix.LCID(static_cast<int>(column));
      if (local >= 0)
        return local;
      const auto [it, inserted] =
        other_slot.try_emplace(column, slot_column.size());
      if (inserted)
        slot_column.push_back(column);
      return it->second;
    }
  } // namespace internal
} // namespace ContactDynamics
