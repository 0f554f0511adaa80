// Geometry of 2-D dual mortar contact on linear faces: the dual basis and
// the projections that bound mortar segments, templated on the number type
// like the shared face geometry (segment_geometry.h) they build on.
#ifndef contact_dynamics_contact_mortar_geometry_h
#define contact_dynamics_contact_mortar_geometry_h

#include <contact_dynamics/contact/segment_geometry.h>

#include <array>
#include <cmath>

namespace ContactDynamics
{
  namespace MortarGeometry
  {
    using SegmentGeometry::cross;
    using SegmentGeometry::interpolate;
    using SegmentGeometry::Vec;

    /**
     * Dual shape functions of a linear face, biorthogonal to N:
     * integral(psi_i N_j) = delta_ij integral(N_j). On a straight face the
     * coefficients D A^-1 (A_ij = integral N_i N_j, D_ii = integral N_i) do
     * not depend on the length: psi_0 = 2 N_0 - N_1, psi_1 = 2 N_1 - N_0.
     */
    template <typename Number>
    std::array<Number, 2>
    dual_shape(const Number &xi)
    {
      return {{(1. - 3. * xi) / 2., (1. + 3. * xi) / 2.}};
    }

    /**
     * The parameter xi on the secondary face (x0, x1) with nodal normals
     * (n0, n1) whose interpolated normal line passes through the point p:
     * cross(x(xi) - p, n(xi)) = 0, a quadratic in xi, solved by Newton in
     * double precision. Returns false if there is no solution near the
     * face.
     */
    inline bool
    project_along_normal_field(const Vec<double> &x0,
                               const Vec<double> &x1,
                               const Vec<double> &n0,
                               const Vec<double> &n1,
                               const Vec<double> &p,
                               double            &xi)
    {
      xi = 0;
      for (unsigned int it = 0; it < 30; ++it)
        {
          const Vec<double> x = interpolate(x0, x1, xi);
          const Vec<double> n = interpolate(n0, n1, xi);
          const double      F = cross(Vec<double>(x - p), n);
          const double      dF =
            cross(Vec<double>((x1 - x0) / 2.), n) +
            cross(Vec<double>(x - p), Vec<double>((n1 - n0) / 2.));
          if (std::abs(dF) < 1e-300)
            return false;
          const double step = F / dF;
          xi -= step;
          if (std::abs(xi) > 1e3)
            return false;
          // relative: far projections (|xi| > 1) stagnate at round-off
          if (std::abs(step) < 1e-13 * (1 + std::abs(xi)))
            return true;
        }
      return false;
    }

    /**
     * The same projection with derivatives: one Newton step in the number
     * type from the converged double value xi gives the exact derivatives
     * of xi (implicit function theorem) and leaves its value unchanged.
     */
    template <typename Number>
    Number
    project_along_normal_field(const Vec<Number> &x0,
                               const Vec<Number> &x1,
                               const Vec<Number> &n0,
                               const Vec<Number> &n1,
                               const Vec<Number> &p,
                               const double       xi)
    {
      const Number      xi_n = xi;
      const Vec<Number> x    = interpolate(x0, x1, xi_n);
      const Vec<Number> n    = interpolate(n0, n1, xi_n);
      const Number      F    = cross(Vec<Number>(x - p), n);
      const Number      dF   = cross(Vec<Number>((x1 - x0) / 2.), n) +
                        cross(Vec<Number>(x - p), Vec<Number>((n1 - n0) / 2.));
      return xi_n - F / dF;
    }

    /**
     * The parameter eta on the primary face (y0, y1) hit by the line
     * through x with direction n (closed form for a straight face).
     */
    template <typename Number>
    Number
    intersect_line_with_face(const Vec<Number> &x,
                             const Vec<Number> &n,
                             const Vec<Number> &y0,
                             const Vec<Number> &y1)
    {
      const Vec<Number> m = (y0 + y1) / 2.;
      const Vec<Number> t = (y1 - y0) / 2.;
      return cross(Vec<Number>(x - m), n) / cross(t, n);
    }
  } // namespace MortarGeometry
} // namespace ContactDynamics

#endif
