// 3-D node-to-segment patches: a secondary node, its closest point on the
// bilinear primary faces (closest_point_3d.h) with the face memory of the
// 2-D code, the gap along the primary normal (optionally blended near the
// face's edges into the normal interpolated from averaged nodal normals,
// continuous across edges and at nodes) and the nodal force with its two
// tangential components. The rules follow node_to_segment_contact.cc.
#include <deal.II/base/exceptions.h>

#include <contact_dynamics/contact/closest_point_3d.h>
#include <contact_dynamics/contact/contact_ad.h>
#include <contact_dynamics/contact/node_projection_3d.h>
#include <contact_dynamics/contact/node_to_segment_contact.h>
#include <contact_dynamics/contact/surface_geometry_3d.h>

#include <algorithm>
#include <cmath>

namespace ContactDynamics
{
  namespace
  {
    using namespace ClippingGeometry;
    using NodeProjection3D::edge_point;
    using NodeProjection3D::projection_edge;

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

    // The closest point to x on edge e of face y (0: xi = 0, 1: xi = 1,
    // 2: eta = 0, 3: eta = 1; the edges of a bilinear face are straight)
    // as the parameter along the edge, not clamped
    template <typename Number>
    Number
    edge_parameter(const std::array<Vec3<Number>, 4> &y,
                   const Vec3<Number>                &x,
                   const unsigned int                 e)
    {
      static constexpr unsigned int ends[4][2] = {{0, 2},
                                                  {1, 3},
                                                  {0, 1},
                                                  {2, 3}};
      const Vec3<Number>            a = y[ends[e][0]], d = y[ends[e][1]] - a;
      return ((x - a) * d) / (d * d);
    }

    // The primary face closest to secondary node j at x and the parameters
    // of the projection on it: the closest point of the face's bilinear
    // surface, which within the tolerance beyond the face's edges extends
    // the face; farther out the closest point on the face's boundary.
    // `previous`: the face of the node's projection in the previous
    // iteration of this attempt, kept while the node stays within the
    // tolerance of it (at a concave kink two faces are equally close, and
    // switching between their normals at every iteration would stall
    // Newton). Faces seen from behind (or degenerate) are skipped.
    unsigned int
    closest_face(const Surface                       &s,
                 const Surface                       &p,
                 const unsigned int                   j,
                 const std::vector<unsigned int>     &candidates,
                 const TrilinosWrappers::MPI::Vector &u,
                 const unsigned int                   previous,
                 std::array<double, 2>               &best_parameters)
    {
      using NodeProjection3D::tolerance;
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
          std::array<double, 2> t;
          const bool            within = closest_point(y, x, t[0], t[1]) &&
                              std::min(t[0], t[1]) >= -tolerance &&
                              std::max(t[0], t[1]) <= 1 + tolerance;
          if (!within)
            {
              double nearest = 1e300;
              for (unsigned int e = 0; e < 4; ++e)
                {
                  const auto q =
                    edge_point(e, std::clamp(edge_parameter(y, x, e), 0., 1.));
                  const double d = norm(x - interpolate(y, q[0], q[1]));
                  if (d < nearest)
                    {
                      nearest = d;
                      t       = q;
                    }
                }
            }
          const double xi_c  = std::clamp(t[0], 0., 1.),
                       eta_c = std::clamp(t[1], 0., 1.);
          if (!(face_normal(y, xi_c, eta_c) * n_s < 0))
            continue;
          if (f == previous && within)
            {
              best_parameters = t;
              return f;
            }
          const double distance = norm(x - interpolate(y, t[0], t[1]));
          if (distance < best_distance)
            {
              best            = f;
              best_distance   = distance;
              best_parameters = t;
            }
        }
      return best;
    }

