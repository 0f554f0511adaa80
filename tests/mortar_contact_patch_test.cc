// Contact patch test (shared/reference/benchmarks.md section 3): two
// stacked blocks with non-matching meshes (7 and 5 elements across), nu = 0,
// the lower one clamped at its bottom, the upper one pressed down by
// delta = 1e-3 at its top. The exact solution is a uniform stress
// -E delta / H in both blocks (H = 1), so the contact pressure is
// E delta = 1000 at every secondary node, which dual mortar with segment
// integration must reproduce to solver tolerance; the contact force equals
// the applied load and the two sides' forces cancel.
#include <contact_dynamics/contact/mortar_contact.h>
#include <contact_dynamics/simulator.h>

#include "tests.h"

using namespace dealii;

int
main()
{
  initlog();
  ParameterHandler prm;
  read_test_parameters("patch.prm",
                       R"(
subsection Scene
  set Scene = patch test
end
subsection Body upper
  set Young's modulus = 1e6
  set Poisson's ratio = 0
end
subsection Body lower
  set Young's modulus = 1e6
  set Poisson's ratio = 0
end
subsection Boundary conditions
  set Dirichlet = lower_bottom: xy: 0; upper_top: y: -1e-3*t
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
  set Formulation = mortar
  set Pairs = upper_bottom: lower_top
  subsection Mortar
    set c_n = 1e6
  end
end
subsection Output
  set Output directory = output_patch
  set VTU interval = 0
end
)",
                       prm);
  std::ostringstream            screen;
  ContactDynamics::Simulator<2> simulator(prm, screen);
  simulator.run();

  const auto *mortar = dynamic_cast<const ContactDynamics::MortarContact<2> *>(
    simulator.get_contact());
  const double exact = 1000;
  double       worst = 0;
  unsigned int n_active = 0;
  for (const auto &node : mortar->node_states(0))
    {
      worst = std::max(worst, std::abs(node.pressure - exact));
      n_active += node.active;
    }
  deallog << "secondary nodes: " << mortar->node_states(0).size()
          << ", active: " << n_active << std::endl;
  check_close("max |pressure - E delta| / (E delta)", worst / exact, 0., 1e-8);
  // informational (numdiff compares values below 1e-6 as equal)
  deallog << "measured relative pressure error: " << worst / exact << std::endl;
  const auto stats = simulator.get_contact()->statistics();
  check_close("contact force on the upper block / applied load",
              stats[2] / exact,
              1.,
              1e-8);
  check_close("tangential contact force / applied load",
              stats[1] / exact,
              0.,
              1e-8);
}
