// 2-D dual mortar contact between two meshed surfaces whose faces are
// 3-node curves (elements of degree 2). Everything is integrated on the
// curved faces: the segment ends are the primary vertices projected along
// the secondary's interpolated normal field (Newton), every quadrature
// point is projected onto the curved primary face (Newton), and the dual
// basis is that of the covered part with the length element of the curve.
// Derivatives are exact (one Newton step in AD numbers from the converged
// value is the implicit function theorem).
//
// The dual basis of the covered part, psi_j = D_j (M^-1 N)_j, has
// D_j = int N_j, which for a vertex function of degree 2 is negative on a
// face covered from its other end beyond its middle. The normalized gap
// g_j / w_j = int (M^-1 N)_j g is computed without that division, so it
// stays bounded for any sign of D_j; a node whose summed weight is not
// positive is not a contact node (surface_contact_complementarity.cc).
#include <deal.II/base/quadrature_lib.h>

#include <contact_dynamics/contact/contact_ad.h>
#include <contact_dynamics/contact/dual_basis_3d.h>
#include <contact_dynamics/contact/kept_multiplier_nodes.h>
#include <contact_dynamics/contact/mortar_contact.h>
#include <contact_dynamics/contact/mortar_geometry.h>
#include <contact_dynamics/contact/quadratic_curve.h>

#include <set>

namespace ContactDynamics
{
  namespace
  {
    using MortarGeometry::value_of;
    using SegmentGeometry::cross;
    using SegmentGeometry::Vec;
    using namespace QuadraticCurve;

    // a mortar patch of degree 2: node positions and velocities of both
    // sides, the face's nodes, nodal normals and tangents, multipliers
    template <typename Number>
    struct QuadraticPatch
    {
      std::map<unsigned int, Vec<Number>> xs, vs, xp, vp;
      Curve<Number>                       x, normal, tangent;
      std::array<Number, 3>               lambda, lambda_t;
    };

    // the face's nodes and nodal normals: the average of the unit normals
    // of the curved faces at the node (frozen for approximate Jacobians)
    template <typename Number, typename Surface>
    void
    set_face_geometry(const Surface          &s,
                      const unsigned int      e,
                      const bool              exact,
                      QuadraticPatch<Number> &m)
    {
      m.x = face_positions(m.xs, s.face_nodes[e]);
      for (unsigned int a = 0; a < 3; ++a)
        {
          const unsigned int node = s.face_nodes[e][a];
          Vec<Number>        sum;
          for (const unsigned int f : s.node_faces[node])
            {
              const auto &nodes = s.face_nodes[f];
              const auto  k =
                std::find(nodes.begin(), nodes.end(), node) - nodes.begin();
              sum += curve_normal(face_positions(m.xs, nodes), node_xi[k]);
            }
          sum /= SegmentGeometry::norm(sum);
          m.normal[a] = sum;
          if (!exact)
            for (unsigned int d = 0; d < 2; ++d)
              m.normal[a][d] = Number(value_of(sum[d]));
          m.tangent[a] = SegmentGeometry::rotate(m.normal[a]);
        }
    }

    // what a face integrates: the normalized weighted gaps int (M^-1 N)_j g,
    // the weights D_j = int N_j, rates, and force rows (friction; the
    // nodal-normal traction for approximate Jacobians)
    template <typename Number>
    struct QuadraticSums
    {
      std::array<Number, 3> ratio, weight, gap_rate, slip_rate;
      std::map<types::global_dof_index, Number> rows, normal_rows;
      std::map<types::global_dof_index, double> tangential_rows;
      std::vector<unsigned int>                 faces; // covering primary
    };

    // one quadrature point of a segment
    template <typename Number>
    struct SegmentPoint
    {
      unsigned int          face;
      std::array<Number, 3> N, Np;
      Number                JxW, gap;
      Vec<Number>           normal;
    };

