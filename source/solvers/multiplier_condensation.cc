#include <deal.II/base/exceptions.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <contact_dynamics/solvers/multiplier_condensation.h>
#include <contact_dynamics/solvers/multiplier_substitution.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <unordered_map>

namespace ContactDynamics
{
  using Index = types::global_dof_index;


  namespace
  {
    using internal::SparseRow;
    using internal::Substitution;

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

    using Elimination = internal::MultiplierElimination;

    /** Whether the sorted list `sorted` holds `i`. */
    bool
    contains(const std::vector<Index> &sorted, const Index i)
    {
      return std::binary_search(sorted.begin(), sorted.end(), i);
    }

    /** A group that can be condensed: its displacement rows and B = Q_1 R. */
    struct CondensableGroup
    {
      const MultiplierGroup           *group = nullptr;
      std::vector<SparseRow>           rows; // of the displacements
      std::vector<std::vector<double>> q, r;
      // the rows' nonzero entries outside the condensed columns, dense on
      // the union of their columns: row d at columns[i] is values[i dim + d]
      std::vector<Index>  columns;
      std::vector<double> values;
    };

    /**
     * Sets g.columns and g.values, in linear time: `condensed` flags the
     * local columns of condensed multipliers, `position` is -1 for every
     * local column and is left so.
     */
    void
    merge_rows(CondensableGroup        &g,
               const Epetra_CrsMatrix  &matrix,
               const std::vector<bool> &condensed,
               std::vector<int>        &position)
    {
      const unsigned int dim = g.rows.size();
      std::vector<int>   local_columns;
      g.values.clear();
      for (unsigned int d = 0; d < dim; ++d)
        {
          const int row =
            matrix.LRID(static_cast<int>(g.group->displacements[d]));
          int     n       = 0;
          double *values  = nullptr;
          int    *indices = nullptr;
          matrix.ExtractMyRowView(row, n, values, indices);
          for (int k = 0; k < n; ++k)
            if (values[k] != 0 && !condensed[indices[k]])
              {
                if (position[indices[k]] < 0)
                  {
                    position[indices[k]] = local_columns.size();
                    local_columns.push_back(indices[k]);
                    g.values.resize(g.values.size() + dim, 0.);
                  }
                g.values[position[indices[k]] * dim + d] = values[k];
              }
        }
      g.columns.clear();
      for (const int c : local_columns)
        {
          g.columns.push_back(static_cast<Index>(matrix.GCID(c)));
          position[c] = -1;
        }
    }

    /** sum_d weights[d] rows[d] of a merged group, zeros dropped. */
    SparseRow
    combine(const CondensableGroup &g, const std::vector<double> &weights)
    {
      SparseRow result;
      for (unsigned int i = 0; i < g.columns.size(); ++i)
        {
          double value = 0;
          for (unsigned int d = 0; d < weights.size(); ++d)
            value += weights[d] * g.values[i * weights.size() + d];
          if (value != 0)
            result.emplace_back(g.columns[i], value);
        }
      return result;
    }

    /** Rows replaced by the condensation, with their right-hand sides. */
    using ReplacedRows =
      std::unordered_map<Index, std::pair<SparseRow, double>>;

    /** Step 1: the groups whose block B has full column rank, with bases. */
    std::vector<CondensableGroup>
    condensable_groups(const Epetra_CrsMatrix             &matrix,
                       const std::vector<MultiplierGroup> &groups)
    {
      std::vector<CondensableGroup> condensed;
      for (const auto &group : groups)
        {
          CondensableGroup g;
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
          condensed.push_back(std::move(g));
        }
      return condensed;
    }

    /** The multipliers of the condensed groups of all processes, sorted. */
    std::vector<Index>
    all_condensed_multipliers(const std::vector<CondensableGroup> &condensed,
                              const MPI_Comm                       comm)
    {
      std::vector<Index> condensed_multipliers;
      for (const auto &g : condensed)
        condensed_multipliers.insert(condensed_multipliers.end(),
                                     g.group->multipliers.begin(),
                                     g.group->multipliers.end());
      std::vector<Index> all_condensed;
      for (const auto &part :
           Utilities::MPI::all_gather(comm, condensed_multipliers))
        all_condensed.insert(all_condensed.end(), part.begin(), part.end());
      std::sort(all_condensed.begin(), all_condensed.end());
      return all_condensed;
    }

