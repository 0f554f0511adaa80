#include <deal.II/base/exceptions.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <contact_dynamics/solvers/multiplier_condensation.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <unordered_map>

namespace ContactDynamics
{
  using Index = types::global_dof_index;

  struct MultiplierCondensation::Elimination
  {
    Index               multiplier = 0;
    double              e          = 0;
    std::vector<Index>  columns;
    std::vector<double> values;
  };

  namespace
  {
    using SparseRow = std::vector<std::pair<Index, double>>;

    /** A locally owned row of the matrix. */
    SparseRow
    read_row(const Epetra_CrsMatrix &matrix, const Index row)
    {
      const int local = matrix.LRID(static_cast<int>(row));
      Assert(local >= 0, ExcInternalError());
      int     n       = 0;
      double *values  = nullptr;
      int    *indices = nullptr;
      matrix.ExtractMyRowView(local, n, values, indices);
      SparseRow result(n);
      for (int k = 0; k < n; ++k)
        result[k] = {static_cast<Index>(matrix.GCID(indices[k])), values[k]};
      return result;
    }

    /** Adds up the entries of equal columns; drops exact zeros. */
    void
    compress_row(SparseRow &row)
    {
      std::sort(row.begin(), row.end(), [](const auto &a, const auto &b) {
        return a.first < b.first;
      });
      SparseRow merged;
      for (const auto &entry : row)
        if (!merged.empty() && merged.back().first == entry.first)
          merged.back().second += entry.second;
        else
          merged.push_back(entry);
      row.clear();
      for (const auto &entry : merged)
        if (entry.second != 0)
          row.push_back(entry);
    }

    double
    entry(const SparseRow &row, const Index column)
    {
      for (const auto &e : row)
        if (e.first == column)
          return e.second;
      return 0.;
    }

    /**
     * Gram-Schmidt on the k columns of b (dim x k), completed to an
     * orthonormal basis q (columns) with b = q_1 r; false if b is rank
     * deficient.
     */
    bool
    orthonormal_basis(const std::vector<std::vector<double>> &b,
                      std::vector<std::vector<double>>       &q,
                      std::vector<std::vector<double>>       &r)
    {
      const unsigned int dim = b.size(), k = b.empty() ? 0 : b[0].size();
      q.assign(dim, std::vector<double>(dim, 0.));
      r.assign(k, std::vector<double>(k, 0.));
      double largest = 0;
      for (unsigned int a = 0; a < k; ++a)
        {
          double norm = 0;
          for (unsigned int d = 0; d < dim; ++d)
            norm += b[d][a] * b[d][a];
          largest = std::max(largest, std::sqrt(norm));
        }
      if (!(largest > 0))
        return false;
      unsigned int n_columns     = 0;
      const auto   orthogonalize = [&](std::vector<double>  v,
                                     std::vector<double> *coefficients) {
        for (int pass = 0; pass < 2; ++pass)
          for (unsigned int c = 0; c < n_columns; ++c)
            {
              double dot = 0;
              for (unsigned int d = 0; d < dim; ++d)
                dot += q[d][c] * v[d];
              for (unsigned int d = 0; d < dim; ++d)
                v[d] -= dot * q[d][c];
              if (coefficients)
                (*coefficients)[c] += dot;
            }
        return v;
      };
      for (unsigned int a = 0; a < k; ++a)
        {
          std::vector<double> column(dim), coefficients(k, 0.);
          for (unsigned int d = 0; d < dim; ++d)
            column[d] = b[d][a];
          const auto v    = orthogonalize(column, &coefficients);
          double     norm = 0;
          for (const double x : v)
            norm += x * x;
          norm = std::sqrt(norm);
          if (norm < 1e-10 * largest)
            return false;
          for (unsigned int c = 0; c < a; ++c)
            r[c][a] = coefficients[c];
          r[a][a] = norm;
          for (unsigned int d = 0; d < dim; ++d)
            q[d][n_columns] = v[d] / norm;
          ++n_columns;
        }
      // completion by the unit vectors, largest remainder first
      while (n_columns < dim)
        {
          std::vector<double> best;
          double              best_norm = 0;
          for (unsigned int u = 0; u < dim; ++u)
            {
              std::vector<double> e(dim, 0.);
              e[u]            = 1;
              const auto v    = orthogonalize(e, nullptr);
              double     norm = 0;
              for (const double x : v)
                norm += x * x;
              if (norm > best_norm)
                {
                  best_norm = norm;
                  best      = v;
                }
            }
          for (unsigned int d = 0; d < dim; ++d)
            q[d][n_columns] = best[d] / std::sqrt(best_norm);
          ++n_columns;
        }
      return true;
    }
  } // namespace

  MultiplierCondensation::MultiplierCondensation()
    : condensed_matrix(std::make_unique<TrilinosWrappers::SparseMatrix>())
    , condensed_rhs(std::make_unique<TrilinosWrappers::MPI::Vector>())
  {}

