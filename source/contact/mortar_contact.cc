#include <deal.II/base/exceptions.h>
#include <deal.II/base/quadrature_lib.h>

#include <contact_dynamics/contact/contact_ad.h>
#include <contact_dynamics/contact/mortar_contact.h>
#include <contact_dynamics/contact/mortar_geometry.h>
#include <contact_dynamics/parameters.h>

#include <algorithm>
#include <set>

namespace ContactDynamics
{
  using ContactAD::AD;
  using ContactAD::constant;
  using ContactAD::value;
  using SegmentGeometry::Vec;

  void
  MortarParameters::declare_parameters(ParameterHandler &prm)
  {
    const MortarParameters defaults;
    ComplementarityParameters::declare_parameters(prm,
                                                  defaults.complementarity);
    prm.declare_entry("Segment quadrature points",
                      default_text(defaults.quadrature_points),
                      Patterns::Integer(1, 10),
                      "Gauss points per mortar segment, in [1, 10]; 2 "
                      "integrates the products of linear functions exactly.");
  }

  void
  MortarParameters::parse_parameters(ParameterHandler &prm)
  {
    complementarity.parse_parameters(prm);
    quadrature_points = prm.get_integer("Segment quadrature points");
  }



  template <int dim>
  MortarContact<dim>::MortarContact(const ContactParameters &contact,
                                    const MortarParameters  &mortar)
    : SurfaceContact<dim>(contact, mortar.complementarity)
    , quadrature_points(mortar.quadrature_points)
  {}

  namespace
  {
    template <int dim, typename PairData>
    std::set<unsigned int>
    primary_nodes(const PairData                  &pair,
                  const std::vector<unsigned int> &primary_faces)
    {
      std::set<unsigned int> nodes;
      for (const unsigned int pf : primary_faces)
        for (const unsigned int node : pair.primary.faces[pf])
          nodes.insert(node);
      return nodes;
    }
  } // namespace

  template <int dim>
  BoundingBox<dim>
  MortarContact<dim>::patch_box(const PairData    &pair,
                                const unsigned int patch,
                                const VectorType  &u,
                                double            &size) const
  {
    return pair.secondary.face_box(patch, u, size);
  }

  template <int dim>
  std::vector<types::global_dof_index>
  MortarContact<dim>::patch_unknowns(
    const PairData                  &pair,
    const unsigned int               face,
    const std::vector<unsigned int> &primary_faces) const
  {
    const auto                          &s = pair.secondary;
    const auto                          &f = s.faces[face];
    std::vector<types::global_dof_index> unknowns;
    for (const unsigned int n :
         {s.neighbour(f[0], face), f[0], f[1], s.neighbour(f[1], face)})
      if (n != ContactSurface<dim>::invalid)
        for (unsigned int d = 0; d < dim; ++d)
          unknowns.push_back(s.dofs[n][d]);
    for (const unsigned int n : primary_nodes<dim>(pair, primary_faces))
      for (unsigned int d = 0; d < dim; ++d)
        unknowns.push_back(pair.primary.dofs[n][d]);
    // normal and tangential multipliers
    for (const unsigned int c : {dim, dim + 1})
      for (const unsigned int n : f)
        unknowns.push_back(s.dofs[n][c]);
    return unknowns;
  }

  namespace
  {
    // a mortar patch in AD numbers: positions and velocities of the
    // secondary nodes (the face and its neighbours) and primary nodes, the
    // face, its nodal normals and tangents and its multipliers
    struct MortarPatch
    {
      std::map<unsigned int, Vec<AD>> xs, vs, xp, vp;
      Vec<AD>                         x0, x1, n0, n1, t0, t1, face_n;
      AD                              half_length;
      AD                              lambda[2], lambda_t[2];
    };

    // what the mortar segments of a patch add up
    struct SegmentSums
    {
      std::map<types::global_dof_index, AD>     rows; // residual contributions
      std::map<types::global_dof_index, double> tangential_rows;
      AD gap[2], weight[2], gap_rate[2], slip_rate[2];
    };

    // the parameters lo < hi on the secondary face of the segment that the
    // primary face (y0, y1) covers, projected along the normal field;
    // false if it covers none
    bool
    segment_bounds(const MortarPatch &m,
                   const Vec<AD>     &y0,
                   const Vec<AD>     &y1,
                   const bool         exact,
                   AD                &lo,
                   AD                &hi)
    {
      double xi_c, xi_d;
      if (!MortarGeometry::project_along_normal_field(value(m.x0),
                                                      value(m.x1),
                                                      value(m.n0),
                                                      value(m.n1),
                                                      value(y0),
                                                      xi_c) ||
          !MortarGeometry::project_along_normal_field(value(m.x0),
                                                      value(m.x1),
                                                      value(m.n0),
                                                      value(m.n1),
                                                      value(y1),
                                                      xi_d))
        return false;
      const double lo_v = std::max(-1., std::min(xi_c, xi_d));
      const double hi_v = std::min(1., std::max(xi_c, xi_d));
      if (hi_v - lo_v < 1e-12)
        return false;
      // an end inside the face moves with the primary node it projects
      const auto end =
        [&](const double bound, const Vec<AD> &y, const double xi) -> AD {
        if (std::abs(bound - xi) > 0 || !exact)
          return AD(bound);
        return MortarGeometry::project_along_normal_field(m.x0,
                                                          m.x1,
                                                          m.n0,
                                                          m.n1,
                                                          y,
                                                          xi);
      };
      lo = (lo_v == std::min(xi_c, xi_d)) ?
             end(lo_v, xi_c < xi_d ? y0 : y1, std::min(xi_c, xi_d)) :
             AD(lo_v);
      hi = (hi_v == std::max(xi_c, xi_d)) ?
             end(hi_v, xi_c < xi_d ? y1 : y0, std::max(xi_c, xi_d)) :
             AD(hi_v);
      return true;
    }

