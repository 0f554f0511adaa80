// 3-D dual mortar patches: a secondary bilinear face, its mortar segments
// with the candidate primary faces (auxiliary plane, clipping and
// triangulation of clipping_geometry.h), and the weighted gaps of its four
// nodes with the dual basis of the covered part. The forces follow the 2-D
// rule (mortar_contact.cc): -sum_j lambda_j w_j d(g_j / w_j)/du.
#include <deal.II/base/exceptions.h>

#include <contact_dynamics/contact/clipping_geometry.h>
#include <contact_dynamics/contact/contact_ad.h>
#include <contact_dynamics/contact/mortar_contact.h>

#include <algorithm>
#include <map>
#include <set>

namespace ContactDynamics
{
  namespace
  {
    using namespace ClippingGeometry;
    using Surface = ContactSurface<3>;

    // clipping tolerance, relative to the secondary face's diameter
    constexpr double clip_tolerance = 1e-10;

    template <typename Number>
    using NodeMap = std::map<unsigned int, Vec3<Number>>;

    // positions (and velocities) of the nodes a face's integrals read: the
    // secondary nodes of the faces around the face's nodes (their nodal
    // normals), the primary nodes of the candidate faces
    template <typename Number>
    struct FacePatch
    {
      NodeMap<Number> xs, vs, xp, vp;
    };

    template <typename Number>
    std::array<Vec3<Number>, 4>
    face_nodes(const Surface         &surface,
               const unsigned int     face,
               const NodeMap<Number> &x)
    {
      std::array<Vec3<Number>, 4> result;
      for (unsigned int a = 0; a < 4; ++a)
        result[a] = x.at(surface.faces[face][a]);
      return result;
    }

    // the average of the unit corner normals of the faces at a node
    template <typename Number>
    Vec3<Number>
    nodal_normal(const Surface         &s,
                 const unsigned int     node,
                 const NodeMap<Number> &xs)
    {
      std::vector<Vec3<Number>> corners;
      for (const unsigned int f : s.node_faces[node])
        {
          const auto &nodes = s.faces[f];
          const auto  a =
            std::find(nodes.begin(), nodes.end(), node) - nodes.begin();
          corners.push_back(corner_normal(face_nodes(s, f, xs), a));
        }
      return averaged_normal(corners);
    }

    template <typename Number>
    Vec3<double>
    values(const Vec3<Number> &x)
    {
      Vec3<double> v;
      for (unsigned int d = 0; d < 3; ++d)
        v[d] = value_of(x[d]);
      return v;
    }

    template <typename Number>
    std::array<Vec3<double>, 4>
    values(const std::array<Vec3<Number>, 4> &x)
    {
      std::array<Vec3<double>, 4> v;
      for (unsigned int a = 0; a < 4; ++a)
        v[a] = values(x[a]);
      return v;
    }

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

    // the weighted gaps, weights and gap rates of a face's nodes
    template <typename Number>
    struct FaceSums
    {
      std::array<Number, 4>     gap, weight, gap_rate;
      std::vector<unsigned int> covering; // primary faces with a segment

      FaceSums()
      {
        for (auto *a : {&gap, &weight, &gap_rate})
          a->fill(Number(0.));
      }
    };

    // The mortar integrals of face e over its segments with the candidate
    // primary faces that face it; nothing if they cover less than
    // `minimum_fraction` of it (the dual basis of a sliver is
    // ill-conditioned, as in 2-D).
    template <typename Number, typename PairData>
    FaceSums<Number>
    face_sums(const PairData          &pair,
              const unsigned int       e,
              const FacePatch<Number> &m,
              const bool               rates,
              const double             minimum_fraction,
              const TriangleRule      &rule)
    {
      const auto                 &s    = pair.secondary;
      const auto                 &p    = pair.primary;
      const auto                 &face = s.faces[e];
      FaceSums<Number>            sums;
      const auto                  xs = face_nodes(s, e, m.xs);
      std::array<Vec3<Number>, 4> ns;
      for (unsigned int a = 0; a < 4; ++a)
        ns[a] = nodal_normal(s, face[a], m.xs);
      const Vec3<double> face_normal =
        values(corner_normal(xs, 0)) + values(corner_normal(xs, 3));

      std::vector<std::vector<SegmentPoint<Number>>> segments;
      double                                         covered = 0;
      for (const unsigned int pf : pair.candidates[e])
        {
          const auto xm = face_nodes(p, pf, m.xp);
          // (in double: the test needs no derivatives)
          if ((values(corner_normal(xm, 0)) + values(corner_normal(xm, 3))) *
                face_normal >=
              0)
            continue;
          std::vector<SegmentPoint<Number>> points;
          if (!segment_points(xs, ns, xm, clip_tolerance, points, rule))
            continue;
          for (const auto &q : points)
            covered += value_of(q.weight);
          segments.push_back(std::move(points));
          sums.covering.push_back(pf);
        }
      double area = 0;
      for (const auto &q : face_points(values(xs)))
        area += q.weight;
      if (segments.empty() || covered < minimum_fraction * area)
        {
          sums.covering.clear();
          return sums;
        }

      std::vector<SegmentPoint<Number>> all;
      for (const auto &points : segments)
        all.insert(all.end(), points.begin(), points.end());
      const auto dual = dual_coefficients(secondary_points(all));
      for (unsigned int k = 0; k < segments.size(); ++k)
        {
          const auto &pf_nodes = p.faces[sums.covering[k]];
          const auto  xm       = face_nodes(p, sums.covering[k], m.xp);
          for (const auto &q : segments[k])
            {
              const auto   Ns = shape(q.xi_s, q.eta_s);
              const auto   Nm = shape(q.xi_m, q.eta_m);
              Vec3<Number> n;
              const Number g   = point_gap(xs, ns, xm, q, n);
              Number       v_n = 0.;
              if (rates)
                {
                  Vec3<Number> v_rel;
                  for (unsigned int a = 0; a < 4; ++a)
                    v_rel +=
                      Ns[a] * m.vs.at(face[a]) - Nm[a] * m.vp.at(pf_nodes[a]);
                  v_n = v_rel * n;
                }
              for (unsigned int j = 0; j < 4; ++j)
                {
                  Number psi = 0.;
                  for (unsigned int k2 = 0; k2 < 4; ++k2)
                    psi += dual[j][k2] * Ns[k2];
                  sums.gap[j] += psi * g * q.weight;
                  sums.weight[j] += Ns[j] * q.weight;
                  if (rates)
                    sums.gap_rate[j] -= psi * v_n * q.weight;
                }
            }
        }
      return sums;
    }

