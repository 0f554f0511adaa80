#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/work_stream.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <contact_dynamics/mechanics/solid_mechanics.h>
#include <contact_dynamics/parallel.h>

#include <Epetra_CrsMatrix.h>
#include <algorithm>
#include <exception>

namespace ContactDynamics
{
  namespace
  {
    constexpr std::size_t none = static_cast<std::size_t>(-1);

    /**
     * The displacement's shape functions on one cell. They are those of the
     * scalar base element times unit vectors: displacement dof i of the
     * system element is e_{component[i]} phi_{node[i]}, so that its gradient
     * is e_{component[i]} (x) grad phi_{node[i]}. Working with the scalar
     * functions avoids FEValuesViews and products with zero entries. Their
     * gradients come from FEValues or from a cache (the mesh does not move:
     * total Lagrangian).
     */
    template <int dim>
    struct ScratchData
    {
      ScratchData(const Mapping<dim> &mapping, const FiniteElement<dim> &fe)
        : mapping(mapping)
        , fe(fe)
        , quadrature(fe.degree + 1)
        , fe_values(mapping,
                    fe.base_element(fe.component_to_base_index(0).first),
                    quadrature,
                    update_values | update_gradients | update_JxW_values)
      {
        const unsigned int base = fe.component_to_base_index(0).first;
        for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
          {
            const auto [c, index] = fe.system_to_component_index(i);
            if (c < dim)
              {
                AssertThrow(fe.component_to_base_index(c).first == base &&
                              fe.base_element(base).n_components() == 1,
                            ExcMessage("The displacement components must "
                                       "share one scalar base element."));
                u_dofs.push_back(i);
                component.push_back(c);
                node.push_back(index);
              }
          }
        u_local.resize(u_dofs.size());
        n_nodes = fe.base_element(base).n_dofs_per_cell();
        cell_gradients.resize(quadrature.size() * n_nodes);
        cell_JxW.resize(quadrature.size());
      }

      // WorkStream copies the sample for each thread
      ScratchData(const ScratchData &other)
        : ScratchData(other.mapping, other.fe)
      {}

      // the system element's dofs are not those of fe_values
      void
      reinit(const typename DoFHandler<dim>::active_cell_iterator &cell)
      {
        fe_values.reinit(typename Triangulation<dim>::cell_iterator(cell));
        for (unsigned int q = 0; q < quadrature.size(); ++q)
          {
            cell_JxW[q] = fe_values.JxW(q);
            for (unsigned int a = 0; a < n_nodes; ++a)
              cell_gradients[q * n_nodes + a] = fe_values.shape_grad(a, q);
          }
        reinit(cell_gradients.data(), cell_JxW.data());
      }

      // gradients[q * n_nodes + a]: of scalar shape function a at point q
      void
      reinit(const Tensor<1, dim> *gradients, const double *JxW_values)
      {
        this->gradients  = gradients;
        this->JxW_values = JxW_values;
      }

      const Tensor<1, dim> &
      grad(const unsigned int k, const unsigned int q) const
      {
        return gradients[q * n_nodes + node[k]];
      }

      double
      JxW(const unsigned int q) const
      {
        return JxW_values[q];
      }

      const Mapping<dim>       &mapping;
      const FiniteElement<dim> &fe;
      const QGauss<dim>         quadrature;
      FEValues<dim>             fe_values;
      // per displacement dof k: its index in the system element, its
      // component, its scalar shape function
      std::vector<unsigned int>   u_dofs, component, node;
      std::vector<double>         u_local; // the displacement dofs' values
      unsigned int                n_nodes;
      std::vector<Tensor<1, dim>> cell_gradients;
      std::vector<double>         cell_JxW;
      const Tensor<1, dim>       *gradients  = nullptr;
      const double               *JxW_values = nullptr;
    };

    template <int dim>
    struct CopyData
    {
      explicit CopyData(const unsigned int n)
        : matrix(n, n)
        , rhs(n)
        , zero(n)
        , dofs(n)
      {}

      FullMatrix<double>                   matrix;
      Vector<double>                       rhs, zero;
      std::vector<types::global_dof_index> dofs;
      double                               energy = 0;
      std::size_t                          cell   = 0; // in a cell list
      // WorkStream aborts on exceptions that escape a worker: the first one
      // in the order of the cells is rethrown after the loop
      std::exception_ptr failure;
    };

