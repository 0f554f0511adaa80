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

#include <contact_dynamics/contact/contact_formulation.h>
#include <contact_dynamics/contact/contact_surface.h>
#include <contact_dynamics/contact/contact_work.h>

#include <array>
#include <map>
#include <memory>
#include <utility>
#include <vector>

namespace ContactDynamics
{
  /** Parameters of the complementarity condition, per formulation. */
  struct ComplementarityParameters
  {
    /** What keeps a node that is in contact from creating energy. */
    enum class Stabilization
    {
      none,                 // the gap is enforced at every step (static)
      persistency,          // Newmark rate of the weighted gap held at zero
      velocity_persistency, // the paper's velocity-level gap rate
      velocity_update       // static, then a velocity correction
    };

    double        c_n           = 1e6;
    bool          normalize_c_n = true;
    Stabilization stabilization;
    double        capture_tolerance = 1e-5;
    bool          exact_jacobian    = true;
    double        c_t               = 1e4;

    /** The formulations differ in the default stabilization only. */
    explicit ComplementarityParameters(
      const Stabilization stabilization = Stabilization::persistency)
      : stabilization(stabilization)
    {}

    /** Whether a node in contact holds its gap (rate) in the next step. */
    bool
    holds_contact() const
    {
      return stabilization != Stabilization::none;
    }

    /** Declares the entries with the values of `defaults` as defaults. */
    static void
    declare_parameters(ParameterHandler                &prm,
                       const ComplementarityParameters &defaults);
    void
    parse_parameters(ParameterHandler &prm);
  };

  /** A value and its derivatives with respect to global unknowns. */
  struct LinearizedValue
  {
    double                                    value = 0;
    std::map<types::global_dof_index, double> derivatives;
  };

  template <int dim>
  class SurfaceContact : public ContactFormulation<dim>
  {
  public:
    using NodeState     = ContactNodeState;
    using Stabilization = ComplementarityParameters::Stabilization;

    SurfaceContact(const ContactParameters         &contact,
                   const ComplementarityParameters &complementarity);

    unsigned int
    n_extra_components() const override
    {
      return dim;
    }

    std::vector<std::string>
    extra_component_names() const override;

    void
    setup(const DoFHandler<dim> &dof_handler) override;

    void
    remesh(const DoFHandler<dim> &dof_handler) override;

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
    n_owned_contact_nodes() const override
    {
      unsigned int n = 0;
      for (unsigned int p = 0; p < pairs.size(); ++p)
        n += n_owned_nodes(p);
      return n;
    }

    unsigned int
    n_active_nodes() const override
    {
      return n_active;
    }

    void
    assemble(const TrialState                &state,
             const AffineConstraints<double> &constraints,
             const bool                       with_jacobian,
             VectorType                      &residual,
             MatrixType                      &jacobian,
             VectorType                      &residual_full) override;

    const std::vector<types::global_dof_index> &
    multiplier_dofs() const override
    {
      return normal_multiplier_dofs;
    }

    void
    commit_step(const VectorType &u, const VectorType &old_u) override;

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
    obstacle_work() const override
    {
      return obstacle_work_done;
    }

    /**
     * Rejects a step in which a secondary node went through a primary face
     * unnoticed: see doc/contact.md, "Search" for the rule.
     */
    std::string
    check_step(const VectorType &u) const override;

    double
    contact_work() const override
    {
      return work.work();
    }

    std::vector<std::string>
    statistics_columns() const override;

    std::vector<double>
    statistics() const override;

    double
    velocity_update_request() const override
    {
      // (not the normal work of a moving obstacle: that is external work)
      return complementarity.stabilization == Stabilization::velocity_update ?
               work.normal_step_work() - obstacle_normal_step_work :
               0.;
    }

    std::vector<MultiplierGroup>
    multiplier_groups() const override;

    const VectorType *
    velocity_update_force() const override
    {
      return &work.step_normal_force();
    }

    void
    add_velocity_update_work(const double work_done) override
    {
      work.add_impulse_work(work_done);
    }

    /**
     * Friction on both sides: a rigid obstacle's share (its friction
     * force on its moving surface) is not in the contact work of the
     * meshed surfaces.
     */
    double
    dissipated_energy() const override
    {
      return work.dissipation() + obstacle_friction_work;
    }

