#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <contact_dynamics/solvers/contact_frame_multigrid.h>

#include <Epetra_CrsMatrix.h>
#include <Teuchos_ParameterList.hpp>
#include <algorithm>
#include <cmath>

namespace ContactDynamics
{
  using Index = types::global_dof_index;

  namespace
  {
    // Reduces the given rows (locally owned, sorted) of a matrix to their
    // diagonal and removes their columns from every other row (collective:
    // the columns owned elsewhere are gathered).
    void
    eliminate_rows_and_columns(TrilinosWrappers::SparseMatrix &matrix,
                               const std::vector<Index>       &rows)
    {
      std::vector<Index> all;
      for (const auto &part :
           Utilities::MPI::all_gather(matrix.get_mpi_communicator(), rows))
        all.insert(all.end(), part.begin(), part.end());
      std::sort(all.begin(), all.end());
      if (all.empty())
        return;
      Epetra_CrsMatrix &a =
        const_cast<Epetra_CrsMatrix &>(matrix.trilinos_matrix());
      for (int r = 0; r < a.NumMyRows(); ++r)
        {
          int     n       = 0;
          double *values  = nullptr;
          int    *indices = nullptr;
          a.ExtractMyRowView(r, n, values, indices);
          const Index row = a.GRID(r);
          const bool  constrained =
            std::binary_search(all.begin(), all.end(), row);
          for (int k = 0; k < n; ++k)
            {
              const Index column = a.GCID(indices[k]);
              if (column != row &&
                  (constrained ||
                   std::binary_search(all.begin(), all.end(), column)))
                values[k] = 0;
            }
        }
    }

    // The identity, except on the dofs of each frame, where the entry in
    // row dofs[i] and column dofs[j] is block(frame, i, j).
    template <typename Block>
    void
    frame_block_matrix(TrilinosWrappers::SparseMatrix &m,
                       const IndexSet                 &owned,
                       const MPI_Comm                  comm,
                       const std::vector<NodeFrame>   &frames,
                       const Block                    &block)
    {
      DynamicSparsityPattern dsp(owned.size(), owned.size(), owned);
      std::vector<bool>      in_frame(owned.n_elements(), false);
      for (const auto &f : frames)
        for (const Index i : f.dofs)
          {
            in_frame[owned.index_within_set(i)] = true;
            for (const Index j : f.dofs)
              dsp.add(i, j);
          }
      for (const Index i : owned)
        if (!in_frame[owned.index_within_set(i)])
          dsp.add(i, i);
      m.reinit(owned, owned, dsp, comm);
      for (const auto &f : frames)
        for (unsigned int i = 0; i < f.dofs.size(); ++i)
          for (unsigned int j = 0; j < f.dofs.size(); ++j)
            m.set(f.dofs[i], f.dofs[j], block(f, i, j));
      for (const Index i : owned)
        if (!in_frame[owned.index_within_set(i)])
          m.set(i, i, 1.);
      m.compress(VectorOperation::insert);
    }

    // Every process's frames: the dofs (dim per frame) and the axes
    // (dim x dim per frame, row c = axis c). Collective.
    void
    gather_frames(const std::vector<NodeFrame> &frames,
                  const MPI_Comm                comm,
                  std::vector<Index>           &dofs,
                  std::vector<double>          &axes)
    {
      std::vector<Index>  own_dofs;
      std::vector<double> own_axes;
      for (const auto &f : frames)
        {
          own_dofs.insert(own_dofs.end(), f.dofs.begin(), f.dofs.end());
          for (const auto &axis : f.axes)
            own_axes.insert(own_axes.end(), axis.begin(), axis.end());
        }
      dofs.clear();
      axes.clear();
      for (const auto &part : Utilities::MPI::all_gather(comm, own_dofs))
        dofs.insert(dofs.end(), part.begin(), part.end());
      for (const auto &part : Utilities::MPI::all_gather(comm, own_axes))
        axes.insert(axes.end(), part.begin(), part.end());
    }

