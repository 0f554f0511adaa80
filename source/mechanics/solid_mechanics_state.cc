// SolidMechanics: the quantities of a given state (inertia forces, the
// initial acceleration system, energies, inverted corners, strains beyond
// the small-strain range).
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <contact_dynamics/contact/coordinates.h>
#include <contact_dynamics/mechanics/solid_mechanics.h>

#include <limits>
#include <sstream>
#include <utility>

namespace ContactDynamics
{
  template <int dim>
  void
  SolidMechanics<dim>::inertia_force(const VectorType &a,
                                     const double      factor,
                                     VectorType       &force) const
  {
    mass.vmult(force, owned(a, scratch[0]));
    force *= factor;
    move_hanging_rows(force, scratch[2]);
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
    VectorType zero_a(body_force_vector), residual(body_force_vector),
      residual_full(body_force_vector);
    zero_a = 0;
    AffineConstraints<double> none;
    none.close();
    assemble(u,
             v,
             zero_a,
             1.,
             0.,
             none,
             false,
             residual,
             mass_matrix,
             residual_full);

    assemble_constant_matrix(1, 0, 0, constraints, mass_matrix, &rhs);
    // rhs -= residual at free dofs (constrained rows carry the prescribed
    // accelerations from distribute_local_to_global)
    for (const auto i : rhs.locally_owned_elements())
      if (!constraints.is_constrained(i))
        rhs(i) -= residual_full(i);
    rhs.compress(VectorOperation::insert);
  }

  template <int dim>
  double
  SolidMechanics<dim>::kinetic_energy(const VectorType &v) const
  {
    return 0.5 * mass.matrix_norm_square(owned(v, scratch[0]));
  }

  template <int dim>
  double
  SolidMechanics<dim>::elastic_energy(const VectorType &u) const
  {
    AffineConstraints<double> none;
    double                    energy =
      Utilities::MPI::sum(assemble_nonlinear(u, none, nullptr, nullptr),
                          u.get_mpi_communicator());
    if (has_linear_cells)
      energy += 0.5 * linear_stiffness.matrix_norm_square(owned(u, scratch[0]));
    return energy;
  }

  template <int dim>
  double
  SolidMechanics<dim>::damping_product(const VectorType &v1,
                                       const VectorType &v2) const
  {
    return damping.matrix_scalar_product(owned(v1, scratch[0]),
                                         owned(v2, scratch[1]));
  }

  template <int dim>
  std::string
  SolidMechanics<dim>::inverted_corner(const VectorType &u_ghost) const
  {
    // nodes of the trial state's neo-Hookean cells: the corners, and with
    // degree 2 the mid-edge, mid-face and centre nodes too
    double     smallest = std::numeric_limits<double>::max();
    Point<dim> where;
    const FEValuesExtractors::Vector displacement(0);
    FEValues<dim>                    fe_values(mapping,
                            dof_handler.get_fe(),
                            QIterated<dim>(QTrapezoid<1>(),
                                           dof_handler.get_fe().degree),
                            update_gradients | update_quadrature_points);
    std::vector<Tensor<2, dim>>      gradients(fe_values.n_quadrature_points);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() &&
          !material(cell->material_id()).is_linear())
        {
          fe_values.reinit(cell);
          fe_values[displacement].get_function_gradients(u_ghost, gradients);
          for (unsigned int q = 0; q < gradients.size(); ++q)
            {
              const double J =
                determinant(unit_symmetric_tensor<dim>() + gradients[q]);
              if (!(J >= smallest))
                {
                  smallest = J;
                  where    = fe_values.quadrature_point(q);
                }
            }
        }
    // the same answer on every process: the smallest over all
    const auto all =
      Utilities::MPI::all_gather(u_ghost.get_mpi_communicator(),
                                 std::make_pair(smallest, where));
    for (const auto &p : all)
      if (!(p.first >= smallest))
        {
          smallest = p.first;
          where    = p.second;
        }
    if (smallest > 0)
      return "";
    std::ostringstream message;
    message << "Inverted element: det F = " << smallest << " <= 0 at the "
            << (dof_handler.get_fe().degree == 1 ? "corner" : "node")
            << " (reference position " << where << ") of a neo-Hookean element";
    return message.str();
  }

  template <int dim>
  std::string
  SolidMechanics<dim>::small_strain_excess(const VectorType &u_ghost) const
  {
    // ((strain norm / limit, strain norm), (body, place)) of the worst
    std::pair<std::pair<double, double>, std::pair<unsigned int, Point<dim>>>
      worst{{0, 0}, {0, Point<dim>()}};
    if (has_linear_cells)
      {
        const FEValuesExtractors::Vector     displacement(0);
        FEValues<dim>                        fe_values(mapping,
                                dof_handler.get_fe(),
                                QMidpoint<dim>(),
                                update_gradients | update_quadrature_points);
        std::vector<SymmetricTensor<2, dim>> strain(1);
        for (const auto &cell : dof_handler.active_cell_iterators())
          {
            const unsigned int body  = cell->material_id();
            const double       limit = bodies[body].material.small_strain_limit;
            if (!cell->is_locally_owned() || !materials[body]->is_linear() ||
                limit == 0)
              continue;
            fe_values.reinit(cell);
            fe_values[displacement].get_function_symmetric_gradients(u_ghost,
                                                                     strain);
            const double norm = strain[0].norm();
            if (norm / limit > worst.first.first)
              worst = {{norm / limit, norm},
                       {body, fe_values.quadrature_point(0)}};
          }
      }
    // (ties: the lowest process's, the same on every process)
    const auto all =
      Utilities::MPI::all_gather(u_ghost.get_mpi_communicator(), worst);
    worst = all[0];
    for (const auto &w : all)
      if (w.first.first > worst.first.first)
        worst = w;
    const auto [ratio, norm] = worst.first;
    const auto [body, where] = worst.second;
    if (!(ratio > 1))
      return "";
    std::ostringstream message;
    message << "The linear elastic body '" << bodies[body].name
            << "' reaches a strain norm of " << norm << " near "
            << coordinates(where) << ", above its Small strain limit "
            << bodies[body].material.small_strain_limit
            << ": linear elasticity does not hold at such strains or "
               "rotations, so the stresses and the energies are not the "
               "physics'. Use 'Body "
            << bodies[body].name
            << "/Material model = neo-Hookean' (or raise the limit if small "
               "strains are not what you model).";
    return message.str();
  }

  template class SolidMechanics<2>;
  template class SolidMechanics<3>;
} // namespace ContactDynamics
