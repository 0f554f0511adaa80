// What one secondary 9-node face of 3-D dual mortar contact integrates
// (mortar_contact_quadratic_3d.cc): its segments' moments with their
// gradients, the dual basis of its covered part, and its Coulomb friction
// terms (mortar_friction_quadratic_3d.cc).
#ifndef contact_dynamics_contact_quadratic_mortar_face_3d_h
#define contact_dynamics_contact_quadratic_mortar_face_3d_h

#include <contact_dynamics/contact/mortar_face_3d.h>
#include <contact_dynamics/contact/quadratic_segment_moments_3d.h>

#include <array>
#include <vector>

namespace ContactDynamics
{
  namespace QuadraticSegment3D
  {
    constexpr int n_v = 54; // a segment's variables: x_s, then x_m
    using Map9        = std::array<std::array<double, 9>, 9>;

    /**
     * What a face's segments give: the summed moments, d moment_q / dx_i
     * in gradient[q n_x + i], and per covering segment its primary face,
     * where its 54 variables sit in the patch positions, its edge points
     * and (with friction) its coupling moments P_lk = int N_l N_k^primary
     * (coupling[9 l + k]) with their derivatives in its 54 variables.
     */
    struct FaceMoments
    {
      std::array<double, n_moments>                        total{};
      std::vector<double>                                  gradient;
      std::vector<unsigned int>                            covering;
      std::vector<std::array<unsigned, n_v>>               variables;
      std::vector<EdgePoints>                              edge_points;
      std::vector<std::array<double, 81>>                  coupling;
      std::vector<std::array<std::array<double, n_v>, 81>> d_coupling;
    };

    /**
     * K = M'^-1 for the multiplier functions N' = T N of the nodes kept,
     * M' = T M T^T with ones on the diagonal of dropped nodes, from a
     * face's moments (Number: with their derivatives).
     */
    template <typename Number>
    std::array<std::array<Number, 9>, 9>
    primed_inverse(const std::array<Number, n_moments> &m, const Map9 &T)
    {
      std::array<std::array<Number, 9>, 9> M, TM, Mp;
      for (unsigned int j = 0, jk = 18; j < 9; ++j)
        for (unsigned int k = j; k < 9; ++k, ++jk)
          M[j][k] = M[k][j] = m[jk];
      for (unsigned int j = 0; j < 9; ++j)
        for (unsigned int k = 0; k < 9; ++k)
          {
            TM[j][k] = Number(0.);
            for (unsigned int l = 0; l < 9; ++l)
              if (T[j][l] != 0)
                TM[j][k] += T[j][l] * M[l][k];
          }
      for (unsigned int j = 0; j < 9; ++j)
        for (unsigned int k = 0; k < 9; ++k)
          {
            Mp[j][k] = Number(T[j][j] == 0 && j == k ? 1. : 0.);
            for (unsigned int l = 0; l < 9; ++l)
              if (T[k][l] != 0)
                Mp[j][k] += TM[j][l] * T[k][l];
          }
      std::array<Number, 9> ones;
      ones.fill(Number(1.));
      return ClippingGeometry::dual_from_moments(ones, Mp);
    }

    /**
     * The Coulomb friction terms of secondary face e (MortarFace3D::
     * FrictionAssembler): the dual functions psi_j = sum_l A_jl N_l of the
     * covered part, A = diag(D') K T, give S_jk = int psi_j N_k and M_jk =
     * int psi_j N_k^primary per segment; the tangents follow the averaged
     * nodal normals of the face's 9 nodes over the curved faces around
     * them. `secondary` are the first secondary.size() patch nodes (the
     * face's 9, then the others around it), whose positions the normals
     * read.
     */
    MortarFace3D::FrictionTerms
    friction_terms(const ClippingGeometry::Surface          &s,
                   const unsigned int                        e,
                   const std::vector<unsigned int>          &secondary,
                   const FaceMoments                        &fm,
                   const Map9                               &T,
                   const std::vector<double>                &position,
                   const std::vector<double>                &velocity,
                   const double                              c_v,
                   const std::vector<std::array<double, 2>> &lambda);
  } // namespace QuadraticSegment3D
} // namespace ContactDynamics

#endif