    // A T in place: in every row, the entries in the columns of a frame
    // rotated (column j of a frame = sum_i column i * axes[j][i]). False
    // if a row holds only some of a frame's columns (the pattern has no
    // room for the product).
    bool
    rotate_columns(Epetra_CrsMatrix          &a,
                   const std::vector<Index>  &dofs,
                   const std::vector<double> &axes,
                   const unsigned int         dim)
    {
      // local column -> frame * dim + component
      std::vector<int> slot(a.NumMyCols(), -1);
      for (unsigned int k = 0; k < dofs.size(); ++k)
        {
          const int column = a.LCID(static_cast<int>(dofs[k]));
          if (column >= 0)
            slot[column] = k;
        }
      std::vector<std::pair<int, int>> found; // (slot, position)
      std::vector<double>              old(dim);
      for (int r = 0; r < a.NumMyRows(); ++r)
        {
          int     n       = 0;
          double *values  = nullptr;
          int    *indices = nullptr;
          a.ExtractMyRowView(r, n, values, indices);
          found.clear();
          for (int k = 0; k < n; ++k)
            if (slot[indices[k]] >= 0)
              found.emplace_back(slot[indices[k]], k);
          if (found.empty())
            continue;
          if (found.size() % dim != 0)
            return false;
          std::sort(found.begin(), found.end());
          for (unsigned int g = 0; g < found.size(); g += dim)
            {
              const int frame = found[g].first / dim;
              for (unsigned int i = 0; i < dim; ++i)
                {
                  if (found[g + i].first != int(frame * dim + i))
                    return false;
                  old[i] = values[found[g + i].second];
                }
              const double *q = axes.data() + frame * dim * dim;
              for (unsigned int j = 0; j < dim; ++j)
                {
                  double value = 0;
                  for (unsigned int i = 0; i < dim; ++i)
                    value += old[i] * q[j * dim + i];
                  values[found[g + j].second] = value;
                }
            }
        }
      return true;
    }

    // L A in place for the locally owned frames: row c of a frame =
    // sum_d to_frame[c][d] * row d. False unless a frame's rows share
    // their columns.
    bool
    combine_rows(Epetra_CrsMatrix &a, const std::vector<NodeFrame> &frames)
    {
      for (const auto &f : frames)
        {
          const unsigned int    dim = f.dofs.size();
          std::vector<double *> rows(dim);
          int                   n             = -1;
          int                  *first_indices = nullptr;
          for (unsigned int d = 0; d < dim; ++d)
            {
              int       m       = 0;
              int      *indices = nullptr;
              const int row     = a.LRID(static_cast<int>(f.dofs[d]));
              if (row < 0)
                return false;
              a.ExtractMyRowView(row, m, rows[d], indices);
              if (d == 0)
                {
                  n             = m;
                  first_indices = indices;
                }
              else if (m != n ||
                       !std::equal(indices, indices + m, first_indices))
                return false;
            }
          std::vector<double> old(dim);
          for (int k = 0; k < n; ++k)
            {
              for (unsigned int d = 0; d < dim; ++d)
                old[d] = rows[d][k];
              for (unsigned int c = 0; c < dim; ++c)
                {
                  double value = 0;
                  for (unsigned int d = 0; d < dim; ++d)
                    value += f.to_frame[c][d] * old[d];
                  rows[c][k] = value;
                }
            }
        }
      return true;
    }

    // whether `compact` is a matrix of `full`'s rows and columns
    bool
    same_maps(const Epetra_CrsMatrix               &full,
              const TrilinosWrappers::SparseMatrix &compact)
    {
      return compact.m() == static_cast<unsigned int>(full.NumGlobalRows()) &&
             compact.trilinos_matrix().RowMap().SameAs(full.RowMap()) &&
             compact.trilinos_matrix().ColMap().SameAs(full.ColMap());
    }

    // The entries of `full` into `compact` (same row and column maps) if
    // its pattern holds all of them that are nonzero. Collective.
    bool
    copy_into_pattern(const Epetra_CrsMatrix         &full,
                      TrilinosWrappers::SparseMatrix &compact,
                      const MPI_Comm                  comm)
    {
      bool fits = same_maps(full, compact);
      if (fits)
        {
          Epetra_CrsMatrix &c =
            const_cast<Epetra_CrsMatrix &>(compact.trilinos_matrix());
          for (int r = 0; r < full.NumMyRows() && fits; ++r)
            {
              int     n = 0, m = 0;
              double *v = nullptr, *cv = nullptr;
              int    *idx = nullptr, *cidx = nullptr;
              full.ExtractMyRowView(r, n, v, idx);
              c.ExtractMyRowView(r, m, cv, cidx);
              int j = 0;
              for (int k = 0; k < n; ++k)
                {
                  while (j < m && cidx[j] < idx[k])
                    cv[j++] = 0;
                  if (j < m && cidx[j] == idx[k])
                    cv[j++] = v[k];
                  else if (v[k] != 0)
                    {
                      fits = false;
                      break;
                    }
                }
              while (j < m)
                cv[j++] = 0;
            }
        }
      return Utilities::MPI::min(int(fits), comm) == 1;
    }

