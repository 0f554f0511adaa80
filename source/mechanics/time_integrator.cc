#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <contact_dynamics/mechanics/time_integrator.h>
#include <contact_dynamics/parameters.h>


namespace ContactDynamics
{
  namespace
  {
    const Selection<TimeIntegrator::Scheme> scheme_names{
      {TimeIntegrator::Scheme::newmark, "newmark"},
      {TimeIntegrator::Scheme::quasi_static, "quasi-static"}};

    const Selection<TimeIntegrator::Predictor> predictor_names{
      {TimeIntegrator::Predictor::displacement, "constant displacement"},
      {TimeIntegrator::Predictor::velocity, "constant velocity"},
      {TimeIntegrator::Predictor::acceleration, "constant acceleration"}};
  } // namespace

  void
  TimeIntegrator::declare_parameters(ParameterHandler &prm)
  {
    const TimeIntegrator defaults;
    prm.declare_entry("Scheme",
                      scheme_names.name(defaults.scheme),
                      scheme_names.pattern(),
                      "'newmark': implicit dynamics with Newmark-beta. "
                      "'quasi-static': no inertia and no damping; time only "
                      "parametrizes the loading (cheaper: no mass matrix).");
    prm.declare_entry("Newmark beta",
                      default_text(defaults.beta_),
                      Patterns::Double(1e-6, 0.5),
                      "Newmark beta in (0, 0.5]. 0.25 with gamma = 0.5 (the "
                      "trapezoidal rule) conserves the energy of a linear "
                      "undamped system; 2 beta >= gamma is required "
                      "(unconditional stability).");
    prm.declare_entry(
      "Predictor",
      predictor_names.name(defaults.predictor),
      predictor_names.pattern(),
      "Start of the Newton iteration of a step (Dirichlet values are always "
      "those of the new time): u_n, u_n + dt v_n, or u_n + dt v_n + dt^2/2 "
      "a_n. The last one saves Newton iterations in smooth motion but "
      "overshoots (and can invert elements) after an impulsive start or an "
      "impact, where the acceleration is large.");
    prm.declare_entry("Newmark gamma",
                      default_text(defaults.gamma_),
                      Patterns::Double(0.5, 1.),
                      "Newmark gamma in [0.5, 1]; gamma > 0.5 adds numerical "
                      "dissipation of first order in dt.");
    prm.declare_entry("Time step",
                      default_text(defaults.time_step_),
                      Patterns::Double(1e-300),
                      "Nominal time step (> 0). Steps are halved when a "
                      "Newton solve fails and grow back to this value.");
    prm.declare_entry("End time",
                      default_text(defaults.end_time_),
                      Patterns::Double(0),
                      "End time (>= 0).");
    prm.declare_entry(
      "Error tolerance",
      default_text(defaults.error_tolerance_),
      Patterns::Double(0),
      "Adaptive time steps (newmark): the largest local error estimate of "
      "a step, in units of length: max over the free displacement "
      "unknowns of |dt^2 (beta - 1/6) (a_{n+1} - a_n)| (Zienkiewicz and "
      "Xie), with a_{n+1} - a_n taken from the mean accelerations (v_{n+1} "
      "- v_n) / dt of this step and the one before (doc/theory.md). A step "
      "above it is solved again with a smaller dt, and each "
      "accepted step sets the next dt to 0.9 (tolerance / estimate)^(1/3) "
      "of its own (between 0.2 and 2 times), never above Time step and "
      "never below Minimum time step (a step at the minimum is accepted "
      "whatever its estimate). 0: no estimate; the step is only cut when "
      "a Newton solve fails, and grows back to Time step.");
    prm.declare_entry("Minimum time step",
                      default_text(defaults.minimum_time_step_),
                      Patterns::Double(1e-300),
                      "The run stops with an error when a failed step would "
                      "need a time step below this value (> 0).");
  }

  void
  TimeIntegrator::parse_parameters(ParameterHandler &prm)
  {
    scheme             = scheme_names.value(prm.get("Scheme"));
    beta_              = prm.get_double("Newmark beta");
    gamma_             = prm.get_double("Newmark gamma");
    predictor          = predictor_names.value(prm.get("Predictor"));
    time_step_         = prm.get_double("Time step");
    end_time_          = prm.get_double("End time");
    minimum_time_step_ = prm.get_double("Minimum time step");
    error_tolerance_   = prm.get_double("Error tolerance");
    AssertThrow(error_tolerance_ == 0 || is_dynamic(),
                ExcMessage("Time integration/Error tolerance = " +
                           format_number(error_tolerance_) +
                           " needs Scheme = newmark (a quasi-static run has "
                           "no acceleration to estimate the error from); "
                           "use 0."));
    AssertThrow(!is_dynamic() || 2 * beta_ >= gamma_ - 1e-12,
                ExcMessage(
                  "Time integration/Newmark beta = " + format_number(beta_) +
                  " with Newmark gamma = " + format_number(gamma_) +
                  " is only conditionally stable; this implicit code "
                  "requires 2 beta >= gamma >= 1/2."));
    AssertThrow(minimum_time_step_ <= time_step_,
                ExcMessage("Time integration/Minimum time step = " +
                           format_number(minimum_time_step_) +
                           " exceeds Time integration/Time step = " +
                           format_number(time_step_) + "."));
  }
} // namespace ContactDynamics