    // matrix(i, j) += factor * A[c_i][k][c_j][l] g_i[k] g_j[l] for the
    // displacement dofs i <= j at point q. A has major symmetry (the
    // second derivative of a stored energy): the caller mirrors the upper
    // triangle.
    template <int dim>
    void
    add_stiffness(const Tensor<4, dim>   &A,
                  const double            factor,
                  const unsigned int      q,
                  const ScratchData<dim> &s,
                  FullMatrix<double>     &matrix)
    {
      const unsigned int n = s.u_dofs.size();
      for (unsigned int i = 0; i < n; ++i)
        {
          const Tensor<1, dim> &g = s.grad(i, q);
          Tensor<2, dim>        h; // h[d][l] = factor g[k] A[c_i][k][d][l]
          for (unsigned int k = 0; k < dim; ++k)
            h += (factor * g[k]) * A[s.component[i]][k];
          for (unsigned int j = i; j < n; ++j)
            matrix(s.u_dofs[i], s.u_dofs[j]) +=
              h[s.component[j]] * s.grad(j, q);
        }
    }

    // matrix(i, j) += factor phi_i phi_j for the displacement dofs i <= j of
    // the same component
    template <int dim>
    void
    add_mass(const double            factor,
             const unsigned int      q,
             const ScratchData<dim> &s,
             FullMatrix<double>     &matrix)
    {
      const unsigned int n = s.u_dofs.size();
      for (unsigned int i = 0; i < n; ++i)
        {
          const double phi = factor * s.fe_values.shape_value(s.node[i], q);
          for (unsigned int j = i; j < n; ++j)
            if (s.component[j] == s.component[i])
              matrix(s.u_dofs[i], s.u_dofs[j]) +=
                phi * s.fe_values.shape_value(s.node[j], q);
        }
    }

    template <int dim>
    void
    mirror_upper_triangle(const ScratchData<dim> &s, FullMatrix<double> &matrix)
    {
      for (unsigned int i = 0; i < s.u_dofs.size(); ++i)
        for (unsigned int j = i + 1; j < s.u_dofs.size(); ++j)
          matrix(s.u_dofs[j], s.u_dofs[i]) = matrix(s.u_dofs[i], s.u_dofs[j]);
    }

    // WorkStream over `cells` (worker(position in cells, ...)): exceptions
    // of `worker` reach the caller
    template <typename Iterator, typename Worker, typename Copier, int dim>
    void
    run_on_cells(const std::vector<Iterator> &cells,
                 const Worker                &worker,
                 const Copier                &copier,
                 const Mapping<dim>          &mapping,
                 const FiniteElement<dim>    &fe)
    {
      std::exception_ptr first_failure;
      using It = typename std::vector<Iterator>::const_iterator;
      WorkStream::run(
        cells.begin(),
        cells.end(),
        [&](const It &cell, ScratchData<dim> &scratch, CopyData<dim> &copy) {
          copy.failure = nullptr;
          try
            {
              (*cell)->get_dof_indices(copy.dofs);
              worker(cell, scratch, copy);
            }
          catch (...)
            {
              copy.failure = std::current_exception();
            }
        },
        [&](const CopyData<dim> &copy) {
          if (copy.failure)
            {
              if (!first_failure)
                first_failure = copy.failure;
            }
          else if (!first_failure)
            copier(copy);
        },
        ScratchData<dim>(mapping, fe),
        CopyData<dim>(fe.n_dofs_per_cell()));
      if (first_failure)
        std::rethrow_exception(first_failure);
    }
  } // namespace



  template <int dim>
  SolidMechanics<dim>::SolidMechanics(const Mapping<dim>    &mapping,
                                      const DoFHandler<dim> &dof_handler,
                                      const std::vector<BodyParameters> &bodies)
    : mapping(mapping)
    , dof_handler(dof_handler)
    , bodies(bodies)
  {
    for (const auto &b : bodies)
      {
        materials.push_back(create_material<dim>(b.material));
        has_linear_cells = has_linear_cells || materials.back()->is_linear();
      }
  }

  template <int dim>
  bool
  SolidMechanics<dim>::is_linear() const
  {
    for (const auto &m : materials)
      if (!m->is_linear())
        return false;
    return true;
  }

