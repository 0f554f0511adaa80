// The interface every contact formulation implements (its parameters and
// the states it reports are in contact_parameters.h and contact_states.h).
#ifndef contact_dynamics_contact_contact_formulation_h
#define contact_dynamics_contact_contact_formulation_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <contact_dynamics/contact/contact_parameters.h>
#include <contact_dynamics/contact/contact_states.h>
#include <contact_dynamics/solvers/multiplier_condensation.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace dealii
{
  template <int dim, int spacedim>
  class Mapping;
}

namespace ContactDynamics
{
  using namespace dealii;
  class CheckpointData;

  template <int dim>
  class ContactFormulation
  {
  public:
    virtual ~ContactFormulation() = default;

    /** Vector components the formulation adds to the displacement. */
    virtual unsigned int
    n_extra_components() const = 0;

    /** Names of the extra components in the output. */
    virtual std::vector<std::string>
    extra_component_names() const = 0;

    /**
     * After distribute_dofs: surfaces (placed by the cells' `mapping`) and
     * degree-of-freedom maps.
     */
    virtual void
    setup(const DoFHandler<dim>   &dof_handler,
          const Mapping<dim, dim> &mapping) = 0;

    /**
     * After the mesh changed (adaptive refinement) and distribute_dofs:
     * setup() again, keeping the work and dissipation done so far. The node
     * history restarts from the committed state, which the caller then
     * assembles and commits (with old_u = u: no work).
     */
    virtual void
    remesh(const DoFHandler<dim> &dof_handler, const Mapping<dim, dim> &mapping)
    {
      (void)dof_handler;
      (void)mapping;
      AssertThrow(false,
                  ExcMessage("This contact formulation cannot follow a "
                             "changing mesh."));
    }

    /**
     * The current positions (configuration `u`, ghosted) of the secondary
     * nodes in contact at the last assembly and of those whose gap closes
     * within `lookahead` time at its present rate; the same on every
     * process (collective).
     */
    virtual std::vector<Point<dim>>
    contact_zone(const VectorType &u, const double lookahead) const
    {
      (void)u;
      (void)lookahead;
      return {};
    }

    /**
     * The boundary ids of the secondary surfaces: their cells carry the
     * contact work (weighted partitioning).
     */
    virtual std::vector<types::boundary_id>
    secondary_boundary_ids() const = 0;

    /** Extra degrees of freedom held at zero (homogeneous constraints). */
    virtual void
    add_constraints(AffineConstraints<double> &constraints) const = 0;

    /**
     * After the hanging-node constraints of the process's own part: those of
     * the other surface degrees of freedom it assembles (an adapted 3-D mesh
     * has hanging nodes on its contact surfaces).
     */
    virtual void
    add_hanging_constraints(AffineConstraints<double> &constraints) const
    {
      (void)constraints;
    }

    /**
     * Updates the candidate pairs for the trial displacement; true if the
     * sparsity pattern must be rebuilt.
     */
    virtual bool
    update_candidates(const VectorType &u) = 0;

    virtual void
    add_sparsity(DynamicSparsityPattern &dsp) const = 0;

    /**
     * Every degree of freedom the formulation reads (on both surfaces): a
     * process needs them all in its ghosted vectors.
     */
    virtual IndexSet
    surface_dofs() const = 0;

    /**
     * Adds the contact residual and, if asked, Jacobian; rows and columns
     * of constrained degrees of freedom are skipped. `residual_full`
     * receives the contact forces on all displacement degrees of freedom.
     */
    virtual void
    assemble(const TrialState                &state,
             const AffineConstraints<double> &constraints,
             const bool                       with_jacobian,
             VectorType                      &residual,
             MatrixType                      &jacobian,
             VectorType                      &residual_full) = 0;

    /**
     * Per secondary node this process owns: its displacement dofs and its
     * multiplier dofs (normal; tangential with friction), for the
     * condensation of the multipliers.
     */
    virtual std::vector<MultiplierGroup>
    multiplier_groups() const
    {
      return {};
    }

    /** Degrees of freedom whose predictor is their old value. */
    virtual const std::vector<types::global_dof_index> &
    multiplier_dofs() const = 0;

    /**
     * The times of the last committed step and of the trial state, before
     * the candidates of a step are searched: rigid obstacles move with
     * time.
     */
    virtual void
    set_times(const double committed, const double trial)
    {
      (void)committed;
      (void)trial;
    }

    /**
     * An attempt at a step starts (again, after a failed one): state that
     * the iterations of an attempt carry goes back to the committed one.
     */
    virtual void
    start_step()
    {}

    /**
     * The step converged at the state `u` of the last assemble(): keep the
     * history the next step needs; `old_u` is the state before. With
     * `reevaluation`, no step was taken: the committed state was assembled
     * again on a new mesh (remesh()).
     */
    virtual void
    commit_step(const VectorType &u,
                const VectorType &old_u,
                const bool        reevaluation) = 0;

