// Geometry of 3-D mortar segments on bilinear quadrilateral faces (Popp,
// Gee and Wall, IJNME 79 (2009); Puso and Laursen 2004): both faces of a
// pair are projected along the normal of an auxiliary plane, the projected
// primary face is clipped against the projected secondary face, and the
// clip polygon is cut into triangles for Gauss quadrature. Templated on the
// number type like the 2-D geometry (mortar_geometry.h): the decisions
// (which vertex lies inside, which points merge) are taken on the values,
// the coordinates carry derivatives, so that Sacado differentiates the
// segment through the normals, the projections and the clip vertices.
//
// A face's nodes are numbered as deal.II numbers a quadrilateral's
// vertices (lexicographic: (0,0), (1,0), (0,1), (1,1) in the reference
// square [0,1]^2), its shape functions are the bilinear N_0..N_3.
#ifndef contact_dynamics_contact_clipping_geometry_h
#define contact_dynamics_contact_clipping_geometry_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/tensor.h>

#include <contact_dynamics/contact/mortar_geometry.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <type_traits>
#include <vector>

namespace ContactDynamics
{
  namespace ClippingGeometry
  {
    using dealii::Tensor;
    using MortarGeometry::value_of;

    template <typename Number>
    using Vec3 = Tensor<1, 3, Number>;

    /** A point in the coordinates of the auxiliary plane. */
    template <typename Number>
    using Point2 = std::array<Number, 2>;

    template <typename Number>
    using Polygon = std::vector<Point2<Number>>;

    template <typename Number>
    using Triangle = std::array<Point2<Number>, 3>;

    template <typename Number>
    Vec3<Number>
    cross(const Vec3<Number> &a, const Vec3<Number> &b)
    {
      Vec3<Number> c;
      c[0] = a[1] * b[2] - a[2] * b[1];
      c[1] = a[2] * b[0] - a[0] * b[2];
      c[2] = a[0] * b[1] - a[1] * b[0];
      return c;
    }

    template <typename Number>
    Number
    norm(const Vec3<Number> &a)
    {
      using std::sqrt;
      return sqrt(a * a);
    }

    /** Bilinear shape functions at (xi, eta) in [0,1]^2, lexicographic. */
    template <typename Number>
    std::array<Number, 4>
    shape(const Number &xi, const Number &eta)
    {
      return {
        {(1. - xi) * (1. - eta), xi * (1. - eta), (1. - xi) * eta, xi * eta}};
    }

    /** 0 for double, 1 for a Fad of doubles, 2 for a Fad of Fads, ... */
    template <typename Number>
    constexpr unsigned int
    derivative_order()
    {
      if constexpr (std::is_arithmetic_v<Number>)
        return 0;
      else
        return 1 + derivative_order<typename Number::value_type>();
    }

    /** The values of a vector with AD components. */
    template <typename Number>
    Vec3<double>
    values(const Vec3<Number> &v)
    {
      Vec3<double> d;
      for (unsigned int i = 0; i < 3; ++i)
        d[i] = value_of(v[i]);
      return d;
    }

    /** The values of the nodes of a face with AD coordinates. */
    template <typename Number>
    std::array<Vec3<double>, 4>
    values(const std::array<Vec3<Number>, 4> &x)
    {
      std::array<Vec3<double>, 4> d;
      for (unsigned int a = 0; a < 4; ++a)
        d[a] = values(x[a]);
      return d;
    }

    /** The tangents dx/dxi and dx/deta of a face at (xi, eta). */
    template <typename Number>
    std::array<Vec3<Number>, 2>
    tangents(const std::array<Vec3<Number>, 4> &x,
             const Number                      &xi,
             const Number                      &eta)
    {
      // (expression templates of AD numbers do not multiply tensors)
      const Number one_minus_eta = 1. - eta, one_minus_xi = 1. - xi;
      return {{one_minus_eta * (x[1] - x[0]) + eta * (x[3] - x[2]),
               one_minus_xi * (x[2] - x[0]) + xi * (x[3] - x[1])}};
    }

