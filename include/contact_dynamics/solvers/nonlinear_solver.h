// Newton's method; the linear solves are left to a LinearSolver.
#ifndef contact_dynamics_solvers_nonlinear_solver_h
#define contact_dynamics_solvers_nonlinear_solver_h

#include <deal.II/base/config.h>

#include <contact_dynamics/solvers/linear_solver.h>
#include <contact_dynamics/solvers/multiplier_condensation.h>

#include <iosfwd>
#include <string>

DEAL_II_NAMESPACE_OPEN
class TimerOutput;
DEAL_II_NAMESPACE_CLOSE

namespace ContactDynamics
{
  using namespace dealii;

  /**
   * The system a Newton solve works on. assemble() evaluates the residual at
   * the current iterate (with the rows of constrained degrees of freedom
   * zeroed) and, if asked, the Jacobian; apply_update() adds a Newton
   * increment to the iterate. converged() lets a formulation veto
   * convergence (for instance while an active set still changes).
   */
  class NonlinearSystem
  {
  public:
    virtual ~NonlinearSystem() = default;

    virtual void
    assemble(const bool                      with_jacobian,
             TrilinosWrappers::MPI::Vector  &residual,
             TrilinosWrappers::SparseMatrix &jacobian) = 0;

    virtual void
    apply_update(const TrilinosWrappers::MPI::Vector &increment) = 0;

    /** The Jacobian does not depend on the iterate (a linear problem). */
    virtual bool
    jacobian_is_constant() const
    {
      return false;
    }

    virtual bool
    converged() const
    {
      return true;
    }

    /**
     * The system has contact multipliers that condensation could eliminate
     * (the same answer on every process).
     */
    virtual bool
    has_multipliers() const
    {
      return false;
    }

    /** The multipliers of the secondary nodes this process owns. */
    virtual std::vector<MultiplierGroup>
    multiplier_groups() const
    {
      return {};
    }

    /** l2 norm of the current iterate, for the step tolerance. */
    virtual double
    iterate_norm() const
    {
      return 0.;
    }
  };

  class NewtonSolver
  {
  public:
    struct Result
    {
      bool         converged         = false;
      unsigned int iterations        = 0; // linear solves
      unsigned int linear_iterations = 0; // GMRES iterations
      double       initial_residual  = 0;
      double       final_residual    = 0;
      std::string  failure;
    };

    /** Also declares the entries of the LinearSolver. */
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    /**
     * Solves the system from its current iterate. `structure_changed` tells
     * that the Jacobian of a constant-Jacobian system must be factorized anew
     * (a new time step size, a new sparsity pattern). Never throws for a
     * numerical failure: the result says why it did not converge.
     */
    Result
    solve(NonlinearSystem                &system,
          TrilinosWrappers::SparseMatrix &jacobian,
          TrilinosWrappers::MPI::Vector  &residual,
          TrilinosWrappers::MPI::Vector  &increment,
          const bool                      structure_changed,
          std::ostream                   &log);

    bool
    verbose() const
    {
      return verbose_;
    }

    /** Times the factorizations and solves in the section "linear solve". */
    void
    set_timer(TimerOutput &timer)
    {
      this->timer = &timer;
    }

    /**
     * The condensed matrices are copies of the Jacobian (for an iterative
     * solver): its sparsity pattern should hold the fill-in
     * (MultiplierCondensation::add_fill_in). A direct solver gets them with
     * their own, smaller pattern instead: the Jacobian's keeps structural
     * zeros at the multipliers, which cost KLU 3 times the time.
     */
    bool
    wants_fill_in() const
    {
      return linear_solver.wants_condensed_matrix();
    }

    /** See LinearSolver::choose(). */
    std::string
    choose_linear_solver(const unsigned long n_unknowns,
                         const bool          dynamic,
                         const unsigned int  n_processes,
                         const unsigned int  dim)
    {
      return linear_solver.choose(n_unknowns, dynamic, n_processes, dim);
    }

    /** See LinearSolver::set_near_null_space(). */
    void
    set_near_null_space(std::vector<std::vector<double>> modes,
                        const unsigned int               dofs_per_vertex)
    {
      linear_solver.set_near_null_space(std::move(modes), dofs_per_vertex);
    }

    /** See LinearSolver::reset(). */
    void
    reset_linear_solver()
    {
      linear_solver.reset();
    }

    /** See LinearSolver::release(). */
    void
    release_factorization()
    {
      linear_solver.release();
    }

  private:
    /** Assembles; on an exception, records it in `result` (false). */
    bool
    assemble(NonlinearSystem                &system,
             TrilinosWrappers::MPI::Vector  &residual,
             TrilinosWrappers::SparseMatrix &jacobian,
             Result                         &result);

    /** Solves J du = -R (timed); on failure, records it (false). */
    bool
    solve_linear_system(const NonlinearSystem                &system,
                        const TrilinosWrappers::SparseMatrix &jacobian,
                        TrilinosWrappers::MPI::Vector        &residual,
                        TrilinosWrappers::MPI::Vector        &increment,
                        const double                          residual_norm,
                        const bool                            keep,
                        Result                               &result);

    double       absolute_tolerance = 1e-10;
    double       relative_tolerance = 1e-10;
    double       step_tolerance     = 1e-12;
    bool         cycle_damping      = true;
    unsigned int max_iterations     = 25;
    bool         verbose_           = false;
    TimerOutput *timer              = nullptr;
    LinearSolver linear_solver;
    bool         condense_multipliers = false;
    // built anew for every linear solve with contact multipliers
    MultiplierCondensation condensation;
  };
} // namespace ContactDynamics

#endif
