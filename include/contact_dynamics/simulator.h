// The time loop: owns the mesh, the unknowns and the pieces that act on
// them, advances Newmark steps with Newton and cuts the step on failure.
#ifndef contact_dynamics_simulator_h
#define contact_dynamics_simulator_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_system.h>

#include <deal.II/lac/affine_constraints.h>

#include <contact_dynamics/contact/contact_formulation.h>
#include <contact_dynamics/mechanics/bodies.h>
#include <contact_dynamics/mechanics/boundary_conditions.h>
#include <contact_dynamics/mechanics/solid_mechanics.h>
#include <contact_dynamics/mechanics/time_integrator.h>
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

  /** Energies of the discrete system; see doc/theory.md. */
  struct EnergyBalance
  {
    double kinetic    = 0;
    double elastic    = 0;
    double dissipated = 0; // time integral of v.C v
    double external   = 0; // work of reactions and body forces
    double initial    = 0; // kinetic + elastic at t = 0
    double frictional = 0; // dissipated by contact friction
    double obstacle   = 0; // work of moving rigid obstacles on the bodies
    double transfer   = 0; // energy change of the mesh transfers
    // removed by the time integrator from the bulk (dissipative schemes)
    double numerical = 0;

    double
    error() const
    {
      return kinetic + elastic + dissipated + frictional + numerical -
             external - obstacle - transfer - initial;
    }
  };

  template <int dim>
  class Simulator : private NonlinearSystem
  {
  public:
    /** Declares every entry; the body subsections follow `layout`. */
    static void
    declare_parameters(ParameterHandler &prm, const SceneLayout &layout);

    /**
     * Reads and checks all parameters (throws ExcMessage on bad input) and
     * builds the mesh; `screen` receives the progress output (from the
     * first process of `comm` only).
     */
    Simulator(ParameterHandler &prm,
              std::ostream     &screen,
              const MPI_Comm    comm = MPI_COMM_WORLD);

    /**
     * Runs to the end time; throws if a step cannot be completed. With
     * `checkpoint` (a checkpoint directory, Checkpoints::find()), continues
     * the run that wrote it instead of starting at t = 0.
     */
    void
    run(const std::string &checkpoint = "");

    const EnergyBalance &
    energy() const
    {
      return energies;
    }

    double
    current_time() const
    {
      return time;
    }

    unsigned int
    n_steps() const
    {
      return step;
    }

    const DoFHandler<dim> &
    get_dof_handler() const
    {
      return dof_handler;
    }

    /**
     * Total reaction force on the Dirichlet degrees of freedom of a named
     * surface at the current time (force exerted by the support).
     */
    Tensor<1, dim>
    reaction_force(const std::string &surface) const;

    /**
     * Constraints of the Newton increments: Dirichlet, unused multipliers
     * (homogeneous) and hanging nodes (those of all contact surface nodes).
     */
    const AffineConstraints<double> &
    get_constraints() const
    {
      return increment_constraints;
    }

    /** The contact formulation, or nullptr without contact. */
    const ContactFormulation<dim> *
    get_contact() const
    {
      return contact.get();
    }

    const VectorType &
    displacement() const
    {
      return u;
    }

    const VectorType &
    velocity() const
    {
      return v;
    }

    /** The mesh (for tests that set refinement flags). */
    parallel::TriangulationBase<dim> &
    get_triangulation()
    {
      return *triangulation;
    }

    /**
     * Refines and coarsens the distributed mesh as its cells are flagged
     * and transfers the state to the new mesh: displacement, velocity and
     * acceleration (and the trial state of the step, with its multipliers)
     * by interpolation; the contact history is evaluated again at the
     * committed state. The energy change is added to energy().transfer.
     * False (nothing done) if no cell is flagged after the mesh's own
     * rules. Collective.
     */
    bool
    refine_and_transfer();

    /** The number of mesh changes so far. */
    unsigned int
    n_mesh_changes() const
    {
      return mesh_changes;
    }

    /** Sets up the unknowns and the initial state (called by run()). */
    void
    initialize();

    /**
     * Instead of initialize(): the mesh, state, history and output
     * positions of a checkpoint directory (written by write_checkpoint()
     * with the same model parameters, on any number of processes).
     */
    void
    restart(const std::string &checkpoint);

    /**
     * Writes a checkpoint of the last completed step to Output
     * directory/checkpoints (collective; see Checkpoints) and keeps the
     * last two.
     */
    void
    write_checkpoint();

    /** One time step of size dt; false (state unchanged) if it failed. */
    bool
    advance(const double dt);

    /**
     * For tests of the Jacobian: the residual of the current time step at
     * the displacement `trial` with time step dt, and the Jacobian there.
     */
    const MatrixType &
    residual_and_jacobian(const VectorType &trial,
                          const double      dt,
                          VectorType       &residual);

  private:
    // NonlinearSystem
    void
    assemble(const bool  with_jacobian,
             VectorType &residual,
             MatrixType &jacobian) override;
    void
    apply_update(const VectorType &increment) override;

    bool
    has_multipliers() const override
    {
      return contact != nullptr;
    }
    std::vector<MultiplierGroup>
    multiplier_groups() const override;

    double
    iterate_norm() const override
    {
      return u_new.l2_norm();
    }
    bool
    jacobian_is_constant() const override;

    /** `first`: at the start; else after a mesh change (keeps the contact
     * history's totals and the output files). */
    void
    setup_system(const bool first = true);
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
    balances_between_steps() const
    {
      return integrator.alpha_m() != 0 || integrator.alpha_f() != 0;
    }
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
    void
    set_trial_velocity_and_acceleration();
    /**
     * Stabilization 'velocity update': after a converged step, one factor
     * on the free velocities of the bodies the contact acted on returns the
     * step's normal contact work to kinetic energy; returns the kinetic
     * energy change.
     */
    double
    apply_velocity_update();
    /** The local error estimate of the trial step (Time
     * integration/Error tolerance): the largest over the free displacement
     * unknowns. Collective. */
    double
    local_error_estimate();
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
    /** The vectors a checkpoint holds, in their order. */
    std::vector<VectorType *>
    checkpoint_vectors();
    /** A replicated mesh: every degree of freedom in the order of the cells
     * (the same on any number of processes), for a checkpoint. */
    std::vector<types::global_dof_index>
    cell_order_of_dofs() const;
    void
    output_step(const unsigned int newton_iterations,
                const double       residual,
                const bool         force_vtu);

    /** A degree of freedom held fixed (Dirichlet or an unused multiplier),
     * not one that follows others (a hanging node). */
    bool
    is_held(const types::global_dof_index i) const
    {
      return held_dofs.is_element(i);
    }

    /** `x` with the ghost entries this process reads, in `ghost`. */
    const VectorType &
    ghosted(const VectorType &x, VectorType &ghost) const;

    /** Screen output of the root process; a sink on the others. */
    std::ostream &
    screen_log();

    /**
     * Corners of neo-Hookean elements where det F <= 0 in the trial state
     * u_ghost: "" if none, else what and where (the same on every process).
     * The quadrature points can all be fine while a corner is inverted, and
     * the stresses written there would be NaN.
     */
    std::string
    inverted_corner() const;

    /**
     * Ends the run at the last completed step: writes its VTU files if the
     * interval skipped them, then throws ExcCollective with `reason` and
     * where the outputs are (or ExcStopped for a signal), then `epilogue`.
     */
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
    RefinementParameters refinement;
    unsigned int         base_level          = 0; // of the initial mesh
    unsigned int         mesh_changes        = 0;
    bool                 cell_limit_reported = false;
    // active contact nodes at the last and the one before committed steps
    unsigned int committed_active_nodes = 0, previous_active_nodes = 0;
    /** Whether the mesh is to be adapted after step `completed` (Interval,
     * On contact change: `active` against `active_before`). */
    bool
    adaptation_due(const unsigned int completed,
                   const unsigned int active,
                   const unsigned int active_before) const
    {
      return completed % refinement.interval == 0 ||
             (refinement.on_contact_change && active != active_before);
    }

    MPI_Comm                                          mpi_communicator;
    ParallelParameters                                parallel_parameters;
    std::unique_ptr<parallel::TriangulationBase<dim>> triangulation;
    std::unique_ptr<ContactFormulation<dim>>          contact;
    std::unique_ptr<FESystem<dim>>                    fe;
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
    /** Prescribed values at t into x, then the hanging nodes that follow
     * them. */
    void
    set_prescribed_values(VectorType &x, const double t);
    std::unique_ptr<SolidMechanics<dim>> mechanics;

    // state at t_n, the trial state at t_{n+1}, and work vectors
    VectorType u, v, a, u_new, v_new, a_new;
    VectorType residual, residual_full, residual_full_old, increment,
      body_force;
    // generalized-alpha and HHT: the forces F_n of the committed state
    // (residual_full_old without M a_n) and the balanced acceleration
    VectorType force_old, effective_acceleration;
    // ghosted: the trial state of the last assembly (committed to the
    // contact when the step converges), and scratch copies
    VectorType    u_ghost, v_ghost, scratch_ghost[2];
    std::ofstream null_stream; // never opened: discards what it gets

    double       time                         = 0;
    double       dt_current                   = 0;
    unsigned int step                         = 0;
    unsigned int cumulative_newton_iterations = 0;
    unsigned int time_step_cuts               = 0;
    // adaptive time steps (Time integration/Error tolerance): the local
    // error estimate of the last converged step, the factor for the next
    // dt, whether the last attempt was rejected by it, and how many were
    double       error_estimate       = 0;
    double       step_factor          = 1;
    bool         rejected_by_estimate = false;
    unsigned int rejected_steps       = 0;
    IndexSet     displacement_dofs; // locally owned
    // the mean accelerations (v_{n+1} - v_n) / dt of the trial step and of
    // the step before (its length dt_before), if that was on this mesh
    VectorType mean_acceleration, mean_acceleration_before;
    double     dt_before              = 0;
    bool       have_mean_acceleration = false;
    // the time-step controller of run(): the next dt, good steps since a
    // Newton failure (two kinds of counting)
    double       dt_next        = 0;
    unsigned int good_since_cut = 0;
    unsigned int cut_since      = 2;
    // checkpoints: the parameters to store, the step of the last one and
    // the wall time since; whether this run continues a checkpoint
    std::string   parameters_text;
    int           last_checkpoint_step = -1;
    Timer         checkpoint_timer;
    bool          restarting        = false;
    unsigned int  linear_iterations = 0; // GMRES, last step
    bool          structure_changed = true;
    int           last_vtu_step     = -1;
    std::string   last_failure; // why the last failed step failed
    std::string   linear_solver_name;
    EnergyBalance energies;

    std::unique_ptr<StatisticsFile>      statistics;
    std::unique_ptr<SolutionWriter<dim>> solution_writer;
    std::unique_ptr<ContactWriter<dim>>  contact_writer;
    Timer                                wall_timer;
    double wall_time_before = 0; // of the runs this one continues
  };
} // namespace ContactDynamics

#endif
