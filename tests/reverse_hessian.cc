// The reverse over forward mode of reverse_hessian.h against a closed form:
// f(x) = 3 x0 x1 - x2 / x0 + sqrt(x1 x2) + (2 - x0) + 5 / x2 - x1
//        + (x0 + 1.5) * 1 + 0 * x3 + x1 x1 + x2 / 4,
// which uses every recorded operation (product, quotient, square root, the
// constant forms, negation) and an input (x3) that enters with weight 0; its
// gradient and Hessian are derived by hand below. Also: the tape restarts
// (start()) and a second function on it gives its own Hessian, and the
// second derivatives of the 3-D mortar projection (face_projection_3d.h,
// one full and one frozen Newton step) match central differences of its
// first derivatives.
#include <contact_dynamics/contact/contact_ad.h>
#include <contact_dynamics/contact/face_projection_3d.h>
#include <contact_dynamics/contact/reverse_hessian_sweep.h>

#include "tests.h"

#include <Sacado.hpp>

using namespace dealii;
using namespace ContactDynamics;

namespace
{
  constexpr int n = 4;
  using Inner     = Sacado::Fad::SFad<double, n>;
  using Number    = ReverseHessian::Number<Inner>;

  void
  closed_form(const std::array<double, n> &x)
  {
    ReverseHessian::start<Inner>();
    std::array<Number, n> v;
    for (int i = 0; i < n; ++i)
      v[i] = Number::independent(x[i], i, n);
    const Number unused = v[0] * v[3]; // on the tape, not in f
    (void)unused;
    const Number f = 3. * (v[0] * v[1]) - v[2] / v[0] + sqrt(v[1] * v[2]) +
                     (2. - v[0]) + 5. / v[2] + (-v[1]) + (v[0] + 1.5) * 1. +
                     0. * v[3] + v[1] * v[1] + v[2] / 4.;
    const ReverseHessian::Sweep<Inner> sweep(f);

    const double s       = std::sqrt(x[1] * x[2]);
    const double g[n]    = {3 * x[1] + x[2] / (x[0] * x[0]) - 1 + 1,
                            3 * x[0] + x[2] / (2 * s) - 1 + 2 * x[1],
                            -1 / x[0] + x[1] / (2 * s) - 5 / (x[2] * x[2]) + 0.25,
                            0};
    double       H[n][n] = {};
    H[0][0]              = -2 * x[2] / (x[0] * x[0] * x[0]);
    H[0][1] = H[1][0] = 3;
    H[0][2] = H[2][0] = 1 / (x[0] * x[0]);
    H[1][1]           = -x[2] * x[2] / (4 * s * s * s) + 2;
    H[1][2] = H[2][1] = 1 / (4 * s);
    H[2][2] = -x[1] * x[1] / (4 * s * s * s) + 10 / (x[2] * x[2] * x[2]);

    double value_error =
      std::abs(ReverseHessian::value_of(f) -
               (3 * x[0] * x[1] - x[2] / x[0] + s + (2 - x[0]) + 5 / x[2] -
                x[1] + x[0] + 1.5 + x[1] * x[1] + x[2] / 4));
    double gradient_error = 0, hessian_error = 0;
    for (int i = 0; i < n; ++i)
      {
        const Inner a  = sweep(v[i]);
        gradient_error = std::max(gradient_error, std::abs(a.val() - g[i]));
        for (int l = 0; l < n; ++l)
          hessian_error = std::max(hessian_error, std::abs(a.dx(l) - H[i][l]));
      }
    deallog << "closed form: value " << (value_error < 1e-13 ? "OK" : "WRONG")
            << ", gradient " << (gradient_error < 1e-13 ? "OK" : "WRONG")
            << ", Hessian " << (hessian_error < 1e-12 ? "OK" : "WRONG")
            << std::endl;
  }

