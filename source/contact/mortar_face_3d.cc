// 3-D dual mortar patches: the integrals of one secondary face, with its
// mortar segments with the candidate primary faces (auxiliary plane,
// clipping and triangulation of clipping_geometry.h), and the weighted gaps
// of its four nodes with the dual basis of the covered part, with first and
// second derivatives (mortar_face_3d.h).
#include <deal.II/base/exceptions.h>

#include <contact_dynamics/contact/contact_ad.h>
#include <contact_dynamics/contact/mortar_face_3d.h>

#include <algorithm>
#include <map>

namespace ContactDynamics
{
  namespace MortarFace3D
  {
    namespace
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

      // Where each of a patch's nodes has its first position (3 k), and how
      // many of them are secondary (the ring, which comes first)
      std::map<std::pair<const Surface *, unsigned int>, unsigned int>
      position_index(
        const Surface                                               &s,
        const std::vector<std::pair<const Surface *, unsigned int>> &nodes,
        unsigned int                                                &n_ring)
      {
        std::map<std::pair<const Surface *, unsigned int>, unsigned int> index;
        n_ring = 0;
        for (unsigned int k = 0; k < nodes.size(); ++k)
          {
            index[nodes[k]] = 3 * k;
            n_ring += nodes[k].first == &s;
          }
        return index;
      }

      // The nodal normals of face e and their derivatives in the positions of
      // the ring of secondary nodes around it (the first 3 n_ring entries of
      // `position`, in the order of `nodes`): gradient[(3 a + c) 3 n_ring + i]
      // and, if AD is a Fad of Fads, hessian[((3 a + c) 3 n_ring + i) 3 n_ring
      // + l] of component c of node a's normal.
      template <typename AD>
      void
      ring_normals(
        const Surface                                               &s,
        const unsigned int                                           e,
        const std::vector<std::pair<const Surface *, unsigned int>> &nodes,
        const std::vector<double>                                   &position,
        std::array<Vec3<double>, 4>                                 &normal,
        std::vector<double>                                         &gradient,
        std::vector<double>                                         &hessian)
      {
        unsigned int n_ring = 0;
        while (n_ring < nodes.size() && nodes[n_ring].first == &s)
          ++n_ring;
        const unsigned int n = 3 * n_ring;
        NodeMap<AD>        ring;
        for (unsigned int k = 0; k < n_ring; ++k)
          for (unsigned int d = 0; d < 3; ++d)
            {
              const unsigned int i = 3 * k + d;
              if constexpr (derivative_order<AD>() == 1)
                ring[nodes[k].second][d] = AD(n, i, position[i]);
              else
                ring[nodes[k].second][d] =
                  AD(n, i, typename AD::value_type(n, i, position[i]));
            }
        gradient.assign(12 * n, 0.);
        hessian.assign(derivative_order<AD>() == 1 ? 0 : 12 * n * n, 0.);
        for (unsigned int a = 0; a < 4; ++a)
          {
            const auto v = nodal_normal(s, s.faces[e][a], ring);
            for (unsigned int c = 0; c < 3; ++c)
              {
                const unsigned int ac = 3 * a + c;
                normal[a][c]          = value_of(v[c]);
                for (int i = 0; i < v[c].size(); ++i)
                  {
                    gradient[ac * n + i] = value_of(v[c].dx(i));
                    if constexpr (derivative_order<AD>() == 2)
                      for (int l = 0; l < v[c].dx(i).size(); ++l)
                        hessian[(ac * n + i) * n + l] = v[c].dx(i).dx(l);
                  }
              }
          }
      }

      // The sparse rows that map the 36 variables of a segment's moments
      // (x of the secondary face, its nodal normals, x of the primary face)
      // to the positions of a patch
      using VariableMap =
        std::array<std::vector<std::pair<unsigned, double>>, 36>;

      VariableMap
      variable_map(const std::array<unsigned int, 4> &secondary_index,
                   const std::array<unsigned int, 4> &primary_index,
                   const std::vector<double>         &normal_gradient,
                   const unsigned int                 n_ring_positions)
      {
        VariableMap map;
        for (unsigned int a = 0; a < 4; ++a)
          for (unsigned int d = 0; d < 3; ++d)
            {
              map[3 * a + d]      = {{secondary_index[a] + d, 1.}};
              map[24 + 3 * a + d] = {{primary_index[a] + d, 1.}};
              for (unsigned int i = 0; i < n_ring_positions; ++i)
                if (const double g =
                      normal_gradient[(3 * a + d) * n_ring_positions + i];
                    g != 0)
                  map[12 + 3 * a + d].emplace_back(i, g);
            }
        return map;
      }