    // The closest point's parameters with, exact, their derivatives: those
    // of the closest point of the surface or of an edge (none at a corner)
    template <typename AD>
    void
    projection_parameters(const std::array<Vec3<AD>, 4> &y,
                          const Vec3<AD>                &x,
                          const std::array<double, 2>   &parameters,
                          AD                            &xi,
                          AD                            &eta)
    {
      const unsigned int edge = projection_edge(parameters);
      double             xi_free, eta_free;
      if (closest_point(values(y), values(x), xi_free, eta_free) &&
          std::abs(xi_free - parameters[0]) +
              std::abs(eta_free - parameters[1]) <
            1e-12)
        {
          const auto r =
            closest_point_with_derivatives(y, x, xi_free, eta_free);
          xi  = r[0];
          eta = r[1];
        }
      else if (edge < 4)
        {
          const auto q = edge_point(edge, edge_parameter(y, x, edge));
          xi           = q[0];
          eta          = q[1];
        }
    }

    // At the projection (parameters) of x onto the bilinear primary face
    // `face`: the shape functions N, the point x_p and the contact normal
    // (the face's normal, blended near the edges into the interpolated
    // nodal normals), with exact derivatives or the parameters and the
    // normal frozen
    template <typename AD>
    void
    linear_contact_geometry(const Surface               &p,
                            const unsigned int           face,
                            const NodeMap<AD>           &xp,
                            const Vec3<AD>              &x,
                            const std::array<double, 2> &parameters,
                            const bool                   exact,
                            const double                 smoothing,
                            std::vector<AD>             &N,
                            Vec3<AD>                    &x_p,
                            Vec3<AD>                    &normal)
    {
      const auto y = face_nodes(p, face, xp);
      AD         xi(parameters[0]), eta(parameters[1]);
      if (exact)
        projection_parameters(y, x, parameters, xi, eta);
      const auto shape_values = shape(xi, eta);
      normal                  = NodeProjection3D::smoothed_normal(p,
                                                 face,
                                                 shape_values,
                                                 xp,
                                                 xi,
                                                 eta,
                                                 smoothing,
                                                 exact,
                                                 face_normal(y, xi, eta));
      N.assign(shape_values.begin(), shape_values.end());
      x_p = interpolate(y, xi, eta);
    }

    // A node's projection: the face (invalid: none), the parameters on it
    // and whether they solve the face's closest-point system (degree 2)
    struct Projection
    {
      unsigned int          face = Surface::invalid;
      std::array<double, 2> parameters{};
      bool                  on_surface = false;
    };

    Projection
    project(const Surface                       &s,
            const Surface                       &p,
            const unsigned int                   j,
            const std::vector<unsigned int>     &candidates,
            const TrilinosWrappers::MPI::Vector &u,
            const unsigned int                   previous)
    {
      Projection r;
      r.face = p.degree == 2 ?
                 NodeProjection3D::Quadratic::closest_face(s,
                                                           p,
                                                           j,
                                                           candidates,
                                                           u,
                                                           previous,
                                                           r.parameters,
                                                           r.on_surface) :
                 closest_face(s, p, j, candidates, u, previous, r.parameters);
      return r;
    }

    // N, x_p and the contact normal at the projection, of either degree
    template <typename AD>
    void
    geometry(const Surface     &p,
             const Projection  &projection,
             const NodeMap<AD> &xp,
             const Vec3<AD>    &x,
             const bool         exact,
             const double       smoothing,
             std::vector<AD>   &N,
             Vec3<AD>          &x_p,
             Vec3<AD>          &normal)
    {
      if (p.degree == 2)
        NodeProjection3D::Quadratic::contact_geometry(p,
                                                      projection.face,
                                                      xp,
                                                      x,
                                                      projection.parameters,
                                                      projection.on_surface,
                                                      exact,
                                                      smoothing,
                                                      N,
                                                      x_p,
                                                      normal);
      else
        linear_contact_geometry(p,
                                projection.face,
                                xp,
                                x,
                                projection.parameters,
                                exact,
                                smoothing,
                                N,
                                x_p,
                                normal);
    }