    // the end of a segment: a projected primary vertex moves with it
    // unless it lies on the face's end (as for degree 1, mortar_contact.cc)
    template <typename Number>
    Number
    segment_end(const QuadraticPatch<Number> &m,
                const double                  bound,
                const double                  xi,
                const Vec<Number>            &y,
                const bool                    exact)
    {
      if (bound != xi || !exact || std::abs(std::abs(xi) - 1) < 1e-12)
        return Number(bound);
      return project_onto_curve(m.x, m.normal, y, xi);
    }

    template <typename Number, typename PairData>
    std::vector<SegmentPoint<Number>>
    segment_points(const PairData               &pair,
                   const unsigned int            e,
                   const QuadraticPatch<Number> &m,
                   const QGauss<1>              &gauss,
                   const bool                    exact,
                   const double                  minimum_covered_fraction,
                   std::vector<unsigned int>    &faces)
    {
      const auto         &p  = pair.primary;
      const Curve<double> xd = values(m.x), nd = values(m.normal);
      const Vec<double>   face_n = SegmentGeometry::face_normal(xd[0], xd[1]);
      std::vector<SegmentPoint<Number>> points;
      double                            covered = 0;
      for (const unsigned int pf : pair.candidates[e])
        {
          const Curve<Number> y  = face_positions(m.xp, p.face_nodes[pf]);
          const Curve<double> yd = values(y);
          if (SegmentGeometry::face_normal(yd[0], yd[1]) * face_n >= 0)
            continue;
          double xi[2];
          bool   found = true;
          // (the chord's solution where Newton on the curve fails far
          // beyond the face's ends, where only its side matters)
          for (unsigned int a = 0; a < 2 && found; ++a)
            {
              found = MortarGeometry::project_along_normal_field(xd[0],
                                                                 xd[1],
                                                                 nd[0],
                                                                 nd[1],
                                                                 yd[a],
                                                                 xi[a]);
              const double chord = xi[a];
              if (found && !project_onto_curve(xd, nd, yd[a], xi[a]))
                {
                  xi[a] = chord;
                  found = std::abs(chord) > 1.5;
                }
            }
          if (!found)
            continue;
          const unsigned int first = xi[0] < xi[1] ? 0 : 1;
          const double       lo_v  = std::max(-1., xi[first]);
          const double       hi_v  = std::min(1., xi[1 - first]);
          if (hi_v - lo_v < 1e-12)
            continue;
          const Number lo = segment_end(m, lo_v, xi[first], y[first], exact);
          const Number hi =
            segment_end(m, hi_v, xi[1 - first], y[1 - first], exact);
          covered += (hi_v - lo_v) / 2;
          faces.push_back(pf);
          for (unsigned int q = 0; q < gauss.size(); ++q)
            {
              SegmentPoint<Number> point;
              point.face          = pf;
              const Number xi_q   = lo + (hi - lo) * gauss.point(q)[0];
              point.N             = QuadraticFace::line_shape(xi_q);
              const Vec<Number> x = combine(m.x, point.N);
              const Vec<Number> dx =
                combine(m.x, QuadraticFace::line_shape_derivative(xi_q));
              point.JxW =
                gauss.weight(q) * (hi - lo) * SegmentGeometry::norm(dx);
              point.normal = combine(m.normal, point.N);
              point.normal /= SegmentGeometry::norm(point.normal);
              const Number eta = intersect_curve(x, point.normal, y, exact);
              point.Np         = QuadraticFace::line_shape(eta);
              point.gap        = (combine(y, point.Np) - x) * point.normal;
              points.push_back(point);
            }
        }
      // a sliver leaves the mass matrix nearly singular: it contributes
      // nothing
      if (covered < minimum_covered_fraction)
        {
          points.clear();
          faces.clear();
        }
      return points;
    }

