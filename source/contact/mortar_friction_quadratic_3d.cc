// 3-D dual mortar patches of degree 2: the Coulomb friction terms of a
// secondary 9-node face (QuadraticSegment3D::friction_terms()), from its
// segments' moments. The mortar factors follow from the dual basis of the
// covered part, the tangents from the averaged nodal normals of the curved
// faces, both with exact first derivatives.
#include <contact_dynamics/contact/contact_ad.h>
#include <contact_dynamics/contact/quadratic_mortar_face_3d.h>

namespace ContactDynamics
{
  namespace QuadraticSegment3D
  {
    namespace
    {
      // the averaged unit normals of face e's nodes and their derivatives
      // gradient[(3 a + c) nr + i] in the first nr = 3 secondary.size()
      // positions
      void
      nodal_normals(const ClippingGeometry::Surface &s,
                    const unsigned int               e,
                    const std::vector<unsigned int> &secondary,
                    const std::vector<double>       &position,
                    std::vector<Vec3<double>>       &normal,
                    std::vector<double>             &gradient)
      {
        const unsigned int nr = 3 * secondary.size();
        normal.resize(9);
        gradient.assign(27 * nr, 0.);
        ContactAD::dispatch(nr, [&](const auto zero) {
          using AD = std::decay_t<decltype(zero)>;
          ClippingGeometry::NodeMap<AD> x;
          for (unsigned int i = 0; i < nr; ++i)
            x[secondary[i / 3]][i % 3] = AD(nr, i, position[i]);
          for (unsigned int a = 0; a < 9; ++a)
            {
              const auto v =
                ClippingGeometry::nodal_normal(s, s.face_nodes[e][a], x);
              for (unsigned int c = 0; c < 3; ++c)
                {
                  normal[a][c] = value_of(v[c]);
                  for (int i = 0; i < v[c].size(); ++i)
                    gradient[(3 * a + c) * nr + i] = value_of(v[c].dx(i));
                }
            }
        });
      }

      // the 54 moments the dual basis depends on: D (9 to 17), M (18 to 62)
      using DualAD = Sacado::Fad::SFad<double, 54>;

      // dX/dx_i of a function of the moments 9 to 62
      std::vector<double>
      chained(const DualAD &X, const FaceMoments &fm, const unsigned int n_x)
      {
        std::vector<double> d(n_x, 0.);
        for (unsigned int v = 0; v < 54; ++v)
          if (const double dv = X.fastAccessDx(v); dv != 0)
            for (unsigned int i = 0; i < n_x; ++i)
              d[i] += dv * fm.gradient[(9 + v) * n_x + i];
        return d;
      }
    } // namespace



    MortarFace3D::FrictionTerms
    friction_terms(const ClippingGeometry::Surface          &s,
                   const unsigned int                        e,
                   const std::vector<unsigned int>          &secondary,
                   const FaceMoments                        &fm,
                   const Map9                               &T,
                   const std::vector<double>                &position,
                   const std::vector<double>                &velocity,
                   const double                              c_v,
                   const std::vector<std::array<double, 2>> &lambda)
    {
      const unsigned int        n_x = position.size();
      std::vector<Vec3<double>> normal;
      std::vector<double>       normal_gradient;
      nodal_normals(s, e, secondary, position, normal, normal_gradient);
      std::vector<unsigned int> axis(9);
      for (unsigned int j = 0; j < 9; ++j)
        axis[j] = ClippingGeometry::tangent_axis(s, s.face_nodes[e][j]);
      MortarFace3D::FrictionAssembler friction(normal,
                                               normal_gradient,
                                               3 * secondary.size(),
                                               axis,
                                               lambda,
                                               velocity,
                                               c_v);

      // psi_j = sum_l A_jl N_l, A = diag(D') K T, as functions of the moments
      std::array<DualAD, n_moments> m;
      for (unsigned int q = 0; q < n_moments; ++q)
        m[q] = q >= 9 && q < 63 ? DualAD(54, q - 9, fm.total[q]) :
                                  DualAD(fm.total[q]);
      const auto                           K = primed_inverse(m, T);
      std::array<std::array<DualAD, 9>, 9> A;
      for (unsigned int j = 0; j < 9; ++j)
        {
          DualAD D = 0.;
          for (unsigned int k = 0; k < 9; ++k)
            if (T[j][k] != 0)
              D += T[j][k] * m[9 + k];
          for (unsigned int l = 0; l < 9; ++l)
            {
              A[j][l] = 0.;
              for (unsigned int r = 0; r < 9; ++r)
                if (T[r][l] != 0)
                  A[j][l] += K[j][r] * T[r][l];
              A[j][l] *= D;
            }
        }
      const auto mass = [&](const unsigned int l, const unsigned int k) {
        const unsigned int a = std::min(l, k), b = std::max(l, k);
        return m[18 + a * 9 - a * (a - 1) / 2 + (b - a)];
      };

      bool identity = true;
      for (unsigned int j = 0; j < 9; ++j)
        for (unsigned int k = 0; k < 9; ++k)
          identity = identity && T[j][k] == (j == k ? 1. : 0.);
      std::vector<std::array<std::vector<double>, 9>> dA(9);
      for (unsigned int j = 0; j < 9; ++j)
        {
          if (T[j][j] == 0)
            continue; // (a dropped node: psi_j = 0)
          for (unsigned int l = 0; l < 9; ++l)
            dA[j][l] = chained(A[j][l], fm, n_x);
          // the secondary nodes: S_jk = sum_l A_jl int N_l N_k (D_j
          // delta_jk where every node keeps its function: biorthogonality)
          for (unsigned int k = 0; k < 9; ++k)
            {
              if (identity && k != j)
                continue;
              DualAD S = identity ? m[9 + j] : DualAD(0.);
              for (unsigned int l = 0; l < 9 && !identity; ++l)
                S += A[j][l] * mass(l, k);
              std::vector<double> d = chained(S, fm, n_x);
              for (double &x : d)
                x = -x;
              friction.add(j, 3 * k, -S.val(), d);
            }
        }
      // the primary nodes: M_jk = sum_l A_jl P_lk per segment
      std::vector<double> d_factor(n_x);
      for (unsigned int g = 0; g < fm.covering.size(); ++g)
        {
          const auto &P     = fm.coupling[g];
          const auto &dP    = fm.d_coupling[g];
          const auto &index = fm.variables[g];
          for (unsigned int j = 0; j < 9; ++j)
            if (T[j][j] != 0)
              for (unsigned int k = 0; k < 9; ++k)
                {
                  double M = 0;
                  std::fill(d_factor.begin(), d_factor.end(), 0.);
                  for (unsigned int l = 0; l < 9; ++l)
                    {
                      const double a = A[j][l].val(), p = P[9 * l + k];
                      M += a * p;
                      for (unsigned int i = 0; i < n_x; ++i)
                        d_factor[i] += dA[j][l][i] * p;
                      for (int v = 0; v < n_v; ++v)
                        d_factor[index[v]] += a * dP[9 * l + k][v];
                    }
                  friction.add(j, index[27 + 3 * k], M, d_factor);
                }
        }
      return std::move(friction.terms);
    }
  } // namespace QuadraticSegment3D
} // namespace ContactDynamics
