#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector_memory.h>

#include <contact_dynamics/parameters.h>
#include <contact_dynamics/solvers/linear_solver.h>

#include <algorithm>

namespace ContactDynamics
{
  namespace
  {
    const Selection<LinearSolver::Type> solver_names{
      {LinearSolver::Type::klu, "KLU"},
      {LinearSolver::Type::umfpack, "UMFPACK"},
      {LinearSolver::Type::mumps, "MUMPS"},
      {LinearSolver::Type::gmres, "GMRES"},
      {LinearSolver::Type::amg, "AMG"},
      {LinearSolver::Type::automatic, "auto"}};
    // measured crossover (doc/solvers.md): in dynamics AMG is as fast as
    // KLU at about 40k unknowns and 1.3 times faster at 133k; in
    // quasi-static contact KLU stays faster up to 222k
    constexpr unsigned long amg_threshold     = 80000;
    constexpr unsigned long umfpack_threshold = 20000;
    // 3-D (doc/solvers.md, 'Direct solvers by dimension'): KLU's fill
    // grows too fast, UMFPACK wins from the smallest scenes on, with METIS
    // from about 80k unknowns on (AMD is faster at 52k), where AMG and UMFPACK
    // cross too
    constexpr unsigned long metis_threshold_3d = 80000;

    // ML's smoothers: Chebyshev (two sweeps) is the cheaper cycle where the
    // mass term helps (dynamics); symmetric Gauss-Seidel (three sweeps)
    // halves the GMRES iterations on quasi-static contact and keeps their
    // growth near 1.2 per refinement (doc/solvers.md)
    const Selection<LinearSolver::SmootherChoice> smoother_names{
      {LinearSolver::SmootherChoice::automatic, "auto"},
      {LinearSolver::SmootherChoice::chebyshev, "Chebyshev"},
      {LinearSolver::SmootherChoice::gauss_seidel, "symmetric Gauss-Seidel"}};

