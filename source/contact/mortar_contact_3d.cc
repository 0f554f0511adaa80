// 3-D dual mortar patches: a secondary bilinear face, its mortar segments
// with the candidate primary faces (auxiliary plane, clipping and
// triangulation of clipping_geometry.h), and the weighted gaps of its four
// nodes with the dual basis of the covered part. The forces follow the 2-D
// rule (mortar_contact.cc): -sum_j lambda_j w_j d(g_j / w_j)/du.
#include <deal.II/base/exceptions.h>

#include <contact_dynamics/contact/clipping_geometry.h>
#include <contact_dynamics/contact/contact_ad.h>
#include <contact_dynamics/contact/mortar_contact.h>
#include <contact_dynamics/contact/surface_geometry_3d.h>

#include <algorithm>
#include <map>
#include <set>

namespace ContactDynamics
{
  namespace
  {
    using namespace ClippingGeometry;

    // clipping tolerance, relative to the secondary face's diameter
    constexpr double clip_tolerance = 1e-10;

    // positions (and velocities) of the nodes a face's integrals read: the
    // secondary nodes of the faces around the face's nodes (their nodal
    // normals), the primary nodes of the candidate faces
    template <typename Number>
    struct FacePatch
    {
      NodeMap<Number> xs, vs, xp, vp;
    };

    // the nodes whose positions a face's integrals read
    template <typename PairData>
    std::set<unsigned int>
    ring_nodes(const PairData &pair, const unsigned int e)
    {
      std::set<unsigned int> nodes;
      for (const unsigned int node : pair.secondary.faces[e])
        for (const unsigned int f : pair.secondary.node_faces[node])
          nodes.insert(pair.secondary.faces[f].begin(),
                       pair.secondary.faces[f].end());
      return nodes;
    }

    template <typename PairData>
    std::set<unsigned int>
    primary_nodes(const PairData &pair, const std::vector<unsigned int> &faces)
    {
      std::set<unsigned int> nodes;
      for (const unsigned int f : faces)
        nodes.insert(pair.primary.faces[f].begin(),
                     pair.primary.faces[f].end());
      return nodes;
    }

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
                        rates->coefficient[m][a][d] += c * value_of(Ns[a]) * nd;
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
      // ring_normals()) and where the face's nodes are in the positions
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

    // The mortar integrals of face e over its segments with the candidate
    // primary faces that face it; nothing if they cover less than
    // `minimum_fraction` of it (the dual basis of a sliver is
    // ill-conditioned, as in 2-D). The derivatives are chained, as the
    // second ones in exact_directions(): each segment's moments in its 36
    // variables, the nodal normals in the ring positions, the gaps in the
    // summed moments; Fads over all of a patch's hundred unknowns cost 6
    // times as much.
    template <typename PairData>
    FaceFirstOrder
    first_order_sums(
      const PairData                                              &pair,
      const unsigned int                                           e,
      const std::vector<std::pair<const Surface *, unsigned int>> &nodes,
      const std::vector<double>                                   &position,
      const std::vector<double>                                   &velocity,
      const double                                                 c_v,
      const bool                                                   rates,
      const bool                                                   friction,
      const double        minimum_fraction,
      const TriangleRule &rule)
    {
      const auto        &s       = pair.secondary;
      const auto        &p       = pair.primary;
      const unsigned int n_x     = position.size();
      unsigned int       n_ring  = 0;
      const auto         index   = position_index(s, nodes, n_ring);
      const auto         corners = [&](const Surface               &surface,
                               const unsigned int           f,
                               const auto                  &x,
                               std::array<unsigned int, 4> &first) {
        std::array<Vec3<double>, 4> result;
        for (unsigned int a = 0; a < 4; ++a)
          {
            first[a] = index.at({&surface, surface.faces[f][a]});
            for (unsigned int d = 0; d < 3; ++d)
              result[a][d] = x[first[a] + d];
          }
        return result;
      };

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
      const auto                  xs_d = corners(s, e, position, is);
      FaceFirstOrder              result;
      result.normal           = normal;
      result.normal_gradient  = normal_gradient;
      result.n_ring_positions = 3 * n_ring;
      result.secondary_index  = is;
      const Vec3<double> face_normal =
        corner_normal(xs_d, 0) + corner_normal(xs_d, 3);

      // the moments summed over the segments, G[q n_x + i] = their
      // derivatives in position i, V[m n_x + i] = the rate moments' in
      // velocity i
      std::array<double, n_rate_moments> total{};
      std::vector<double>    G(n_rate_moments * n_x, 0.), V(4 * n_x, 0.);
      constexpr unsigned int n_v = 36;
      using Segment              = Sacado::Fad::SFad<double, n_v>;
      for (const unsigned int pf : pair.candidates[e])
        {
          const auto xm_d = corners(p, pf, position, ip);
          if ((corner_normal(xm_d, 0) + corner_normal(xm_d, 3)) * face_normal >=
              0)
            continue;
          {
            // (most candidates do not overlap: found without derivatives)
            std::vector<SegmentPoint<double>> points;
            if (!segment_points(xs_d,
                                normal,
                                xm_d,
                                clip_tolerance,
                                points,
                                rule))
              continue;
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
          const auto map = variable_map(is, ip, normal_gradient, 3 * n_ring);
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
              total[q] += moments[q].val();
              for (unsigned int w = 0; w < n_v; ++w)
                if (const double dq = moments[q].fastAccessDx(w); dq != 0)
                  for (const auto &[i, y] : map[w])
                    G[q * n_x + i] += dq * y;
            }
          if (rates)
            for (unsigned int m = 0; m < 4; ++m)
              for (unsigned int a = 0; a < 8; ++a)
                for (unsigned int d = 0; d < 3; ++d)
                  V[m * n_x + (a < 4 ? is[a] : ip[a - 4]) + d] +=
                    v.coefficient[m][a][d];
          result.covering.push_back(pf);
        }
      double area = 0, covered = 0;
      for (const auto &q : face_points(xs_d))
        area += q.weight;
      for (unsigned int j = 0; j < 4; ++j)
        covered += total[4 + j];
      if (result.covering.empty() || covered < minimum_fraction * area)
        {
          result.covering.clear();
          result.segments.clear();
          return result;
        }

      // the gaps and rates in the summed moments
      using Moments = Sacado::Fad::SFad<double, n_rate_moments>;
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
      return result;
    }