      // The corners of face f of `surface` from the patch's positions (or
      // velocities) x, and where each corner's first entry is (`first`)
      std::array<Vec3<double>, 4>
      corners(const std::map<std::pair<const Surface *, unsigned int>,
                             unsigned int> &index,
              const Surface                &surface,
              const unsigned int            f,
              const std::vector<double>    &x,
              std::array<unsigned int, 4>  &first)
      {
        std::array<Vec3<double>, 4> result;
        for (unsigned int a = 0; a < 4; ++a)
          {
            first[a] = index.at({&surface, surface.faces[f][a]});
            for (unsigned int d = 0; d < 3; ++d)
              result[a][d] = x[first[a] + d];
          }
        return result;
      }

      // The moments of a face summed over its segments, G[q n_x + i] = their
      // derivatives in position i, V[m n_x + i] = the rate moments' in
      // velocity i
      struct MomentSums
      {
        std::array<double, n_rate_moments> total{};
        std::vector<double>                G, V;
      };

      // Adds the moments of the segment of the face (corners xs_d at `is`,
      // nodal normals `normal`) with a primary face (xm_d at `ip`) to `sums`
      // and, with friction, its mortar moments to `result`; false if they do
      // not overlap.
      bool
      add_segment(const std::array<Vec3<double>, 4> &xs_d,
                  const std::array<Vec3<double>, 4> &xm_d,
                  const std::array<unsigned int, 4> &is,
                  const std::array<unsigned int, 4> &ip,
                  const std::vector<double>         &velocity,
                  const bool                         rates,
                  const bool                         friction,
                  const TriangleRule                &rule,
                  FaceFirstOrder                    &result,
                  MomentSums                        &sums)
      {
        const unsigned int     n_x    = velocity.size();
        const auto            &normal = result.normal;
        constexpr unsigned int n_v    = 36;
        using Segment                 = Sacado::Fad::SFad<double, n_v>;
        {
          // (most candidates do not overlap: found without derivatives)
          std::vector<SegmentPoint<double>> points;
          if (!segment_points(xs_d, normal, xm_d, clip_tolerance, points, rule))
            return false;
        }
        std::array<Vec3<Segment>, 4> xs, ns, xm;
        for (unsigned int a = 0; a < 4; ++a)
          for (unsigned int d = 0; d < 3; ++d)
            {
              xs[a][d] = Segment(n_v, 3 * a + d, xs_d[a][d]);
              ns[a][d] = Segment(n_v, 12 + 3 * a + d, normal[a][d]);
              xm[a][d] = Segment(n_v, 24 + 3 * a + d, xm_d[a][d]);
            }
        SegmentVelocities v;
        if (rates)
          for (unsigned int a = 0; a < 4; ++a)
            for (unsigned int d = 0; d < 3; ++d)
              {
                v.vs[a][d] = velocity[is[a] + d];
                v.vm[a][d] = velocity[ip[a] + d];
              }
        std::array<Segment, 16> mortar;
        const auto              moments =
          segment_moments<Segment, n_rate_moments>(xs,
                                                   ns,
                                                   xm,
                                                   rule,
                                                   &v,
                                                   friction ? &mortar :
                                                              nullptr);
        const auto map =
          variable_map(is, ip, result.normal_gradient, result.n_ring_positions);
        if (friction)
          {
            FaceFirstOrder::Segment segment;
            segment.primary_index = ip;
            segment.d_P.assign(n_x, FaceFirstOrder::Matrix{});
            for (unsigned int lk = 0; lk < 16; ++lk)
              {
                segment.P[lk / 4][lk % 4] = mortar[lk].val();
                for (unsigned int w = 0; w < n_v; ++w)
                  if (const double d = mortar[lk].fastAccessDx(w); d != 0)
                    for (const auto &[i, y] : map[w])
                      segment.d_P[i][lk / 4][lk % 4] += d * y;
              }
            result.segments.push_back(std::move(segment));
          }
        for (unsigned int q = 0; q < n_rate_moments; ++q)
          {
            sums.total[q] += moments[q].val();
            for (unsigned int w = 0; w < n_v; ++w)
              if (const double dq = moments[q].fastAccessDx(w); dq != 0)
                for (const auto &[i, y] : map[w])
                  sums.G[q * n_x + i] += dq * y;
          }
        if (rates)
          for (unsigned int m = 0; m < 4; ++m)
            for (unsigned int a = 0; a < 8; ++a)
              for (unsigned int d = 0; d < 3; ++d)
                sums.V[m * n_x + (a < 4 ? is[a] : ip[a - 4]) + d] +=
                  v.coefficient[m][a][d];
        return true;
      }