  // The 18 inputs of a projection: the corners of a warped face (12), the
  // point (3) and the direction (3)
  constexpr unsigned int n_in = 18;
  using Inputs                = std::array<double, n_in>;

  // (xi, eta, alpha) of the projection of the point onto the face along
  // the direction from (xi, eta, alpha) near it, in the number type T
  // seeded by make(value, k)
  template <typename T, typename Make>
  std::array<T, 3>
  projection(const Inputs                &in,
             const std::array<double, 3> &start,
             const Make                  &make)
  {
    std::array<ClippingGeometry::Vec3<T>, 4> x;
    ClippingGeometry::Vec3<T>                p, dir;
    for (unsigned int k = 0; k < n_in; ++k)
      (k < 12 ? x[k / 3][k % 3] :
       k < 15 ? p[k - 12] :
                dir[k - 15]) = make(in[k], k);
    return ClippingGeometry::projection_with_derivatives(x,
                                                         p,
                                                         dir,
                                                         start[0],
                                                         start[1],
                                                         start[2]);
  }

  // converged (xi, eta, alpha) by Newton in double
  std::array<double, 3>
  converged(const Inputs &in)
  {
    std::array<double, 3> y{{0.5, 0.5, 0.}};
    for (int k = 0; k < 30; ++k)
      y = projection<double>(in, y, [](double v, unsigned) {
        return v;
      });
    return y;
  }

  // d^2 (w . y) / dx_i dx_l by reverse over forward against central
  // differences of the first-order AD gradient, in all 18 inputs
  void
  projection_hessian()
  {
    const Inputs                in0 = {{0,
                                        0,
                                        0.1,
                                        1.1,
                                        0,
                                        -0.05,
                                        0,
                                        0.9,
                                        0.2,
                                        1.2,
                                        1.05,
                                        0.3,
                                        0.4,
                                        0.3,
                                        0.25,
                                        0.1,
                                        -0.2,
                                        -1.}};
    const std::array<double, 3> w   = {{0.7, -1.3, 2.1}};
    using Inner18                   = Sacado::Fad::SFad<double, n_in>;
    using Number18                  = ReverseHessian::Number<Inner18>;
    ReverseHessian::start<Inner18>();
    std::array<Number18, n_in> inputs;
    const auto                 y =
      projection<Number18>(in0, converged(in0), [&](double v, unsigned k) {
        return inputs[k] = Number18::independent(v, k, n_in);
      });
    const Number18 f = w[0] * y[0] + w[1] * y[1] + w[2] * y[2];
    const ReverseHessian::Sweep<Inner18> sweep(f);

    const auto first_order = [](double v, unsigned k) {
      return Inner18(n_in, k, v);
    };
    const double h   = 1e-5;
    double       err = 0, scale = 0;
    for (unsigned int l = 0; l < n_in; ++l)
      {
        auto inp = in0, inm = in0;
        inp[l] += h;
        inm[l] -= h;
        const auto yp = projection<Inner18>(inp, converged(inp), first_order);
        const auto ym = projection<Inner18>(inm, converged(inm), first_order);
        for (unsigned int i = 0; i < n_in; ++i)
          {
            double fd = 0;
            for (unsigned int c = 0; c < 3; ++c)
              fd += w[c] * (yp[c].dx(i) - ym[c].dx(i)) / (2 * h);
            err   = std::max(err, std::abs(sweep(inputs[i]).dx(l) - fd));
            scale = std::max(scale, std::abs(fd));
          }
      }
    deallog << "projection Hessian against central differences: "
            << (err < 1e-7 * scale ? "OK" : "WRONG") << " (scale "
            << (scale > 0.1 ? "nonzero" : "ZERO") << ")" << std::endl;
  }
} // namespace

int
main()
{
  initlog();
  closed_form({{1.3, 0.7, 2.2, 5.}});
  // the tape restarted: a second point gives its own values
  closed_form({{-0.8, 1.9, 0.45, -1.}});
  projection_hessian();
}
