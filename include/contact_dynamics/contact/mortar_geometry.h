// Geometry of 2-D dual mortar contact on linear faces, templated on the
// number type so that the same code yields values (double) and exact
// derivatives (Sacado AD numbers).
//
// A face runs from node 0 to node 1, parametrized by xi in [-1, 1] with
// N_0 = (1 - xi)/2, N_1 = (1 + xi)/2; its outward normal is the tangent
// x_1 - x_0 turned clockwise.
#ifndef contact_dynamics_contact_mortar_geometry_h
#define contact_dynamics_contact_mortar_geometry_h

#include <deal.II/base/tensor.h>

#include <array>
#include <cmath>

namespace ContactDynamics
{
  namespace MortarGeometry
  {
    using dealii::Tensor;

    template <typename Number>
    using Vec = Tensor<1, 2, Number>;

    template <typename Number>
    Number
    cross(const Vec<Number> &a, const Vec<Number> &b)
    {
      return a[0] * b[1] - a[1] * b[0];
    }

    template <typename Number>
    Number
    norm(const Vec<Number> &a)
    {
      using std::sqrt;
      return sqrt(a[0] * a[0] + a[1] * a[1]);
    }

    /** Linear shape functions N_0, N_1 of a face at xi. */
    template <typename Number>
    std::array<Number, 2>
    shape(const Number &xi)
    {
      return {{(1. - xi) / 2., (1. + xi) / 2.}};
    }

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

    /** The vector turned counterclockwise by 90 degrees (a tangent). */
    template <typename Number>
    Vec<Number>
    rotate(const Vec<Number> &n)
    {
      Vec<Number> t;
      t[0] = -n[1];
      t[1] = n[0];
      return t;
    }

    /** Unit outward normal of the face x0 -> x1. */
    template <typename Number>
    Vec<Number>
    face_normal(const Vec<Number> &x0, const Vec<Number> &x1)
    {
      Vec<Number> n;
      n[0] = x1[1] - x0[1];
      n[1] = -(x1[0] - x0[0]);
      return n / norm(n);
    }

    template <typename Number>
    Vec<Number>
    interpolate(const Vec<Number> &a, const Vec<Number> &b, const Number &xi)
    {
      const auto N = shape(xi);
      return N[0] * a + N[1] * b;
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
