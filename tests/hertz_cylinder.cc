// Hertz contact of a cylinder on a half-space (plane strain), frictionless,
// quasi-static, linear elastic, equal materials (E = 1000, nu = 0.3), the
// flat face of the half-cylinder (R = 1) pushed down by 0.02 in one load
// step (frictionless: the same state as in four steps). Reference:
// Hertz's solution for the measured load P per unit length (analytic;
// ../shared/reference/benchmarks.md section 3): E* = E / (2 (1 - nu^2)),
// a = sqrt(4 P R / (pi E*)), p0 = 2 P / (pi a), p(x) = p0 sqrt(1 - x^2/a^2).
// The half-width is measured from the second moment of the nodal pressures
// (a^2 = 4 int p x^2 / int p for the Hertz profile), with the nodal weights
// integral(N_j) of the current configuration. What is asserted:
// - convergence: mortar on two meshes (refinement factor 1 and 2: 4.3 and
//   8.7 elements per contact half-width); the L2 error of the pressure
//   profile falls by at least a factor 1.4 (an order of at least 1/2, what
//   the square-root edge of the Hertz pressure allows; measured 1.76, order
//   0.8); an error that does not vanish with the mesh (a wrong force, a
//   wrong weight) fails it;
// - on the finer mesh the half-width and the peak pressure are within
//   2.5 % of Hertz's and the profile within 3.5 % (measured -1.24 %, +1.48 %,
//   2.5 %; about 1 % is the model error of Hertz's formulas for these
//   finite bodies, a / R = 0.1): a 10 % error in the pressures or the
//   half-width fails;
// - the nodal forces add up to the load P (0.5 %; equilibrium);
// - the node-to-segment formulation (nodal pressure = nodal force /
//   tributary length) on the coarser mesh agrees with mortar on the same
//   mesh: profile error within 1 percentage point and half-width within
//   0.5 point of mortar's (an independent discretization; measured
//   4.67 % against 4.43 %, -0.09 % against -0.07 %), peak within 2.5 %.
// - elements of degree 2 (mortar on 3-node curved faces), on factors 0.5
//   and 1 (the nodes of degree 1 on 1 and 2): the same bounds on the finer
//   mesh (measured -1.70 %, +1.94 %, 1.98 %: the profile closer than degree
//   1's at the same nodes) and the profile error falling by at least 1.4
//   (measured 2.46); node-to-segment of degree 2 agrees with mortar of
//   degree 2 on factor 0.5 as for degree 1.
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
    double half_width, peak, profile;
  };

  Errors
  run(const double       factor,
      const std::string &formulation = "mortar",
      const unsigned int degree      = 1)
  {
    ParameterHandler prm;
    read_test_parameters("hertz.prm",
                         R"(
subsection Scene
  set Scene = hertz
  set Refinement factor = )" +
                           std::to_string(factor) +
                           R"(
end
subsection Body cylinder
  set Young's modulus = 1000
  set Poisson's ratio = 0.3
end
subsection Body block
  set Young's modulus = 1000
  set Poisson's ratio = 0.3
end
subsection Boundary conditions
  set Dirichlet = block_bottom: xy: 0; cylinder_top: x: 0; cylinder_top: y: -0.02*t
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
  set Pairs = cylinder_arc: block_top
  subsection Mortar
    set c_n = 1e4
  end
  subsection Node to segment
    set c_n = 1e4
  end
end
subsection Finite element
  set Polynomial degree = )" + std::to_string(degree) +
                           R"(
end
subsection Output
  set Output directory = output_hertz
  set VTU interval = 0
