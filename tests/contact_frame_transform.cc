// The transform of the AMG contact elimination (ContactFrameMultigrid)
// against dense products written out here: for a 3-D matrix of three
// nodes (9 dofs) with a frame on the first node (a rotation T and an
// equation map L, both arbitrary), matrix() must equal L A T, rhs() L b
// and back_transform(y) T y, to round-off:
// 1. a Q1-like pattern (every row holds all or none of a node's columns):
//    the transform is formed in that pattern; the explicit zeros of the
//    pattern (contact couplings out of contact) are not stored;
// 2. a pattern where a row holds only one of the node's columns: the same
//    numbers (by the sparse products);
// 3. the same matrix with new values, one of them in place of a stored
//    zero: the numbers follow (the kept pattern is not reused wrongly);
// 4. new values inside the kept pattern, one nonzero entry now zero.
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <contact_dynamics/solvers/contact_frame_multigrid.h>

#include "tests.h"

#include <cmath>

using namespace dealii;
using ContactDynamics::ContactFrameMultigrid;
using ContactDynamics::NodeFrame;

namespace
{
  constexpr unsigned int n = 9;

  // a's entries where `in_pattern`, stored (zeros too)
  TrilinosWrappers::SparseMatrix
  trilinos_matrix(const FullMatrix<double>             &a,
                  const std::vector<std::vector<bool>> &in_pattern)
  {
    DynamicSparsityPattern dsp(n, n);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        if (in_pattern[i][j])
          dsp.add(i, j);
    TrilinosWrappers::SparseMatrix m;
    m.reinit(complete_index_set(n), complete_index_set(n), dsp, MPI_COMM_WORLD);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        if (in_pattern[i][j])
          m.set(i, j, a(i, j));
    m.compress(VectorOperation::insert);
    return m;
  }

  NodeFrame
  frame()
  {
    NodeFrame f;
    f.dofs = {0, 1, 2};
    // a rotation about (1, 2, 2)/3 by 0.7 (Rodrigues), row c = axis c
    const double k[3] = {1. / 3, 2. / 3, 2. / 3}, c = std::cos(0.7),
                 s = std::sin(0.7);
    f.axes.assign(3, std::vector<double>(3));
    const double cross[3][3] = {{0, -k[2], k[1]},
                                {k[2], 0, -k[0]},
                                {-k[1], k[0], 0}};
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        f.axes[i][j] =
          (i == j ? c : 0) + s * cross[i][j] + (1 - c) * k[i] * k[j];
    f.to_frame    = {{2.0, 0.5, -1.0}, {0.25, 3.0, 0.0}, {-0.5, 1.5, 1.25}};
    f.constrained = {true, false, false};
    return f;
  }

  // the largest |entry of m - dense| over all (i, j), and whether m stores
  // no zero off the diagonal
  std::pair<double, bool>
  compare(const TrilinosWrappers::SparseMatrix &m,
          const FullMatrix<double>             &dense)
  {
    double largest = 0;
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        largest = std::max(largest, std::abs(m.el(i, j) - dense(i, j)));
    bool no_zeros = true;
    for (auto it = m.begin(); it != m.end(); ++it)
      if (it->row() != it->column() && it->value() == 0)
        no_zeros = false;
    return {largest, no_zeros};
  }

  void
  check_case(const std::string                    &name,
             ContactFrameMultigrid                &multigrid,
             const FullMatrix<double>             &a,
             const std::vector<std::vector<bool>> &pattern,
             const bool                            expect_no_zeros)
  {
    const NodeFrame    f = frame();
    FullMatrix<double> L(n, n), T(n, n);
    for (unsigned int i = 0; i < n; ++i)
      L(i, i) = T(i, i) = 1;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        {
          L(i, j) = f.to_frame[i][j];
          T(i, j) = f.axes[j][i];
        }
    FullMatrix<double> LA(n, n), LAT(n, n);
    L.mmult(LA, a);
    LA.mmult(LAT, T);

    TrilinosWrappers::MPI::Vector b(complete_index_set(n), MPI_COMM_WORLD),
      y(b), x(b);
    Vector<double> bd(n), yd(n), Lb(n), Ty(n);
    for (unsigned int i = 0; i < n; ++i)
      {
        b[i] = bd[i] = 1.0 + 0.3 * i - 0.05 * i * i;
        y[i] = yd[i] = std::sin(1.0 + i);
      }
    L.vmult(Lb, bd);
    T.vmult(Ty, yd);

    multigrid.transform(trilinos_matrix(a, pattern), b, {f});
    const auto [error, no_zeros] = compare(multigrid.matrix(), LAT);
    check_close(name + ": |matrix() - L A T|_max", error, 0, 1e-12);
    if (expect_no_zeros)
      check_true(name + ": no stored zeros off the diagonal", no_zeros);
    double rhs_error = 0, back_error = 0;
    multigrid.back_transform(y, x);
    for (unsigned int i = 0; i < n; ++i)
      {
        rhs_error  = std::max(rhs_error, std::abs(multigrid.rhs()[i] - Lb[i]));
        back_error = std::max(back_error, std::abs(x[i] - Ty[i]));
      }
    check_close(name + ": |rhs() - L b|_max", rhs_error, 0, 1e-13);
    check_close(name + ": |back_transform(y) - T y|_max", back_error, 0, 1e-13);
  }
} // namespace

int
main()
{
  initlog();
  // every node couples to every node, except nodes 1 and 2, whose
  // coupling is in the pattern but zero (a contact coupling out of contact)
  FullMatrix<double>             a(n, n);
  std::vector<std::vector<bool>> pattern(n, std::vector<bool>(n, true));
  for (unsigned int i = 0; i < n; ++i)
    for (unsigned int j = 0; j < n; ++j)
      {
        const bool zero_block =
          (i / 3 == 1 && j / 3 == 2) || (i / 3 == 2 && j / 3 == 1);
        a(i, j) =
          zero_block ? 0 : (i == j ? 10.0 + i : std::cos(1.0 + 3 * i + 7 * j));
      }
  ContactFrameMultigrid first;
  check_case("1. node blocks in the pattern", first, a, pattern, true);

  // 2. row 6 holds column 0 of the framed node but not columns 1 and 2
  std::vector<std::vector<bool>> partial = pattern;
  partial[6][1] = partial[6][2] = false;
  FullMatrix<double> b          = a;
  b(6, 1) = b(6, 2) = 0;
  ContactFrameMultigrid second;
  check_case("2. a row with part of a node's columns",
             second,
             b,
             partial,
             false);

  // 3. the first object again, a stored zero now nonzero
  FullMatrix<double> c = a;
  c(4, 7)              = 0.625;
  for (unsigned int i = 0; i < n; ++i)
    c(i, i) += 1;
  check_case("3. new values, a stored zero switched on",
             first,
             c,
             pattern,
             true);

  // 4. the first object again: values within its pattern, one set to zero
  FullMatrix<double> d = c;
  d(4, 7)              = 0;
  d(5, 0) *= -2.5;
  d(0, 8) = 0;
  for (unsigned int i = 0; i < n; ++i)
    d(i, i) *= 0.5;
  check_case("4. new values in the kept pattern, one set to zero",
             first,
             d,
             pattern,
             false);
}