    void
    check_initial_state(std::ostream &log) const override;

    /**
     * The normalized gap and, with friction, the slip rates along the
     * nodal tangents (of the last committed step).
     */
    std::vector<std::pair<const VectorType *, std::string>>
    nodal_output_fields() const override
    {
      std::vector<std::pair<const VectorType *, std::string>> fields{
        {&gap_field, "normal_gap"}};
      if (friction)
        {
          fields.emplace_back(&slip_field[0], "slip_rate");
          if (dim == 3)
            fields.emplace_back(&slip_field[1], "slip_rate_2");
        }
      return fields;
    }

    const std::vector<NodeState> &
    node_states(const unsigned int pair) const
    {
      return pairs[pair].nodes;
    }

    const ContactSurface<dim> &
    secondary_surface(const unsigned int pair) const
    {
      return pairs[pair].secondary;
    }

    /** Empty for a rigid obstacle. */
    const ContactSurface<dim> &
    primary_surface(const unsigned int pair) const
    {
      return pairs[pair].primary;
    }

    unsigned int
    n_pairs() const override
    {
      return pairs.size();
    }

    SecondaryNodes<dim>
    secondary_nodes(const unsigned int pair) const override
    {
      return {pairs[pair].secondary.reference,
              pairs[pair].position,
              pairs[pair].nodes};
    }

    const std::vector<std::vector<double>> &
    monitored_points() const override
    {
      return contact.monitored_points;
    }

  protected:
    struct PairData
    {
      ContactSurface<dim>                    secondary, primary;
      std::vector<std::vector<unsigned int>> candidates; // per patch
      std::vector<std::vector<unsigned int>> pattern;    // in the sparsity
      std::vector<NodeState>                 nodes;
      // per secondary node: gap, its normalization weight, gap rate,
      // relative tangential velocity (secondary minus primary) along the
      // node's dim - 1 tangents
      std::vector<LinearizedValue>                      gap, weight, gap_rate;
      std::vector<std::array<LinearizedValue, dim - 1>> slip_rate;
      double friction_coefficient = 0;
      // in parallel: the nodes whose multipliers this process owns, the
      // patches that touch them (whose candidates and couplings it needs)
      // and the patches it computes (an equal share of all: the contact
      // surface may lie on one process's part of the mesh); a patch's
      // contributions to a node go to the node's owner (node_owner)
      std::vector<bool>         owned_node, handled_patch, assembled_patch;
      std::vector<unsigned int> node_owner;
      // secondary nodes at the last committed step
      std::vector<Point<dim>> position;
      // a rigid obstacle as the primary side (`primary` is empty then), at
      // the committed and the trial time; per secondary node the axis its
      // tangents are built from (3-D, tangent_basis())
      std::shared_ptr<const RigidObstacle<dim>> obstacle;
      typename RigidObstacle<dim>::Placement    committed_place, trial_place;
      std::vector<unsigned int>                 tangent_axis;
      std::map<types::global_dof_index, std::pair<unsigned int, unsigned int>>
        dof_node; // displacement dof -> (node, component)
      // per secondary node that hangs on an adapted 3-D mesh: the nodes it
      // follows and their weights (empty for a node with its own unknowns)
      std::vector<std::vector<std::pair<unsigned int, double>>> hanging_parents;
      // on the obstacle at the trial state and at the last committed step:
      // force, torque about its center (3 components; z only in 2-D) and
      // their friction parts
      struct Reaction
      {
        Tensor<1, dim> force, friction_force;
        Tensor<1, 3>   torque, friction_torque;
      };
      Reaction reaction, committed_reaction;
    };

    /**
     * The forces of one patch in the order a formulation computes them;
     * SurfaceContact adds them to the system (or, for a patch assembled
     * for its gaps only, drops them).
     */
    struct PatchForces
    {
      using Derivatives =
        std::vector<std::pair<types::global_dof_index, double>>;

      /** A residual row of a contact force with its derivatives. */
      void
      add(const types::global_dof_index row,
          const double                  value,
          Derivatives                 &&derivatives)
      {
        rows.push_back({row, value, std::move(derivatives)});
      }

