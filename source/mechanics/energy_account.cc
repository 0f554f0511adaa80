// The energy account of a run (doc/theory.md).
#include <deal.II/base/mpi.h>

#include <contact_dynamics/mechanics/energy_account.h>
#include <contact_dynamics/output/checkpoint.h>
#include <contact_dynamics/parameters.h>

#include <array>
#include <cmath>
#include <utility>

namespace ContactDynamics
{
  namespace
  {
    // the terms of the energy balance in the order of a checkpoint (a
    // checkpoint of an older version ends before `numerical`)
    std::array<double *, 9>
    energy_terms(EnergyBalance &e)
    {
      return {{&e.kinetic,
               &e.elastic,
               &e.dissipated,
               &e.external,
               &e.initial,
               &e.frictional,
               &e.obstacle,
               &e.transfer,
               &e.numerical}};
    }
  } // namespace

  template <int dim>
  EnergyAccount<dim>::EnergyAccount(const TimeIntegrator &integrator)
    : integrator(integrator)
  {}

  template <int dim>
  void
  EnergyAccount<dim>::start(const SolidMechanics<dim> &mechanics,
                            const VectorType          &v,
                            const VectorType          &u_ghost)
  {
    committed = EnergyBalance();
    committed.kinetic =
      integrator.is_dynamic() ? mechanics.kinetic_energy(v) : 0.;
    committed.elastic = mechanics.elastic_energy(u_ghost);
    committed.initial = committed.kinetic + committed.elastic;
  }

  template <int dim>
  std::string
  EnergyAccount<dim>::evaluate_step(
    const SolidMechanics<dim>       &mechanics,
    const BodyState                 &state,
    const VectorType                &u_ghost,
    const AffineConstraints<double> &constraints,
    const IndexSet                  &held_dofs,
    const VectorType                &body_force,
    const double                     dt,
    const double                     contact_work,
    VectorType                      &increment)
  {
    trial       = committed;
    bulk_before = committed.kinetic + committed.elastic + committed.dissipated -
                  committed.external;
    contact_work_before = contact_work;
    contact_work_after  = contact_work;

    VectorType mean_velocity(state.v);
    mean_velocity.sadd(0.5, 0.5, state.v_new);
    increment = state.u_new;
    increment -= state.u;
    trial.dissipated +=
      dt * mechanics.damping_product(mean_velocity, mean_velocity);
    const IndexSet locally_owned = state.u.locally_owned_elements();
    double         boundary_work = 0;
    for (const auto &line : constraints.get_lines())
      if (locally_owned.is_element(line.index) &&
          held_dofs.is_element(line.index))
        boundary_work += increment(line.index) * 0.5 *
                         (state.residual_full_old(line.index) +
                          state.residual_full(line.index));
    trial.external +=
      Utilities::MPI::sum(boundary_work, state.u.get_mpi_communicator()) +
      increment * body_force;
    trial.kinetic =
      integrator.is_dynamic() ? mechanics.kinetic_energy(state.v_new) : 0.;
    trial.elastic = mechanics.elastic_energy(u_ghost);
    if (std::isfinite(trial.error()))
      return "";
    std::vector<std::string> which;
    for (const auto &e :
         {std::make_pair(trial.kinetic, "kinetic"),
          std::make_pair(trial.elastic, "elastic"),
          std::make_pair(trial.dissipated, "damping dissipation"),
          std::make_pair(trial.external, "external work")})
      if (!std::isfinite(e.first))
        which.push_back(std::string(e.first != e.first ? "NaN " : "infinite ") +
                        e.second);
    return "the energies are not finite numbers (" + join(which, ", ") +
           "; the largest nodal body force is " +
           format_number(body_force.linfty_norm()) + ")";
  }

  template <int dim>
  void
  EnergyAccount<dim>::add_contact(const double velocity_update,
                                  const double frictional,
                                  const double obstacle,
                                  const double contact_work)
  {
    trial.kinetic += velocity_update;
    trial.frictional   = frictional;
    trial.obstacle     = obstacle;
    contact_work_after = contact_work;
  }

  template <int dim>
  void
  EnergyAccount<dim>::commit(const RunContext &)
  {
    // what the bulk lost beyond its physical account (damping, external
    // work, the work of the contact forces), all trapezoidal in time
    if (integrator.is_dissipative())
      trial.numerical += (contact_work_after - contact_work_before) -
                         (trial.kinetic + trial.elastic + trial.dissipated -
                          trial.external - bulk_before);
    committed = trial;
  }

  template <int dim>
  double
  EnergyAccount<dim>::before_mesh_change() const
  {
    return committed.kinetic + committed.elastic;
  }

  template <int dim>
  double
  EnergyAccount<dim>::after_mesh_change(const SolidMechanics<dim> &mechanics,
                                        const VectorType          &v,
                                        const VectorType          &u_ghost,
                                        const double               before)
  {
    committed.kinetic =
      integrator.is_dynamic() ? mechanics.kinetic_energy(v) : 0.;
    committed.elastic  = mechanics.elastic_energy(u_ghost);
    const double after = committed.kinetic + committed.elastic;
    committed.transfer += after - before;
    return after;
  }

  template <int dim>
  void
  EnergyAccount<dim>::save(CheckpointData &data, const RunContext &) const
  {
    EnergyBalance       copy = committed;
    std::vector<double> values;
    for (const double *e : energy_terms(copy))
      values.push_back(*e);
    data.set("energies", values);
  }

  template <int dim>
  void
  EnergyAccount<dim>::load(const CheckpointData &data,
                           const RunContext     &context)
  {
    // (8 values: written before the numerical dissipation was counted)
    const auto &e = data.get("energies", 0);
    AssertThrow(e.size() == 8 || e.size() == 9,
                ExcMessage("The checkpoint '" + context.checkpoint + "' has " +
                           std::to_string(e.size()) +
                           " energies where 8 or 9 are expected: it was "
                           "written by another version."));
    const auto terms = energy_terms(committed);
    for (unsigned int i = 0; i < terms.size(); ++i)
      *terms[i] = i < e.size() ? e[i] : 0.;
  }

  template class EnergyAccount<2>;
  template class EnergyAccount<3>;
} // namespace ContactDynamics
