// Node-to-segment contact (2-D, and 3-D in node_to_segment_contact_3d.cc):
// every secondary node is projected onto the closest primary face; the
// pointwise gap along the (optionally smoothed) primary normal is enforced
// kinematically with a nodal Lagrange multiplier and the same complementarity
// function as the mortar formulation; see doc/contact.md.
#ifndef contact_dynamics_contact_node_to_segment_contact_h
#define contact_dynamics_contact_node_to_segment_contact_h

#include <contact_dynamics/contact/surface_contact.h>

#include <array>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace ContactDynamics
{
  struct NodeToSegmentParameters
  {
    ComplementarityParameters complementarity{
      ComplementarityParameters::Stabilization::none};
    double smoothing_distance = 0;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };

  /**
   * The owner of the face memory of the projections: per pair (by index)
   * and secondary node the primary face of the projection at the last
   * committed step, and at the last assembly of this attempt (what the next
   * iteration keeps; reset to the committed faces when an attempt starts,
   * committed when the step is accepted). In 3-D likewise the coordinate
   * axis each node's friction tangents are built from (tangent_basis()):
   * kept while the contact normal stays clear of it, so that the frame does
   * not turn with the primary face a node projects onto.
   */
  class FaceMemory : public ContactHistoryOwner
  {
  public:
    /** `comm`, `n_pairs`: the formulation's, as set up. */
    FaceMemory(const MPI_Comm                      &comm,
               const std::function<unsigned int()> &n_pairs)
      : comm(comm)
      , n_pairs(n_pairs)
    {}

    std::string
    name() const override
    {
      return "node-to-segment faces";
    }

    void
    start_attempt(const ContactHistoryContext &) override
    {
      trial      = committed;
      trial_axis = committed_axis;
    }

    /** The faces of the converged state's projections (the last assembly). */
    void
    commit(const ContactHistoryContext &) override
    {
      committed      = trial;
      committed_axis = trial_axis;
    }

    void
    save(CheckpointData &data, const ContactHistoryContext &) const override;

    /** Kept if the numbering is the saved one, else searched anew. */
    void
    load(const CheckpointData        &data,
         const ContactHistoryContext &context) override;

    /**
     * The faces refer to the old mesh's nodes: the memory starts empty (the
     * tangent axes are chosen again from the normals).
     */
    void
    transfer(const ContactHistoryContext &) override
    {
      committed.clear();
      trial.clear();
      committed_axis.clear();
      trial_axis.clear();
    }

    /** The trial faces of a pair's nodes (empty at first). */
    std::vector<unsigned int> &
    trial_faces(const unsigned int pair)
    {
      return trial[pair];
    }

    /**
     * The tangent axis of node j of a pair's n nodes for the contact
     * normal n (3-D): the trial one, chosen anew (the axis least aligned
     * with n) where there is none or n has come within about 37 degrees of
     * it.
     */
    unsigned int
    tangent_axis(const unsigned int           pair,
                 const unsigned int           j,
                 const unsigned int           n_nodes,
                 const std::array<double, 3> &normal);

    std::map<unsigned int, std::vector<unsigned int>> trial;

  private:
    const MPI_Comm                                   &comm;
    std::function<unsigned int()>                     n_pairs;
    std::map<unsigned int, std::vector<unsigned int>> committed;
    std::map<unsigned int, std::vector<unsigned int>> trial_axis,
      committed_axis;
  };

  template <int dim>
  class NodeToSegmentContact : public SurfaceContact<dim>
  {
  public:
    NodeToSegmentContact(const ContactParameters       &contact,
                         const NodeToSegmentParameters &parameters);

  protected:
    using PairData = typename SurfaceContact<dim>::PairData;

    /** A patch is a secondary node. */
    unsigned int
    n_patches(const PairData &pair) const override
    {
      return pair.secondary.n_nodes();
    }

    /**
     * The nodal force is the multiplier times the reference tributary
     * length; the traction divides it by the current one.
     */
    double
    traction_per_multiplier(const PairData    &pair,
                            const unsigned int node,
                            const VectorType  &u) const override;

    /** The nodal force is lambda_j L_j n_j: L_j, the reference weight. */
    double
    force_per_gap_sum(const PairData    &pair,
                      const unsigned int node) const override
    {
      return pair.secondary.reference_weight[node];
    }

    BoundingBox<dim>
    patch_box(const PairData    &pair,
              const unsigned int patch,
              const VectorType  &u,
              double            &size) const override;

    std::vector<unsigned int>
    patch_nodes(const PairData &, const unsigned int patch) const override
    {
      return {patch};
    }

    std::vector<types::global_dof_index>
    patch_unknowns(
      const PairData                  &pair,
      const unsigned int               patch,
      const std::vector<unsigned int> &primary_faces) const override;

    using PatchForces = typename SurfaceContact<dim>::PatchForces;

    void
    assemble_patch(PairData          &pair,
                   const unsigned int patch,
                   const TrialState  &state,
                   PatchForces       &forces) override;

    /** Against a rigid obstacle: source/contact/obstacle_patches.cc. */
    void
    assemble_obstacle_patch(PairData          &pair,
                            const unsigned int patch,
                            const TrialState  &state,
                            PatchForces       &forces) override;

  private:
    /**
     * The primary nodes a node's patch reads with the candidate faces:
     * their nodes and those that define their smoothed normals.
     */
    std::set<unsigned int>
    primary_nodes(const PairData                  &pair,
                  const std::vector<unsigned int> &faces) const;

    /** assemble_patch() with the AD number type AD for `unknowns`. */
    template <typename AD>
    void
    assemble_patch_ad(PairData                                   &pair,
                      const unsigned int                          node,
                      const TrialState                           &state,
                      const std::vector<types::global_dof_index> &unknowns,
                      PatchForces                                &forces);

    /** The same on primary faces of degree 2: node_to_segment_quadratic.cc. */
    template <typename AD>
    void
    assemble_quadratic_patch_ad(
      PairData                                   &pair,
      const unsigned int                          node,
      const TrialState                           &state,
      const std::vector<types::global_dof_index> &unknowns,
      PatchForces                                &forces);

    double     smoothing_distance;
    FaceMemory face_memory;
    // (face_memory.trial, as the 3-D projection reads it)
    std::map<unsigned int, std::vector<unsigned int>> &trial_face;
  };
  // 3-D (node_to_segment_contact_3d.cc): closest points on bilinear faces,
  // the change of the area around a node
  template <>
  void
  NodeToSegmentContact<3>::assemble_patch(PairData          &pair,
                                          const unsigned int patch,
                                          const TrialState  &state,
                                          PatchForces       &forces);
  template <>
  double
  NodeToSegmentContact<3>::traction_per_multiplier(const PairData    &pair,
                                                   const unsigned int node,
                                                   const VectorType  &u) const;
} // namespace ContactDynamics

#endif
