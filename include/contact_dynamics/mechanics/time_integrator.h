// Newmark-beta, generalized-alpha (Chung and Hulbert) and HHT-alpha time
// integration, and the quasi-static special case.
#ifndef contact_dynamics_mechanics_time_integrator_h
#define contact_dynamics_mechanics_time_integrator_h

#include <deal.II/base/config.h>

#include <string>

DEAL_II_NAMESPACE_OPEN
class ParameterHandler;
DEAL_II_NAMESPACE_CLOSE

namespace ContactDynamics
{
  using namespace dealii;

  /**
   * Newmark-beta: with u_{n+1} the unknown,
   *   a_{n+1} = (u_{n+1} - u_n - dt v_n) / (beta dt^2) - (1/(2 beta) - 1) a_n
   *   v_{n+1} = v_n + dt ((1 - gamma) a_n + gamma a_{n+1}).
   * Both are affine in u_{n+1}: a = c_a u + a_0, v = c_v u + v_0.
   * Generalized-alpha and HHT-alpha keep these kinematics (with their own
   * beta and gamma) and balance the forces between the steps:
   *   M ((1 - alpha_m) a_{n+1} + alpha_m a_n)
   *     + (1 - alpha_f) F_{n+1} + alpha_f F_n = 0,
   * F = C v + f_int - f_ext + f_contact (Newmark: alpha_m = alpha_f = 0).
   * The quasi-static scheme has no inertia and no damping. Also holds the
   * time step and the end time of the `Time integration` subsection.
   */
  class TimeIntegrator
  {
  public:
    enum class Scheme
    {
      newmark,
      generalized_alpha,
      hht_alpha,
      quasi_static
    };

    enum class Predictor
    {
      displacement,
      velocity,
      acceleration
    };

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    bool
    is_dynamic() const
    {
      return scheme != Scheme::quasi_static;
    }

    /**
     * Whether the scheme dissipates energy in the bulk: the statistics then
     * report this numerical dissipation in a column of its own. Not the
     * trapezoidal rule (beta = 1/4, gamma = 1/2), nor generalized-alpha
     * with alpha_m = alpha_f (rho_inf = 1), whose amplification has
     * spectral radius 1 at every omega dt.
     */
    bool
    is_dissipative() const
    {
      return is_dynamic() &&
             (alpha_m_ != alpha_f_ || beta_ != 0.25 || gamma_ != 0.5);
    }

    /** Weight of a_n in the balanced inertia (0 for Newmark). */
    double
    alpha_m() const
    {
      return alpha_m_;
    }

    /** Weight of F_n in the balanced forces (0 for Newmark). */
    double
    alpha_f() const
    {
      return alpha_f_;
    }

    /**
     * The balance divided by 1 - alpha_f reads M a_eff + F_{n+1} +
     * old_force_factor() F_n = 0 with a_eff = inertia_factor() a_{n+1} +
     * old_inertia_factor() a_n.
     */
    double
    inertia_factor() const
    {
      return (1 - alpha_m_) / (1 - alpha_f_);
    }

    double
    old_inertia_factor() const
    {
      return alpha_m_ / (1 - alpha_f_);
    }

    double
    old_force_factor() const
    {
      return alpha_f_ / (1 - alpha_f_);
    }

    /** The scheme's name as the parameter file writes it. */
    std::string
    scheme_name() const;

    /** The nominal time step, to which cut steps grow back. */
    double
    time_step() const
    {
      return time_step_;
    }

    double
    end_time() const
    {
      return end_time_;
    }

    /** A step cut below this stops the run. */
    double
    minimum_time_step() const
    {
      return minimum_time_step_;
    }

    double
    beta() const
    {
      return beta_;
    }

    double
    gamma() const
    {
      return gamma_;
    }

    /** The largest local error estimate a step may have (0: no
     * estimate; the step is then only cut when Newton fails). */
    double
    error_tolerance() const
    {
      return error_tolerance_;
    }

    /**
     * The local error of the displacement in a Newmark step (Zienkiewicz
     * and Xie 1991): dt^2 (beta - 1/6) (a_{n+1} - a_n), the difference to
     * the step with a linearly varying acceleration, one order higher
     * (beta >= 1/4 here, so the factor is at least dt^2 / 12). Returns the
     * factor of a_{n+1} - a_n.
     */
    double
    local_error_factor(const double dt) const
    {
      return dt * dt * (beta_ - 1. / 6.);
    }

    /** d a_{n+1} / d u_{n+1} */
    double
    acceleration_factor(const double dt) const
    {
      return is_dynamic() ? 1. / (beta_ * dt * dt) : 0.;
    }

    /** d a_eff / d u_{n+1}: the mass factor of the Jacobian */
    double
    effective_acceleration_factor(const double dt) const
    {
      return acceleration_factor(dt) * inertia_factor();
    }

    /** d v_{n+1} / d u_{n+1}; quasi-static: v = (u_{n+1} - u_n) / dt */
    double
    velocity_factor(const double dt) const
    {
      return is_dynamic() ? gamma_ / (beta_ * dt) : 1. / dt;
    }

    /**
     * New velocity and acceleration from the new displacement, for one
     * degree of freedom (works on vector entries or whole vectors).
     */
    template <typename Number>
    void
    update(const double  dt,
           const Number &u_old,
           const Number &v_old,
           const Number &a_old,
           const Number &u_new,
           Number       &v_new,
           Number       &a_new) const
    {
      if (!is_dynamic())
        {
          v_new = (u_new - u_old) / dt;
          a_new = 0. * a_old;
          return;
        }
      a_new = (u_new - u_old - dt * v_old) / (beta_ * dt * dt) -
              (0.5 / beta_ - 1.) * a_old;
      v_new = v_old + dt * ((1. - gamma_) * a_old + gamma_ * a_new);
    }

    /** Predicted displacement at t_{n+1} (see the Predictor entry). */
    template <typename Number>
    Number
    predict(const double  dt,
            const Number &u_old,
            const Number &v_old,
            const Number &a_old) const
    {
      if (!is_dynamic() || predictor == Predictor::displacement)
        return u_old;
      if (predictor == Predictor::velocity)
        return u_old + dt * v_old;
      return u_old + dt * v_old + 0.5 * dt * dt * a_old;
    }

  private:
    /** alpha_m, alpha_f, beta and gamma of the scheme. */
    void
    parse_alphas(const std::string    &alpha_m,
                 const std::string    &alpha_f,
                 const TimeIntegrator &defaults);

    // the defaults of the parameter file
    Scheme    scheme             = Scheme::newmark;
    Predictor predictor          = Predictor::velocity;
    double    beta_              = 0.25;
    double    gamma_             = 0.5;
    double    alpha_m_           = 0;
    double    alpha_f_           = 0;
    double    spectral_radius_   = 0.8;
    double    time_step_         = 0.025;
    double    end_time_          = 1.;
    double    minimum_time_step_ = 1e-6;
    double    error_tolerance_   = 0;
  };
} // namespace ContactDynamics

#endif
