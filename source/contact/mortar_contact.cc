#include <deal.II/base/exceptions.h>
#include <deal.II/base/quadrature_lib.h>

#include <contact_dynamics/contact/contact_ad.h>
#include <contact_dynamics/contact/mortar_contact.h>
#include <contact_dynamics/contact/mortar_geometry.h>

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
    ComplementarityParameters::declare_parameters(prm, "persistency");
    prm.declare_entry("Segment quadrature points",
                      "2",
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

  template <int dim>
  void
  MortarContact<dim>::assemble_patch(
    PairData                        &pair,
    const unsigned int               e,
    const TrialState                &state,
    const AffineConstraints<double> &constraints,
    const bool                       with_jacobian,
    VectorType                      &residual,
    MatrixType                      &jacobian,
    VectorType                      &residual_full)
  {
    const auto &s        = pair.secondary;
    const auto &p        = pair.primary;
    const auto &face     = s.faces[e];
    const auto  unknowns = patch_unknowns(pair, e, pair.candidates[e]);
    const bool  exact    = this->complementarity.exact_jacobian;

    // independent variables: positions of the secondary nodes of the face
    // and their neighbours, of the primary nodes, then the multipliers
    ContactAD::NodeVariables<dim>   variables(unknowns, state);
    std::map<unsigned int, Vec<AD>> xs, vs, xp, vp;
    const unsigned int              before = s.neighbour(face[0], e);
    const unsigned int              after  = s.neighbour(face[1], e);
    for (const unsigned int node : {before, face[0], face[1], after})
      if (node != ContactSurface<dim>::invalid)
        variables.add(s, node, xs[node], vs[node]);
    for (const unsigned int node : primary_nodes<dim>(pair, pair.candidates[e]))
      variables.add(p, node, xp[node], vp[node]);
    const AD lambda_0   = variables.multiplier();
    const AD lambda_1   = variables.multiplier();
    const AD lambda_t_0 = variables.multiplier();
    const AD lambda_t_1 = variables.multiplier();

    // nodal normals: average of the adjacent unit face normals
    const auto face_normal = [&](const unsigned int f) {
      return SegmentGeometry::face_normal(xs.at(s.faces[f][0]),
                                          xs.at(s.faces[f][1]));
    };
    const auto nodal_normal = [&](const unsigned int node) {
      Vec<AD> sum;
      for (const unsigned int f : s.node_faces[node])
        sum += face_normal(f);
      sum /= SegmentGeometry::norm(sum);
      return exact ? sum : constant(sum);
    };
    const Vec<AD> &x0 = xs.at(face[0]), &x1 = xs.at(face[1]);
    const Vec<AD>  n0 = nodal_normal(face[0]), n1 = nodal_normal(face[1]);
    const Vec<AD>  face_n      = SegmentGeometry::face_normal(x0, x1);
    const AD       half_length = SegmentGeometry::norm(Vec<AD>(x1 - x0)) / 2.;

    const Vec<AD> t0 = SegmentGeometry::rotate(n0),
                  t1 = SegmentGeometry::rotate(n1);
    std::map<types::global_dof_index, AD>     rows; // residual contributions
    std::map<types::global_dof_index, double> tangential_rows;
    AD gap[2], weight[2], gap_rate[2], slip_rate[2];
    for (unsigned int i = 0; i < 2; ++i)
      gap[i] = weight[i] = gap_rate[i] = slip_rate[i] = AD(0.);
    const bool      friction = pair.friction_coefficient > 0;
    const QGauss<1> gauss(quadrature_points);

    for (const unsigned int pf : pair.candidates[e])
      {
        const Vec<AD> &y0 = xp.at(p.faces[pf][0]), &y1 = xp.at(p.faces[pf][1]);
        // only faces that face the secondary one
        if (value(SegmentGeometry::face_normal(y0, y1)) * value(face_n) >= 0)
          continue;
        double xi_c, xi_d;
        if (!MortarGeometry::project_along_normal_field(value(x0),
                                                        value(x1),
                                                        value(n0),
                                                        value(n1),
                                                        value(y0),
                                                        xi_c) ||
            !MortarGeometry::project_along_normal_field(value(x0),
                                                        value(x1),
                                                        value(n0),
                                                        value(n1),
                                                        value(y1),
                                                        xi_d))
          continue;
        const double lo_v = std::max(-1., std::min(xi_c, xi_d));
        const double hi_v = std::min(1., std::max(xi_c, xi_d));
        if (hi_v - lo_v < 1e-12)
          continue;
        const auto end =
          [&](const double bound, const Vec<AD> &y, const double xi) -> AD {
          if (std::abs(bound - xi) > 0 || !exact)
            return AD(bound);
          return MortarGeometry::project_along_normal_field(x0,
                                                            x1,
                                                            n0,
                                                            n1,
                                                            y,
                                                            xi);
        };
        const AD lo = (lo_v == std::min(xi_c, xi_d)) ?
                        end(lo_v, xi_c < xi_d ? y0 : y1, std::min(xi_c, xi_d)) :
                        AD(lo_v);
        const AD hi = (hi_v == std::max(xi_c, xi_d)) ?
                        end(hi_v, xi_c < xi_d ? y1 : y0, std::max(xi_c, xi_d)) :
                        AD(hi_v);

        for (unsigned int q = 0; q < gauss.size(); ++q)
          {
            const AD      xi     = lo + (hi - lo) * gauss.point(q)[0];
            const AD      JxW    = gauss.weight(q) * (hi - lo) * half_length;
            const auto    N      = SegmentGeometry::shape(xi);
            const auto    psi    = MortarGeometry::dual_shape(xi);
            const Vec<AD> x      = N[0] * x0 + N[1] * x1;
            Vec<AD>       normal = N[0] * n0 + N[1] * n1;
            normal /= SegmentGeometry::norm(normal);
            AD eta =
              MortarGeometry::intersect_line_with_face(x, normal, y0, y1);
            if (!exact)
              eta = constant(eta);
            const auto    Np = SegmentGeometry::shape(eta);
            const Vec<AD> y  = Np[0] * y0 + Np[1] * y1;
            const AD      g  = (y - x) * normal;
            for (unsigned int i = 0; i < 2; ++i)
              {
                gap[i] += psi[i] * g * JxW;
                weight[i] += N[i] * JxW;
              }
            const bool rates =
              this->complementarity.persistency && state.dynamic;
            if (rates || friction)
              {
                const Vec<AD> v_s =
                  N[0] * vs.at(face[0]) + N[1] * vs.at(face[1]);
                const Vec<AD> v_p =
                  Np[0] * vp.at(p.faces[pf][0]) + Np[1] * vp.at(p.faces[pf][1]);
                const Vec<AD> v_rel = v_s - v_p;
                for (unsigned int i = 0; i < 2; ++i)
                  {
                    if (rates)
                      gap_rate[i] -= psi[i] * (v_rel * normal) * JxW;
                    if (friction)
                      slip_rate[i] +=
                        psi[i] * (v_rel * SegmentGeometry::rotate(normal)) *
                        JxW;
                  }
              }
            // contact traction z = sum_j psi_j (lambda_j n_j + lambda_t,j
            // t_j), acting on both sides
            const Vec<AD> z_t =
              AD(psi[0] * lambda_t_0) * t0 + AD(psi[1] * lambda_t_1) * t1;
            const Vec<AD> z =
              AD(psi[0] * lambda_0) * n0 + AD(psi[1] * lambda_1) * n1 + z_t;
            for (unsigned int i = 0; i < 2; ++i)
              for (unsigned int d = 0; d < 2; ++d)
                {
                  rows[s.dofs[face[i]][d]] += N[i] * z[d] * JxW;
                  rows[p.dofs[p.faces[pf][i]][d]] -= Np[i] * z[d] * JxW;
                  if (friction)
                    {
                      const double ft = (z_t[d] * JxW).val();
                      tangential_rows[s.dofs[face[i]][d]] += N[i].val() * ft;
                      tangential_rows[p.dofs[p.faces[pf][i]][d]] -=
                        Np[i].val() * ft;
                    }
                }
          }
      }

    for (const auto &r : rows)
      this->add_force(r.first,
                      r.second.val(),
                      ContactAD::derivatives(r.second, unknowns),
                      constraints,
                      with_jacobian,
                      residual,
                      jacobian,
                      residual_full);
    for (const auto &r : tangential_rows)
      this->add_tangential_force(r.first, r.second);
    for (unsigned int i = 0; i < 2; ++i)
      {
        ContactAD::add_to(pair.gap[face[i]], gap[i], unknowns);
        ContactAD::add_to(pair.weight[face[i]], weight[i], unknowns);
        ContactAD::add_to(pair.gap_rate[face[i]], gap_rate[i], unknowns);
        ContactAD::add_to(pair.slip_rate[face[i]], slip_rate[i], unknowns);
      }
  }

  template class MortarContact<2>;
  template class MortarContact<3>;
} // namespace ContactDynamics
