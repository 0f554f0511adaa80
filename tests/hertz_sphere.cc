// Hertz contact of a sphere on a half-space in 3-D (the 'hertz' scene in
// 3-D: a quarter of the sphere's cap and of the block, with the symmetry
// planes x = 0 and z = 0 held normally), frictionless, quasi-static,
// linear elastic, equal materials (E = 1000, nu = 0.3, R = 1), the top of
// the cap pushed down by 0.012 in one load step. Reference: Hertz's
// solution for the measured load P (four times the quarter's contact
// force; analytic): E* = E / (2 (1 - nu^2)), a = (3 P R / (4 E*))^(1/3),
// p0 = 3 P / (2 pi a^2), p(r) = p0 sqrt(1 - r^2/a^2). The contact radius is
// measured from the second moment of the nodal pressures (a^2 = 5/2
// int p r^2 / int p for the Hertz profile), with the nodal weights
// integral(N_j) of the current configuration. What is asserted:
// - convergence: mortar at refinement factors 0.75 and 1 (fine cells of
//   R/30 and R/40: 3.4 and 4.5 per contact radius); the L2 error of the
//   pressure profile falls by at least a factor 1.2 (order 1/2 over this
//   step, what the square-root edge of the Hertz pressure allows);
// - at factor 1, a and p0 within 3 % of Hertz's and the profile within
//   6 % (a/R = 0.11: Hertz's formulas for these finite bodies are good to
//   about 1 %);
// - the nodal forces add up to the load P (0.5 %; equilibrium);
// - node-to-segment (nodal pressure = nodal force / current tributary
//   area) on the same mesh agrees with mortar: contact radius within 1
//   point, peak within 3 % of Hertz's.
// The measured values are in the file "measured" beside "output" and in
// doc/testing.md.
#include <contact_dynamics/contact/surface_contact.h>
#include <contact_dynamics/simulator.h>

#include "tests.h"

#include <cmath>

using namespace dealii;

namespace
{
  struct Errors
  {
    double radius, peak, profile;
  };

