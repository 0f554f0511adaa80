// MultiplierCondensation::add_fill_in on a model of a contact surface: a
// chain of n secondary nodes (two displacements and a multiplier each)
// over n + 1 primary nodes, with the bulk coupling neighbours and each
// node's contact patch (its neighbours, its multiplier, two primary nodes)
// dense, random values.
// 1. The pattern with the fill holds the condensed matrix: condense() keeps
//    it (the fast path) and gives, entry by entry, the matrix that
//    condense() builds with its own pattern from the substituted rows (the
//    exact structure, zeros dropped).
// 2. The fill per secondary node does not depend on the surface's length
//    (the fill grows linearly with it)
//    (one substitution per multiplier: a row gets the columns of the rows
//    it is substituted with, not those of the fill of other nodes). Before
//    this was fixed, the fill spread along the surface node by node: 710k
//    entries instead of 333k for the ironing, 57 % of them zeros.
#include <deal.II/base/index_set.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <contact_dynamics/solvers/multiplier_condensation.h>

#include "tests.h"

using namespace dealii;
using ContactDynamics::MultiplierCondensation;
using ContactDynamics::MultiplierGroup;

namespace
{
  struct Chain
  {
    unsigned int                 n;
    unsigned int                 size;
    DynamicSparsityPattern       dsp;
    std::vector<MultiplierGroup> groups;

    std::vector<types::global_dof_index>
    secondary(const unsigned int j) const
    {
      return {3 * j, 3 * j + 1};
    }
    std::vector<types::global_dof_index>
    primary(const unsigned int k) const
    {
      return {3 * n + 2 * k, 3 * n + 2 * k + 1};
    }

    explicit Chain(const unsigned int n)
      : n(n)
      , size(3 * n + 2 * (n + 1))
      , dsp(size, size)
    {
      const auto couple = [&](const std::vector<types::global_dof_index> &a) {
        for (const auto i : a)
          for (const auto j : a)
            dsp.add(i, j);
      };
      const auto join = [](std::vector<types::global_dof_index>        a,
                           const std::vector<types::global_dof_index> &b) {
        a.insert(a.end(), b.begin(), b.end());
        return a;
      };
      for (unsigned int j = 0; j + 1 < n; ++j)
        couple(join(secondary(j), secondary(j + 1)));
      for (unsigned int k = 0; k < n; ++k)
        couple(join(primary(k), primary(k + 1)));
      for (unsigned int j = 0; j < n; ++j)
        {
          std::vector<types::global_dof_index> patch = secondary(j);
          if (j > 0)
            patch = join(patch, secondary(j - 1));
          if (j + 1 < n)
            patch = join(patch, secondary(j + 1));
          patch = join(patch, primary(j));
          patch = join(patch, primary(j + 1));
          patch.push_back(3 * j + 2);
          couple(patch);
          groups.push_back({secondary(j), {3 * j + 2}});
        }
      for (unsigned int i = 0; i < size; ++i)
        dsp.add(i, i);
    }
  };

  // the same value for an entry in every matrix
  double
  value(const unsigned int i, const unsigned int j)
  {
    if (i == j)
      return i % 3 == 2 ? 0.5 : 20.;
    const unsigned int h = (i * 7919u + j * 104729u) % 1000u;
    return 0.1 + h / 1000.;
  }

  TrilinosWrappers::SparseMatrix
  matrix(const DynamicSparsityPattern &pattern,
         const DynamicSparsityPattern &values)
  {
    TrilinosWrappers::SparseMatrix a;
    const IndexSet                 all = complete_index_set(pattern.n_rows());
    a.reinit(all, all, pattern, MPI_COMM_WORLD);
    for (unsigned int i = 0; i < values.n_rows(); ++i)
      for (auto it = values.begin(i); it != values.end(i); ++it)
        a.set(i, it->column(), value(i, it->column()));
    a.compress(VectorOperation::insert);
    return a;
  }

  // the entries the fill adds; checks that the filled pattern holds
  // the condensed matrix
  double
  fill(const unsigned int n)
  {
    // (a DynamicSparsityPattern is not copied)
    Chain                         chain(n), with_fill(n);
    const DynamicSparsityPattern &filled = with_fill.dsp;
    MultiplierCondensation::add_fill_in(with_fill.dsp, chain.groups);

    TrilinosWrappers::MPI::Vector rhs(complete_index_set(chain.size),
                                      MPI_COMM_WORLD);
    for (unsigned int i = 0; i < chain.size; ++i)
      rhs[i] = std::sin(1. + i);

    MultiplierCondensation exact, fast;
    exact.condense(matrix(chain.dsp, chain.dsp), rhs, chain.groups, false);
    fast.condense(matrix(filled, chain.dsp), rhs, chain.groups, true);
    const std::string name = "n = " + std::to_string(n);
    check_true(name + ": the condensed matrix keeps the filled pattern",
               fast.matrix().n_nonzero_elements() ==
                 filled.n_nonzero_elements());
    // every entry of either matrix, by rows
    double largest = 0, scale = 0;
    for (unsigned int i = 0; i < chain.size; ++i)
      {
        for (auto it = exact.matrix().begin(i); it != exact.matrix().end(i);
             ++it)
          {
            scale   = std::max(scale, std::abs(it->value()));
            largest = std::max(largest,
                               std::abs(it->value() -
                                        fast.matrix().el(i, it->column())));
          }
        for (auto it = fast.matrix().begin(i); it != fast.matrix().end(i); ++it)
          largest = std::max(largest,
                             std::abs(it->value() -
                                      exact.matrix().el(i, it->column())));
      }
    check_close(name + ": entries equal to the exactly structured matrix",
                largest / scale,
                0,
                1e-14);
    return double(filled.n_nonzero_elements()) -
           double(chain.dsp.n_nonzero_elements());
  }
} // namespace

int
main()
{
  initlog();
  // away from the ends every node adds the same fill
  const double f20 = fill(20), f40 = fill(40), f80 = fill(80);
  record_measured("fill entries per interior node", (f80 - f40) / 40, 0, 1e6);
  check_close("fill per node added, 40 to 80 nodes against 20 to 40",
              (f80 - f40) / 40 - (f40 - f20) / 20,
              0,
              1e-12);
}