  template <int dim>
  void
  SolidMechanics<dim>::make_sparsity_pattern(
    const AffineConstraints<double> &constraints,
    DynamicSparsityPattern          &dsp) const
  {
    const unsigned int n_components = dof_handler.get_fe().n_components();
    Table<2, DoFTools::Coupling> coupling(n_components, n_components);
    for (unsigned int c = 0; c < n_components; ++c)
      for (unsigned int d = 0; d < n_components; ++d)
        coupling(c, d) =
          (c < dim && d < dim) ? DoFTools::always : DoFTools::none;
    DoFTools::make_sparsity_pattern(dof_handler,
                                    coupling,
                                    dsp,
                                    constraints,
                                    false);
    // the diagonal of the ghost rows too: a constraint added later (all
    // multipliers for the initial acceleration) puts a diagonal entry into
    // rows owned by another process, which Trilinos refuses where the
    // pattern has none (a rigid obstacle's multipliers on a distributed
    // mesh)
    // (every row the pattern keeps: on a replicated mesh of a few cells
    // the locally relevant rows are all rows)
    for (const auto i : dsp.row_index_set())
      dsp.add(i, i);
    // a new pattern for the Jacobian follows
    positions_found = false;
  }

  template <int dim>
  void
  SolidMechanics<dim>::find_positions(const MatrixType &jacobian) const
  {
    positions_found    = true;
    positions_matrix   = &jacobian.trilinos_matrix();
    positions_nonzeros = jacobian.trilinos_matrix().NumMyNonzeros();
    positions_values   = nullptr;
    cell_positions.clear();
    first_position.assign(nonlinear_cells.size(), none);
    constant_positions.clear();
    const Epetra_CrsMatrix &J = jacobian.trilinos_matrix();
    int                    *row_start, *columns;
    double                 *values;
    if (J.ExtractCrsDataPointers(row_start, columns, values) != 0)
      return;
    positions_values = values;
    // the position of entry (row, column) in global numbering, or -1
    const auto position = [&](const long long row, const long long column) {
      const int r = J.RowMap().LID(row), c = J.ColMap().LID(column);
      if (r < 0 || c < 0)
        return -1ll;
      const int *begin = columns + row_start[r],
                *end   = columns + row_start[r + 1];
      // once per pattern: a linear search needs no sorted rows
      const int *found = std::find(begin, end, c);
      return found != end ? found - columns : -1ll;
    };

    const AffineConstraints<double> &constraints = *jacobian_constraints;
    ScratchData<dim>                 s(mapping, dof_handler.get_fe());
    const unsigned int               n = s.u_dofs.size();
    position_dofs                      = s.u_dofs;
    std::vector<types::global_dof_index> dofs(
      dof_handler.get_fe().n_dofs_per_cell());
    std::vector<unsigned int> cell(n * n);
    for (std::size_t c = 0; c < nonlinear_cells.size(); ++c)
      {
        nonlinear_cells[c]->get_dof_indices(dofs);
        bool complete = true;
        for (unsigned int i = 0; i < n && complete; ++i)
          {
            const auto row = dofs[s.u_dofs[i]];
            complete       = !constraints.is_constrained(row);
            for (unsigned int j = 0; j < n && complete; ++j)
              {
                const long long p = position(row, dofs[s.u_dofs[j]]);
                complete          = p >= 0;
                cell[i * n + j]   = p;
              }
          }
        if (complete)
          {
            first_position[c] = cell_positions.size();
            cell_positions.insert(cell_positions.end(),
                                  cell.begin(),
                                  cell.end());
          }
      }

    const Epetra_CrsMatrix &C = constant_jacobian.trilinos_matrix();
    // its values are read in storage order
    int    *c_start, *c_columns;
    double *c_values;
    if (C.ExtractCrsDataPointers(c_start, c_columns, c_values) != 0)
      return;
    for (int r = 0; r < C.NumMyRows(); ++r)
      {
        int     length;
        double *unused;
        int    *local_columns;
        C.ExtractMyRowView(r, length, unused, local_columns);
        for (int k = 0; k < length; ++k)
          {
            const long long p =
              position(C.RowMap().GID(r), C.ColMap().GID(local_columns[k]));
            if (p < 0)
              {
                constant_positions.clear();
                return;
              }
            constant_positions.push_back(p);
          }
      }
  }

  template <int dim>
  bool
  SolidMechanics<dim>::positions_fit(const MatrixType &jacobian) const
  {
    const Epetra_CrsMatrix &J = jacobian.trilinos_matrix();
    int                    *unused_start, *unused_columns;
    double                 *values = nullptr;
    J.ExtractCrsDataPointers(unused_start, unused_columns, values);
    return positions_found && positions_matrix == &J &&
           positions_values == values &&
           positions_nonzeros == J.NumMyNonzeros();
  }

