// 3-D friction on symmetry planes: the stacked blocks of the contact patch
// test (non-matching, distorted grids) as a quarter model, both bodies held
// in x on x = 0 and in z on z = 0, the lower one on rollers at its bottom,
// nu = 0.3 and mu = 0.5, pressed by delta = 1e-3. Both blocks are in the
// same uniaxial stress E delta / H (H = 1): they stretch sideways alike,
// nothing slips, and the friction traction is zero everywhere (the
// pressure, a Cauchy traction, is E delta / (1 + nu delta)^2 on the
// widened face). On the symmetry planes the tangential direction normal to
// the plane is held on both sides: its stick row was zero, and the first
// step stopped with "KLU's factorization failed: the matrix is singular"
// (the 3-D ironing half model and the Hertz quarter model with friction
// alike). That direction now carries no friction (doc/contact.md, "3-D
// friction"). Dual mortar reproduces the exact solution to the quadrature
// error; node-to-segment, which fails the patch test already without
// friction, runs and carries the load.
// A direction held on the secondary side only keeps its friction: a block
// whose bottom is driven along x (Dirichlet) slides on a rigid plane (an
// obstacle has no dofs, so that direction's rows lie on held dofs only):
// every node slides, and the friction force is mu times the normal force
// along the drive (the Poisson spreading in z turns a few per mille of it;
// the first version of the held directions dropped it, found in review).
// Then the Hertz quarter model (sphere on block, the same E and nu) with
// and without friction: for elastically similar bodies normal loading
// makes no slip, so friction leaves the load unchanged (Johnson, Contact
// Mechanics, 1985, section 5.4).
#include <contact_dynamics/contact/surface_contact.h>
#include <contact_dynamics/simulator.h>

#include "tests.h"

using namespace dealii;

namespace
{
  const ContactDynamics::SurfaceContact<3> &
  surface_contact(const ContactDynamics::Simulator<3> &simulator)
  {
    return dynamic_cast<const ContactDynamics::SurfaceContact<3> &>(
      *simulator.get_contact());
  }

  void
  patch_test(const std::string &formulation)
  {
    ParameterHandler prm;
    read_shipped(
      "prm/examples/patch_test_3d.prm",
      {{"Body upper/Poisson's ratio", "0.3"},
       {"Body lower/Poisson's ratio", "0.3"},
       {"Boundary conditions/Dirichlet",
        "lower_bottom: y: 0; upper_top: y: -1e-3*t; upper_left: x: 0; "
        "lower_left: x: 0; upper_front: z: 0; lower_front: z: 0"},
       {"Nonlinear solver/Absolute tolerance", "1e-11"},
       {"Contact/Formulation", formulation},
       {"Contact/Friction coefficients", "0.5"},
       {"Contact/Mortar/Segment quadrature points", "4"},
       {"Contact/Node to segment/c_n", "1e6"},
       {"Output/Output directory", "output_symmetry_" + formulation},
       {"Output/VTU interval", "0"}},
      prm);
    std::ostringstream            screen;
    ContactDynamics::Simulator<3> simulator(prm, screen);
    simulator.run();

    const double exact = 1000 / std::pow(1 + 0.3e-3, 2);
    double       p_min = 1e300, p_max = 0, t_max = 0;
    unsigned int n_active = 0;
    const auto  &contact  = surface_contact(simulator);
    const auto  &nodes    = contact.node_states(0);
    for (unsigned int j = 0; j < nodes.size(); ++j)
      if (nodes[j].active)
        {
          ++n_active;
          p_min = std::min(p_min, nodes[j].pressure);
          p_max = std::max(p_max, nodes[j].pressure);
          t_max = std::max(t_max,
                           std::hypot(nodes[j].tangential[0],
                                      nodes[j].tangential[1]));
        }
    const auto top = simulator.reaction_force("upper_top");
    deallog.push(formulation);
    deallog << "active nodes " << n_active << " of " << nodes.size()
            << std::endl;
    check_true("every secondary node active", n_active == nodes.size());
    check_close("load / (E delta area)", -top[1] / 1000, 1., 1e-2);
    if (formulation == "mortar")
      {
        check_close("max pressure / (E delta / (1 + nu delta)^2)",
                    p_max / exact,
                    1.,
                    1e-8);
        check_close("min pressure / (E delta / (1 + nu delta)^2)",
                    p_min / exact,
                    1.,
                    1e-8);
        check_close("max |friction traction| / pressure",
                    t_max / exact,
                    0.,
                    1e-8);
      }
    deallog.pop();
  }

  void
  driven_on_obstacle()
  {
    ParameterHandler prm;
    read_test_parameters("driven.prm",
                         R"(
set Dimension = 3
subsection Scene
  set Scene = block
  subsection Block
    set Origin       = 0, 0, 0
    set Size         = 1, 0.2, 1
    set Subdivisions = 4, 2, 4
  end
end
subsection Body body
  set Material model  = linear elastic
  set Young's modulus = 1e6
  set Poisson's ratio = 0.3
end
subsection Boundary conditions
  set Dirichlet = top: y: -1e-3*t; bottom: x: 1e-2*t
end
subsection Time integration
  set Scheme    = quasi-static
  set Time step = 0.5
  set End time  = 1
end
subsection Contact
  set Formulation           = mortar
  set Rigid obstacles       = ground
  set Pairs                 = bottom: ground
  set Friction coefficients = 0.3
  subsection Rigid obstacle ground
    set Shape  = plane
    set Point  = 0, 0, 0
    set Normal = 0, 1, 0
  end
end
subsection Output
  set Output directory = output_symmetry_driven
  set VTU interval     = 0
end
)",
                         prm);
    std::ostringstream            screen;
    ContactDynamics::Simulator<3> simulator(prm, screen);
    simulator.run();
    const auto stats = contact_statistics(*simulator.get_contact());
    deallog << "driven block: contact force " << stats.at("contact_force_x")
            << ", " << stats.at("contact_force_y") << std::endl;
    check_close("driven block: |friction force| / (mu normal force)",
                std::abs(stats.at("contact_force_x")) /
                  (0.3 * stats.at("contact_force_y")),
                1.,
                1e-2);
  }

  double
  hertz_load(const double mu)
  {
    ParameterHandler prm;
    read_shipped("prm/examples/hertz_3d.prm",
                 {{"Scene/Refinement factor", "0.5"},
                  {"Contact/Friction coefficients", std::to_string(mu)},
                  {"Output/Output directory", "output_symmetry_hertz"},
                  {"Output/VTU interval", "0"}},
                 prm);
    std::ostringstream            screen;
    ContactDynamics::Simulator<3> simulator(prm, screen);
    simulator.run();
    return -simulator.reaction_force("sphere_top")[1];
  }
} // namespace

int
main()
{
  initlog();
  patch_test("mortar");
  patch_test("nts");
  driven_on_obstacle();
  const double frictionless = hertz_load(0), with_friction = hertz_load(0.3);
  deallog << "Hertz quarter model: load " << frictionless << " frictionless, "
          << with_friction << " with mu = 0.3" << std::endl;
  check_close("Hertz: load with friction / frictionless load",
              with_friction / frictionless,
              1.,
              5e-3);
}