  Errors
  run(const double factor, const std::string &formulation = "mortar")
  {
    ParameterHandler prm;
    read_test_parameters("hertz_sphere.prm",
                         R"(
set Dimension = 3
subsection Scene
  set Scene = hertz
  set Refinement factor = )" +
                           std::to_string(factor) +
                           R"(
  subsection Hertz
    set Block width  = 2
    set Block height = 1
  end
end
subsection Body sphere
  set Young's modulus = 1000
  set Poisson's ratio = 0.3
end
subsection Body block
  set Young's modulus = 1000
  set Poisson's ratio = 0.3
end
subsection Boundary conditions
  set Dirichlet = block_bottom: xyz: 0; block_left: x: 0; block_front: z: 0; sphere_left: x: 0; sphere_front: z: 0; sphere_top: y: -0.012*t
end
subsection Time integration
  set Scheme = quasi-static
  set Time step = 1
  set End time = 1
end
subsection Nonlinear solver
  set Absolute tolerance = 1e-9
end
subsection Contact
  set Formulation = )" + formulation +
                           R"(
  set Pairs = sphere_bottom: block_top
  subsection Mortar
    set c_n = 1e4
    set Jacobian = approximate
  end
  subsection Node to segment
    set c_n = 1e4
    set Jacobian = approximate
  end
end
subsection Output
  set Output directory = output_hertz_sphere
  set VTU interval = 0
end
)",
                         prm);
    std::ostringstream            screen;
    ContactDynamics::Simulator<3> simulator(prm, screen);
    simulator.run();
    const auto *contact =
      dynamic_cast<const ContactDynamics::SurfaceContact<3> *>(
        simulator.get_contact());
    const auto  &surface = contact->secondary_surface(0);
    const auto  &nodes   = contact->node_states(0);
    const auto  &u       = simulator.displacement();
    const double P =
      4 * contact_statistics(*simulator.get_contact()).at("contact_force_y");

    const double E = 1000, nu = 0.3, R = 1;
    const double E_star = E / (2 * (1 - nu * nu));
    const double a      = std::cbrt(3 * P * R / (4 * E_star));
    const double p0     = 3 * P / (2 * M_PI * a * a);

    // the area a node's pressure acts on: integral of N_j over the covered
    // part of the surface (mortar), or for nts (whose pressure output is
    // the nodal force lambda_j integral(N_j) over the current area) the
    // reference integral(N_j) times the change of the quarters of the
    // node's faces
    const auto weight = [&](const unsigned int j) {
      if (formulation != "nts")
        return nodes[j].weight;
      double current = 0, reference = 0;
      for (const unsigned int f : surface.node_faces[j])
        {
          const auto &face = surface.faces[f];
          const auto  x    = [&](const unsigned int k) {
            return surface.position(face[k], u);
          };
          const auto X = [&](const unsigned int k) {
            return surface.reference[face[k]];
          };
          current += cross_product_3d(x(3) - x(0), x(2) - x(1)).norm();
          reference += cross_product_3d(X(3) - X(0), X(2) - X(1)).norm();
        }
      return surface.reference_weight[j] * current / reference;
    };
    const auto radius2 = [&](const unsigned int j) {
      const Point<3> x = surface.position(j, u);
      return x[0] * x[0] + x[2] * x[2];
    };
    double m0 = 0, m2 = 0, peak = 0;
    for (unsigned int j = 0; j < nodes.size(); ++j)
      {
        const double w = weight(j);
        m0 += nodes[j].pressure * w;
        m2 += nodes[j].pressure * w * radius2(j);
        peak = std::max(peak, nodes[j].pressure);
      }
    const double a_h = std::sqrt(2.5 * m2 / m0);
    double       num = 0, den = 0;
    for (unsigned int j = 0; j < nodes.size(); ++j)
      {
        const double exact = p0 * std::sqrt(std::max(0., 1 - radius2(j) / (a * a)));
        const double w     = weight(j);
        num += w * std::pow(nodes[j].pressure - exact, 2);
        den += w * exact * exact;
      }
    const std::string name =
      formulation + ", factor " + Utilities::to_string(factor);
    record_measured(name + ": P", P, 0, 0);
    record_measured(name + ": Hertz a", a, 0, 0);
    record_measured(name + ": Hertz p0", p0, 0, 0);
    check_range(name + ": sum of nodal forces / P - 1",
                4 * m0 / P - 1,
                -5e-3,
                5e-3);
    return {a_h / a - 1, peak / p0 - 1, std::sqrt(num / den)};
  }
} // namespace

int
main()
{
  initlog();
  const Errors coarse = run(0.75);
  const Errors fine   = run(1);
  const Errors nts    = run(1, "nts");
  for (const auto &e : {std::make_pair(std::string("mortar, factor 0.75"), coarse),
                        std::make_pair(std::string("mortar, factor 1"), fine),
                        std::make_pair(std::string("nts, factor 1"), nts)})
    {
      record_measured(e.first + ": contact radius error", e.second.radius, 0, 0);
      record_measured(e.first + ": peak pressure error", e.second.peak, 0, 0);
      record_measured(e.first + ": profile L2 error", e.second.profile, 0, 0);
    }
  check_range("mortar: profile L2 error, factor 0.75 / factor 1",
              coarse.profile / fine.profile,
              1.2,
              1e9);
  check_range("mortar, factor 1: contact radius error",
              fine.radius,
              -0.03,
              0.03);
  check_range("mortar, factor 1: peak pressure error", fine.peak, -0.03, 0.03);
  check_range("mortar, factor 1: profile L2 error", fine.profile, 0., 0.06);
  check_range("nts - mortar, factor 1: contact radius error",
              nts.radius - fine.radius,
              -0.01,
              0.01);
  check_range("nts, factor 1: peak pressure error", nts.peak, -0.03, 0.03);
}