    // The nodal force f (tangential part f_t) on secondary node j and,
    // with weights N (of the face's nodes), opposite on the primary face
    template <typename AD, typename PatchForces>
    void
    add_nodal_force(const Surface                              &s,
                    const Surface                              &p,
                    const unsigned int                          j,
                    const unsigned int                          face,
                    const std::vector<AD>                      &N,
                    const Vec3<AD>                             &f,
                    const Vec3<AD>                             &f_t,
                    const bool                                  friction,
                    const std::vector<types::global_dof_index> &unknowns,
                    PatchForces                                &forces)
    {
      const auto &nodes = p.face_nodes[face];
      for (unsigned int k = 0; k < 3; ++k)
        {
          forces.add(s.dofs[j][k],
                     f[k].val(),
                     ContactAD::derivatives(f[k], unknowns));
          for (unsigned int a = 0; a < N.size(); ++a)
            {
              const AD row = -N[a] * f[k];
              forces.add(p.dofs[nodes[a]][k],
                         row.val(),
                         ContactAD::derivatives(row, unknowns));
            }
          if (friction)
            {
              forces.add_tangential(s.dofs[j][k], f_t[k].val());
              for (unsigned int a = 0; a < N.size(); ++a)
                forces.add_tangential(p.dofs[nodes[a]][k],
                                      -N[a].val() * f_t[k].val());
            }
        }
    }
  } // namespace



  template <>
  double
  NodeToSegmentContact<3>::traction_per_multiplier(const PairData    &pair,
                                                   const unsigned int node,
                                                   const VectorType  &u) const
  {
    // the change of the area around the node: a quarter of each face's
    // area (half the cross product of its diagonals), now and in the
    // reference configuration (reference_weight is integral N_j, which
    // differs from that on faces that are not parallelograms)
    const auto &surface = pair.secondary;
    if (surface.degree == 2)
      return surface.reference_weight[node] / surface.current_weight(node, u);
    double current = 0, reference = 0;
    for (const unsigned int face : surface.node_faces[node])
      {
        const auto &f       = surface.faces[face];
        const auto  quarter = [&](const auto &x) {
          return cross_product_3d(x(3) - x(0), x(2) - x(1)).norm() / 8;
        };
        current += quarter([&](const unsigned int a) {
          return surface.position(f[a], u);
        });
        reference += quarter([&](const unsigned int a) {
          return surface.reference[f[a]];
        });
      }
    return current > 0 ? reference / current : 1.;
  }

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
    const Projection projection =
      project(s, p, j, pair.candidates[j], state.u, current[j]);
    const unsigned int face = projection.face;
    current[j]              = face;
    if (face == Surface::invalid)
      return; // no projection: the node is inactive

    // the patch reads the projection's face only (and, for the smoothed
    // normal, the faces around its nodes)
    const std::vector<unsigned int> faces{face};
    const auto                      unknowns = patch_unknowns(pair, j, faces);
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

      std::vector<AD> N;
      Vec3<AD>        x_p, normal;
      geometry(p, projection, xp, x, exact, smoothing_distance, N, x_p, normal);
      const AD g = (x - x_p) * normal;
      ContactAD::add_to(pair.gap[j], g, unknowns);
      pair.weight[j].value += 1.;

      // the secondary side's normal and tangents
      const Vec3<AD>          n_secondary = -normal;
      const bool              friction    = pair.friction_coefficient > 0;
      std::array<Vec3<AD>, 2> tangent;
      if (friction)
        {
          std::array<double, 3> n;
          for (unsigned int d = 0; d < 3; ++d)
            n[d] = value_of(n_secondary[d]);
          tangent = tangent_basis(
            n_secondary,
            face_memory.tangent_axis(pair.index, j, s.n_nodes(), n));
        }
      if ((this->complementarity.holds_contact() && state.dynamic) || friction)
        {
          Vec3<AD> v_rel = v;
          for (unsigned int a = 0; a < N.size(); ++a)
            v_rel -= N[a] * vp.at(p.face_nodes[face][a]);
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
      add_nodal_force(s, p, j, face, N, f, f_t, friction, unknowns, forces);
    });
  }
} // namespace ContactDynamics
