// The 3-node curves of 2-D faces of degree 2 (nodes at xi = -1, 1, 0, as
// QuadraticFace::line_shape), templated on the number type: points,
// normals and the Newton projections the contact formulations need, with
// exact derivatives in AD numbers.
#ifndef contact_dynamics_contact_quadratic_curve_h
#define contact_dynamics_contact_quadratic_curve_h

#include <contact_dynamics/contact/mortar_geometry.h>
#include <contact_dynamics/contact/quadratic_face.h>

#include <array>
#include <cmath>
#include <map>
#include <type_traits>
#include <vector>

namespace ContactDynamics
{
  namespace QuadraticCurve
  {
    using MortarGeometry::value_of;
    using SegmentGeometry::cross;
    using SegmentGeometry::Vec;

    template <typename Number>
    using Curve = std::array<Vec<Number>, 3>;

    // node a of a 3-node curve sits at xi = -1, 1, 0
    constexpr double node_xi[3] = {-1., 1., 0.};

    template <typename Number, typename Coefficient>
    Vec<Number>
    combine(const Curve<Number> &x, const std::array<Coefficient, 3> &N)
    {
      // (by component: no temporary AD numbers, which dominated the
      // second derivatives' cost)
      Vec<Number> y;
      for (unsigned int d = 0; d < 2; ++d)
        y[d] = N[0] * x[0][d] + N[1] * x[1][d] + N[2] * x[2][d];
      return y;
    }

    template <typename Number>
    Vec<double>
    values(const Vec<Number> &x)
    {
      return Vec<double>({value_of(x[0]), value_of(x[1])});
    }

    template <typename Number>
    Curve<double>
    values(const Curve<Number> &x)
    {
      return {{values(x[0]), values(x[1]), values(x[2])}};
    }

    /** Unit outward normal of the curve at xi: the tangent turned clockwise. */
    template <typename Number, typename Xi>
    Vec<Number>
    curve_normal(const Curve<Number> &x, const Xi &xi)
    {
      const Vec<Number> t =
        combine(x, QuadraticFace::line_shape_derivative(xi));
      Vec<Number> n;
      n[0] = t[1];
      n[1] = -t[0];
      return n / SegmentGeometry::norm(n);
    }

    /**
     * Newton on a scalar equation residual(xi) = {F, dF/dxi} from the start
     * xi: false if the derivative vanishes or xi runs off (|xi| > 1e3);
     * converged when a step is below `tolerance` (1 + |xi|). `derivative`:
     * dF/dxi at the last iterate.
     */
    template <typename Residual>
    bool
    newton(const Residual &residual,
           double         &xi,
           const double    tolerance,
           double         &derivative)
    {
      for (unsigned int it = 0; it < 30; ++it)
        {
          const auto [F, dF] = residual(xi);
          derivative         = dF;
          if (std::abs(dF) < 1e-300)
            return false;
          const double step = F / dF;
          xi -= step;
          if (std::abs(xi) > 1e3)
            return false;
          if (std::abs(step) < tolerance * (1 + std::abs(xi)))
            return true;
        }
      return false;
    }

    /**
     * The solution with derivatives: two Newton steps in Number from the
     * converged xi (the first gives exact first derivatives, the second
     * exact second derivatives; the value does not change).
     */
    template <typename Number, typename Residual>
    Number
    newton_derivatives(const Residual &residual, const double xi)
    {
      Number result(xi);
      for (unsigned int step = 0; step < 2; ++step)
        {
          const auto [F, dF] = residual(result);
          result -= F / dF;
        }
      return result;
    }

    /** cross(x(xi) - p, n(xi)) and its derivative in xi. */
    template <typename Number, typename Xi>
    std::array<Number, 2>
    normal_line_residual(const Curve<Number> &x,
                         const Curve<Number> &n,
                         const Vec<Number>   &p,
                         const Xi            &xi)
    {
      const auto        N  = QuadraticFace::line_shape(xi);
      const auto        dN = QuadraticFace::line_shape_derivative(xi);
      const Vec<Number> d  = combine(x, N) - p;
      return {
        {cross(d, combine(n, N)),
         cross(combine(x, dN), combine(n, N)) + cross(d, combine(n, dN))}};
    }