    // The entries of `full` that are nonzero or on the diagonal, into
    // `compact` with a pattern of their own: the contact pattern reserves
    // couplings that are zero most of the time, and ML and GMRES pay for
    // every stored entry. Entries of the previous pattern stay while they
    // add at most 5 % (some stiffness entries are zero in symmetric
    // states: on the 3-D bouncing block in flight, without them, every
    // Newton iteration rebuilt the pattern). Collective.
    void
    copy_nonzeros(const Epetra_CrsMatrix         &full,
                  TrilinosWrappers::SparseMatrix &compact)
    {
      const bool              had_pattern = same_maps(full, compact);
      const Epetra_CrsMatrix &old         = compact.trilinos_matrix();
      // per row: which entries of `full` to keep, 1 (nonzero or diagonal)
      // or 2 (also in the previous pattern)
      std::vector<std::vector<char>> keep(full.NumMyRows());
      std::size_t                    n_nonzero = 0, n_union = 0;
      for (int r = 0; r < full.NumMyRows(); ++r)
        {
          int     n = 0, m = 0;
          double *v = nullptr, *ov = nullptr;
          int    *idx = nullptr, *oidx = nullptr;
          full.ExtractMyRowView(r, n, v, idx);
          if (had_pattern)
            old.ExtractMyRowView(r, m, ov, oidx);
          const int diagonal = full.LCID(full.GRID(r));
          keep[r].assign(n, 0);
          for (int k = 0, j = 0; k < n; ++k)
            {
              while (j < m && oidx[j] < idx[k])
                ++j;
              if (v[k] != 0 || idx[k] == diagonal)
                keep[r][k] = 1;
              else if (j < m && oidx[j] == idx[k])
                keep[r][k] = 2;
              n_nonzero += (keep[r][k] == 1);
              n_union += (keep[r][k] > 0);
            }
        }
      const char       largest = n_union <= 1.05 * n_nonzero ? 2 : 1;
      std::vector<int> counts(full.NumMyRows(), 0);
      for (int r = 0; r < full.NumMyRows(); ++r)
        for (const char k : keep[r])
          counts[r] += (k > 0 && k <= largest);
      Epetra_CrsMatrix    reduced(Copy,
                               full.RowMap(),
                               full.ColMap(),
                               counts.data(),
                               true);
      std::vector<int>    columns;
      std::vector<double> values;
      for (int r = 0; r < full.NumMyRows(); ++r)
        {
          int     n   = 0;
          double *v   = nullptr;
          int    *idx = nullptr;
          full.ExtractMyRowView(r, n, v, idx);
          columns.clear();
          values.clear();
          for (int k = 0; k < n; ++k)
            if (keep[r][k] > 0 && keep[r][k] <= largest)
              {
                columns.push_back(idx[k]);
                values.push_back(v[k]);
              }
          reduced.InsertMyValues(r,
                                 columns.size(),
                                 values.data(),
                                 columns.data());
        }
      reduced.FillComplete(full.DomainMap(), full.RangeMap());
      compact.reinit(reduced, true);
    }

