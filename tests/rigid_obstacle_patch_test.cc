// Contact patch test against a rigid plane (an obstacle with no mesh and no
// unknowns), 2-D and 3-D, mortar and node-to-segment, quasi-static: a
// block (E = 1e6, nu = 0, height H = 1, base area A = 1) stands on the
// plane y = 0; its top is held laterally and pushed down by 1e-3 until
// t = 1, then held while the plane rises by another 1e-3 until t = 2. The
// exact solution is a uniform stress: the contact pressure is E delta / H
// at every secondary node, with delta the total shortening. Asserted
// against that solution and against mechanics outside the code:
// - every nodal pressure equals E delta / H to 1e-8 (both formulations: a
//   plane and a uniform pressure leave nothing to interpolate);
// - the reaction on the plane is -E delta A / H along y, its torque about
//   the plane's point (the origin, moved) is that of the uniform pressure
//   over the base (2-D: -p A / 2; 3-D: (p A / 2, 0, -p A / 2));
// - the work the rising plane does on the block is the elastic energy it
//   adds, E A (delta_2^2 - delta_1^2) / (2 H) = 1.5 (linear in time:
//   trapezoidal rule exact), and the energy balance closes to 1e-9.
// With elements of degree 1 and 2 (issue 41: then the mid-side nodes, and
// in 3-D the face centres, are contact nodes too, with weights 1/6, 2/3 or
// 1/36, 1/9, 4/9 of a face; each must carry the same pressure).
#include <contact_dynamics/contact/surface_contact.h>
#include <contact_dynamics/simulator.h>

#include "tests.h"

using namespace dealii;

namespace
{
  template <int dim>
  void
  run(const std::string &formulation, const unsigned int degree)
  {
    const std::string d3   = dim == 3 ? ", 1" : "";
    const std::string name = std::to_string(dim) + "-D " + formulation +
                             (degree == 2 ? ", degree 2" : "") + ": ";
    ParameterHandler prm;
    read_test_parameters("obstacle_patch.prm",
                         "set Dimension = " + std::to_string(dim) + R"(
subsection Finite element
  set Polynomial degree = )" +
                           std::to_string(degree) +
                           R"(
end
subsection Scene
  set Scene = block
  subsection Block
    set Origin       = 0, 0)" +
                           (dim == 3 ? ", 0" : "") + R"(
    set Size         = 1, 1)" +
                           d3 + R"(
    set Subdivisions = 5, 3)" +
                           (dim == 3 ? ", 4" : "") + R"(
  end
end
subsection Body body
  set Young's modulus = 1e6
  set Poisson's ratio = 0
end
subsection Boundary conditions
  set Dirichlet = top: x)" +
                           (dim == 3 ? "z" : "") +
                           R"(: 0; top: y: -1e-3*min(t, 1)
end
subsection Time integration
  set Scheme    = quasi-static
  set Time step = 0.5
  set End time  = 2
end
subsection Nonlinear solver
  set Absolute tolerance = 1e-9
end
subsection Contact
  set Formulation     = )" +
                           formulation + R"(
  set Rigid obstacles = ground
  set Pairs           = bottom: ground
  subsection Rigid obstacle ground
    set Shape       = plane
    set Point       = 0, 0)" +
                           (dim == 3 ? ", 0" : "") + R"(
    set Normal      = 0, 1)" +
                           (dim == 3 ? ", 0" : "") + R"(
    set Translation = 0; 1e-3*max(t - 1, 0))" +
                           (dim == 3 ? "; 0" : "") + R"(
  end
end
subsection Output
  set Output directory = output_obstacle_patch
  set VTU interval     = 0
end
)",
                         prm);
    std::ostringstream              screen;
    ContactDynamics::Simulator<dim> simulator(prm, screen);
    simulator.initialize();
    const double E = 1e6, H = 1, A = 1;
    double       worst = 0, worst_force = 0, worst_torque = 0;
    while (simulator.current_time() < 2 - 1e-9)
      {
        if (!simulator.advance(0.5))
          check_true(name + "step converged", false);
        const double t     = simulator.current_time();
        const double delta = 1e-3 * (std::min(t, 1.) + std::max(t - 1, 0.));
        const double p     = E * delta / H;
        const auto  *contact =
          dynamic_cast<const ContactDynamics::SurfaceContact<dim> *>(
            simulator.get_contact());
        for (const auto &node : contact->node_states(0))
          worst = std::max(worst, std::abs(node.pressure - p) / p);
        const auto stats = contact_statistics(*contact);
        worst_force =
          std::max(worst_force,
                   std::abs(stats.at("ground_force_y") + p * A) / (p * A));
        if (dim == 2)
          worst_torque =
            std::max(worst_torque,
                     std::abs(stats.at("ground_torque") + p * A / 2) / p);
        else
          worst_torque =
            std::max({worst_torque,
                      std::abs(stats.at("ground_torque_x") - p * A / 2) / p,
                      std::abs(stats.at("ground_torque_y")) / p,
                      std::abs(stats.at("ground_torque_z") + p * A / 2) / p});
      }
    const auto *contact =
      dynamic_cast<const ContactDynamics::SurfaceContact<dim> *>(
        simulator.get_contact());
    // every node of the bottom (5 or 5 x 4 faces): 6 or 6 x 5 vertices,
    // 11 or 11 x 9 nodes of degree 2
    check_true(name + "every bottom node a contact node",
               contact->node_states(0).size() == (dim == 2 ?
                                                    (degree == 1 ? 6u : 11u) :
                                                    (degree == 1 ? 30u : 99u)));
    check_close(name + "max |pressure - E delta / H| / (E delta / H)",
                worst,
                0.,
                1e-8);
    check_close(name + "reaction on the plane / (-E delta A / H) - 1",
                worst_force,
                0.,
                1e-8);
    check_close(name + "torque on the plane, error / (E delta / H)",
                worst_torque,
                0.,
                1e-8);
    const auto &e = simulator.energy();
    check_close(name + "work of the rising plane / (E A (d2^2 - d1^2) / 2H)",
                e.obstacle / (E * A * (4e-6 - 1e-6) / (2 * H)),
                1.,
                1e-8);
    check_close(name + "energy balance error / elastic energy",
                e.error() / e.elastic,
                0.,
                1e-9);
    record_measured(name + "pressure error", worst, 0., 1e-8);
  }
} // namespace

int
main()
{
  initlog();
  for (const std::string formulation : {"mortar", "nts"})
    {
      for (const unsigned int degree : {1u, 2u})
        {
          run<2>(formulation, degree);
          run<3>(formulation, degree);
        }
    }
}
