// 2-D node-to-segment contact on primary faces of degree 2 (3-node
// curves): every secondary node (vertices and mid-side nodes) is projected
// onto the closest curved primary face (Newton), the gap is measured along
// the curve's normal there, and the nodal force lambda L_j n acts on the
// node and, with the weights N(eta) of the three face nodes, opposite on
// the primary face. Normal smoothing blends, within the smoothing distance
// of a face end, into the mean of the two curves' normals at their shared
// vertex (continuous there; within a curve the normal is continuous
// anyway).
#include <contact_dynamics/contact/contact_ad.h>
#include <contact_dynamics/contact/node_to_segment_contact.h>
#include <contact_dynamics/contact/quadratic_curve.h>

namespace ContactDynamics
{
  namespace
  {
    using namespace QuadraticCurve;

    // the closest primary face of degree 2 to node j at x (as closest_face
    // of node_to_segment_contact.cc for straight faces: faces seen from
    // behind skipped, the previous face kept within a tolerance)
    template <typename PairData, typename AD>
    unsigned int
    closest_curve(const PairData                        &pair,
                  const unsigned int                     j,
                  const Vec<double>                     &x,
                  const std::map<unsigned int, Vec<AD>> &xp,
                  const VectorType                      &u,
                  const unsigned int                     previous,
                  double                                &best_eta)
    {
      const auto &s = pair.secondary;
      const auto &p = pair.primary;
      Vec<double> n_s; // the secondary chords' normals
      for (const unsigned int f : s.node_faces[j])
        n_s += SegmentGeometry::face_normal(
          Vec<double>(s.position(s.faces[f][0], u)),
          Vec<double>(s.position(s.faces[f][1], u)));
      constexpr double tangential_tolerance = 1e-2;
      unsigned int     best                 = ContactSurface<2>::invalid;
      double           best_distance        = 1e300;
      best_eta                              = 0;
      for (const unsigned int f : pair.candidates[j])
        {
          const Curve<double> y = values(face_positions(xp, p.face_nodes[f]));
          if (SegmentGeometry::face_normal(y[0], y[1]) * n_s >= 0)
            continue;
          const Vec<double> t        = (y[1] - y[0]) / 2.;
          double            eta_free = (x - (y[0] + y[1]) / 2.) * t / (t * t);
          // (Newton failed or found a farthest point: the chord's
          // projection, without derivatives, see below)
          const double chord = eta_free;
          if (!closest_point(y, x, eta_free))
            eta_free = chord;
          if (f == previous && std::abs(eta_free) <= 1 + tangential_tolerance)
            {
              best     = f;
              best_eta = eta_free;
              break;
            }
          const double eta = std::max(-1., std::min(1., eta_free));
          const double distance =
            (x - combine(y, QuadraticFace::line_shape(eta))).norm();
          if (distance < best_distance)
            {
              best          = f;
              best_distance = distance;
              best_eta =
                std::abs(eta_free) <= 1 + tangential_tolerance ? eta_free : eta;
            }
        }
      return best;
    }

    // the unit normal of primary face f at eta, smoothed near its ends
    template <typename PairData, typename AD>
    Vec<AD>
    curve_normal_smoothed(const PairData                        &pair,
                          const unsigned int                     f,
                          const AD                              &eta,
                          const std::map<unsigned int, Vec<AD>> &xp,
                          const double                           smoothing)
    {
      const auto     &p      = pair.primary;
      const Curve<AD> y      = face_positions(xp, p.face_nodes[f]);
      Vec<AD>         normal = curve_normal(y, eta);
      if (smoothing <= 0)
        return normal;
      for (const unsigned int end : {0u, 1u})
        {
          const AD to_end =
            end == 0 ? AD((1. + eta) / 2.) : AD((1. - eta) / 2.);
          const unsigned int node  = p.faces[f][end];
          unsigned int       other = ContactSurface<2>::invalid;
          for (const unsigned int g : p.node_faces[node])
            if (g != f)
              other = g;
          if (to_end.val() >= smoothing || other == ContactSurface<2>::invalid)
            continue;
          const auto &nodes = p.face_nodes[other];
          const auto  k =
            std::find(nodes.begin(), nodes.end(), node) - nodes.begin();
          const Vec<AD> n_other =
            curve_normal(face_positions(xp, nodes), node_xi[k]);
          const Vec<AD> n_end = curve_normal(y, node_xi[end]);
          if (to_end.val() <= 0) // beyond the end (the face memory): the mean
            {
              normal = AD(0.5) * (n_end + n_other);
              break;
            }
          const AD weight = (smoothing - to_end) / smoothing;
          normal += AD(weight / 2.) * (n_other - n_end);
        }
      return normal / SegmentGeometry::norm(normal);
    }
  } // namespace



