#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <contact_dynamics/parallel.h>
#include <contact_dynamics/parameters.h>
#include <contact_dynamics/solvers/nonlinear_solver.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <memory>
#include <ostream>
#include <sstream>

namespace ContactDynamics
{
  namespace
  {
    /**
     * The residual norms of the last two iterations and what follows from
     * them: whether the residual stagnated at round-off, and the damping
     * of the next update. Semi-smooth Newton can cycle between two active
     * sets (stick and slip, say): the residual then repeats every other
     * iteration; or the update jumps across a kink of the residual and
     * back, its norm the same at every iteration (AMG on the quasi-static
     * Hertz cylinder). Damped updates break both cycles.
     */
    class ResidualHistory
    {
    public:
      ResidualHistory(const double step_tolerance, const bool cycle_damping)
        : step_tolerance(step_tolerance)
        , cycle_damping(cycle_damping)
      {}

      /** Round-off: the residual stopped falling and the update is tiny. */
      bool
      stagnated(const unsigned int it, const double norm) const
      {
        return it > 0 && norm > 0.5 * previous_norm &&
               step_ratio <= step_tolerance;
      }

      /**
       * Records the residual norm of iteration `it` and adapts the damping;
       * true if it detected a cycle.
       */
      bool
      record(const unsigned int it, const double norm)
      {
        bool cycle = false;
        if (damping < 1 && norm < 0.5 * previous_norm)
          damping = 1; // out of the cycle: full Newton steps again
        else if (cycle_damping && it > 1 &&
                 std::abs(norm - older_norm) <= 1e-3 * norm &&
                 (std::abs(norm - previous_norm) > 1e-2 * norm ||
                  (std::abs(norm - previous_norm) <= 1e-3 * norm &&
                   step_ratio > step_tolerance)))
          {
            damping = std::max(damping / 2, 1. / 16);
            cycle   = true;
          }
        older_norm    = previous_norm;
        previous_norm = norm;
        return cycle;
      }

      double damping    = 1;
      double step_ratio = 0; // |du| / |u| of the last update

    private:
      const double step_tolerance;
      const bool   cycle_damping;
      double       previous_norm = 0;
      double       older_norm    = -1;
    };
  } // namespace

  void
  NewtonSolver::declare_parameters(ParameterHandler &prm)
  {
    const NewtonSolver defaults;
    prm.declare_entry("Absolute tolerance",
                      default_text(defaults.absolute_tolerance),
                      Patterns::Double(0),
                      "Converged when the l2 norm of the residual (forces at "
                      "free degrees of freedom) is below this value (force "
                      "units, >= 0).");
    prm.declare_entry("Relative tolerance",
                      default_text(defaults.relative_tolerance),
                      Patterns::Double(0, 1),
                      "... or below this fraction of the residual at the "
                      "first iteration of the time step, in [0, 1).");
    prm.declare_entry(
      "Step tolerance",
      default_text(defaults.step_tolerance),
      Patterns::Double(0, 1),
      "... or, once the residual stagnates (it fell by less than half in "
      "the last iteration), when the l2 norm of the last Newton update is "
      "below this fraction of that of the iterate: the residual has then "
      "reached its round-off level, which can lie above the absolute "
      "tolerance for stiff bodies or tiny time steps. In [0, 1); 0 turns "
      "the criterion off.");
    prm.declare_entry(
      "Cycle damping",
      default_text(defaults.cycle_damping),
      Patterns::Bool(),
      "Semi-smooth Newton can cycle between two active sets (stick and "
      "slip, contact and no contact): the residual then repeats every other "
      "iteration, or keeps its norm while the update jumps back and forth "
      "across a kink of the residual (its sign flips). When it does (to "
      "0.1 %, with updates above the Step tolerance), the updates are halved "
      "(down to 1/16) until the residual halves, then full steps resume. "
      "Converging iterations never trigger it. Without it, ironing with "
      "mu = 1 stops after first contact, and AMG on the quasi-static Hertz "
      "cylinder stalls at a residual of 4e-6 (doc/extreme-cases.md, "
      "doc/solvers.md).");
    prm.declare_entry("Maximum iterations",
                      default_text(defaults.max_iterations),
                      Patterns::Integer(1, 1000),
                      "Newton iterations (linear solves) allowed per time "
                      "step before the step is cut, in [1, 1000].");
    prm.declare_entry(
      "Condense multipliers",
      default_text(defaults.condense_multipliers),
      Patterns::Bool(),
      "Eliminate the contact multipliers node by node from each Newton "
      "system: the linear solver sees displacement unknowns only, the "
      "multipliers are recovered after the solve. Node-to-segment: the "
      "same Newton iterates as the full system. Mortar: this code's force "
      "(the derivative of the enforced gaps) couples a node's rows to its "
      "neighbours' multipliers by terms of the size of the gap, which the "
      "elimination leaves out: an inexact Newton method, measured 5-28 % "
      "more iterations to the same states (doc/solvers.md).");
    prm.declare_entry("Verbose",
                      default_text(defaults.verbose_),
                      Patterns::Bool(),
                      "Print the residual of every Newton iteration.");
    LinearSolver::declare_parameters(prm);
  }

  void
  NewtonSolver::parse_parameters(ParameterHandler &prm)
  {
    absolute_tolerance   = prm.get_double("Absolute tolerance");
    relative_tolerance   = prm.get_double("Relative tolerance");
    step_tolerance       = prm.get_double("Step tolerance");
    cycle_damping        = prm.get_bool("Cycle damping");
    max_iterations       = prm.get_integer("Maximum iterations");
    verbose_             = prm.get_bool("Verbose");
    condense_multipliers = prm.get_bool("Condense multipliers");
    linear_solver.parse_parameters(prm, verbose_);
  }

