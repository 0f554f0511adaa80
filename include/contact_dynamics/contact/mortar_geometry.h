// Geometry of 2-D dual mortar contact on linear faces: the dual basis and
// the projections that bound mortar segments, templated on the number type
// like the shared face geometry (segment_geometry.h) they build on.
#ifndef contact_dynamics_contact_mortar_geometry_h
#define contact_dynamics_contact_mortar_geometry_h

#include <contact_dynamics/contact/segment_geometry.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

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

    // the value of a double or of an AD number
    inline double
    value_of(const double x)
    {
      return x;
    }

    template <typename Number>
    double
    value_of(const Number &x)
    {
      return value_of(x.val()); // (nested AD numbers too)
    }

    /**
     * Coefficients a_jk of the dual basis psi_j = a_j0 N_0 + a_j1 N_1 of a
     * face of which only the segments [lo, hi] (in xi) are covered:
     * A = D M^-1 with D_jj = integral N_j and M_jk = integral N_j N_k over
     * the covered segments, so that integral(psi_j N_k) = delta_jk
     * integral(N_k) holds on what is integrated (Popp, Wohlmuth, Gee, Wall,
     * SIAM J Sci Comput 34 (2012); CMAME 264 (2013)); sum_j psi_j = 1 still.
     * The length of the face scales D and M alike and cancels. A face
     * covered without gaps or overlaps gets the closed form of dual_shape()
     * exactly. M is singular when nothing is covered; its condition number
     * is about 12 / c^2 for a covered fraction c at one end.
     */
    template <typename Number>
    std::array<std::array<Number, 2>, 2>
    dual_coefficients(const std::vector<std::pair<Number, Number>> &segments)
    {
      std::vector<std::pair<double, double>> bounds;
      for (const auto &s : segments)
        bounds.emplace_back(value_of(s.first), value_of(s.second));
      std::sort(bounds.begin(), bounds.end());
      bool full = !bounds.empty() && bounds.front().first == -1. &&
                  bounds.back().second == 1.;
      for (unsigned int i = 0; full && i + 1 < bounds.size(); ++i)
        full = std::abs(bounds[i].second - bounds[i + 1].first) < 1e-14;
      if (full)
        return {{{{Number(2.), Number(-1.)}}, {{Number(-1.), Number(2.)}}}};

      // two Gauss points per segment integrate the products exactly
      Number       D[2] = {0., 0.}, M[2][2] = {{0., 0.}, {0., 0.}};
      const double gauss = 1. / std::sqrt(3.);
      for (const auto &s : segments)
        for (const double q : {-gauss, gauss})
          {
            const Number xi =
              (s.first + s.second) / 2. + (s.second - s.first) / 2. * q;
            const Number w = (s.second - s.first) / 2.;
            const auto   N = SegmentGeometry::shape(xi);
            for (unsigned int j = 0; j < 2; ++j)
              {
                D[j] += w * N[j];
                for (unsigned int k = 0; k < 2; ++k)
                  M[j][k] += w * N[j] * N[k];
              }
          }
      const Number det = M[0][0] * M[1][1] - M[0][1] * M[1][0];
      return {{{{D[0] * M[1][1] / det, -D[0] * M[0][1] / det}},
               {{-D[1] * M[1][0] / det, D[1] * M[0][0] / det}}}};
    }

    /** The dual functions at xi for the coefficients a of dual_coefficients. */
    template <typename Number>
    std::array<Number, 2>
    dual_shape(const Number &xi, const std::array<std::array<Number, 2>, 2> &a)
    {
      const auto N = SegmentGeometry::shape(xi);
      return {
        {a[0][0] * N[0] + a[0][1] * N[1], a[1][0] * N[0] + a[1][1] * N[1]}};
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
