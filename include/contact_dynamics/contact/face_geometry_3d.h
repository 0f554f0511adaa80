// Bilinear quadrilateral faces in 3-D for the mortar geometry
// (clipping_geometry.h): vectors, shape functions, tangents, points and
// normals, templated on the number type.
//
// A face's nodes are numbered as deal.II numbers a quadrilateral's
// vertices (lexicographic: (0,0), (1,0), (0,1), (1,1) in the reference
// square [0,1]^2), its shape functions are the bilinear N_0..N_3.
#ifndef contact_dynamics_contact_face_geometry_3d_h
#define contact_dynamics_contact_face_geometry_3d_h

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
  } // namespace ClippingGeometry
} // namespace ContactDynamics

#endif