    /**
     * Step 2: dlambda = -e - F du for each multiplier of the group, with
     * E = R^-1 Q_1^T by back substitution of R E = Q_1^T.
     */
    void
    add_eliminations(const CondensableGroup              &g,
                     const TrilinosWrappers::MPI::Vector &rhs,
                     std::vector<Elimination>            &eliminations)
    {
      const unsigned int dim = g.rows.size(), k = g.group->multipliers.size();
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
          for (unsigned int d = 0; d < dim; ++d)
            elimination.e += e[a][d] * rhs(g.group->displacements[d]);
          for (const auto &x : combine(g, e[a]))
            {
              elimination.columns.push_back(x.first);
              elimination.values.push_back(x.second);
            }
          eliminations.push_back(std::move(elimination));
        }
    }

    /**
     * The eliminations of all processes: every process needs those of the
     * multipliers in its rows.
     */
    std::unordered_map<Index, Elimination>
    gather_eliminations(const std::vector<Elimination> &eliminations,
                        const MPI_Comm                  comm)
    {
      std::unordered_map<Index, Elimination> all_eliminations;
      std::vector<Index>                     indices;
      std::vector<double>                    values;
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
      return all_eliminations;
    }


    /**
     * The k condensed multiplier rows and the dim - k rotated displacement
     * rows Q_2^T (J_s du + r_s) = 0 of a group, with their right-hand sides.
     */
    void
    group_equations(const CondensableGroup              &g,
                    const TrilinosWrappers::MPI::Vector &rhs,
                    Substitution                        &substitute,
                    std::vector<SparseRow>              &equations,
                    std::vector<double>                 &values)
    {
      const unsigned int dim = g.rows.size(), k = g.group->multipliers.size();
      equations.assign(dim, SparseRow());
      values.assign(dim, 0.);
      for (unsigned int a = 0; a < k; ++a)
        {
          const Index m = g.group->multipliers[a];
          values[a]     = rhs(m);
          equations[a]  = substitute(m, values[a]);
        }
      for (unsigned int b = k; b < dim; ++b)
        {
          std::vector<double> weights(dim);
          for (unsigned int d = 0; d < dim; ++d)
            {
              values[b] += g.q[d][b] * rhs(g.group->displacements[d]);
              weights[d] = g.q[d][b];
            }
          equations[b] = combine(g, weights);
        }
    }

    /**
     * Which equation goes on which displacement row: the permutation with
     * the largest product of the diagonals.
     */
    std::vector<unsigned int>
    placement(const std::vector<SparseRow> &equations,
              const std::vector<Index>     &displacements)
    {
      const unsigned int        dim = equations.size();
      std::vector<unsigned int> order(dim), best;
      std::iota(order.begin(), order.end(), 0);
      double best_product = -1;
      do
        {
          double product = 1;
          for (unsigned int d = 0; d < dim; ++d)
            product *= std::abs(entry(equations[order[d]], displacements[d]));
          if (product > best_product)
            {
              best_product = product;
              best         = order;
            }
      } while (std::next_permutation(order.begin(), order.end()));
      return best;
    }

    /**
     * Whether the row of multiplier m is a constraint on the displacements
     * (active normal, stick) rather than an equation for the multipliers
     * (inactive, slip): it has no entry on the group's multipliers.
     */
    bool
    is_constraint(const Epetra_CrsMatrix &matrix,
                  const Index             m,
                  const MultiplierGroup  &group)
    {
      for (const auto &x : read_row(matrix, m))
        if (x.second != 0 && std::find(group.multipliers.begin(),
                                       group.multipliers.end(),
                                       x.first) != group.multipliers.end())
          return false;
      return true;
    }