      // The gaps, weights and rates of the face's nodes (and, with friction,
      // its dual basis) in the summed moments, chained to the positions.
      void
      gaps_from_moments(const MomentSums &sums,
                        const double      c_v,
                        const bool        rates,
                        const bool        friction,
                        FaceFirstOrder   &result)
      {
        const auto        &total = sums.total;
        const auto        &G     = sums.G;
        const auto        &V     = sums.V;
        const unsigned int n_x   = V.size() / 4;
        using Moments            = Sacado::Fad::SFad<double, n_rate_moments>;
        std::array<Moments, n_rate_moments> moments;
        for (unsigned int q = 0; q < n_rate_moments; ++q)
          moments[q] = Moments(n_rate_moments, q, total[q]);
        const auto A    = dual_of(moments);
        const auto gap  = dual_sums(A, moments, 0);
        const auto rate = dual_sums(A, moments, n_moments);
        for (auto *d : {&result.d_gap, &result.d_weight, &result.d_rate})
          d->assign(n_x, {{0., 0., 0., 0.}});
        if (friction)
          {
            result.d_A.assign(n_x, FaceFirstOrder::Matrix{});
            for (unsigned int j = 0; j < 4; ++j)
              for (unsigned int l = 0; l < 4; ++l)
                {
                  result.A[j][l] = A[j][l].val();
                  for (unsigned int q = 0; q < n_moments; ++q)
                    if (const double d = A[j][l].fastAccessDx(q); d != 0)
                      for (unsigned int i = 0; i < n_x; ++i)
                        result.d_A[i][j][l] += d * G[q * n_x + i];
                }
          }
        for (unsigned int j = 0; j < 4; ++j)
          {
            result.gap[j]      = gap[j].val();
            result.weight[j]   = total[4 + j];
            result.gap_rate[j] = rates ? -rate[j].val() : 0.;
            for (unsigned int i = 0; i < n_x; ++i)
              result.d_weight[i][j] = G[(4 + j) * n_x + i];
            for (unsigned int q = 0; q < n_rate_moments; ++q)
              {
                const double dg = gap[j].fastAccessDx(q);
                const double dr = rates ? -rate[j].fastAccessDx(q) : 0.;
                if (dg != 0 || dr != 0)
                  for (unsigned int i = 0; i < n_x; ++i)
                    {
                      result.d_gap[i][j] += dg * G[q * n_x + i];
                      result.d_rate[i][j] += dr * G[q * n_x + i];
                    }
              }
            if (rates)
              for (unsigned int m = 0; m < 4; ++m)
                for (unsigned int i = 0; i < n_x; ++i)
                  result.d_rate[i][j] -= c_v * A[j][m].val() * V[m * n_x + i];
          }
      }

