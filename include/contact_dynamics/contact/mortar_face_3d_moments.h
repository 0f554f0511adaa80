// Internals of the 3-D mortar face integrals shared by the first-order pass
// (source/contact/mortar_face_3d.cc) and the second-order one
// (source/contact/mortar_face_3d_hessian.cc): the moments of one mortar
// segment, the dual basis from them, and the maps from a segment's
// variables to a patch's positions. Not part of the interface.
#ifndef contact_dynamics_contact_mortar_face_3d_moments_h
#define contact_dynamics_contact_mortar_face_3d_moments_h

#include <deal.II/base/exceptions.h>

#include <contact_dynamics/contact/mortar_face_3d.h>

#include <map>

namespace ContactDynamics
{
  namespace MortarFace3D
  {
    namespace internal
    {
      using namespace ClippingGeometry;


      // clipping tolerance, relative to the secondary face's diameter
      constexpr double clip_tolerance = 1e-10;

      // The mortar moments of one segment: I_m = sum N_m g w (m over the
      // secondary face's nodes), D_j = sum N_j w and M_jk = sum N_j N_k w
      // (j <= k), from which the face's gaps follow (dual_sums()); with
      // `rates`, also R_m = sum N_m (v_rel . n) w (moments 18 to 21).
      constexpr unsigned int n_moments = 18, n_rate_moments = 22;

      // The velocities of a segment's nodes, constants to segment_moments():
      // they enter the rates linearly, with the coefficients dR_m / dv of the
      // secondary (a < 4) and primary (4 + a) nodes' components d that
      // segment_moments() adds to `coefficient[m][a][d]`.
      struct SegmentVelocities
      {
        std::array<Vec3<double>, 4>                         vs, vm;
        std::array<std::array<std::array<double, 3>, 8>, 4> coefficient{};
      };

      template <typename Number, std::size_t n_out>
      std::array<Number, n_out>
      segment_moments(const std::array<Vec3<Number>, 4> &xs,
                      const std::array<Vec3<Number>, 4> &ns,
                      const std::array<Vec3<Number>, 4> &xm,
                      const TriangleRule                &rule,
                      SegmentVelocities                 *rates  = nullptr,
                      std::array<Number, 16>            *mortar = nullptr)
      {
        static_assert(n_out == n_moments || n_out == n_rate_moments);
        Assert((n_out == n_rate_moments) == (rates != nullptr),
               ExcInternalError());
        std::vector<SegmentPoint<Number>> points;
        AssertThrow(segment_points(xs, ns, xm, clip_tolerance, points, rule),
                    ExcInternalError());
        std::array<Number, n_out> moments;
        moments.fill(Number(0.));
        if (mortar)
          mortar->fill(Number(0.));
        for (const auto &q : points)
          {
            // P_lk = sum N_l N_k^primary w, of the mortar matrix M = A P
            if (mortar)
              {
                const auto Ns = shape(q.xi_s, q.eta_s);
                const auto Nm = shape(q.xi_m, q.eta_m);
                for (unsigned int l = 0; l < 4; ++l)
                  for (unsigned int k = 0; k < 4; ++k)
                    (*mortar)[4 * l + k] += Ns[l] * Nm[k] * q.weight;
              }
            const auto   Ns = shape(q.xi_s, q.eta_s);
            Vec3<Number> n;
            const Number g = point_gap(xs, ns, xm, q, n);
            for (unsigned int j = 0, jk = 8; j < 4; ++j)
              {
                moments[j] += Ns[j] * g * q.weight;
                moments[4 + j] += Ns[j] * q.weight;
                for (unsigned int k = j; k < 4; ++k, ++jk)
                  moments[jk] += Ns[j] * Ns[k] * q.weight;
              }
            if constexpr (n_out == n_rate_moments)
              {
                const auto Nm  = shape(q.xi_m, q.eta_m);
                Number     v_n = 0.;
                for (unsigned int d = 0; d < 3; ++d)
                  {
                    Number v = 0.;
                    for (unsigned int a = 0; a < 4; ++a)
                      v += Ns[a] * rates->vs[a][d] - Nm[a] * rates->vm[a][d];
                    v_n += v * n[d];
                  }
                for (unsigned int m = 0; m < 4; ++m)
                  {
                    moments[n_moments + m] += Ns[m] * v_n * q.weight;
                    const double c = value_of(Ns[m] * q.weight);
                    for (unsigned int a = 0; a < 4; ++a)
                      for (unsigned int d = 0; d < 3; ++d)
                        {
                          const double nd = value_of(n[d]);
                          rates->coefficient[m][a][d] +=
                            c * value_of(Ns[a]) * nd;
                          rates->coefficient[m][4 + a][d] -=
                            c * value_of(Nm[a]) * nd;
                        }
                  }
              }
          }
        return moments;
      }