    /** The point x(xi, eta) of a face with nodes x. */
    template <typename Number>
    Vec3<Number>
    interpolate(const std::array<Vec3<Number>, 4> &x,
                const Number                      &xi,
                const Number                      &eta)
    {
      Vec3<Number> p;
      if constexpr (derivative_order<Number>() == 1)
        {
          // x(xi_0) + dx/dxi (xi - xi_0): the same value and first
          // derivatives with products of AD numbers and doubles only
          const double xi_0 = value_of(xi), eta_0 = value_of(eta);
          const auto   N    = shape(xi_0, eta_0);
          const auto   t    = tangents(values(x), xi_0, eta_0);
          const Number d_xi = xi - xi_0, d_eta = eta - eta_0;
          for (unsigned int d = 0; d < 3; ++d)
            p[d] = N[0] * x[0][d] + N[1] * x[1][d] + N[2] * x[2][d] +
                   N[3] * x[3][d] + t[0][d] * d_xi + t[1][d] * d_eta;
        }
      else
        {
          const auto N = shape(xi, eta);
          for (unsigned int a = 0; a < 4; ++a)
            p += N[a] * x[a];
        }
      return p;
    }

    /**
     * The unit normal (dx/dxi x dx/deta, normalized) of face x at its node
     * a, where the face's tangents are those of the corner.
     */
    template <typename Number>
    Vec3<Number>
    corner_normal(const std::array<Vec3<Number>, 4> &x, const unsigned int a)
    {
      const auto t =
        tangents(x, Number((a % 2) ? 1. : 0.), Number((a / 2) ? 1. : 0.));
      Vec3<Number> n = cross(t[0], t[1]);
      return n / norm(n);
    }

    /**
     * A node's normal: the normalized sum of the unit corner normals of
     * the faces around it (as the 2-D code averages its faces' normals).
     */
    template <typename Number>
    Vec3<Number>
    averaged_normal(const std::vector<Vec3<Number>> &corner_normals)
    {
      Vec3<Number> sum;
      for (const auto &n : corner_normals)
        sum += n;
      return sum / norm(sum);
    }

    /**
     * The auxiliary plane of a secondary face: through `center`, with unit
     * normal `normal` and an orthonormal in-plane basis. The basis only
     * names coordinates: areas and the points mapped back do not depend on
     * it.
     */
    template <typename Number>
    struct Plane
    {
      Vec3<Number> center, normal, t1, t2;

      Plane(const Vec3<Number> &center, const Vec3<Number> &unit_normal)
        : center(center)
        , normal(unit_normal)
      {
        // the coordinate axis least aligned with the normal
        unsigned int axis = 0;
        for (unsigned int d = 1; d < 3; ++d)
          if (std::abs(value_of(normal[d])) < std::abs(value_of(normal[axis])))
            axis = d;
        Vec3<Number> e;
        e[axis]          = 1.;
        const Number e_n = e * normal;
        t1               = e - e_n * normal;
        t1 /= norm(t1);
        t2 = cross(normal, t1);
      }

      /** x projected along the normal, in plane coordinates. */
      Point2<Number>
      project(const Vec3<Number> &x) const
      {
        const Vec3<Number> d = x - center;
        return {{Number(d * t1), Number(d * t2)}};
      }

      /** The point of the plane with coordinates p. */
      Vec3<Number>
      point(const Point2<Number> &p) const
      {
        return center + p[0] * t1 + p[1] * t2;
      }
    };

    /** Signed area (positive counterclockwise), by the shoelace formula. */
    template <typename Number>
    Number
    signed_area(const Polygon<Number> &p)
    {
      Number area = 0.;
      for (unsigned int i = 0; i < p.size(); ++i)
        {
          const auto &a = p[i], &b = p[(i + 1) % p.size()];
          area += a[0] * b[1] - a[1] * b[0];
        }
      return area / 2.;
    }

    /**
     * The projected quadrilateral face, counterclockwise: its nodes in the
     * order 0, 1, 3, 2 (lexicographic to cyclic), reversed if they turn
     * clockwise as seen from the plane's normal.
     */
    template <typename Number>
    Polygon<Number>
    project_face(const Plane<Number>               &plane,
                 const std::array<Vec3<Number>, 4> &x)
    {
      Polygon<Number> p{plane.project(x[0]),
                        plane.project(x[1]),
                        plane.project(x[3]),
                        plane.project(x[2])};
      if (value_of(signed_area(p)) < 0)
        std::reverse(p.begin(), p.end());
      return p;
    }

