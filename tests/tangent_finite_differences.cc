// The consistent tangent against central finite differences:
// 1. dP/dF of each material model against differences of P(F);
// 2. the global Newton Jacobian (inertia, Rayleigh damping, neo-Hookean
//    stiffness) against differences of the global residual, at a random
//    large-deformation state, for Newmark, generalized-alpha, HHT-alpha
//    and quasi-statics.
#include <deal.II/base/tensor.h>

#include <contact_dynamics/mechanics/material.h>
#include <contact_dynamics/simulator.h>

#include "tests.h"

#include <random>

using namespace dealii;

namespace
{
  void
  check_material(const std::string &model)
  {
    ContactDynamics::MaterialParameters p;
    p.model          = ContactDynamics::MaterialParameters::model_named(model);
    p.youngs_modulus = 3.;
    p.poissons_ratio = 0.3;
    const auto material = ContactDynamics::create_material<2>(p);

    Tensor<2, 2> grad_u;
    grad_u[0][0] = 0.2;
    grad_u[0][1] = -0.15;
    grad_u[1][0] = 0.3;
    grad_u[1][1] = -0.1;
    Tensor<2, 2> P;
    Tensor<4, 2> A;
    double       W;
    material->evaluate(grad_u, P, A, W);

    const double h     = 1e-6;
    double       worst = 0, worst_energy = 0;
    for (unsigned int k = 0; k < 2; ++k)
      for (unsigned int l = 0; l < 2; ++l)
        {
          Tensor<2, 2> plus = grad_u, minus = grad_u, Pp, Pm;
          plus[k][l] += h;
          minus[k][l] -= h;
          Tensor<4, 2> dummy;
          double       Wp, Wm;
          material->evaluate(plus, Pp, dummy, Wp);
          material->evaluate(minus, Pm, dummy, Wm);
          // dW/dF = P
          worst_energy =
            std::max(worst_energy, std::abs((Wp - Wm) / (2 * h) - P[k][l]));
          for (unsigned int i = 0; i < 2; ++i)
            for (unsigned int j = 0; j < 2; ++j)
              worst = std::max(worst,
                               std::abs((Pp[i][j] - Pm[i][j]) / (2 * h) -
                                        A[i][j][k][l]));
        }
    check_close(model + ": |dP/dF - finite differences| / E",
                worst / 3.,
                0.,
                1e-8);
    check_close(model + ": |dW/dF - P| / E", worst_energy / 3., 0., 1e-8);
  }

  void
  check_jacobian(const std::string &scheme)
  {
    dealii::ParameterHandler prm;
    read_test_parameters("jacobian.prm",
                         R"(
subsection Scene
  set Scene = block
  subsection Block
    set Size = 1, 0.6
    set Subdivisions = 4, 3
  end
end
subsection Body body
  set Material model = neo-Hookean
  set Young's modulus = 100
  set Poisson's ratio = 0.35
  set Density = 3
  set Rayleigh mass coefficient = 0.3
  set Rayleigh stiffness coefficient = 0.02
  set Body force = 1, -2
  set Initial velocity = 0.3*y; -0.2*x
end
subsection Time integration
  set Scheme = )" + scheme +
                           R"(
end
subsection Output
  set Output directory = output_jacobian
  set VTU interval = 0
end
)",
                         prm);
    std::ostringstream            screen;
    ContactDynamics::Simulator<2> simulator(prm, screen);
    simulator.initialize();

    using ContactDynamics::VectorType;
    VectorType trial(simulator.displacement()), direction(trial),
      residual(trial), residual_plus(trial), residual_minus(trial), jd(trial);
    std::mt19937                           rng(42);
    std::uniform_real_distribution<double> uniform(-1., 1.);
    for (auto &x : trial)
      x += 0.05 * uniform(rng);
    for (auto &x : direction)
      x = uniform(rng);

    const double dt = 0.01, h = 1e-6;
    VectorType   shifted(trial);
    shifted.add(h, direction);
    simulator.residual_and_jacobian(shifted, dt, residual_plus);
    shifted.add(-2 * h, direction);
    simulator.residual_and_jacobian(shifted, dt, residual_minus);
    const auto &jacobian = simulator.residual_and_jacobian(trial, dt, residual);

    jacobian.vmult(jd, direction);
    VectorType fd(residual_plus);
    fd -= residual_minus;
    fd /= 2 * h;
    const double norm = jd.l2_norm();
    fd -= jd;
    check_close(scheme + ": |J d - finite differences| / |J d|",
                fd.l2_norm() / norm,
                0.,
                1e-7);
  }
} // namespace

int
main()
{
  initlog();
  check_material("linear elastic");
  check_material("neo-Hookean");
  check_jacobian("newmark");
  // the mass factor (1 - alpha_m) / ((1 - alpha_f) beta dt^2) and the
  // balance with the committed forces (rho_inf = 0.8)
  check_jacobian("generalized-alpha");
  check_jacobian("hht-alpha");
  check_jacobian("quasi-static");
}