      // The dual basis A = D M^-1 of the covered part from a face's moments
      // (summed over its segments)
      template <typename Number, std::size_t n_out>
      std::array<std::array<Number, 4>, 4>
      dual_of(const std::array<Number, n_out> &moments)
      {
        std::array<Number, 4>                D;
        std::array<std::array<Number, 4>, 4> M;
        for (unsigned int j = 0, jk = 8; j < 4; ++j)
          {
            D[j] = moments[4 + j];
            for (unsigned int k = j; k < 4; ++k, ++jk)
              M[j][k] = M[k][j] = moments[jk];
          }
        return dual_from_moments(D, M);
      }

      // sum_m A_jm moments[first + m] for the face's nodes j: the weighted
      // gaps (first = 0) or rates (first = 18, with the opposite sign)
      template <typename Number, std::size_t n_out>
      std::array<Number, 4>
      dual_sums(const std::array<std::array<Number, 4>, 4> &A,
                const std::array<Number, n_out>            &moments,
                const unsigned int                          first)
      {
        std::array<Number, 4> result;
        for (unsigned int j = 0; j < 4; ++j)
          {
            result[j] = 0.;
            for (unsigned int m = 0; m < 4; ++m)
              result[j] += A[j][m] * moments[first + m];
          }
        return result;
      }

      // Where each of a patch's nodes has its first position (3 k)
      using PositionIndex =
        std::map<std::pair<const Surface *, unsigned int>, unsigned int>;

      // What a face reads of its patch: the index of every node of `nodes`,
      // how many of them are secondary (the ring around the face, which
      // comes first), and the face's nodal normals with their derivatives
      // in the ring positions (the first 3 n_ring entries of `position`):
      // normal_gradient[(3 a + c) 3 n_ring + i] of component c of node a's
      struct FaceRing
      {
        PositionIndex               index;
        unsigned int                n_ring = 0;
        std::array<Vec3<double>, 4> normal;
        std::vector<double>         normal_gradient;
      };

      FaceRing
      face_ring(const Surface             &s,
                const unsigned int         e,
                const PatchNodes          &nodes,
                const std::vector<double> &position);

      // The sparse rows that map the 36 variables of a segment's moments
      // (x of the secondary face, its nodal normals, x of the primary face)
      // to the positions of a patch
      using VariableMap =
        std::array<std::vector<std::pair<unsigned, double>>, 36>;

      VariableMap
      variable_map(const std::array<unsigned int, 4> &secondary_index,
                   const std::array<unsigned int, 4> &primary_index,
                   const std::vector<double>         &normal_gradient,
                   const unsigned int                 n_ring_positions);

      // The corners of face f of `surface` from the patch's positions (or
      // velocities) x, and where each corner's first entry is (`first`)
      std::array<Vec3<double>, 4>
      corners(const PositionIndex         &index,
              const Surface               &surface,
              const unsigned int           f,
              const std::vector<double>   &x,
              std::array<unsigned int, 4> &first);
    } // namespace internal
  }   // namespace MortarFace3D
} // namespace ContactDynamics

#endif
