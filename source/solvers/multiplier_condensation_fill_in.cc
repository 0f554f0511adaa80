// The sparsity side of the multiplier condensation: the entries it fills
// into the Jacobian's pattern, so that condense() may copy the Jacobian.
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <contact_dynamics/solvers/multiplier_condensation.h>

#include <algorithm>

namespace ContactDynamics
{
  using Index = types::global_dof_index;

  std::vector<MultiplierCondensation::FillIn>
  MultiplierCondensation::fill_in(const DynamicSparsityPattern       &pattern,
                                  const std::vector<MultiplierGroup> &groups)
  {
    // (not begin(row): for a row without entries it walks on to the next
    // stored row, O(n) per call)
    const auto columns_of = [&](const Index row) {
      std::vector<Index> columns(pattern.row_length(row));
      for (unsigned int k = 0; k < columns.size(); ++k)
        columns[k] = pattern.column_number(row, k);
      return columns;
    };
    const auto sorted = [](std::vector<Index> v) {
      std::sort(v.begin(), v.end());
      v.erase(std::unique(v.begin(), v.end()), v.end());
      return v;
    };
    // the condensation substitutes once, with the Jacobian's own rows:
    // the fill comes from the pattern without any of it (adding it group
    // by group would spread it along the surface)
    std::vector<FillIn> additions;
    for (const auto &group : groups)
      {
        // dlambda = -e - F du with F = E J_s, the group's displacement rows
        std::vector<Index> displacement_columns, multiplier_columns;
        for (const Index i : group.displacements)
          {
            const auto c = columns_of(i);
            displacement_columns.insert(displacement_columns.end(),
                                        c.begin(),
                                        c.end());
          }
        for (const Index m : group.multipliers)
          {
            const auto c = columns_of(m);
            multiplier_columns.insert(multiplier_columns.end(),
                                      c.begin(),
                                      c.end());
          }
        // a row with a multiplier column (by the pattern's symmetry, a
        // column of the multiplier's row) gets the columns of F; the
        // group's own rows take the multiplier rows and Q_2^T J_s
        std::vector<Index> own = displacement_columns;
        own.insert(own.end(),
                   multiplier_columns.begin(),
                   multiplier_columns.end());
        additions.push_back(
          {sorted(multiplier_columns), sorted(displacement_columns)});
        additions.push_back({group.displacements, sorted(own)});
      }
    return additions;
  }

  void
  MultiplierCondensation::add_fill_in(
    DynamicSparsityPattern             &dsp,
    const std::vector<MultiplierGroup> &groups)
  {
    for (const auto &addition : fill_in(dsp, groups))
      for (const Index r : addition.rows)
        if (dsp.row_index_set().size() == 0 ||
            dsp.row_index_set().is_element(r))
          dsp.add_entries(r,
                          addition.columns.begin(),
                          addition.columns.end(),
                          true);
  }
} // namespace ContactDynamics
