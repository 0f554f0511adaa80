// The stabilization "velocity update" of a converged step (doc/contact.md).
#ifndef contact_dynamics_contact_velocity_update_h
#define contact_dynamics_contact_velocity_update_h

#include <deal.II/base/index_set.h>

#include <deal.II/dofs/dof_handler.h>

#include <contact_dynamics/contact/contact_formulation.h>
#include <contact_dynamics/mechanics/solid_mechanics.h>

namespace ContactDynamics
{
  using namespace dealii;

  /**
   * After a converged step, one factor on the free velocities (not in
   * `held_dofs`) of the bodies the contact acted on returns the step's
   * normal contact work (the contact's velocity_update_request()) to
   * kinetic energy: `v_new` is changed and the change of the kinetic energy
   * is returned (and given to the contact's add_velocity_update_work()); 0
   * if nothing is requested. `n_bodies`: the material ids of the cells.
   * Collective.
   */
  template <int dim>
  double
  apply_velocity_update(ContactFormulation<dim>   &contact,
                        const SolidMechanics<dim> &mechanics,
                        const DoFHandler<dim>     &dof_handler,
                        const IndexSet            &held_dofs,
                        const unsigned int         n_bodies,
                        const double               work,
                        VectorType                &v_new);
} // namespace ContactDynamics

#endif
