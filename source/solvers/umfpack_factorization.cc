#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <contact_dynamics/solvers/umfpack_factorization.h>

#include <Epetra_CrsMatrix.h>
#include <algorithm>
#include <numeric>
#include <string>
#include <umfpack.h>

namespace ContactDynamics
{
  UmfpackFactorization::~UmfpackFactorization()
  {
    free_numeric();
    free_symbolic();
  }

  void
  UmfpackFactorization::free_numeric()
  {
    if (numeric != nullptr)
      umfpack_dl_free_numeric(&numeric);
    numeric = nullptr;
  }

  void
  UmfpackFactorization::free_symbolic()
  {
    if (symbolic != nullptr)
      umfpack_dl_free_symbolic(&symbolic);
    symbolic = nullptr;
  }

  void
  UmfpackFactorization::factorize(const TrilinosWrappers::SparseMatrix &matrix)
  {
    AssertThrow(Utilities::MPI::n_mpi_processes(
                  matrix.get_mpi_communicator()) == 1,
                ExcMessage("Linear solver = UMFPACK runs on one process only; "
                           "with mpirun use KLU, MUMPS or AMG (or auto)."));
    const Epetra_CrsMatrix &A = matrix.trilinos_matrix();
    const int               n = A.NumMyRows();
    AssertThrow(n == A.NumGlobalRows(), ExcInternalError());

    // the rows in global numbering with sorted columns
    std::vector<std::int64_t> new_start(n + 1, 0), new_columns;
    std::vector<double>       new_values;
    new_columns.reserve(A.NumMyNonzeros());
    new_values.reserve(A.NumMyNonzeros());
    std::vector<std::pair<std::int64_t, double>> row;
    for (int r = 0; r < n; ++r)
      {
        AssertThrow(A.RowMap().GID(r) == r, ExcInternalError());
        int     length;
        double *row_values;
        int    *row_columns;
        A.ExtractMyRowView(r, length, row_values, row_columns);
        row.resize(length);
        for (int k = 0; k < length; ++k)
          row[k] = {A.ColMap().GID(row_columns[k]), row_values[k]};
        std::sort(row.begin(), row.end(), [](const auto &a, const auto &b) {
          return a.first < b.first;
        });
        for (const auto &entry : row)
          {
            new_columns.push_back(entry.first);
            new_values.push_back(entry.second);
          }
        new_start[r + 1] = new_columns.size();
      }

    free_numeric();
    if (symbolic == nullptr || new_start != row_start || new_columns != columns)
      {
        free_symbolic();
        row_start.swap(new_start);
        columns.swap(new_columns);
        values.swap(new_values);
        const auto status = umfpack_dl_symbolic(n,
                                                n,
                                                row_start.data(),
                                                columns.data(),
                                                values.data(),
                                                &symbolic,
                                                nullptr,
                                                nullptr);
        AssertThrow(status == UMFPACK_OK,
                    ExcMessage("UMFPACK's symbolic analysis failed (status " +
                               std::to_string(status) + ")."));
        ++n_symbolic;
      }
    else
      values.swap(new_values);

    const auto status = umfpack_dl_numeric(row_start.data(),
                                           columns.data(),
                                           values.data(),
                                           symbolic,
                                           &numeric,
                                           nullptr,
                                           nullptr);
    if (status != UMFPACK_OK)
      {
        free_numeric();
        AssertThrow(false,
                    ExcMessage(std::string("UMFPACK's factorization failed: ") +
                               (status == UMFPACK_WARNING_singular_matrix ?
                                  "the matrix is singular" :
                                  "status " + std::to_string(status)) +
                               "."));
      }
  }

  void
  UmfpackFactorization::solve(const TrilinosWrappers::MPI::Vector &rhs,
                              TrilinosWrappers::MPI::Vector &solution) const
  {
    Assert(numeric != nullptr, ExcInternalError());
    // the stored rows are the columns of the transpose: solve A^T^T x = b
    const auto status = umfpack_dl_solve(UMFPACK_Aat,
                                         row_start.data(),
                                         columns.data(),
                                         values.data(),
                                         solution.begin(),
                                         rhs.begin(),
                                         numeric,
                                         nullptr,
                                         nullptr);
    AssertThrow(status == UMFPACK_OK,
                ExcMessage("UMFPACK's solve failed (status " +
                           std::to_string(status) + ")."));
  }
} // namespace ContactDynamics