      /**
       * The mortar normal force rows -sum_j lambda_j direction[i][j] of the
       * positions i (the first direction.size() unknowns), with their
       * derivatives in the multipliers (the unknowns that follow the
       * positions) and, unless `hessian` is empty, in the positions
       * (hessian[i n + l]); extra(i, derivatives) may add more.
       */
      template <std::size_t n_nodes, typename Extra>
      void
      add_normal_rows(const std::vector<types::global_dof_index>     &unknowns,
                      const std::array<double, n_nodes>              &lambda,
                      const std::vector<std::array<double, n_nodes>> &direction,
                      const std::vector<double>                      &hessian,
                      const Extra                                    &extra)
      {
        const unsigned int n_positions = direction.size();
        for (unsigned int i = 0; i < n_positions; ++i)
          {
            Derivatives derivatives;
            double      value = 0;
            for (unsigned int j = 0; j < n_nodes; ++j)
              {
                value -= lambda[j] * direction[i][j];
                if (direction[i][j] != 0)
                  derivatives.emplace_back(unknowns[n_positions + j],
                                           -direction[i][j]);
              }
            if (!hessian.empty())
              for (unsigned int l = 0; l < n_positions; ++l)
                if (const double h = hessian[i * n_positions + l]; h != 0)
                  derivatives.emplace_back(unknowns[l], -h);
            extra(i, derivatives);
            if (value != 0 || !derivatives.empty())
              add(unknowns[i], value, std::move(derivatives));
          }
      }

      /** Records the tangential (friction) part of a force row. */
      void
      add_tangential(const types::global_dof_index row, const double value)
      {
        tangential.emplace_back(row, value);
      }

      struct Row
      {
        types::global_dof_index row;
        double                  value;
        Derivatives             derivatives;
      };
      std::vector<Row>                                        rows;
      std::vector<std::pair<types::global_dof_index, double>> tangential;
    };

    /**
     * Fraction of its reference weight a node's weight must reach for the
     * node to count as projected.
     */
    virtual double
    minimum_coverage() const
    {
      return 1e-12;
    }

    /**
     * Traction on the current surface per unit multiplier at secondary node
     * j, for the output of pressures: 1 where the multipliers are tractions
     * on the current surface (mortar).
     */
    virtual double
    traction_per_multiplier(const PairData &,
                            const unsigned int,
                            const VectorType &) const
    {
      return 1.;
    }

    /**
     * The factor between a node's multiplier times the derivative of its
     * gap sum and the force it exerts: 1 where the force is the derivative
     * of lambda_j g_j (mortar), the node's reference weight where it is
     * lambda_j L_j n_j (node-to-segment). A hanging node's sums go to the
     * nodes it follows scaled by it, so that each node's condition stays
     * conjugate to its force.
     */
    virtual double
    force_per_gap_sum(const PairData &, const unsigned int) const
    {
      return 1.;
    }

    /** Number of patches of a pair (faces or nodes of the secondary side). */
    virtual unsigned int
    n_patches(const PairData &pair) const = 0;

    /** Box around a patch in the configuration u, before enlarging. */
    virtual BoundingBox<dim>
    patch_box(const PairData    &pair,
              const unsigned int patch,
              const VectorType  &u,
              double            &size) const = 0;

    /** Secondary nodes whose gaps a patch contributes to. */
    virtual std::vector<unsigned int>
    patch_nodes(const PairData &pair, const unsigned int patch) const = 0;

    /** Unknowns a patch's contributions depend on, given primary faces. */
    virtual std::vector<types::global_dof_index>
    patch_unknowns(const PairData                  &pair,
                   const unsigned int               patch,
                   const std::vector<unsigned int> &primary_faces) const = 0;

    /**
     * Adds a patch's forces to `forces` and its contributions to pair.gap,
     * pair.weight, pair.gap_rate and pair.slip_rate of its nodes.
     */
    virtual void
    assemble_patch(PairData          &pair,
                   const unsigned int patch,
                   const TrialState  &state,
                   PatchForces       &forces) = 0;