    // the gap, weight, rate and force integrals over the segment [lo, hi]
    // of face e that the primary face pf covers; `rates`: gap rates too
    template <typename PairData>
    void
    integrate_segment(const PairData                         &pair,
                      const unsigned int                      e,
                      const unsigned int                      pf,
                      const MortarPatch                      &m,
                      const AD                               &lo,
                      const AD                               &hi,
                      const std::array<std::array<AD, 2>, 2> &dual,
                      const QGauss<1>                        &gauss,
                      const bool                              rates,
                      const bool                              exact,
                      SegmentSums                            &sums)
    {
      const auto    &s        = pair.secondary;
      const auto    &p        = pair.primary;
      const auto    &face     = s.faces[e];
      const bool     friction = pair.friction_coefficient > 0;
      const Vec<AD> &y0       = m.xp.at(p.faces[pf][0]);
      const Vec<AD> &y1       = m.xp.at(p.faces[pf][1]);
      for (unsigned int q = 0; q < gauss.size(); ++q)
        {
          const AD      xi     = lo + (hi - lo) * gauss.point(q)[0];
          const AD      JxW    = gauss.weight(q) * (hi - lo) * m.half_length;
          const auto    N      = SegmentGeometry::shape(xi);
          const auto    psi    = MortarGeometry::dual_shape(xi, dual);
          const Vec<AD> x      = N[0] * m.x0 + N[1] * m.x1;
          Vec<AD>       normal = N[0] * m.n0 + N[1] * m.n1;
          normal /= SegmentGeometry::norm(normal);
          AD eta = MortarGeometry::intersect_line_with_face(x, normal, y0, y1);
          if (!exact)
            eta = constant(eta);
          const auto    Np = SegmentGeometry::shape(eta);
          const Vec<AD> y  = Np[0] * y0 + Np[1] * y1;
          const AD      g  = (y - x) * normal;
          for (unsigned int i = 0; i < 2; ++i)
            {
              sums.gap[i] += psi[i] * g * JxW;
              sums.weight[i] += N[i] * JxW;
            }
          if (rates || friction)
            {
              const Vec<AD> v_s =
                N[0] * m.vs.at(face[0]) + N[1] * m.vs.at(face[1]);
              const Vec<AD> v_p = Np[0] * m.vp.at(p.faces[pf][0]) +
                                  Np[1] * m.vp.at(p.faces[pf][1]);
              const Vec<AD> v_rel = v_s - v_p;
              for (unsigned int i = 0; i < 2; ++i)
                {
                  if (rates)
                    sums.gap_rate[i] -= psi[i] * (v_rel * normal) * JxW;
                  if (friction)
                    sums.slip_rate[i] +=
                      psi[i] * (v_rel * SegmentGeometry::rotate(normal)) * JxW;
                }
            }
          // contact traction z = sum_j psi_j (lambda_j n_j + lambda_t,j t_j),
          // acting on both sides (nodal normals: measured against the
          // interpolated normal n(xi) in doc/contact.md)
          const Vec<AD> z_t = AD(psi[0] * m.lambda_t[0]) * m.t0 +
                              AD(psi[1] * m.lambda_t[1]) * m.t1;
          const Vec<AD> z = AD(psi[0] * m.lambda[0]) * m.n0 +
                            AD(psi[1] * m.lambda[1]) * m.n1 + z_t;
          for (unsigned int i = 0; i < 2; ++i)
            for (unsigned int d = 0; d < 2; ++d)
              {
                sums.rows[s.dofs[face[i]][d]] += N[i] * z[d] * JxW;
                sums.rows[p.dofs[p.faces[pf][i]][d]] -= Np[i] * z[d] * JxW;
                if (friction)
                  {
                    const double ft = (z_t[d] * JxW).val();
                    sums.tangential_rows[s.dofs[face[i]][d]] += N[i].val() * ft;
                    sums.tangential_rows[p.dofs[p.faces[pf][i]][d]] -=
                      Np[i].val() * ft;
                  }
              }
        }
    }
  } // namespace

