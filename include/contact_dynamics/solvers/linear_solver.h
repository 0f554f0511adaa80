// The linear solve of a Newton iteration: a sparse direct solver (KLU or
// UMFPACK on one process, Trilinos Amesos KLU or MUMPS), GMRES with a
// block-wise direct preconditioner, or GMRES with ML algebraic multigrid,
// chosen when the parameters are read (or by size for 'auto'), with the reuse
// of a factorization or hierarchy across solves behind one interface.
#ifndef contact_dynamics_solvers_linear_solver_h
#define contact_dynamics_solvers_linear_solver_h

#include <deal.II/base/types.h>

#include <contact_dynamics/solvers/contact_frame_multigrid.h>
#include <contact_dynamics/solvers/direct_factorization.h>
#include <contact_dynamics/solvers/trilinos_forward.h>

#include <memory>
#include <string>
#include <vector>


namespace ContactDynamics
{
  using namespace dealii;

  class LinearSolver
  {
  public:
    enum class Type
    {
      klu,
      umfpack,
      mumps,
      gmres,
      amg,
      automatic // resolved by choose(): UMFPACK, KLU, MUMPS or AMG
    };

    // UMFPACK's ordering: `automatic` is METIS in 3-D and AMD in 2-D
    enum class Ordering
    {
      automatic,
      amd,
      metis
    };

    // AMG's smoother: `automatic` is Chebyshev in dynamics, symmetric
    // Gauss-Seidel for quasi-static problems
    enum class SmootherChoice
    {
      automatic,
      chebyshev,
      gauss_seidel
    };

    LinearSolver();
    ~LinearSolver();

    /** Entries of the `Nonlinear solver` subsection that concern it. */
    static void
    declare_parameters(ParameterHandler &prm);
    /** `verbose`: GMRES prints its iterations. */
    void
    parse_parameters(ParameterHandler &prm, const bool verbose);

    /**
     * AMG: the near-null space (rigid-body modes per body), each vector
     * over the locally owned dofs, and the number of dofs per vertex.
     */
    void
    set_near_null_space(std::vector<std::vector<double>> modes,
                        const unsigned int               dofs_per_vertex);

    /**
     * `Linear solver = auto`: AMG for dynamic problems of at least
     * `amg_threshold` unknowns; otherwise in 2-D UMFPACK on one process
     * from `umfpack_threshold` unknowns and KLU below or on several
     * processes, in 3-D UMFPACK on one process (METIS ordering from
     * `metis_threshold_3d` unknowns) and MUMPS on several (doc/solvers.md
     * has the measured crossovers). Returns the name of the solver used.
     * Resolves `AMG smoother = auto` by `dynamic` as well. Throws if
     * UMFPACK is asked for on several processes.
     */
    std::string
    choose(const unsigned long n_unknowns,
           const bool          dynamic,
           const unsigned int  n_processes,
           const unsigned int  dim);

    /**
     * AMG: the condensed nodes of the next (condensed) matrix in their
     * frames (MultiplierCondensation::node_frames()). With `AMG contact
     * elimination`, GMRES solves the system in these frames, preconditioned
     * by ContactFrameMultigrid.
     */
    void
    set_node_frames(const std::vector<NodeFrame> &node_frames)
    {
      frames = node_frames;
    }

    /** The solver works best on a displacement-only (condensed) matrix. */
    bool
    wants_condensed_matrix() const
    {
      return type == Type::amg;
    }

    /** The next solve needs a matrix: there is no valid factorization. */
    bool
    needs_matrix() const
    {
      return !factorization_valid;
    }

    /** The matrix changed: factorize it anew at the next solve. */
    void
    invalidate()
    {
      factorization_valid = false;
    }

    /**
     * A Newton solve failed: besides invalidate(), KLU searches its pivots
     * anew at the next factorization.
     */
    void
    invalidate_after_failure()
    {
      invalidate();
      klu.pivot_anew();
    }