    /**
     * The part of the polygon `subject` inside the convex counterclockwise
     * polygon `clip` (Sutherland-Hodgman, one clip edge at a time; the clip
     * polygon must be convex: the projection of a valid bilinear face onto
     * its own plane is, since a non-convex quadrilateral has a Jacobian
     * that changes sign). Edges of `clip` shorter than the tolerance are
     * skipped. A point
     * within `tolerance` (a length) of a clip edge counts as on it, and
     * points closer than `tolerance` merge: a shared edge, a vertex on an
     * edge and coincident vertices give no slivers or duplicate vertices.
     * Returns an empty polygon if fewer than 3 vertices remain.
     */
    template <typename Number>
    Polygon<Number>
    clip_polygon(const Polygon<Number> &subject,
                 const Polygon<Number> &clip,
                 const double           tolerance)
    {
      Polygon<Number> result = subject;
      for (unsigned int e = 0; e < clip.size() && result.size() > 0; ++e)
        {
          const Point2<Number> &c0 = clip[e], &c1 = clip[(e + 1) % clip.size()];
          const Number          ex = c1[0] - c0[0], ey = c1[1] - c0[1];
          using std::sqrt;
          const Number length = sqrt(ex * ex + ey * ey);
          // a degenerate edge bounds nothing (and its normal is undefined)
          if (value_of(length) <= tolerance)
            continue;
          // signed distance, positive inside (to the left of the edge)
          const auto distance = [&](const Point2<Number> &p) -> Number {
            return (ex * (p[1] - c0[1]) - ey * (p[0] - c0[0])) / length;
          };
          Polygon<Number>     input = std::move(result);
          std::vector<Number> d;
          for (const auto &p : input)
            d.push_back(distance(p));
          result.clear();
          for (unsigned int i = 0; i < input.size(); ++i)
            {
              const unsigned int j  = (i + 1) % input.size();
              const double       di = value_of(d[i]), dj = value_of(d[j]);
              if (di >= -tolerance)
                result.push_back(input[i]);
              // a crossing strictly from one side to the other
              if ((di > tolerance && dj < -tolerance) ||
                  (di < -tolerance && dj > tolerance))
                {
                  const Number s = d[i] / (d[i] - d[j]);
                  result.push_back(
                    {{input[i][0] + s * (input[j][0] - input[i][0]),
                      input[i][1] + s * (input[j][1] - input[i][1])}});
                }
            }
        }
      // merge points closer than the tolerance, cyclically
      Polygon<Number> merged;
      const auto close = [&](const Point2<Number> &a, const Point2<Number> &b) {
        const double dx = value_of(a[0]) - value_of(b[0]),
                     dy = value_of(a[1]) - value_of(b[1]);
        return dx * dx + dy * dy <= tolerance * tolerance;
      };
      for (const auto &p : result)
        if (merged.empty() || !close(merged.back(), p))
          merged.push_back(p);
      while (merged.size() > 1 && close(merged.front(), merged.back()))
        merged.pop_back();
      if (merged.size() < 3 ||
          std::abs(value_of(signed_area(merged))) <= tolerance * tolerance)
        return {};
      return merged;
    }

