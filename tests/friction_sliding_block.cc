// Coulomb friction (mu = 0.3), mortar and node-to-segment. What is asserted,
// and against what (none of it is the Coulomb branch equation that the
// solver enforces node by node):
// 1. Quasi-static: the upper block of the patch-test scene (nu = 0,
//    E = 1e6) is pressed onto the lower one (normal force
//    E delta = 1000 for delta = 1e-3 over the total height 1) and then its
//    top is pulled sideways by u(t) = 1e-3 (t - 1), up to 2e-3. In the stick
//    phase the tangential force grows as 3.1e5 u (measured), so the stick
//    limit mu N = 300 is near u = 1e-3; gross sliding is t >= 2.5
//    (u >= 1.5e-3):
//    - at a small tangential force (T < mu N / 2) the interface sticks: no
//      slip node (the edges, where the free sides concentrate the traction,
//      start to slip before T reaches mu N, as in Cattaneo's problem;
//      first slip node at T = 0.72 mu N);
//    - in gross sliding every node slips, and the lower block's support,
//      which carries the friction force through the whole lower block
//      (equilibrium; reactions from the bulk residual, not from the contact
//      forces), gives |R_x| / R_y = mu within 2 % (measured -0.22 %, the
//      tilt of the deformed normals);
//    - the frictional dissipation over the gross sliding is the friction
//      force times the slip distance: the blocks' shear is then constant,
//      so the interface slips at the speed of the pulled top (1e-3), and
//      D(3) - D(2.5) = mu int R_y du_top within 2 % (measured -0.15 %);
//    - the energy balance with the frictional dissipation counted closes
//      (conservation law; 1e-3 of the dissipation).
// 2. Dynamics: the upper block (rho = 1, weight 5 per unit length) slides
//    with an initial velocity 0.5 and is braked by friction for 0.1 s:
//    - its mean deceleration is mu g = 3 (Newton's law with Coulomb's
//      force mu m g; within 3 %, measured -1.0 %: the normal force starts
//      at 0 and oscillates about the weight);
//    - the frictional dissipation equals the time integral of the friction
//      force mu N times the slip rate, N the normal contact force and the
//      slip rate the difference of the two sides' mean velocities along
//      the interface (trapezoidal rule over the steps; within 3 %,
//      measured +0.43 %);
//    - the energy balance closes (1e-3 of the dissipation): the kinetic
//      energy lost is the frictional dissipation.
// The measured values are in the file "measured" beside "output" and in
// doc/testing.md.
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
    const double mu = 0.3, pull_rate = 1e-3, dt = 0.05;
    bool         stuck_phase = false, all_slip = true;
    double       onset = -1, worst_ratio = 0, dissipation_start = -1;
    double       expected_dissipation = 0, previous_Ry = 0;
    while (simulator.current_time() < 3 - 1e-9)
      {
        if (!simulator.advance(dt))
          check_true(formulation + ": step converged", false);
        const double t     = simulator.current_time();
        const auto   stats = contact_statistics(*simulator.get_contact());
        const double T     = std::abs(stats.at("contact_force_x"));
        const double N     = stats.at("contact_force_y");
        if (t > 1 + 1e-9 && T < 0.5 * mu * N)
          {
            stuck_phase = true;
            if (stats.at("slip_nodes") != 0)
              check_true(formulation + ": no slip node below mu N / 2", false);
          }
        if (stats.at("slip_nodes") > 0 && onset < 0)
          onset = T / (mu * N);
        // the lower block's support carries the interface forces
        const auto   R  = simulator.reaction_force("lower_bottom");
        const double Ry = std::abs(R[1]);
        if (t > 2.5 - 1e-9)
          {
            all_slip = all_slip && stats.at("stick_nodes") == 0 &&
                       stats.at("slip_nodes") > 0;
            worst_ratio =
              std::max(worst_ratio, std::abs(std::abs(R[0]) / (mu * Ry) - 1));
            if (dissipation_start < 0)
              dissipation_start = simulator.energy().frictional;
            else
              // friction force mu N times the top's displacement in the step
              expected_dissipation +=
                mu * 0.5 * (Ry + previous_Ry) * pull_rate * dt;
          }
        previous_Ry = Ry;
      }
    deallog << formulation
            << ": first slip node at T / (mu N) = " << std::setprecision(2)
            << onset << std::endl;
    check_true(formulation + ": a stick phase below mu N / 2", stuck_phase);
    check_true(formulation + ": every node slips in gross sliding", all_slip);
    check_range(formulation + ": support |R_x| / (mu R_y) - 1 in gross "
                              "sliding",
                worst_ratio,
                0.,
                0.02);
    const auto &e = simulator.energy();
    check_range(formulation + ": dissipation / (mu int R_y du_top) - 1",
                (e.frictional - dissipation_start) / expected_dissipation - 1,
                -0.02,
                0.02);
    check_close(formulation + ": energy balance error / dissipation",
                e.error() / e.frictional,
                0.,
                1e-3);
  }

  // Mean x velocity of the body's boundary faces at reference height y (the
  // interface), weighted by face length: the slip rate is the difference of
  // the two sides.
  double
  interface_velocity_x(const ContactDynamics::Simulator<2> &simulator,
                       const unsigned int                   body,
                       const double                         y)
  {
    double sum = 0, length = 0;
    for (const auto &cell : simulator.get_dof_handler().active_cell_iterators())
      if (cell->material_id() == body)
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              std::abs(cell->face(f)->center()[1] - y) < 1e-9)
            for (unsigned int v = 0; v < 2; ++v)
              {
                sum += cell->face(f)->measure() / 2 *
                       simulator.velocity()(cell->face(f)->vertex_dof_index(v, 0));
                length += cell->face(f)->measure() / 2;
              }
    return sum / length;
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
  // mu N times the slip rate (upper minus lower mean velocity), trapezoidal
  const double mu = 0.3, g = 10, v0 = 0.5, dt = 0.005;
  double       friction_power = 0, integral = 0;
  for (unsigned int n = 0; n < 20; ++n)
    {
      if (!simulator.advance(dt))
        check_true(formulation + " braking: step converged", false);
      const double N = contact_statistics(*simulator.get_contact())
                         .at("contact_force_y");
      const double power =
        mu * std::abs(N) *
        std::abs(interface_velocity_x(simulator, 0, 0.5) -
                 interface_velocity_x(simulator, 1, 0.5));
      integral += 0.5 * (friction_power + power) * dt;
      friction_power = power;
    }
  const double t = 20 * dt;
  const auto  &e = simulator.energy();
  check_true(formulation + " braking: friction dissipates", e.frictional > 0);
  check_close(formulation + " braking: energy balance error / dissipation",
              e.error() / e.frictional,
              0.,
              1e-3);
  check_range(formulation + " braking: deceleration / (mu g) - 1",
              (v0 - mean_velocity_x(simulator, 0)) / t / (mu * g) - 1,
              -0.03,
              0.03);
  check_range(formulation + " braking: dissipation / int mu N v_slip dt - 1",
              e.frictional / integral - 1,
              -0.03,
              0.03);
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
