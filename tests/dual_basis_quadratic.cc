// The faces of elements of degree 2 (quadratic_face.h):
// - their shape functions are deal.II's FE_Q(2) in one and two dimensions,
//   node for node (the order the contact surfaces will collect them in);
// - they integrate to positive weights, the numbers worked out by hand
//   (1/6, 2/3, 1/6 of a line; 1/36, 1/9, 4/9 of a face), so the dual basis
//   needs no transformation (unlike the 8-node serendipity face);
// - the dual basis built on one rule is biorthogonal under another rule
//   exact for the products, to 1e-13: on a straight 3-node line whose
//   middle node is off centre (a Jacobian linear in xi), on a part of it
//   (partial coverage), and on a 9-node parallelogram face;
// - it sums to one, and D^-1 integral(psi_j f) gives back the nodal values
//   of a quadratic field f;
// - D_jj > 0 holds on whole faces only: on part of a line a quadratic N_j
//   can integrate to a negative weight (the value integrated by hand).
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_q.h>

#include <contact_dynamics/contact/quadratic_face.h>

#include "tests.h"

using namespace dealii;
using namespace ContactDynamics;

namespace
{
  // a straight 3-node line from 0 to 2 with its middle node at 1.3: the
  // Jacobian dx/dxi = 1 - 0.6 xi is linear
  double
  line_jacobian(const double xi)
  {
    const auto dN = QuadraticFace::line_shape_derivative(xi);
    return 2 * dN[1] + 1.3 * dN[2];
  }

  // points and weights (with the Jacobian) of a Gauss rule on [lo, hi]
  void
  line_rule(const unsigned int                  n,
            const double                        lo,
            const double                        hi,
            std::vector<std::array<double, 3>> &N,
            std::vector<double>                &w,
            std::vector<double>                &xis)
  {
    const QGauss<1> gauss(n);
    N.clear();
    w.clear();
    xis.clear();
    for (unsigned int q = 0; q < gauss.size(); ++q)
      {
        const double xi = lo + (hi - lo) * gauss.point(q)[0];
        xis.push_back(xi);
        N.push_back(QuadraticFace::line_shape(xi));
        w.push_back((hi - lo) * gauss.weight(q) * line_jacobian(xi));
      }
  }

  // largest |sum_q w psi_j N_k - delta_jk sum_q w N_k| / sum_q w
  template <std::size_t n>
  double
  biorthogonality_error(const std::array<std::array<double, n>, n> &a,
                        const std::vector<std::array<double, n>>   &N,
                        const std::vector<double>                  &w)
  {
    std::array<std::array<double, n>, n> psi_N{};
    std::array<double, n>                D{};
    double                               length = 0;
    for (unsigned int q = 0; q < w.size(); ++q)
      {
        const auto psi = QuadraticFace::dual_values(a, N[q]);
        length += w[q];
        for (unsigned int j = 0; j < n; ++j)
          {
            D[j] += w[q] * N[q][j];
            for (unsigned int k = 0; k < n; ++k)
              psi_N[j][k] += w[q] * psi[j] * N[q][k];
          }
      }
    double worst = 0;
    for (unsigned int j = 0; j < n; ++j)
      for (unsigned int k = 0; k < n; ++k)
        worst = std::max(worst,
                         std::abs(psi_N[j][k] - (j == k ? D[k] : 0.)) / length);
    return worst;
  }
} // namespace

