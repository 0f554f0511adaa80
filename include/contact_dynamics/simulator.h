// The time loop: owns the mesh, the unknowns and the pieces that act on
// them, advances Newmark steps with Newton and cuts the step on failure.
#ifndef contact_dynamics_simulator_h
#define contact_dynamics_simulator_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/lac/affine_constraints.h>

#include <contact_dynamics/contact/contact_formulation.h>
#include <contact_dynamics/mechanics/bodies.h>
#include <contact_dynamics/mechanics/body_state.h>
#include <contact_dynamics/mechanics/boundary_conditions.h>
#include <contact_dynamics/mechanics/discretization.h>
#include <contact_dynamics/mechanics/energy_account.h>
#include <contact_dynamics/mechanics/energy_watchdog.h>
#include <contact_dynamics/mechanics/solid_mechanics.h>
#include <contact_dynamics/mechanics/time_integrator.h>
#include <contact_dynamics/mechanics/time_step_controller.h>
#include <contact_dynamics/mesh/adaptation_schedule.h>
#include <contact_dynamics/mesh/contact_refinement.h>
#include <contact_dynamics/output/contact_writer.h>
#include <contact_dynamics/output/postprocessing.h>
#include <contact_dynamics/parallel.h>
#include <contact_dynamics/scenes/scene.h>
#include <contact_dynamics/solvers/nonlinear_solver.h>

