// 3-D contact on a mesh read from Gmsh with named physical groups: the
// shipped prm/examples/gmsh_3d.prm (two stacked blocks, the interface
// faces 3 x 3 below and 2 x 2 above, not matching; E = 1e6, nu = 0,
// frictionless dual mortar, quasi-static, the upper top pushed down by
// 1e-3, the lower bottom clamped). The exact solution is a uniform stress:
// the contact pressure is E delta / H = 1e6 1e-3 / 1.5 at every secondary
// node (flat parallelogram faces: the mortar integrals are exact).
// Asserted: every nodal pressure to 1e-8, the contact force on the upper
// block against the pressure times the area (1) and against the reaction
// at the upper top (equilibrium), the bodies and surfaces named from the
// file's physical groups.
#include <contact_dynamics/contact/surface_contact.h>
#include <contact_dynamics/simulator.h>

#include "tests.h"

#include <fstream>
#include <sstream>

using namespace dealii;

int
main()
{
  initlog();
  const std::string source = std::string(SOURCE_DIR) + "/../prm/examples/";
  std::ifstream     in(source + "gmsh_3d.prm");
  std::stringstream text;
  text << in.rdbuf();
  std::string prm_text = text.str();
  const auto  replace  = [&](const std::string &from, const std::string &to) {
    const auto pos = prm_text.find(from);
    AssertThrow(pos != std::string::npos, ExcMessage(from));
    prm_text.replace(pos, from.size(), to);
  };
  replace("prm/examples/two_blocks_3d.msh", source + "two_blocks_3d.msh");
  replace("output/gmsh_3d", "output_gmsh_3d");

  ParameterHandler prm;
  read_test_parameters("gmsh_3d.prm", prm_text, prm);
  std::ostringstream            screen;
  ContactDynamics::Simulator<3> simulator(prm, screen);
  simulator.initialize();
  while (simulator.current_time() < 1 - 1e-9)
    if (!simulator.advance(0.5))
      check_true("step converged", false);

  const auto *contact =
    dynamic_cast<const ContactDynamics::SurfaceContact<3> *>(
      simulator.get_contact());
  const double exact = 1e6 * 1e-3 / 1.5;
  double       worst = 0;
  for (const auto &node : contact->node_states(0))
    worst = std::max(worst, std::abs(node.pressure - exact) / exact);
  deallog << "secondary nodes: " << contact->node_states(0).size() << std::endl;
  check_close("max |pressure - E delta / H| / (E delta / H)", worst, 0., 1e-8);
  const auto stats = contact_statistics(*contact);
  check_close("contact force on the upper block / (p A)",
              stats.at("contact_force_y") / exact,
              1.,
              1e-8);
  check_close("reaction at the upper top / contact force",
              -simulator.reaction_force("upper_top")[1] /
                stats.at("contact_force_y"),
              1.,
              1e-8);
}
