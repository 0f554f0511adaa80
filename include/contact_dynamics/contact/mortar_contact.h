// Dual mortar segment-to-segment contact with Lagrange multipliers (2-D):
// weighted gaps on mortar segments, a nonlinear complementarity function
// solved by semi-smooth Newton, optional persistency stabilization, and a
// Jacobian by automatic differentiation over every degree of freedom the
// residual depends on.
#ifndef contact_dynamics_contact_mortar_contact_h
#define contact_dynamics_contact_mortar_contact_h

#include <deal.II/base/bounding_box.h>

#include <contact_dynamics/contact/contact_formulation.h>
#include <contact_dynamics/contact/contact_surface.h>

#include <fstream>
#include <map>
#include <memory>

namespace ContactDynamics
{
  struct MortarParameters
  {
    double       c_n               = 1e6;
    bool         normalize_c_n     = true;
    bool         persistency       = true;
    double       capture_tolerance = 1e-5;
    bool         exact_jacobian    = true;
    unsigned int quadrature_points = 2;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };

  /** A value and its derivatives with respect to global unknowns. */
  struct LinearizedValue
  {
    double                                    value = 0;
    std::map<types::global_dof_index, double> derivatives;

    void
    clear()
    {
      value = 0;
      derivatives.clear();
    }
  };

  template <int dim>
  class MortarContact : public ContactFormulation<dim>
  {
  public:
    MortarContact(const ContactParameters &contact,
                  const MortarParameters  &mortar);

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
    add_constraints(AffineConstraints<double> &constraints) const override;

    bool
    update_candidates(const VectorType &u) override;

    void
    add_sparsity(DynamicSparsityPattern &dsp) const override;

    void
    assemble(const TrialState                &state,
             const AffineConstraints<double> &constraints,
             const bool                       with_jacobian,
             VectorType                      &residual,
             MatrixType                      &jacobian,
             VectorType                      &residual_full) override;

    bool
    active_set_converged() const override
    {
      return !active_set_changed;
    }

    const std::vector<types::global_dof_index> &
    multiplier_dofs() const override
    {
      return normal_multiplier_dofs;
    }

    void
    commit_step(const VectorType &old_u, const double time) override;

    std::vector<std::string>
    statistics_columns() const override;

    std::vector<double>
    statistics() const override;

    void
    write_output(const std::string &directory,
                 const unsigned int step) override;

    std::vector<std::pair<const VectorType *, std::string>>
    nodal_output_fields() const override
    {
      return {{&gap_field, "weighted_gap"}};
    }

    /** Per secondary node of a pair, for tests and output. */
    struct NodeState
    {
      double weighted_gap  = 0; // integral psi_j g
      double weight        = 0; // integral N_j over the covered part
      double pressure      = 0; // lambda_n
      bool   projected     = false;
      bool   active        = false;
      bool   persistent    = false; // velocity-level condition this step
      double gap_at_commit = 0;     // normalized weighted gap, last step
    };

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

  private:
    struct PairData
    {
      ContactSurface<dim>                    secondary, primary;
      std::vector<std::vector<unsigned int>> candidates; // per secondary face
      std::vector<std::vector<unsigned int>> pattern;    // in the sparsity
      std::vector<NodeState>                 nodes;
      std::vector<LinearizedValue>           gap, weight, gap_rate;
    };

    void
    assemble_face(PairData                        &pair,
                  const unsigned int               face,
                  const TrialState                &state,
                  const AffineConstraints<double> &constraints,
                  const bool                       with_jacobian,
                  VectorType                      &residual,
                  MatrixType                      &jacobian,
                  VectorType                      &residual_full);

    std::vector<std::vector<unsigned int>>
    compute_candidates(const PairData &pair,
                       const VectorType &u,
                       const double      margin_factor) const;

    /** Unknowns a secondary face's contributions depend on. */
    std::vector<types::global_dof_index>
    face_unknowns(const PairData &pair, const unsigned int face,
                  const std::vector<unsigned int> &primary_faces) const;

    ContactParameters                    contact;
    MortarParameters                     mortar;
    std::vector<PairData>                pairs;
    std::vector<types::global_dof_index> normal_multiplier_dofs;
    std::vector<types::global_dof_index> other_multiplier_dofs;
    bool                                 active_set_changed = true;

    // contact forces (residual contributions) at the last assembly and at
    // the last committed step, for the contact work
    VectorType   force, force_committed, committed_u;
    VectorType   gap_field; // normalized weighted gap at the multiplier dofs
    double       contact_work = 0;
    unsigned int n_active     = 0;
    double       total_force[2] = {0, 0};

    std::vector<std::pair<unsigned int, unsigned int>> monitored; // pair, node
    std::unique_ptr<std::ofstream>                     history;
    std::string                                        directory;
    bool                                               have_state = false;
    const VectorType                                  *last_u     = nullptr;

  public:
    void
    set_output_directory(const std::string &dir);
  };
} // namespace ContactDynamics

#endif
