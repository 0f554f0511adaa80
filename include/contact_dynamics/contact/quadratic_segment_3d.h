// Mortar segments between two curved 9-node faces (3-D elements of degree
// 2), templated on the number type: the primary face's boundary nodes are
// projected onto the secondary face along its normal field (closest
// points), the polygon they span in the secondary face's coordinates is
// clipped to the unit square and split into triangles, and every
// quadrature point is integrated on the curved secondary face and
// projected onto the curved primary face along the secondary's normal.
// Newton runs in double; two steps in the number type from the converged
// value give exact first and second derivatives.
//
// The only approximation is the segment's boundary: between the projected
// edge points it is straight in the secondary face's coordinates (exact
// where the primary edges project onto straight lines, as between
// parallelogram faces on a flat interface).
#ifndef contact_dynamics_contact_quadratic_segment_3d_h
#define contact_dynamics_contact_quadratic_segment_3d_h

#include <contact_dynamics/contact/face_projection_3d.h>
#include <contact_dynamics/contact/quadratic_face.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace ContactDynamics
{
  namespace QuadraticSegment3D
  {
    using ClippingGeometry::cross;
    using ClippingGeometry::norm;
    using ClippingGeometry::TriangleRule;
    using ClippingGeometry::Vec3;
    using MortarGeometry::value_of;

    template <typename Number>
    using Face = std::array<Vec3<Number>, 9>;


    /** Shape functions, first and second derivatives at (xi, eta). */
    template <typename Number>
    struct Shape
    {
      std::array<Number, 9>                N;
      std::array<std::array<Number, 9>, 2> dN;
      std::array<std::array<Number, 9>, 3> d2N; // xx, xy, yy
    };

    template <typename Number>
    Shape<Number>
    shape(const Number &xi, const Number &eta)
    {
      static constexpr unsigned int a[9] = {0, 1, 0, 1, 0, 1, 2, 2, 2};
      static constexpr unsigned int b[9] = {0, 0, 1, 1, 2, 2, 0, 1, 2};
      const auto l = [](const Number &t) -> std::array<Number, 3> {
        return {
          {(1. - t) * (1. - 2. * t), t * (2. * t - 1.), 4. * t * (1. - t)}};
      };
      const auto dl = [](const Number &t) -> std::array<Number, 3> {
        return {{4. * t - 3., 4. * t - 1., 4. - 8. * t}};
      };
      static constexpr double d2l[3] = {4., 4., -8.};
      const auto              x = l(xi), y = l(eta), dx = dl(xi), dy = dl(eta);
      Shape<Number>           s;
      for (unsigned int j = 0; j < 9; ++j)
        {
          s.N[j]      = x[a[j]] * y[b[j]];
          s.dN[0][j]  = dx[a[j]] * y[b[j]];
          s.dN[1][j]  = x[a[j]] * dy[b[j]];
          s.d2N[0][j] = d2l[a[j]] * y[b[j]];
          s.d2N[1][j] = dx[a[j]] * dy[b[j]];
          s.d2N[2][j] = x[a[j]] * d2l[b[j]];
        }
      return s;
    }

    /** sum_j c_j x_j, by component. */
    template <typename Number, typename Coefficient>
    Vec3<Number>
    combine(const Face<Number> &x, const std::array<Coefficient, 9> &c)
    {
      Vec3<Number> y;
      for (unsigned int d = 0; d < 3; ++d)
        {
          y[d] = c[0] * x[0][d];
          for (unsigned int j = 1; j < 9; ++j)
            y[d] += c[j] * x[j][d];
        }
      return y;
    }

    template <typename Number>
    Face<double>
    values(const Face<Number> &x)
    {
      Face<double> y;
      for (unsigned int j = 0; j < 9; ++j)
        for (unsigned int d = 0; d < 3; ++d)
          y[j][d] = value_of(x[j][d]);
      return y;
    }

    /** x - b, the residual of a linear system, solved for by Cramer. */
    template <typename Number, int n>
    std::array<Number, n>
    solve(const std::array<std::array<Number, n>, n> &A,
          const std::array<Number, n>                &b)
    {
      if constexpr (n == 2)
        {
          const Number det = A[0][0] * A[1][1] - A[0][1] * A[1][0];
          return {{(b[0] * A[1][1] - A[0][1] * b[1]) / det,
                   (A[0][0] * b[1] - b[0] * A[1][0]) / det}};
        }
      else
        {
          Vec3<Number> c[3];
          for (unsigned int k = 0; k < 3; ++k)
            for (unsigned int d = 0; d < 3; ++d)
              c[k][d] = A[d][k];
          Vec3<Number> r;
          for (unsigned int d = 0; d < 3; ++d)
            r[d] = b[d];
          const Number det = cross(c[0], c[1]) * c[2];
          return {{(cross(r, c[1]) * c[2]) / det,
                   (cross(c[0], r) * c[2]) / det,
                   (cross(c[0], c[1]) * r) / det}};
        }
    }

    /**
     * The closest point residual t_a . (p - x(y)) of the point p on the
     * face x at y = (xi, eta), and its Jacobian.
     */
    template <typename Number>
    void
    closest_point_system(const Face<Number>                   &x,
                         const Vec3<Number>                   &p,
                         const std::array<Number, 2>          &y,
                         std::array<Number, 2>                &r,
                         std::array<std::array<Number, 2>, 2> &J)
    {
      const auto         s = shape(y[0], y[1]);
      const Vec3<Number> d = p - combine(x, s.N);
      Vec3<Number>       t[2], h[3];
      for (unsigned int a = 0; a < 2; ++a)
        t[a] = combine(x, s.dN[a]);
      for (unsigned int a = 0; a < 3; ++a)
        h[a] = combine(x, s.d2N[a]);
      for (unsigned int a = 0; a < 2; ++a)
        {
          r[a] = t[a] * d;
          for (unsigned int b = 0; b < 2; ++b)
            J[a][b] = d * h[a + b] - t[a] * t[b];
        }
    }

    /**
     * The residual x_p(xi, eta) - o - t n of the point o + t n on the face
     * x_p at y = (xi, eta, t), and its Jacobian.
     */
    template <typename Number>
    void
    ray_system(const Face<Number>                   &x,
               const Vec3<Number>                   &o,
               const Vec3<Number>                   &n,
               const std::array<Number, 3>          &y,
               std::array<Number, 3>                &r,
               std::array<std::array<Number, 3>, 3> &J)
    {
      const auto         s  = shape(y[0], y[1]);
      const Vec3<Number> t0 = combine(x, s.dN[0]), t1 = combine(x, s.dN[1]);
      const Vec3<Number> d = combine(x, s.N) - o - y[2] * n;
      for (unsigned int c = 0; c < 3; ++c)
        {
          r[c]    = d[c];
          J[c][0] = t0[c];
          J[c][1] = t1[c];
          J[c][2] = -n[c];
        }
    }

    /**
     * The start of the closest point of p on face x: its projection onto
     * the face's tangent plane at the centre (Newton's steps are limited,
     * and a point many faces away would exhaust them from the centre).
     */
    inline std::array<double, 2>
    affine_guess(const Face<double> &x, const Vec3<double> &p)
    {
      const auto         s    = shape(0.5, 0.5);
      const Vec3<double> d    = p - combine(x, s.N);
      const Vec3<double> t[2] = {combine(x, s.dN[0]), combine(x, s.dN[1])};
      const std::array<std::array<double, 2>, 2> A = {
        {{{t[0] * t[0], t[0] * t[1]}}, {{t[1] * t[0], t[1] * t[1]}}}};
      const auto y = solve<double, 2>(A, {{t[0] * d, t[1] * d}});
      return {{0.5 + y[0], 0.5 + y[1]}};
    }

    /**
     * Newton on system(y, r, J) in double from y, with steps limited to
     * `limit` in the face's coordinates; false without convergence.
     */
    template <int n, typename System>
    bool
    newton(const System &system, std::array<double, n> &y, const double limit)
    {
      double previous = 1e300;
      for (unsigned int it = 0; it < 40; ++it)
        {
          std::array<double, n>                r;
          std::array<std::array<double, n>, n> J;
          system(y, r, J);
          auto         dy   = solve<double, n>(J, r);
          const double step = std::max(std::abs(dy[0]), std::abs(dy[1]));
          if (!std::isfinite(step))
            return false;
          const double scale = step > limit ? limit / step : 1.;
          for (int k = 0; k < n; ++k)
            y[k] -= scale * dy[k];
          // (converged, or stalled at round-off)
          if (step < 1e-13 || (step < 1e-9 && step > 0.25 * previous))
            return std::abs(y[0]) < 1e3 && std::abs(y[1]) < 1e3;
          previous = step;
        }
      return false;
    }

    /**
     * The solution y of system(y) = 0 in Number from its value in double:
     * steps in Number carry the derivatives (one gives the first, two
     * the second derivatives).
     */
    template <typename Number, int n, typename System>
    std::array<Number, n>
    refine(const System &system, const std::array<double, n> &y0)
    {
      std::array<Number, n> y;
      for (int k = 0; k < n; ++k)
        y[k] = Number(y0[k]);
      for (unsigned int step = 0;
           step < ClippingGeometry::derivative_order<Number>();
           ++step)
        {
          std::array<Number, n>                r;
          std::array<std::array<Number, n>, n> J;
          system(y, r, J);
          const auto dy = solve<Number, n>(J, r);
          for (int k = 0; k < n; ++k)
            y[k] -= dy[k];
        }
      return y;
    }

  } // namespace QuadraticSegment3D
} // namespace ContactDynamics

#endif
