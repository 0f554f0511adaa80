#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <contact_dynamics/mechanics/solid_mechanics.h>
#include <contact_dynamics/parallel.h>

namespace ContactDynamics
{
  namespace
  {
    // Evaluates the displacement-field quantities of one cell at all
    // quadrature points.
    template <int dim>
    struct CellFields
    {
      CellFields(const DoFHandler<dim> &dof_handler)
        : quadrature(dof_handler.get_fe().degree + 1)
        , fe_values(dof_handler.get_fe(),
                    quadrature,
                    update_values | update_gradients | update_JxW_values)
        , displacement(0)
        , dofs(dof_handler.get_fe().n_dofs_per_cell())
        , grad_u(quadrature.size())
        , grad_v(quadrature.size())
        , v(quadrature.size())
        , a(quadrature.size())
      {
        // only the displacement components carry mass and stiffness
        const auto &fe = dof_handler.get_fe();
        for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
          if (fe.system_to_component_index(i).first < dim)
            u_local.push_back(i);
      }

      void
      reinit(const typename DoFHandler<dim>::active_cell_iterator &cell)
      {
        fe_values.reinit(cell);
        cell->get_dof_indices(dofs);
      }

      QGauss<dim>                          quadrature;
      FEValues<dim>                        fe_values;
      const FEValuesExtractors::Vector     displacement;
      std::vector<types::global_dof_index> dofs;
      std::vector<unsigned int>            u_local;
      std::vector<Tensor<2, dim>>          grad_u, grad_v;
      std::vector<Tensor<1, dim>>          v, a;
    };

    template <int dim>
    Tensor<2, dim>
    symmetrize(const Tensor<2, dim> &t)
    {
      return 0.5 * (t + transpose(t));
    }
  } // namespace