    // dst = src; the values only if every process's pattern is the same
    // (decided together: SparseMatrix::copy_from decides per process
    // whether to rebuild, and the rebuild is collective). Collective.
    void
    copy_matrix(const TrilinosWrappers::SparseMatrix &src,
                TrilinosWrappers::SparseMatrix       &dst,
                const MPI_Comm                        comm)
    {
      const Epetra_CrsMatrix &a = src.trilinos_matrix();
      Epetra_CrsMatrix       &b =
        const_cast<Epetra_CrsMatrix &>(dst.trilinos_matrix());
      bool same = dst.m() == src.m() && a.RowMap().SameAs(b.RowMap()) &&
                  a.ColMap().SameAs(b.ColMap()) &&
                  a.NumMyNonzeros() == b.NumMyNonzeros();
      for (int r = 0; same && r < a.NumMyRows(); ++r)
        {
          int     n = 0, m = 0;
          double *v = nullptr, *w = nullptr;
          int    *i = nullptr, *j = nullptr;
          a.ExtractMyRowView(r, n, v, i);
          b.ExtractMyRowView(r, m, w, j);
          same = n == m && std::equal(i, i + n, j);
        }
      if (Utilities::MPI::min(int(same), comm) == 0)
        {
          dst.reinit(a, true);
          return;
        }
      for (int r = 0; r < a.NumMyRows(); ++r)
        {
          int     n = 0, m = 0;
          double *v = nullptr, *w = nullptr;
          int    *i = nullptr, *j = nullptr;
          a.ExtractMyRowView(r, n, v, i);
          b.ExtractMyRowView(r, m, w, j);
          std::copy(v, v + n, w);
        }
    }
  } // namespace

  NodeFrame
  make_node_frame(const std::vector<Index>               &dofs,
                  const std::vector<std::vector<double>> &q,
                  const std::vector<std::vector<double>> &stiffness,
                  const std::vector<std::vector<double>> &coefficients,
                  const std::vector<unsigned int>        &placed,
                  const std::vector<double>              &factors,
                  const std::vector<bool>                &constrained)
  {
    const unsigned int dim = dofs.size();
    NodeFrame          frame;
    frame.dofs        = dofs;
    frame.constrained = constrained;
    frame.axes.assign(dim, std::vector<double>(dim));
    frame.to_frame.assign(dim, std::vector<double>(dim, 0.));
    for (unsigned int b = 0; b < dim; ++b)
      for (unsigned int d = 0; d < dim; ++d)
        frame.axes[b][d] = q[d][b];
    for (unsigned int d = 0; d < dim; ++d)
      {
        const unsigned int b   = placed[d];
        double             own = 0, rotated = 0;
        for (unsigned int e = 0; e < dim; ++e)
          {
            own += coefficients[b][e] * q[e][b];
            for (unsigned int f = 0; f < dim; ++f)
              rotated += q[e][b] * stiffness[e][f] * q[f][b];
          }
        frame.to_frame[b][d] =
          (own != 0 ? std::abs(rotated) / own : 1.) / factors[d];
      }
    return frame;
  }

  void
  initialize_amg(TrilinosWrappers::PreconditionAMG    &amg,
                 const TrilinosWrappers::SparseMatrix &matrix,
                 const std::vector<double>            &null_space,
                 const unsigned int                    n_modes,
                 const unsigned int                    dofs_per_vertex,
                 const AmgSmoother                    &smoother)
  {
    TrilinosWrappers::PreconditionAMG::AdditionalData data(true, false);
    data.smoother_type   = smoother.type.c_str();
    data.smoother_sweeps = smoother.sweeps;
    Teuchos::ParameterList              list;
    std::unique_ptr<Epetra_MultiVector> unused_modes;
    data.set_parameters(list, unused_modes, matrix);
    list.set("ML output", 0);
    if (n_modes > 0 &&
        null_space.size() ==
          n_modes * matrix.locally_owned_range_indices().n_elements())
      {
        list.set("PDE equations", static_cast<int>(dofs_per_vertex));
        list.set("null space: type", "pre-computed");
        list.set("null space: dimension", static_cast<int>(n_modes));
        // (ML copies the vectors)
        list.set("null space: vectors",
                 const_cast<double *>(null_space.data()));
      }
    amg.initialize(matrix, list);
  }

  ContactFrameMultigrid::ContactFrameMultigrid()
    : rotation(std::make_unique<TrilinosWrappers::SparseMatrix>())
    , transformed(std::make_unique<TrilinosWrappers::SparseMatrix>())
    , compact(std::make_unique<TrilinosWrappers::SparseMatrix>())
    , transformed_rhs(std::make_unique<TrilinosWrappers::MPI::Vector>())
    , ghosted(std::make_unique<TrilinosWrappers::MPI::Vector>())
  {}

  ContactFrameMultigrid::~ContactFrameMultigrid() = default;

  const TrilinosWrappers::SparseMatrix &
  ContactFrameMultigrid::matrix() const
  {
    return in_place ? *compact : *transformed;
  }