    /**
     * Step 3: the rows of a group's displacements replaced by its
     * equations, each on the displacement row with the largest diagonals.
     */
    void
    replace_group_rows(const CondensableGroup              &g,
                       const Epetra_CrsMatrix              &matrix,
                       const TrilinosWrappers::MPI::Vector &rhs,
                       Substitution                        &substitute,
                       ReplacedRows                        &replaced,
                       std::vector<NodeFrame>              &frames)
    {
      std::vector<SparseRow> equations;
      std::vector<double>    values;
      group_equations(g, rhs, substitute, equations, values);
      const std::vector<unsigned int> best =
        placement(equations, g.group->displacements);
      // each equation scaled to the diagonal of the stiffness row it
      // replaces: the same solution, and the smoothers of an algebraic
      // multigrid see the scale of the elasticity rows
      std::vector<double> factors(g.rows.size());
      for (unsigned int d = 0; d < g.rows.size(); ++d)
        {
          const Index  row      = g.group->displacements[d];
          SparseRow    equation = equations[best[d]];
          const double diagonal = entry(equation, row);
          const double target   = std::abs(entry(g.rows[d], row));
          factors[d] = (diagonal != 0 && target > 0) ? target / diagonal : 1.;
          for (auto &x : equation)
            x.second *= factors[d];
          replaced[row] = {std::move(equation), factors[d] * values[best[d]]};
        }
      // the node's frame if it carries a constraint (a rotated free node
      // makes ML's point smoother weaker, measured on the 3-D sphere)
      const auto        &dofs = g.group->displacements;
      const unsigned int dim = dofs.size(), k = g.group->multipliers.size();
      std::vector<bool>  constrained(dim, false);
      std::vector<std::vector<double>> stiffness(dim), coefficients(dim);
      for (unsigned int b = 0; b < dim; ++b)
        {
          for (unsigned int e = 0; e < dim; ++e)
            {
              stiffness[b].push_back(entry(g.rows[b], dofs[e]));
              coefficients[b].push_back(entry(equations[b], dofs[e]));
            }
          constrained[b] =
            b < k && is_constraint(matrix, g.group->multipliers[b], *g.group);
        }
      if (std::find(constrained.begin(), constrained.end(), true) !=
          constrained.end())
        frames.push_back(make_node_frame(dofs,
                                         g.q,
                                         stiffness,
                                         coefficients,
                                         best,
                                         factors,
                                         constrained));
    }