  template <int dim>
  SolidMechanics<dim>::SolidMechanics(const DoFHandler<dim> &dof_handler,
                                      const std::vector<BodyParameters> &bodies)
    : dof_handler(dof_handler)
    , bodies(bodies)
  {
    for (const auto &b : bodies)
      materials.push_back(create_material<dim>(b.material));
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
    residual      = 0;
    residual_full = 0;
    if (with_jacobian)
      jacobian = 0;

    CellFields<dim>             f(dof_handler);
    const bool                  dynamic = (c_a > 0);
    const unsigned int          n       = f.dofs.size();
    FullMatrix<double>          cell_matrix(n, n);
    Vector<double>              cell_rhs(n);
    std::vector<Tensor<2, dim>> grad_phi(n);
    std::vector<Tensor<1, dim>> phi(n);
    std::vector<Tensor<2, dim>> tangent_grad_phi(n);

    // an inverted element throws on its process only
    const auto local = [&]() {
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            f.reinit(cell);
            const Material<dim>  &material = *materials[cell->material_id()];
            const BodyParameters &body     = bodies[cell->material_id()];
            const double          rho      = body.material.density;
            const double   alpha = body.material.rayleigh_mass_coefficient;
            const double   beta  = body.material.rayleigh_stiffness_coefficient;
            Tensor<1, dim> body_force;
            for (unsigned int d = 0; d < dim; ++d)
              body_force[d] = body.body_force[d];

            f.fe_values[f.displacement].get_function_gradients(u, f.grad_u);
            if (dynamic)
              {
                f.fe_values[f.displacement].get_function_values(v, f.v);
                f.fe_values[f.displacement].get_function_values(a, f.a);
                f.fe_values[f.displacement].get_function_gradients(v, f.grad_v);
              }
            cell_matrix = 0;
            cell_rhs    = 0;

            for (unsigned int q = 0; q < f.quadrature.size(); ++q)
              {
                Tensor<2, dim> stress;
                Tensor<4, dim> tangent;
                double         W;
                material.evaluate(f.grad_u[q], stress, tangent, W);
                Tensor<1, dim> inertia = -body_force;
                if (dynamic)
                  {
                    inertia += rho * (f.a[q] + alpha * f.v[q]);
                    if (beta > 0)
                      stress += beta * double_contract<2, 0, 3, 1>(
                                         material.reference_elasticity(),
                                         symmetrize(f.grad_v[q]));
                  }
                const double JxW = f.fe_values.JxW(q);
                for (const unsigned int i : f.u_local)
                  {
                    phi[i]      = f.fe_values[f.displacement].value(i, q);
                    grad_phi[i] = f.fe_values[f.displacement].gradient(i, q);
                    cell_rhs(i) +=
                      (inertia * phi[i] + scalar_product(stress, grad_phi[i])) *
                      JxW;
                  }
                if (!with_jacobian)
                  continue;

                if (dynamic && beta > 0)
                  tangent += (c_v * beta) * material.reference_elasticity();
                const double mass_factor =
                  dynamic ? rho * (c_a + alpha * c_v) : 0.;
                for (const unsigned int j : f.u_local)
                  tangent_grad_phi[j] =
                    double_contract<2, 0, 3, 1>(tangent, grad_phi[j]);
                for (const unsigned int i : f.u_local)
                  for (const unsigned int j : f.u_local)
                    cell_matrix(i, j) +=
                      (scalar_product(grad_phi[i], tangent_grad_phi[j]) +
                       mass_factor * (phi[i] * phi[j])) *
                      JxW;
              }

            residual_full.add(f.dofs, cell_rhs);
            if (with_jacobian)
              constraints.distribute_local_to_global(cell_matrix,
                                                     cell_rhs,
                                                     f.dofs,
                                                     jacobian,
                                                     residual);
            else
              constraints.distribute_local_to_global(cell_rhs,
                                                     f.dofs,
                                                     residual);
          }
    };
    run_collectively(residual.get_mpi_communicator(), local, [&]() {
      residual.compress(VectorOperation::add);
      residual_full.compress(VectorOperation::add);
      if (with_jacobian)
        jacobian.compress(VectorOperation::add);
    });
  }

  template <int dim>
  void
  SolidMechanics<dim>::assemble_initial_acceleration_system(
    const VectorType                &u,
    const VectorType                &v,
    const AffineConstraints<double> &constraints,
    MatrixType                      &mass_matrix,
    VectorType                      &rhs) const
  {
    // -(C v0 + f_int(u0) - f_body): the residual with zero acceleration
    VectorType zero_a(v), residual, residual_full;
    zero_a = 0;
    residual.reinit(rhs.locally_owned_elements(), rhs.get_mpi_communicator());
    residual_full.reinit(residual);
    assemble(u,
             v,
             zero_a,
             1.,
             0.,
             AffineConstraints<double>(),
             false,
             residual,
             mass_matrix,
             residual_full);

    mass_matrix = 0;
    rhs         = 0;
    CellFields<dim>    f(dof_handler);
    const unsigned int n = f.dofs.size();
    FullMatrix<double> cell_matrix(n, n);
    Vector<double>     cell_rhs(n);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          f.reinit(cell);
          const double rho = bodies[cell->material_id()].material.density;
          cell_matrix      = 0;
          for (unsigned int q = 0; q < f.quadrature.size(); ++q)
            for (const unsigned int i : f.u_local)
              for (const unsigned int j : f.u_local)
                cell_matrix(i, j) += rho *
                                     (f.fe_values[f.displacement].value(i, q) *
                                      f.fe_values[f.displacement].value(j, q)) *
                                     f.fe_values.JxW(q);
          for (unsigned int i = 0; i < n; ++i)
            cell_rhs(i) = 0;
          constraints.distribute_local_to_global(cell_matrix,
                                                 cell_rhs,
                                                 f.dofs,
                                                 mass_matrix,
                                                 rhs,
                                                 true);
        }
    mass_matrix.compress(VectorOperation::add);
    rhs.compress(VectorOperation::add);
    // rhs -= residual at free dofs (constrained rows carry the prescribed
    // accelerations from distribute_local_to_global)
    for (const auto i : rhs.locally_owned_elements())
      if (!constraints.is_constrained(i))
        rhs(i) -= residual_full(i);
    rhs.compress(VectorOperation::insert);
  }

  template <int dim>
  void
  SolidMechanics<dim>::assemble_body_force(VectorType &force) const
  {
    force = 0;
    CellFields<dim>    f(dof_handler);
    const unsigned int n = f.dofs.size();
    Vector<double>     cell_rhs(n);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          f.reinit(cell);
          const BodyParameters &body = bodies[cell->material_id()];
          Tensor<1, dim>        b;
          for (unsigned int d = 0; d < dim; ++d)
            b[d] = body.body_force[d];
          cell_rhs = 0;
          for (unsigned int q = 0; q < f.quadrature.size(); ++q)
            for (const unsigned int i : f.u_local)
              cell_rhs(i) += b * f.fe_values[f.displacement].value(i, q) *
                             f.fe_values.JxW(q);
          force.add(f.dofs, cell_rhs);
        }
    force.compress(VectorOperation::add);
  }

  template <int dim>
  double
  SolidMechanics<dim>::kinetic_energy(const VectorType &v) const
  {
    CellFields<dim> f(dof_handler);
    double          energy = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          f.reinit(cell);
          f.fe_values[f.displacement].get_function_values(v, f.v);
          const double rho = bodies[cell->material_id()].material.density;
          for (unsigned int q = 0; q < f.quadrature.size(); ++q)
            energy += 0.5 * rho * (f.v[q] * f.v[q]) * f.fe_values.JxW(q);
        }
    return Utilities::MPI::sum(energy, v.get_mpi_communicator());
  }

  template <int dim>
  double
  SolidMechanics<dim>::elastic_energy(const VectorType &u) const
  {
    CellFields<dim> f(dof_handler);
    double          energy = 0;
    Tensor<2, dim>  stress;
    Tensor<4, dim>  tangent;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          f.reinit(cell);
          f.fe_values[f.displacement].get_function_gradients(u, f.grad_u);
          const Material<dim> &material = *materials[cell->material_id()];
          for (unsigned int q = 0; q < f.quadrature.size(); ++q)
            {
              double W;
              material.evaluate(f.grad_u[q], stress, tangent, W);
              energy += W * f.fe_values.JxW(q);
            }
        }
    return Utilities::MPI::sum(energy, u.get_mpi_communicator());
  }

  template <int dim>
  double
  SolidMechanics<dim>::damping_product(const VectorType &v1,
                                       const VectorType &v2) const
  {
    CellFields<dim>             f(dof_handler);
    std::vector<Tensor<1, dim>> w(f.quadrature.size());
    std::vector<Tensor<2, dim>> grad_w(f.quadrature.size());
    double                      product = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const auto  &m     = bodies[cell->material_id()].material;
          const double alpha = m.rayleigh_mass_coefficient;
          const double beta  = m.rayleigh_stiffness_coefficient;
          if (alpha == 0 && beta == 0)
            continue;
          f.reinit(cell);
          f.fe_values[f.displacement].get_function_values(v1, f.v);
          f.fe_values[f.displacement].get_function_gradients(v1, f.grad_v);
          f.fe_values[f.displacement].get_function_values(v2, w);
          f.fe_values[f.displacement].get_function_gradients(v2, grad_w);
          const Tensor<4, dim> &C =
            materials[cell->material_id()]->reference_elasticity();
          for (unsigned int q = 0; q < f.quadrature.size(); ++q)
            product +=
              (alpha * m.density * (f.v[q] * w[q]) +
               beta *
                 scalar_product(
                   symmetrize(f.grad_v[q]),
                   double_contract<2, 0, 3, 1>(C, symmetrize(grad_w[q])))) *
              f.fe_values.JxW(q);
        }
    return Utilities::MPI::sum(product, v1.get_mpi_communicator());
  }

  template class SolidMechanics<2>;
  template class SolidMechanics<3>;
} // namespace ContactDynamics
