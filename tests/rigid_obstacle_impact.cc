// A block (E = 1e4, nu = 0.3, rho = 1, 1 x 0.5) flies at 1 onto a rigid plane
// 0.005 below it, hits it, bounces off and flies away, 2-D, mortar and
// node-to-segment with persistency (held gaps): the impact and the release
// of the stabilized contact. Asserted against mechanics outside the code:
// - no energy is created: the energy balance error (kinetic + elastic -
//   initial, no external work, nothing dissipated) stays below 1 % of the
//   initial kinetic energy at every step (the static formulations create
//   energy at release);
// - the block leaves the plane: at the end no node is in contact and the
//   block's mean vertical velocity is upward, at most the impact speed
//   (momentum: the plane only pushes);
// - the impulse of the plane on the block equals the change of its
//   momentum, m (v_end - v_0) = int F dt (trapezoidal, as Newmark
//   integrates it: 1e-8; measured 8e-12).
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
    read_test_parameters("impact.prm",
                         R"(
subsection Scene
  set Scene = block
  subsection Block
    set Origin       = 0, 0
    set Size         = 1, 0.5
    set Subdivisions = 8, 4
  end
end
subsection Body body
  set Young's modulus = 1e4
  set Poisson's ratio = 0.3
  set Density = 1
  set Initial velocity = 0; -1
end
subsection Time integration
  set Time step = 0.0005
  set End time = 0.03
end
subsection Contact
  set Formulation = )" + formulation +
                           R"(
  set Rigid obstacles = floor
  set Pairs = bottom: floor
  subsection Rigid obstacle floor
    set Shape = plane
    set Point = 0, -0.005
  end
  subsection Mortar
    set c_n = 1e4
    set Stabilization = persistency
  end
  subsection Node to segment
    set c_n = 1e4
    set Stabilization = persistency
  end
end
subsection Output
  set Output directory = output_impact
  set VTU interval = 0
end
)",
                         prm);
    std::ostringstream            screen;
    ContactDynamics::Simulator<2> simulator(prm, screen);
    simulator.initialize();
    const double dt = 0.0005, mass = 0.5, v0 = -1;
    const double kinetic0 = 0.5 * mass * v0 * v0;
    double       worst = 0, impulse = 0, previous_force = 0;
    unsigned int max_active = 0, active = 0;
    while (simulator.current_time() < 0.03 - 1e-9)
      {
        if (!simulator.advance(dt))
          check_true(formulation + ": step converged", false);
        const auto stats = contact_statistics(*simulator.get_contact());
        // the force on the block is minus the force on the plane
        const double force = -stats.at("floor_force_y");
        impulse += 0.5 * (force + previous_force) * dt;
        previous_force = force;
        active         = std::lround(stats.at("active_contact_nodes"));
        max_active     = std::max(max_active, active);
        worst          = std::max(worst, simulator.energy().error() / kinetic0);
      }
    const double v_end = mean_velocity(simulator, 0, 1);
    check_true(formulation + ": the block hit the plane with all its bottom",
               max_active == 9);
    check_true(formulation + ": it has left the plane", active == 0);
    check_range(formulation + ": rebound speed / impact speed",
                v_end / -v0,
                0.,
                1.);
    check_range(formulation + ": energy created / initial kinetic energy",
                worst,
                -1.,
                0.01);
    check_range(formulation + ": plane's impulse / change of momentum - 1",
                impulse / (mass * (v_end - v0)) - 1,
                -1e-8,
                1e-8);
  }
} // namespace

int
main()
{
  initlog();
  run("mortar");
  run("nts");
}
