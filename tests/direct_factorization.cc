// The one-process direct solvers (KLU with refactorization, UMFPACK) on
// small matrices with known solutions:
// 1. a nonsymmetric system: x against the solution written down by hand
//    (a solver that solved the transpose would give another x);
// 2. KLU reuses the pivot order of its last full factorization for a
//    matrix with the same pattern and nearby values (no new pivoting), and
//    pivots anew when the old order would divide by a pivot 1e-14 times the
//    others (the count of full factorizations shows it; the solutions are
//    exact to round-off in all cases);
// 3. rows with only a diagonal entry beside a coupled block (the
//    multipliers off the contact surfaces): exact solution, and a zero
//    there is a singular matrix;
// 4. a singular matrix is reported as singular by both;
// 5. UMFPACK with METIS ordering is exact and fills less than with AMD on
//    a 3-D grid;
// 6. explicit zeros in the pattern (contact couplings out of contact) are
//    not factorized if asked (3-D): a coupling switched on costs one new
//    analysis and switched off again none, the solutions exact; without
//    the option one analysis; the 3-D grid with a wider pattern of zeros
//    fills exactly as the grid alone.
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <contact_dynamics/solvers/direct_factorization.h>

#include "tests.h"

using namespace dealii;
using ContactDynamics::DirectFactorization;

namespace
{
  // a full pattern (every method sees the same structure), or the nonzero
  // entries only
  TrilinosWrappers::SparseMatrix
  matrix(const std::vector<std::vector<double>> &rows, const bool full = true)
  {
    const unsigned int     n = rows.size();
    DynamicSparsityPattern dsp(n, n);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        if (full || rows[i][j] != 0)
          dsp.add(i, j);
    TrilinosWrappers::SparseMatrix a;
    a.reinit(complete_index_set(n), complete_index_set(n), dsp, MPI_COMM_WORLD);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        if (full || rows[i][j] != 0)
          a.set(i, j, rows[i][j]);
    a.compress(VectorOperation::insert);
    return a;
  }

  // the largest error of the solution of a x = b against `exact`
  double
  error(DirectFactorization                  &solver,
        const TrilinosWrappers::SparseMatrix &a,
        const std::vector<double>            &exact)
  {
    const unsigned int            n = exact.size();
    TrilinosWrappers::MPI::Vector x(complete_index_set(n), MPI_COMM_WORLD),
      b(x);
    for (unsigned int i = 0; i < n; ++i)
      x[i] = exact[i];
    a.vmult(b, x);
    solver.factorize(a);
    solver.solve(b, x);
    double largest = 0;
    for (unsigned int i = 0; i < n; ++i)
      largest = std::max(largest, std::abs(x[i] - exact[i]));
    return largest;
  }
} // namespace

