// Newmark-beta time integration and the quasi-static special case.
#ifndef contact_dynamics_mechanics_time_integrator_h
#define contact_dynamics_mechanics_time_integrator_h

#include <deal.II/base/config.h>

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
   * Both are affine in u_{n+1}: a = c_a u + a_0, v = c_v u + v_0. The
   * quasi-static scheme has no inertia and no damping. Also holds the
   * time step and the end time of the `Time integration` subsection.
   */
  class TimeIntegrator
  {
  public:
    enum class Scheme
    {
      newmark,
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
      return scheme == Scheme::newmark;
    }

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
    // the defaults of the parameter file
    Scheme    scheme             = Scheme::newmark;
    Predictor predictor          = Predictor::velocity;
    double    beta_              = 0.25;
    double    gamma_             = 0.5;
    double    time_step_         = 0.025;
    double    end_time_          = 1.;
    double    minimum_time_step_ = 1e-6;
    double    error_tolerance_   = 0;
  };
} // namespace ContactDynamics

#endif