  MultiplierCondensation::~MultiplierCondensation() = default;

  const TrilinosWrappers::SparseMatrix &
  MultiplierCondensation::matrix() const
  {
    return *condensed_matrix;
  }

  const TrilinosWrappers::MPI::Vector &
  MultiplierCondensation::rhs() const
  {
    return *condensed_rhs;
  }

  void
  MultiplierCondensation::condense(
    const TrilinosWrappers::SparseMatrix &jacobian,
    const TrilinosWrappers::MPI::Vector  &rhs,
    const std::vector<MultiplierGroup>   &groups,
    const bool                            copy_jacobian)
  {
    const Epetra_CrsMatrix &matrix = jacobian.trilinos_matrix();
    const IndexSet         &owned  = rhs.locally_owned_elements();
    const MPI_Comm          comm   = rhs.get_mpi_communicator();

    // 1. which groups can be condensed, with their bases
    struct GroupElimination
    {
      const MultiplierGroup           *group = nullptr;
      std::vector<SparseRow>           rows; // of the displacements
      std::vector<std::vector<double>> q, r;
    };
    std::vector<GroupElimination> condensed;
    std::vector<Index>            condensed_multipliers;
    for (const auto &group : groups)
      {
        GroupElimination g;
        g.group = &group;
        for (const Index i : group.displacements)
          g.rows.push_back(read_row(matrix, i));
        std::vector<std::vector<double>> b(group.displacements.size(),
                                           std::vector<double>(
                                             group.multipliers.size()));
        for (unsigned int d = 0; d < b.size(); ++d)
          for (unsigned int a = 0; a < group.multipliers.size(); ++a)
            b[d][a] = entry(g.rows[d], group.multipliers[a]);
        if (group.multipliers.empty() ||
            group.multipliers.size() > group.displacements.size() ||
            !orthonormal_basis(b, g.q, g.r))
          continue;
        condensed_multipliers.insert(condensed_multipliers.end(),
                                     group.multipliers.begin(),
                                     group.multipliers.end());
        condensed.push_back(std::move(g));
      }
    std::vector<Index> all_condensed;
    for (const auto &part :
         Utilities::MPI::all_gather(comm, condensed_multipliers))
      all_condensed.insert(all_condensed.end(), part.begin(), part.end());
    std::sort(all_condensed.begin(), all_condensed.end());
    n_condensed_multipliers = all_condensed.size();
    const auto is_condensed = [&](const Index i) {
      return std::binary_search(all_condensed.begin(), all_condensed.end(), i);
    };

    // 2. dlambda = -e - F du per condensed multiplier: E = R^-1 Q_1^T
    eliminations.clear();
    for (const auto &g : condensed)
      {
        const unsigned int dim = g.rows.size(), k = g.group->multipliers.size();
        // E, by back substitution of R E = Q_1^T
        std::vector<std::vector<double>> e(k, std::vector<double>(dim, 0.));
        for (int a = k - 1; a >= 0; --a)
          for (unsigned int d = 0; d < dim; ++d)
            {
              double value = g.q[d][a];
              for (unsigned int c = a + 1; c < k; ++c)
                value -= g.r[a][c] * e[c][d];
              e[a][d] = value / g.r[a][a];
            }
        for (unsigned int a = 0; a < k; ++a)
          {
            Elimination elimination;
            elimination.multiplier = g.group->multipliers[a];
            SparseRow f;
            for (unsigned int d = 0; d < dim; ++d)
              {
                elimination.e += e[a][d] * rhs(g.group->displacements[d]);
                for (const auto &x : g.rows[d])
                  if (!is_condensed(x.first))
                    f.emplace_back(x.first, e[a][d] * x.second);
              }
            compress_row(f);
            for (const auto &x : f)
              {
                elimination.columns.push_back(x.first);
                elimination.values.push_back(x.second);
              }
            eliminations.push_back(std::move(elimination));
          }
      }

    // every process needs the eliminations of the multipliers in its rows
    std::unordered_map<Index, Elimination> all_eliminations;
    {
      std::vector<Index>  indices;
      std::vector<double> values;
      for (const auto &x : eliminations)
        {
          indices.push_back(x.multiplier);
          indices.push_back(x.columns.size());
          indices.insert(indices.end(), x.columns.begin(), x.columns.end());
          values.push_back(x.e);
          values.insert(values.end(), x.values.begin(), x.values.end());
        }
      const auto all_indices = Utilities::MPI::all_gather(comm, indices);
      const auto all_values  = Utilities::MPI::all_gather(comm, values);
      for (unsigned int p = 0; p < all_indices.size(); ++p)
        {
          auto i = all_indices[p].begin();
          auto v = all_values[p].begin();
          while (i != all_indices[p].end())
            {
              Elimination &x = all_eliminations[*i];
              x.multiplier   = *i;
              const Index n  = *(i + 1);
              x.columns.assign(i + 2, i + 2 + n);
              x.e = *v;
              x.values.assign(v + 1, v + 1 + n);
              i += 2 + n;
              v += 1 + n;
            }
        }
    }

    std::vector<bool> condensed_column(matrix.NumMyCols(), false);
    for (int c = 0; c < matrix.NumMyCols(); ++c)
      condensed_column[c] = is_condensed(static_cast<Index>(matrix.GCID(c)));
    // a row of the matrix with the condensed multipliers substituted: in
    // 3-D a row collects some thirty eliminations of two hundred columns
    // each, merged in linear time in a dense accumulator over "slots" (the
    // columns that occur) instead of sorted
    std::unordered_map<Index, unsigned int> slot_of;
    std::vector<Index>                      slot_column;
    const auto                              slot = [&](const Index column) {
      const auto [it, inserted] =
        slot_of.try_emplace(column, slot_column.size());
      if (inserted)
        slot_column.push_back(column);
      return it->second;
    };
    std::vector<unsigned int> local_slot(matrix.NumMyCols());
    for (int c = 0; c < matrix.NumMyCols(); ++c)
      local_slot[c] = slot(static_cast<Index>(matrix.GCID(c)));
    std::unordered_map<Index, std::vector<unsigned int>> elimination_slots;
    for (const auto &[m, x] : all_eliminations)
      {
        auto &slots = elimination_slots[m];
        for (const Index c : x.columns)
          slots.push_back(slot(c));
      }
    std::vector<double>       sum(slot_column.size(), 0.);
    std::vector<bool>         touched(slot_column.size(), false);
    std::vector<unsigned int> touched_slots;
    const auto add_to_sum = [&](const unsigned int s, const double value) {
      if (!touched[s])
        {
          touched[s] = true;
          touched_slots.push_back(s);
        }
      sum[s] += value;
    };
    const auto substitute = [&](const Index row, double &rhs_value) {
      int     n       = 0;
      double *values  = nullptr;
      int    *indices = nullptr;
      Assert(matrix.LRID(static_cast<int>(row)) >= 0, ExcInternalError());
      matrix.ExtractMyRowView(matrix.LRID(static_cast<int>(row)),
                              n,
                              values,
                              indices);
      for (int k = 0; k < n; ++k)
        if (!condensed_column[indices[k]])
          add_to_sum(local_slot[indices[k]], values[k]);
        else
          {
            const Index        m           = matrix.GCID(indices[k]);
            const Elimination &elimination = all_eliminations.at(m);
            const auto        &slots       = elimination_slots.at(m);
            rhs_value -= values[k] * elimination.e;
            for (unsigned int c = 0; c < slots.size(); ++c)
              add_to_sum(slots[c], -values[k] * elimination.values[c]);
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
    };

    // 3. the condensed rows
    std::unordered_map<Index, std::pair<SparseRow, double>> replaced;
    for (const auto &g : condensed)
      {
        const unsigned int dim = g.rows.size(), k = g.group->multipliers.size();
        std::vector<SparseRow> equations(dim);
        std::vector<double>    values(dim, 0.);
        for (unsigned int a = 0; a < k; ++a)
          {
            const Index m = g.group->multipliers[a];
            values[a]     = rhs(m);
            equations[a]  = substitute(m, values[a]);
          }
        for (unsigned int b = k; b < dim; ++b)
          {
            for (unsigned int d = 0; d < dim; ++d)
              {
                values[b] += g.q[d][b] * rhs(g.group->displacements[d]);
                for (const auto &x : g.rows[d])
                  if (!is_condensed(x.first))
                    equations[b].emplace_back(x.first, g.q[d][b] * x.second);
              }
            compress_row(equations[b]);
          }
        // the equations on the displacement rows with the largest
        // diagonals
        std::vector<unsigned int> order(dim), best;
        std::iota(order.begin(), order.end(), 0);
        double best_product = -1;
        do
          {
            double product = 1;
            for (unsigned int d = 0; d < dim; ++d)
              product *=
                std::abs(entry(equations[order[d]], g.group->displacements[d]));
            if (product > best_product)
              {
                best_product = product;
                best         = order;
              }
        } while (std::next_permutation(order.begin(), order.end()));
        // each equation scaled to the diagonal of the stiffness row it
        // replaces: the same solution, and the smoothers of an algebraic
        // multigrid see the scale of the elasticity rows
        for (unsigned int d = 0; d < dim; ++d)
          {
            const Index  row      = g.group->displacements[d];
            SparseRow    equation = equations[best[d]];
            const double diagonal = entry(equation, row);
            const double target   = std::abs(entry(g.rows[d], row));
            const double factor =
              (diagonal != 0 && target > 0) ? target / diagonal : 1.;
            for (auto &x : equation)
              x.second *= factor;
            replaced[row] = {std::move(equation), factor * values[best[d]]};
          }
      }

    // the rows that change: the groups' displacement rows (above), the
    // condensed multipliers' rows, and every row with a condensed column
    std::vector<Index> affected;
    for (int r = 0; r < matrix.NumMyRows(); ++r)
      {
        const Index row = matrix.GRID(r);
        if (replaced.count(row) > 0)
          continue;
        int     n       = 0;
        double *values  = nullptr;
        int    *indices = nullptr;
        matrix.ExtractMyRowView(r, n, values, indices);
        bool changes = is_condensed(row);
        for (int k = 0; k < n && !changes; ++k)
          changes = condensed_column[indices[k]];
        if (changes)
          affected.push_back(row);
      }
    for (const Index row : affected)
      {
        double    value = rhs(row);
        SparseRow new_row;
        if (is_condensed(row))
          {
            new_row = {{row, 1.}};
            value   = 0;
          }
        else
          new_row = substitute(row, value);
        replaced[row] = {std::move(new_row), value};
      }

    // with the fill-in in the Jacobian's pattern (add_fill_in), a copy of
    // the Jacobian with these rows rewritten; else a new matrix
    bool fits = copy_jacobian;
    for (const auto &r : replaced)
      {
        const SparseRow    existing = read_row(matrix, r.first);
        std::vector<Index> columns;
        for (const auto &x : existing)
          columns.push_back(x.first);
        std::sort(columns.begin(), columns.end());
        for (const auto &x : r.second.first)
          fits =
            fits && std::binary_search(columns.begin(), columns.end(), x.first);
        if (!fits)
          break;
      }
    fits = Utilities::MPI::min(fits ? 1 : 0, comm) == 1;

    TrilinosWrappers::MPI::Vector &b = *condensed_rhs;
    b.reinit(rhs);
    b = rhs;
    for (const auto &r : replaced)
      b(r.first) = r.second.second;
    b.compress(VectorOperation::insert);

    std::vector<TrilinosWrappers::SparseMatrix::size_type> columns;
    std::vector<TrilinosScalar>                            values;
    const auto set_row = [&](const Index row, const SparseRow &entries) {
      columns.clear();
      values.clear();
      for (const auto &x : entries)
        {
          columns.push_back(x.first);
          values.push_back(x.second);
        }
      condensed_matrix->set(row, columns, values, false);
    };
    if (fits)
      {
        condensed_matrix->copy_from(jacobian);
        for (const auto &r : replaced)
          {
            condensed_matrix->clear_row(r.first);
            set_row(r.first, r.second.first);
          }
        condensed_matrix->compress(VectorOperation::insert);
        return;
      }

    DynamicSparsityPattern dsp(rhs.size(), rhs.size(), owned);
    std::vector<SparseRow> rows;
    std::vector<Index>     row_indices;
    for (const Index i : owned)
      {
        const auto it = replaced.find(i);
        SparseRow  row =
          it != replaced.end() ? it->second.first : read_row(matrix, i);
        for (const auto &x : row)
          dsp.add(i, x.first);
        dsp.add(i, i);
        rows.push_back(std::move(row));
        row_indices.push_back(i);
      }
    condensed_matrix->reinit(owned, owned, dsp, comm);
    for (unsigned int r = 0; r < rows.size(); ++r)
      set_row(row_indices[r], rows[r]);
    condensed_matrix->compress(VectorOperation::insert);
  }

  std::vector<MultiplierCondensation::FillIn>
  MultiplierCondensation::fill_in(const DynamicSparsityPattern       &pattern,
                                  const std::vector<MultiplierGroup> &groups)
  {
    const auto columns_of = [&](const Index row) {
      std::vector<Index> columns;
      for (auto it = pattern.begin(row); it != pattern.end(row); ++it)
        columns.push_back(it->column());
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

  void
  MultiplierCondensation::recover(TrilinosWrappers::MPI::Vector &solution) const
  {
    const IndexSet &owned = solution.locally_owned_elements();
    IndexSet        needed(solution.size());
    for (const auto &x : eliminations)
      needed.add_indices(x.columns.begin(), x.columns.end());
    needed.add_indices(owned);
    needed.compress();
    TrilinosWrappers::MPI::Vector ghosted(owned,
                                          needed,
                                          solution.get_mpi_communicator());
    ghosted = solution;
    for (const auto &x : eliminations)
      {
        double value = -x.e;
        for (unsigned int c = 0; c < x.columns.size(); ++c)
          value -= x.values[c] * ghosted(x.columns[c]);
        solution(x.multiplier) = value;
      }
    solution.compress(VectorOperation::insert);
  }
} // namespace ContactDynamics
