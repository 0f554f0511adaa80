// A check of every committed step against energy created from nothing: the
// growth of the energy balance error in the step (what contact, an
// impulsive obstacle or an under-resolved impact create; a dissipative step
// lowers it) as a fraction of the energy scale of the run.
#ifndef contact_dynamics_mechanics_energy_watchdog_h
#define contact_dynamics_mechanics_energy_watchdog_h

#include <deal.II/base/parameter_handler.h>

#include <contact_dynamics/mechanics/energy_balance.h>

#include <string>

namespace dealii
{
  class ConditionalOStream;
}

namespace ContactDynamics
{
  using dealii::ParameterHandler;

  /**
   * `subsection Energy watchdog`. Holds the balance error of the last
   * committed step only (set again from the state a restart or a mesh
   * change leaves: nothing to save).
   */
  class EnergyWatchdog
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    /** The committed balance a step starts from (t = 0, a restart). */
    void
    reset(const EnergyBalance &balance);

    /**
     * The energy the committed step that led to `balance` created, as a
     * fraction of the energy scale (the largest of kinetic plus elastic
     * energy, the external and obstacle work, the initial energy and the
     * dissipated energy), or 0 if it created none.
     */
    double
    created_fraction(const EnergyBalance &balance);

    /** The message for a step above the Fraction, or "". */
    std::string
    warning(const double fraction, const unsigned int step) const;

    /**
     * The message for a mesh change at `time` that created the energy
     * `created` (the transfer's change of kinetic plus elastic energy) above
     * the Fraction of the energy scale of `balance`, or "". (Judged at the
     * mesh change: the balance error, which the steps are judged by, counts
     * the transfer as a source; so a restart from a checkpoint written
     * after the change judges the same steps.)
     */
    std::string
    mesh_change_warning(const EnergyBalance &balance,
                        const double         created,
                        const double         time) const;

    /**
     * A warning (if not "") stops the run after `step` (Action = stop,
     * collectively) or goes to `out`.
     */
    void
    act(const std::string                &warning,
        const unsigned int                step,
        const dealii::ConditionalOStream &out) const;

  private:
    // the largest of the energies of the run (created_fraction())
    static double
    energy_scale(const EnergyBalance &balance);

    double limit      = 0.1;
    bool   stop       = false;
    double last_error = 0;
  };
} // namespace ContactDynamics

#endif