int
main()
{
  initlog();
  for (const auto method :
       {DirectFactorization::Method::klu, DirectFactorization::Method::umfpack})
    {
      const std::string name =
        method == DirectFactorization::Method::klu ? "KLU" : "UMFPACK";
      DirectFactorization solver(method);

      // 1. nonsymmetric
      const auto a = matrix({{2, 1, 0}, {0, 3, 2}, {1, 0, 4}});
      check_close(name + ": nonsymmetric system, |x - exact|_max",
                  error(solver, a, {1, -2, 3}),
                  0,
                  1e-14);
      {
        // by hand: a x = (2, 2, 5) for x = (1, 0, 1); the transposed
        // system a^T y = (2, 2, 5) has y = (0.5, 0.5, 1)
        TrilinosWrappers::MPI::Vector b(complete_index_set(3), MPI_COMM_WORLD),
          x(b);
        b[0] = 2;
        b[1] = 2;
        b[2] = 5;
        solver.factorize(a);
        solver.solve(b, x);
        check_close(name + ": a x = (2, 2, 5) gives x = (1, 0, 1)",
                    std::abs(x[0] - 1) + std::abs(x[1]) + std::abs(x[2] - 1),
                    0,
                    1e-14);
      }

      // 2. the same pattern, nearby values, then a pivot that vanishes
      const auto b1 = matrix({{4, 1, 1}, {1, 4, 1}, {1, 1, 4}});
      const auto b2 = matrix({{4.1, 1, 1.2}, {0.9, 4, 1}, {1, 1.1, 3.9}});
      const auto b3 = matrix({{1e-14, 1, 1}, {1, 1e-14, 1}, {1, 1, 1}});
      const std::vector<double> exact{1, -2, 3};
      DirectFactorization       fresh(method);
      check_close(name + ": diagonally dominant",
                  error(fresh, b1, exact),
                  0,
                  1e-14);
      const unsigned int pivoting = fresh.n_pivoting_factorizations();
      check_close(name + ": nearby values", error(fresh, b2, exact), 0, 1e-14);
      if (method == DirectFactorization::Method::klu)
        check_true(name + ": nearby values reuse the pivot order",
                   fresh.n_pivoting_factorizations() == pivoting);
      check_close(name + ": vanishing diagonal",
                  error(fresh, b3, exact),
                  0,
                  1e-13);
      if (method == DirectFactorization::Method::klu)
        check_true(name + ": a vanishing pivot makes it pivot anew",
                   fresh.n_pivoting_factorizations() == pivoting + 1);
      check_true(name + ": one analysis for one pattern",
                 fresh.n_symbolic_analyses() == 1);

      // 3. two decoupled rows beside a coupled block
      const auto c =
        matrix({{2, 1, 0, 0}, {1, 3, 0, 0}, {0, 0, 5, 0}, {0, 0, 0, 0.5}},
               false);
      DirectFactorization decoupled(method);
      check_close(name + ": decoupled rows beside a coupled block",
                  error(decoupled, c, {1, -2, 3, -4}),
                  0,
                  1e-14);

      // 4. singular: a zero column; a zero in a decoupled row
      const auto singular = [&](const TrilinosWrappers::SparseMatrix &s) {
        try
          {
            DirectFactorization solver(method);
            solver.factorize(s);
          }
        catch (const std::exception &e)
          {
            return std::string(e.what()).find("singular") != std::string::npos;
          }
        return false;
      };
      check_true(name + ": a zero column is reported as singular",
                 singular(matrix({{1, 2, 0}, {3, 4, 0}, {5, 6, 0}})));
      auto zero_row =
        matrix({{2, 1, 0, 0}, {1, 3, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}, false);
      const bool nonzero_singular = singular(zero_row);
      zero_row.set(3, 3, 0.);
      zero_row.compress(VectorOperation::insert);
      check_true(name + ": a zero decoupled row is reported as singular",
                 !nonzero_singular && singular(zero_row));

      // 6. a tridiagonal matrix in a full pattern, then the same pattern
      //    with the corner coupling switched on and off
      std::vector<std::vector<double>> rows(8, std::vector<double>(8, 0.));
      for (unsigned int i = 0; i < 8; ++i)
        {
          rows[i][i] = 4;
          if (i > 0)
            rows[i][i - 1] = rows[i - 1][i] = -1;
        }
      const std::vector<double> exact8{1, -2, 3, -4, 5, -6, 7, -8};
      DirectFactorization       zeros(method), all(method);
      zeros.set_skip_zeros(true);
      check_close(name + ": explicit zeros, |x - exact|_max",
                  error(zeros, matrix(rows), exact8),
                  0,
                  1e-14);
      rows[0][7] = rows[7][0] = -1.5;
      check_close(name + ": a zero entry switched on, |x - exact|_max",
                  error(zeros, matrix(rows), exact8),
                  0,
                  1e-14);
      const unsigned int analyses = zeros.n_symbolic_analyses();
      rows[0][7] = rows[7][0] = 0;
      check_close(name + ": and off again, |x - exact|_max",
                  error(zeros, matrix(rows), exact8),
                  0,
                  1e-14);
      check_true(name + ": switched on it costs an analysis, off none",
                 analyses == 2 && zeros.n_symbolic_analyses() == 2);
      // by default every stored entry is factorized: one analysis, also
      // when a zero entry switches on
      check_close(name + ": all entries, zeros stored, |x - exact|_max",
                  error(all, matrix(rows), exact8),
                  0,
                  1e-14);
      rows[0][7] = rows[7][0] = -1.5;
      check_close(name + ": all entries, one switched on, |x - exact|_max",
                  error(all, matrix(rows), exact8),
                  0,
                  1e-14);
      check_true(name + ": all entries stored, one analysis",
                 all.n_symbolic_analyses() == 1);
      // switching the option forgets the analysis
      zeros.set_skip_zeros(false);
      check_close(name + ": option switched off, |x - exact|_max",
                  error(zeros, matrix(rows), exact8),
                  0,
                  1e-14);
      check_true(name + ": option switched off, a new analysis",
                 zeros.n_symbolic_analyses() == 3);
    }

  // 5. UMFPACK's orderings on a 3-D grid (7-point stencil with a
  //    nonsymmetric convection part): both exact, and nested dissection
  //    (METIS) fills less than minimum degree (AMD), the separator theorem
  //    of George (1973) for grids
  const unsigned int m = 24, n = m * m * m;
  const auto             index = [&](const int i, const int j, const int k) {
    return (i * m + j) * m + k;
  };
  std::vector<std::tuple<unsigned int, unsigned int, double>> entries;
  for (unsigned int i = 0; i < m; ++i)
    for (unsigned int j = 0; j < m; ++j)
      for (unsigned int k = 0; k < m; ++k)
        {
          const unsigned int row = index(i, j, k);
          entries.emplace_back(row, row, 6.);
          const int c[3] = {int(i), int(j), int(k)};
          for (unsigned int d = 0; d < 3; ++d)
            for (const int s : {-1, 1})
              {
                int neighbour[3] = {c[0], c[1], c[2]};
                neighbour[d] += s;
                if (neighbour[d] >= 0 && neighbour[d] < int(m))
                  entries.emplace_back(row,
                                       index(neighbour[0],
                                             neighbour[1],
                                             neighbour[2]),
                                       -1. + 0.2 * s);
              }
        }
  // the grid in its own pattern, and in one that also couples every point
  // to its neighbours' neighbours (held zero)
  std::vector<std::vector<unsigned int>> neighbours(n);
  for (const auto &[r, c, v] : entries)
    neighbours[r].push_back(c);
  const auto grid_matrix = [&](const bool wide) {
    DynamicSparsityPattern dsp(n, n);
    for (unsigned int r = 0; r < n; ++r)
      for (const auto c : neighbours[r])
        {
          dsp.add(r, c);
          if (wide)
            for (const auto c2 : neighbours[c])
              dsp.add(r, c2);
        }
    TrilinosWrappers::SparseMatrix a;
    a.reinit(complete_index_set(n), complete_index_set(n), dsp, MPI_COMM_WORLD);
    for (const auto &[r, c, v] : entries)
      a.set(r, c, v);
    a.compress(VectorOperation::insert);
    return a;
  };
  const auto grid = grid_matrix(false);
  std::vector<double> exact(n);
  for (unsigned int i = 0; i < n; ++i)
    exact[i] = std::sin(0.1 * i);
  double entries_of[2];
  for (const auto ordering : {DirectFactorization::Ordering::amd,
                              DirectFactorization::Ordering::metis})
    {
      const bool metis = ordering == DirectFactorization::Ordering::metis;
      DirectFactorization solver(DirectFactorization::Method::umfpack);
      solver.set_ordering(ordering);
      check_close(std::string("UMFPACK with ") + (metis ? "METIS" : "AMD") +
                    ": 3-D grid, |x - exact|_max",
                  error(solver, grid, exact),
                  0,
                  1e-12);
      entries_of[metis] = solver.n_entries_of_factors();
    }
  // (to the screen: the ratio depends on the METIS version)
  std::cout << "entries of L and U, METIS / AMD: "
            << entries_of[1] / entries_of[0] << std::endl;
  check_true("UMFPACK: METIS fills less than AMD on a 3-D grid",
             entries_of[1] < 0.9 * entries_of[0]);
  DirectFactorization wide(DirectFactorization::Method::umfpack);
  wide.set_ordering(DirectFactorization::Ordering::metis);
  wide.set_skip_zeros(true);
  check_close("UMFPACK with METIS: the grid in a wider pattern of zeros, "
              "|x - exact|_max",
              error(wide, grid_matrix(true), exact),
              0,
              1e-12);
  check_true("UMFPACK: the zeros add no entries to L and U",
             wide.n_entries_of_factors() == entries_of[1]);
}
