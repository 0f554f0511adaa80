// 3-D node-to-segment patches: a secondary node, its closest point on the
// bilinear primary faces (closest_point_3d.h) with the face memory of the
// 2-D code, the gap along the primary normal (optionally blended near the
// face's edges into the normal interpolated from averaged nodal normals,
// continuous across edges and at nodes) and the nodal force with its two
// tangential components. The rules follow node_to_segment_contact.cc.
#include <deal.II/base/exceptions.h>

#include <contact_dynamics/contact/closest_point_3d.h>
#include <contact_dynamics/contact/contact_ad.h>
#include <contact_dynamics/contact/node_to_segment_contact.h>
#include <contact_dynamics/contact/surface_geometry_3d.h>

#include <algorithm>
#include <cmath>

namespace ContactDynamics
{
  namespace
  {
    using namespace ClippingGeometry;

    Vec3<double>
    to_vec(const Point<3> &x)
    {
      Vec3<double> v;
      for (unsigned int d = 0; d < 3; ++d)
        v[d] = x[d];
      return v;
    }

    // the unit normal dx/dxi x dx/deta of a face at (xi, eta)
    template <typename Number>
    Vec3<Number>
    face_normal(const std::array<Vec3<Number>, 4> &y,
                const Number                      &xi,
                const Number                      &eta)
    {
      const auto   t = tangents(y, xi, eta);
      Vec3<Number> n = cross(t[0], t[1]);
      return n / norm(n);
    }

    // The primary face closest to secondary node j at x and the parameters
    // of the projection on it (within the tolerance beyond the face's edges
    // the projection extends the face; farther out it is clamped to the
    // face). `previous`: the face of the node's projection in the previous
    // iteration of this attempt, kept while the node stays within the
    // tolerance of it (at a concave kink two faces are equally close, and
    // switching between their normals at every iteration would stall
    // Newton). Faces seen from behind are skipped.
    unsigned int
    closest_face(const Surface                   &s,
                 const Surface                   &p,
                 const unsigned int               j,
                 const std::vector<unsigned int> &candidates,
                 const TrilinosWrappers::MPI::Vector &u,
                 const unsigned int               previous,
                 std::array<double, 2>           &best_parameters)
    {
      // (the 2-D tolerance, 1e-2 of the half-face, as a fraction of the face)
      constexpr double tolerance = 5e-3;
      const auto position = [&](const Surface &surface, const unsigned int k) {
        return to_vec(surface.position(k, u));
      };
      const Vec3<double> x = position(s, j);
      NodeMap<double>    xs;
      for (const unsigned int f : s.node_faces[j])
        for (const unsigned int k : s.faces[f])
          xs[k] = position(s, k);
      const Vec3<double> n_s = nodal_normal(s, j, xs);

      unsigned int best          = Surface::invalid;
      double       best_distance = 1e300;
      best_parameters            = {{0., 0.}};
      for (const unsigned int f : candidates)
        {
          std::array<Vec3<double>, 4> y;
          for (unsigned int a = 0; a < 4; ++a)
            y[a] = position(p, p.faces[f][a]);
          double xi, eta;
          if (!closest_point(y, x, xi, eta))
            continue;
          const bool within = std::min(xi, eta) >= -tolerance &&
                              std::max(xi, eta) <= 1 + tolerance;
          const double xi_c  = std::clamp(xi, 0., 1.),
                       eta_c = std::clamp(eta, 0., 1.);
          if (face_normal(y, xi_c, eta_c) * n_s >= 0)
            continue;
          if (f == previous && within)
            {
              best_parameters = {{xi, eta}};
              return f;
            }
          const double distance = norm(x - interpolate(y, xi_c, eta_c));
          if (distance < best_distance)
            {
              best            = f;
              best_distance   = distance;
              best_parameters = within ? std::array<double, 2>{{xi, eta}} :
                                         std::array<double, 2>{{xi_c, eta_c}};
            }
        }
      return best;
    }

    // The weight of the smoothed normal at a face parameter s in [0, 1]:
    // 1 at the face's ends, 0 farther than `distance` from them (linear)
    template <typename Number>
    Number
    end_weight(const Number &s, const double distance)
    {
      const Number to_end = s.val() <= 0.5 ? s : Number(1. - s);
      return to_end.val() >= distance ? Number(0.) :
                                        Number((distance - to_end) / distance);
    }
  } // namespace