      // Step (2) of exact_directions(): each covering segment's moments in its
      // 36 variables, second order, with the maps of the variables to the
      // positions, and the moments summed over the segments
      void
      segment_second_orders(
        const Surface     &s,
        const Surface     &p,
        const unsigned int e,
        const std::map<std::pair<const Surface *, unsigned int>, unsigned int>
                                                &index,
        const std::vector<unsigned int>         &covering,
        const std::vector<double>               &position,
        const std::array<Vec3<double>, 4>       &normal,
        const std::vector<double>               &normal_gradient,
        const unsigned int                       n_ring,
        const TriangleRule                      &rule,
        std::vector<SecondOrder<n_moments, 36>> &segments,
        std::vector<VariableMap>                &maps,
        std::array<double, n_moments>           &total)
      {
        const auto            &face = s.faces[e];
        constexpr unsigned int n_v  = 36;
        using Segment2 = Sacado::Fad::SFad<Sacado::Fad::SFad<double, n_v>, n_v>;
        total.fill(0.);
        for (const unsigned int pf : covering)
          {
            std::array<Vec3<Segment2>, 4> xs, ns, xm;
            std::array<unsigned int, 4>   is, ip;
            for (unsigned int a = 0; a < 4; ++a)
              {
                is[a] = index.at({&s, face[a]});
                ip[a] = index.at({&p, p.faces[pf][a]});
                for (unsigned int d = 0; d < 3; ++d)
                  {
                    xs[a][d] = seeded<n_v>(position[is[a] + d], 3 * a + d);
                    ns[a][d] = seeded<n_v>(normal[a][d], 12 + 3 * a + d);
                    xm[a][d] = seeded<n_v>(position[ip[a] + d], 24 + 3 * a + d);
                  }
              }
            const auto map = variable_map(is, ip, normal_gradient, 3 * n_ring);
            segments.emplace_back();
            segments.back().set(
              segment_moments<Segment2, n_moments>(xs, ns, xm, rule));
            for (unsigned int q = 0; q < n_moments; ++q)
              total[q] += segments.back().value[q];
            maps.push_back(map);
          }
      }

