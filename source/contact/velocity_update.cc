// The stabilization "velocity update" (doc/contact.md).
#include <deal.II/base/mpi.h>

#include <contact_dynamics/contact/velocity_update.h>

#include <cmath>
#include <vector>

namespace ContactDynamics
{
  template <int dim>
  double
  apply_velocity_update(ContactFormulation<dim>   &contact,
                        const SolidMechanics<dim> &mechanics,
                        const DoFHandler<dim>     &dof_handler,
                        const IndexSet            &held_dofs,
                        const unsigned int         n_bodies,
                        const double               work,
                        VectorType                &v_new)
  {
    const VectorType *force         = contact.velocity_update_force();
    const IndexSet   &locally_owned = dof_handler.locally_owned_dofs();
    // the bodies the step's contact impulse acted on: only their free
    // velocities change
    std::vector<double>                  touched(n_bodies, 0.);
    std::vector<types::global_dof_index> cell_dofs(
      dof_handler.get_fe().n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(cell_dofs);
          for (const auto i : cell_dofs)
            if (locally_owned.is_element(i) && (*force)(i) != 0)
              touched[cell->material_id()] = 1;
        }
    Utilities::MPI::sum(touched, v_new.get_mpi_communicator(), touched);

    // A projection onto the energy the step should end with (after Hairer,
    // Lubich and Wanner, Geometric Numerical Integration, IV.4: along the
    // gradient of the kinetic energy, M^-1 M v = v): a factor 1 + s on the
    // free velocities of those bodies. It can remove all of their kinetic
    // energy; D^-1 M v (lumped metric) and the least-norm M_FF^-1 (M v)_F
    // were tried and could not (doc/contact.md)
    VectorType direction(v_new);
    for (const auto i : locally_owned)
      if (held_dofs.is_element(i))
        direction(i) = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && touched[cell->material_id()] == 0.)
        {
          cell->get_dof_indices(cell_dofs);
          for (const auto i : cell_dofs)
            if (locally_owned.is_element(i))
              direction(i) = 0;
        }
    direction.compress(VectorOperation::insert);

    // K(v + s w) = K(v) + s b + s^2 K(w) = K(v) - work: the root of
    // smaller size, or the largest removal (s = -1 when the prescribed
    // velocities do not couple) if the step created more than w carries
    const double k_w = mechanics.kinetic_energy(direction);
    if (!(k_w > 0))
      return 0;
    VectorType sum(v_new);
    sum += direction;
    const double k_v          = mechanics.kinetic_energy(v_new);
    const double b            = mechanics.kinetic_energy(sum) - k_v - k_w;
    const double discriminant = b * b - 4 * k_w * work;
    double       s            = -b / (2 * k_w);
    if (discriminant >= 0)
      {
        const double root = std::sqrt(discriminant);
        const double s1 = (-b + root) / (2 * k_w), s2 = (-b - root) / (2 * k_w);
        s = std::abs(s1) < std::abs(s2) ? s1 : s2;
      }
    v_new.add(s, direction);
    const double change = k_w * s * s + b * s;
    contact.add_velocity_update_work(change);
    return change;
  }

  template double
  apply_velocity_update(ContactFormulation<2> &,
                        const SolidMechanics<2> &,
                        const DoFHandler<2> &,
                        const IndexSet &,
                        const unsigned int,
                        const double,
                        VectorType &);
  template double
  apply_velocity_update(ContactFormulation<3> &,
                        const SolidMechanics<3> &,
                        const DoFHandler<3> &,
                        const IndexSet &,
                        const unsigned int,
                        const double,
                        VectorType &);
} // namespace ContactDynamics
