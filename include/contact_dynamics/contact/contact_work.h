// The work of the contact forces on the bodies and its frictional part,
// trapezoidal in time: the forces of the trial state (the last assembly)
// and of the last committed step. It owns that history (history.h).
#ifndef contact_dynamics_contact_contact_work_h
#define contact_dynamics_contact_contact_work_h

#include <deal.II/base/index_set.h>

#include <deal.II/lac/trilinos_vector.h>

#include <contact_dynamics/contact/contact_history.h>

#include <string>
#include <vector>

namespace ContactDynamics
{
  using namespace dealii;

  class ContactWork : public ContactHistoryOwner
  {
  public:
    /**
     * No forces yet, on a new mesh. `dofs`: the displacement degrees of
     * freedom of the contact surfaces (in any order of processes, sorted).
     * The work and dissipation done so far are kept (on a mesh change they
     * carry over; a new object starts from none).
     */
    void
    reinit(const IndexSet                             &owned_dofs,
           const MPI_Comm                              comm,
           const std::vector<types::global_dof_index> &dofs,
           const bool                                  friction);

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

    std::string
    name() const override
    {
      return "contact work";
    }

    /** commit() of the converged state context.u from context.old_u. */
    void
    commit(const ContactHistoryContext &context) override
    {
      commit(*context.u, *context.old_u);
    }

    /** The work and the dissipation so far. */
    void
    save(CheckpointData &data, const ContactHistoryContext &) const override;
    void
    load(const CheckpointData &data, const ContactHistoryContext &) override;

    /** The forces of the last committed step. */
    void
    list_vectors(std::vector<TrilinosWrappers::MPI::Vector *> &vectors) override
    {
      vectors.insert(vectors.end(),
                     {&force_committed, &friction_force_committed});
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
