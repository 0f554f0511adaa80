// 3-D dual mortar patches: the integrals of one secondary face, with its
// mortar segments with the candidate primary faces (auxiliary plane,
// clipping and triangulation of clipping_geometry.h), and the weighted gaps
// of its four nodes with the dual basis of the covered part, with first
// derivatives (mortar_face_3d.h; the second ones are in
// mortar_face_3d_hessian.cc).
#include <deal.II/base/exceptions.h>

#include <contact_dynamics/contact/contact_ad.h>
#include <contact_dynamics/contact/mortar_face_3d.h>
#include <contact_dynamics/contact/mortar_face_3d_moments.h>

#include <algorithm>

namespace ContactDynamics
{
  namespace MortarFace3D
  {
    namespace internal
    {
      FaceRing
      face_ring(const Surface             &s,
                const unsigned int         e,
                const PatchNodes          &nodes,
                const std::vector<double> &position)
      {
        FaceRing ring;
        for (unsigned int k = 0; k < nodes.size(); ++k)
          {
            ring.index[nodes[k]] = 3 * k;
            ring.n_ring += nodes[k].first == &s;
          }
        // the ring comes first
        const unsigned int n = 3 * ring.n_ring;
        ContactAD::dispatch(n, [&](const auto zero) {
          using AD = std::decay_t<decltype(zero)>;
          NodeMap<AD> positions;
          for (unsigned int i = 0; i < n; ++i)
            positions[nodes[i / 3].second][i % 3] = AD(n, i, position[i]);
          ring.normal_gradient.assign(12 * n, 0.);
          for (unsigned int a = 0; a < 4; ++a)
            {
              const auto v = nodal_normal(s, s.faces[e][a], positions);
              for (unsigned int c = 0; c < 3; ++c)
                {
                  ring.normal[a][c] = value_of(v[c]);
                  for (int i = 0; i < v[c].size(); ++i)
                    ring.normal_gradient[(3 * a + c) * n + i] =
                      value_of(v[c].dx(i));
                }
            }
        });
        return ring;
      }

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

      std::array<Vec3<double>, 4>
      corners(const PositionIndex         &index,
              const Surface               &surface,
              const unsigned int           f,
              const std::vector<double>   &x,
              std::array<unsigned int, 4> &first)
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
    } // namespace internal

    namespace
    {
      using namespace internal;

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
      const unsigned int n_x = position.size();
      const auto &[index, n_ring, normal, normal_gradient] =
        face_ring(s, e, nodes, position);
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
  } // namespace MortarFace3D
} // namespace ContactDynamics