      // G[q n_x + i] = d moment_q / dx_i of the summed moments, and into
      // `hessian` sum_q c_q d^2 moment_q / dx^2: chained through the maps,
      // plus the normals' own second derivatives
      void
      add_moment_hessians(
        const std::vector<SecondOrder<n_moments, 36>> &segments,
        const std::vector<VariableMap>                &maps,
        const std::array<double, n_moments>           &c,
        const std::vector<double>                     &normal_hessian,
        const unsigned int                             n_ring,
        const unsigned int                             n_x,
        std::vector<double>                           &G,
        std::vector<double>                           &hessian)
      {
        constexpr unsigned int n_v = 36;
        for (unsigned int k = 0; k < segments.size(); ++k)
          {
            const auto                              &seg = segments[k];
            const auto                              &map = maps[k];
            std::array<std::array<double, n_v>, n_v> h{};
            for (unsigned int q = 0; q < n_moments; ++q)
              for (unsigned int v = 0; v < n_v; ++v)
                {
                  for (const auto &[i, y] : map[v])
                    G[q * n_x + i] += seg.gradient[q][v] * y;
                  if (c[q] != 0)
                    for (unsigned int w = 0; w < n_v; ++w)
                      h[v][w] += c[q] * seg.hessian[q][v][w];
                }
            // sum_q c_q d^2 moment_q / dx^2: chained through the map, plus
            // the normals' own second derivatives
            for (unsigned int v = 0; v < n_v; ++v)
              for (unsigned int w = 0; w < n_v; ++w)
                if (h[v][w] != 0)
                  for (const auto &[i, yi] : map[v])
                    for (const auto &[l, yl] : map[w])
                      hessian[i * n_x + l] += h[v][w] * yi * yl;
            for (unsigned int v = 12; v < 24; ++v)
              {
                double weight = 0;
                for (unsigned int q = 0; q < n_moments; ++q)
                  weight += c[q] * seg.gradient[q][v];
                if (weight != 0)
                  for (unsigned int i = 0; i < 3 * n_ring; ++i)
                    for (unsigned int l = 0; l < 3 * n_ring; ++l)
                      hessian[i * n_x + l] +=
                        weight * normal_hessian[((v - 12) * 3 * n_ring + i) *
                                                  3 * n_ring +
                                                l];
              }
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

    // The derivatives are chained, as the second ones in exact_directions():
    // each segment's moments in its 36 variables, the nodal normals in the
    // ring positions, the gaps in the summed moments; Fads over all of a
    // patch's hundred unknowns cost 6 times as much.
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
                     const TriangleRule              &rule)
    {
      const unsigned int n_x    = position.size();
      unsigned int       n_ring = 0;
      const auto         index  = position_index(s, nodes, n_ring);

      std::array<Vec3<double>, 4> normal;
      std::vector<double>         normal_gradient, unused;
      ContactAD::dispatch(3 * n_ring, [&](const auto zero) {
        ring_normals<std::decay_t<decltype(zero)>>(s,
                                                   e,
                                                   nodes,
                                                   position,
                                                   normal,
                                                   normal_gradient,
                                                   unused);
      });
      std::array<unsigned int, 4> is, ip;
      const auto                  xs_d = corners(index, s, e, position, is);
      FaceFirstOrder              result;
      result.normal           = normal;
      result.normal_gradient  = normal_gradient;
      result.n_ring_positions = 3 * n_ring;
      result.secondary_index  = is;
      const Vec3<double> face_normal =
        corner_normal(xs_d, 0) + corner_normal(xs_d, 3);

      MomentSums sums;
      sums.G.assign(n_rate_moments * n_x, 0.);
      sums.V.assign(4 * n_x, 0.);
      for (const unsigned int pf : candidates)
        {
          const auto xm_d = corners(index, p, pf, position, ip);
          if ((corner_normal(xm_d, 0) + corner_normal(xm_d, 3)) * face_normal >=
              0)
            continue;
          if (!add_segment(xs_d,
                           xm_d,
                           is,
                           ip,
                           velocity,
                           rates,
                           friction,
                           rule,
                           result,
                           sums))
            continue;
          result.covering.push_back(pf);
        }
      double area = 0, covered = 0;
      for (const auto &q : face_points(xs_d))
        area += q.weight;
      for (unsigned int j = 0; j < 4; ++j)
        covered += sums.total[4 + j];
      if (result.covering.empty() || covered < minimum_fraction * area)
        {
          result.covering.clear();
          result.segments.clear();
          return result;
        }

      // the gaps and rates in the summed moments
      gaps_from_moments(sums, c_v, rates, friction, result);
      return result;
    }

    // Second derivatives cost the square of the number of variables, so they
    // are taken where they are few and chained: (1) the four nodal normals in
    // the positions of the secondary nodes around the face; (2) each
    // segment's moments in the 36 variables it reads (the face's nodes, its
    // nodal normals, the primary face's nodes); (3) the normalized gaps in
    // the 18 moments summed over the segments (the dual basis of the covered
    // part couples them). A Fad of Fads in all of a patch's positions (60 to
    // 80) cost 5.6 times as much.
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
      // the index of a node's first position in `position`
      unsigned int n_ring = 0;
      const auto   index  = position_index(s, nodes, n_ring);

      // (1) nodal normals in the ring positions (the first 3 n_ring)
      std::array<Vec3<double>, 4> normal;
      std::vector<double>         normal_gradient, normal_hessian;
      ring_normals<Sacado::Fad::DFad<Sacado::Fad::DFad<double>>>(
        s,
        e,
        nodes,
        position,
        normal,
        normal_gradient,
        normal_hessian);

      // (2) each segment's moments in its 36 variables; variable k is
      // x_face (k < 12), the normals (12 <= k < 24) or x_primary, and
      // maps to the positions by the sparse rows `map`
      std::vector<SecondOrder<n_moments, 36>> segments;
      std::vector<VariableMap>                maps;
      std::array<double, n_moments>           total;
      segment_second_orders(s,
                            p,
                            e,
                            index,
                            covering,
                            position,
                            normal,
                            normal_gradient,
                            n_ring,
                            rule,
                            segments,
                            maps,
                            total);

      // (3) the normalized gaps in the moments
      using Moments2 =
        Sacado::Fad::SFad<Sacado::Fad::SFad<double, n_moments>, n_moments>;
      std::array<Moments2, n_moments> moments;
      for (unsigned int q = 0; q < n_moments; ++q)
        moments[q] = seeded<n_moments>(total[q], q);
      SecondOrder<4, n_moments> ratio;
      ratio.set(normalized_gaps(moments));

      // G[q][i] = d moment_q / dx_i; c_q weights the moments' Hessians
      std::vector<double>           G(n_moments * n_x, 0.);
      std::array<double, n_moments> c;
      for (unsigned int q = 0; q < n_moments; ++q)
        {
          c[q] = 0;
          for (unsigned int j = 0; j < 4; ++j)
            c[q] += lambda[j] * total[4 + j] * ratio.gradient[j][q];
        }
      std::fill(hessian.begin(), hessian.end(), 0.);
      add_moment_hessians(segments,
                          maps,
                          c,
                          normal_hessian,
                          n_ring,
                          n_x,
                          G,
                          hessian);
      add_gap_hessian(ratio, total, lambda, G, n_x, direction, hessian);
    }
  } // namespace MortarFace3D
} // namespace ContactDynamics