    /**
     * Triangles of a convex polygon: a fan around the mean of its vertices
     * (as in Popp et al. 2009: no triangle degenerates where the polygon
     * has collinear vertices); a triangle is returned as it is.
     */
    template <typename Number>
    std::vector<Triangle<Number>>
    triangulate(const Polygon<Number> &p)
    {
      std::vector<Triangle<Number>> triangles;
      if (p.size() < 3)
        return triangles;
      if (p.size() == 3)
        return {{{p[0], p[1], p[2]}}};
      Point2<Number> center{{0., 0.}};
      for (const auto &v : p)
        {
          center[0] += v[0] / double(p.size());
          center[1] += v[1] / double(p.size());
        }
      for (unsigned int i = 0; i < p.size(); ++i)
        triangles.push_back({{center, p[i], p[(i + 1) % p.size()]}});
      return triangles;
    }

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
      xi = eta = 0.5;
      alpha    = 0;
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
     * The same projection with derivatives: from the converged values,
     * exact_newton_steps() Newton steps in the number type give the exact
     * derivatives (implicit function theorem) and leave the values
     * unchanged.
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
      if constexpr (derivative_order<Number>() == 1)
        {
          // First derivatives by the implicit function theorem, dy = -J^-1
          // dr with J at the converged point in double precision: a Newton
          // step with J frozen, whose residual is linear in the AD inputs
          // (a sixth of the operations of the step in the AD type, which
          // dominated the 3-D mortar's cost).
          const Vec3<double>    m       = -values(n);
          const auto            t       = tangents(values(x), xi, eta);
          const double          det     = cross(t[0], t[1]) * m;
          const Vec3<double>    rows[3] = {cross(t[1], m),
                                           cross(m, t[0]),
                                           cross(t[0], t[1])};
          const auto            N       = shape(xi, eta);
          std::array<Number, 3> y{{Number(xi), Number(eta), Number(alpha)}};
          for (unsigned int d = 0; d < 3; ++d)
            {
              const Number r = N[0] * x[0][d] + N[1] * x[1][d] +
                               N[2] * x[2][d] + N[3] * x[3][d] - p[d] -
                               alpha * n[d];
              for (unsigned int k = 0; k < 3; ++k)
                y[k] -= (rows[k][d] / det) * r;
            }
          return y;
        }
      std::array<Number, 3> y{{Number(xi), Number(eta), Number(alpha)}};
      const Vec3<Number>    m = -n;
      for (unsigned int step = 0; step < exact_newton_steps<Number>(); ++step)
        {
          const Vec3<Number> r   = interpolate(x, y[0], y[1]) - p - y[2] * n;
          const auto         t   = tangents(x, y[0], y[1]);
          const Number       det = cross(t[0], t[1]) * m;
          y                      = {{y[0] - (cross(r, t[1]) * m) / det,
                                     y[1] - (cross(t[0], r) * m) / det,
                                     y[2] - (cross(t[0], t[1]) * r) / det}};
        }
      return y;
    }

    /** A quadrature point in a face's reference square, weight with area. */
    template <typename Number>
    struct FacePoint
    {
      Number xi, eta, weight;
    };

    /**
     * A = D M^-1 from D_jj = integral N_j and M_jk = integral N_j N_k.
     */
    template <typename Number>
    std::array<std::array<Number, 4>, 4>
    dual_from_moments(const std::array<Number, 4>         &D,
                      std::array<std::array<Number, 4>, 4> M)
    {
      // M^-1 by Gauss-Jordan elimination with partial pivoting on values
      std::array<std::array<Number, 4>, 4> inverse{};
      for (unsigned int j = 0; j < 4; ++j)
        for (unsigned int k = 0; k < 4; ++k)
          inverse[j][k] = Number(j == k ? 1. : 0.);
      for (unsigned int c = 0; c < 4; ++c)
        {
          unsigned int pivot = c;
          for (unsigned int r = c + 1; r < 4; ++r)
            if (std::abs(value_of(M[r][c])) > std::abs(value_of(M[pivot][c])))
              pivot = r;
          std::swap(M[c], M[pivot]);
          std::swap(inverse[c], inverse[pivot]);
          const Number diagonal = M[c][c];
          for (unsigned int k = 0; k < 4; ++k)
            {
              M[c][k] /= diagonal;
              inverse[c][k] /= diagonal;
            }
          for (unsigned int r = 0; r < 4; ++r)
            if (r != c)
              {
                const Number factor = M[r][c];
                for (unsigned int k = 0; k < 4; ++k)
                  {
                    M[r][k] -= factor * M[c][k];
                    inverse[r][k] -= factor * inverse[c][k];
                  }
              }
        }
      std::array<std::array<Number, 4>, 4> a;
      for (unsigned int j = 0; j < 4; ++j)
        for (unsigned int k = 0; k < 4; ++k)
          a[j][k] = D[j] * inverse[j][k];
      return a;
    }

    /**
     * Coefficients a_jk of the dual basis psi_j = sum_k a_jk N_k of a face,
     * biorthogonal to N on what the points integrate: A = D M^-1 with
     * D_jj = sum w N_j and M_jk = sum w N_j N_k (the whole face, or its
     * covered part, as in the 2-D dual_coefficients). Sum_j psi_j = 1.
     */
    template <typename Number>
    std::array<std::array<Number, 4>, 4>
    dual_coefficients(const std::vector<FacePoint<Number>> &points)
    {
      std::array<Number, 4>                D{};
      std::array<std::array<Number, 4>, 4> M{};
      for (auto &row : M)
        row.fill(Number(0.));
      D.fill(Number(0.));
      for (const auto &q : points)
        {
          const auto N = shape(q.xi, q.eta);
          for (unsigned int j = 0; j < 4; ++j)
            {
              D[j] += q.weight * N[j];
              for (unsigned int k = 0; k < 4; ++k)
                M[j][k] += q.weight * N[j] * N[k];
            }
        }
      return dual_from_moments(D, M);
    }