    // Coulomb friction on a face, with first derivatives: the forces of the
    // tangential traction z_t = sum_j psi_j lambda_t,j on both sides
    // (lambda_t,j = sum_a lambda_a,j t_a,j along node j's tangents),
    // D_i lambda_t,i on the secondary nodes and -sum_j M_jk lambda_t,j on
    // the primary ones, and the slip rates t_a,j . (D_j v_j - sum_k M_jk
    // v_k) of the face's nodes (= int psi_j v_rel . t_a,j, by the
    // biorthogonality of the dual basis on the covered part).
    struct FrictionTerms
    {
      // per position i; d_force[i][l], l over the positions, then the 4
      // normal and the 8 tangential multipliers (4 + 2 j + a)
      std::vector<double>                               force;
      std::vector<std::vector<double>>                  d_force;
      std::array<std::array<double, 2>, 4>              slip{};
      std::array<std::array<std::vector<double>, 2>, 4> d_slip;
    };

    FrictionTerms
    friction_terms(const Surface                              &s,
                   const unsigned int                          e,
                   const FaceFirstOrder                       &sums,
                   const std::vector<double>                  &velocity,
                   const double                                c_v,
                   const std::array<std::array<double, 2>, 4> &lambda)
    {
      const unsigned int n  = velocity.size();
      const unsigned int nr = sums.n_ring_positions;
      const auto        &is = sums.secondary_index;
      // tangents t[j][a] and their derivatives dt[j][a][c][i], i < nr
      std::array<std::array<Vec3<double>, 2>, 4>                       t;
      std::array<std::array<std::array<std::vector<double>, 3>, 2>, 4> dt;
      // lambda_t,j and its derivatives in the ring positions
      std::array<Vec3<double>, 4>                       lt;
      std::array<std::array<std::vector<double>, 3>, 4> dlt;
      using N3 = Sacado::Fad::SFad<double, 3>;
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

      FrictionTerms result;
      result.force.assign(n, 0.);
      result.d_force.assign(n, std::vector<double>(n + 12, 0.));
      for (unsigned int j = 0; j < 4; ++j)
        for (unsigned int a = 0; a < 2; ++a)
          result.d_slip[j][a].assign(n, 0.);
      const auto multiplier = [&](const unsigned int j, const unsigned int a) {
        return n + 4 + 2 * j + a;
      };
      // adds node k's force -factor lambda_t,j (factor: -D_j or M_jk, with
      // derivatives d_factor) and its part of node j's slip rates
      const auto add = [&](const unsigned int         j,
                           const unsigned int         first, // of x_k
                           const double               factor,
                           const std::vector<double> &d_factor) {
        for (unsigned int c = 0; c < 3; ++c)
          {
            auto &row = result.d_force[first + c];
            result.force[first + c] -= factor * lt[j][c];
            for (unsigned int i = 0; i < n; ++i)
              row[i] -= d_factor[i] * lt[j][c];
            for (unsigned int i = 0; i < nr; ++i)
              row[i] -= factor * dlt[j][c][i];
            for (unsigned int a = 0; a < 2; ++a)
              row[multiplier(j, a)] -= factor * t[j][a][c];
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

    // The directions w_j d(g_j / w_j)/du_i of the normal force and their
    // derivatives weighted with the multipliers, hessian[i n + l] =
    // sum_j lambda_j d direction[i][j]/du_l. Second derivatives cost the
    // square of the number of variables, so they are taken where they are
    // few and chained: (1) the four nodal normals in the positions of the
    // secondary nodes around the face; (2) each segment's moments in the 36
    // variables it reads (the face's nodes, its nodal normals, the primary
    // face's nodes); (3) the normalized gaps in the 18 moments summed over
    // the segments (the dual basis of the covered part couples them). A Fad
    // of Fads in all of a patch's positions (60 to 80) cost 5.6 times as
    // much.
    template <typename PairData>
    void
    exact_directions(
      const PairData                                              &pair,
      const unsigned int                                           e,
      const std::vector<std::pair<const Surface *, unsigned int>> &nodes,
      const std::vector<unsigned int>                             &covering,
      const std::vector<double>                                   &position,
      const TriangleRule                                          &rule,
      const std::array<double, 4>                                 &lambda,
      std::vector<std::array<double, 4>>                          &direction,
      std::vector<double>                                         &hessian)
    {
      const auto        &s    = pair.secondary;
      const auto        &p    = pair.primary;
      const auto        &face = s.faces[e];
      const unsigned int n_x  = position.size();
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
      constexpr unsigned int n_v = 36;
      using Segment2 = Sacado::Fad::SFad<Sacado::Fad::SFad<double, n_v>, n_v>;
      std::vector<SecondOrder<n_moments, n_v>> segments;
      std::vector<VariableMap>                 maps;
      std::array<double, n_moments>            total;
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
                      weight *
                      normal_hessian[((v - 12) * 3 * n_ring + i) * 3 * n_ring +
                                     l];
            }
        }
      // the moments' first derivatives through the gaps' second ones, and
      // the derivative of the weights w_j = D_j in the directions
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

  template <>
  std::vector<types::global_dof_index>
  MortarContact<3>::patch_unknowns(
    const PairData                  &pair,
    const unsigned int               e,
    const std::vector<unsigned int> &primary_faces) const
  {
    std::vector<types::global_dof_index> unknowns;
    for (const unsigned int n : ring_nodes(pair, e))
      for (unsigned int d = 0; d < 3; ++d)
        unknowns.push_back(pair.secondary.dofs[n][d]);
    for (const unsigned int n : primary_nodes(pair, primary_faces))
      for (unsigned int d = 0; d < 3; ++d)
        unknowns.push_back(pair.primary.dofs[n][d]);
    // the normal multipliers, then the tangential ones (with friction)
    for (const unsigned int n : pair.secondary.faces[e])
      unknowns.push_back(pair.secondary.dofs[n][3]);
    if (pair.friction_coefficient > 0)
      for (const unsigned int n : pair.secondary.faces[e])
        for (const unsigned int c : {4, 5})
          unknowns.push_back(pair.secondary.dofs[n][c]);
    return unknowns;
  }

  template <>
  void
  MortarContact<3>::assemble_patch(PairData          &pair,
                                   const unsigned int e,
                                   const TrialState  &state,
                                   PatchForces       &forces)
  {
    const auto &s        = pair.secondary;
    const auto &p        = pair.primary;
    const auto &face     = s.faces[e];
    const bool  exact    = this->complementarity.exact_jacobian;
    const auto  unknowns = patch_unknowns(pair, e, pair.candidates[e]);
    const bool  rates = this->complementarity.holds_contact() && state.dynamic;
    const bool  friction     = pair.friction_coefficient > 0;
    const TriangleRule &rule = triangle_rule(quadrature_points);

    std::vector<std::pair<const Surface *, unsigned int>> nodes;
    for (const unsigned int n : ring_nodes(pair, e))
      nodes.emplace_back(&s, n);
    for (const unsigned int n : primary_nodes(pair, pair.candidates[e]))
      nodes.emplace_back(&p, n);
    const unsigned int    n_positions = 3 * nodes.size();
    std::array<double, 4> lambda;
    for (unsigned int j = 0; j < 4; ++j)
      lambda[j] = state.u(unknowns[n_positions + j]);

    std::vector<double> position(n_positions), velocity(n_positions);
    for (unsigned int i = 0; i < n_positions; ++i)
      {
        position[i] =
          nodes[i / 3].first->reference[nodes[i / 3].second][i % 3] +
          state.u(unknowns[i]);
        velocity[i] = state.v(unknowns[i]);
      }
    // the gaps, weights and rates of the face's nodes with their first
    // derivatives, and direction[i][j] = w_j d(g_j / w_j)/du_i
    const auto  sums     = first_order_sums(pair,
                                       e,
                                       nodes,
                                       position,
                                       velocity,
                                       state.c_v,
                                       rates,
                                       friction,
                                       minimum_covered_fraction,
                                       rule);
    const auto &covering = sums.covering;
    if (covering.empty())
      return;
    const auto add = [&](LinearizedValue                          &target,
                         const double                              value,
                         const std::vector<std::array<double, 4>> &d,
                         const unsigned int                        j) {
      target.value += value;
      for (unsigned int i = 0; i < n_positions; ++i)
        if (d[i][j] != 0)
          target.derivatives[unknowns[i]] += d[i][j];
    };
    std::vector<std::array<double, 4>> direction(n_positions,
                                                 {{0., 0., 0., 0.}});
    for (unsigned int j = 0; j < 4; ++j)
      {
        add(pair.gap[face[j]], sums.gap[j], sums.d_gap, j);
        add(pair.weight[face[j]], sums.weight[j], sums.d_weight, j);
        add(pair.gap_rate[face[j]], sums.gap_rate[j], sums.d_rate, j);
        if (sums.weight[j] > 0)
          {
            const double ratio = sums.gap[j] / sums.weight[j];
            for (unsigned int i = 0; i < n_positions; ++i)
              direction[i][j] = sums.d_gap[i][j] - ratio * sums.d_weight[i][j];
          }
      }

    // 'approximate': the geometric stiffness (the derivatives of the
    // directions) is dropped
    std::vector<double> hessian(exact ? n_positions * n_positions : 0);
    // (weighted with the multipliers: nothing to compute without them, as
    // on faces out of contact; the second derivatives cost about as much
    // as a first-order pass per seeded position)
    if (exact && std::any_of(lambda.begin(), lambda.end(), [](double l) {
          return l != 0;
        }))
      {
        exact_directions(pair,
                         e,
                         nodes,
                         covering,
                         position,
                         rule,
                         lambda,
                         direction,
                         hessian);
      }
    forces.add_normal_rows(unknowns,
                           lambda,
                           direction,
                           hessian,
                           [](unsigned int, auto &) {});
    if (!friction)
      return;

    std::array<std::array<double, 2>, 4> lambda_t;
    for (unsigned int j = 0; j < 4; ++j)
      for (unsigned int a = 0; a < 2; ++a)
        lambda_t[j][a] = state.u(unknowns[n_positions + 4 + 2 * j + a]);
    const FrictionTerms f =
      friction_terms(s, e, sums, velocity, state.c_v, lambda_t);
    for (unsigned int i = 0; i < n_positions; ++i)
      {
        typename PatchForces::Derivatives derivatives;
        for (unsigned int l = 0; l < f.d_force[i].size(); ++l)
          if (f.d_force[i][l] != 0)
            derivatives.emplace_back(unknowns[l], f.d_force[i][l]);
        if (f.force[i] != 0 || !derivatives.empty())
          {
            forces.add(unknowns[i], f.force[i], std::move(derivatives));
            forces.add_tangential(unknowns[i], f.force[i]);
          }
      }
    for (unsigned int j = 0; j < 4; ++j)
      for (unsigned int a = 0; a < 2; ++a)
        {
          LinearizedValue &slip = pair.slip_rate[face[j]][a];
          slip.value += f.slip[j][a];
          for (unsigned int i = 0; i < n_positions; ++i)
            if (f.d_slip[j][a][i] != 0)
              slip.derivatives[unknowns[i]] += f.d_slip[j][a][i];
        }
  }
} // namespace ContactDynamics
