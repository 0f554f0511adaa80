// The time-step control of the Simulator (doc/time-integration.md).
#include <deal.II/base/mpi.h>

#include <contact_dynamics/mechanics/time_step_controller.h>
#include <contact_dynamics/output/checkpoint.h>
#include <contact_dynamics/parameters.h>

#include <algorithm>
#include <cmath>

namespace ContactDynamics
{
  TimeStepController::TimeStepController(const TimeIntegrator &integrator)
    : integrator(integrator)
  {}

  void
  TimeStepController::start()
  {
    cumulative_newton_iterations = 0;
    time_step_cuts               = 0;
    rejected_steps               = 0;
    error_estimate               = 0;
    have_mean_acceleration       = false;
    dt_before                    = 0;
    dt_next                      = integrator.time_step();
    good_since_cut               = 0;
    cut_since                    = 2;
  }

  bool
  TimeStepController::begin_attempt(const double dt)
  {
    const bool changed = dt != dt_current;
    dt_current         = dt;
    rejected_by_error  = false;
    return changed;
  }

  double
  TimeStepController::next_dt(const double time_left) const
  {
    return std::min(dt_next, time_left);
  }

  std::string
  TimeStepController::judge_error(const BodyState &state,
                                  const IndexSet  &locally_owned,
                                  const IndexSet  &displacement_dofs,
                                  const AffineConstraints<double> &constraints)
  {
    // The change of the acceleration over the step, a_{n+1} - a_n, from
    // the mean accelerations of this step and the one before, so that the
    // step-to-step alternation of the trapezoidal rule's acceleration after
    // a velocity jump (undamped, at the step's Nyquist frequency, not a
    // motion a smaller step resolves) does not count; the same for a
    // smooth motion. The first step uses a_{n+1} - a_n; a mesh change
    // transfers the last mean acceleration.
    const double dt = dt_current;
    mean_acceleration.reinit(state.v);
    for (const auto i : locally_owned)
      mean_acceleration(i) = (state.v_new(i) - state.v(i)) / dt;
    mean_acceleration.compress(VectorOperation::insert);
    const bool history = have_mean_acceleration &&
                         mean_acceleration_before.size() == state.v.size();
    // the mean acceleration (1 - gamma) a_n + gamma a_{n+1} belongs to
    // t_n + gamma dt_n (to first order): the two are that far apart
    const double gamma   = integrator.gamma();
    const double scale   = dt / (gamma * dt + (1 - gamma) * dt_before);
    const double factor  = std::abs(integrator.local_error_factor(dt));
    double       largest = 0;
    for (const auto i : displacement_dofs)
      if (!constraints.is_constrained(i))
        {
          const double change =
            history ?
              (mean_acceleration(i) - mean_acceleration_before(i)) * scale :
              state.a_new(i) - state.a(i);
          largest = std::max(largest, factor * std::abs(change));
        }
    error_estimate =
      Utilities::MPI::max(largest, state.v.get_mpi_communicator());

    // the step is solved again with a smaller dt if its local error is too
    // large (not below the minimum dt)
    const double tolerance = integrator.error_tolerance();
    step_factor =
      error_estimate > 0 ?
        std::clamp(0.9 * std::cbrt(tolerance / error_estimate), 0.2, 2.) :
        2.;
    if (error_estimate > tolerance &&
        dt > integrator.minimum_time_step() * (1 + 1e-9))
      {
        rejected_by_error = true;
        return "the local error estimate " + format_number(error_estimate) +
               " exceeds Time integration/Error tolerance = " +
               format_number(tolerance);
      }
    return "";
  }

  void
  TimeStepController::accepted(const double dt_try, std::ostream &screen)
  {
    const double time_step = integrator.time_step();
    if (integrator.error_tolerance() > 0)
      {
        // after a Newton failure, two good steps before it grows
        const bool recently_cut = cut_since < 2;
        cut_since += recently_cut;
        dt_next =
          std::clamp(dt_try *
                       (recently_cut ? std::min(step_factor, 1.) : step_factor),
                     integrator.minimum_time_step(),
                     time_step);
        if (error_estimate > integrator.error_tolerance())
          screen << "  accepted at the Minimum time step with the "
                    "error estimate "
                 << error_estimate << " above the tolerance" << std::endl;
      }
    else if (dt_next < time_step && ++good_since_cut >= 2)
      {
        dt_next        = std::min(2 * dt_next, time_step);
        good_since_cut = 0;
      }
  }

  void
  TimeStepController::rejected(const double dt_try, std::ostream &screen)
  {
    ++rejected_steps;
    dt_next = std::max(dt_try * step_factor, integrator.minimum_time_step());
    screen << "  reducing the time step to " << dt_next << std::endl;
  }

  bool
  TimeStepController::cut(const double dt_try)
  {
    ++time_step_cuts;
    good_since_cut = 0;
    cut_since      = 0;
    dt_next        = dt_try / 2;
    return !(dt_next < integrator.minimum_time_step());
  }

  void
  TimeStepController::commit(const RunContext &)
  {
    if (integrator.error_tolerance() > 0)
      {
        mean_acceleration_before.swap(mean_acceleration);
        dt_before              = dt_current;
        have_mean_acceleration = true;
      }
  }

  void
  TimeStepController::save(CheckpointData &data, const RunContext &) const
  {
    data.set("controller",
             {dt_current,
              dt_next,
              double(good_since_cut),
              double(cut_since),
              double(time_step_cuts),
              double(cumulative_newton_iterations),
              double(rejected_steps),
              error_estimate,
              step_factor,
              dt_before,
              double(have_mean_acceleration)});
  }

  void
  TimeStepController::load(const CheckpointData &data, const RunContext &)
  {
    const auto &values           = data.get("controller", 11);
    dt_current                   = values[0];
    dt_next                      = values[1];
    good_since_cut               = values[2];
    cut_since                    = values[3];
    time_step_cuts               = values[4];
    cumulative_newton_iterations = values[5];
    rejected_steps               = values[6];
    error_estimate               = values[7];
    step_factor                  = values[8];
    dt_before                    = values[9];
    have_mean_acceleration       = values[10] != 0;
    // a shorter Time step than the run's (the solver settings may change)
    dt_next = std::min(dt_next, integrator.time_step());
  }

  void
  TimeStepController::list_vectors(std::vector<VectorType *> &vectors)
  {
    if (have_mean_acceleration)
      vectors.push_back(&mean_acceleration_before);
  }

  void
  TimeStepController::reinit_vectors(const VectorType &layout)
  {
    if (have_mean_acceleration)
      mean_acceleration_before.reinit(layout);
  }

  void
  TimeStepController::prepare_transfer(std::vector<VectorType *> &vectors)
  {
    keep_on_new_mesh =
      integrator.error_tolerance() > 0 && have_mean_acceleration;
    if (keep_on_new_mesh)
      vectors.push_back(&mean_acceleration_before);
  }

  void
  TimeStepController::transfer(const RunContext &)
  {
    have_mean_acceleration = keep_on_new_mesh;
  }
} // namespace ContactDynamics