    /**
     * The multiplier functions N'_j = sum_k T_jk N_k of a face of degree 2
     * on its covered part. A vertex function is negative on the far half of
     * its face, so the covered integral D_j = int N_j of a node whose
     * support is covered from the other end beyond the middle is small or
     * negative, and its dual function and multiplier blow up (the sum of
     * the others is then no longer 1). A node whose covered D_j is below
     * 10 % of its whole-face one leaves the face's multiplier
     * space: its function is spread onto the nodes kept as they interpolate
     * a linear function (one node kept: a constant), so that the N'
     * still sum to 1 and reproduce linear fields, and so do their dual
     * functions (the patch test up to the edge of the covered part).
     */
    template <typename Number>
    std::array<std::array<double, 3>, 3>
    multiplier_map(const Curve<Number>                     &x,
                   const std::vector<SegmentPoint<Number>> &points,
                   const QGauss<1>                         &gauss)
    {
      const Curve<double>   xd = values(x);
      std::array<double, 3> covered{}, whole{};
      for (const auto &q : points)
        for (unsigned int j = 0; j < 3; ++j)
          covered[j] += value_of(q.N[j]) * value_of(q.JxW);
      for (unsigned int q = 0; q < gauss.size(); ++q)
        {
          const double xi = 2. * gauss.point(q)[0] - 1.;
          const double J  = SegmentGeometry::norm(
            combine(xd, QuadraticFace::line_shape_derivative(xi)));
          const auto N = QuadraticFace::line_shape(xi);
          for (unsigned int j = 0; j < 3; ++j)
            whole[j] += N[j] * 2. * gauss.weight(q) * J;
        }
      const auto kept = kept_multiplier_nodes(covered, whole);
      std::array<std::array<double, 3>, 3> T{};
      for (const unsigned int j : kept)
        T[j][j] = 1.;
      for (unsigned int d = 0; d < 3; ++d)
        if (T[d][d] == 0)
          {
            if (kept.size() == 1)
              T[kept[0]][d] = 1.;
            else
              for (unsigned int a = 0; a < 2; ++a) // (two kept: linear)
                {
                  const unsigned int i = kept[a], o = kept[1 - a];
                  T[i][d] =
                    (node_xi[d] - node_xi[o]) / (node_xi[i] - node_xi[o]);
                }
          }
      return T;
    }

    /** T N at one point. */
    template <typename Number>
    std::array<Number, 3>
    apply(const std::array<std::array<double, 3>, 3> &T,
          const std::array<Number, 3>                &N)
    {
      std::array<Number, 3> TN;
      for (unsigned int j = 0; j < 3; ++j)
        TN[j] = T[j][0] * N[0] + T[j][1] * N[1] + T[j][2] * N[2];
      return TN;
    }