    // The mortar moments of one segment: I_m = sum N_m g w (m over the
    // secondary face's nodes), D_j = sum N_j w and M_jk = sum N_j N_k w
    // (j <= k), from which the face's normalized gaps follow
    // (normalized_gaps()).
    constexpr unsigned int n_moments = 18;

    template <typename Number>
    std::array<Number, n_moments>
    segment_moments(const std::array<Vec3<Number>, 4> &xs,
                    const std::array<Vec3<Number>, 4> &ns,
                    const std::array<Vec3<Number>, 4> &xm,
                    const TriangleRule                &rule)
    {
      std::vector<SegmentPoint<Number>> points;
      AssertThrow(segment_points(xs, ns, xm, clip_tolerance, points, rule),
                  ExcInternalError());
      std::array<Number, n_moments> moments;
      moments.fill(Number(0.));
      for (const auto &q : points)
        {
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
        }
      return moments;
    }

    // g_j / w_j of the face's nodes from its moments (summed over the
    // segments): the dual basis A = D M^-1 of the covered part,
    // g_j = sum_m A_jm I_m, w_j = D_j
    template <typename Number>
    std::array<Number, 4>
    normalized_gaps(const std::array<Number, n_moments> &moments)
    {
      std::array<Number, 4>                D;
      std::array<std::array<Number, 4>, 4> M;
      for (unsigned int j = 0, jk = 8; j < 4; ++j)
        {
          D[j] = moments[4 + j];
          for (unsigned int k = j; k < 4; ++k, ++jk)
            M[j][k] = M[k][j] = moments[jk];
        }
      const auto            A = dual_from_moments(D, M);
      std::array<Number, 4> ratio;
      for (unsigned int j = 0; j < 4; ++j)
        {
          Number g = 0.;
          for (unsigned int m = 0; m < 4; ++m)
            g += A[j][m] * moments[m];
          ratio[j] = g / D[j];
        }
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
      std::map<std::pair<const Surface *, unsigned int>, unsigned int> index;
      unsigned int n_ring = 0;
      for (unsigned int k = 0; k < nodes.size(); ++k)
        {
          index[nodes[k]] = 3 * k;
          n_ring += nodes[k].first == &s;
        }

      // (1) nodal normals in the ring positions (the first 3 n_ring)
      using Inner = Sacado::Fad::DFad<double>;
      using AD2   = Sacado::Fad::DFad<Inner>;
      NodeMap<AD2> ring;
      for (unsigned int k = 0; k < n_ring; ++k)
        for (unsigned int d = 0; d < 3; ++d)
          ring[nodes[k].second][d] =
            AD2(3 * n_ring,
                3 * k + d,
                Inner(3 * n_ring, 3 * k + d, position[3 * k + d]));
      std::array<Vec3<double>, 4> normal;
      // d normal[a][c] / dx_i and d^2 normal[a][c] / dx_i dx_l, i, l < 3 n_ring
      std::vector<double> normal_gradient(12 * 3 * n_ring, 0.),
        normal_hessian(12 * 9 * n_ring * n_ring, 0.);
      for (unsigned int a = 0; a < 4; ++a)
        {
          const auto n = nodal_normal(s, face[a], ring);
          for (unsigned int c = 0; c < 3; ++c)
            {
              const unsigned int ac = 3 * a + c;
              normal[a][c]          = n[c].val().val();
              for (int i = 0; i < n[c].size(); ++i)
                {
                  normal_gradient[ac * 3 * n_ring + i] = n[c].dx(i).val();
                  for (int l = 0; l < n[c].dx(i).size(); ++l)
                    normal_hessian[(ac * 3 * n_ring + i) * 3 * n_ring + l] =
                      n[c].dx(i).dx(l);
                }
            }
        }

      // (2) each segment's moments in its 36 variables; variable k is
      // x_face (k < 12), the normals (12 <= k < 24) or x_primary, and
      // maps to the positions by the sparse rows `map`
      constexpr unsigned int n_v = 36;
      using Segment2 = Sacado::Fad::SFad<Sacado::Fad::SFad<double, n_v>, n_v>;
      std::vector<SecondOrder<n_moments, n_v>> segments;
      std::vector<std::array<std::vector<std::pair<unsigned, double>>, n_v>>
                                    maps;
      std::array<double, n_moments> total;
      total.fill(0.);
      for (const unsigned int pf : covering)
        {
          std::array<Vec3<Segment2>, 4>                             xs, ns, xm;
          std::array<std::vector<std::pair<unsigned, double>>, n_v> map;
          for (unsigned int a = 0; a < 4; ++a)
            for (unsigned int d = 0; d < 3; ++d)
              {
                const unsigned int is = index.at({&s, face[a]}) + d;
                const unsigned int ip = index.at({&p, p.faces[pf][a]}) + d;
                xs[a][d]              = seeded<n_v>(position[is], 3 * a + d);
                ns[a][d]            = seeded<n_v>(normal[a][d], 12 + 3 * a + d);
                xm[a][d]            = seeded<n_v>(position[ip], 24 + 3 * a + d);
                map[3 * a + d]      = {{is, 1.}};
                map[24 + 3 * a + d] = {{ip, 1.}};
                for (unsigned int i = 0; i < 3 * n_ring; ++i)
                  if (const double g =
                        normal_gradient[(3 * a + d) * 3 * n_ring + i];
                      g != 0)
                    map[12 + 3 * a + d].emplace_back(i, g);
              }
          segments.emplace_back();
          segments.back().set(segment_moments(xs, ns, xm, rule));
          for (unsigned int q = 0; q < n_moments; ++q)
            total[q] += segments.back().value[q];
          maps.push_back(std::move(map));
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
    // the normal multipliers (frictionless)
    for (const unsigned int n : pair.secondary.faces[e])
      unknowns.push_back(pair.secondary.dofs[n][3]);
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

    // the first derivatives: the gaps, weights and rates of the face's
    // nodes, and direction[i][j] = w_j d(g_j / w_j)/du_i; derivatives on
    // the stack where they fit (a patch reads about a hundred unknowns,
    // and a heap allocation per temporary cost 4 times as much)
    std::vector<std::array<double, 4>> direction(n_positions,
                                                 {{0., 0., 0., 0.}});
    std::vector<unsigned int>          covering;
    const auto                         first_order = [&](const auto zero) {
      using AD = std::decay_t<decltype(zero)>;
      ContactAD::NodeVariables<3, AD> variables(unknowns, state);
      FacePatch<AD>                   m;
      for (const auto &[surface, n] : nodes)
        {
          auto &x = surface == &s ? m.xs : m.xp;
          auto &v = surface == &s ? m.vs : m.vp;
          variables.add(*surface, n, x[n], v[n]);
        }
      const auto sums =
        face_sums(pair, e, m, rates, minimum_covered_fraction, rule);
      for (unsigned int j = 0; j < 4; ++j)
        {
          ContactAD::add_to(pair.gap[face[j]], sums.gap[j], unknowns);
          ContactAD::add_to(pair.weight[face[j]], sums.weight[j], unknowns);
          ContactAD::add_to(pair.gap_rate[face[j]], sums.gap_rate[j], unknowns);
        }
      covering      = sums.covering;
      const auto dx = [](const AD &x, const unsigned int i) {
        return x.size() > int(i) ? x.dx(i) : 0.;
      };
      for (unsigned int j = 0; j < 4; ++j)
        if (!covering.empty() && sums.weight[j].val() > 0)
          {
            const double ratio = sums.gap[j].val() / sums.weight[j].val();
            for (unsigned int i = 0; i < n_positions; ++i)
              direction[i][j] =
                dx(sums.gap[j], i) - ratio * dx(sums.weight[j], i);
          }
    };
    constexpr unsigned int static_width = 128;
    if (unknowns.size() <= static_width)
      first_order(ContactAD::StaticAD<static_width>());
    else
      first_order(ContactAD::AD());
    if (covering.empty())
      return;

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
        std::vector<double> position(n_positions);
        for (unsigned int i = 0; i < n_positions; ++i)
          position[i] =
            nodes[i / 3].first->reference[nodes[i / 3].second][i % 3] +
            state.u(unknowns[i]);
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
  }
} // namespace ContactDynamics
