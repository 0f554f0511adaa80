// What the contact formulations with nodal Lagrange multipliers on the
// secondary surface share: surfaces, search, multiplier unknowns, the
// nonlinear complementarity function solved by semi-smooth Newton (with
// optional persistency), friction and the node states the output shows. A
// formulation only says how one contact "patch" (a secondary face for
// mortar, a secondary node for node-to-segment) contributes forces and
// nodal gaps.
#ifndef contact_dynamics_contact_surface_contact_h
#define contact_dynamics_contact_surface_contact_h

#include <deal.II/base/bounding_box.h>

#include <contact_dynamics/contact/complementarity_parameters.h>
#include <contact_dynamics/contact/contact_formulation.h>
#include <contact_dynamics/contact/contact_history.h>
#include <contact_dynamics/contact/contact_pair_data.h>
#include <contact_dynamics/contact/contact_patches.h>
#include <contact_dynamics/contact/contact_surface.h>
#include <contact_dynamics/contact/contact_work.h>
#include <contact_dynamics/contact/hanging_surface_dofs.h>
#include <contact_dynamics/contact/node_history.h>
#include <contact_dynamics/contact/obstacle_coupling.h>
#include <contact_dynamics/contact/patch_forces.h>
#include <contact_dynamics/contact/search_history.h>