    /**
     * 2 x 2 Gauss points of the whole face x, with the area element:
     * exact for the products N_j N_k |dx/dxi x dx/deta| of a flat face.
     */
    template <typename Number>
    std::vector<FacePoint<Number>>
    face_points(const std::array<Vec3<Number>, 4> &x)
    {
      std::vector<FacePoint<Number>> points;
      const double                   g = 0.5 / std::sqrt(3.);
      for (const double xi : {0.5 - g, 0.5 + g})
        for (const double eta : {0.5 - g, 0.5 + g})
          {
            const auto t = tangents(x, Number(xi), Number(eta));
            points.push_back(
              {Number(xi), Number(eta), norm(cross(t[0], t[1])) / 4.});
          }
      return points;
    }

    /**
     * What a pair of a secondary and a primary face contributes to the
     * mortar integrals of the secondary face's nodes j (primary nodes k):
     * D_j = integral psi_j, M_jk = integral psi_j N_k (primary), and the
     * weighted gap g_j = integral psi_j (x_m - x_s) . n, over the part of
     * the secondary face the primary face covers.
     */
    template <typename Number>
    struct SegmentIntegrals
    {
      std::array<Number, 4>                D{}, gap{};
      std::array<std::array<Number, 4>, 4> M{};
      Number                               area = 0.;

      SegmentIntegrals()
      {
        D.fill(Number(0.));
        gap.fill(Number(0.));
        for (auto &row : M)
          row.fill(Number(0.));
      }
    };

    /**
     * A quadrature point of a mortar segment: its parameters on the
     * secondary and on the primary face, and its weight (area in the
     * auxiliary plane).
     */
    template <typename Number>
    struct SegmentPoint
    {
      Number xi_s, eta_s, xi_m, eta_m, weight;
    };

    /**
     * The quadrature points of the segment of a secondary face xs (nodal
     * unit normals ns) and a primary face xm, appended to `points`: the
     * auxiliary plane through the secondary face's center with its
     * interpolated normal there, both faces projected onto it along that
     * normal and clipped, the clip polygon triangulated, and at each point
     * of the 6-point rule on each triangle the points of both faces hit
     * along the plane's normal (Popp, Gee and Wall 2009: the integration
     * cells live in the plane; exact for flat secondary faces).
     * `tolerance` is relative to the secondary face's diameter. False if
     * the faces do not overlap; throws if a point of the overlap cannot be
     * projected onto its faces (then nothing is appended).
     */
    template <typename Number>
    bool
    segment_points(const std::array<Vec3<Number>, 4> &xs,
                   const std::array<Vec3<Number>, 4> &ns,
                   const std::array<Vec3<Number>, 4> &xm,
                   const double                       tolerance,
                   std::vector<SegmentPoint<Number>> &points,
                   const TriangleRule                &rule = triangle_rule())
    {
      const Number       half   = 0.5;
      const Vec3<Number> center = interpolate(xs, half, half);
      Vec3<Number>       normal = interpolate(ns, half, half);
      normal /= norm(normal);
      const Plane<Number> plane(center, normal);
      const double        diameter =
        std::max(value_of(norm(Vec3<Number>(xs[3] - xs[0]))),
                 value_of(norm(Vec3<Number>(xs[2] - xs[1]))));
      const Polygon<Number> clip = clip_polygon(project_face(plane, xm),
                                                project_face(plane, xs),
                                                tolerance * diameter);
      if (clip.empty())
        return false;
      const std::array<Vec3<double>, 4> xs_d = values(xs), xm_d = values(xm);
      const Vec3<double>                normal_d = values(normal);
      std::vector<SegmentPoint<Number>> found;
      for (const auto &triangle : triangulate(clip))
        {
          const Number area =
            signed_area(Polygon<Number>(triangle.begin(), triangle.end()));
          for (const auto &[b, w] : rule)
            {
              Point2<Number> q;
              for (unsigned int c = 0; c < 2; ++c)
                q[c] = b[0] * triangle[0][c] + b[1] * triangle[1][c] +
                       b[2] * triangle[2][c];
              const Vec3<Number> p = plane.point(q);
              double             s[3], m[3];
              // a point of the clip polygon lies on both projected faces:
              // not finding it on either is a geometry failure, not a
              // missing overlap
              AssertThrow(
                project_along_direction(xs_d,
                                        values(p),
                                        normal_d,
                                        s[0],
                                        s[1],
                                        s[2]) &&
                  project_along_direction(xm_d,
                                          values(p),
                                          normal_d,
                                          m[0],
                                          m[1],
                                          m[2]),
                dealii::ExcMessage(
                  "3-D mortar: a point of a mortar segment could not be "
                  "projected onto its faces (faces nearly parallel to the "
                  "auxiliary plane's normal, or badly distorted)."));
              const auto ps =
                projection_with_derivatives(xs, p, normal, s[0], s[1], s[2]);
              const auto pm =
                projection_with_derivatives(xm, p, normal, m[0], m[1], m[2]);
              found.push_back({ps[0], ps[1], pm[0], pm[1], Number(area * w)});
            }
        }
      points.insert(points.end(), found.begin(), found.end());
      return true;
    }