    /**
     * Solves matrix * solution = -rhs, negating `rhs` in place, and
     * returns the number of GMRES iterations (0 for a direct solve).
     * Factorizes `matrix` first when needs_matrix(); `keep` lets the
     * following solves reuse that factorization (the matrix is constant).
     * GMRES stops at tolerance times `rhs_norm`, the l2 norm of `rhs`.
     * Throws if the solver fails.
     */
    unsigned int
    solve(const TrilinosWrappers::SparseMatrix &matrix,
          TrilinosWrappers::MPI::Vector        &rhs,
          TrilinosWrappers::MPI::Vector        &solution,
          const double                          rhs_norm,
          const bool                            keep);

    /**
     * Forgets the factorization. Must be called before the matrix is
     * reinitialized with a new sparsity pattern: the direct solver keeps a
     * pointer to the matrix, and MUMPS touches it when it is destroyed.
     */
    void
    release();

    /**
     * Forgets everything kept from earlier solves: the factorization, the
     * symbolic analysis, KLU's pivot order and the multigrid hierarchy. A
     * run does this at each checkpoint, so that a run restarted there
     * solves exactly as the one that wrote it.
     */
    void
    reset();

  private:
    static void
    declare_amg_parameters(ParameterHandler &prm);

    void
    factorize(const TrilinosWrappers::SparseMatrix &matrix);

    unsigned int
    solve_gmres(const TrilinosWrappers::SparseMatrix &matrix,
                const TrilinosWrappers::MPI::Vector  &rhs,
                TrilinosWrappers::MPI::Vector        &solution,
                const double                          rhs_norm) const;

    Type         type           = Type::automatic;
    Type         requested      = Type::automatic;
    double       tolerance      = 1e-6;
    unsigned int max_iterations = 1000;
    bool         verbose        = false;
    Ordering     ordering       = Ordering::automatic;

    std::unique_ptr<SolverControl>                  solver_control;
    std::unique_ptr<TrilinosWrappers::SolverDirect> direct_solver;
    // on one process, kept across factorizations: the symbolic analysis
    // (and KLU's pivot order) is reused
    DirectFactorization umfpack{DirectFactorization::Method::umfpack};
    DirectFactorization klu{DirectFactorization::Method::klu};
    bool                use_own_klu = false;
    std::unique_ptr<TrilinosWrappers::PreconditionBlockwiseDirect>
         preconditioner;
    bool factorization_valid = false;

    // AMG: the hierarchy is built on a copy of a matrix and reused for the
    // following matrices while GMRES needs at most twice the iterations it
    // needed right after the build
    unsigned int
    solve_amg(const TrilinosWrappers::SparseMatrix &matrix,
              const TrilinosWrappers::MPI::Vector  &rhs,
              TrilinosWrappers::MPI::Vector        &solution,
              const double                          rhs_norm);
    // (in this order: the hierarchy goes before its matrix)
    std::unique_ptr<TrilinosWrappers::SparseMatrix>    amg_matrix;
    std::unique_ptr<TrilinosWrappers::PreconditionAMG> amg;
    std::vector<double>                                null_space;
    unsigned int                                       n_modes         = 0;
    unsigned int                                       dofs_per_vertex = 1;
    unsigned int iterations_after_build                                = 0;
    bool         eliminate_constrained                                 = true;
    SmootherChoice smoother_choice = SmootherChoice::automatic;
    unsigned int   smoother_sweeps = 0;
    // resolved by choose()
    AmgSmoother smoother;
    // of the next matrix; the multigrid in their frames
    std::vector<NodeFrame>                 frames;
    std::unique_ptr<ContactFrameMultigrid> frame_multigrid;
    // GMRES failed in the frames even with a new hierarchy: until reset()
    bool frames_failed = false;
    unsigned int
                 solve_in_frames(const TrilinosWrappers::SparseMatrix &matrix,
                                 const TrilinosWrappers::MPI::Vector  &rhs,
                                 TrilinosWrappers::MPI::Vector        &solution);
    unsigned int amg_builds  = 0;
    bool         rebuild_amg = false;
  };
} // namespace ContactDynamics

#endif