    /**
     * Step 4: the other rows that change: the condensed multipliers' rows
     * (identity rows) and every row with a condensed column.
     */
    void
    replace_other_rows(const Epetra_CrsMatrix              &matrix,
                       const TrilinosWrappers::MPI::Vector &rhs,
                       const std::vector<Index>            &all_condensed,
                       Substitution                        &substitute,
                       ReplacedRows                        &replaced)
    {
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
          bool changes = contains(all_condensed, row);
          for (int k = 0; k < n && !changes; ++k)
            changes = substitute.is_condensed_column(indices[k]);
          if (changes)
            affected.push_back(row);
        }
      for (const Index row : affected)
        {
          double    value = rhs(row);
          SparseRow new_row;
          if (contains(all_condensed, row))
            {
              new_row = {{row, 1.}};
              value   = 0;
            }
          else
            new_row = substitute(row, value);
          replaced[row] = {std::move(new_row), value};
        }
    }

    /**
     * Whether every process may copy the Jacobian and rewrite the replaced
     * rows: with `copy_jacobian` and the fill-in in its pattern
     * (add_fill_in). Collective.
     */
    bool
    fits_pattern(const Epetra_CrsMatrix &matrix,
                 const ReplacedRows     &replaced,
                 const bool              copy_jacobian,
                 const MPI_Comm          comm)
    {
      bool             fits = copy_jacobian;
      std::vector<int> row_of_column(matrix.NumMyCols(), -1);
      for (auto r = replaced.begin(); fits && r != replaced.end(); ++r)
        {
          const int row = matrix.LRID(static_cast<int>(r->first));
          Assert(row >= 0, ExcInternalError());
          int     n       = 0;
          double *values  = nullptr;
          int    *indices = nullptr;
          matrix.ExtractMyRowView(row, n, values, indices);
          for (int k = 0; k < n; ++k)
            row_of_column[indices[k]] = row;
          for (const auto &x : r->second.first)
            {
              const int column = matrix.LCID(static_cast<int>(x.first));
              fits = fits && column >= 0 && row_of_column[column] == row;
            }
        }
      return Utilities::MPI::min(fits ? 1 : 0, comm) == 1;
    }

    /** Sets the entries of a row (within the matrix's pattern). */
    void
    set_row(TrilinosWrappers::SparseMatrix &matrix,
            const Index                     row,
            const SparseRow                &entries)
    {
      std::vector<TrilinosWrappers::SparseMatrix::size_type> columns;
      std::vector<TrilinosScalar>                            values;
      for (const auto &x : entries)
        {
          columns.push_back(x.first);
          values.push_back(x.second);
        }
      matrix.set(row, columns, values, false);
    }

    /**
     * The condensed matrix as a copy of the Jacobian, rows rewritten in
     * place (their columns are in the pattern: fits_pattern()).
     */
    void
    copy_with_rows(TrilinosWrappers::SparseMatrix       &condensed,
                   const TrilinosWrappers::SparseMatrix &jacobian,
                   const ReplacedRows                   &replaced)
    {
      condensed.copy_from(jacobian);
      Epetra_CrsMatrix &c =
        const_cast<Epetra_CrsMatrix &>(condensed.trilinos_matrix());
      std::vector<int> position(c.NumMyCols(), -1);
      for (const auto &r : replaced)
        {
          int     n       = 0;
          double *values  = nullptr;
          int    *indices = nullptr;
          c.ExtractMyRowView(c.LRID(static_cast<int>(r.first)),
                             n,
                             values,
                             indices);
          for (int k = 0; k < n; ++k)
            {
              position[indices[k]] = k;
              values[k]            = 0;
            }
          for (const auto &x : r.second.first)
            {
              const int column = c.LCID(static_cast<int>(x.first));
              Assert(column >= 0 && position[column] >= 0, ExcInternalError());
              values[position[column]] = x.second;
            }
          for (int k = 0; k < n; ++k)
            position[indices[k]] = -1;
        }
    }

    /** The condensed matrix with a pattern of its own. */
    void
    build_with_rows(TrilinosWrappers::SparseMatrix &condensed,
                    const Epetra_CrsMatrix         &matrix,
                    const ReplacedRows             &replaced,
                    const IndexSet                 &owned,
                    const MPI_Comm                  comm)
    {
      DynamicSparsityPattern dsp(owned.size(), owned.size(), owned);
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
      condensed.reinit(owned, owned, dsp, comm);
      for (unsigned int r = 0; r < rows.size(); ++r)
        set_row(condensed, row_indices[r], rows[r]);
      condensed.compress(VectorOperation::insert);
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
    std::vector<CondensableGroup> condensed =
      condensable_groups(matrix, groups);
    const std::vector<Index> all_condensed =
      all_condensed_multipliers(condensed, comm);
    n_condensed_multipliers = all_condensed.size();
    {
      std::vector<bool> condensed_column(matrix.NumMyCols(), false);
      for (const Index m : all_condensed)
        if (matrix.LCID(static_cast<int>(m)) >= 0)
          condensed_column[matrix.LCID(static_cast<int>(m))] = true;
      std::vector<int> position(matrix.NumMyCols(), -1);
      for (auto &g : condensed)
        merge_rows(g, matrix, condensed_column, position);
    }

    // 2. dlambda = -e - F du per condensed multiplier: E = R^-1 Q_1^T
    eliminations.clear();
    for (const auto &g : condensed)
      add_eliminations(g, rhs, eliminations);
    const std::unordered_map<Index, Elimination> all_eliminations =
      gather_eliminations(eliminations, comm);
    Substitution substitute(matrix, all_condensed, all_eliminations);

    // 3. the condensed rows, 4. the other rows that change
    ReplacedRows replaced;
    frames.clear();
    for (const auto &g : condensed)
      replace_group_rows(g, matrix, rhs, substitute, replaced, frames);
    replace_other_rows(matrix, rhs, all_condensed, substitute, replaced);

    const bool fits = fits_pattern(matrix, replaced, copy_jacobian, comm);

    TrilinosWrappers::MPI::Vector &b = *condensed_rhs;
    b.reinit(rhs);
    b = rhs;
    for (const auto &r : replaced)
      b(r.first) = r.second.second;
    b.compress(VectorOperation::insert);

    // with the fill-in in the Jacobian's pattern (add_fill_in), a copy of
    // the Jacobian with these rows rewritten; else a new matrix
    if (fits)
      copy_with_rows(*condensed_matrix, jacobian, replaced);
    else
      build_with_rows(*condensed_matrix, matrix, replaced, owned, comm);
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