  bool
  NewtonSolver::assemble(NonlinearSystem                &system,
                         TrilinosWrappers::MPI::Vector  &residual,
                         TrilinosWrappers::SparseMatrix &jacobian,
                         Result                         &result)
  {
    try
      {
        system.assemble(linear_solver.needs_matrix(), residual, jacobian);
        return true;
      }
    catch (const ExceptionBase &e)
      {
        result.failure = exception_message(e);
      }
    catch (const std::exception &e)
      {
        result.failure = e.what();
      }
    linear_solver.invalidate_after_failure();
    return false;
  }

  bool
  NewtonSolver::solve_linear_system(
    const NonlinearSystem                &system,
    const TrilinosWrappers::SparseMatrix &jacobian,
    TrilinosWrappers::MPI::Vector        &residual,
    TrilinosWrappers::MPI::Vector        &increment,
    const double                          residual_norm,
    const bool                            keep,
    Result                               &result)
  {
    try
      {
        std::unique_ptr<TimerOutput::Scope> scope;
        if (timer)
          scope = std::make_unique<TimerOutput::Scope>(*timer, "linear solve");
        if ((condense_multipliers || linear_solver.wants_condensed_matrix()) &&
            system.has_multipliers())
          {
            // the solver refers to the matrix condense() rebuilds
            linear_solver.release();
            {
              std::unique_ptr<TimerOutput::Scope> condense_scope;
              if (timer)
                condense_scope =
                  std::make_unique<TimerOutput::Scope>(*timer, "condensation");
              condensation.condense(jacobian,
                                    residual,
                                    system.multiplier_groups(),
                                    linear_solver.wants_condensed_matrix());
            }
            TrilinosWrappers::MPI::Vector rhs(condensation.rhs());
            linear_solver.set_node_frames(condensation.node_frames());
            result.linear_iterations +=
              linear_solver.solve(condensation.matrix(),
                                  rhs,
                                  increment,
                                  rhs.l2_norm(),
                                  false);
            condensation.recover(increment);
            return true;
          }
        linear_solver.set_node_frames({});
        result.linear_iterations += linear_solver.solve(jacobian,
                                                        residual,
                                                        increment,
                                                        residual_norm,
                                                        keep);
        return true;
      }
    catch (const std::exception &e)
      {
        // (the message alone: deal.II's what() carries a stack trace)
        result.failure =
          std::string("the linear solver failed: ") + exception_message(e);
        linear_solver.invalidate_after_failure();
        return false;
      }
  }

  NewtonSolver::Result
  NewtonSolver::solve(NonlinearSystem                &system,
                      TrilinosWrappers::SparseMatrix &jacobian,
                      TrilinosWrappers::MPI::Vector  &residual,
                      TrilinosWrappers::MPI::Vector  &increment,
                      const bool                      structure_changed,
                      std::ostream                   &log)
  {
    Result     result;
    const bool reuse = system.jacobian_is_constant();
    if (structure_changed || !reuse)
      linear_solver.invalidate();

    ResidualHistory history(step_tolerance, cycle_damping);
    for (unsigned int it = 0;; ++it)
      {
        if (!assemble(system, residual, jacobian, result))
          return result;
        const double norm = residual.l2_norm();
        if (it == 0)
          result.initial_residual = norm;
        result.final_residual = norm;
        if (verbose_)
          log << "    Newton " << std::setw(2) << it << "  residual "
              << std::scientific << std::setprecision(3) << norm
              << std::defaultfloat << std::endl;
        if (!std::isfinite(norm))
          {
            // a norm of finite forces overflows above 1e154
            const double largest = residual.linfty_norm();
            result.failure       = std::isfinite(largest) ?
                                     "the residual norm overflows (forces up to " +
                                 format_number(largest) + ")" :
                                     "the residual is not a finite number";
            linear_solver.invalidate_after_failure();
            return result;
          }
        const bool stagnated = history.stagnated(it, norm);
        if (history.record(it, norm) && verbose_)
          log << "    (cycle detected: damping " << history.damping << ")"
              << std::endl;
        if ((norm <= absolute_tolerance ||
             norm <= relative_tolerance * result.initial_residual ||
             stagnated) &&
            system.converged())
          {
            result.converged = true;
            return result;
          }
        if (it == max_iterations)
          {
            result.failure = "no convergence in " +
                             std::to_string(max_iterations) +
                             " Newton iterations";
            linear_solver.invalidate_after_failure();
            return result;
          }

        if (!solve_linear_system(system,
                                 jacobian,
                                 residual,
                                 increment,
                                 norm,
                                 reuse,
                                 result))
          return result;
        ++result.iterations;
        if (history.damping < 1)
          increment *= history.damping;
        system.apply_update(increment);
        const double iterate = system.iterate_norm();
        // (of the undamped update: a damped one is no sign of round-off)
        history.step_ratio = iterate > 0 ? increment.l2_norm() /
                                             history.damping / iterate :
                                           std::numeric_limits<double>::infinity();
        if (verbose_)
          log << "              |du| / |u| = " << std::scientific
              << std::setprecision(3) << history.step_ratio << std::defaultfloat
              << std::endl;
      }
  }
} // namespace ContactDynamics