#include <array>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace ContactDynamics
{
  template <int dim>
  class SurfaceContact : public ContactFormulation<dim>,
                         protected ContactPatches<dim>
  {
  public:
    using NodeState     = ContactNodeState;
    using Stabilization = ComplementarityParameters::Stabilization;

    SurfaceContact(const ContactParameters         &contact,
                   const ComplementarityParameters &complementarity);

    unsigned int
    n_extra_components() const override;

    std::vector<std::string>
    extra_component_names() const override;

    void
    setup(const DoFHandler<dim>   &dof_handler,
          const Mapping<dim, dim> &mapping) override;

    void
    remesh(const DoFHandler<dim>   &dof_handler,
           const Mapping<dim, dim> &mapping) override;

    std::vector<Point<dim>>
    contact_zone(const VectorType &u, const double lookahead) const override;

    std::vector<types::boundary_id>
    secondary_boundary_ids() const override;

    void
    add_constraints(AffineConstraints<double> &constraints) const override;

    void
    add_hanging_constraints(
      AffineConstraints<double> &constraints) const override;

    bool
    update_candidates(const VectorType &u) override;

    void
    add_sparsity(DynamicSparsityPattern &dsp) const override;

    IndexSet
    surface_dofs() const override;

    /** Secondary nodes of a pair whose conditions this process assembles. */
    unsigned int
    n_owned_nodes(const unsigned int pair) const;

    unsigned int
    n_owned_contact_nodes() const override;

    unsigned int
    n_active_nodes() const override;

    void
    assemble(const TrialState                &state,
             const AffineConstraints<double> &constraints,
             const bool                       with_jacobian,
             VectorType                      &residual,
             MatrixType                      &jacobian,
             VectorType                      &residual_full) override;

    const std::vector<types::global_dof_index> &
    multiplier_dofs() const override;

    /** The history's lifecycle: calls of the owners in `history`. */
    void
    start_step() override;

    void
    commit_step(const VectorType &u,
                const VectorType &old_u,
                const bool        reevaluation) override;

    std::vector<VectorType *>
    history_vectors() override;

    void
    save_history(CheckpointData &data) const override;

    void
    load_history(const CheckpointData &data, const VectorType &u) override;

    /** Places the rigid obstacles at the committed and the trial time. */
    void
    set_times(const double committed, const double trial) override;

    /** The work the rigid obstacles did on the bodies so far. */
    double
    obstacle_work() const override;

    /** Rejects a step with a missed contact: doc/contact.md, "Search". */
    std::string
    check_step(const VectorType &u) const override;

    double
    contact_work() const override;

    std::vector<std::string>
    statistics_columns() const override;

    std::vector<double>
    statistics() const override;

    double
    velocity_update_request() const override;

    std::vector<MultiplierGroup>
    multiplier_groups() const override;

    const VectorType *
    velocity_update_force() const override;

    void
    add_velocity_update_work(const double work_done) override;

    /**
     * Friction on both sides: a rigid obstacle's share (its friction
     * force on its moving surface) is not in the contact work of the
     * meshed surfaces.
     */
    double
    dissipated_energy() const override;

    void
    check_initial_state(const VectorType &u, std::ostream &log) const override;
    std::string
    caveats() const override;
    void
    report_initial_overlap(double             worst,
                           unsigned int       pair,
                           const std::string &node,
                           std::ostream      &log) const;

    /**
     * The normalized gap and, with friction, the slip rates along the
     * nodal tangents (of the last committed step).
     */
    std::vector<std::pair<const VectorType *, std::string>>
    nodal_output_fields() const override;

    const std::vector<NodeState> &
    node_states(const unsigned int pair) const;

    const ContactSurface<dim> &
    secondary_surface(const unsigned int pair) const;

    /** Empty for a rigid obstacle. */
    const ContactSurface<dim> &
    primary_surface(const unsigned int pair) const;

    unsigned int
    n_pairs() const override;

    SecondaryNodes<dim>
    secondary_nodes(const unsigned int pair) const override;

    const std::vector<std::vector<double>> &
    monitored_points() const override;

  protected:
    using PairData    = ContactPairData<dim>;
    using PatchForces = ContactDynamics::PatchForces;

    // the patch interface (ContactPatches: a dependent base)
    using ContactPatches<dim>::minimum_coverage;
    using ContactPatches<dim>::traction_per_multiplier;
    using ContactPatches<dim>::force_per_gap_sum;
    using ContactPatches<dim>::n_patches;
    using ContactPatches<dim>::patch_box;
    using ContactPatches<dim>::patch_nodes;
    using ContactPatches<dim>::patch_unknowns;
    using ContactPatches<dim>::assemble_patch;
    using ContactPatches<dim>::assemble_obstacle_patch;

    /**
     * The unknowns of a patch against a rigid obstacle: the displacements
     * of patch_nodes() node by node, then their multipliers component by
     * component (normal, then the tangential ones).
     */
    std::vector<types::global_dof_index>
    obstacle_patch_unknowns(const PairData    &pair,
                            const unsigned int patch) const;

    ContactParameters         contact;
    ComplementarityParameters complementarity;
    std::vector<PairData>     pairs;

    /**
     * The owners of the history, in the order of their calls: the contact
     * work, the obstacles, the nodes, the search (a formulation with history
     * of its own adds its owner).
     */
    ContactHistoryRegistry history;

    MPI_Comm                 comm         = MPI_COMM_WORLD;
    const Mapping<dim, dim> *cell_mapping = nullptr; // of the last setup()

    /**
     * Checkpoints: per pair, the node of this mesh at each saved node (by
     * reference position); empty if the numbering is the saved one. Throws
     * if a saved node is not on this mesh.
     */
    std::vector<std::vector<unsigned int>>
    saved_node_map(const CheckpointData &data) const;

  private:
    using LinearSystem = ContactLinearSystem;

    /** setup(): the surfaces of pair p and its multiplier unknowns. */
    void
    build_pair(const unsigned int                 p,
               const DoFHandler<dim>             &dof_handler,
               std::set<types::global_dof_index> &secondary_normal);

    /**
     * setup(): the nodes of a pair this process owns, and the patches it
     * handles and computes.
     */
    void
    distribute(PairData &pair) const;

    /** The patches this process computes; their forces are added. */
    void
    assemble_patches(PairData           &pair,
                     const TrialState   &state,
                     const LinearSystem &system);

    /**
     * Sends the patches' contributions to the gaps, weights and rates of
     * other processes' nodes to their owners, and adds those received
     * (collective).
     */
    void
    exchange_node_sums(PairData &pair) const;

    /** The complementarity rows of the owned nodes. */
    void
    assemble_nodes(PairData           &pair,
                   const TrialState   &state,
                   const LinearSystem &system);

    /** Adds a patch's forces to the system and the contact work. */
    void
    add_forces(const PatchForces &forces, const LinearSystem &system);

    /**
     * Moves the gap, weight and rate sums of the hanging secondary nodes to
     * the nodes they follow (the multiplier of a hanging node is that
     * interpolation of theirs, so its condition is part of theirs).
     */
    void
    move_hanging_sums(PairData &pair) const;

    /**
     * The normal complementarity condition of node j: its state, the
     * constraint quantity c g / w and, unless its row is constrained, its
     * row. Returns whether the node is active.
     */
    bool
    assemble_normal(PairData           &pair,
                    const unsigned int  node,
                    const TrialState   &state,
                    const LinearSystem &system,
                    LinearizedValue    &constraint);

    /**
     * c_n dt times the Newmark rate of node j's normalized weighted gap
     * (the 'persistency' condition of a held node), with derivatives;
     * stores the rates in the node's state.
     */
    LinearizedValue
    held_gap_rate(PairData          &pair,
                  const unsigned int node,
                  const TrialState  &state) const;

    /**
     * The slip rates of node j normalized like its gap, with derivatives;
     * stores them and the tangential tractions in the node's state.
     */
    std::array<LinearizedValue, dim - 1>
    normalized_slip_rates(PairData          &pair,
                          const unsigned int j,
                          const VectorType  &u) const;

    /** The friction condition of node j, given its normal condition. */
    void
    assemble_friction(PairData              &pair,
                      const unsigned int     node,
                      const bool             active,
                      const LinearizedValue &constraint,
                      const VectorType      &u,
                      const LinearSystem    &system);

    /**
     * Candidate primary faces per patch: boxes around the volume swept in
     * the step (the union of the boxes at the committed and at the trial
     * configuration u), enlarged by margin_factor times the patch or face
     * size.
     */
    std::vector<std::vector<unsigned int>>
    compute_candidates(const PairData   &pair,
                       const VectorType &u,
                       const double      margin_factor) const;

    /**
     * The box of a patch at the committed and the trial configuration u,
     * enlarged by margin_factor times the patch's size.
     */
    BoundingBox<dim>
    swept_patch_box(const PairData    &pair,
                    const unsigned int patch,
                    const VectorType  &u,
                    const double       margin_factor) const;

    /** compute_candidates() for a rigid obstacle: {0} or nothing. */
    std::vector<std::vector<unsigned int>>
    obstacle_candidates(const PairData   &pair,
                        const VectorType &u,
                        const double      margin_factor) const;

    /**
     * check_step() for the secondary node j of pair p, with the primary
     * faces its patches found: the failure, or empty.
     */
    std::string
    check_node(const unsigned int            p,
               const unsigned int            j,
               const std::set<unsigned int> &faces,
               const VectorType             &u) const;
    /** Per secondary node, the primary faces its patches found. */
    std::vector<std::set<unsigned int>>
    candidate_faces(const PairData &pair) const;

    /** Makes the node states of all processes' nodes known everywhere. */
    void
    gather_node_states();

    /** After the patches and rows: compress and reduce the statistics. */
    void
    finish_assembly(const LinearSystem &system);

    IndexSet owned_dofs;

    std::vector<types::global_dof_index> normal_multiplier_dofs;
    std::vector<types::global_dof_index> other_multiplier_dofs;

    HangingSurfaceDofs hanging;

    // the owners of history (registered in `history`)
    ContactWork           work;
    ObstacleCoupling<dim> obstacles;
    NodeHistory<dim>      node_history;
    SearchHistory<dim>    search;

    bool         friction = false;
    unsigned int n_stick = 0, n_slip = 0;
    unsigned int n_active         = 0;
    double       total_force[dim] = {};
  };
} // namespace ContactDynamics

#endif
