// Closest points of 3-D node-to-segment contact: the edges of a primary
// face (shared by faces of degree 1 and 2), and the projection onto the
// curved 9-node faces of degree 2: Newton on the closest-point system of
// quadratic_segment_3d.h in double, within a tolerance beyond the face's
// edges on the face's extension, farther out the closest point of its
// (curved) boundary; exact derivatives by one Newton step in AD numbers.
#ifndef contact_dynamics_contact_node_projection_3d_h
#define contact_dynamics_contact_node_projection_3d_h

#include <contact_dynamics/contact/quadratic_segment_3d.h>
#include <contact_dynamics/contact/surface_geometry_3d.h>

#include <algorithm>
#include <array>
#include <vector>

namespace ContactDynamics
{
  namespace NodeProjection3D
  {
    using ClippingGeometry::NodeMap;
    using ClippingGeometry::norm;
    using ClippingGeometry::Surface;
    using ClippingGeometry::Vec3;

    // (1e-2 of the half-face in 2-D, as a fraction of the face)
    constexpr double tolerance = 5e-3;

    /**
     * The face parameters of the point at parameter t along edge e (0: xi
     * = 0, 1: xi = 1, 2: eta = 0, 3: eta = 1).
     */
    template <typename Number>
    std::array<Number, 2>
    edge_point(const unsigned int e, const Number &t)
    {
      const Number end(e % 2 ? 1. : 0.);
      return e < 2 ? std::array<Number, 2>{{end, t}} :
                     std::array<Number, 2>{{t, end}};
    }

    /**
     * The edge a point with parameters outside the face was projected onto
     * (edge_point()), or 4 at a corner or inside.
     */
    inline unsigned int
    projection_edge(const std::array<double, 2> &parameters)
    {
      const auto on_end = [](const double t) {
        return t == 0. || t == 1.;
      };
      const auto inside = [](const double t) {
        return t > 0. && t < 1.;
      };
      if (on_end(parameters[0]) && inside(parameters[1]))
        return parameters[0] == 0. ? 0 : 1;
      if (on_end(parameters[1]) && inside(parameters[0]))
        return parameters[1] == 0. ? 2 : 3;
      return 4;
    }

    /**
     * The weight of the smoothed normal at a face parameter s: 1 at and
     * beyond the face's ends, 0 farther than `distance` from them (linear).
     */
    template <typename Number>
    Number
    end_weight(const Number &s, const double distance)
    {
      const Number to_end = s.val() <= 0.5 ? s : Number(1. - s);
      if (to_end.val() >= distance)
        return Number(0.);
      if (to_end.val() <= 0)
        return Number(1.);
      return Number((distance - to_end) / distance);
    }

    /**
     * The contact normal of primary face f near its edges: the face's
     * unit normal blended within `smoothing` of them into the nodal
     * normals interpolated with the face's shape functions N (of its
     * nodes, in the order of face_nodes); frozen (no derivatives) unless
     * `exact`.
     */
    template <typename AD, typename Weights>
    Vec3<AD>
    smoothed_normal(const Surface     &p,
                    const unsigned int f,
                    const Weights     &N,
                    const NodeMap<AD> &xp,
                    const AD          &xi,
                    const AD          &eta,
                    const double       smoothing,
                    const bool         exact,
                    Vec3<AD>           normal)
    {
      if (smoothing > 0)
        {
          Vec3<AD> interpolated;
          for (unsigned int a = 0; a < N.size(); ++a)
            interpolated +=
              N[a] * ClippingGeometry::nodal_normal(p, p.face_nodes[f][a], xp);
          const AD w_xi  = end_weight(xi, smoothing),
                   w_eta = end_weight(eta, smoothing);
          const AD w     = 1. - (1. - w_xi) * (1. - w_eta);
          normal += w * (interpolated / norm(interpolated) - normal);
          normal /= norm(normal);
        }
      if (!exact)
        for (unsigned int d = 0; d < 3; ++d)
          normal[d] = AD(normal[d].val());
      return normal;
    }