  const TrilinosWrappers::MPI::Vector &
  ContactFrameMultigrid::rhs() const
  {
    return *transformed_rhs;
  }

  void
  ContactFrameMultigrid::transform(const TrilinosWrappers::SparseMatrix &a,
                                   const TrilinosWrappers::MPI::Vector  &b,
                                   const std::vector<NodeFrame> &new_frames)
  {
    frames                = new_frames;
    const IndexSet &owned = b.locally_owned_elements();
    const MPI_Comm  comm  = b.get_mpi_communicator();

    // in the Jacobian's own pattern where each row holds all or none of a
    // node's columns (Q1 couplings); else as sparse products
    std::vector<Index>  all_dofs;
    std::vector<double> all_axes;
    gather_frames(frames, comm, all_dofs, all_axes);
    copy_matrix(a, *transformed, comm);
    Epetra_CrsMatrix &m =
      const_cast<Epetra_CrsMatrix &>(transformed->trilinos_matrix());
    const unsigned int dim =
      all_dofs.empty() ? 1 : all_axes.size() / all_dofs.size();
    in_place =
      Utilities::MPI::min(int(rotate_columns(m, all_dofs, all_axes, dim) &&
                              combine_rows(m, frames)),
                          comm) == 1;
    if (!in_place)
      {
        frame_block_matrix(*rotation,
                           owned,
                           comm,
                           frames,
                           [](const NodeFrame &f,
                              unsigned int     d,
                              unsigned int     c) {
                             return f.axes[c][d];
                           });
        TrilinosWrappers::SparseMatrix to_frame, la;
        frame_block_matrix(to_frame,
                           owned,
                           comm,
                           frames,
                           [](const NodeFrame &f,
                              unsigned int     c,
                              unsigned int     d) {
                             return f.to_frame[c][d];
                           });
        to_frame.mmult(la, a);
        la.mmult(*transformed, *rotation);
      }
    else if (!copy_into_pattern(m, *compact, comm))
      copy_nonzeros(m, *compact);
    transformed_rhs->reinit(b);
    *transformed_rhs = b;
    apply_blocks(*transformed_rhs,
                 b,
                 [](const NodeFrame &f, unsigned int c, unsigned int d) {
                   return f.to_frame[c][d];
                 });

    constrained.clear();
    for (const auto &f : frames)
      for (unsigned int c = 0; c < f.dofs.size(); ++c)
        if (f.constrained[c])
          constrained.push_back(f.dofs[c]);
    std::sort(constrained.begin(), constrained.end());
    constrained_local.clear();
    constrained_diagonal.clear();
    for (const Index i : constrained)
      {
        constrained_local.push_back(owned.index_within_set(i));
        const double diagonal = matrix().diag_element(i);
        // (a zero diagonal: the cycle's value stays)
        constrained_diagonal.push_back(diagonal != 0 ? diagonal : HUGE_VAL);
      }
    store_constraint_rows();
  }

  void
  ContactFrameMultigrid::store_constraint_rows()
  {
    const IndexSet &owned = transformed_rhs->locally_owned_elements();
    const MPI_Comm  comm  = transformed_rhs->get_mpi_communicator();
    // the constraint rows' entries: their residuals after each cycle
    // without a product with the whole matrix
    const Epetra_CrsMatrix &t = matrix().trilinos_matrix();
    IndexSet                needed(owned.size());
    std::vector<Index>      columns;
    row_values.clear();
    row_start.assign(1, 0);
    for (const Index i : constrained)
      {
        int     n       = 0;
        double *values  = nullptr;
        int    *indices = nullptr;
        t.ExtractMyRowView(t.LRID(static_cast<int>(i)), n, values, indices);
        for (int k = 0; k < n; ++k)
          {
            columns.push_back(t.GCID(indices[k]));
            row_values.push_back(values[k]);
          }
        row_start.push_back(row_values.size());
      }
    std::vector<Index> sorted(columns);
    std::sort(sorted.begin(), sorted.end());
    sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
    needed.add_indices(sorted.begin(), sorted.end());
    needed.add_indices(owned);
    needed.compress();
    any_constrained = Utilities::MPI::max(int(!constrained.empty()), comm) > 0;
    ghosted->reinit(owned, needed, comm);
    const Epetra_BlockMap &map = ghosted->trilinos_vector().Map();
    row_columns.clear();
    for (const Index c : columns)
      row_columns.push_back(map.LID(static_cast<int>(c)));
    corrections.resize(constrained.size());
  }