    template <typename Number, typename PairData>
    QuadraticSums<Number>
    integrate_face(const PairData               &pair,
                   const unsigned int            e,
                   const QuadraticPatch<Number> &m,
                   const QGauss<1>              &gauss,
                   const bool                    rates,
                   const bool                    exact,
                   const bool                    forces,
                   const double                  minimum_covered_fraction)
    {
      const auto           &s        = pair.secondary;
      const auto           &p        = pair.primary;
      const bool            friction = forces && pair.friction_coefficient > 0;
      QuadraticSums<Number> sums;
      for (unsigned int j = 0; j < 3; ++j)
        sums.ratio[j] = sums.weight[j] = sums.gap_rate[j] = sums.slip_rate[j] =
          Number(0.);
      const auto points = segment_points(pair,
                                         e,
                                         m,
                                         gauss,
                                         exact,
                                         minimum_covered_fraction,
                                         sums.faces);
      if (points.empty())
        return sums;
      // the dual basis of the covered part, psi_j = D_j (M^-1 N')_j, for
      // the multiplier functions N' = T N of the nodes kept (multiplier_map)
      const auto T = multiplier_map(m.x, points, gauss);
      std::array<std::array<Number, 3>, 3> M;
      for (unsigned int j = 0; j < 3; ++j)
        for (unsigned int k = 0; k < 3; ++k) // (identity rows of dropped j)
          M[j][k] = Number(j == k && T[j][j] == 0 ? 1. : 0.);
      const auto multipliers = [&](const SegmentPoint<Number> &q) {
        return apply(T, q.N);
      };
      for (const auto &q : points)
        {
          const auto Nm = multipliers(q);
          for (unsigned int j = 0; j < 3; ++j)
            {
              sums.weight[j] += Nm[j] * q.JxW;
              for (unsigned int k = 0; k < 3; ++k)
                M[j][k] += Nm[j] * Nm[k] * q.JxW;
            }
        }
      const auto B = ClippingGeometry::dual_from_moments(
        std::array<Number, 3>{{Number(1.), Number(1.), Number(1.)}},
        M);
      const auto &face = s.face_nodes[e];
      for (const auto &q : points)
        {
          std::array<Number, 3> phi, psi;
          const auto            Nm = multipliers(q);
          for (unsigned int j = 0; j < 3; ++j)
            {
              phi[j] = B[j][0] * Nm[0] + B[j][1] * Nm[1] + B[j][2] * Nm[2];
              psi[j] = sums.weight[j] * phi[j];
              sums.ratio[j] += phi[j] * q.gap * q.JxW;
            }
          const auto &primary = p.face_nodes[q.face];
          if (rates || friction)
            {
              Vec<Number> v_rel;
              for (unsigned int k = 0; k < 3; ++k)
                v_rel +=
                  q.N[k] * m.vs.at(face[k]) - q.Np[k] * m.vp.at(primary[k]);
              for (unsigned int j = 0; j < 3; ++j)
                {
                  if (rates)
                    sums.gap_rate[j] -= psi[j] * (v_rel * q.normal) * q.JxW;
                  if (friction)
                    sums.slip_rate[j] +=
                      psi[j] * (v_rel * SegmentGeometry::rotate(q.normal)) *
                      q.JxW;
                }
            }
          if (!forces || (exact && !friction))
            continue;
          Vec<Number> z_t, z_n;
          for (unsigned int j = 0; j < 3; ++j)
            {
              z_t += Number(psi[j] * m.lambda_t[j]) * m.tangent[j];
              z_n += Number(psi[j] * m.lambda[j]) * m.normal[j];
            }
          for (unsigned int i = 0; i < 3; ++i)
            for (unsigned int d = 0; d < 2; ++d)
              {
                const auto rs = s.dofs[face[i]][d];
                const auto rp = p.dofs[primary[i]][d];
                if (!exact)
                  {
                    sums.normal_rows[rs] += q.N[i] * z_n[d] * q.JxW;
                    sums.normal_rows[rp] -= q.Np[i] * z_n[d] * q.JxW;
                  }
                if (friction)
                  {
                    sums.rows[rs] += q.N[i] * z_t[d] * q.JxW;
                    sums.rows[rp] -= q.Np[i] * z_t[d] * q.JxW;
                    const double ft = value_of(z_t[d] * q.JxW);
                    sums.tangential_rows[rs] += value_of(q.N[i]) * ft;
                    sums.tangential_rows[rp] -= value_of(q.Np[i]) * ft;
                  }
              }
        }
      return sums;
    }

    // the secondary nodes a face of degree 2 reads: its own, then those of
    // the faces that share its vertices (their normals)
    template <typename Surface>
    std::vector<unsigned int>
    secondary_nodes(const Surface &s, const unsigned int e)
    {
      std::vector<unsigned int> nodes = s.face_nodes[e];
      for (const unsigned int v : s.faces[e])
        for (const unsigned int f : s.node_faces[v])
          for (const unsigned int node : s.face_nodes[f])
            if (std::find(nodes.begin(), nodes.end(), node) == nodes.end())
              nodes.push_back(node);
      return nodes;
    }

    template <typename PairData>
    std::set<unsigned int>
    primary_nodes(const PairData &pair, const std::vector<unsigned int> &faces)
    {
      std::set<unsigned int> nodes;
      for (const unsigned int pf : faces)
        nodes.insert(pair.primary.face_nodes[pf].begin(),
                     pair.primary.face_nodes[pf].end());
      return nodes;
    }
  } // namespace



