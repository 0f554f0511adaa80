#include <deal.II/base/mpi.h>

#include <contact_dynamics/contact/contact_work.h>
#include <contact_dynamics/output/checkpoint.h>

namespace ContactDynamics
{
  void
  ContactWork::reinit(const IndexSet                             &owned_dofs,
                      const MPI_Comm                              comm,
                      const std::vector<types::global_dof_index> &dofs,
                      const bool                                  friction)
  {
    this->comm       = comm;
    this->owned_dofs = owned_dofs;
    this->dofs       = dofs;
    this->friction   = friction;
    for (auto *v : {&force,
                    &force_committed,
                    &friction_force,
                    &friction_force_committed,
                    &mean_normal_force})
      v->reinit(owned_dofs, comm);
    last_normal_work = 0;
  }

  void
  ContactWork::start_assembly()
  {
    force          = 0;
    friction_force = 0;
  }

  void
  ContactWork::compress()
  {
    force.compress(VectorOperation::add);
    friction_force.compress(VectorOperation::add);
  }

  void
  ContactWork::commit(const TrilinosWrappers::MPI::Vector &u,
                      const TrilinosWrappers::MPI::Vector &old_u)
  {
    double work = 0, friction_work = 0;
    for (const auto i : dofs)
      if (owned_dofs.is_element(i))
        {
          const double du = u(i) - old_u(i);
          work -= du * 0.5 * (force(i) + force_committed(i));
          if (friction)
            friction_work -=
              du * 0.5 * (friction_force(i) + friction_force_committed(i));
        }
    double sums[2] = {work, friction_work};
    Utilities::MPI::sum(ArrayView<const double>(sums, 2),
                        comm,
                        ArrayView<double>(sums, 2));
    contact_work += sums[0];
    last_normal_work  = sums[0] - sums[1];
    mean_normal_force = force;
    mean_normal_force += force_committed;
    if (friction)
      {
        mean_normal_force -= friction_force;
        mean_normal_force -= friction_force_committed;
      }
    mean_normal_force *= 0.5;
    if (friction)
      {
        frictional_dissipation -= sums[1];
        friction_force_committed = friction_force;
      }
    force_committed = force;
  }

  void
  ContactWork::save(CheckpointData &data, const ContactHistoryContext &) const
  {
    data.set("contact/work", {contact_work, frictional_dissipation});
  }

  void
  ContactWork::load(const CheckpointData &data, const ContactHistoryContext &)
  {
    const auto &totals     = data.get("contact/work", 2);
    contact_work           = totals[0];
    frictional_dissipation = totals[1];
  }
} // namespace ContactDynamics
