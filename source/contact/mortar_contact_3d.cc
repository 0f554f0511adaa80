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
              Vec3<Number> n  = interpolate(ns, q.xi_s, q.eta_s);
              n /= norm(n);
              const Number g = (interpolate(xm, q.xi_m, q.eta_m) -
                                interpolate(xs, q.xi_s, q.eta_s)) *
                               n;
              Number v_n = 0.;
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

    // The directions w_j d(g_j / w_j)/du_i of the normal force and their
    // derivatives weighted with the multipliers, hessian[i n + l] =
    // sum_j lambda_j d direction[i][j]/du_l, by a Fad of Fads in the
    // positions the gaps depend on (`seeded`), as in 2-D.
    template <typename PairData>
    void
    exact_directions(
      const PairData                                              &pair,
      const unsigned int                                           e,
      const std::vector<std::pair<const Surface *, unsigned int>> &nodes,
      const std::vector<unsigned int>                             &seeded,
      const std::vector<types::global_dof_index>                  &unknowns,
      const TrialState                                            &state,
      const double                        minimum_fraction,
      const TriangleRule                 &rule,
      const std::array<double, 4>        &lambda,
      std::vector<std::array<double, 4>> &direction,
      std::vector<double>                &hessian)
    {
      using Inner                    = Sacado::Fad::DFad<double>;
      using AD2                      = Sacado::Fad::DFad<Inner>;
      const unsigned int n_positions = 3 * nodes.size();
      const unsigned int n_seeded    = seeded.size();
      FacePatch<AD2>     m;
      for (unsigned int k = 0, v = 0; k < nodes.size(); ++k)
        {
          const Surface &surface = *nodes[k].first;
          auto          &x =
            (&surface == &pair.secondary ? m.xs : m.xp)[nodes[k].second];
          for (unsigned int d = 0; d < 3; ++d)
            {
              const unsigned int i = 3 * k + d;
              const double       value =
                surface.reference[nodes[k].second][d] + state.u(unknowns[i]);
              if (v < n_seeded && seeded[v] == i)
                {
                  x[d] = AD2(n_seeded, v, Inner(n_seeded, v, value));
                  ++v;
                }
              else
                x[d] = AD2(value);
            }
        }
      const auto f = face_sums(pair, e, m, false, minimum_fraction, rule);
      for (unsigned int v = 0; v < n_seeded; ++v)
        {
          std::array<Inner, 4> d;
          for (unsigned int j = 0; j < 4; ++j)
            {
              d[j] = Inner(0.);
              if (value_of(f.weight[j]) > 0)
                {
                  const AD2 ratio = f.gap[j] / f.weight[j];
                  if (v < unsigned(ratio.size()))
                    d[j] = f.weight[j].val() * ratio.dx(v);
                }
              direction[seeded[v]][j] = d[j].val();
            }
          for (unsigned int w = 0; w < n_seeded; ++w)
            {
              double h = 0;
              for (unsigned int j = 0; j < 4; ++j)
                if (d[j].size() > int(w))
                  h += lambda[j] * d[j].dx(w);
              hessian[seeded[v] * n_positions + seeded[w]] = h;
            }
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
    // (a patch reads about a hundred unknowns: dynamic derivatives)
    using AD             = ContactAD::AD;
    const auto &s        = pair.secondary;
    const auto &p        = pair.primary;
    const auto &face     = s.faces[e];
    const bool  exact    = this->complementarity.exact_jacobian;
    const auto  unknowns = patch_unknowns(pair, e, pair.candidates[e]);

    ContactAD::NodeVariables<3, AD> variables(unknowns, state);
    FacePatch<AD>                   m;
    std::vector<std::pair<const Surface *, unsigned int>> nodes;
    for (const unsigned int n : ring_nodes(pair, e))
      {
        variables.add(s, n, m.xs[n], m.vs[n]);
        nodes.emplace_back(&s, n);
      }
    for (const unsigned int n : primary_nodes(pair, pair.candidates[e]))
      {
        variables.add(p, n, m.xp[n], m.vp[n]);
        nodes.emplace_back(&p, n);
      }
    const unsigned int    n_positions = 3 * nodes.size();
    std::array<double, 4> lambda;
    for (unsigned int j = 0; j < 4; ++j)
      lambda[j] = variables.multiplier().val();

    const bool rates = this->complementarity.holds_contact() && state.dynamic;
    const TriangleRule &rule = triangle_rule(quadrature_points);
    const auto          sums =
      face_sums(pair, e, m, rates, minimum_covered_fraction, rule);
    for (unsigned int j = 0; j < 4; ++j)
      {
        ContactAD::add_to(pair.gap[face[j]], sums.gap[j], unknowns);
        ContactAD::add_to(pair.weight[face[j]], sums.weight[j], unknowns);
        ContactAD::add_to(pair.gap_rate[face[j]], sums.gap_rate[j], unknowns);
      }
    if (sums.covering.empty())
      return;

    // direction[i][j] = w_j d(g_j / w_j)/du_i
    std::vector<std::array<double, 4>> direction(n_positions,
                                                 {{0., 0., 0., 0.}});
    const auto dx = [](const AD &x, const unsigned int i) {
      return x.size() > int(i) ? x.dx(i) : 0.;
    };
    for (unsigned int j = 0; j < 4; ++j)
      if (sums.weight[j].val() > 0)
        {
          const double ratio = sums.gap[j].val() / sums.weight[j].val();
          for (unsigned int i = 0; i < n_positions; ++i)
            direction[i][j] =
              dx(sums.gap[j], i) - ratio * dx(sums.weight[j], i);
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
        // the positions of the secondary nodes and of the primary nodes of
        // the covering faces: the gaps do not depend on the others
        const auto                covering = primary_nodes(pair, sums.covering);
        std::vector<unsigned int> seeded;
        for (unsigned int k = 0; k < nodes.size(); ++k)
          if (nodes[k].first == &s || covering.count(nodes[k].second) > 0)
            for (unsigned int d = 0; d < 3; ++d)
              seeded.push_back(3 * k + d);
        exact_directions(pair,
                         e,
                         nodes,
                         seeded,
                         unknowns,
                         state,
                         minimum_covered_fraction,
                         rule,
                         lambda,
                         direction,
                         hessian);
      }
    for (unsigned int i = 0; i < n_positions; ++i)
      {
        typename PatchForces::Derivatives derivatives;
        double                            value = 0;
        for (unsigned int j = 0; j < 4; ++j)
          {
            value -= lambda[j] * direction[i][j];
            if (direction[i][j] != 0)
              derivatives.emplace_back(unknowns[n_positions + j],
                                       -direction[i][j]);
          }
        if (exact)
          for (unsigned int l = 0; l < n_positions; ++l)
            if (const double h = hessian[i * n_positions + l]; h != 0)
              derivatives.emplace_back(unknowns[l], -h);
        if (value != 0 || !derivatives.empty())
          forces.add(unknowns[i], value, std::move(derivatives));
      }
  }
} // namespace ContactDynamics
