// The energy account of a run: every term of the discrete energy balance
// is computed and kept here (doc/theory.md).
#ifndef contact_dynamics_mechanics_energy_account_h
#define contact_dynamics_mechanics_energy_account_h

#include <deal.II/base/index_set.h>

#include <deal.II/lac/affine_constraints.h>

#include <contact_dynamics/mechanics/body_state.h>
#include <contact_dynamics/mechanics/energy_balance.h>
#include <contact_dynamics/mechanics/solid_mechanics.h>
#include <contact_dynamics/mechanics/time_integrator.h>

#include <string>

namespace ContactDynamics
{
  /**
   * The energies of the committed state and of the trial step: at t = 0,
   * over a converged step (bulk terms trapezoidal in time, then the
   * contact's totals, the velocity update and the numerical dissipation),
   * and over a mesh change. The checkpoint entry "energies".
   */
  template <int dim>
  class EnergyAccount : public HistoryOwner<RunContext>
  {
  public:
    explicit EnergyAccount(const TimeIntegrator &integrator);

    std::string
    name() const override
    {
      return "energies";
    }

    /** Those of the committed state. */
    const EnergyBalance &
    balance() const
    {
      return committed;
    }

    /** At t = 0: the initial state (`u_ghost` ghosted) and nothing else. */
    void
    start(const SolidMechanics<dim> &mechanics,
          const VectorType          &v,
          const VectorType          &u_ghost);

    /**
     * The bulk terms of the converged trial step of `state` (`u_ghost`: its
     * displacement, ghosted; `held_dofs`: where the supports do work;
     * `increment` receives u_{n+1} - u_n), and the contact work so far
     * (`contact_work`, for the numerical dissipation). Returns why the
     * energies are not finite numbers, or "". Collective.
     */
    std::string
    evaluate_step(const SolidMechanics<dim>       &mechanics,
                  const BodyState                 &state,
                  const VectorType                &u_ghost,
                  const AffineConstraints<double> &constraints,
                  const IndexSet                  &held_dofs,
                  const VectorType                &body_force,
                  const double                     dt,
                  const double                     contact_work,
                  VectorType                      &increment);

    /**
     * The contact part of the trial step once the contact committed it:
     * the kinetic energy the velocity update added, the totals of friction
     * and obstacle work, and the contact work so far.
     */
    void
    add_contact(const double velocity_update,
                const double frictional,
                const double obstacle,
                const double contact_work);

    /** The trial step's energies become the committed ones. */
    void
    commit(const RunContext &) override;

    /** Before a mesh change: kinetic + elastic energy. */
    double
    before_mesh_change() const;

    /**
     * After it, at the transferred state (`u_ghost` ghosted): the energies
     * again, their change to the transfer account; kinetic + elastic.
     */
    double
    after_mesh_change(const SolidMechanics<dim> &mechanics,
                      const VectorType          &v,
                      const VectorType          &u_ghost,
                      const double               before);

    void
    save(CheckpointData &data, const RunContext &) const override;

    /** (8 values: written before the numerical dissipation was counted) */
    void
    load(const CheckpointData &data, const RunContext &context) override;

  private:
    const TimeIntegrator &integrator;
    EnergyBalance         committed, trial;
    // the bulk's account and the contact work before the trial step, for
    // the numerical dissipation
    double bulk_before = 0, contact_work_before = 0, contact_work_after = 0;
  };
} // namespace ContactDynamics

#endif