int
main()
{
  initlog();

  // shape functions against deal.II's
  {
    const FE_Q<1> line(2);
    const FE_Q<2> face(2);
    double        worst = 0;
    for (const double t : {0., 0.13, 0.5, 0.71, 1.})
      {
        const auto N = QuadraticFace::line_shape(2 * t - 1);
        for (unsigned int j = 0; j < 3; ++j)
          worst =
            std::max(worst, std::abs(N[j] - line.shape_value(j, Point<1>(t))));
        for (const double s : {0., 0.37, 0.5, 1.})
          {
            const auto M = QuadraticFace::quad_shape(t, s);
            for (unsigned int j = 0; j < 9; ++j)
              worst =
                std::max(worst,
                         std::abs(M[j] - face.shape_value(j, Point<2>(t, s))));
          }
      }
    check_close("shape functions against FE_Q(2) in 1-D and 2-D",
                worst,
                0,
                1e-14);
  }

  // integrals of the shape functions over the reference faces
  {
    const QGauss<1>       gauss(3);
    std::array<double, 3> line{};
    std::array<double, 9> face{};
    for (unsigned int q = 0; q < gauss.size(); ++q)
      {
        const auto N = QuadraticFace::line_shape(2 * gauss.point(q)[0] - 1);
        for (unsigned int j = 0; j < 3; ++j)
          line[j] += gauss.weight(q) * N[j];
        for (unsigned int r = 0; r < gauss.size(); ++r)
          {
            const auto M =
              QuadraticFace::quad_shape(gauss.point(q)[0], gauss.point(r)[0]);
            for (unsigned int j = 0; j < 9; ++j)
              face[j] += gauss.weight(q) * gauss.weight(r) * M[j];
          }
      }
    double worst = 0;
    for (unsigned int j = 0; j < 3; ++j)
      worst = std::max(worst, std::abs(line[j] - (j < 2 ? 1. / 6 : 2. / 3)));
    for (unsigned int j = 0; j < 9; ++j)
      worst = std::max(worst,
                       std::abs(face[j] - (j < 4 ? 1. / 36 :
                                           j < 8 ? 1. / 9 :
                                                   4. / 9)));
    check_close("integrals of N_j: 1/6, 2/3, 1/6 and 1/36, 1/9, 4/9",
                worst,
                0,
                1e-15);
  }

  // the 3-node line, whole and partly covered: built on 3 Gauss points
  // (exact: psi N J has degree 5), checked on 7
  // (lo, hi) of the covered part in [0, 1]: xi = 2 t - 1
  for (const auto &[lo, hi] : {std::pair<double, double>{-1, 1}, {-1, 0.3}})
    {
      std::vector<std::array<double, 3>> N;
      std::vector<double>                w, xis;
      line_rule(3, lo, hi, N, w, xis);
      const auto a = QuadraticFace::dual_coefficients(N, w);
      line_rule(7, lo, hi, N, w, xis);
      const std::string part =
        hi == 1 ? "whole line" : "line covered on xi in [-1, 0.3]";
      check_close("3-node " + part + ": biorthogonality",
                  biorthogonality_error(a, N, w),
                  0,
                  1e-13);
      // f = 1 + xi - 0.4 xi^2, quadratic on the line
      const auto f = [](const double xi) {
        return 1 + xi - 0.4 * xi * xi;
      };
      double worst = 0, sum_error = 0;
      for (unsigned int j = 0; j < 3; ++j)
        {
          double weighted = 0, D = 0;
          for (unsigned int q = 0; q < w.size(); ++q)
            {
              const auto psi = QuadraticFace::dual_values(a, N[q]);
              weighted += w[q] * psi[j] * f(xis[q]);
              D += w[q] * N[q][j];
              sum_error =
                std::max(sum_error, std::abs(psi[0] + psi[1] + psi[2] - 1));
            }
          const double node_xi = j == 0 ? -1. : j == 1 ? 1. : 0.;
          worst = std::max(worst, std::abs(weighted / D - f(node_xi)));
        }
      check_close("3-node " + part +
                    ": D^-1 integral(psi_j f) = f(x_j) for a quadratic f",
                  worst,
                  0,
                  1e-13);
      check_close("3-node " + part + ": sum of psi_j = 1", sum_error, 0, 1e-13);
      // D_jj > 0 on the whole line; on part of it the quadratic N_1 (the
      // node at xi = 1) integrates to a negative weight
      std::array<double, 3> D{};
      for (unsigned int q = 0; q < w.size(); ++q)
        for (unsigned int j = 0; j < 3; ++j)
          D[j] += w[q] * N[q][j];
      if (hi == 1)
        check_true("3-node whole line: every D_jj > 0",
                   D[0] > 0 && D[1] > 0 && D[2] > 0);
      else
        check_close("3-node " + part +
                      ": D_11 (integrated by hand: "
                      "-0.0846408333)",
                    D[1],
                    -0.0846408333333,
                    1e-12);
    }

  // a 9-node parallelogram face (constant Jacobian 0.8): built on 3 x 3
  // Gauss points, checked on 6 x 6, covered on [0, 1] x [0, 0.4]
  for (const double top : {1., 0.4})
    {
      std::vector<std::array<double, 9>> N;
      std::vector<double>                w;
      const auto                         rule = [&](const unsigned int n) {
        const QGauss<1> gauss(n);
        N.clear();
        w.clear();
        for (unsigned int q = 0; q < gauss.size(); ++q)
          for (unsigned int r = 0; r < gauss.size(); ++r)
            {
              N.push_back(QuadraticFace::quad_shape(gauss.point(q)[0],
                                                    top * gauss.point(r)[0]));
              w.push_back(0.8 * top * gauss.weight(q) * gauss.weight(r));
            }
      };
      rule(3);
      const auto a = QuadraticFace::dual_coefficients(N, w);
      rule(6);
      check_close(std::string("9-node face") +
                    (top == 1 ? "" : " covered on eta in [0, 0.4]") +
                    ": biorthogonality",
                  biorthogonality_error(a, N, w),
                  0,
                  1e-13);
    }
}
