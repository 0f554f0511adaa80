// The work of the contact forces on the bodies and its frictional part,
// trapezoidal in time: the forces of the trial state (the last assembly)
// and of the last committed step.
#ifndef contact_dynamics_contact_contact_work_h
#define contact_dynamics_contact_contact_work_h

#include <deal.II/base/index_set.h>

#include <deal.II/lac/trilinos_vector.h>

#include <vector>

namespace ContactDynamics
{
  using namespace dealii;

  class ContactWork
  {
  public:
    /**
     * No forces and no work yet. `dofs`: the displacement degrees of
     * freedom of the contact surfaces (in any order of processes, sorted).
     */
    void
    reinit(const IndexSet                             &owned_dofs,
           const MPI_Comm                              comm,
           const std::vector<types::global_dof_index> &dofs,
           const bool                                  friction);

    /**
     * After reinit() on a new mesh: the work and dissipation done on the
     * old one.
     */
    void
    carry_totals(const double work, const double dissipation)
    {
      contact_work           = work;
      frictional_dissipation = dissipation;
    }

    /** Before an assembly: the trial forces start from zero. */
    void
    start_assembly();

    /** A contact force on a degree of freedom, in the trial state. */
    void
    add_force(const types::global_dof_index row, const double value)
    {
      force(row) += value;
    }

    /** The friction part of a force added with add_force(). */
    void
    add_friction_force(const types::global_dof_index row, const double value)
    {
      friction_force(row) += value;
    }

    /** After an assembly: the forces of all processes are added up. */
    void
    compress();

    /** The contact forces of the last assembly. */
    const TrilinosWrappers::MPI::Vector &
    trial_force() const
    {
      return force;
    }

    /**
     * The step from `old_u` to `u` converged with the forces of the last
     * assembly: adds their work and they become the committed forces.
     */
    void
    commit(const TrilinosWrappers::MPI::Vector &u,
           const TrilinosWrappers::MPI::Vector &old_u);

    /** The work of the normal (frictionless) forces in the last step. */
    double
    normal_step_work() const
    {
      return last_normal_work;
    }

    /**
     * The mean normal (frictionless) contact force of the last committed
     * step, 1/2 (f_n + f_{n+1}) without the friction part, as the residual
     * carries it (minus the force on the bodies): the direction of the
     * trapezoidal rule's contact impulse.
     */
    const TrilinosWrappers::MPI::Vector &
    step_normal_force() const
    {
      return mean_normal_force;
    }

    /** Kinetic energy a velocity correction gave the bodies at contact. */
    void
    add_impulse_work(const double work)
    {
      contact_work += work;
      last_normal_work += work;
    }

    /** The forces of the last committed step (for a checkpoint). */
    std::vector<TrilinosWrappers::MPI::Vector *>
    committed_forces()
    {
      return {&force_committed, &friction_force_committed};
    }

    /** Work of the contact forces on the bodies so far. */
    double
    work() const
    {
      return contact_work;
    }

    /** Energy dissipated by friction so far. */
    double
    dissipation() const
    {
      return frictional_dissipation;
    }

  private:
    MPI_Comm                             comm = MPI_COMM_WORLD;
    IndexSet                             owned_dofs;
    std::vector<types::global_dof_index> dofs;
    bool                                 friction = false;
    // zero before the first step: the trapezoidal rule starts from no force
    TrilinosWrappers::MPI::Vector force, force_committed;
    TrilinosWrappers::MPI::Vector friction_force, friction_force_committed;
    TrilinosWrappers::MPI::Vector mean_normal_force;
    double                        contact_work           = 0;
    double                        frictional_dissipation = 0;
    double                        last_normal_work       = 0;
  };
} // namespace ContactDynamics

#endif