    /**
     * The xi on the curve x with nodal normals n whose interpolated normal
     * line passes through p: cross(x(xi) - p, n(xi)) = 0. `xi` comes in as
     * the start (the chord's solution).
     */
    inline bool
    project_onto_curve(const Curve<double> &x,
                       const Curve<double> &n,
                       const Vec<double>   &p,
                       double              &xi)
    {
      double derivative;
      return newton(
        [&](const double s) {
          return normal_line_residual(x, n, p, s);
        },
        xi,
        1e-13,
        derivative);
    }

    /** The same with derivatives, from the converged xi. */
    template <typename Number>
    Number
    project_onto_curve(const Curve<Number> &x,
                       const Curve<Number> &n,
                       const Vec<Number>   &p,
                       const double         xi)
    {
      return newton_derivatives<Number>(
        [&](const Number &s) {
          return normal_line_residual(x, n, p, s);
        },
        xi);
    }

    /** cross(y(eta) - x, n) and its derivative in eta. */
    template <typename Number, typename Xi>
    std::array<Number, 2>
    line_hit_residual(const Vec<Number>   &x,
                      const Vec<Number>   &n,
                      const Curve<Number> &y,
                      const Xi            &eta)
    {
      return {
        {cross(Vec<Number>(combine(y, QuadraticFace::line_shape(eta)) - x), n),
         cross(combine(y, QuadraticFace::line_shape_derivative(eta)), n)}};
    }

    /**
     * The eta on the curve y hit by the line through x along the unit
     * vector n: cross(y(eta) - x, n) = 0, from the chord's solution, by
     * Newton in double, then (exact) with derivatives.
     */
    template <typename Number>
    Number
    intersect_curve(const Vec<Number>   &x,
                    const Vec<Number>   &n,
                    const Curve<Number> &y,
                    const bool           exact)
    {
      const Curve<double> yd = values(y);
      const Vec<double>   xd = values(x), nd = values(n);
      double              eta =
        MortarGeometry::intersect_line_with_face(xd, nd, yd[0], yd[1]);
      double derivative;
      newton(
        [&](const double e) {
          return line_hit_residual(xd, nd, yd, e);
        },
        eta,
        1e-14,
        derivative);
      if (!exact)
        return Number(eta);
      return newton_derivatives<Number>(
        [&](const Number &e) {
          return line_hit_residual(x, n, y, e);
        },
        eta);
    }

    /** (x(xi) - p).x'(xi) and its derivative in xi. */
    template <typename Number, typename Xi>
    std::array<Number, 2>
    closest_point_residual(const Curve<Number> &x,
                           const Vec<Number>   &p,
                           const Xi            &xi)
    {
      const Vec<Number> d = combine(x, QuadraticFace::line_shape(xi)) - p;
      const Vec<Number> t =
        combine(x, QuadraticFace::line_shape_derivative(xi));
      const Vec<Number> k = x[0] + x[1] - 2. * x[2]; // x''
      return {{d * t, t * t + d * k}};
    }

    /**
     * The xi of the point of the curve x closest to p: (x(xi) - p).x'(xi)
     * = 0, by Newton from the chord's projection `xi`; false if Newton
     * fails or ends at a largest distance.
     */
    inline bool
    closest_point(const Curve<double> &x, const Vec<double> &p, double &xi)
    {
      double derivative;
      return newton(
               [&](const double s) {
                 return closest_point_residual(x, p, s);
               },
               xi,
               1e-14,
               derivative) &&
             derivative > 0; // (a closest point, not a farthest one)
    }

    /** The same with derivatives, from the converged xi. */
    template <typename Number>
    Number
    closest_point(const Curve<Number> &x, const Vec<Number> &p, const double xi)
    {
      return newton_derivatives<Number>(
        [&](const Number &s) {
          return closest_point_residual(x, p, s);
        },
        xi);
    }

    /** The positions of a face's nodes from those of the nodes. */
    template <typename Number>
    Curve<Number>
    face_positions(const std::map<unsigned int, Vec<Number>> &positions,
                   const std::vector<unsigned int>           &nodes)
    {
      return {{positions.at(nodes[0]),
               positions.at(nodes[1]),
               positions.at(nodes[2])}};
    }

  } // namespace QuadraticCurve
} // namespace ContactDynamics

#endif
