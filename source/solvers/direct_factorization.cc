#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <contact_dynamics/solvers/direct_factorization.h>

#include <Epetra_CrsMatrix.h>
#include <algorithm>
#include <klu.h>
#include <string>
#include <umfpack.h>

namespace ContactDynamics
{
  DirectFactorization::DirectFactorization(const Method method)
    : method(method)
  {
    if (method == Method::klu)
      {
        auto *common = new klu_l_common;
        klu_l_defaults(common);
        klu_common = common;
      }
  }

  DirectFactorization::~DirectFactorization()
  {
    clear();
    delete static_cast<klu_l_common *>(klu_common);
  }

  void
  DirectFactorization::clear()
  {
    free_numeric();
    free_symbolic();
    row_start.clear();
    columns.clear();
    matrix_start.clear();
    matrix_columns.clear();
    position.clear();
  }

  void
  DirectFactorization::set_ordering(const Ordering new_ordering)
  {
    if (new_ordering != ordering)
      clear();
    ordering = new_ordering;
  }

  void
  DirectFactorization::set_skip_zeros(const bool skip)
  {
    if (skip != skip_zeros)
      clear();
    skip_zeros = skip;
  }

  void
  DirectFactorization::free_numeric()
  {
    if (numeric == nullptr)
      return;
    if (method == Method::umfpack)
      umfpack_dl_free_numeric(&numeric);
    else
      {
        auto *klu_numeric = static_cast<klu_l_numeric *>(numeric);
        klu_l_free_numeric(&klu_numeric,
                           static_cast<klu_l_common *>(klu_common));
      }
    numeric = nullptr;
  }

  void
  DirectFactorization::free_symbolic()
  {
    if (symbolic == nullptr)
      return;
    if (method == Method::umfpack)
      umfpack_dl_free_symbolic(&symbolic);
    else
      {
        auto *klu_symbolic = static_cast<klu_l_symbolic *>(symbolic);
        klu_l_free_symbolic(&klu_symbolic,
                            static_cast<klu_l_common *>(klu_common));
      }
    symbolic = nullptr;
  }

  void
  DirectFactorization::factorize(const TrilinosWrappers::SparseMatrix &matrix)
  {
    AssertThrow(Utilities::MPI::n_mpi_processes(
                  matrix.get_mpi_communicator()) == 1,
                ExcInternalError());
    const Epetra_CrsMatrix &A = matrix.trilinos_matrix();
    const int               n = A.NumMyRows();
    AssertThrow(n == A.NumGlobalRows(), ExcInternalError());

    // the same pattern as last time: gather the values in the stored order
    int       *offsets, *indices;
    double    *epetra_values;
    const bool contiguous =
      A.ExtractCrsDataPointers(offsets, indices, epetra_values) == 0;
    const bool same_pattern =
      contiguous && !matrix_start.empty() &&
      epetra_offsets.size() == static_cast<std::size_t>(n) + 1 &&
      std::equal(offsets, offsets + n + 1, epetra_offsets.begin()) &&
      std::equal(indices, indices + offsets[n], epetra_columns.begin());
    if (same_pattern)
      for (std::size_t k = 0; k < matrix_values.size(); ++k)
        matrix_values[k] = epetra_values[source[k]];
    else
      {
        // the rows in global numbering with sorted columns (removing the
        // rows that hold only a diagonal entry, half of a contact scene's,
        // was measured: UMFPACK handles them as singletons in no time)
        // (forgotten first: an exception below must not leave a stale
        // pattern that the next call would trust)
        epetra_offsets.clear();
        std::vector<std::int64_t> new_start(n + 1, 0), new_columns;
        new_columns.reserve(A.NumMyNonzeros());
        matrix_values.clear();
        source.clear();
        std::vector<std::pair<std::int64_t, int>> row;
        for (int r = 0; r < n; ++r)
          {
            AssertThrow(A.RowMap().GID(r) == r, ExcInternalError());
            int     length;
            double *row_values;
            int    *row_columns;
            A.ExtractMyRowView(r, length, row_values, row_columns);
            row.resize(length);
            for (int k = 0; k < length; ++k)
              row[k] = {A.ColMap().GID(row_columns[k]), k};
            std::sort(row.begin(), row.end());
            for (const auto &[column, k] : row)
              {
                new_columns.push_back(column);
                matrix_values.push_back(row_values[k]);
                source.push_back(contiguous ? offsets[r] + k : 0);
              }
            new_start[r + 1] = new_columns.size();
          }
        if (new_start != matrix_start || new_columns != matrix_columns)
          {
            // (an analysis exists only with the positions of its pattern)
            position.clear();
            free_numeric();
            free_symbolic();
            matrix_start.swap(new_start);
            matrix_columns.swap(new_columns);
          }
        if (contiguous)
          {
            epetra_offsets.assign(offsets, offsets + n + 1);
            epetra_columns.assign(indices, indices + offsets[n]);
          }
      }
    const bool new_pattern = !select_entries();
    if (method == Method::umfpack)
      factorize_umfpack(new_pattern);
    else
      factorize_klu(new_pattern);
  }

