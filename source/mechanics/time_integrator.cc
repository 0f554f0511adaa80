#include <deal.II/base/exceptions.h>

#include <contact_dynamics/mechanics/time_integrator.h>

namespace ContactDynamics
{
  void
  TimeIntegrator::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Scheme",
                      "newmark",
                      Patterns::Selection("newmark|quasi-static"),
                      "'newmark': implicit dynamics with Newmark-beta. "
                      "'quasi-static': no inertia and no damping; time only "
                      "parametrizes the loading (cheaper: no mass matrix).");
    prm.declare_entry("Newmark beta",
                      "0.25",
                      Patterns::Double(1e-6, 0.5),
                      "Newmark beta in (0, 0.5]. 0.25 with gamma = 0.5 (the "
                      "trapezoidal rule) conserves the energy of a linear "
                      "undamped system; 2 beta >= gamma is required "
                      "(unconditional stability).");
    prm.declare_entry(
      "Predictor",
      "constant velocity",
      Patterns::Selection(
        "constant displacement|constant velocity|constant acceleration"),
      "Start of the Newton iteration of a step (Dirichlet values are always "
      "those of the new time): u_n, u_n + dt v_n, or u_n + dt v_n + dt^2/2 "
      "a_n. The last one saves Newton iterations in smooth motion but "
      "overshoots (and can invert elements) after an impulsive start or an "
      "impact, where the acceleration is large.");
    prm.declare_entry("Newmark gamma",
                      "0.5",
                      Patterns::Double(0.5, 1.),
                      "Newmark gamma in [0.5, 1]; gamma > 0.5 adds numerical "
                      "dissipation of first order in dt.");
  }

  void
  TimeIntegrator::parse_parameters(ParameterHandler &prm)
  {
    dynamic             = (prm.get("Scheme") == "newmark");
    beta_               = prm.get_double("Newmark beta");
    gamma_              = prm.get_double("Newmark gamma");
    const std::string p = prm.get("Predictor");
    predictor = (p == "constant displacement" ? Predictor::displacement :
                 p == "constant velocity"     ? Predictor::velocity :
                                                Predictor::acceleration);
    AssertThrow(!dynamic || 2 * beta_ >= gamma_ - 1e-12,
                ExcMessage(
                  "Time integration/Newmark beta = " + std::to_string(beta_) +
                  " with Newmark gamma = " + std::to_string(gamma_) +
                  " is only conditionally stable; this implicit code "
                  "requires 2 beta >= gamma >= 1/2."));
  }
} // namespace ContactDynamics