#include <deal.II/distributed/shared_tria.h>
#include <fstream>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace ContactDynamics
{
  using namespace dealii;

  template <int dim>
  class Simulator : private NonlinearSystem
  {
  public:
    /** Declares every entry; the body subsections follow `layout`. */
    static void
    declare_parameters(ParameterHandler &prm, const SceneLayout &layout);

    /** Reads and checks all parameters (throws ExcMessage on bad input) and
     * builds the mesh; `screen` receives the progress output (from the
     * first process of `comm` only). */
    Simulator(ParameterHandler &prm,
              std::ostream     &screen,
              const MPI_Comm    comm = MPI_COMM_WORLD);

    /** Runs to the end time; throws if a step cannot be completed. With
     * `checkpoint` (a checkpoint directory, Checkpoints::find()), continues
     * the run that wrote it instead of starting at t = 0. */
    void
    run(const std::string &checkpoint = "");

    /** The energies, time and number of the last completed step. */
    const EnergyBalance &
    energy() const;
    double
    current_time() const;
    unsigned int
    n_steps() const;

    /** The degrees of freedom, the committed displacement and velocity. */
    const DoFHandler<dim> &
    get_dof_handler() const;
    const VectorType &
    displacement() const;
    const VectorType &
    velocity() const;

    /** Total reaction force on the Dirichlet degrees of freedom of a named
     * surface at the current time (force exerted by the support). */
    Tensor<1, dim>
    reaction_force(const std::string &surface) const;

    /** Constraints of the Newton increments: Dirichlet, unused multipliers
     * (homogeneous) and hanging nodes (those of all contact surface nodes). */
    const AffineConstraints<double> &
    get_constraints() const;

    /** The contact formulation, or nullptr without contact. */
    const ContactFormulation<dim> *
    get_contact() const;

    /** The mesh (for tests that set refinement flags). */
    parallel::TriangulationBase<dim> &
    get_triangulation();

    /** Refines and coarsens the distributed mesh as its cells are flagged;
     * the committed and the trial state move by interpolation, the contact
     * history is evaluated again (energy change: energy().transfer). False
     * (nothing done) if no cell is flagged. Collective. */
    bool
    refine_and_transfer();

    /** The number of mesh changes so far. */
    unsigned int
    n_mesh_changes() const;

    /** Sets up the unknowns and the initial state (called by run()). */
    void
    initialize();

    /** Instead of initialize(): continues from a checkpoint directory
     * (write_checkpoint(), the same model, any number of processes). */
    void
    restart(const std::string &checkpoint);

    /** A checkpoint of the last completed step in Output
     * directory/checkpoints (collective; Checkpoints); keeps the last two. */
    void
    write_checkpoint();

    /** One time step of size dt; false (state unchanged) if it failed:
     * predict(), solve(), evaluate(), then reject() or commit(). */
    bool
    advance(const double dt);

    /** For tests of the Jacobian: the residual of the current time step at
     * the displacement `trial` with time step dt, and the Jacobian there. */
    const MatrixType &
    residual_and_jacobian(const VectorType &trial,
                          const double      dt,
                          VectorType       &residual);

  private:
    /** The Newton solve of a step, over the meshes it was solved on. */
    struct SolveResult
    {
      NewtonSolver::Result newton;
      bool                 adapted = false; // on a mesh adapted to it
    };

    /** The trial state at t_new from the committed one. */
    void
    predict(const double t_new);
    /** Newton, and again on a mesh adapted to the step's contact. */
    SolveResult
    solve(const double t_new);
    /** Energies, checks of the converged state, the error estimate. */
    StepVerdict
    evaluate(const NewtonSolver::Result &result);
    /** The bulk forces M a_{n+1} + F_{n+1} of a balanced scheme. */
    void
    complete_balanced_forces();
    /** A failed or rejected step: the state stays, the screen says why. */
    void
    reject(const StepVerdict &verdict,
           const SolveResult &solved,
           const double       t_new);
    /** The trial state becomes the committed one (every owner). */
    void
    commit(const NewtonSolver::Result &result, const double t_new);
    /** run(): a signal stops the run between steps, with a checkpoint. */
    void
    stop_on_signal();
    /** run(): after an accepted step, the mesh, dt and checkpoint. */
    void
    after_accepted_step(const double dt_try);
    /** run(): after a failed or rejected step, the next dt. */
    void
    after_failed_step(const double dt_try);

    // NonlinearSystem
    void
    assemble(const bool  with_jacobian,
             VectorType &residual,
             MatrixType &jacobian) override;
    void
    apply_update(const VectorType &increment) override;
    bool
    has_multipliers() const override;
    std::vector<MultiplierGroup>
    multiplier_groups() const override;
    double
    iterate_norm() const override;
    bool
    jacobian_is_constant() const override;

    /** `first`: at the start; else after a mesh change (keeps the contact
     * history's totals, the output files); `sparsity`: false at a load. */
    void
    setup_system(const bool first = true, const bool sparsity = true);
    /** Marks the cells near the trial state's contact zone and
     * refine_and_transfer(). */
    bool
    adapt_mesh();
    /** The bulk forces of the committed state u, v, a into
     * residual_full_old: the reactions for the trapezoidal external work of
     * the next step. */
    void
    assemble_committed_reactions();
    /** Whether the scheme balances the forces between the steps. */
    bool
    balances_between_steps() const;
    /** The contact's view of the trial state u_ghost, v_ghost. */
    TrialState
    trial_state() const;
    /** force_old from residual_full_old and a. */
    void
    compute_old_forces();
    /** effective_acceleration from a and a_new. */
    void
    compute_effective_acceleration();
    /** The bulk reactions of the committed state and, with contact, its
     * history on a new mesh. */
    void
    reevaluate_committed_state();
    void
    setup_sparsity();
    /** The triangulation of the scene (constructor). */
    void
    create_mesh();
    /** The rigid-body modes of each body, for an algebraic multigrid. */
    void
    set_near_null_space();
    /** The constraints of the increments, and which dofs are held. */
    void
    setup_constraints();
    /** u and v at t = 0 from the bodies' initial conditions. */
    void
    interpolate_initial_state();
    /** Throws, naming the parameter, if an input of the initial state (body
     * force, initial conditions, Dirichlet values and rates) is not finite.
     */
    void
    check_initial_inputs(
      const std::map<types::global_dof_index, double> &u_dirichlet,
      const std::map<types::global_dof_index, double> &v_dirichlet,
      const std::map<types::global_dof_index, double> &a_dirichlet,
      const double                                     h) const;
    void
    apply_initial_conditions();
    /** a at t = 0 from M a = f_body - C v - f_int(u) (Dirichlet: given). */
    void
    solve_initial_acceleration(
      const std::map<types::global_dof_index, double> &a_dirichlet);
    /** Throws if the initial state overflowed. */
    void
    check_initial_state() const;
    /** The gaps at t = 0: overlapping bodies stop the run. */
    void
    check_initial_contact();
    void
    set_trial_velocity_and_acceleration();
    /** The stabilization 'velocity update' of a converged step (contact/
     * velocity_update.h); returns the kinetic energy change. */
    double
    apply_velocity_update();
    void
    write_solution();
    /** The columns of statistics.csv. */
    std::vector<std::string>
    statistics_columns() const;
    /** statistics.csv (continued if `append`) and the solution writer. */
    void
    open_output_files(const bool append);
    /** The scene, its size and the partition, on the screen. */
    void
    print_problem_size();
    /** The mesh, state and history of a checkpoint (`data`, read from
     * `checkpoint`); the output files are left as they are. */
    void
    load_checkpoint(const std::string &checkpoint, const CheckpointData &data);
    /** The checks of a restart before any file is touched. */
    void
    check_checkpoint(const std::string &checkpoint, CheckpointData &data) const;
    /** The files of the checkpoint `final` into `temporary`, renamed. */
    void
    write_checkpoint_files(const std::string &temporary,
                           const std::string &final);
    /** All of a checkpoint but its vectors. */
    void
    save_run(CheckpointData &data);
    /** Its vectors (the mesh file into `directory`); true if distributed. */
    bool
    save_vectors(CheckpointData &data, const std::string &directory);
    /** The vectors a checkpoint holds, in their order. */
    std::vector<VectorType *>
    checkpoint_vectors();
    void
    output_step(const unsigned int newton_iterations,
                const double       residual,
                const bool         force_vtu);

    /** A degree of freedom held fixed (Dirichlet or an unused multiplier),
     * not one that follows others (a hanging node). */
    bool
    is_held(const types::global_dof_index i) const;

    /** `x` with the ghost entries this process reads, in `ghost`. */
    const VectorType &
    ghosted(const VectorType &x, VectorType &ghost) const;
    /** Screen output of the root process; a sink on the others. */
    std::ostream &
    screen_log();

    /** Ends the run at the last completed step: its VTU files if the
     * interval skipped them, then throws ExcCollective with `reason` and
     * where the outputs are (or ExcStopped for a signal), then `epilogue`. */
    [[noreturn]] void
    stop_run(const std::string &reason,
             const int          signal   = 0,
             const std::string &epilogue = "");

    ConditionalOStream pcout;
    // created last by the constructor: a TimerOutput destroyed by an
    // exception prints a banner before the error message
    std::unique_ptr<TimerOutput> timer;

    Scene<dim>                  scene;
    SceneLayout                 layout;
    std::vector<BodyParameters> bodies;
    DirichletConditions<dim>    dirichlet;
    TimeIntegrator              integrator;
    // the Jacobian must outlive the factorization that refers to it
    MatrixType           jacobian;
    NewtonSolver         newton;
    OutputParameters     output_parameters;
    EnergyWatchdog       watchdog;
    bool                 small_strain_warned = false;
    RefinementParameters refinement;
    unsigned int         base_level = 0; // of the initial mesh
    AdaptationSchedule   adaptation;

    MPI_Comm                                          mpi_communicator;
    ParallelParameters                                parallel_parameters;
    std::unique_ptr<parallel::TriangulationBase<dim>> triangulation;
    std::unique_ptr<ContactFormulation<dim>>          contact;
    Discretization<dim>                               discretization;
    DoFHandler<dim>                                   dof_handler;
    IndexSet                                          locally_owned;
    // owned, neighbours of owned cells, and every contact surface dof
    IndexSet                  locally_relevant;
    AffineConstraints<double> increment_constraints;
    // hanging nodes only, with their inhomogeneities zero: for the state
    AffineConstraints<double> hanging_constraints;
    bool                      any_hanging_nodes = false; // on any process
    // Dirichlet dofs, and those plus the unused multipliers
    IndexSet dirichlet_dofs, held_dofs;
    /** Prescribed values at t into x, then the hanging nodes after them. */
    void
    set_prescribed_values(VectorType &x, const double t);
    std::unique_ptr<SolidMechanics<dim>> mechanics;

    // the owners of the history, registered in the order of a checkpoint's
    // vectors: the state of the bodies, the time-step control, the energies
    BodyState                   state;
    TimeStepController          controller{integrator};
    EnergyAccount<dim>          energy_account{integrator};
    HistoryRegistry<RunContext> history;
    // (the names the numerics use for the state's vectors)
    VectorType &u = state.u, &v = state.v, &a = state.a, &u_new = state.u_new,
               &v_new = state.v_new, &a_new = state.a_new;
    VectorType &residual_full          = state.residual_full,
               &residual_full_old      = state.residual_full_old;
    VectorType &force_old              = state.force_old,
               &effective_acceleration = state.effective_acceleration;
    // work vectors
    VectorType residual, increment, body_force;
    // ghosted: the trial state of the last assembly (committed to the
    // contact when the step converges), and scratch copies
    VectorType    u_ghost, v_ghost, scratch_ghost[2];
    std::ofstream null_stream; // never opened: discards what it gets

    double       time = 0;
    unsigned int step = 0;
    IndexSet     displacement_dofs; // locally owned
    // checkpoints: the parameters to store, the step of the last one and
    // the wall time since; whether this run continues a checkpoint
    std::string  parameters_text;
    int          last_checkpoint_step = -1;
    Timer        checkpoint_timer;
    bool         restarting        = false;
    unsigned int linear_iterations = 0; // GMRES, last step
    bool         structure_changed = true;
    int          last_vtu_step     = -1;
    std::string  last_failure;          // why the last failed step failed
    unsigned int failures_in_a_row = 0; // since the last committed step
    std::string  linear_solver_name;

    std::unique_ptr<StatisticsFile>      statistics;
    std::unique_ptr<SolutionWriter<dim>> solution_writer;
    std::unique_ptr<ContactWriter<dim>>  contact_writer;
    Timer                                wall_timer;
    double wall_time_before = 0; // of the runs this one continues
  };
} // namespace ContactDynamics

#endif