  template <int dim>
  void
  SolidMechanics<dim>::setup(const AffineConstraints<double> &constraints)
  {
    jacobian_constraints = &constraints;
    // (their own constraints: those of the increments have dropped the
    // held parents, which must get their share for the reactions)
    hanging_rows.clear();
    {
      AffineConstraints<double> hanging;
      DoFTools::make_hanging_node_constraints(dof_handler, hanging);
      hanging.close();
      for (const auto &line : hanging.get_lines())
        if (dof_handler.locally_owned_dofs().is_element(line.index))
          hanging_rows.emplace_back(line.index, line.entries);
    }
    any_hanging_rows = Utilities::MPI::max(unsigned(!hanging_rows.empty()),
                                           dof_handler.get_communicator()) > 0;
    owned_cells.clear();
    nonlinear_cells.clear();
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          owned_cells.push_back(cell);
          if (!materials[cell->material_id()]->is_linear())
            nonlinear_cells.push_back(cell);
        }

    const MPI_Comm  comm          = dof_handler.get_communicator();
    const IndexSet &locally_owned = dof_handler.locally_owned_dofs();
    IndexSet        locally_relevant;
    DoFTools::extract_locally_relevant_dofs(dof_handler, locally_relevant);
    const auto pattern = [&](const AffineConstraints<double> &c) {
      DynamicSparsityPattern dsp(locally_relevant);
      make_sparsity_pattern(c, dsp);
      SparsityTools::distribute_sparsity_pattern(dsp,
                                                 locally_owned,
                                                 comm,
                                                 locally_relevant);
      return dsp;
    };

    AffineConstraints<double> none;
    none.close();
    const DynamicSparsityPattern full = pattern(none);
    mass.reinit(locally_owned, locally_owned, full, comm);
    damping.reinit(mass);
    assemble_constant_matrix(1, 0, 0, none, mass);
    assemble_constant_matrix(0, 1, 0, none, damping);
    if (has_linear_cells)
      {
        linear_stiffness.reinit(mass);
        assemble_constant_matrix(0, 0, 1, none, linear_stiffness);
      }
    constant_jacobian.reinit(locally_owned,
                             locally_owned,
                             pattern(constraints),
                             comm);
    constant_jacobian_c_a = constant_jacobian_c_v = -1;

    body_force_vector.reinit(locally_owned, comm);
    for (VectorType &v : scratch)
      v.reinit(locally_owned, comm);
    ScratchData<dim> s(mapping, dof_handler.get_fe());
    CopyData<dim>    copy(dof_handler.get_fe().n_dofs_per_cell());
    for (const auto &cell : owned_cells)
      {
        s.reinit(cell);
        cell->get_dof_indices(copy.dofs);
        const auto &b = bodies[cell->material_id()].body_force;
        copy.rhs      = 0;
        for (unsigned int q = 0; q < s.quadrature.size(); ++q)
          for (unsigned int k = 0; k < s.u_dofs.size(); ++k)
            copy.rhs(s.u_dofs[k]) += b[s.component[k]] *
                                     s.fe_values.shape_value(s.node[k], q) *
                                     s.JxW(q);
        body_force_vector.add(copy.dofs, copy.rhs);
      }
    body_force_vector.compress(VectorOperation::add);