    namespace Quadratic
    {
      using namespace QuadraticSegment3D;

      template <typename Number>
      Face<Number>
      face(const Surface &p, const unsigned int f, const NodeMap<Number> &x)
      {
        Face<Number> y;
        for (unsigned int a = 0; a < 9; ++a)
          y[a] = x.at(p.face_nodes[f][a]);
        return y;
      }

      template <typename Number>
      Vec3<Number>
      unit_normal(const Face<Number> &y, const Shape<Number> &s)
      {
        const Vec3<Number> n = cross(combine(y, s.dN[0]), combine(y, s.dN[1]));
        return n / norm(n);
      }

      // r = (y(t) - x) . y'(t) along edge e and dr/dt
      template <typename Number>
      void
      edge_residual(const Face<Number> &y,
                    const Vec3<Number> &x,
                    const unsigned int  e,
                    const Number       &t,
                    Number             &r,
                    Number             &dr)
      {
        const auto         q = edge_point(e, t);
        const auto         s = shape(q[0], q[1]);
        const unsigned int k = e < 2 ? 1 : 0; // the direction along it
        const Vec3<Number> d = combine(y, s.N) - x, t1 = combine(y, s.dN[k]),
                           t2 = combine(y, s.d2N[2 * k]);
        r                     = d * t1;
        dr                    = t1 * t1 + d * t2;
      }

      // the closest point to x on edge e, its parameter in [0, 1]
      inline double
      edge_closest(const Face<double> &y,
                   const Vec3<double> &x,
                   const unsigned int  e)
      {
        double best = 0, nearest = 1e300;
        for (unsigned int k = 0; k <= 8; ++k)
          {
            const auto   q = edge_point(e, k / 8.);
            const double d = norm(x - combine(y, shape(q[0], q[1]).N));
            if (d < nearest)
              {
                nearest = d;
                best    = k / 8.;
              }
          }
        for (unsigned int it = 0; it < 30; ++it)
          {
            double r, dr;
            edge_residual(y, x, e, best, r, dr);
            if (!(dr > 0))
              break;
            const double next = std::clamp(best - r / dr, 0., 1.);
            const bool   done = std::abs(next - best) < 1e-14;
            best              = next;
            if (done)
              break;
          }
        return best;
      }

