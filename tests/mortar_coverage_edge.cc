// Coverage-edge patch test of the dual mortar formulation: the secondary
// surface is the top of the wide lower block of the 'two blocks' scene
// (5 faces of 0.2), the primary one the bottom of the narrow upper block
// [0.25, 0.75] (6 faces), so the primary surface ends inside the secondary
// faces [0.2, 0.4] (covered 3/4) and [0.6, 0.8] (covered 1/4).
//
// Where the pressure is exactly uniform: on an elastic lower block the edge
// of the punch is a stress singularity, so the traction cannot be uniform.
// Held rigid (Dirichlet conditions on its top and bottom), it leaves the
// upper block (nu = 0, pressed down by delta at its top, its left side
// held in x) in a homogeneous state: a uniform pressure
// p = E delta / H = 1e6 1e-3 / 0.5 = 2000 on its whole bottom, which is
// what a traction uniform up to the edge reproduces exactly (the primary
// nodal forces are then those of a uniform pressure, since the dual basis
// of the covered part sums to one). The multipliers lambda_j are the
// traction at every node with a covered support, including the nodes at
// x = 0.2 and 0.8 outside the upper block (their faces are partially
// covered): each must be p to 1e-8; the nodes at x = 0 and 1 have no
// covered support and carry nothing. The total force is p times the
// covered length 0.5.
//
// On the elastic lower block (the physical punch) the traction is not
// uniform, but it must be nowhere tensile.
//
// With elements of degree 2 (3-node faces) on the rigid foundation, with
// the upper block shifted by s = 0, 0.03 and -0.01 (its edges at
// xi = -0.5/0.5, -0.2/0.8 and -0.6/0.4 of the partly covered faces): a
// vertex whose support is covered from the other end beyond the middle
// has a covered integral of N_j that is small or negative (0 at xi = 0.5);
// below 10 % of its whole-face value it leaves the face's multiplier space
// (mortar_contact_quadratic.cc). Every active node must still carry p to
// 1e-8, the load must be p times the covered length 0.5 to 1e-9, and no
// tangential force arises (frictionless).
#include <contact_dynamics/contact/surface_contact.h>
#include <contact_dynamics/simulator.h>

#include "tests.h"

using namespace dealii;

namespace
{
  void
  run(const bool         rigid_foundation,
      const unsigned int degree = 1,
      const double       shift  = 0)
  {
    const std::string name =
      std::string(rigid_foundation ? "rigid foundation" : "punch") +
      (degree == 2 ? ", degree 2, shift " + std::to_string(shift) : "");
    std::ostringstream s_stream;
    s_stream << shift;
    const std::string s_text = s_stream.str();
    ParameterHandler  prm;
    read_test_parameters("edge.prm",
                         std::string(R"(
subsection Scene
  set Scene = two blocks
end
subsection Body upper
  set Young's modulus = 1e6
  set Poisson's ratio = 0
  set Initial displacement = )" + s_text + R"(; 0
end
subsection Finite element
  set Polynomial degree = )" + std::to_string(degree) +
                                     R"(
end
subsection Body lower
  set Young's modulus = 1e6
  set Poisson's ratio = 0
end
subsection Boundary conditions
  set Dirichlet = lower_bottom: xy: 0; upper_top: y: -1e-3*t; upper_left: x: )" + s_text) +
                           (rigid_foundation ? "; lower_top: xy: 0" : "") +
                           R"(
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
  set Pairs = lower_top: upper_bottom
  subsection Mortar
    set c_n = 1e6
  end
end
subsection Output
  set Output directory = output_edge
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
    const auto  &nodes = contact->node_states(0);
    const auto  &s     = contact->secondary_surface(0);
    const double p     = 2000;
    double       worst = 0, lowest = 1e300, outside = 0;
    unsigned int n_active = 0, n_covered = 0;
    for (unsigned int j = 0; j < nodes.size(); ++j)
      {
        const double x = s.reference[j][0];
        lowest         = std::min(lowest, nodes[j].pressure);
        n_active += nodes[j].active;
        if (degree == 2 ? nodes[j].active : (x > 0.1 && x < 0.9))
          {
            ++n_covered;
            worst = std::max(worst, std::abs(nodes[j].pressure - p) / p);
          }
        else
          outside = std::max(outside, std::abs(nodes[j].pressure));
      }
    const auto top = simulator.reaction_force("upper_top");
    deallog << name << ": secondary nodes " << nodes.size() << ", active "
            << n_active << std::endl;
    check_true(name + ": nowhere tensile", lowest >= -1e-9 * p);
    check_close(name + ": no traction at the nodes without covered support",
                outside / p,
                0.,
                1e-12);
    if (rigid_foundation)
      {
        if (degree == 1)
          check_true(name + ": the 4 nodes with covered support are active",
                     n_active == 4 && n_covered == 4);
        else
          check_close(name + ": tangential contact force / load",
                      contact_statistics(*contact).at("contact_force_x") /
                        (p * 0.5),
                      0.,
                      1e-9);
        check_close(name + ": max |lambda_j - p| / p up to the edge",
                    worst,
                    0.,
                    1e-8);
        check_close(name + ": load / (p x 0.5)", -top[1] / (p * 0.5), 1., 1e-9);
        deallog << name << ": measured max relative traction error "
                << (worst < 1e-12 ? "below 1e-12" : "above 1e-12") << std::endl;
      }
    else
      {
        const auto stats = contact_statistics(*contact);
        check_close(name + ": contact force + reaction at the top / load",
                    (stats.at("contact_force_y") - top[1]) / top[1],
                    0.,
                    1e-9);
      }
  }
} // namespace

int
main()
{
  initlog();
  run(true);
  run(false);
  for (const double shift : {0., 0.03, -0.01})
    run(true, 2, shift);
}
