// 3-D dual mortar patches: the Coulomb friction terms of a secondary face
// (MortarFace3D::FrictionAssembler, shared by faces of degree 1 and 2;
// friction_terms() for degree 1, from its first-order pass).
#include <contact_dynamics/contact/contact_ad.h>
#include <contact_dynamics/contact/mortar_face_3d.h>

#include <algorithm>

namespace ContactDynamics
{
  namespace MortarFace3D
  {
    using namespace ClippingGeometry;

    FrictionAssembler::FrictionAssembler(
      const std::vector<Vec3<double>>          &normal,
      const std::vector<double>                &normal_gradient,
      const unsigned int                        n_ring,
      const std::vector<unsigned int>          &axis,
      const std::vector<std::array<double, 2>> &lambda,
      const std::vector<double>                &velocity,
      const double                              c_v)
      : velocity(velocity)
      , c_v(c_v)
      , n_ring(n_ring)
      , n_face(normal.size())
      , t(n_face)
      , dt(n_face)
      , lt(n_face)
      , dlt(n_face)
    {
      const unsigned int nr = n_ring;
      using N3              = Sacado::Fad::SFad<double, 3>;
      for (unsigned int j = 0; j < n_face; ++j)
        {
          Vec3<N3> n;
          for (unsigned int c = 0; c < 3; ++c)
            n[c] = N3(3, c, normal[j][c]);
          const auto basis = tangent_basis(n, axis[j]);
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
                        d * normal_gradient[(3 * j + b) * nr + i];
                lt[j][c] += lambda[j][a] * t[j][a][c];
                for (unsigned int i = 0; i < nr; ++i)
                  dlt[j][c][i] += lambda[j][a] * dt[j][a][c][i];
              }
        }
      const unsigned int n = velocity.size();
      terms.force.assign(n, 0.);
      terms.d_force.assign(n, std::vector<double>(n + 3 * n_face, 0.));
      terms.slip.assign(n_face, {{0., 0.}});
      terms.d_slip.resize(n_face);
      for (unsigned int j = 0; j < n_face; ++j)
        for (unsigned int a = 0; a < 2; ++a)
          terms.d_slip[j][a].assign(n, 0.);
    }



    void
    FrictionAssembler::add(const unsigned int         j,
                           const unsigned int         first,
                           const double               factor,
                           const std::vector<double> &d_factor)
    {
      const unsigned int n  = velocity.size();
      const unsigned int nr = n_ring;
      // the tangential multipliers follow the positions and the normal ones
      for (unsigned int c = 0; c < 3; ++c)
        {
          auto &row = terms.d_force[first + c];
          terms.force[first + c] -= factor * lt[j][c];
          for (unsigned int i = 0; i < n; ++i)
            row[i] -= d_factor[i] * lt[j][c];
          for (unsigned int i = 0; i < nr; ++i)
            row[i] -= factor * dlt[j][c][i];
          for (unsigned int a = 0; a < 2; ++a)
            row[n + n_face + 2 * j + a] -= factor * t[j][a][c];
        }
      for (unsigned int a = 0; a < 2; ++a)
        {
          auto  &d  = terms.d_slip[j][a];
          double tv = 0;
          for (unsigned int c = 0; c < 3; ++c)
            {
              const double v = velocity[first + c];
              tv += t[j][a][c] * v;
              for (unsigned int i = 0; i < nr; ++i)
                d[i] -= factor * dt[j][a][c][i] * v;
              d[first + c] -= c_v * factor * t[j][a][c];
            }
          terms.slip[j][a] -= factor * tv;
          for (unsigned int i = 0; i < n; ++i)
            d[i] -= d_factor[i] * tv;
        }
    }



    FrictionTerms
    friction_terms(const Surface                              &s,
                   const unsigned int                          e,
                   const FaceFirstOrder                       &sums,
                   const std::vector<double>                  &velocity,
                   const double                                c_v,
                   const std::array<std::array<double, 2>, 4> &lambda)
    {
      const unsigned int        n  = velocity.size();
      const auto               &is = sums.secondary_index;
      std::vector<unsigned int> axis(4);
      for (unsigned int j = 0; j < 4; ++j)
        axis[j] = tangent_axis(s, s.faces[e][j]);
      FrictionAssembler friction(
        std::vector<Vec3<double>>(sums.normal.begin(), sums.normal.end()),
        sums.normal_gradient,
        sums.n_ring_positions,
        axis,
        std::vector<std::array<double, 2>>(lambda.begin(), lambda.end()),
        velocity,
        c_v);

      // the secondary nodes: D_j
      std::vector<double> d_factor(n);
      for (unsigned int j = 0; j < 4; ++j)
        {
          for (unsigned int i = 0; i < n; ++i)
            d_factor[i] = -sums.d_weight[i][j];
          friction.add(j, is[j], -sums.weight[j], d_factor);
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
              friction.add(j, segment.primary_index[k], M, d_factor);
            }
      return std::move(friction.terms);
    }
  } // namespace MortarFace3D
} // namespace ContactDynamics
