// Quasi-static uniaxial stretch of a neo-Hookean block in plane strain to
// lambda_1 = 1.5 in 10 load steps, with rollers on the left and bottom and
// the top free. Closed form: F = diag(l1, l2, 1) with l2 from
//   P_22 = mu (l2 - 1/l2) + lambda ln(l1 l2) / l2 = 0,
// then sigma_11 = (mu (l1^2 - 1) + lambda ln J) / J, W = mu/2 (l1^2 + l2^2
// - 2) - mu ln J + lambda/2 (ln J)^2. The homogeneous deformation is in the
// finite element space, so the discrete solution must reproduce it.
#include <deal.II/numerics/vector_tools.h>

#include <contact_dynamics/simulator.h>

#include "tests.h"

#include <cmath>

using namespace dealii;

int
main()
{
  initlog();
  const double E = 10, nu = 0.3;
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
  const double mu     = E / (2 * (1 + nu));
  const double l1     = 1.5;

  // the lateral stretch, by scalar Newton on P_22(l2) = 0
  double l2 = 1;
  for (unsigned int it = 0; it < 50; ++it)
    {
      const double f = mu * (l2 - 1 / l2) + lambda * std::log(l1 * l2) / l2;
      const double df =
        mu * (1 + 1 / (l2 * l2)) + lambda * (1 - std::log(l1 * l2)) / (l2 * l2);
      l2 -= f / df;
    }
  const double J       = l1 * l2;
  const double sigma11 = (mu * (l1 * l1 - 1) + lambda * std::log(J)) / J;
  const double W       = 0.5 * mu * (l1 * l1 + l2 * l2 - 2) - mu * std::log(J) +
                   0.5 * lambda * std::log(J) * std::log(J);

  ParameterHandler prm;
  read_test_parameters("uniaxial.prm",
                       R"(
subsection Scene
  set Scene = block
  subsection Block
    set Size = 1, 1
    set Subdivisions = 2, 2
  end
end
subsection Body body
  set Material model = neo-Hookean
  set Young's modulus = 10
  set Poisson's ratio = 0.3
end
subsection Boundary conditions
  set Dirichlet = left: x: 0; bottom: y: 0; right: x: 0.5*t
end
subsection Time integration
  set Scheme = quasi-static
  set Time step = 0.1
  set End time = 1
end
subsection Nonlinear solver
  set Absolute tolerance = 1e-12
end
subsection Output
  set Output directory = output_uniaxial
  set VTU interval = 0
end
)",
                       prm);
  std::ostringstream            screen;
  ContactDynamics::Simulator<2> simulator(prm, screen);
  simulator.run();

  check_close("final time", simulator.current_time(), 1., 1e-12);
  Vector<double> corner(2);
  VectorTools::point_value(simulator.get_dof_handler(),
                           simulator.displacement(),
                           Point<2>(1, 1),
                           corner);
  check_close("u_x at (1,1) = l1 - 1", corner(0), l1 - 1, 1e-10);
  check_close("u_y at (1,1) = l2 - 1", corner(1), l2 - 1, 1e-10);

  std::vector<Tensor<1, 2>> gradient(2);
  VectorTools::point_gradient(simulator.get_dof_handler(),
                              simulator.displacement(),
                              Point<2>(0.3, 0.6),
                              gradient);
  Tensor<2, 2> grad_u;
  grad_u[0] = gradient[0];
  grad_u[1] = gradient[1];
  ContactDynamics::MaterialParameters p;
  p.model          = ContactDynamics::MaterialParameters::Model::neo_hookean;
  p.youngs_modulus = E;
  p.poissons_ratio = nu;
  const auto         material = ContactDynamics::create_material<2>(p);
  const Tensor<2, 3> sigma    = material->cauchy_stress(grad_u);
  check_close("sigma_11 / closed form", sigma[0][0] / sigma11, 1., 1e-9);
  check_close("sigma_22 (free surface) / sigma_11",
              sigma[1][1] / sigma11,
              0.,
              1e-9);
  check_close("elastic energy / closed form",
              simulator.energy().elastic / W,
              1.,
              1e-9);
  // quasi-static: the boundary work (trapezoidal in load steps) approximates
  // the stored energy to O(load step^2)
  check_close("external work / stored energy",
              simulator.energy().external / simulator.energy().elastic,
              1.,
              5e-3);
  deallog << "lateral stretch l2 = " << l2 << ", sigma_11 = " << sigma11
          << std::endl;
}
