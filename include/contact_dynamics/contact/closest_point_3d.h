// Closest-point projection onto a bilinear quadrilateral face, for 3-D
// node-to-segment contact: the point x(xi, eta) of the face nearest to p,
// where p - x is normal to both tangents. Newton in double precision, then
// one Newton step in the AD number type for the exact derivatives, as the
// other projections (clipping_geometry.h).
#ifndef contact_dynamics_contact_closest_point_3d_h
#define contact_dynamics_contact_closest_point_3d_h

#include <contact_dynamics/contact/clipping_geometry.h>

namespace ContactDynamics
{
  namespace ClippingGeometry
  {
    /**
     * The residual (x - p) . t_xi, (x - p) . t_eta of the closest-point
     * condition and its Jacobian, at (xi, eta).
     */
    template <typename Number>
    void
    closest_point_system(const std::array<Vec3<Number>, 4>    &x,
                         const Vec3<Number>                   &p,
                         const Number                         &xi,
                         const Number                         &eta,
                         std::array<Number, 2>                &r,
                         std::array<std::array<Number, 2>, 2> &J)
    {
      const Vec3<Number> d = interpolate(x, xi, eta) - p;
      const auto         t = tangents(x, xi, eta);
      // the mixed second derivative of a bilinear face; the pure ones
      // vanish
      const Vec3<Number> t_xe = x[0] - x[1] - x[2] + x[3];
      r[0]                    = d * t[0];
      r[1]                    = d * t[1];
      J[0][0]                 = t[0] * t[0];
      J[1][1]                 = t[1] * t[1];
      J[0][1]                 = t[0] * t[1] + d * t_xe;
      J[1][0]                 = J[0][1];
    }

    /**
     * The closest point of the face x to p by Newton from the face's
     * center. False if Newton does not converge (the closest point may
     * then lie far outside the face) or converges to a stationary point
     * that is not a minimum of the distance; the parameters may lie
     * outside [0,1]^2 (the caller decides which face a node belongs to).
     */
    inline bool
    closest_point(const std::array<Vec3<double>, 4> &x,
                  const Vec3<double>                &p,
                  double                            &xi,
                  double                            &eta)
    {
      xi = eta = 0.5;
      for (unsigned int it = 0; it < 50; ++it)
        {
          std::array<double, 2>                r;
          std::array<std::array<double, 2>, 2> J;
          closest_point_system(x, p, xi, eta, r, J);
          const double det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
          if (!(std::abs(det) > 1e-300))
            return false;
          const double dxi  = -(J[1][1] * r[0] - J[0][1] * r[1]) / det;
          const double deta = -(J[0][0] * r[1] - J[1][0] * r[0]) / det;
          xi += dxi;
          eta += deta;
          if (std::abs(xi) > 1e3 || std::abs(eta) > 1e3)
            return false;
          // a minimum of the distance, not a saddle or a maximum: the
          // Hessian J positive definite
          if (std::abs(dxi) + std::abs(deta) <
              1e-14 * (1 + std::abs(xi) + std::abs(eta)))
            return J[0][0] > 0 && det > 0;
        }
      return false;
    }

    /** The converged (xi, eta) with exact derivatives (exact_newton_steps). */
    template <typename Number>
    std::array<Number, 2>
    closest_point_with_derivatives(const std::array<Vec3<Number>, 4> &x,
                                   const Vec3<Number>                &p,
                                   const double                       xi,
                                   const double                       eta)
    {
      std::array<Number, 2> y{{Number(xi), Number(eta)}};
      for (unsigned int step = 0; step < exact_newton_steps<Number>(); ++step)
        {
          std::array<Number, 2>                r;
          std::array<std::array<Number, 2>, 2> J;
          closest_point_system(x, p, y[0], y[1], r, J);
          const Number det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
          y                = {{y[0] - (J[1][1] * r[0] - J[0][1] * r[1]) / det,
                               y[1] - (J[0][0] * r[1] - J[1][0] * r[0]) / det}};
        }
      return y;
    }
  } // namespace ClippingGeometry
} // namespace ContactDynamics

#endif
