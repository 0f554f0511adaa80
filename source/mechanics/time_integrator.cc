#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <contact_dynamics/mechanics/time_integrator.h>
#include <contact_dynamics/parameters.h>

#include <cmath>


namespace ContactDynamics
{
  namespace
  {
    const Selection<TimeIntegrator::Scheme> scheme_names{
      {TimeIntegrator::Scheme::newmark, "newmark"},
      {TimeIntegrator::Scheme::generalized_alpha, "generalized-alpha"},
      {TimeIntegrator::Scheme::hht_alpha, "hht-alpha"},
      {TimeIntegrator::Scheme::quasi_static, "quasi-static"}};

    // an optional number: empty or one value in [lower, upper]
    Patterns::List
    optional_number(const double lower, const double upper)
    {
      return Patterns::List(Patterns::Double(lower, upper), 0, 1);
    }

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
                      "'generalized-alpha' (Chung and Hulbert 1993) and "
                      "'hht-alpha' (Hilber, Hughes and Taylor 1977): "
                      "second-order accurate dynamics that damp the "
                      "frequencies the step does not resolve (set by the "
                      "Spectral radius at infinity) and hardly the resolved "
                      "ones, unlike Rayleigh damping; beta and gamma follow "
                      "from the alphas. 'quasi-static': no inertia and no "
                      "damping; time only parametrizes the loading (cheaper: "
                      "no mass matrix).");
    prm.declare_entry(
      "Spectral radius at infinity",
      default_text(defaults.spectral_radius_),
      Patterns::Double(0, 1),
      "generalized-alpha and hht-alpha: the amplification of a frequency "
      "far above 1/dt per step, rho_inf in [0, 1] (hht-alpha: [0.5, 1]). 1 "
      "dissipates nothing (generalized-alpha is then the trapezoidal rule "
      "between the steps), 0 annihilates the unresolved frequencies in one "
      "step; the resolved ones lose less the smaller omega dt is "
      "(doc/theory.md). Generalized-alpha: alpha_m = (2 rho_inf - 1) / "
      "(rho_inf + 1), alpha_f = rho_inf / (rho_inf + 1); hht-alpha: alpha_m "
      "= 0, alpha_f = (1 - rho_inf) / (1 + rho_inf); both: gamma = 1/2 - "
      "alpha_m + alpha_f, beta = (1 - alpha_m + alpha_f)^2 / 4.");
    prm.declare_entry(
      "Alpha m",
      "",
      optional_number(-1, 0.5),
      "generalized-alpha: the classical alpha_m, the weight of the old "
      "acceleration in the balance, in [-1, 1/2] and not above Alpha f; "
      "given with Alpha f, the two replace the Spectral radius at infinity. "
      "Empty: from the spectral radius. hht-alpha: empty or 0.");
    prm.declare_entry(
      "Alpha f",
      "",
      optional_number(0, 0.5),
      "generalized-alpha and hht-alpha: the classical alpha_f, the weight of "
      "the old forces in the balance, in [0, 1/2] (hht-alpha: [0, 1/3]; "
      "Hilber's alpha is -alpha_f); replaces the Spectral radius at "
      "infinity. Empty: from the spectral radius.");
    prm.declare_entry("Newmark beta",
                      default_text(defaults.beta_),
                      Patterns::Double(1e-6, 0.5),
                      "Newmark beta in (0, 0.5]. 0.25 with gamma = 0.5 (the "
                      "trapezoidal rule) conserves the energy of a linear "
                      "undamped system; 2 beta >= gamma is required "
                      "(unconditional stability). Scheme = newmark only.");
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
                      "dissipation of first order in dt (and the "
                      "numerical_dissipation column). Scheme = newmark "
                      "only.");
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
    const TimeIntegrator defaults;
    scheme           = scheme_names.value(prm.get("Scheme"));
    beta_            = prm.get_double("Newmark beta");
    gamma_           = prm.get_double("Newmark gamma");
    spectral_radius_ = prm.get_double("Spectral radius at infinity");
    parse_alphas(prm.get("Alpha m"), prm.get("Alpha f"), defaults);
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
    AssertThrow(error_tolerance_ == 0 || scheme == Scheme::newmark,
                ExcMessage("Time integration/Error tolerance = " +
                           format_number(error_tolerance_) +
                           " needs Scheme = newmark (the estimate is the "
                           "Newmark step's local error; " +
                           scheme_names.name(scheme) +
                           " has another one); use 0."));
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

  void
  TimeIntegrator::parse_alphas(const std::string    &alpha_m,
                               const std::string    &alpha_f,
                               const TimeIntegrator &defaults)
  {
    const std::string name = scheme_names.name(scheme);
    // an entry that the scheme would ignore is refused, not ignored
    // (hht-alpha: Alpha m may only repeat its 0)
    const bool alphas_given =
      !alpha_f.empty() || (scheme != Scheme::hht_alpha && !alpha_m.empty());
    AssertThrow(scheme != Scheme::generalized_alpha ||
                  alpha_m.empty() == alpha_f.empty(),
                ExcMessage("Time integration/Alpha m = '" + alpha_m +
                           "' and Alpha f = '" + alpha_f +
                           "': give both (they replace the Spectral "
                           "radius at infinity) or neither."));
    AssertThrow(spectral_radius_ == defaults.spectral_radius_ ||
                  (!alphas_given && scheme != Scheme::newmark &&
                   scheme != Scheme::quasi_static),
                ExcMessage("Time integration/Spectral radius at infinity = " +
                           format_number(spectral_radius_) +
                           (alphas_given ?
                              std::string(" is replaced by the Alpha m and "
                                          "Alpha f given") :
                              " applies to Scheme = generalized-alpha or "
                              "hht-alpha only, not to " +
                                name) +
                           ": leave it at its default " +
                           format_number(defaults.spectral_radius_) + "."));
    if (scheme == Scheme::newmark || scheme == Scheme::quasi_static)
      {
        AssertThrow(alpha_m.empty() && alpha_f.empty(),
                    ExcMessage("Time integration/Alpha m = '" + alpha_m +
                               "' and Alpha f = '" + alpha_f +
                               "' apply to Scheme = generalized-alpha or "
                               "hht-alpha only; leave them empty for " +
                               name + "."));
        alpha_m_ = alpha_f_ = 0;
        return;
      }
    // the scheme's beta and gamma replace Newmark's
    std::vector<std::string> changed;
    if (beta_ != defaults.beta_)
      changed.push_back("Newmark beta = " + format_number(beta_));
    if (gamma_ != defaults.gamma_)
      changed.push_back("Newmark gamma = " + format_number(gamma_));
    AssertThrow(changed.empty(),
                ExcMessage("Time integration/" + join(changed, " and ") +
                           " applies to Scheme = newmark only; " + name +
                           " takes beta and gamma from its alphas (leave "
                           "Newmark beta at 0.25 and Newmark gamma at "
                           "0.5)."));
    const double rho = spectral_radius_;
    if (scheme == Scheme::hht_alpha)
      {
        AssertThrow(alpha_m.empty() || std::stod(alpha_m) == 0,
                    ExcMessage("Time integration/Alpha m = " + alpha_m +
                               " with Scheme = hht-alpha, which has alpha_m "
                               "= 0: leave it empty, or use "
                               "generalized-alpha."));
        if (alpha_f.empty())
          {
            AssertThrow(rho >= 0.5,
                        ExcMessage(
                          "Time integration/Spectral radius at infinity = " +
                          format_number(rho) +
                          " is below what hht-alpha reaches (0.5 to 1, "
                          "alpha_f up to 1/3); use generalized-alpha for "
                          "smaller values."));
            alpha_f_ = (1 - rho) / (1 + rho);
          }
        else
          alpha_f_ = std::stod(alpha_f);
        alpha_m_ = 0;
        AssertThrow(alpha_f_ <= 1. / 3 + 1e-12,
                    ExcMessage("Time integration/Alpha f = " + alpha_f +
                               " with Scheme = hht-alpha: allowed is [0, "
                               "1/3] (Hilber's alpha in [-1/3, 0]), where "
                               "the scheme is unconditionally stable."));
      }
    else
      {
        if (alpha_m.empty())
          {
            alpha_m_ = (2 * rho - 1) / (rho + 1);
            alpha_f_ = rho / (rho + 1);
          }
        else
          {
            alpha_m_ = std::stod(alpha_m);
            alpha_f_ = std::stod(alpha_f);
            AssertThrow(alpha_m_ <= alpha_f_,
                        ExcMessage("Time integration/Alpha m = " + alpha_m +
                                   " exceeds Alpha f = " + alpha_f +
                                   ": generalized-alpha is unconditionally "
                                   "stable for alpha_m <= alpha_f <= 1/2."));
          }
      }
    // second order, and the most high-frequency dissipation for the alphas
    gamma_ = 0.5 - alpha_m_ + alpha_f_;
    beta_  = 0.25 * std::pow(1 - alpha_m_ + alpha_f_, 2);
  }

  std::string
  TimeIntegrator::scheme_name() const
  {
    return scheme_names.name(scheme);
  }
} // namespace ContactDynamics