  template <int dim>
  template <typename AD>
  void
  NodeToSegmentContact<dim>::assemble_quadratic_patch_ad(
    PairData                                   &pair,
    const unsigned int                          j,
    const TrialState                           &state,
    const std::vector<types::global_dof_index> &unknowns,
    PatchForces                                &forces)
  {
    const auto &s     = pair.secondary;
    const auto &p     = pair.primary;
    const bool  exact = this->complementarity.exact_jacobian;
    ContactAD::NodeVariables<dim, AD> variables(unknowns, state);
    Vec<AD>                           x, v;
    std::map<unsigned int, Vec<AD>>   xp, vp;
    variables.add(s, j, x, v);
    for (const unsigned int node : primary_nodes(pair, pair.candidates[j]))
      variables.add(p, node, xp[node], vp[node]);
    const AD lambda   = variables.multiplier();
    const AD lambda_t = variables.multiplier();
    auto    &current  = face_memory.trial_faces(pair.index);
    current.resize(s.n_nodes(), ContactSurface<dim>::invalid);
    double             best_eta = 0;
    const unsigned int best =
      closest_curve(pair, j, values(x), xp, state.u, current[j], best_eta);
    current[j] = best;
    if (best == ContactSurface<dim>::invalid)
      return; // no projection: the node is inactive
    const auto     &face = p.face_nodes[best];
    const Curve<AD> y    = face_positions(xp, face);
    AD              eta  = closest_point(y, x, best_eta);
    if (std::abs(eta.val() - best_eta) > 1e-12 || !exact)
      eta = AD(best_eta); // clamped at a face end, or approximate
    Vec<AD> normal =
      curve_normal_smoothed(pair, best, eta, xp, smoothing_distance);
    if (!exact)
      normal = ContactAD::constant(normal);
    const auto N = QuadraticFace::line_shape(eta);
    const AD   g = (x - combine(y, N)) * normal;
    ContactAD::add_to(pair.gap[j], g, unknowns);
    pair.weight[j].value += 1.;
    const Vec<AD> n_secondary = -normal;
    const Vec<AD> tangent     = SegmentGeometry::rotate(n_secondary);
    const bool    friction    = pair.friction_coefficient > 0;
    if ((this->complementarity.holds_contact() && state.dynamic) || friction)
      {
        Vec<AD> v_rel = v;
        for (unsigned int k = 0; k < 3; ++k)
          v_rel -= N[k] * vp.at(face[k]);
        ContactAD::add_to(pair.gap_rate[j],
                          AD(-(v_rel * n_secondary)),
                          unknowns);
        if (friction)
          ContactAD::add_to(pair.slip_rate[j][0],
                            AD(v_rel * tangent),
                            unknowns);
      }
    // the nodal force L (lambda n + lambda_t t) on the secondary node, with
    // the weights N(eta) opposite on the primary face's nodes
    const double  L   = s.reference_weight[j];
    const Vec<AD> f_t = AD(lambda_t * L) * tangent;
    const Vec<AD> f   = AD(lambda * L) * n_secondary + f_t;
    for (unsigned int d = 0; d < 2; ++d)
      {
        forces.add(s.dofs[j][d],
                   f[d].val(),
                   ContactAD::derivatives(f[d], unknowns));
        if (friction)
          forces.add_tangential(s.dofs[j][d], f_t[d].val());
        for (unsigned int k = 0; k < 3; ++k)
          {
            const AD row = -N[k] * f[d];
            forces.add(p.dofs[face[k]][d],
                       row.val(),
                       ContactAD::derivatives(row, unknowns));
            if (friction)
              forces.add_tangential(p.dofs[face[k]][d],
                                    -N[k].val() * f_t[d].val());
          }
      }
  }

#define INSTANTIATE(AD)                                                   \
  template void NodeToSegmentContact<2>::assemble_quadratic_patch_ad<AD>( \
    PairData &,                                                           \
    const unsigned int,                                                   \
    const TrialState &,                                                   \
    const std::vector<types::global_dof_index> &,                         \
    PatchForces &);
  INSTANTIATE(ContactAD::StaticAD<ContactAD::static_width>)
  INSTANTIATE(ContactAD::AD)
#undef INSTANTIATE
} // namespace ContactDynamics