end
)",
                         prm);
    std::ostringstream            screen;
    ContactDynamics::Simulator<2> simulator(prm, screen);
    simulator.run();
    const auto *mortar =
      dynamic_cast<const ContactDynamics::SurfaceContact<2> *>(
        simulator.get_contact());
    const auto  &surface = mortar->secondary_surface(0);
    const auto  &nodes   = mortar->node_states(0);
    const double P =
      contact_statistics(*simulator.get_contact()).at("contact_force_y");

    const double E = 1000, nu = 0.3, R = 1;
    const double E_star = E / (2 * (1 - nu * nu));
    const double a      = std::sqrt(4 * P * R / (M_PI * E_star));
    const double p0     = 2 * P / (M_PI * a);

    // tributary length of a node: integral of N_j over the covered part of
    // the surface (mortar), or half its current faces (nts, whose pressure
    // output is the nodal force over that length)
    const auto weight = [&](const unsigned int j) {
      if (formulation != "nts")
        return nodes[j].weight;
      if (degree == 2) // (integral N_j)
        return surface.current_weight(j, simulator.displacement());
      double length = 0;
      for (const unsigned int f : surface.node_faces[j])
        {
          double l;
          surface.face_box(f, simulator.displacement(), l);
          length += l / 2;
        }
      return length;
    };
    double m0 = 0, m1 = 0, m2 = 0, peak = 0;
    for (unsigned int j = 0; j < nodes.size(); ++j)
      {
        const double x = surface.position(j, simulator.displacement())[0];
        const double w = weight(j);
        m0 += nodes[j].pressure * w;
        m1 += nodes[j].pressure * w * x;
        m2 += nodes[j].pressure * w * x * x;
        peak = std::max(peak, nodes[j].pressure);
      }
    const double centre = m1 / m0;
    const double a_h    = std::sqrt(4 * (m2 / m0 - centre * centre));
    double       num = 0, den = 0;
    for (unsigned int j = 0; j < nodes.size(); ++j)
      {
        const double r =
          (surface.position(j, simulator.displacement())[0] - centre) / a;
        const double exact = p0 * std::sqrt(std::max(0., 1 - r * r));
        const double w     = weight(j);
        num += w * std::pow(nodes[j].pressure - exact, 2);
        den += w * exact * exact;
      }
    const std::string name =
      formulation + (degree == 2 ? " degree 2" : "") + ", factor " +
      Utilities::to_string(factor);
    record_measured(name + ": P", P, 0, 0);
    record_measured(name + ": Hertz a", a, 0, 0);
    record_measured(name + ": Hertz p0", p0, 0, 0);
    check_range(name + ": sum of nodal forces / P - 1", m0 / P - 1, -5e-3, 5e-3);
    return {a_h / a - 1, peak / p0 - 1, std::sqrt(num / den)};
  }
} // namespace

int
main()
{
  initlog();
  const Errors coarse = run(1);
  const Errors fine   = run(2);
  const Errors nts    = run(1, "nts");
  const Errors coarse_2 = run(0.5, "mortar", 2);
  const Errors fine_2   = run(1, "mortar", 2);
  const Errors nts_2    = run(0.5, "nts", 2);
  for (const auto &e :
       {std::make_pair(std::string("mortar, factor 1"), coarse),
        std::make_pair(std::string("mortar, factor 2"), fine),
        std::make_pair(std::string("nts, factor 1"), nts),
        std::make_pair(std::string("mortar degree 2, factor 0.5"), coarse_2),
        std::make_pair(std::string("mortar degree 2, factor 1"), fine_2),
        std::make_pair(std::string("nts degree 2, factor 0.5"), nts_2)})
    {
      record_measured(e.first + ": half-width error", e.second.half_width, 0, 0);
      record_measured(e.first + ": peak pressure error", e.second.peak, 0, 0);
      record_measured(e.first + ": profile L2 error", e.second.profile, 0, 0);
    }
  check_range("mortar: profile L2 error, factor 1 / factor 2",
              coarse.profile / fine.profile,
              1.4,
              1e9);
  check_range("mortar, factor 2: half-width error", fine.half_width, -0.025, 0.025);
  check_range("mortar, factor 2: peak pressure error", fine.peak, -0.025, 0.025);
  check_range("mortar, factor 2: profile L2 error", fine.profile, 0., 0.035);
  check_range("nts - mortar, factor 1: profile L2 error",
              nts.profile - coarse.profile,
              -0.01,
              0.01);
  check_range("nts - mortar, factor 1: half-width error",
              nts.half_width - coarse.half_width,
              -0.005,
              0.005);
  check_range("nts, factor 1: peak pressure error", nts.peak, -0.025, 0.025);
  // degree 2 (3-node curved faces) on the same nodes as degree 1 on
  // factors 1 and 2
  check_range("mortar degree 2: profile L2 error, factor 0.5 / factor 1",
              coarse_2.profile / fine_2.profile,
              1.4,
              1e9);
  check_range("mortar degree 2, factor 1: half-width error",
              fine_2.half_width,
              -0.025,
              0.025);
  check_range("mortar degree 2, factor 1: peak pressure error",
              fine_2.peak,
              -0.025,
              0.025);
  check_range("mortar degree 2, factor 1: profile L2 error",
              fine_2.profile,
              0.,
              0.035);
  check_range("nts - mortar degree 2, factor 0.5: profile L2 error",
              nts_2.profile - coarse_2.profile,
              -0.01,
              0.01);
  check_range("nts - mortar degree 2, factor 0.5: half-width error",
              nts_2.half_width - coarse_2.half_width,
              -0.005,
              0.005);
}