      /**
       * The primary face of degree 2 closest to secondary node j at x and
       * the parameters of the projection on it; `on_surface`: found by the
       * face's closest-point system (not on its boundary). `previous` and
       * faces seen from behind as for faces of degree 1.
       */
      inline unsigned int
      closest_face(const Surface                       &s,
                   const Surface                       &p,
                   const unsigned int                   j,
                   const std::vector<unsigned int>     &candidates,
                   const TrilinosWrappers::MPI::Vector &u,
                   const unsigned int                   previous,
                   std::array<double, 2>               &best_parameters,
                   bool                                &on_surface)
      {
        const auto position = [&](const Surface &surface, const unsigned k) {
          const auto   x = surface.position(k, u);
          Vec3<double> v;
          for (unsigned int d = 0; d < 3; ++d)
            v[d] = x[d];
          return v;
        };
        const Vec3<double> x = position(s, j);
        NodeMap<double>    xs;
        for (const unsigned int f : s.node_faces[j])
          for (const unsigned int k : s.face_nodes[f])
            xs[k] = position(s, k);
        const Vec3<double> n_s = ClippingGeometry::nodal_normal(s, j, xs);

        unsigned int best          = Surface::invalid;
        double       best_distance = 1e300;
        // the previous face's distance, size, parameters and `within`
        std::array<double, 5> kept{{1e300, 0., 0., 0., 0.}};
        for (const unsigned int f : candidates)
          {
            Face<double> y;
            for (unsigned int a = 0; a < 9; ++a)
              y[a] = position(p, p.face_nodes[f][a]);
            std::array<double, 2> t      = affine_guess(y, x);
            const bool            within = newton<2>(
                                  [&](const auto &z, auto &r, auto &J) {
                                    closest_point_system(y, x, z, r, J);
                                  },
                                  t,
                                  0.5) &&
                                std::min(t[0], t[1]) >= -tolerance &&
                                std::max(t[0], t[1]) <= 1 + tolerance;
            if (!within)
              {
                double nearest = 1e300;
                for (unsigned int e = 0; e < 4; ++e)
                  {
                    const auto   q = edge_point(e, edge_closest(y, x, e));
                    const double d = norm(x - combine(y, shape(q[0], q[1]).N));
                    if (d < nearest)
                      {
                        nearest = d;
                        t       = q;
                      }
                  }
              }
            const auto n = unit_normal(y,
                                       shape(std::clamp(t[0], 0., 1.),
                                             std::clamp(t[1], 0., 1.)));
            if (!(n * n_s < 0))
              continue;
            if (f == previous && within)
              {
                best_parameters = t;
                on_surface      = true;
                return f;
              }
            const double distance = norm(x - combine(y, shape(t[0], t[1]).N));
            if (f == previous)
              kept = {
                {distance, norm(y[3] - y[0]), t[0], t[1], within ? 1. : 0.}};
            if (distance < best_distance)
              {
                best            = f;
                best_distance   = distance;
                best_parameters = t;
                on_surface      = within;
              }
          }
        // beyond the surface's boundary, at a corner two faces share, their
        // closest points nearly coincide, and switching between their
        // normals at every iteration stalled Newton (a 2-cycle on the 3-D
        // bouncing block): the previous face is kept while it is within the
        // tolerance of the closest
        if (kept[0] <= best_distance + tolerance * kept[1])
          {
            best_parameters = {{kept[2], kept[3]}};
            on_surface      = kept[4] != 0;
            return previous;
          }
        return best;
      }

      /**
       * At the projection (parameters) of x onto primary face `f` of
       * degree 2: the shape functions N, the point x_p and the contact
       * normal (the face's unit normal, blended within `smoothing` of its
       * edges into the nodal normals interpolated with N), with exact
       * derivatives, or with the parameters and the normal frozen.
       */
      template <typename AD>
      void
      contact_geometry(const Surface               &p,
                       const unsigned int           f,
                       const NodeMap<AD>           &xp,
                       const Vec3<AD>              &x,
                       const std::array<double, 2> &parameters,
                       const bool                   on_surface,
                       const bool                   exact,
                       const double                 smoothing,
                       std::vector<AD>             &N,
                       Vec3<AD>                    &x_p,
                       Vec3<AD>                    &normal)
      {
        const Face<AD>     y    = face(p, f, xp);
        std::array<AD, 2>  q    = {{AD(parameters[0]), AD(parameters[1])}};
        const unsigned int edge = projection_edge(parameters);
        if (exact && on_surface)
          q = refine<AD, 2>(
            [&](const auto &z, auto &r, auto &J) {
              closest_point_system(y, x, z, r, J);
            },
            parameters);
        else if (exact && edge < 4)
          {
            // one Newton step in AD numbers from the converged parameter
            const AD t0(parameters[edge < 2 ? 1 : 0]);
            AD       r, dr;
            edge_residual(y, x, edge, t0, r, dr);
            q = edge_point(edge, AD(t0 - r / dr.val()));
          }
        const auto s = shape(q[0], q[1]);
        N.assign(s.N.begin(), s.N.end());
        x_p    = combine(y, s.N);
        normal = smoothed_normal(p,
                                 f,
                                 s.N,
                                 xp,
                                 q[0],
                                 q[1],
                                 smoothing,
                                 exact,
                                 unit_normal(y, s));
      }
    } // namespace Quadratic
  }   // namespace NodeProjection3D
} // namespace ContactDynamics

#endif
