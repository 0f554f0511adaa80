// Closest-point projection onto a warped bilinear face (3-D
// node-to-segment): a point placed at a distance 0.2 along the face's
// normal above (xi, eta) = (0.35, 0.7) projects back there; the distance
// found is the minimum of a brute-force search over a 400 x 400 grid of the
// face; a point above (1.3, 0.4) gives parameters outside [0,1]^2 (the
// caller decides the face); the AD derivatives of (xi, eta) with respect
// to the point and to a face node match central differences.
#include <deal.II/differentiation/ad/sacado_math.h>
#include <deal.II/differentiation/ad/sacado_number_types.h>
#include <deal.II/differentiation/ad/sacado_product_types.h>

#include <contact_dynamics/contact/closest_point_3d.h>

#include "tests.h"

#include <Sacado.hpp>

using namespace dealii;
using namespace ContactDynamics::ClippingGeometry;

int
main()
{
  initlog();
  std::array<Vec3<double>, 4> x;
  const double                coords[4][3] = {{0, 0, 0},
                                              {1.1, 0, 0.1},
                                              {0, 0.9, -0.05},
                                              {1, 1.2, 0.3}};
  for (unsigned int a = 0; a < 4; ++a)
    for (unsigned int d = 0; d < 3; ++d)
      x[a][d] = coords[a][d];
  const auto above = [&](const double xi, const double eta, const double h) {
    const auto   t = tangents(x, xi, eta);
    Vec3<double> n = cross(t[0], t[1]);
    return Vec3<double>(interpolate(x, xi, eta) + h * n / n.norm());
  };

  const Vec3<double> p = above(0.35, 0.7, 0.2);
  double             xi, eta;
  check_true("converges", closest_point(x, p, xi, eta));
  check_close("recovers (0.35, 0.7)",
              std::abs(xi - 0.35) + std::abs(eta - 0.7),
              0,
              1e-13);
  double best = 1e300, best_xi = 0, best_eta = 0;
  for (unsigned int i = 0; i <= 400; ++i)
    for (unsigned int j = 0; j <= 400; ++j)
      {
        const double d = (interpolate(x, i / 400., j / 400.) - p).norm();
        if (d < best)
          {
            best     = d;
            best_xi  = i / 400.;
            best_eta = j / 400.;
          }
      }
  const double found = (interpolate(x, xi, eta) - p).norm();
  check_close("the distance found is 0.2", found, 0.2, 1e-13);
  check_true("no grid point of the face is nearer", best >= found - 1e-14);
  check_true("the grid's nearest point is next to it",
             std::abs(best_xi - xi) <= 1. / 400 &&
               std::abs(best_eta - eta) <= 1. / 400);

  double xo, eo;
  check_true("outside the face: converges",
             closest_point(x, above(1.3, 0.4, 0.1), xo, eo));
  check_close("outside the face: (1.3, 0.4)",
              std::abs(xo - 1.3) + std::abs(eo - 0.4),
              0,
              1e-12);

  using AD = Sacado::Fad::DFad<double>;
  std::array<Vec3<AD>, 4> xa;
  Vec3<AD>                pa;
  for (unsigned int a = 0; a < 4; ++a)
    for (unsigned int d = 0; d < 3; ++d)
      xa[a][d] = x[a][d];
  for (unsigned int d = 0; d < 3; ++d)
    pa[d] = p[d];
  xa[3][2]             = AD(2, 0, x[3][2]);
  pa[1]                = AD(2, 1, p[1]);
  const auto   r       = closest_point_with_derivatives(xa, pa, xi, eta);
  double       largest = 0;
  const double h       = 1e-6;
  for (unsigned int k = 0; k < 2; ++k)
    {
      double plus[2], minus[2];
      for (const int sign : {1, -1})
        {
          auto         xs = x;
          Vec3<double> ps = p;
          (k == 0 ? xs[3][2] : ps[1]) += sign * h;
          double a, b;
          closest_point(xs, ps, a, b);
          (sign > 0 ? plus : minus)[0] = a;
          (sign > 0 ? plus : minus)[1] = b;
        }
      for (unsigned int i = 0; i < 2; ++i)
        largest =
          std::max(largest,
                   std::abs(r[i].dx(k) - (plus[i] - minus[i]) / (2 * h)));
    }
  record_measured("AD against differences", largest, 0, 1e-8);
  check_close("AD derivatives against central differences", largest, 0, 1e-8);
}