  template <int dim>
  std::vector<types::global_dof_index>
  MortarContact<dim>::quadratic_patch_unknowns(
    const PairData                  &pair,
    const unsigned int               e,
    const std::vector<unsigned int> &primary_faces) const
  {
    const auto                          &s = pair.secondary;
    std::vector<types::global_dof_index> unknowns;
    for (const unsigned int n : secondary_nodes(s, e))
      for (unsigned int d = 0; d < dim; ++d)
        unknowns.push_back(s.dofs[n][d]);
    for (const unsigned int n : primary_nodes(pair, primary_faces))
      for (unsigned int d = 0; d < dim; ++d)
        unknowns.push_back(pair.primary.dofs[n][d]);
    for (const unsigned int c : {dim, dim + 1})
      for (const unsigned int n : s.face_nodes[e])
        unknowns.push_back(s.dofs[n][c]);
    return unknowns;
  }



  namespace
  {
    using Nodes = std::vector<std::pair<bool, unsigned int>>; // secondary?

    // A patch of degree 2 reads 7 secondary nodes, 5 to 9 primary ones and
    // 6 multipliers: numbers on the stack up to 48 first derivatives and
    // 32 seeded positions (the dynamic types allocate for every temporary:
    // 10 times slower contact assembly on the bouncing block)
    template <typename Function>
    void
    dispatch_first(const unsigned int n, const Function &f)
    {
      if (n <= ContactAD::static_width)
        f(ContactAD::StaticAD<ContactAD::static_width>());
      else if (n <= 48)
        f(ContactAD::StaticAD<48>());
      else
        f(ContactAD::AD());
    }

    // (seeded: 14 secondary positions and 6, 10 or 14 of the covering
    // primary faces; loops of fixed length are 2.5 times faster)
    template <typename Function>
    void
    dispatch_second(const unsigned int n, const Function &f)
    {
      if (n == 20)
        f(ContactAD::FixedAD2<20>(0.));
      else if (n == 24)
        f(ContactAD::FixedAD2<24>(0.));
      else if (n == 28)
        f(ContactAD::FixedAD2<28>(0.));
      else if (n <= ContactAD::static_width_second || n > 32)
        ContactAD::dispatch_second(n, f);
      else
        f(Sacado::Fad::SLFad<ContactAD::StaticAD<32>, 32>());
    }

