// 3-D dual mortar patches: the second derivatives of a secondary face's
// normal force (exact_directions() of mortar_face_3d.h), chained from the
// segments' moments, the nodal normals and the dual basis of the covered
// part (the first-order pass is mortar_face_3d.cc).
#include <deal.II/base/exceptions.h>

#include <contact_dynamics/contact/contact_ad.h>
#include <contact_dynamics/contact/mortar_face_3d.h>
#include <contact_dynamics/contact/mortar_face_3d_moments.h>
#include <contact_dynamics/contact/reverse_hessian_sweep.h>

#include <algorithm>

namespace ContactDynamics
{
  namespace MortarFace3D
  {
    namespace
    {
      using namespace internal;


      // the ring positions of a face's normals that fit on the stack (16
      // nodes on a structured surface)
      constexpr int ring_width = 60;

      // g_j / w_j of the face's nodes from its moments, w_j = D_j
      template <typename Number>
      std::array<Number, 4>
      normalized_gaps(const std::array<Number, n_moments> &moments)
      {
        auto ratio = dual_sums(dual_of(moments), moments, 0);
        for (unsigned int j = 0; j < 4; ++j)
          ratio[j] /= moments[4 + j];
        return ratio;
      }

      // The value, gradient and Hessian of a function's outputs in n inputs.
      template <unsigned int n_outputs, unsigned int n>
      struct SecondOrder
      {
        std::array<double, n_outputs>                               value;
        std::array<std::array<double, n>, n_outputs>                gradient;
        std::array<std::array<std::array<double, n>, n>, n_outputs> hessian;

        // from the outputs y of a Fad of Fads seeded in n inputs
        template <typename AD2>
        void
        set(const std::array<AD2, n_outputs> &y)
        {
          for (unsigned int q = 0; q < n_outputs; ++q)
            {
              value[q] = y[q].val().val();
              for (unsigned int k = 0; k < n; ++k)
                {
                  gradient[q][k] = y[q].dx(k).val();
                  for (unsigned int l = 0; l < n; ++l)
                    hessian[q][k][l] = y[q].dx(k).dx(l);
                }
            }
        }
      };

      template <int n>
      Sacado::Fad::SFad<Sacado::Fad::SFad<double, n>, n>
      seeded(const double value, const unsigned int k)
      {
        using Inner = Sacado::Fad::SFad<double, n>;
        return Sacado::Fad::SFad<Inner, n>(n, k, Inner(n, k, value));
      }

      // The moments of a segment in its 36 variables (x of the secondary
      // face, its nodal normals, x of the primary face): their gradients,
      // and the Hessian of sum_q c_q moment_q only
      struct SegmentSecondOrder
      {
        std::array<std::array<double, 36>, n_moments> gradient;
        std::array<std::array<double, 36>, 36>        hessian;
      };

      // The covering segments' corners (their first positions in `is`,
      // `ip`) and the maps of their variables to the positions
      struct CoveringSegments
      {
        std::vector<std::array<Vec3<double>, 4>> xs, xm;
        std::vector<VariableMap>                 maps;
      };

      CoveringSegments
      covering_segments(const Surface                   &s,
                        const Surface                   &p,
                        const unsigned int               e,
                        const PositionIndex             &index,
                        const std::vector<unsigned int> &covering,
                        const std::vector<double>       &position,
                        const std::vector<double>       &normal_gradient,
                        const unsigned int               n_ring)
      {
        CoveringSegments            result;
        std::array<unsigned int, 4> is, ip;
        for (const unsigned int pf : covering)
          {
            result.xs.push_back(corners(index, s, e, position, is));
            result.xm.push_back(corners(index, p, pf, position, ip));
            result.maps.push_back(
              variable_map(is, ip, normal_gradient, 3 * n_ring));
          }
        return result;
      }

      // Step (4) of exact_directions(): a segment's moments with their
      // gradients, and the Hessian of sum_q c_q moment_q, by reverse over
      // forward mode (reverse_hessian.h: 10 times faster here than a Fad of
      // Fads, which gives the Hessian of every moment)
      SegmentSecondOrder
      segment_second_order(const std::array<Vec3<double>, 4>   &xs_d,
                           const std::array<Vec3<double>, 4>   &normal,
                           const std::array<Vec3<double>, 4>   &xm_d,
                           const std::array<double, n_moments> &c,
                           const TriangleRule                  &rule)
      {
        constexpr int n_v = 36;
        using Inner       = Sacado::Fad::SFad<double, n_v>;
        using Number      = ReverseHessian::Number<Inner>;
        ReverseHessian::start<Inner>();
        std::array<Vec3<Number>, 4> xs, ns, xm;
        for (unsigned int a = 0; a < 4; ++a)
          for (unsigned int d = 0; d < 3; ++d)
            {
              xs[a][d] = Number::independent(xs_d[a][d], 3 * a + d, n_v);
              ns[a][d] = Number::independent(normal[a][d], 12 + 3 * a + d, n_v);
              xm[a][d] = Number::independent(xm_d[a][d], 24 + 3 * a + d, n_v);
            }
        const auto moments =
          segment_moments<Number, n_moments>(xs, ns, xm, rule);
        SegmentSecondOrder result;
        Number             weighted = 0.;
        for (unsigned int q = 0; q < n_moments; ++q)
          {
            weighted += c[q] * moments[q];
            for (int v = 0; v < n_v; ++v)
              result.gradient[q][v] =
                moments[q].index < 0 ? 0. : moments[q].value().dx(v);
          }
        result.hessian = {};
        if (weighted.index < 0)
          return result;
        const ReverseHessian::Sweep<Inner> sweep(weighted);
        for (unsigned int a = 0; a < 4; ++a)
          for (unsigned int d = 0; d < 3; ++d)
            for (const auto &[k, x] :
                 {std::make_pair(3 * a + d, xs[a][d]),
                  std::make_pair(12 + 3 * a + d, ns[a][d]),
                  std::make_pair(24 + 3 * a + d, xm[a][d])})
              {
                const auto adjoint = sweep(x);
                for (int l = 0; l < n_v; ++l)
                  result.hessian[k][l] = adjoint.dx(l);
              }
        return result;
      }