    // the nonlinear cells' shape gradients, for every Newton iteration
    const unsigned int n_q = s.quadrature.size(), n_nodes = s.n_nodes;
    nonlinear_gradients.resize(nonlinear_cells.size() * n_q * n_nodes);
    nonlinear_JxW.resize(nonlinear_cells.size() * n_q);
    for (std::size_t c = 0; c < nonlinear_cells.size(); ++c)
      {
        s.reinit(nonlinear_cells[c]);
        std::copy(s.cell_gradients.begin(),
                  s.cell_gradients.end(),
                  nonlinear_gradients.begin() + c * n_q * n_nodes);
        std::copy(s.cell_JxW.begin(),
                  s.cell_JxW.end(),
                  nonlinear_JxW.begin() + c * n_q);
      }
  }

  template <int dim>
  void
  SolidMechanics<dim>::assemble_constant_matrix(
    const double                     factor_m,
    const double                     factor_c,
    const double                     factor_k,
    const AffineConstraints<double> &constraints,
    MatrixType                      &matrix,
    VectorType                      *rhs) const
  {
    // a linear material's tangent is its constant elasticity tensor
    std::vector<Tensor<4, dim>> linear_tangent(materials.size());
    for (unsigned int b = 0; b < materials.size(); ++b)
      if (materials[b]->is_linear())
        {
          Tensor<2, dim> stress;
          double         W;
          materials[b]->evaluate(Tensor<2, dim>(),
                                 stress,
                                 linear_tangent[b],
                                 W);
        }

    matrix = 0;
    if (rhs)
      *rhs = 0;
    const auto worker =
      [&](const auto &it, ScratchData<dim> &s, CopyData<dim> &copy) {
        const CellIterator &cell = *it;
        s.reinit(cell);
        const types::material_id  id = cell->material_id();
        const MaterialParameters &p  = bodies[id].material;
        const double              m =
          p.density * (factor_m + factor_c * p.rayleigh_mass_coefficient);
        const double c = factor_c * p.rayleigh_stiffness_coefficient;
        const double k = materials[id]->is_linear() ? factor_k : 0.;
        copy.matrix    = 0;
        for (unsigned int q = 0; q < s.quadrature.size(); ++q)
          {
            const double JxW = s.JxW(q);
            if (m != 0)
              add_mass(m * JxW, q, s, copy.matrix);
            if (c != 0)
              add_stiffness(materials[id]->reference_elasticity(),
                            c * JxW,
                            q,
                            s,
                            copy.matrix);
            if (k != 0)
              add_stiffness(linear_tangent[id], k * JxW, q, s, copy.matrix);
          }
        mirror_upper_triangle(s, copy.matrix);
      };
    const auto copier = [&](const CopyData<dim> &copy) {
      if (rhs)
        constraints.distribute_local_to_global(copy.matrix,
                                               copy.zero,
                                               copy.dofs,
                                               matrix,
                                               *rhs,
                                               true);
      else
        constraints.distribute_local_to_global(copy.matrix, copy.dofs, matrix);
    };
    run_on_cells(owned_cells, worker, copier, mapping, dof_handler.get_fe());
    matrix.compress(VectorOperation::add);
    if (rhs)
      rhs->compress(VectorOperation::add);
  }

  template <int dim>
  double
  SolidMechanics<dim>::assemble_nonlinear(
    const VectorType                &u,
    const AffineConstraints<double> &constraints,
    VectorType                      *force,
    MatrixType                      *tangent) const
  {
    double             energy = 0;
    const unsigned int n_q =
      nonlinear_JxW.size() / std::max<std::size_t>(nonlinear_cells.size(), 1);
    const auto worker = [&](const auto       &it,
                            ScratchData<dim> &s,
                            CopyData<dim>    &copy) {
      const CellIterator &cell = *it;
      const std::size_t   c    = it - nonlinear_cells.begin();
      copy.cell                = c;
      s.reinit(&nonlinear_gradients[c * n_q * s.n_nodes],
               &nonlinear_JxW[c * n_q]);
      const Material<dim> &material = *materials[cell->material_id()];
      const unsigned int   n        = s.u_dofs.size();
      copy.energy                   = 0;
      copy.rhs                      = 0;
      if (tangent)
        copy.matrix = 0;
      for (unsigned int k = 0; k < n; ++k)
        s.u_local[k] = u(copy.dofs[s.u_dofs[k]]);
      Tensor<2, dim> P;
      Tensor<4, dim> A;
      double         W;
      for (unsigned int q = 0; q < s.quadrature.size(); ++q)
        {
          Tensor<2, dim> grad_u;
          for (unsigned int k = 0; k < n; ++k)
            grad_u[s.component[k]] += s.u_local[k] * s.grad(k, q);
          material.evaluate(grad_u, P, A, W);
          const double JxW = s.JxW(q);
          copy.energy += W * JxW;
          if (force)
            for (unsigned int k = 0; k < n; ++k)
              copy.rhs(s.u_dofs[k]) += (P[s.component[k]] * s.grad(k, q)) * JxW;
          if (tangent)
            add_stiffness(A, JxW, q, s, copy.matrix);
        }
      if (tangent)
        mirror_upper_triangle(s, copy.matrix);
    };
    // the cells' positions in the Jacobian's values, if found
    double *values = nullptr;
    if (tangent && !cell_positions.empty() && positions_fit(*tangent))
      {
        int *unused_start, *unused_columns;
        tangent->trilinos_matrix().ExtractCrsDataPointers(unused_start,
                                                          unused_columns,
                                                          values);
      }
    const auto copier = [&](const CopyData<dim> &copy) {
      energy += copy.energy;
      if (force)
        force->add(copy.dofs, copy.rhs);
      if (!tangent)
        return;
      if (values != nullptr && first_position[copy.cell] != none)
        {
          const unsigned int *p = &cell_positions[first_position[copy.cell]];
          for (const unsigned int i : position_dofs)
            for (const unsigned int j : position_dofs)
              values[*p++] += copy.matrix(i, j);
        }
      else
        constraints.distribute_local_to_global(copy.matrix,
                                               copy.dofs,
                                               *tangent);
    };
    run_on_cells(nonlinear_cells,
                 worker,
                 copier,
                 mapping,
                 dof_handler.get_fe());
    return energy;
  }

  template <int dim>
  const VectorType &
  SolidMechanics<dim>::owned(const VectorType &x, VectorType &copy) const
  {
    if (!x.has_ghost_elements())
      return x;
    copy = x;
    return copy;
  }

  template <int dim>
  void
  SolidMechanics<dim>::assemble(const VectorType                &u,
                                const VectorType                &v,
                                const VectorType                &a,
                                const double                     c_a,
                                const double                     c_v,
                                const AffineConstraints<double> &constraints,
                                const bool                       with_jacobian,
                                VectorType                      &residual,
                                MatrixType                      &jacobian,
                                VectorType &residual_full) const
  {
    // quasi-statics (c_a = 0) has neither inertia nor damping
    const bool dynamic = (c_a > 0);
    residual_full      = 0;
    if (with_jacobian)
      {
        Assert(&constraints == jacobian_constraints,
               ExcMessage("The Jacobian's constraints are those of setup()."));
        const double m = dynamic ? c_a : 0., c = dynamic ? c_v : 0.;
        if (m != constant_jacobian_c_a || c != constant_jacobian_c_v)
          {
            assemble_constant_matrix(m, c, 1, constraints, constant_jacobian);
            constant_jacobian_c_a = m;
            constant_jacobian_c_v = c;
          }
        if (!positions_fit(jacobian))
          find_positions(jacobian);
        jacobian = 0;
        if (constant_positions.empty())
          jacobian.add(1., constant_jacobian);
        else
          {
            int    *unused_start, *unused_columns;
            double *values, *constant_values;
            jacobian.trilinos_matrix().ExtractCrsDataPointers(unused_start,
                                                              unused_columns,
                                                              values);
            constant_jacobian.trilinos_matrix().ExtractCrsDataPointers(
              unused_start,
              unused_columns,
              constant_values);
            for (std::size_t k = 0; k < constant_positions.size(); ++k)
              values[constant_positions[k]] += constant_values[k];
          }
      }

    // an inverted element throws on its process only
    run_collectively(
      residual.get_mpi_communicator(),
      [&]() {
        assemble_nonlinear(u,
                           constraints,
                           &residual_full,
                           with_jacobian ? &jacobian : nullptr);
      },
      [&]() {
        residual_full.compress(VectorOperation::add);
        if (with_jacobian)
          jacobian.compress(VectorOperation::add);
      });

    // the state-independent part: matrix-vector products
    residual_full -= body_force_vector;
    VectorType &product = scratch[2];
    if (dynamic)
      {
        mass.vmult(product, owned(a, scratch[0]));
        residual_full += product;
        damping.vmult(product, owned(v, scratch[0]));
        residual_full += product;
      }
    if (has_linear_cells)
      {
        linear_stiffness.vmult(product, owned(u, scratch[0]));
        residual_full += product;
      }
    // the rows of hanging nodes go to the rows they follow, held ones too
    // (their reactions); then the rows of the held and hanging degrees of
    // freedom are dropped
    move_hanging_rows(residual_full, residual);
    residual = residual_full;
    constraints.set_zero(residual);
  }

  template <int dim>
  void
  SolidMechanics<dim>::move_hanging_rows(VectorType &full,
                                         VectorType &copy) const
  {
    if (!any_hanging_rows)
      return;
    copy = full;
    for (const auto &row : hanging_rows)
      {
        for (const auto &entry : row.second)
          full.add(std::vector<types::global_dof_index>{entry.first},
                   std::vector<double>{entry.second * copy(row.first)});
        full.add(std::vector<types::global_dof_index>{row.first},
                 std::vector<double>{-copy(row.first)});
      }
    full.compress(VectorOperation::add);
  }

  template class SolidMechanics<2>;
  template class SolidMechanics<3>;
} // namespace ContactDynamics
