// The length of the time steps: Newton cutback and the error-based control
// (Time integration/Error tolerance), with the values they keep.
#ifndef contact_dynamics_mechanics_time_step_controller_h
#define contact_dynamics_mechanics_time_step_controller_h

#include <deal.II/base/index_set.h>

#include <deal.II/lac/affine_constraints.h>

#include <contact_dynamics/mechanics/body_state.h>
#include <contact_dynamics/mechanics/time_integrator.h>

#include <ostream>
#include <string>

namespace ContactDynamics
{
  /** What the evaluation of a solved step decides. */
  struct StepVerdict
  {
    enum Kind
    {
      accept,
      reject, // by the error estimate: again with a smaller step
      cut     // failed: again with half the step
    } kind = accept;
    std::string reason;
  };

  /**
   * Chooses the next dt: after a Newton failure the step is cut in half and
   * grows again after good steps; with an error tolerance, the local error
   * estimate of each converged step sets the next dt and rejects a step
   * whose estimate is too large. Owns the counts, the estimate and the mean
   * accelerations the estimate compares (the checkpoint entry "controller").
   */
  class TimeStepController : public HistoryOwner<RunContext>
  {
  public:
    explicit TimeStepController(const TimeIntegrator &integrator);

    std::string
    name() const override
    {
      return "controller";
    }

    /** At t = 0: the Time step, no cuts, no estimate. */
    void
    start();

    /** The step of length dt begins; true if dt differs from the last. */
    bool
    begin_attempt(const double dt);

    /** The dt of the current (or last completed) step. */
    double
    dt() const
    {
      return dt_current;
    }

    /** Sets the current dt only (for tests of the Jacobian). */
    void
    set_dt(const double dt)
    {
      dt_current = dt;
    }

    /** The dt of the next attempt, at most `time_left`. */
    double
    next_dt(const double time_left) const;

    /**
     * The local error estimate of the converged trial step: the largest
     * over the free displacement unknowns (not constrained). Sets the
     * factor of the next dt; returns why the step is rejected, or "".
     * Collective.
     */
    std::string
    judge_error(const BodyState                 &state,
                const IndexSet                  &locally_owned,
                const IndexSet                  &displacement_dofs,
                const AffineConstraints<double> &constraints);

    /** Whether the last attempt was rejected by the error estimate. */
    bool
    rejected_by_estimate() const
    {
      return rejected_by_error;
    }

    /** After an accepted step of length dt_try: the next dt. */
    void
    accepted(const double dt_try, std::ostream &screen);

    /** After a step rejected by the estimate: a smaller dt. */
    void
    rejected(const double dt_try, std::ostream &screen);

    /** After a failed step: half of it; false if below the minimum. */
    bool
    cut(const double dt_try);

    /** The dt the next attempt starts from. */
    double
    planned_dt() const
    {
      return dt_next;
    }

    void
    add_newton_iterations(const unsigned int n)
    {
      cumulative_newton_iterations += n;
    }

    unsigned int
    newton_iterations() const
    {
      return cumulative_newton_iterations;
    }

    unsigned int
    n_cuts() const
    {
      return time_step_cuts;
    }

    unsigned int
    n_rejected() const
    {
      return rejected_steps;
    }

    /** The estimate of the last converged step. */
    double
    estimate() const
    {
      return error_estimate;
    }

    /** The mean acceleration of the step becomes the one before. */
    void
    commit(const RunContext &) override;

    void
    save(CheckpointData &data, const RunContext &) const override;

    void
    load(const CheckpointData &data, const RunContext &) override;

    /** The last mean acceleration, if the estimate uses it. */
    void
    list_vectors(std::vector<VectorType *> &vectors) override;

    void
    reinit_vectors(const VectorType &layout) override;

    /**
     * Before a mesh change: the vectors to move with the state (the last
     * mean acceleration, if the estimate will use it).
     */
    void
    prepare_transfer(std::vector<VectorType *> &vectors) override;

    /** After the mesh change that prepare_transfer() began. */
    void
    transfer(const RunContext &) override;

  private:
    const TimeIntegrator &integrator;

    // the dt of the step (being) computed, and the next one to try
    double dt_current = 0;
    double dt_next    = 0;
    // good steps since a Newton failure (two kinds of counting)
    unsigned int good_since_cut = 0;
    unsigned int cut_since      = 2;
    unsigned int time_step_cuts = 0;
    // Newton iterations of the completed steps
    unsigned int cumulative_newton_iterations = 0;
    // the local error estimate of the last converged step, the factor for
    // the next dt, whether the last attempt was rejected by it, and how
    // many were
    unsigned int rejected_steps    = 0;
    double       error_estimate    = 0;
    double       step_factor       = 1;
    bool         rejected_by_error = false;
    // the mean accelerations (v_{n+1} - v_n) / dt of the trial step and of
    // the step before (its length dt_before), if that was on this mesh
    VectorType mean_acceleration, mean_acceleration_before;
    double     dt_before              = 0;
    bool       have_mean_acceleration = false;
    bool       keep_on_new_mesh       = false;
  };
} // namespace ContactDynamics

#endif
