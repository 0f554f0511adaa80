// Coulomb friction, quasi-static: the upper block of the patch-test scene
// (nu = 0, E = 1e6) is pressed onto the lower one (normal force about
// E delta = 1000 for delta = 1e-3 over the total height 1) and then its top
// is pulled sideways by u(t), up to 2e-3, well beyond the stick limit
// (a shear stiffness of at most G = E/2 reaches mu N = 300 at u = 6e-4):
// - at a small tangential force (T < mu N / 2) the interface sticks: no slip
//   node, and no relative tangential motion at sticking nodes (the edges of
//   the interface, where the free sides concentrate the traction, start to
//   slip before T reaches mu N, as in Cattaneo's problem);
// - once every node slips, each node's traction obeys Coulomb's law,
//   |lambda_t| = mu lambda_n, to solver tolerance, and T approaches mu N
//   (up to the tilt of the deformed normals);
// - the energy balance with the frictional dissipation counted closes: the
//   work of the support = stored energy + frictional dissipation.
// For the mortar and the node-to-segment formulations. Then dynamics: the
// upper block, pressed by its weight, slides with an initial velocity and is
// braked by friction; the kinetic energy it loses is the frictional
// dissipation (the energy balance closes to 1e-3 of it), and its mean
// deceleration is mu g.
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
    read_test_parameters("friction.prm",
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
  set Dirichlet = lower_bottom: xy: 0; upper_top: y: -1e-3*min(t, 1); upper_top: x: 1e-3*max(t - 1, 0)
end
subsection Time integration
  set Scheme = quasi-static
  set Time step = 0.05
  set End time = 3
end
subsection Nonlinear solver
  set Absolute tolerance = 1e-9
end
subsection Contact
  set Formulation = )" + formulation +
                           R"(
  set Pairs = upper_bottom: lower_top
  set Friction coefficients = 0.3
  subsection Mortar
    set c_n = 1e6
    set c_t = 1e4
  end
  subsection Node to segment
    set c_n = 1e6
    set c_t = 1e4
  end
end
subsection Output
  set Output directory = output_friction
  set VTU interval = 0
end
)",
                         prm);
    std::ostringstream            screen;
    ContactDynamics::Simulator<2> simulator(prm, screen);
    simulator.initialize();
    const double mu = 0.3;
    const auto  *contact =
      dynamic_cast<const ContactDynamics::SurfaceContact<2> *>(
        simulator.get_contact());
    bool   stuck_phase = false, slid_phase = false;
    double worst_stick_slip = 0, worst_slip_ratio = 0;
    double worst_force_ratio = 0, onset = -1;
    while (simulator.current_time() < 3 - 1e-9)
      {
        if (!simulator.advance(0.05))
          check_true(formulation + ": step converged", false);
        const auto   stats = contact_statistics(*simulator.get_contact());
        const double T     = std::abs(stats.at("contact_force_x"));
        const double N     = stats.at("contact_force_y");
        if (simulator.current_time() > 1 + 1e-9 && T < 0.5 * mu * N)
          {
            stuck_phase = true;
            if (stats.at("slip_nodes") != 0)
              check_true(formulation + ": no slip node below mu N / 2", false);
          }
        for (const auto &node : contact->node_states(0))
          if (node.stick)
            worst_stick_slip =
              std::max(worst_stick_slip, std::abs(node.slip_rate) * 0.05);
        if (stats.at("stick_nodes") == 0 && stats.at("slip_nodes") > 0)
          {
            slid_phase = true;
            worst_force_ratio =
              std::max(worst_force_ratio, std::abs(T / (mu * N) - 1));
            for (const auto &node : contact->node_states(0))
              if (node.active)
                worst_slip_ratio = std::max(worst_slip_ratio,
                                            std::abs(std::abs(node.tangential) /
                                                       (mu * node.pressure) -
                                                     1));
          }
        if (stats.at("slip_nodes") > 0 && onset < 0)
          onset = T / (mu * N);
      }
    deallog << formulation
            << ": first slip node at T / (mu N) = " << std::setprecision(2)
            << onset << std::endl;
    check_true(formulation + ": a stick phase and a slip phase",
               stuck_phase && slid_phase);
    check_close(formulation + ": slip increment of sticking nodes",
                worst_stick_slip,
                0.,
                1e-12);
    check_close(formulation + ": |lambda_t| / (mu lambda_n) - 1 at slipping "
                              "nodes",
                worst_slip_ratio,
                0.,
                1e-8);
    check_close(formulation + ": T / (mu N) - 1 while all nodes slip",
                worst_force_ratio,
                0.,
                5e-3);
    const auto &e = simulator.energy();
    check_true(formulation + ": friction dissipates", e.frictional > 0);
    check_close(formulation + ": energy balance error / dissipation",
                e.error() / e.frictional,
                0.,
                1e-3);
  }
} // namespace

void
braking(const std::string &formulation)
{
  // rho = 1, g = 10: weight 5 per unit length on the interface of length 1
  ParameterHandler prm;
  read_test_parameters("braking.prm",
                       R"(
subsection Scene
  set Scene = patch test
end
subsection Body upper
  set Young's modulus = 1e4
  set Poisson's ratio = 0.3
  set Body force = 0, -10
  set Initial velocity = 0.5; 0
  set Rayleigh stiffness coefficient = 1e-3
end
subsection Body lower
  set Young's modulus = 1e4
  set Poisson's ratio = 0.3
  set Rayleigh stiffness coefficient = 1e-3
end
subsection Boundary conditions
  set Dirichlet = lower_bottom: xy: 0
end
subsection Time integration
  set Time step = 0.005
  set End time = 0.1
end
subsection Contact
  set Formulation = )" + formulation +
                         R"(
  set Pairs = upper_bottom: lower_top
  set Friction coefficients = 0.3
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
  set Output directory = output_braking
  set VTU interval = 0
end
)",
                       prm);
  std::ostringstream            screen;
  ContactDynamics::Simulator<2> simulator(prm, screen);
  simulator.initialize();
  for (unsigned int n = 0; n < 20; ++n)
    if (!simulator.advance(0.005))
      check_true(formulation + " braking: step converged", false);
  const auto &e = simulator.energy();
  check_true(formulation + " braking: friction dissipates", e.frictional > 0);
  check_close(formulation + " braking: energy balance error / dissipation",
              e.error() / e.frictional,
              0.,
              1e-3);
  check_close(formulation + " braking: deceleration / (mu g)",
              (0.5 - mean_velocity_x(simulator, 0)) / 0.1 / 3.,
              1.,
              0.05);
}

int
main()
{
  initlog();
  run("mortar");
  run("nts");
  braking("mortar");
  braking("nts");
}
