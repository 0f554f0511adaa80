// Hertz contact of a cylinder on a half-space (plane strain), frictionless,
// quasi-static, linear elastic, equal materials (E = 1000, nu = 0.3), the
// flat face of the half-cylinder (R = 1) pushed down by 0.02. From the
// measured load P per unit length: E* = E / (2 (1 - nu^2)),
// a = sqrt(4 P R / (pi E*)), p0 = 2 P / (pi a), p(x) = p0 sqrt(1 - x^2/a^2).
// The half-width is measured from the second moment of the nodal pressures
// (a^2 = 4 int p x^2 / int p for the Hertz profile), with the nodal weights
// integral(N_j) of the current configuration. Checked at two mesh
// refinements: within a few percent, and the errors decrease; and the
// node-to-segment formulation (nodal pressure = nodal force / tributary
// length) on the finer mesh.
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
  run(const double factor, const std::string &formulation = "mortar")
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
  set Time step = 0.25
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
    deallog << std::setprecision(3) << formulation << ", factor " << factor
            << ": P = " << P << ", a = " << a << ", p0 = " << p0 << std::endl;
    check_close(formulation + ", factor " + std::to_string(factor) +
                  ": sum of nodal forces / P",
                m0 / P,
                1.,
                5e-3);
    return {a_h / a - 1, peak / p0 - 1, std::sqrt(num / den)};
  }
} // namespace

int
main()
{
  initlog();
  const Errors coarse = run(0.5);
  const Errors fine   = run(1);
  for (const auto &e :
       {std::make_pair("coarse", coarse), std::make_pair("fine", fine)})
    {
      check_close(std::string(e.first) + ": half-width error within 5 %",
                  e.second.half_width,
                  0.,
                  0.05);
      check_close(std::string(e.first) + ": peak pressure error within 3 %",
                  e.second.peak,
                  0.,
                  0.03);
      check_close(std::string(e.first) + ": profile L2 error within 6 %",
                  e.second.profile,
                  0.,
                  0.06);
    }
  check_true("half-width error decreases with refinement",
             std::abs(fine.half_width) < std::abs(coarse.half_width));
  check_true("profile error decreases with refinement",
             fine.profile < coarse.profile);
  const Errors nts = run(1, "nts");
  check_close("nts: half-width error within 5 %", nts.half_width, 0., 0.05);
  check_close("nts: peak pressure error within 3 %", nts.peak, 0., 0.03);
  check_close("nts: profile L2 error within 6 %", nts.profile, 0., 0.06);
  deallog << std::setprecision(2)
          << "nts errors (half-width, peak, profile): " << 100 * nts.half_width
          << "% " << 100 * nts.peak << "% " << 100 * nts.profile << "%"
          << std::endl;
  deallog << std::setprecision(2) << "errors (half-width, peak, profile): "
          << "coarse " << 100 * coarse.half_width << "% " << 100 * coarse.peak
          << "% " << 100 * coarse.profile << "%, fine " << 100 * fine.half_width
          << "% " << 100 * fine.peak << "% " << 100 * fine.profile << "%"
          << std::endl;
}
