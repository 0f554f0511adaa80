// Geometry of straight 2-D faces shared by the contact formulations,
// templated on the number type so that the same code yields values
// (double) and exact derivatives (Sacado AD numbers).
//
// A face runs from node 0 to node 1, parametrized by xi in [-1, 1] with
// N_0 = (1 - xi)/2, N_1 = (1 + xi)/2; its outward normal is the tangent
// x_1 - x_0 turned clockwise.
#ifndef contact_dynamics_contact_segment_geometry_h
#define contact_dynamics_contact_segment_geometry_h

#include <deal.II/base/tensor.h>

#include <array>
#include <cmath>

namespace ContactDynamics
{
  namespace SegmentGeometry
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
  } // namespace SegmentGeometry
} // namespace ContactDynamics

#endif
