// The integrals of one secondary face of 3-D dual mortar contact
// (MortarContact<3>): its weighted gaps, weights and gap rates with their
// first derivatives (source/contact/mortar_face_3d.cc), the second
// derivatives of the normal force's directions (same file) and its Coulomb
// friction terms (source/contact/mortar_friction_3d.cc).
#ifndef contact_dynamics_contact_mortar_face_3d_h
#define contact_dynamics_contact_mortar_face_3d_h

#include <contact_dynamics/contact/clipping_geometry.h>
#include <contact_dynamics/contact/surface_geometry_3d.h>

#include <array>
#include <utility>
#include <vector>

namespace ContactDynamics
{
  namespace MortarFace3D
  {
    using ClippingGeometry::Surface;
    using ClippingGeometry::TriangleRule;
    using ClippingGeometry::Vec3;

    /**
     * The nodes whose positions a face's integrals read, as (surface,
     * node): the ring of secondary nodes around the face first, then the
     * primary nodes of its candidate faces. Node k's position is entries
     * 3 k to 3 k + 2 of a patch's positions.
     */
    using PatchNodes = std::vector<std::pair<const Surface *, unsigned int>>;

    // What a face's first-order pass gives: its nodes' weighted gaps,
    // weights and gap rates, and their derivatives in the patch's
    // positions (d_x[i][j]), the rates' including those through the
    // Newmark velocities.
    struct FaceFirstOrder
    {
      std::array<double, 4>              gap{}, weight{}, gap_rate{};
      std::vector<std::array<double, 4>> d_gap, d_weight, d_rate;
      std::vector<unsigned int> covering; // primary faces with a segment

      // with friction: the dual basis A of the covered part and, per
      // covering face, the moments P_lk = sum N_l N_k^primary w of the
      // mortar matrix M = A P (l over the secondary face's nodes, k over
      // the primary face's), with derivatives d_x[i]
      using Matrix = std::array<std::array<double, 4>, 4>;
      // the nodal normals, their derivatives in the ring positions (as in
      // face_ring()) and where the face's nodes are in the positions
      std::array<Vec3<double>, 4> normal;
      std::vector<double>         normal_gradient;
      unsigned int                n_ring_positions = 0;
      std::array<unsigned int, 4> secondary_index{};
      Matrix                      A{};
      std::vector<Matrix>         d_A;
      struct Segment
      {
        std::array<unsigned int, 4> primary_index; // of x_k in the positions
        Matrix                      P{};
        std::vector<Matrix>         d_P;
      };
      std::vector<Segment> segments;
    };

    /**
     * The mortar integrals of face e of `s` over its segments with the
     * `candidates` faces of `p` that face it; nothing if they cover less
     * than `minimum_fraction` of it (the dual basis of a sliver is
     * ill-conditioned, as in 2-D). `position` and `velocity` are those of
     * `nodes`; with `rates`, the gap rates, with `friction`, the mortar
     * matrices.
     */
    FaceFirstOrder
    first_order_sums(const Surface                   &s,
                     const Surface                   &p,
                     const std::vector<unsigned int> &candidates,
                     const unsigned int               e,
                     const PatchNodes                &nodes,
                     const std::vector<double>       &position,
                     const std::vector<double>       &velocity,
                     const double                     c_v,
                     const bool                       rates,
                     const bool                       friction,
                     const double                     minimum_fraction,
                     const TriangleRule              &rule);

    /**
     * The directions w_j d(g_j / w_j)/du_i of the normal force of face e
     * and their derivatives weighted with the multipliers `lambda`,
     * hessian[i n + l] = sum_j lambda_j d direction[i][j]/du_l, over the
     * `covering` faces of `p` (from first_order_sums()).
     */
    void
    exact_directions(const Surface                      &s,
                     const Surface                      &p,
                     const unsigned int                  e,
                     const PatchNodes                   &nodes,
                     const std::vector<unsigned int>    &covering,
                     const std::vector<double>          &position,
                     const TriangleRule                 &rule,
                     const std::array<double, 4>        &lambda,
                     std::vector<std::array<double, 4>> &direction,
                     std::vector<double>                &hessian);

    // Coulomb friction on a face, with first derivatives: the forces of the
    // tangential traction z_t = sum_j psi_j lambda_t,j on both sides
    // (lambda_t,j = sum_a lambda_a,j t_a,j along node j's tangents),
    // sum_j S_jk lambda_t,j on the secondary nodes (S_jk = int psi_j N_k =
    // D_j delta_jk by biorthogonality where no node left the face's
    // multipliers) and
    // -sum_j M_jk lambda_t,j on the primary ones, and the slip rates
    // t_a,j . (sum_k S_jk v_k - sum_k M_jk v_k) of the face's nodes (=
    // int psi_j v_rel . t_a,j).
    struct FrictionTerms
    {
      // per position i; d_force[i][l], l over the positions, then the face's
      // n normal and 2 n tangential multipliers (n + 2 j + a)
      std::vector<double>                             force;
      std::vector<std::vector<double>>                d_force;
      std::vector<std::array<double, 2>>              slip;
      std::vector<std::array<std::vector<double>, 2>> d_slip;
    };

    /**
     * Builds FrictionTerms from a face's nodal normals (with their
     * derivatives normal_gradient[(3 j + b) n_ring + i] in the first n_ring
     * positions), the reference tangent axes of its nodes, the tangential
     * multipliers and the nodes' velocities: add() takes one mortar factor
     * (-S_jk for a secondary node k, M_jk for a primary one) with its
     * derivatives in the positions.
     */
    class FrictionAssembler
    {
    public:
      FrictionAssembler(const std::vector<Vec3<double>> &normal,
                        const std::vector<double>       &normal_gradient,
                        const unsigned int               n_ring,
                        const std::vector<unsigned int> &axis,
                        const std::vector<std::array<double, 2>> &lambda,
                        const std::vector<double>                &velocity,
                        const double                              c_v);

      // node k's force -factor lambda_t,j and its part of node j's slip
      // rates; `first` is where x_k is in the positions
      void
      add(const unsigned int         j,
          const unsigned int         first,
          const double               factor,
          const std::vector<double> &d_factor);

      FrictionTerms terms;

    private:
      const std::vector<double> &velocity;
      const double               c_v;
      const unsigned int         n_ring, n_face;
      // the tangents t[j][a] and their derivatives dt[j][a][c][i] in the
      // ring positions; lambda_t,j and its derivatives
      std::vector<std::array<Vec3<double>, 2>>                       t;
      std::vector<std::array<std::array<std::vector<double>, 3>, 2>> dt;
      std::vector<Vec3<double>>                                      lt;
      std::vector<std::array<std::vector<double>, 3>>                dlt;
    };

    /**
     * The friction terms of face e of `s` from its first-order pass `sums`
     * (with friction) and the tangential multipliers `lambda`.
     */
    FrictionTerms
    friction_terms(const Surface                              &s,
                   const unsigned int                          e,
                   const FaceFirstOrder                       &sums,
                   const std::vector<double>                  &velocity,
                   const double                                c_v,
                   const std::array<std::array<double, 2>, 4> &lambda);
  } // namespace MortarFace3D
} // namespace ContactDynamics

#endif