  template <int dim>
  void
  MortarContact<dim>::assemble_patch(PairData          &pair,
                                     const unsigned int e,
                                     const TrialState  &state,
                                     PatchForces       &forces)
  {
    const auto &s        = pair.secondary;
    const auto &p        = pair.primary;
    const auto &face     = s.faces[e];
    const auto  unknowns = patch_unknowns(pair, e, pair.candidates[e]);
    const bool  exact    = this->complementarity.exact_jacobian;

    // independent variables: positions of the secondary nodes of the face
    // and their neighbours, of the primary nodes, then the multipliers
    ContactAD::NodeVariables<dim> variables(unknowns, state);
    MortarPatch                   m;
    const unsigned int            before = s.neighbour(face[0], e);
    const unsigned int            after  = s.neighbour(face[1], e);
    for (const unsigned int node : {before, face[0], face[1], after})
      if (node != ContactSurface<dim>::invalid)
        variables.add(s, node, m.xs[node], m.vs[node]);
    for (const unsigned int node : primary_nodes<dim>(pair, pair.candidates[e]))
      variables.add(p, node, m.xp[node], m.vp[node]);
    m.lambda[0]   = variables.multiplier();
    m.lambda[1]   = variables.multiplier();
    m.lambda_t[0] = variables.multiplier();
    m.lambda_t[1] = variables.multiplier();

    // nodal normals: average of the adjacent unit face normals
    const auto face_normal = [&](const unsigned int f) {
      return SegmentGeometry::face_normal(m.xs.at(s.faces[f][0]),
                                          m.xs.at(s.faces[f][1]));
    };
    const auto nodal_normal = [&](const unsigned int node) {
      Vec<AD> sum;
      for (const unsigned int f : s.node_faces[node])
        sum += face_normal(f);
      sum /= SegmentGeometry::norm(sum);
      return exact ? sum : constant(sum);
    };
    m.x0          = m.xs.at(face[0]);
    m.x1          = m.xs.at(face[1]);
    m.n0          = nodal_normal(face[0]);
    m.n1          = nodal_normal(face[1]);
    m.face_n      = SegmentGeometry::face_normal(m.x0, m.x1);
    m.half_length = SegmentGeometry::norm(Vec<AD>(m.x1 - m.x0)) / 2.;
    m.t0          = SegmentGeometry::rotate(m.n0);
    m.t1          = SegmentGeometry::rotate(m.n1);

    const QGauss<1> gauss(quadrature_points);
    const bool      rates = this->complementarity.persistency && state.dynamic;
    SegmentSums     sums;
    for (unsigned int i = 0; i < 2; ++i)
      sums.gap[i] = sums.weight[i] = sums.gap_rate[i] = sums.slip_rate[i] =
        AD(0.);
    // the mortar segments: the parts of the face that primary faces
    // (facing it) cover
    std::vector<unsigned int>      segment_faces;
    std::vector<std::pair<AD, AD>> segments;
    double                         covered = 0;
    for (const unsigned int pf : pair.candidates[e])
      {
        const Vec<AD> &y0 = m.xp.at(p.faces[pf][0]);
        const Vec<AD> &y1 = m.xp.at(p.faces[pf][1]);
        AD             lo, hi;
        // only faces that face the secondary one
        if (value(SegmentGeometry::face_normal(y0, y1)) * value(m.face_n) >=
              0 ||
            !segment_bounds(m, y0, y1, exact, lo, hi))
          continue;
        segment_faces.push_back(pf);
        segments.emplace_back(lo, hi);
        covered += (hi.val() - lo.val()) / 2;
      }
    // the dual basis of the covered part (A_e = D_e M_e^-1 over all the
    // segments first), linearized through the segment ends; a sliver (M_e
    // nearly singular) contributes nothing
    if (covered < minimum_covered_fraction)
      segments.clear();
    if (!segments.empty())
      {
        const auto dual = MortarGeometry::dual_coefficients(segments);
        for (unsigned int i = 0; i < segments.size(); ++i)
          integrate_segment(pair,
                            e,
                            segment_faces[i],
                            m,
                            segments[i].first,
                            segments[i].second,
                            dual,
                            gauss,
                            rates,
                            exact,
                            sums);
      }

    for (const auto &r : sums.rows)
      forces.add(r.first,
                 r.second.val(),
                 ContactAD::derivatives(r.second, unknowns));
    for (const auto &r : sums.tangential_rows)
      forces.add_tangential(r.first, r.second);
    for (unsigned int i = 0; i < 2; ++i)
      {
        ContactAD::add_to(pair.gap[face[i]], sums.gap[i], unknowns);
        ContactAD::add_to(pair.weight[face[i]], sums.weight[i], unknowns);
        ContactAD::add_to(pair.gap_rate[face[i]], sums.gap_rate[i], unknowns);
        ContactAD::add_to(pair.slip_rate[face[i]], sums.slip_rate[i], unknowns);
      }
  }

  template class MortarContact<2>;
  template class MortarContact<3>;
} // namespace ContactDynamics
