#include <deal.II/base/conditional_ostream.h>

#include <contact_dynamics/mechanics/energy_watchdog.h>
#include <contact_dynamics/parallel.h>
#include <contact_dynamics/parameters.h>

#include <algorithm>
#include <cmath>

namespace ContactDynamics
{
  using namespace dealii;

  void
  EnergyWatchdog::declare_parameters(ParameterHandler &prm)
  {
    const EnergyWatchdog defaults;
    prm.declare_entry(
      "Fraction",
      default_text(defaults.limit),
      Patterns::Double(0, 1e6),
      "A committed step whose energy balance error grows by more than "
      "this fraction of the run's energy scale (the largest of kinetic "
      "plus elastic energy, external and obstacle work, initial and "
      "dissipated energy) created that energy from nothing: a warning on "
      "the screen names the step and the amount (0: no check). Every "
      "step's fraction is the statistics column energy_created. The "
      "default 0.1 passes every shipped benchmark with the paper's damping "
      "(at most 5.4 %: the ironing's first contacts without "
      "stabilization; 1e-6 with persistency) and flags the shipped "
      "undamped variants (the bouncing blocks 27 %, where the contact work "
      "of the held nodes swings up at impact; the ironing 10.1 %), an "
      "impulsive obstacle start (31 %) and impacts shorter than a time "
      "step (doc/extreme-cases.md). A mesh change that raises kinetic "
      "plus elastic energy by more than this fraction warns likewise, at "
      "the mesh change. Costs nothing.");
    prm.declare_entry("Action",
                      defaults.stop ? "stop" : "warn",
                      Patterns::Selection("warn|stop"),
                      "warn: the run goes on; stop: the run stops after the "
                      "step's outputs, with the warning as its error.");
  }

  void
  EnergyWatchdog::parse_parameters(ParameterHandler &prm)
  {
    limit = prm.get_double("Fraction");
    stop  = prm.get("Action") == "stop";
  }

  void
  EnergyWatchdog::reset(const EnergyBalance &balance)
  {
    last_error = balance.error();
  }

  double
  EnergyWatchdog::created_fraction(const EnergyBalance &balance)
  {
    const double created = balance.error() - last_error;
    last_error           = balance.error();
    const double scale   = energy_scale(balance);
    return created > 0 && scale > 0 ? created / scale : 0.;
  }

  double
  EnergyWatchdog::energy_scale(const EnergyBalance &balance)
  {
    return std::max(
      {balance.kinetic + balance.elastic,
       std::abs(balance.external),
       std::abs(balance.obstacle),
       balance.initial,
       balance.dissipated + balance.frictional + balance.numerical});
  }

  std::string
  EnergyWatchdog::mesh_change_warning(const EnergyBalance &balance,
                                      const double         created,
                                      const double         time) const
  {
    const double scale    = energy_scale(balance);
    const double fraction = created > 0 && scale > 0 ? created / scale : 0.;
    if (limit == 0 || !(fraction > limit))
      return "";
    return "Energy watchdog: the mesh change at t = " + format_number(time) +
           " created " + format_number(100 * fraction) +
           " % of the run's energy scale (Energy watchdog/Fraction = " +
           format_number(limit) +
           ") in the transfer of the state to the new mesh (the statistics "
           "column transfer_energy sums these changes); typical cause: coarsening where the "
           "strain or the velocity still varies. Mesh refinement/Coarsen = "
           "false, more Buffer cells or a larger Interval keep it down "
           "(doc/refinement.md).";
  }

  std::string
  EnergyWatchdog::warning(const double fraction, const unsigned int step) const
  {
    if (limit == 0 || !(fraction > limit))
      return "";
    return "Energy watchdog: step " + std::to_string(step) + " created " +
           format_number(100 * fraction) +
           " % of the run's energy scale (Energy watchdog/Fraction = " +
           format_number(limit) +
           "); typical causes: an impact or an obstacle start faster than the time "
           "step resolves, or contact without stabilization. A smaller Time "
           "step, or Stabilization = velocity update (it returns the step's "
           "contact work), removes it (doc/extreme-cases.md).";
  }

  void
  EnergyWatchdog::act(const std::string        &warning,
                      const unsigned int        step,
                      const ConditionalOStream &out) const
  {
    // (the same on every process: one message)
    AssertThrow(warning.empty() || !stop,
                ExcCollective(warning +
                              " The run stops (Energy watchdog/Action "
                              "= stop) at step " +
                              std::to_string(step) +
                              "; what was written before is complete."));
    if (!warning.empty())
      out << "Warning: " << warning << std::endl;
  }
} // namespace ContactDynamics