  bool
  DirectFactorization::select_entries()
  {
    // With skip_zeros the analysed pattern holds the entries that were
    // nonzero when it was made: the contact pattern of the matrix couples
    // every candidate patch in full, in or out of contact (62 % of the
    // entries of the 3-D ironing, issue 40), and a factorization of those
    // zeros costs their fill-in. While the nonzeros stay inside it the
    // analysis is kept.
    if (symbolic != nullptr && position.size() == matrix_values.size())
      {
        // (every entry analysed: the positions are the identity)
        if (!skip_zeros)
          {
            values = matrix_values;
            return true;
          }
        std::fill(values.begin(), values.end(), 0.);
        bool inside = true;
        for (std::size_t k = 0; inside && k < matrix_values.size(); ++k)
          if (matrix_values[k] != 0)
            {
              inside = position[k] != invalid_position;
              if (inside)
                values[position[k]] = matrix_values[k];
            }
        if (inside)
          return true;
      }
    free_numeric();
    free_symbolic();
    position.assign(matrix_values.size(), invalid_position);
    const std::size_t n = matrix_start.size() - 1;
    row_start.assign(n + 1, 0);
    columns.clear();
    values.clear();
    for (std::size_t r = 0; r < n; ++r)
      {
        for (auto k = matrix_start[r]; k < matrix_start[r + 1]; ++k)
          // (the diagonal always, zero or not: a diagonal that switches
          // between zero and nonzero would cost analyses)
          if (!skip_zeros || matrix_values[k] != 0 ||
              matrix_columns[k] == static_cast<std::int64_t>(r))
            {
              position[k] = columns.size();
              columns.push_back(matrix_columns[k]);
              values.push_back(matrix_values[k]);
            }
        row_start[r + 1] = columns.size();
      }
    return false;
  }