    // The directions w_j d(g_j / w_j)/du_i of the normal force and their
    // derivatives weighted with the multipliers, hessian[i n + l], seeded
    // in the positions `seeded` (indices i) that the gaps depend on
    template <typename AD2, typename PairData>
    void
    quadratic_directions(const PairData                             &pair,
                         const unsigned int                          e,
                         const Nodes                                &nodes,
                         const std::vector<unsigned int>            &seeded,
                         const std::vector<types::global_dof_index> &unknowns,
                         const TrialState                           &state,
                         const QGauss<1>                            &gauss,
                         const double                        minimum_fraction,
                         const std::array<double, 3>        &lambda,
                         std::vector<std::array<double, 3>> &direction,
                         std::vector<double>                &hessian)
    {
      using Inner                     = typename AD2::value_type;
      const unsigned int  n_positions = 2 * nodes.size();
      const unsigned int  n_seeded    = seeded.size();
      QuadraticPatch<AD2> m;
      for (unsigned int k = 0, v = 0; k < nodes.size(); ++k)
        {
          const auto &surface = nodes[k].first ? pair.secondary : pair.primary;
          auto       &x       = (nodes[k].first ? m.xs : m.xp)[nodes[k].second];
          for (unsigned int d = 0; d < 2; ++d)
            {
              const unsigned int i = 2 * k + d;
              const double       value =
                surface.reference[nodes[k].second][d] + state.u(unknowns[i]);
              if (v < n_seeded && seeded[v] == i)
                x[d] = AD2(n_seeded, v, Inner(n_seeded, v, value)), ++v;
              else
                x[d] = AD2(value);
            }
        }
      set_face_geometry(pair.secondary, e, true, m);
      const auto f =
        integrate_face(pair, e, m, gauss, false, true, false, minimum_fraction);
      for (unsigned int v = 0; v < n_seeded; ++v)
        {
          std::array<Inner, 3> d;
          for (unsigned int j = 0; j < 3; ++j)
            {
              d[j]                    = v < unsigned(f.ratio[j].size()) ?
                                          f.weight[j].val() * f.ratio[j].dx(v) :
                                          Inner(0.);
              direction[seeded[v]][j] = d[j].val();
            }
          for (unsigned int w = 0; w < n_seeded; ++w)
            {
              double h = 0;
              for (unsigned int j = 0; j < 3; ++j)
                if (d[j].size() > int(w))
                  h += lambda[j] * d[j].dx(w);
              hessian[seeded[v] * n_positions + seeded[w]] = h;
            }
        }
    }
    // quadratic_directions() seeded in the positions the gaps depend on:
    // the secondary nodes and those of the covering primary faces
    template <typename PairData>
    void
    exact_directions(const PairData                             &pair,
                     const unsigned int                          e,
                     const Nodes                                &nodes,
                     const std::vector<unsigned int>            &covering,
                     const std::vector<types::global_dof_index> &unknowns,
                     const TrialState                           &state,
                     const QGauss<1>                            &gauss,
                     const double                        minimum_fraction,
                     const std::array<double, 3>        &lambda,
                     std::vector<std::array<double, 3>> &direction,
                     std::vector<double>                &hessian)
    {
      const auto                covering_nodes = primary_nodes(pair, covering);
      std::vector<unsigned int> seeded;
      for (unsigned int k = 0; k < nodes.size(); ++k)
        if (nodes[k].first || covering_nodes.count(nodes[k].second) > 0)
          for (unsigned int d = 0; d < 2; ++d)
            seeded.push_back(2 * k + d);
      dispatch_second(seeded.size(), [&](const auto zero) {
        quadratic_directions<std::decay_t<decltype(zero)>>(pair,
                                                           e,
                                                           nodes,
                                                           seeded,
                                                           unknowns,
                                                           state,
                                                           gauss,
                                                           minimum_fraction,
                                                           lambda,
                                                           direction,
                                                           hessian);
      });
    }

    // the face's gaps, weights and rates into the pair's nodes, its
    // friction rows into `forces`
    template <typename AD, typename PairData, typename PatchForces>
    void
    add_face_sums(PairData                                   &pair,
                  const unsigned int                          e,
                  const QuadraticSums<AD>                    &sums,
                  const std::vector<types::global_dof_index> &unknowns,
                  PatchForces                                &forces)
    {
      for (unsigned int a = 0; a < 3; ++a)
        {
          const unsigned int j = pair.secondary.face_nodes[e][a];
          ContactAD::add_to(pair.gap[j],
                            AD(sums.weight[a] * sums.ratio[a]),
                            unknowns);
          ContactAD::add_to(pair.weight[j], sums.weight[a], unknowns);
          ContactAD::add_to(pair.gap_rate[j], sums.gap_rate[a], unknowns);
          ContactAD::add_to(pair.slip_rate[j][0], sums.slip_rate[a], unknowns);
        }
      for (const auto &r : sums.rows)
        forces.add(r.first,
                   r.second.val(),
                   ContactAD::derivatives(r.second, unknowns));
      for (const auto &r : sums.tangential_rows)
        forces.add_tangential(r.first, r.second);
    }
  } // namespace