    /**
     * The gap (x_m - x_s) . n at a segment point, along the interpolated
     * unit normal n of the secondary face (returned in `normal`).
     */
    template <typename Number>
    Number
    point_gap(const std::array<Vec3<Number>, 4> &xs,
              const std::array<Vec3<Number>, 4> &ns,
              const std::array<Vec3<Number>, 4> &xm,
              const SegmentPoint<Number>        &q,
              Vec3<Number>                      &normal)
    {
      normal = interpolate(ns, q.xi_s, q.eta_s);
      normal /= norm(normal);
      return (interpolate(xm, q.xi_m, q.eta_m) -
              interpolate(xs, q.xi_s, q.eta_s)) *
             normal;
    }

    /**
     * The points of a face's segments as points of the face, for
     * dual_coefficients() of a partially covered face (the 2-D rule: the
     * dual basis is biorthogonal on what is integrated).
     */
    template <typename Number>
    std::vector<FacePoint<Number>>
    secondary_points(const std::vector<SegmentPoint<Number>> &points)
    {
      std::vector<FacePoint<Number>> result;
      for (const auto &q : points)
        result.push_back({q.xi_s, q.eta_s, q.weight});
      return result;
    }

    /**
     * Adds the mortar integrals at a segment's points: D_j, M_jk and the
     * weighted gap, the gap measured along the interpolated normal of the
     * secondary face.
     */
    template <typename Number>
    void
    add_segment_integrals(const std::array<Vec3<Number>, 4>          &xs,
                          const std::array<Vec3<Number>, 4>          &ns,
                          const std::array<Vec3<Number>, 4>          &xm,
                          const std::array<std::array<Number, 4>, 4> &dual,
                          const std::vector<SegmentPoint<Number>>    &points,
                          SegmentIntegrals<Number>                   &result)
    {
      for (const auto &q : points)
        {
          const auto   Ns = shape(q.xi_s, q.eta_s);
          const auto   Nm = shape(q.xi_m, q.eta_m);
          Vec3<Number> n;
          const Number g = point_gap(xs, ns, xm, q, n);
          result.area += q.weight;
          for (unsigned int j = 0; j < 4; ++j)
            {
              Number psi = 0.;
              for (unsigned int k = 0; k < 4; ++k)
                psi += dual[j][k] * Ns[k];
              result.D[j] += psi * q.weight;
              result.gap[j] += psi * g * q.weight;
              for (unsigned int k = 0; k < 4; ++k)
                result.M[j][k] += psi * Nm[k] * q.weight;
            }
        }
    }

    /**
     * segment_points() and add_segment_integrals() of one face pair with
     * given dual coefficients. False if the faces do not overlap.
     */
    template <typename Number>
    bool
    integrate_segment(const std::array<Vec3<Number>, 4>          &xs,
                      const std::array<Vec3<Number>, 4>          &ns,
                      const std::array<Vec3<Number>, 4>          &xm,
                      const std::array<std::array<Number, 4>, 4> &dual,
                      const double                                tolerance,
                      SegmentIntegrals<Number>                   &result)
    {
      std::vector<SegmentPoint<Number>> points;
      if (!segment_points(xs, ns, xm, tolerance, points))
        return false;
      add_segment_integrals(xs, ns, xm, dual, points, result);
      return true;
    }
  } // namespace ClippingGeometry
} // namespace ContactDynamics

#endif
