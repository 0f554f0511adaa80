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
                 const unsigned int                    dofs_per_vertex)
  {
    TrilinosWrappers::PreconditionAMG::AdditionalData data(true, false);
    data.smoother_sweeps = 2;
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
    , transformed_rhs(std::make_unique<TrilinosWrappers::MPI::Vector>())
    , residual(std::make_unique<TrilinosWrappers::MPI::Vector>())
  {}

  ContactFrameMultigrid::~ContactFrameMultigrid() = default;

  const TrilinosWrappers::SparseMatrix &
  ContactFrameMultigrid::matrix() const
  {
    return *transformed;
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
    frame_block_matrix(*rotation,
                       owned,
                       comm,
                       frames,
                       [](const NodeFrame &f, unsigned int d, unsigned int c) {
                         return f.axes[c][d];
                       });
    TrilinosWrappers::SparseMatrix to_frame, la;
    frame_block_matrix(to_frame,
                       owned,
                       comm,
                       frames,
                       [](const NodeFrame &f, unsigned int c, unsigned int d) {
                         return f.to_frame[c][d];
                       });
    to_frame.mmult(la, a);
    la.mmult(*transformed, *rotation);
    transformed_rhs->reinit(b);
    to_frame.vmult(*transformed_rhs, b);
    residual->reinit(b);

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
        const double diagonal = transformed->diag_element(i);
        // (a zero diagonal: the cycle's value stays)
        constrained_diagonal.push_back(diagonal != 0 ? diagonal : HUGE_VAL);
      }
  }

  void
  ContactFrameMultigrid::back_transform(const TrilinosWrappers::MPI::Vector &y,
                                        TrilinosWrappers::MPI::Vector &x) const
  {
    rotation->vmult(x, y);
  }

  bool
  ContactFrameMultigrid::needs_build() const
  {
    return Utilities::MPI::max(int(!amg || constrained != built_constrained),
                               transformed->get_mpi_communicator()) > 0;
  }

  void
  ContactFrameMultigrid::build(const std::vector<double> &null_space,
                               const unsigned int         n_modes,
                               const unsigned int         dofs_per_vertex)
  {
    amg_matrix = std::make_unique<TrilinosWrappers::SparseMatrix>();
    amg_matrix->copy_from(*transformed);
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
    initialize_amg(*amg, *amg_matrix, modes, n_modes, dofs_per_vertex);
  }

  void
  ContactFrameMultigrid::vmult(TrilinosWrappers::MPI::Vector       &dst,
                               const TrilinosWrappers::MPI::Vector &src) const
  {
    amg->vmult(dst, src);
    // each constraint row solved for its own component, given the others
    transformed->residual(*residual, dst, src);
    double       *x = dst.begin();
    const double *r = residual->begin();
    for (unsigned int k = 0; k < constrained_local.size(); ++k)
      x[constrained_local[k]] +=
        r[constrained_local[k]] / constrained_diagonal[k];
  }
} // namespace ContactDynamics
