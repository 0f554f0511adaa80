// 3-D dual mortar patches: the Coulomb friction terms of a secondary face
// (MortarFace3D::friction_terms()), from its first-order pass.
#include <contact_dynamics/contact/contact_ad.h>
#include <contact_dynamics/contact/mortar_face_3d.h>

#include <algorithm>

namespace ContactDynamics
{
  namespace MortarFace3D
  {
    namespace
    {
      using namespace ClippingGeometry;

      // The tangents t[j][a] of the face's nodes and their derivatives
      // dt[j][a][c][i] in the ring positions (i < nr); lambda_t,j and its
      // derivatives in the ring positions
      struct FaceTangents
      {
        std::array<std::array<Vec3<double>, 2>, 4>                       t;
        std::array<std::array<std::array<std::vector<double>, 3>, 2>, 4> dt;
        std::array<Vec3<double>, 4>                                      lt;
        std::array<std::array<std::vector<double>, 3>, 4>                dlt;
      };

      FaceTangents
      face_tangents(const Surface                              &s,
                    const unsigned int                          e,
                    const FaceFirstOrder                       &sums,
                    const std::array<std::array<double, 2>, 4> &lambda)
      {
        const unsigned int nr = sums.n_ring_positions;
        FaceTangents       tangents;
        auto              &t   = tangents.t;
        auto              &dt  = tangents.dt;
        auto              &lt  = tangents.lt;
        auto              &dlt = tangents.dlt;
        using N3               = Sacado::Fad::SFad<double, 3>;
        for (unsigned int j = 0; j < 4; ++j)
          {
            Vec3<N3> normal;
            for (unsigned int c = 0; c < 3; ++c)
              normal[c] = N3(3, c, sums.normal[j][c]);
            const auto basis =
              tangent_basis(normal, tangent_axis(s, s.faces[e][j]));
            for (unsigned int c = 0; c < 3; ++c)
              dlt[j][c].assign(nr, 0.);
            for (unsigned int a = 0; a < 2; ++a)
              for (unsigned int c = 0; c < 3; ++c)
                {
                  t[j][a][c] = basis[a][c].val();
                  dt[j][a][c].assign(nr, 0.);
                  for (unsigned int b = 0; b < 3; ++b)
                    if (const double d = basis[a][c].fastAccessDx(b); d != 0)
                      for (unsigned int i = 0; i < nr; ++i)
                        dt[j][a][c][i] +=
                          d * sums.normal_gradient[(3 * j + b) * nr + i];
                  lt[j][c] += lambda[j][a] * t[j][a][c];
                  for (unsigned int i = 0; i < nr; ++i)
                    dlt[j][c][i] += lambda[j][a] * dt[j][a][c][i];
                }
          }
        return tangents;
      }

      // Adds node k's force -factor lambda_t,j (factor: -D_j or M_jk, with
      // derivatives d_factor) and its part of node j's slip rates; `first`
      // is where x_k is in the positions
      void
      add_node_terms(const FaceTangents        &tangents,
                     const unsigned int         nr,
                     const std::vector<double> &velocity,
                     const double               c_v,
                     const unsigned int         j,
                     const unsigned int         first,
                     const double               factor,
                     const std::vector<double> &d_factor,
                     FrictionTerms             &result)
      {
        const unsigned int n   = velocity.size();
        const auto        &t   = tangents.t;
        const auto        &dt  = tangents.dt;
        const auto        &lt  = tangents.lt;
        const auto        &dlt = tangents.dlt;
        // the tangential multipliers follow the positions and the normal ones
        for (unsigned int c = 0; c < 3; ++c)
          {
            auto &row = result.d_force[first + c];
            result.force[first + c] -= factor * lt[j][c];
            for (unsigned int i = 0; i < n; ++i)
              row[i] -= d_factor[i] * lt[j][c];
            for (unsigned int i = 0; i < nr; ++i)
              row[i] -= factor * dlt[j][c][i];
            for (unsigned int a = 0; a < 2; ++a)
              row[n + 4 + 2 * j + a] -= factor * t[j][a][c];
          }
        for (unsigned int a = 0; a < 2; ++a)
          {
            auto  &d  = result.d_slip[j][a];
            double tv = 0;
            for (unsigned int c = 0; c < 3; ++c)
              {
                const double v = velocity[first + c];
                tv += t[j][a][c] * v;
                for (unsigned int i = 0; i < nr; ++i)
                  d[i] -= factor * dt[j][a][c][i] * v;
                d[first + c] -= c_v * factor * t[j][a][c];
              }
            result.slip[j][a] -= factor * tv;
            for (unsigned int i = 0; i < n; ++i)
              d[i] -= d_factor[i] * tv;
          }
      }
    } // namespace

    FrictionTerms
    friction_terms(const Surface                              &s,
                   const unsigned int                          e,
                   const FaceFirstOrder                       &sums,
                   const std::vector<double>                  &velocity,
                   const double                                c_v,
                   const std::array<std::array<double, 2>, 4> &lambda)
    {
      const unsigned int n        = velocity.size();
      const unsigned int nr       = sums.n_ring_positions;
      const auto        &is       = sums.secondary_index;
      const FaceTangents tangents = face_tangents(s, e, sums, lambda);

      FrictionTerms result;
      result.force.assign(n, 0.);
      result.d_force.assign(n, std::vector<double>(n + 12, 0.));
      for (unsigned int j = 0; j < 4; ++j)
        for (unsigned int a = 0; a < 2; ++a)
          result.d_slip[j][a].assign(n, 0.);
      const auto add = [&](const unsigned int         j,
                           const unsigned int         first, // of x_k
                           const double               factor,
                           const std::vector<double> &d_factor) {
        add_node_terms(tangents,
                       nr,
                       velocity,
                       c_v,
                       j,
                       first,
                       factor,
                       d_factor,
                       result);
      };

      // the secondary nodes: D_j
      std::vector<double> d_factor(n);
      for (unsigned int j = 0; j < 4; ++j)
        {
          for (unsigned int i = 0; i < n; ++i)
            d_factor[i] = -sums.d_weight[i][j];
          add(j, is[j], -sums.weight[j], d_factor);
        }
      // the primary nodes: M_jk = sum_l A_jl P_lk per segment
      for (const auto &segment : sums.segments)
        for (unsigned int j = 0; j < 4; ++j)
          for (unsigned int k = 0; k < 4; ++k)
            {
              double M = 0;
              std::fill(d_factor.begin(), d_factor.end(), 0.);
              for (unsigned int l = 0; l < 4; ++l)
                {
                  M += sums.A[j][l] * segment.P[l][k];
                  for (unsigned int i = 0; i < n; ++i)
                    d_factor[i] += sums.d_A[i][j][l] * segment.P[l][k] +
                                   sums.A[j][l] * segment.d_P[i][l][k];
                }
              add(j, segment.primary_index[k], M, d_factor);
            }
      return result;
    }
  } // namespace MortarFace3D
} // namespace ContactDynamics