  void
  DirectFactorization::factorize_umfpack(const bool new_pattern)
  {
    const std::int64_t n = row_start.size() - 1;
    free_numeric();
    if (new_pattern)
      {
        double control[UMFPACK_CONTROL];
        umfpack_dl_defaults(control);
        // (METIS on the pattern of A + A^T: nested dissection, which wins
        // on 3-D meshes, where minimum degree leaves large separators)
        control[UMFPACK_ORDERING] = ordering == Ordering::metis ?
                                      UMFPACK_ORDERING_METIS :
                                      UMFPACK_ORDERING_AMD;
        const auto status         = umfpack_dl_symbolic(n,
                                                n,
                                                row_start.data(),
                                                columns.data(),
                                                values.data(),
                                                &symbolic,
                                                control,
                                                nullptr);
        AssertThrow(status == UMFPACK_OK,
                    ExcMessage("UMFPACK's symbolic analysis failed (status " +
                               std::to_string(status) + ")."));
        ++n_symbolic;
      }
    double     info[UMFPACK_INFO];
    const auto status = umfpack_dl_numeric(row_start.data(),
                                           columns.data(),
                                           values.data(),
                                           symbolic,
                                           &numeric,
                                           nullptr,
                                           info);
    n_factor_entries  = info[UMFPACK_LNZ] + info[UMFPACK_UNZ];
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
  DirectFactorization::factorize_klu(const bool new_pattern)
  {
    auto *common = static_cast<klu_l_common *>(klu_common);
    if (new_pattern)
      {
        symbolic = klu_l_analyze(row_start.size() - 1,
                                 row_start.data(),
                                 columns.data(),
                                 common);
        AssertThrow(symbolic != nullptr,
                    ExcMessage("KLU's analysis failed (status " +
                               std::to_string(common->status) + ")."));
        ++n_symbolic;
      }
    auto *klu_symbolic = static_cast<klu_l_symbolic *>(symbolic);
    // the pivot order of the last full factorization while the pivots stay
    // within a factor 1000 of the conditioning it had: a Newton iteration
    // changes the values only a little
    if (numeric != nullptr)
      {
        auto *klu_numeric = static_cast<klu_l_numeric *>(numeric);
        if (klu_l_refactor(row_start.data(),
                           columns.data(),
                           values.data(),
                           klu_symbolic,
                           klu_numeric,
                           common) &&
            klu_l_rcond(klu_symbolic, klu_numeric, common) &&
            rcond_after_pivoting > 0 &&
            common->rcond >= 1e-3 * rcond_after_pivoting)
          return;
        free_numeric();
      }
    numeric = klu_l_factor(row_start.data(),
                           columns.data(),
                           values.data(),
                           klu_symbolic,
                           common);
    AssertThrow(numeric != nullptr,
                ExcMessage(std::string("KLU's factorization failed: ") +
                           (common->status == KLU_SINGULAR ?
                              "the matrix is singular" :
                              "status " + std::to_string(common->status)) +
                           "."));
    ++n_pivoting;
    klu_l_rcond(klu_symbolic, static_cast<klu_l_numeric *>(numeric), common);
    rcond_after_pivoting = common->rcond;
  }

  void
  DirectFactorization::solve(const TrilinosWrappers::MPI::Vector &rhs,
                             TrilinosWrappers::MPI::Vector &solution) const
  {
    Assert(numeric != nullptr, ExcInternalError());
    const std::size_t n = row_start.size() - 1;
    if (method == Method::klu)
      {
        // the stored rows are the columns of the transpose: KLU factorized
        // A^T, so A x = b is its transposed solve
        solution      = rhs;
        const auto ok = klu_l_tsolve(static_cast<klu_l_symbolic *>(symbolic),
                                     static_cast<klu_l_numeric *>(numeric),
                                     n,
                                     1,
                                     solution.begin(),
                                     static_cast<klu_l_common *>(klu_common));
        AssertThrow(ok, ExcMessage("KLU's solve failed."));
        return;
      }
    double control[UMFPACK_CONTROL];
    umfpack_dl_defaults(control);
    // KLU and Amesos do not refine either; they agree with this to 1e-11 on
    // the shipped scenes, and a refinement step costs two substitutions
    control[UMFPACK_IRSTEP] = 0;
    work_indices.resize(n);
    work.resize(5 * n);
    // the stored rows are the columns of the transpose: solve A^T^T x = b
    const auto status = umfpack_dl_wsolve(UMFPACK_Aat,
                                          row_start.data(),
                                          columns.data(),
                                          values.data(),
                                          solution.begin(),
                                          rhs.begin(),
                                          numeric,
                                          control,
                                          nullptr,
                                          work_indices.data(),
                                          work.data());
    AssertThrow(status == UMFPACK_OK,
                ExcMessage("UMFPACK's solve failed (status " +
                           std::to_string(status) + ")."));
  }
} // namespace ContactDynamics