    /**
     * Checkpoints: vectors on the degrees of freedom that the history of the
     * last committed step holds (its contact forces, the output fields);
     * the simulator saves and restores them with the state, in this order.
     */
    virtual std::vector<VectorType *>
    history_vectors()
    {
      return {};
    }

    /**
     * Checkpoints: the history of the last committed step into `data`
     * (complete on the first process, which writes it). Collective.
     */
    virtual void
    save_history(CheckpointData &data) const
    {
      (void)data;
      AssertThrow(false,
                  ExcMessage("This contact formulation cannot write "
                             "checkpoints."));
    }

    /**
     * Checkpoints: after setup() on the checkpoint's mesh and with
     * history_vectors() restored, the history of `data`; `u` is the
     * committed state (ghosted). The nodes are found by their reference
     * positions: the checkpoint may come from another number of processes.
     */
    virtual void
    load_history(const CheckpointData &data, const VectorType &u)
    {
      (void)data;
      (void)u;
      AssertThrow(false,
                  ExcMessage("This contact formulation cannot read "
                             "checkpoints."));
    }

    /**
     * Called for a converged step before commit_step(), at the state `u` of
     * the last assemble(), on every process: a non-empty message (the same
     * on all processes) rejects the step, and the simulator cuts it.
     */
    virtual std::string
    check_step(const VectorType &u) const
    {
      (void)u;
      return {};
    }

    /**
     * The work of the contact forces on the bodies so far, trapezoidal in
     * time (velocity corrections included).
     */
    virtual double
    contact_work() const = 0;

    virtual std::vector<std::string>
    statistics_columns() const = 0;

    virtual std::vector<double>
    statistics() const = 0;

    /**
     * Nodal fields for the VTU output: vectors on all degrees of freedom
     * whose first multiplier component holds the value.
     */
    virtual std::vector<std::pair<const VectorType *, std::string>>
    nodal_output_fields() const
    {
      return {};
    }

    /**
     * Called after an assemble() at the initial state `u` (ghosted): bodies
     * that overlap stop the run with a message (or, if allowed, get a
     * warning on `log`).
     */
    virtual void
    check_initial_state(const VectorType &u, std::ostream &log) const
    {
      (void)u;
      (void)log;
    }

    /**
     * Findings of the set-up that do not stop the run but may explain a
     * later failure (setup_caveats.h), or "". The same on every process.
     */
    virtual std::string
    caveats() const
    {
      return "";
    }

    /** Secondary nodes whose conditions this process assembles. */
    virtual unsigned int
    n_owned_contact_nodes() const
    {
      return 0;
    }

    /** Active secondary nodes of all processes at the last assembly. */
    virtual unsigned int
    n_active_nodes() const
    {
      return 0;
    }

    /**
     * Stabilization 'velocity update': the normal contact work of the last
     * committed step, which the velocities are to return (0: nothing to
     * correct, or another stabilization).
     */
    virtual double
    velocity_update_request() const
    {
      return 0;
    }

    /**
     * Stabilization 'velocity update': the step's mean normal contact force
     * (as in the residual), which says on which bodies the contact acted;
     * nullptr if none.
     */
    virtual const VectorType *
    velocity_update_force() const
    {
      return nullptr;
    }

    /** The kinetic energy the velocity correction added. */
    virtual void
    add_velocity_update_work(const double)
    {}

    /** Work done on the bodies by prescribed (rigid) obstacles so far. */
    virtual double
    obstacle_work() const
    {
      return 0;
    }

    /** Energy dissipated by the contact so far (friction). */
    virtual double
    dissipated_energy() const
    {
      return 0;
    }

    /** Contact pairs, in the order of `Contact/Pairs`. */
    virtual unsigned int
    n_pairs() const = 0;

    /**
     * The secondary nodes of a pair and their states, known on every
     * process after an assembly.
     */
    virtual SecondaryNodes<dim>
    secondary_nodes(const unsigned int pair) const = 0;

    /** Reference points whose nearest secondary nodes the output follows. */
    virtual const std::vector<std::vector<double>> &
    monitored_points() const = 0;
  };

  template <int dim>
  std::unique_ptr<ContactFormulation<dim>>
  create_contact_formulation(ParameterHandler &prm, const SceneLayout &layout);

  template <int dim>
  class ContactSurface;

  /**
   * The checks of the Contact parameters that need the mesh, done once the
   * contact surfaces exist (before the first step): the two sides of every
   * pair on different bodies, a capture tolerance small against the contact
   * faces, and every monitored point within an element of a secondary node.
   * `surfaces` holds the secondary and primary surface of each pair; the
   * capture tolerance is that of the formulation in use. Throws a message
   * naming the parameter, the value and what is allowed.
   */
  template <int dim>
  void
  check_contact_setup(
    const ContactParameters                                       &contact,
    const std::vector<std::array<const ContactSurface<dim> *, 2>> &surfaces,
    const double              capture_tolerance,
    const Triangulation<dim> &triangulation);
} // namespace ContactDynamics

#endif