    /**
     * assemble_patch() for a pair whose primary side is a rigid obstacle
     * (pair.obstacle, at pair.trial_place), with the unknowns of
     * obstacle_patch_unknowns().
     */
    virtual void
    assemble_obstacle_patch(PairData          &pair,
                            const unsigned int patch,
                            const TrialState  &state,
                            PatchForces       &forces) = 0;

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
     * Checkpoints: per pair, the node of this mesh at each saved node (by
     * reference position); empty if the numbering is the saved one. Throws
     * if a saved node is not on this mesh.
     */
    std::vector<std::vector<unsigned int>>
    saved_node_map(const CheckpointData &data) const;

    /**
     * Checkpoints: per-process lists of indices of a pair (`lists` on this
     * process), all of them on the first process under `name`.
     */
    void
    save_per_process(CheckpointData                               &data,
                     const std::string                            &name,
                     const std::vector<std::vector<unsigned int>> &lists) const;

    /**
     * The lists save_per_process() saved for this process, if the
     * checkpoint comes from as many processes as there are now; else
     * empty.
     */
    std::vector<std::vector<unsigned int>>
    load_per_process(const CheckpointData &data, const std::string &name) const;

  private:
    /** The linear system an assembly adds to; constrained rows are skipped. */
    struct LinearSystem
    {
      const AffineConstraints<double> &constraints;
      const bool                       with_jacobian;
      VectorType                      &residual;
      MatrixType                      &jacobian;
      VectorType                      &residual_full; // all force rows
    };

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
     * Adds factor times the derivatives to a row of the Jacobian: columns
     * of hanging degrees of freedom go to the columns they follow, other
     * constrained columns are dropped.
     */
    template <typename Derivatives>
    void
    add_row(const LinearSystem           &system,
            const types::global_dof_index row,
            const Derivatives            &derivatives,
            const double                  factor = 1.) const;

    /**
     * Moves the gap, weight and rate sums of the hanging secondary nodes to
     * the nodes they follow (the multiplier of a hanging node is that
     * interpolation of theirs, so its condition is part of theirs).
     */
    void
    move_hanging_sums(PairData &pair) const;

    /**
     * hanging_dofs from the hanging-node constraints of every process
     * (collective).
     */
    void
    collect_hanging_dofs(const DoFHandler<dim> &dof_handler);

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

    /** The obstacle of a pair, its placements and node maps. */
    void
    set_up_obstacle(PairData                      &pair,
                    const RigidObstacleParameters &parameters) const;

    /** Makes the node states of all processes' nodes known everywhere. */
    void
    gather_node_states();

    /** After the patches and rows: compress and reduce the statistics. */
    void
    finish_assembly(const LinearSystem &system);

    MPI_Comm comm = MPI_COMM_WORLD;
    IndexSet owned_dofs;

    // the state of the last committed step (ghosted like the trial state),
    // for the swept search; zero (the reference configuration) before it
    VectorType committed_u;
    bool       committed_is_next = false; // after remesh()

    std::vector<types::global_dof_index> normal_multiplier_dofs;
    std::vector<types::global_dof_index> other_multiplier_dofs;

    // the hanging-node constraints of the surface dofs of an adapted 3-D
    // mesh, of all processes (a process computes patches of any part)
    std::map<types::global_dof_index,
             std::vector<std::pair<types::global_dof_index, double>>>
      hanging_dofs;

    double committed_time = 0, trial_time = 0;
    // the work of the obstacles on the bodies, and its friction part
    double obstacle_work_done = 0, obstacle_friction_work = 0;
    double obstacle_normal_step_work = 0; // of the last committed step

    /** Adds a patch's forces to the reaction on the pair's obstacle. */
    void
    add_reaction(PairData          &pair,
                 const PatchForces &forces,
                 const VectorType  &u) const;

    ContactWork  work;
    bool         friction = false;
    unsigned int n_stick = 0, n_slip = 0;
    VectorType   gap_field; // normalized gap at the multiplier dofs
    std::array<VectorType, dim - 1> slip_field; // slip rates, likewise
    unsigned int                    n_active         = 0;
    double                          total_force[dim] = {};
  };
} // namespace ContactDynamics

#endif