    const Selection<LinearSolver::Ordering> ordering_names{
      {LinearSolver::Ordering::automatic, "auto"},
      {LinearSolver::Ordering::amd, "AMD"},
      {LinearSolver::Ordering::metis, "METIS"}};
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
      "KLU, UMFPACK and MUMPS are sparse direct solvers. KLU (SuiteSparse) "
      "factorizes, in 3-D, the matrix's nonzero entries only (the contact "
      "pattern reserves couplings for nodes out of contact), keeps its "
      "analysis while the nonzeros stay inside the analysed ones and "
      "refactorizes with the pivot order of its last full factorization "
      "while the pivots stay within a factor 1000 of the conditioning they "
      "had (the fastest below about 20,000 unknowns); with mpirun it is "
      "Trilinos Amesos KLU on the matrix gathered on one process. UMFPACK (SuiteSparse, multifrontal with BLAS) runs on one "
      "process only and keeps its symbolic analysis likewise: with an "
      "optimized BLAS (OpenBLAS) it is "
      "the fastest direct solver from about 20,000 unknowns on. MUMPS "
      "(Amesos) factorizes in parallel. "
      "GMRES is iterative, preconditioned by additive Schwarz with an exact "
      "(KLU) solve of each process's block: the blocks keep the saddle-point "
      "structure of the contact rows intact, which incomplete factorizations "
      "and AMG do not handle; on one process it is a direct solve. AMG is "
      "GMRES preconditioned by Trilinos ML smoothed aggregation with the "
      "rigid-body modes of each body as near-null space, on the system "
      "with the contact multipliers condensed (Condense multipliers is "
      "implied); the hierarchy is reused while GMRES needs at most twice "
      "the iterations it needed after its build. See doc/parallel.md and "
      "doc/solvers.md for what each costs. auto: AMG for dynamic problems "
      "of at least 80,000 unknowns; below, in 2-D UMFPACK on one process "
      "from 20,000 unknowns and KLU otherwise, in 3-D UMFPACK on one "
      "process and MUMPS on several (KLU's fill grows too fast in 3-D: "
      "2.5 times UMFPACK's time on the 16k 3-D ironing). The crossovers are "
      "measured in doc/solvers.md; the run's log says which solver runs.");
    prm.declare_entry(
      "Linear tolerance",
      default_text(defaults.tolerance),
      Patterns::Double(1e-300, 0.5),
      "GMRES: solve to this fraction of the residual norm, "
      "in (0, 0.5] (1 would be no reduction at all). Newton still converges to its own "
      "tolerances (an inexact Newton method), only with more "
      "iterations when this is large. Contact makes the "
      "system ill-conditioned: below about 1e-8 GMRES can "
      "fail with a loss of precision.");
    prm.declare_entry(
      "Direct solver ordering",
      ordering_names.name(defaults.ordering),
      ordering_names.pattern(),
      "UMFPACK's fill-reducing ordering, which decides the fill of the "
      "factors and hence the cost of each factorization: AMD (approximate "
      "minimum degree) or METIS (nested dissection). auto: METIS in 3-D "
      "from 80,000 unknowns, AMD otherwise. Measured on the 3-D ironing "
      "(doc/solvers.md, 'Direct solvers by dimension'): METIS needs 0.6 of "
      "AMD's flops at 105k unknowns and 9 % less time per factorization "
      "and less memory for the factors; at 16k it takes as long (small "
      "fronts), in 2-D the two are within noise. KLU orders with AMD always.");
    prm.declare_entry("Maximum linear iterations",
                      default_text(defaults.max_iterations),
                      Patterns::Integer(1),
                      "GMRES: iterations (restarted every 100) before the "
                      "solve counts as failed and the time step is cut.");
    declare_amg_parameters(prm);
  }

  void
  LinearSolver::declare_amg_parameters(ParameterHandler &prm)
  {
    const LinearSolver defaults;
    prm.declare_entry(
      "AMG contact elimination",
      default_text(defaults.eliminate_constrained),
      Patterns::Bool(),
      "AMG: GMRES solves the condensed system with each secondary node "
      "that carries a contact constraint (an active normal or a sticking "
      "tangential condition) rotated into the frame of its multiplier "
      "block (normal, tangents); the ML hierarchy is built on a copy with "
      "the constrained components removed from rows and columns, the "
      "rigid-body modes rotated alike, and rebuilt when that set changes; "
      "each multigrid cycle is followed by the constraint rows, solved for "
      "their component given the others. The Newton iterates are those of "
      "the condensed system either way. Without it (false) the row-replaced "
      "operator defeats the aggregation as the contact grows. Measured "
      "(doc/solvers.md): the 2-D ironing (34k unknowns, t in [0, 1]) needs "
      "20.7 instead of 44.0 GMRES iterations per Newton iteration (linear "
      "solve 0.69 of the time); the 3-D ironing (16k, indentation) 26.3 "
      "instead of 28.0 (0.75). If GMRES fails in the frames even with a new "
      "hierarchy (seen with 3-D friction), the run goes on with the plain "
      "hierarchy.");
    prm.declare_entry(
      "AMG smoother",
      smoother_names.name(defaults.smoother_choice),
      smoother_names.pattern(),
      "AMG: ML's smoother on every level. Chebyshev (a polynomial in the "
      "diagonally scaled matrix) or symmetric Gauss-Seidel (on each "
      "process's rows). auto: Chebyshev for dynamic problems, symmetric "
      "Gauss-Seidel for quasi-static ones. Measured (doc/solvers.md, "
      "doc/krylov-growth-table.md): on the quasi-static Hertz cylinder "
      "(15k, 56k, 220k unknowns) symmetric Gauss-Seidel with 3 sweeps "
      "needs 14.6, 17.4 and 20.4 GMRES iterations per Newton iteration "
      "where Chebyshev needs 28.8, 36.1 and 46.8 (growth 1.2 per "
      "refinement against 1.3), in about the same time at these sizes; "
      "in dynamics Chebyshev's cheaper cycle is 2.5 times faster (2-D "
      "ironing).");
    prm.declare_entry(
      "AMG smoother sweeps",
      default_text(defaults.smoother_sweeps),
      Patterns::Integer(0, 20),
      "AMG: sweeps of the smoother before and after each coarse "
      "correction (for Chebyshev its polynomial degree), in [0, 20]; 0: "
      "2 for Chebyshev, 3 for symmetric Gauss-Seidel. More sweeps cost "
      "more per cycle and save GMRES iterations.");
  }

  void
  LinearSolver::parse_parameters(ParameterHandler &prm, const bool verbose)
  {
    requested      = solver_names.value(prm.get("Linear solver"));
    type           = requested == Type::automatic ? Type::klu : requested;
    tolerance      = prm.get_double("Linear tolerance");
    max_iterations = prm.get_integer("Maximum linear iterations");
    eliminate_constrained = prm.get_bool("AMG contact elimination");
    smoother_choice       = smoother_names.value(prm.get("AMG smoother"));
    smoother_sweeps       = prm.get_integer("AMG smoother sweeps");
    ordering      = ordering_names.value(prm.get("Direct solver ordering"));
    this->verbose = verbose;
  }

  std::string
  LinearSolver::choose(const unsigned long n_unknowns,
                       const bool          dynamic,
                       const unsigned int  n_processes,
                       const unsigned int  dim)
  {
    AssertThrow(requested != Type::umfpack || n_processes == 1,
                ExcMessage("Nonlinear solver/Linear solver = UMFPACK runs on "
                           "one process, and this run has " +
                           std::to_string(n_processes) +
                           ": use KLU, MUMPS, GMRES, AMG or auto."));
    if (requested == Type::automatic)
      {
        release();
        if (dynamic && n_unknowns >= amg_threshold)
          type = Type::amg;
        else if (n_processes == 1 &&
                 (dim == 3 || n_unknowns >= umfpack_threshold))
          type = Type::umfpack;
        else if (dim == 3)
          type = Type::mumps;
        else
          type = Type::klu;
      }
    const bool gauss_seidel =
      smoother_choice == SmootherChoice::gauss_seidel ||
      (smoother_choice == SmootherChoice::automatic && !dynamic);
    smoother.type    = gauss_seidel ? "symmetric Gauss-Seidel" : "Chebyshev";
    smoother.sweeps  = smoother_sweeps > 0 ? smoother_sweeps :
                       gauss_seidel        ? 3 :
                                             2;
    const bool metis = ordering == Ordering::metis ||
                       (ordering == Ordering::automatic && dim == 3 &&
                        n_unknowns >= metis_threshold_3d);
    umfpack.set_ordering(metis ? DirectFactorization::Ordering::metis :
                                 DirectFactorization::Ordering::amd);
    // (in 3-D the zeros of the contact pattern are most of the matrix; in
    // 2-D a few percent, where leaving them out saves about 5 % and
    // changes round-off, which the 2-D ironing amplifies: doc/solvers.md)
    for (auto *direct : {&umfpack, &klu})
      direct->set_skip_zeros(dim == 3);
    return solver_names.name(type);
  }

  void
  LinearSolver::set_near_null_space(std::vector<std::vector<double>> modes,
                                    const unsigned int dofs_per_vertex)
  {
    n_modes               = modes.size();
    this->dofs_per_vertex = dofs_per_vertex;
    null_space.clear();
    for (const auto &mode : modes)
      null_space.insert(null_space.end(), mode.begin(), mode.end());
    // new unknowns (a mesh change): no hierarchy of the old ones survives,
    // the frames' one included (its constrained components can compare
    // equal across a mesh change, none in both, say)
    amg.reset();
    amg_matrix.reset();
    frame_multigrid.reset();
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
  LinearSolver::reset()
  {
    release();
    umfpack.clear();
    klu.clear();
    klu.pivot_anew();
    amg.reset();
    amg_matrix.reset();
    frame_multigrid.reset();
    frames_failed          = false;
    iterations_after_build = 0;
    rebuild_amg            = false;
  }

  void
  LinearSolver::factorize(const TrilinosWrappers::SparseMatrix &matrix)
  {
    release();
    if (type == Type::amg)
      return;
    if (type == Type::umfpack)
      {
        umfpack.factorize(matrix);
        return;
      }
    use_own_klu = type == Type::klu && Utilities::MPI::n_mpi_processes(
                                         matrix.get_mpi_communicator()) == 1;
    if (use_own_klu)
      {
        klu.factorize(matrix);
        return;
      }
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
    if (type == Type::amg)
      return solve_amg(matrix, rhs, solution, rhs_norm);
    if (type == Type::gmres)
      return solve_gmres(matrix, rhs, solution, rhs_norm);
    if (type == Type::umfpack)
      umfpack.solve(rhs, solution);
    else if (use_own_klu)
      klu.solve(rhs, solution);
    else
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

  unsigned int
  LinearSolver::solve_amg(const TrilinosWrappers::SparseMatrix &matrix,
                          const TrilinosWrappers::MPI::Vector  &rhs,
                          TrilinosWrappers::MPI::Vector        &solution,
                          const double                          rhs_norm)
  {
    if (eliminate_constrained && !frames_failed)
      try
        {
          return solve_in_frames(matrix, rhs, solution);
        }
      catch (const SolverControl::NoConvergence &)
        {
          // (collective: GMRES fails on every process) 3-D friction can
          // defeat it (doc/solvers.md): the row-replaced hierarchy for the
          // rest of the run
          frames_failed = true;
        }
    const auto build = [&]() {
      // ML's destruction reads its matrix (IFPACK's smoothers do)
      amg.reset();
      amg_matrix = std::make_unique<TrilinosWrappers::SparseMatrix>();
      amg_matrix->copy_from(matrix);
      amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
      initialize_amg(*amg,
                     *amg_matrix,
                     null_space,
                     n_modes,
                     dofs_per_vertex,
                     smoother);
      ++amg_builds;
      iterations_after_build = 0;
    };
    if (!amg || rebuild_amg)
      build();
    rebuild_amg = false;
    SolverControl control(max_iterations, tolerance * rhs_norm, false, false);
    TrilinosWrappers::SolverGMRES gmres(
      control,
      TrilinosWrappers::SolverGMRES::AdditionalData(verbose, 100));
    const auto attempt = [&]() {
      solution = 0;
      try
        {
          gmres.solve(matrix, solution, rhs, *amg);
          return true;
        }
      catch (const std::exception &)
        {
          return false;
        }
    };
    if (!attempt())
      {
        // an old hierarchy that no longer works: once more with a new one
        build();
        solution = 0;
        gmres.solve(matrix, solution, rhs, *amg);
      }
    if (iterations_after_build == 0)
      iterations_after_build = std::max(1u, control.last_step());
    else if (control.last_step() > 2 * iterations_after_build)
      rebuild_amg = true;
    return control.last_step();
  }

  unsigned int
  LinearSolver::solve_in_frames(const TrilinosWrappers::SparseMatrix &matrix,
                                const TrilinosWrappers::MPI::Vector  &rhs,
                                TrilinosWrappers::MPI::Vector        &solution)
  {
    if (!frame_multigrid)
      frame_multigrid = std::make_unique<ContactFrameMultigrid>();
    ContactFrameMultigrid &multigrid = *frame_multigrid;
    multigrid.transform(matrix, rhs, frames);
    const auto build = [&]() {
      multigrid.build(null_space, n_modes, dofs_per_vertex, smoother);
      ++amg_builds;
      iterations_after_build = 0;
    };
    // (collective: every process builds, or none)
    if (multigrid.needs_build() || rebuild_amg)
      build();
    rebuild_amg                            = false;
    const TrilinosWrappers::MPI::Vector &b = multigrid.rhs();
    SolverControl                        control(max_iterations,
                          tolerance * b.l2_norm(),
                          false,
                          false);
    // right preconditioning: the stopping test sees the true residual
    SolverGMRES<TrilinosWrappers::MPI::Vector> gmres(
      control,
      SolverGMRES<TrilinosWrappers::MPI::Vector>::AdditionalData(102, true));
    TrilinosWrappers::MPI::Vector y(b);
    const auto                    attempt = [&]() {
      y = 0;
      gmres.solve(multigrid.matrix(), y, b, multigrid);
    };
    try
      {
        attempt();
      }
    catch (const SolverControl::NoConvergence &)
      {
        // an old hierarchy that no longer works: once more with a new one
        build();
        attempt();
      }
    multigrid.back_transform(y, solution);
    if (iterations_after_build == 0)
      iterations_after_build = std::max(1u, control.last_step());
    else if (control.last_step() > 2 * iterations_after_build)
      rebuild_amg = true;
    return control.last_step();
  }
} // namespace ContactDynamics
