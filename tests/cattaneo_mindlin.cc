// Partial slip of a cylinder on a half-space (Cattaneo-Mindlin), mortar
// contact with Coulomb friction, quasi-static, equal materials (E = 1000,
// nu = 0.3, so normal and tangential problems decouple), mu = 0.3: the
// half-cylinder (R = 1) is pressed down by 0.08, giving P and the Hertz
// half-width a = sqrt(4 P R / (pi E*)), then pulled sideways with a
// tangential force Q < mu P. Exact: a central stick zone of half-width
// c = a sqrt(1 - Q / (mu P)) surrounded by slip. Measured: the midpoint
// between the outermost sticking node and the innermost slipping one, on a
// mesh with about 19 active nodes; tolerance 8 % (one node spacing is
// about 14 % of c).
#include <contact_dynamics/contact/surface_contact.h>
#include <contact_dynamics/simulator.h>

#include "tests.h"

#include <cmath>

using namespace dealii;

int
main()
{
  initlog();
  ParameterHandler prm;
  read_test_parameters("cattaneo.prm",
                       R"(
subsection Scene
  set Scene = hertz
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
  set Dirichlet = block_bottom: xy: 0; cylinder_top: x: 0.016*max(t - 1, 0); cylinder_top: y: -0.08*min(t, 1)
end
subsection Time integration
  set Scheme = quasi-static
  set Time step = 0.125
  set End time = 2
end
subsection Nonlinear solver
  set Absolute tolerance = 1e-9
end
subsection Contact
  set Formulation = mortar
  set Pairs = cylinder_arc: block_top
  set Friction coefficients = 0.3
  subsection Mortar
    set c_n = 1e4
    set c_t = 1e3
  end
end
subsection Output
  set Output directory = output_cattaneo
  set VTU interval = 0
end
)",
                       prm);
  std::ostringstream            screen;
  ContactDynamics::Simulator<2> simulator(prm, screen);
  simulator.run();

  const auto *contact =
    dynamic_cast<const ContactDynamics::SurfaceContact<2> *>(
      simulator.get_contact());
  const auto   stats = contact_statistics(*contact);
  const double P     = stats.at("contact_force_y"),
               Q = std::abs(stats.at("contact_force_x")), mu = 0.3;
  const double E_star = 1000 / (2 * (1 - 0.3 * 0.3));
  const double a      = std::sqrt(4 * P / (M_PI * E_star));
  const double c      = a * std::sqrt(1 - Q / (mu * P));

  const auto &surface = contact->secondary_surface(0);
  const auto &nodes   = contact->node_states(0);
  double      sum = 0, moment = 0;
  for (unsigned int j = 0; j < nodes.size(); ++j)
    if (nodes[j].active)
      {
        sum += nodes[j].pressure;
        moment +=
          nodes[j].pressure * surface.position(j, simulator.displacement())[0];
      }
  const double centre      = moment / sum;
  double       outer_stick = 0, inner_slip = 1e300;
  for (unsigned int j = 0; j < nodes.size(); ++j)
    if (nodes[j].active)
      {
        const double r =
          std::abs(surface.position(j, simulator.displacement())[0] - centre);
        if (nodes[j].stick)
          outer_stick = std::max(outer_stick, r);
        else
          inner_slip = std::min(inner_slip, r);
      }
  deallog << std::setprecision(3) << "Q / (mu P) = " << Q / (mu * P)
          << ", a = " << a << ", c exact = " << c << std::endl;
  check_true("a stick zone surrounded by slip",
             outer_stick > 0 && inner_slip < 1e300 && inner_slip > outer_stick);
  const double measured = (outer_stick + inner_slip) / 2;
  check_close("stick zone half-width / exact", measured / c, 1., 0.08);
  deallog << std::setprecision(2)
          << "stick zone half-width error: " << 100 * (measured / c - 1) << " %"
          << std::endl;
}
