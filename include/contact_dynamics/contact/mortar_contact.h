// Dual mortar segment-to-segment contact with Lagrange multipliers:
// weighted gaps on mortar segments with dual basis functions, forces on
// both sides through the same traction; see doc/contact.md.
#ifndef contact_dynamics_contact_mortar_contact_h
#define contact_dynamics_contact_mortar_contact_h

#include <contact_dynamics/contact/surface_contact.h>

namespace ContactDynamics
{
  namespace MortarFace3D
  {
    struct FrictionTerms;
  }

  struct MortarParameters
  {
    ComplementarityParameters complementarity;
    unsigned int              quadrature_points   = 2;
    unsigned int              segment_edge_points = 4;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };

  template <int dim>
  class MortarContact : public SurfaceContact<dim>
  {
  public:
    MortarContact(const ContactParameters &contact,
                  const MortarParameters  &mortar);

  protected:
    using PairData = typename SurfaceContact<dim>::PairData;

    /**
     * Covered fraction of a secondary face below which it contributes
     * nothing: the mass matrix of the covered part, whose inverse gives the
     * dual basis, has a condition number of about 12 / c^2 (1.2e7 here),
     * and the derivatives through its inverse lose about as many digits.
     */
    static constexpr double minimum_covered_fraction = 1e-3;

    /**
     * The same for faces of degree 2, whose 3 x 3 mass matrix of a covered
     * fraction c has a condition number growing like c^-4.
     */
    static constexpr double minimum_covered_fraction_2 = 1e-2;

    /**
     * Any weight will do: the dual basis of the covered part keeps the
     * normalized weighted gap of every node of a contributing face bounded
     * (for a linear gap it is the gap at the node); that node's weight is
     * at least minimum_covered_fraction^2 / 2 of the face length (degree
     * 1) or 10 % of its weight on the whole face (degree 2: a node below
     * that leaves the face's multipliers, mortar_contact_quadratic.cc).
     */
    double
    minimum_coverage() const override
    {
      return 0.;
    }

    /** A patch is a secondary face. */
    unsigned int
    n_patches(const PairData &pair) const override
    {
      return pair.secondary.n_faces();
    }

    BoundingBox<dim>
    patch_box(const PairData    &pair,
              const unsigned int patch,
              const VectorType  &u,
              double            &size) const override;

    std::vector<unsigned int>
    patch_nodes(const PairData &pair, const unsigned int patch) const override
    {
      return pair.secondary.face_nodes[patch];
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
    /** assemble_patch() with the AD number type AD for `unknowns`. */
    template <typename AD>
    void
    assemble_patch_ad(PairData                                   &pair,
                      const unsigned int                          patch,
                      const TrialState                           &state,
                      const std::vector<types::global_dof_index> &unknowns,
                      PatchForces                                &forces);

    /** Faces of degree 2: mortar_contact_quadratic.cc (2-D), _3d.cc. */
    std::vector<types::global_dof_index>
    quadratic_patch_unknowns(
      const PairData                  &pair,
      const unsigned int               patch,
      const std::vector<unsigned int> &primary_faces) const;

    void
    assemble_quadratic_patch(PairData          &pair,
                             const unsigned int patch,
                             const TrialState  &state,
                             PatchForces       &forces);

    /**
     * 3-D: adds a face's friction forces to `forces` and the slip rates of
     * its nodes `face` (4 or 9) to the pair's (mortar_contact_3d.cc).
     */
    void
    add_friction(PairData                                   &pair,
                 const std::vector<unsigned int>            &face,
                 const MortarFace3D::FrictionTerms          &f,
                 const std::vector<types::global_dof_index> &unknowns,
                 const unsigned int                          n_positions,
                 PatchForces                                &forces) const;

    unsigned int quadrature_points;
    unsigned int segment_edge_points;
  };

  // 3-D (mortar_contact_3d.cc): a patch reads the secondary nodes of the
  // faces around the face's nodes (their averaged normals), the primary
  // nodes of the candidate faces and the face's normal multipliers
  template <>
  std::vector<types::global_dof_index>
  MortarContact<3>::patch_unknowns(
    const PairData                  &pair,
    const unsigned int               patch,
    const std::vector<unsigned int> &primary_faces) const;

  template <>
  void
  MortarContact<3>::assemble_patch(PairData          &pair,
                                   const unsigned int patch,
                                   const TrialState  &state,
                                   PatchForces       &forces);

  template <>
  void
  MortarContact<3>::add_friction(
    PairData                                   &pair,
    const std::vector<unsigned int>            &face,
    const MortarFace3D::FrictionTerms          &f,
    const std::vector<types::global_dof_index> &unknowns,
    const unsigned int                          n_positions,
    PatchForces                                &forces) const;

  // 3-D faces of degree 2 (mortar_contact_quadratic_3d.cc): the face's 9
  // nodes (with friction the secondary nodes around them), the primary
  // nodes of the candidates, the 9 normal multipliers (with friction the
  // 18 tangential ones)
  template <>
  std::vector<types::global_dof_index>
  MortarContact<3>::quadratic_patch_unknowns(
    const PairData                  &pair,
    const unsigned int               patch,
    const std::vector<unsigned int> &primary_faces) const;

  template <>
  void
  MortarContact<3>::assemble_quadratic_patch(PairData          &pair,
                                             const unsigned int patch,
                                             const TrialState  &state,
                                             PatchForces       &forces);
} // namespace ContactDynamics

#endif