  template <>
  void
  NodeToSegmentContact<3>::assemble_patch(PairData          &pair,
                                          const unsigned int j,
                                          const TrialState  &state,
                                          PatchForces       &forces)
  {
    const auto &s     = pair.secondary;
    const auto &p     = pair.primary;
    const bool  exact = this->complementarity.exact_jacobian;

    // the projection, in double
    const std::ptrdiff_t pair_index = &pair - this->pairs.data();
    auto                &current    = trial_face[pair_index];
    current.resize(s.n_nodes(), Surface::invalid);
    std::array<double, 2> parameters;
    const unsigned int    face = closest_face(
      s, p, j, pair.candidates[j], state.u, current[j], parameters);
    current[j] = face;
    if (face == Surface::invalid)
      return; // no projection: the node is inactive

    // the patch reads the projection's face only (and, for the smoothed
    // normal, the faces around its nodes)
    const std::vector<unsigned int> faces{face};
    const auto unknowns = patch_unknowns(pair, j, faces);
    ContactAD::dispatch(unknowns.size(), [&](const auto zero) {
      using AD = std::decay_t<decltype(zero)>;
      ContactAD::NodeVariables<3, AD> variables(unknowns, state);
      Vec3<AD>                        x, v;
      NodeMap<AD>                     xp, vp;
      variables.add(s, j, x, v);
      for (const unsigned int node : primary_nodes(pair, faces))
        variables.add(p, node, xp[node], vp[node]);
      const AD                lambda = variables.multiplier();
      const std::array<AD, 2> lambda_t{
        {variables.multiplier(), variables.multiplier()}};

      const auto y = face_nodes(p, face, xp);
      AD         xi(parameters[0]), eta(parameters[1]);
      if (exact)
        {
          // derivatives of the closest point in the parameters that are
          // the closest point's (not clamped to the face's edge)
          double xi_free, eta_free;
          if (closest_point(values(y), values(x), xi_free, eta_free))
            {
              const auto r = closest_point_with_derivatives(y,
                                                            x,
                                                            xi_free,
                                                            eta_free);
              if (std::abs(xi_free - parameters[0]) < 1e-12)
                xi = r[0];
              if (std::abs(eta_free - parameters[1]) < 1e-12)
                eta = r[1];
            }
        }

      Vec3<AD> normal = face_normal(y, xi, eta);
      if (smoothing_distance > 0)
        {
          // blended near the edges into the interpolated nodal normals
          const auto N = shape(xi, eta);
          Vec3<AD>   interpolated;
          for (unsigned int a = 0; a < 4; ++a)
            interpolated += N[a] * nodal_normal(p, p.faces[face][a], xp);
          const AD w_xi  = end_weight(xi, smoothing_distance),
                   w_eta = end_weight(eta, smoothing_distance);
          const AD w     = 1. - (1. - w_xi) * (1. - w_eta);
          normal += w * (interpolated / norm(interpolated) - normal);
          normal /= norm(normal);
        }
      if (!exact)
        for (unsigned int d = 0; d < 3; ++d)
          normal[d] = AD(normal[d].val());

      const auto     N   = shape(xi, eta);
      const Vec3<AD> x_p = interpolate(y, xi, eta);
      const AD       g   = (x - x_p) * normal;
      ContactAD::add_to(pair.gap[j], g, unknowns);
      pair.weight[j].value += 1.;

      // the secondary side's normal and tangents
      const Vec3<AD> n_secondary = -normal;
      const bool     friction    = pair.friction_coefficient > 0;
      std::array<Vec3<AD>, 2> tangent;
      if (friction)
        tangent = tangent_basis(n_secondary, tangent_axis(s, j));
      if ((this->complementarity.holds_contact() && state.dynamic) || friction)
        {
          Vec3<AD> v_rel = v;
          for (unsigned int a = 0; a < 4; ++a)
            v_rel -= N[a] * vp.at(p.faces[face][a]);
          ContactAD::add_to(pair.gap_rate[j],
                            AD(-(v_rel * n_secondary)),
                            unknowns);
          if (friction)
            for (unsigned int a = 0; a < 2; ++a)
              ContactAD::add_to(pair.slip_rate[j][a],
                                AD(v_rel * tangent[a]),
                                unknowns);
        }

      // the nodal force L (lambda n + lambda_t,a t_a) on the secondary node
      // and, with weights N(xi, eta), opposite on the primary face
      const double L = s.reference_weight[j];
      Vec3<AD>     f_t;
      if (friction)
        for (unsigned int a = 0; a < 2; ++a)
          f_t += AD(lambda_t[a] * L) * tangent[a];
      const Vec3<AD> f = AD(lambda * L) * n_secondary + f_t;
      for (unsigned int k = 0; k < 3; ++k)
        {
          forces.add(s.dofs[j][k],
                     f[k].val(),
                     ContactAD::derivatives(f[k], unknowns));
          for (unsigned int a = 0; a < 4; ++a)
            {
              const AD row = -N[a] * f[k];
              forces.add(p.dofs[p.faces[face][a]][k],
                         row.val(),
                         ContactAD::derivatives(row, unknowns));
            }
          if (friction)
            {
              forces.add_tangential(s.dofs[j][k], f_t[k].val());
              for (unsigned int a = 0; a < 4; ++a)
                forces.add_tangential(p.dofs[p.faces[face][a]][k],
                                      -N[a].val() * f_t[k].val());
            }
        }
    });
  }
} // namespace ContactDynamics