      // G[q n_x + i] = d moment_q / dx_i of the summed moments, and into
      // `hessian` sum_q c_q d^2 moment_q / dx^2: chained through the maps,
      // plus the normals' own second derivatives
      void
      add_moment_hessians(const SegmentSecondOrder            &seg,
                          const VariableMap                   &map,
                          const std::array<double, n_moments> &c,
                          const unsigned int                   n_x,
                          std::vector<double>                 &G,
                          std::array<double, 12>              &normal_weight,
                          std::vector<double>                 &hessian)
      {
        constexpr unsigned int n_v = 36;
        for (unsigned int q = 0; q < n_moments; ++q)
          for (unsigned int v = 0; v < n_v; ++v)
            for (const auto &[i, y] : map[v])
              G[q * n_x + i] += seg.gradient[q][v] * y;
        for (unsigned int v = 0; v < n_v; ++v)
          for (unsigned int w = 0; w < n_v; ++w)
            if (const double h = seg.hessian[v][w]; h != 0)
              for (const auto &[i, yi] : map[v])
                for (const auto &[l, yl] : map[w])
                  hessian[i * n_x + l] += h * yi * yl;
        for (unsigned int v = 12; v < 24; ++v)
          for (unsigned int q = 0; q < n_moments; ++q)
            normal_weight[v - 12] += c[q] * seg.gradient[q][v];
      }

      // Adds sum_v weight_v d^2 n_v / dx^2 of the face's nodal normals n_v
      // (component v % 3 of node v / 3) in the ring positions, by reverse
      // over forward mode with Inner's first derivatives
      template <typename Inner>
      void
      add_normal_hessian(const Surface                &s,
                         const unsigned int            e,
                         const PatchNodes             &nodes,
                         const std::vector<double>    &position,
                         const unsigned int            n_ring,
                         const std::array<double, 12> &weight,
                         std::vector<double>          &hessian)
      {
        using Number       = ReverseHessian::Number<Inner>;
        const int      n   = 3 * n_ring;
        const unsigned n_x = position.size();
        ReverseHessian::start<Inner>();
        NodeMap<Number>     ring;
        std::vector<Number> inputs;
        for (int i = 0; i < n; ++i)
          {
            inputs.push_back(Number::independent(position[i], i, n));
            ring[nodes[i / 3].second][i % 3] = inputs.back();
          }
        Number weighted = 0.;
        for (unsigned int a = 0; a < 4; ++a)
          {
            const auto normal = nodal_normal(s, s.faces[e][a], ring);
            for (unsigned int c = 0; c < 3; ++c)
              if (weight[3 * a + c] != 0)
                weighted += weight[3 * a + c] * normal[c];
          }
        if (weighted.index < 0)
          return;
        const ReverseHessian::Sweep<Inner> sweep(weighted);
        for (int i = 0; i < n; ++i)
          {
            const Inner adjoint = sweep(inputs[i]);
            for (int l = 0; l < adjoint.size(); ++l)
              hessian[i * n_x + l] += adjoint.dx(l);
          }
      }

