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
      for (unsigned int it = 0; it < 30; ++it)
        {
          const auto        N  = QuadraticFace::line_shape(xi);
          const auto        dN = QuadraticFace::line_shape_derivative(xi);
          const Vec<double> d  = combine(x, N) - p;
          const double      F  = cross(d, combine(n, N));
          const double      dF =
            cross(combine(x, dN), combine(n, N)) + cross(d, combine(n, dN));
          if (std::abs(dF) < 1e-300)
            return false;
          const double step = F / dF;
          xi -= step;
          if (std::abs(xi) > 1e3)
            return false;
          if (std::abs(step) < 1e-13 * (1 + std::abs(xi)))
            return true;
        }
      return false;
    }

    /**
     * The same with derivatives: two Newton steps in Number from the
     * converged xi (the first gives exact first derivatives, the second
     * exact second derivatives; the value does not change).
     */
    template <typename Number>
    Number
    project_onto_curve(const Curve<Number> &x,
                       const Curve<Number> &n,
                       const Vec<Number>   &p,
                       const double         xi)
    {
      Number result(xi);
      for (unsigned int step = 0; step < 2; ++step)
        {
          const auto        N  = QuadraticFace::line_shape(result);
          const auto        dN = QuadraticFace::line_shape_derivative(result);
          const Vec<Number> d  = combine(x, N) - p;
          const Number      F  = cross(d, combine(n, N));
          const Number      dF =
            cross(combine(x, dN), combine(n, N)) + cross(d, combine(n, dN));
          result -= F / dF;
        }
      return result;
    }

    /**
     * The eta on the curve y hit by the line through x along the unit
     * vector n: cross(y(eta) - x, n) = 0, from the chord's solution, by
     * Newton in double, then one step in Number.
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
      for (unsigned int it = 0; it < 30; ++it)
        {
          const double G =
            cross(Vec<double>(combine(yd, QuadraticFace::line_shape(eta)) - xd),
                  nd);
          const double dG =
            cross(combine(yd, QuadraticFace::line_shape_derivative(eta)), nd);
          if (std::abs(dG) < 1e-300)
            break;
          eta -= G / dG;
          if (std::abs(G / dG) < 1e-14 * (1 + std::abs(eta)) ||
              std::abs(eta) > 1e3)
            break;
        }
      if (!exact)
        return Number(eta);
      // two steps: exact second derivatives
      Number result(eta);
      for (unsigned int step = 0; step < 2; ++step)
        {
          const auto   N  = QuadraticFace::line_shape(result);
          const auto   dN = QuadraticFace::line_shape_derivative(result);
          const Number G  = cross(Vec<Number>(combine(y, N) - x), n);
          result -= G / cross(combine(y, dN), n);
        }
      return result;
    }

    /**
     * The xi of the point of the curve x closest to p: (x(xi) - p).x'(xi)
     * = 0, by Newton from the chord's projection `xi`; false if Newton
     * fails or ends at a largest distance.
     */
    inline bool
    closest_point(const Curve<double> &x, const Vec<double> &p, double &xi)
    {
      for (unsigned int it = 0; it < 30; ++it)
        {
          const Vec<double> d = combine(x, QuadraticFace::line_shape(xi)) - p;
          const Vec<double> t =
            combine(x, QuadraticFace::line_shape_derivative(xi));
          const Vec<double> k = x[0] + x[1] - 2. * x[2]; // x''
          const double      F = d * t, dF = t * t + d * k;
          if (std::abs(dF) < 1e-300)
            return false;
          xi -= F / dF;
          if (std::abs(xi) > 1e3)
            return false;
          if (std::abs(F / dF) < 1e-14 * (1 + std::abs(xi)))
            return dF > 0; // (a closest point, not a farthest one)
        }
      return false;
    }

    /** The same with derivatives: two Newton steps from the converged xi. */
    template <typename Number>
    Number
    closest_point(const Curve<Number> &x, const Vec<Number> &p, const double xi)
    {
      Number     result(xi);
      const auto k = x[0] + x[1] - 2. * x[2];
      for (unsigned int step = 0; step < 2; ++step)
        {
          const Vec<Number> d =
            combine(x, QuadraticFace::line_shape(result)) - p;
          const Vec<Number> t =
            combine(x, QuadraticFace::line_shape_derivative(result));
          result -= (d * t) / (t * t + d * Vec<Number>(k));
        }
      return result;
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
