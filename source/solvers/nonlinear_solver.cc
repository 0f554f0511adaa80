#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <contact_dynamics/solvers/nonlinear_solver.h>

#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace ContactDynamics
{
  void
  NewtonSolver::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Absolute tolerance",
                      "1e-10",
                      Patterns::Double(0),
                      "Converged when the l2 norm of the residual (forces at "
                      "free degrees of freedom) is below this value (force "
                      "units, >= 0).");
    prm.declare_entry("Relative tolerance",
                      "1e-10",
                      Patterns::Double(0, 1),
                      "... or below this fraction of the residual at the "
                      "first iteration of the time step, in [0, 1).");
    prm.declare_entry(
      "Step tolerance",
      "1e-12",
      Patterns::Double(0, 1),
      "... or, once the residual stagnates (it fell by less than half in "
      "the last iteration), when the l2 norm of the last Newton update is "
      "below this fraction of that of the iterate: the residual has then "
      "reached its round-off level, which can lie above the absolute "
      "tolerance for stiff bodies or tiny time steps. In [0, 1); 0 turns "
      "the criterion off.");
    prm.declare_entry(
      "Cycle damping",
      "true",
      Patterns::Bool(),
      "Semi-smooth Newton can cycle between two active sets (stick and "
      "slip, contact and no contact): the residual then repeats every other "
      "iteration. When it does (to 0.1 %), the updates are halved (down to "
      "1/16) until the residual halves, then full steps resume. Converging "
      "iterations never trigger it. Without it, ironing with mu = 1 stops "
      "after first contact (doc/extreme-cases.md).");
    prm.declare_entry("Maximum iterations",
                      "25",
                      Patterns::Integer(1, 1000),
                      "Newton iterations (linear solves) allowed per time "
                      "step before the step is cut, in [1, 1000].");
    prm.declare_entry(
      "Linear solver",
      "KLU",
      Patterns::Selection("KLU|MUMPS|GMRES"),
      "KLU and MUMPS are sparse direct solvers (Trilinos Amesos). KLU "
      "factorizes on one process (with mpirun the matrix is gathered there): "
      "fastest for the 2-D scenes of the paper. MUMPS factorizes in parallel. "
      "GMRES is iterative, preconditioned by additive Schwarz with an exact "
      "(KLU) solve of each process's block: the blocks keep the saddle-point "
      "structure of the contact rows intact, which incomplete factorizations "
      "and AMG do not handle; on one process it is a direct solve. See "
      "doc/parallel.md for what each costs.");
    prm.declare_entry("Linear tolerance",
                      "1e-6",
                      Patterns::Double(1e-300, 1),
                      "GMRES: solve to this fraction of the residual norm, "
                      "in (0, 1). Newton still converges to its own "
                      "tolerances (an inexact Newton method), only with more "
                      "iterations when this is large. Contact makes the "
                      "system ill-conditioned: below about 1e-8 GMRES can "
                      "fail with a loss of precision.");
    prm.declare_entry("Maximum linear iterations",
                      "1000",
                      Patterns::Integer(1),
                      "GMRES: iterations (restarted every 100) before the "
                      "solve counts as failed and the time step is cut.");
    prm.declare_entry("Verbose",
                      "false",
                      Patterns::Bool(),
                      "Print the residual of every Newton iteration.");
  }

  void
  NewtonSolver::parse_parameters(ParameterHandler &prm)
  {
    absolute_tolerance    = prm.get_double("Absolute tolerance");
    relative_tolerance    = prm.get_double("Relative tolerance");
    step_tolerance        = prm.get_double("Step tolerance");
    cycle_damping         = prm.get_bool("Cycle damping");
    max_iterations        = prm.get_integer("Maximum iterations");
    linear_solver         = prm.get("Linear solver");
    linear_tolerance      = prm.get_double("Linear tolerance");
    max_linear_iterations = prm.get_integer("Maximum linear iterations");
    verbose_              = prm.get_bool("Verbose");
  }

  void
  NewtonSolver::release_factorization()
  {
    // the solver refers to its control, so it goes first
    direct_solver.reset();
    solver_control.reset();
    preconditioner.reset();
    factorization_valid = false;
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
      factorization_valid = false;

    double previous_norm = 0, step_ratio = 0;
    // semi-smooth Newton can cycle between two active sets (stick and slip,
    // say): the residual then repeats every other iteration; damped
    // updates break the cycle
    double older_norm = -1, damping = 1;
    for (unsigned int it = 0;; ++it)
      {
        const bool need_jacobian = !factorization_valid;
        try
          {
            system.assemble(need_jacobian, residual, jacobian);
          }
        catch (const ExceptionBase &e)
          {
            std::ostringstream message;
            e.print_info(message);
            result.failure      = Utilities::trim(message.str());
            factorization_valid = false;
            return result;
          }
        catch (const std::exception &e)
          {
            result.failure      = e.what();
            factorization_valid = false;
            return result;
          }
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
            result.failure      = "the residual is not a finite number";
            factorization_valid = false;
            return result;
          }
        // round-off: the residual stopped falling and the update is tiny
        const bool stagnated =
          it > 0 && norm > 0.5 * previous_norm && step_ratio <= step_tolerance;
        if (damping < 1 && norm < 0.5 * previous_norm)
          damping = 1; // out of the cycle: full Newton steps again
        else if (cycle_damping && it > 1 &&
                 std::abs(norm - older_norm) <= 1e-3 * norm &&
                 std::abs(norm - previous_norm) > 1e-2 * norm)
          {
            damping = std::max(damping / 2, 1. / 16);
            if (verbose_)
              log << "    (cycle detected: damping " << damping << ")"
                  << std::endl;
          }
        older_norm    = previous_norm;
        previous_norm = norm;
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
            return result;
          }

        try
          {
            std::unique_ptr<TimerOutput::Scope> scope;
            if (timer)
              scope =
                std::make_unique<TimerOutput::Scope>(*timer, "linear solve");
            if (linear_solver == "GMRES")
              {
                if (need_jacobian)
                  {
                    release_factorization();
                    preconditioner = std::make_unique<
                      TrilinosWrappers::PreconditionBlockwiseDirect>();
                    preconditioner->initialize(jacobian);
                    factorization_valid = reuse;
                  }
                residual *= -1.;
                SolverControl                 control(max_linear_iterations,
                                      linear_tolerance * norm,
                                      false,
                                      false);
                TrilinosWrappers::SolverGMRES gmres(
                  control,
                  TrilinosWrappers::SolverGMRES::AdditionalData(verbose_, 100));
                increment = 0;
                gmres.solve(jacobian, increment, residual, *preconditioner);
                result.linear_iterations += control.last_step();
              }
            else if (need_jacobian)
              {
                release_factorization();
                solver_control =
                  std::make_unique<SolverControl>(1, 0, false, false);
                direct_solver =
                  std::make_unique<TrilinosWrappers::SolverDirect>(
                    *solver_control,
                    TrilinosWrappers::SolverDirect::AdditionalData(
                      false,
                      linear_solver == "MUMPS" ? "Amesos_Mumps" :
                                                 "Amesos_Klu"));
                direct_solver->initialize(jacobian);
                factorization_valid = reuse;
              }
            // Newton: J du = -R
            if (linear_solver != "GMRES")
              {
                residual *= -1.;
                direct_solver->solve(increment, residual);
              }
          }
        catch (const std::exception &e)
          {
            result.failure =
              std::string("the linear solver failed: ") + e.what();
            factorization_valid = false;
            return result;
          }
        ++result.iterations;
        if (damping < 1)
          increment *= damping;
        system.apply_update(increment);
        const double iterate = system.iterate_norm();
        step_ratio           = iterate > 0 ? increment.l2_norm() / iterate :
                                             std::numeric_limits<double>::infinity();
        if (verbose_)
          log << "              |du| / |u| = " << std::scientific
              << std::setprecision(3) << step_ratio << std::defaultfloat
              << std::endl;
      }
  }
} // namespace ContactDynamics