      // The moments' first derivatives through the gaps' second ones, and
      // the derivative of the weights w_j = D_j in the directions
      void
      add_gap_hessian(const SecondOrder<4, n_moments>     &ratio,
                      const std::array<double, n_moments> &total,
                      const std::array<double, 4>         &lambda,
                      const std::vector<double>           &G,
                      const unsigned int                   n_x,
                      std::vector<std::array<double, 4>>  &direction,
                      std::vector<double>                 &hessian)
      {
        std::vector<std::array<double, 4>> gradient(n_x, {{0., 0., 0., 0.}});
        for (unsigned int i = 0; i < n_x; ++i)
          for (unsigned int j = 0; j < 4; ++j)
            {
              for (unsigned int q = 0; q < n_moments; ++q)
                gradient[i][j] += ratio.gradient[j][q] * G[q * n_x + i];
              direction[i][j] = total[4 + j] * gradient[i][j];
            }
        std::array<std::array<double, n_moments>, n_moments> B{};
        for (unsigned int j = 0; j < 4; ++j)
          for (unsigned int q = 0; q < n_moments; ++q)
            for (unsigned int r = 0; r < n_moments; ++r)
              B[q][r] += lambda[j] * total[4 + j] * ratio.hessian[j][q][r];
        std::vector<double> BG(n_moments * n_x, 0.);
        for (unsigned int q = 0; q < n_moments; ++q)
          for (unsigned int r = 0; r < n_moments; ++r)
            if (B[q][r] != 0)
              for (unsigned int l = 0; l < n_x; ++l)
                BG[q * n_x + l] += B[q][r] * G[r * n_x + l];
        for (unsigned int i = 0; i < n_x; ++i)
          for (unsigned int l = 0; l < n_x; ++l)
            {
              double h = 0;
              for (unsigned int q = 0; q < n_moments; ++q)
                h += G[q * n_x + i] * BG[q * n_x + l];
              for (unsigned int j = 0; j < 4; ++j)
                h += lambda[j] * gradient[i][j] * G[(4 + j) * n_x + l];
              hessian[i * n_x + l] += h;
            }
      }
    } // namespace

    // Second derivatives cost the square of the number of variables, so they
    // are taken where they are few and chained: the normalized gaps in the
    // 18 moments summed over the segments (the dual basis of the covered part
    // couples them) by a Fad of Fads; each segment's moments in the 36
    // variables it reads (the face's nodes, its nodal normals, the primary
    // face's nodes) and the four nodal normals in the positions of the
    // secondary nodes around the face by reverse over forward mode, which
    // gives the Hessian of the one weighted sum that the force needs
    // (sum_q c_q m_q, with c_q from the gaps' gradients) and not of every
    // moment. A Fad of Fads in all of a patch's positions (60 to 80) cost
    // 5.6 times as much as the first chaining; reverse over forward cut what
    // was left by 6.
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
                     std::vector<double>                &hessian)
    {
      const unsigned int n_x = position.size();
      // (1) where the nodes are in `position`, and the nodal normals in the
      // ring positions (the first 3 n_ring), first order (their second
      // derivatives follow in (5))
      const auto &[index, n_ring, normal, normal_gradient] =
        face_ring(s, e, nodes, position);

      // (2) the moments summed over the covering segments, in double
      const auto                    segs = covering_segments(s,
                                          p,
                                          e,
                                          index,
                                          covering,
                                          position,
                                          normal_gradient,
                                          n_ring);
      std::array<double, n_moments> total{};
      for (unsigned int k = 0; k < covering.size(); ++k)
        {
          const auto m = segment_moments<double, n_moments>(segs.xs[k],
                                                            normal,
                                                            segs.xm[k],
                                                            rule);
          for (unsigned int q = 0; q < n_moments; ++q)
            total[q] += m[q];
        }

      // (3) the normalized gaps in the moments
      using Moments2 =
        Sacado::Fad::SFad<Sacado::Fad::SFad<double, n_moments>, n_moments>;
      std::array<Moments2, n_moments> moments;
      for (unsigned int q = 0; q < n_moments; ++q)
        moments[q] = seeded<n_moments>(total[q], q);
      SecondOrder<4, n_moments> ratio;
      ratio.set(normalized_gaps(moments));

      // (4) each segment's moments in its 36 variables (x of the face, its
      // normals, x of the primary face), mapped to the positions; c_q
      // weights the moments' Hessians, G[q n_x + i] = d moment_q / dx_i
      std::array<double, n_moments> c;
      for (unsigned int q = 0; q < n_moments; ++q)
        {
          c[q] = 0;
          for (unsigned int j = 0; j < 4; ++j)
            c[q] += lambda[j] * total[4 + j] * ratio.gradient[j][q];
        }
      std::vector<double> G(n_moments * n_x, 0.);
      std::fill(hessian.begin(), hessian.end(), 0.);
      std::array<double, 12> normal_weight{};
      for (unsigned int k = 0; k < covering.size(); ++k)
        add_moment_hessians(
          segment_second_order(segs.xs[k], normal, segs.xm[k], c, rule),
          segs.maps[k],
          c,
          n_x,
          G,
          normal_weight,
          hessian);

      // (5) the normals' own second derivatives, weighted
      if (3 * n_ring <= ring_width)
        add_normal_hessian<Sacado::Fad::SLFad<double, ring_width>>(
          s,
          e,
          nodes,
          position,
          n_ring,
          normal_weight,
          hessian);
      else
        add_normal_hessian<Sacado::Fad::DFad<double>>(s,
                                                      e,
                                                      nodes,
                                                      position,
                                                      n_ring,
                                                      normal_weight,
                                                      hessian);
      add_gap_hessian(ratio, total, lambda, G, n_x, direction, hessian);
    }
  } // namespace MortarFace3D
} // namespace ContactDynamics
