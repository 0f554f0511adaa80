#include <deal.II/base/parameter_handler.h>

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <contact_dynamics/parameters.h>
#include <contact_dynamics/solvers/linear_solver.h>

namespace ContactDynamics
{
  namespace
  {
    const Selection<LinearSolver::Type> solver_names{
      {LinearSolver::Type::klu, "KLU"},
      {LinearSolver::Type::mumps, "MUMPS"},
      {LinearSolver::Type::gmres, "GMRES"}};
  } // namespace

  LinearSolver::LinearSolver() = default;

  // the unique_ptr members need the complete types
  LinearSolver::~LinearSolver() = default;

  void
  LinearSolver::declare_parameters(ParameterHandler &prm)
  {
    const LinearSolver defaults;
    prm.declare_entry(
      "Linear solver",
      solver_names.name(defaults.type),
      solver_names.pattern(),
      "KLU and MUMPS are sparse direct solvers (Trilinos Amesos). KLU "
      "factorizes on one process (with mpirun the matrix is gathered there): "
      "fastest for the 2-D scenes of the paper. MUMPS factorizes in parallel. "
      "GMRES is iterative, preconditioned by additive Schwarz with an exact "
      "(KLU) solve of each process's block: the blocks keep the saddle-point "
      "structure of the contact rows intact, which incomplete factorizations "
      "and AMG do not handle; on one process it is a direct solve. See "
      "doc/parallel.md for what each costs.");
    prm.declare_entry("Linear tolerance",
                      default_text(defaults.tolerance),
                      Patterns::Double(1e-300, 1),
                      "GMRES: solve to this fraction of the residual norm, "
                      "in (0, 1). Newton still converges to its own "
                      "tolerances (an inexact Newton method), only with more "
                      "iterations when this is large. Contact makes the "
                      "system ill-conditioned: below about 1e-8 GMRES can "
                      "fail with a loss of precision.");
    prm.declare_entry("Maximum linear iterations",
                      default_text(defaults.max_iterations),
                      Patterns::Integer(1),
                      "GMRES: iterations (restarted every 100) before the "
                      "solve counts as failed and the time step is cut.");
  }

  void
  LinearSolver::parse_parameters(ParameterHandler &prm, const bool verbose)
  {
    type           = solver_names.value(prm.get("Linear solver"));
    tolerance      = prm.get_double("Linear tolerance");
    max_iterations = prm.get_integer("Maximum linear iterations");
    this->verbose  = verbose;
  }

  void
  LinearSolver::release()
  {
    // the solver refers to its control, so it goes first
    direct_solver.reset();
    solver_control.reset();
    preconditioner.reset();
    factorization_valid = false;
  }

  void
  LinearSolver::factorize(const TrilinosWrappers::SparseMatrix &matrix)
  {
    release();
    if (type == Type::gmres)
      {
        preconditioner =
          std::make_unique<TrilinosWrappers::PreconditionBlockwiseDirect>();
        preconditioner->initialize(matrix);
        return;
      }
    solver_control = std::make_unique<SolverControl>(1, 0, false, false);
    direct_solver  = std::make_unique<TrilinosWrappers::SolverDirect>(
      *solver_control,
      TrilinosWrappers::SolverDirect::AdditionalData(false,
                                                     type == Type::mumps ?
                                                        "Amesos_Mumps" :
                                                        "Amesos_Klu"));
    direct_solver->initialize(matrix);
  }

  unsigned int
  LinearSolver::solve(const TrilinosWrappers::SparseMatrix &matrix,
                      TrilinosWrappers::MPI::Vector        &rhs,
                      TrilinosWrappers::MPI::Vector        &solution,
                      const double                          rhs_norm,
                      const bool                            keep)
  {
    if (!factorization_valid)
      {
        factorize(matrix);
        factorization_valid = keep;
      }
    rhs *= -1.;
    if (type == Type::gmres)
      return solve_gmres(matrix, rhs, solution, rhs_norm);
    direct_solver->solve(solution, rhs);
    return 0;
  }

  unsigned int
  LinearSolver::solve_gmres(const TrilinosWrappers::SparseMatrix &matrix,
                            const TrilinosWrappers::MPI::Vector  &rhs,
                            TrilinosWrappers::MPI::Vector        &solution,
                            const double rhs_norm) const
  {
    SolverControl control(max_iterations, tolerance * rhs_norm, false, false);
    TrilinosWrappers::SolverGMRES gmres(
      control,
      TrilinosWrappers::SolverGMRES::AdditionalData(verbose, 100));
    solution = 0;
    gmres.solve(matrix, solution, rhs, *preconditioner);
    return control.last_step();
  }
} // namespace ContactDynamics