  void
  ContactFrameMultigrid::back_transform(const TrilinosWrappers::MPI::Vector &y,
                                        TrilinosWrappers::MPI::Vector &x) const
  {
    if (!in_place)
      {
        rotation->vmult(x, y);
        return;
      }
    x = y;
    apply_blocks(x, y, [](const NodeFrame &f, unsigned int d, unsigned int c) {
      return f.axes[c][d];
    });
  }

  template <typename Block>
  void
  ContactFrameMultigrid::apply_blocks(TrilinosWrappers::MPI::Vector       &dst,
                                      const TrilinosWrappers::MPI::Vector &src,
                                      const Block &block) const
  {
    const IndexSet &owned = src.locally_owned_elements();
    const double   *in    = src.begin();
    double         *out   = dst.begin();
    for (const auto &f : frames)
      for (unsigned int i = 0; i < f.dofs.size(); ++i)
        {
          double value = 0;
          for (unsigned int j = 0; j < f.dofs.size(); ++j)
            value += block(f, i, j) * in[owned.index_within_set(f.dofs[j])];
          out[owned.index_within_set(f.dofs[i])] = value;
        }
  }

  bool
  ContactFrameMultigrid::needs_build() const
  {
    // (a hierarchy of other unknowns would write past its vectors)
    return Utilities::MPI::max(int(!amg || constrained != built_constrained ||
                                   amg_matrix->m() != matrix().m() ||
                                   amg_matrix->local_size() !=
                                     matrix().local_size()),
                               transformed->get_mpi_communicator()) > 0;
  }

  void
  ContactFrameMultigrid::build(const std::vector<double> &null_space,
                               const unsigned int         n_modes,
                               const unsigned int         dofs_per_vertex,
                               const AmgSmoother         &smoother)
  {
    // ML's destruction reads its matrix (IFPACK's smoothers do)
    amg.reset();
    amg_matrix = std::make_unique<TrilinosWrappers::SparseMatrix>();
    amg_matrix->copy_from(matrix());
    eliminate_rows_and_columns(*amg_matrix, constrained);
    built_constrained = constrained;
    // the modes in the frames: T^T v at the frames' dofs
    const IndexSet     &owned   = transformed_rhs->locally_owned_elements();
    const std::size_t   n_owned = owned.n_elements();
    std::vector<double> modes(null_space);
    if (modes.size() == n_modes * n_owned)
      for (const auto &f : frames)
        for (unsigned int m = 0; m < n_modes; ++m)
          {
            double             *v = modes.data() + m * n_owned;
            std::vector<double> old(f.dofs.size());
            for (unsigned int d = 0; d < f.dofs.size(); ++d)
              old[d] = v[owned.index_within_set(f.dofs[d])];
            for (unsigned int c = 0; c < f.dofs.size(); ++c)
              {
                double value = 0;
                for (unsigned int d = 0; d < f.dofs.size(); ++d)
                  value += f.axes[c][d] * old[d];
                v[owned.index_within_set(f.dofs[c])] = value;
              }
          }
    amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
    initialize_amg(*amg,
                   *amg_matrix,
                   modes,
                   n_modes,
                   dofs_per_vertex,
                   smoother);
  }

  void
  ContactFrameMultigrid::vmult(TrilinosWrappers::MPI::Vector       &dst,
                               const TrilinosWrappers::MPI::Vector &src) const
  {
    amg->vmult(dst, src);
    if (!any_constrained)
      return;
    // each constraint row solved for its own component, given the others
    *ghosted         = dst;
    const double *g  = ghosted->trilinos_vector()[0];
    const double *in = src.begin();
    for (unsigned int k = 0; k < constrained_local.size(); ++k)
      {
        double r = in[constrained_local[k]];
        for (unsigned int e = row_start[k]; e < row_start[k + 1]; ++e)
          r -= row_values[e] * g[row_columns[e]];
        corrections[k] = r / constrained_diagonal[k];
      }
    double *x = dst.begin();
    for (unsigned int k = 0; k < constrained_local.size(); ++k)
      x[constrained_local[k]] += corrections[k];
  }
} // namespace ContactDynamics