  template <int dim>
  void
  MortarContact<dim>::assemble_quadratic_patch(PairData          &pair,
                                               const unsigned int e,
                                               const TrialState  &state,
                                               PatchForces       &forces)
  {
    const auto &s       = pair.secondary;
    const auto &p       = pair.primary;
    const auto unknowns = quadratic_patch_unknowns(pair, e, pair.candidates[e]);
    const bool exact    = this->complementarity.exact_jacobian;
    const bool rates = this->complementarity.holds_contact() && state.dynamic;
    const QGauss<1> gauss(quadrature_points + 2);
    Nodes           nodes;
    for (const unsigned int n : secondary_nodes(s, e))
      nodes.emplace_back(true, n);
    for (const unsigned int n : primary_nodes(pair, pair.candidates[e]))
      nodes.emplace_back(false, n);
    const unsigned int                 n_positions = 2 * nodes.size();
    std::array<double, 3>              lambda;
    std::vector<unsigned int>          covering;
    std::vector<std::array<double, 3>> direction(n_positions, {{0., 0., 0.}});
    std::map<types::global_dof_index, typename PatchForces::Derivatives>
      normal_derivatives;

    // gaps, weights, rates and force rows with first derivatives
    dispatch_first(unknowns.size(), [&](const auto zero) {
      using AD = std::decay_t<decltype(zero)>;
      ContactAD::NodeVariables<dim, AD> variables(unknowns, state);
      QuadraticPatch<AD>                m;
      for (const auto &[secondary, n] : nodes)
        if (secondary)
          variables.add(s, n, m.xs[n], m.vs[n]);
        else
          variables.add(p, n, m.xp[n], m.vp[n]);
      for (auto &l : m.lambda)
        l = variables.multiplier();
      for (auto &l : m.lambda_t)
        l = variables.multiplier();
      for (unsigned int j = 0; j < 3; ++j)
        lambda[j] = m.lambda[j].val();
      set_face_geometry(s, e, exact, m);
      const auto sums = integrate_face(pair,
                                       e,
                                       m,
                                       gauss,
                                       rates,
                                       exact,
                                       true,
                                       minimum_covered_fraction_2);
      covering        = sums.faces;
      add_face_sums(pair, e, sums, unknowns, forces);
      // approximate: the directions from the exact geometry, without their
      // derivatives, and the derivatives of the nodal-normal traction
      if (exact)
        return;
      for (const auto &r : sums.normal_rows)
        for (unsigned int l = 0; l < n_positions; ++l)
          if (l < unsigned(r.second.size()) && r.second.dx(l) != 0)
            normal_derivatives[r.first].emplace_back(unknowns[l],
                                                     r.second.dx(l));
      set_face_geometry(s, e, true, m);
      const auto f = integrate_face(pair,
                                    e,
                                    m,
                                    gauss,
                                    false,
                                    true,
                                    false,
                                    minimum_covered_fraction_2);
      for (unsigned int i = 0; i < n_positions; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          direction[i][j] = f.ratio[j].size() > int(i) ?
                              f.weight[j].val() * f.ratio[j].dx(i) :
                              0.;
    });

    std::vector<double> hessian(exact ? n_positions * n_positions : 0);
    if (exact && !covering.empty())
      {
        exact_directions(pair,
                         e,
                         nodes,
                         covering,
                         unknowns,
                         state,
                         gauss,
                         minimum_covered_fraction_2,
                         lambda,
                         direction,
                         hessian);
      }
    forces.add_normal_rows(
      unknowns,
      lambda,
      direction,
      hessian,
      [&](const unsigned int i, typename PatchForces::Derivatives &d) {
        const auto r = normal_derivatives.find(unknowns[i]);
        if (r != normal_derivatives.end())
          d.insert(d.end(), r->second.begin(), r->second.end());
      });
  }

  template std::vector<types::global_dof_index>
  MortarContact<2>::quadratic_patch_unknowns(
    const PairData &,
    const unsigned int,
    const std::vector<unsigned int> &) const;
  template void
  MortarContact<2>::assemble_quadratic_patch(PairData &,
                                             const unsigned int,
                                             const TrialState &,
                                             PatchForces &);
} // namespace ContactDynamics
