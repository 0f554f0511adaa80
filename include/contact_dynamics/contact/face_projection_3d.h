// Quadrature on triangles and the projection of points onto a bilinear
// face along a direction, with derivatives (clipping_geometry.h).
#ifndef contact_dynamics_contact_face_projection_3d_h
#define contact_dynamics_contact_face_projection_3d_h

#include <contact_dynamics/contact/auxiliary_plane.h>

namespace ContactDynamics
{
  namespace ClippingGeometry
  {
    /** Barycentric coordinates and weights (summing to 1) on a triangle. */
    using TriangleRule = std::vector<std::pair<std::array<double, 3>, double>>;

    /**
     * The Witherden-Vincent rule on a triangle with n_points_1d "points per
     * direction" (1 to 7; 1, 6, 7, 15, 19, 28, 37 points), exact for
     * polynomials of degree 2 n_points_1d - 1 (the 6-point rule of 2 is
     * Dunavant's, of degree 4). Multiply the weights by the triangle's area.
     */
    const TriangleRule &
    triangle_rule(const unsigned int n_points_1d = 2);

    /**
     * The parameters (xi, eta) of the face x and the distance alpha along
     * the unit direction n with x(xi, eta) = p + alpha n, by Newton in
     * double precision. False if Newton does not converge or the direction
     * is parallel to the face.
     */
    inline bool
    project_along_direction(const std::array<Vec3<double>, 4> &x,
                            const Vec3<double>                &p,
                            const Vec3<double>                &n,
                            double                            &xi,
                            double                            &eta,
                            double                            &alpha)
    {
      xi = eta    = 0.5;
      alpha       = 0;
      double step = 1;
      for (unsigned int it = 0; it < 30; ++it)
        {
          const Vec3<double> r = interpolate(x, xi, eta) - p - alpha * n;
          const auto         t = tangents(x, xi, eta);
          // J = [t0 t1 -n]: solve J dx = -r by Cramer's rule
          const double det = cross(t[0], t[1]) * (-n);
          if (std::abs(det) < 1e-300)
            return false;
          const double dxi    = -(cross(r, t[1]) * (-n)) / det;
          const double deta   = -(cross(t[0], r) * (-n)) / det;
          const double dalpha = -(cross(t[0], t[1]) * r) / det;
          xi += dxi;
          eta += deta;
          alpha += dalpha;
          if (std::abs(xi) > 1e3 || std::abs(eta) > 1e3)
            return false;
          step = (std::abs(dxi) + std::abs(deta)) /
                 (1 + std::abs(xi) + std::abs(eta));
          if (step < 1e-14)
            return true;
        }
      // on small faces far from the origin the steps can stall at the
      // round-off of the coordinates, above 1e-14
      return step < 1e-10;
    }

    /**
     * Newton steps in the number type, from a converged value, that give
     * exact derivatives up to the number's order: the error of the
     * derivatives' Taylor expansion squares with every step (one step is
     * exact to first order, two to third).
     */
    template <typename Number>
    constexpr unsigned int
    exact_newton_steps()
    {
      return derivative_order<Number>() <= 1 ? 1 : 2;
    }

    /**
     * Subtracts J^-1 r from y, with the Jacobian J of the projection
     * residual r = x(xi, eta) - p - alpha n frozen at the converged point
     * (xi, eta) in double precision: a chord step.
     */
    template <typename Number>
    void
    frozen_newton_step(const std::array<Vec3<Number>, 4> &x,
                       const Vec3<Number>                &n,
                       const double                       xi,
                       const double                       eta,
                       const Vec3<Number>                &r,
                       std::array<Number, 3>             &y)
    {
      const Vec3<double> m       = -values(n);
      const auto         t       = tangents(values(x), xi, eta);
      const double       det     = cross(t[0], t[1]) * m;
      const Vec3<double> rows[3] = {cross(t[1], m),
                                    cross(m, t[0]),
                                    cross(t[0], t[1])};
      for (unsigned int d = 0; d < 3; ++d)
        for (unsigned int k = 0; k < 3; ++k)
          y[k] -= (rows[k][d] / det) * r[d];
    }

    /**
     * The same projection with derivatives: from the converged values,
     * Newton steps in the number type give the exact derivatives (implicit
     * function theorem) and leave the values unchanged. First order: one
     * chord step (frozen_newton_step()), whose residual is linear in the
     * AD inputs (a sixth of the operations of a full step, which dominated
     * the 3-D mortar's cost). Second order: a full step (error O(dx^2)),
     * then a chord step (the frozen Jacobian is off by O(dx), so the error
     * becomes O(dx^3)): exact to second order at about 60 % of the cost of
     * two full steps. In double, one full step.
     */
    template <typename Number>
    std::array<Number, 3>
    projection_with_derivatives(const std::array<Vec3<Number>, 4> &x,
                                const Vec3<Number>                &p,
                                const Vec3<Number>                &n,
                                const double                       xi,
                                const double                       eta,
                                const double                       alpha)
    {
      std::array<Number, 3> y{{Number(xi), Number(eta), Number(alpha)}};
      if constexpr (derivative_order<Number>() == 1)
        {
          const auto   N = shape(xi, eta);
          Vec3<Number> r;
          for (unsigned int d = 0; d < 3; ++d)
            r[d] = N[0] * x[0][d] + N[1] * x[1][d] + N[2] * x[2][d] +
                   N[3] * x[3][d] - p[d] - alpha * n[d];
          frozen_newton_step(x, n, xi, eta, r, y);
          return y;
        }
      static_assert(derivative_order<Number>() <= 2,
                    "exact to second order only");
      const Vec3<Number> m   = -n;
      const Vec3<Number> r   = interpolate(x, y[0], y[1]) - p - y[2] * n;
      const auto         t   = tangents(x, y[0], y[1]);
      const Number       det = cross(t[0], t[1]) * m;
      y                      = {{y[0] - (cross(r, t[1]) * m) / det,
                                 y[1] - (cross(t[0], r) * m) / det,
                                 y[2] - (cross(t[0], t[1]) * r) / det}};
      if constexpr (derivative_order<Number>() == 2)
        {
          const Vec3<Number> r1 = interpolate(x, y[0], y[1]) - p - y[2] * n;
          frozen_newton_step(x, n, xi, eta, r1, y);
        }
      return y;
    }
  } // namespace ClippingGeometry
} // namespace ContactDynamics

#endif
