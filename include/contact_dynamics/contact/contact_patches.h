// What a contact formulation with nodal Lagrange multipliers implements for
// SurfaceContact: how one contact "patch" (a secondary face for mortar, a
// secondary node for node-to-segment) is found and what forces and nodal
// gaps it contributes. SurfaceContact does the rest (search, multipliers,
// complementarity, history).
#ifndef contact_dynamics_contact_contact_patches_h
#define contact_dynamics_contact_contact_patches_h

#include <deal.II/base/bounding_box.h>

#include <contact_dynamics/contact/contact_pair_data.h>
#include <contact_dynamics/contact/contact_states.h>
#include <contact_dynamics/contact/patch_forces.h>

#include <vector>

namespace ContactDynamics
{
  template <int dim>
  class ContactPatches
  {
  public:
    virtual ~ContactPatches() = default;

  protected:
    using PairData    = ContactPairData<dim>;
    using PatchForces = ContactDynamics::PatchForces;

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
  };
} // namespace ContactDynamics

#endif
