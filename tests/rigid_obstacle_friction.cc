// A block dragged by a moving rigid plane (an obstacle with no mesh and no
// unknowns), 2-D, mortar and node-to-segment, Coulomb friction mu = 0.3:
// the block (rho = 1, weight 5 per unit length, E = 1e4) starts at rest on
// the plane y = 0, which moves along x at V = 1 (Translation = t; 0, the
// plane's velocity by central differences). The block slips throughout
// (its speed mu g t stays below V), so Newton's law with Coulomb's force
// mu m g gives the acceleration mu g = 3. Asserted:
// - the block's mean acceleration over 0.1 s is mu g within 3 % (the
//   normal force starts at 0 and oscillates about the weight);
// - the friction force on the plane is -mu N on average (Coulomb; 3 %);
// - the energy balance closes with the plane's work on the block and the
//   dissipation on both sides of the interface (conservation law, 1e-3 of
//   the plane's work): the kinetic energy gained is the plane's work minus
//   the frictional dissipation, and both are positive.
#include <contact_dynamics/contact/surface_contact.h>
#include <contact_dynamics/simulator.h>

#include "tests.h"

using namespace dealii;

namespace
{
  void
  run(const std::string &formulation)
  {
    ParameterHandler prm;
    read_test_parameters("dragged.prm",
                         R"(
subsection Scene
  set Scene = block
  subsection Block
    set Origin       = 0, 0
    set Size         = 1, 0.5
    set Subdivisions = 4, 2
  end
end
subsection Body body
  set Young's modulus = 1e4
  set Poisson's ratio = 0.3
  set Body force = 0, -10
  set Rayleigh stiffness coefficient = 1e-3
end
subsection Time integration
  set Time step = 0.005
  set End time = 0.1
end
subsection Contact
  set Formulation = )" + formulation +
                           R"(
  set Rigid obstacles = belt
  set Pairs = bottom: belt
  set Friction coefficients = 0.3
  subsection Rigid obstacle belt
    set Shape       = plane
    set Point       = 0, 0
    set Normal      = 0, 1
    set Translation = t; 0
  end
  subsection Mortar
    set c_n = 1e4
    set c_t = 100
  end
  subsection Node to segment
    set c_n = 1e4
    set c_t = 100
    set Stabilization = persistency
  end
end
subsection Output
  set Output directory = output_dragged
  set VTU interval = 0
end
)",
                         prm);
    std::ostringstream            screen;
    ContactDynamics::Simulator<2> simulator(prm, screen);
    simulator.initialize();
    const double mu = 0.3, g = 10, dt = 0.005;
    double       friction = 0, normal = 0;
    for (unsigned int n = 0; n < 20; ++n)
      {
        if (!simulator.advance(dt))
          check_true(formulation + ": step converged", false);
        const auto stats = contact_statistics(*simulator.get_contact());
        friction += stats.at("belt_force_x");
        normal += stats.at("belt_force_y");
      }
    const double t = 20 * dt;
    check_range(formulation + ": acceleration / (mu g) - 1",
                mean_velocity_x(simulator, 0) / t / (mu * g) - 1,
                -0.03,
                0.03);
    check_range(formulation + ": mean friction force on the plane / "
                              "(-mu N) - 1",
                friction / (mu * std::abs(normal)) + 1,
                -0.03,
                0.03);
    const auto &e = simulator.energy();
    check_true(formulation + ": the plane works, friction dissipates",
               e.obstacle > 0 && e.frictional > 0);
    check_close(formulation + ": energy balance error / plane's work",
                e.error() / e.obstacle,
                0.,
                1e-3);
  }
} // namespace

int
main()
{
  initlog();
  run("mortar");
  run("nts");
}
