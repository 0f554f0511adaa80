// The contact rows of the Jacobian against a rigid obstacle (automatic
// differentiation through the signed distance, its normal, the dual basis
// of the face and the obstacle's velocity field) against central finite
// differences of the residual: a block whose bottom is bent and perturbed
// at random, pressed onto a rigid circle (2-D) or sphere (3-D) of radius 1
// that translates and spins, so that nodes near the top of the obstacle
// are active and those farther out are not; mortar and node-to-segment,
// quasi-static (the weighted gaps and the variationally consistent normal
// force with its second derivatives), after one dynamic step (the
// persistency rows of held nodes, with the obstacle's velocity) and with
// Coulomb friction (mu = 0.3, random tangential multipliers so that some
// active nodes stick and some slip: the slip rates relative to the moving
// obstacle, the nodal tangents of its normal). Repeated with elements of
// degree 2 (issue 41): the bent bottom is then a curved 3-node or 9-node
// face, its mid-side and centre nodes are contact nodes, and the mortar
// patch is integrated on the curved face with its own dual basis.
#include <contact_dynamics/contact/surface_contact.h>
#include <contact_dynamics/simulator.h>

#include "tests.h"

#include <random>

using namespace dealii;
using ContactDynamics::VectorType;

namespace
{
  template <int dim>
  std::string
  parameters(const std::string &formulation,
             const std::string &scheme,
             const bool         friction,
             const unsigned int degree)
  {
    const bool three   = dim == 3;
    const bool dynamic = scheme != "quasi-static";
    // the block starts 0.03 into the obstacle: near its top the nodes are
    // active, farther out (x = 1/3) they are 0.03 away
    const std::string z = three ? ", -0.5" : "";
    return "set Dimension = " + std::to_string(dim) + R"(
subsection Finite element
  set Polynomial degree = )" +
           std::to_string(degree) + R"(
end
subsection Scene
  set Scene = block
  subsection Block
    set Origin       = -0.5, 0)" +
           z + R"(
    set Size         = 1, 0.5)" +
           (three ? ", 1" : "") + R"(
    set Subdivisions = 6, 2)" +
           (three ? ", 5" : "") + R"(
  end
end
subsection Body body
  set Young's modulus = 1000
  set Poisson's ratio = 0.3
  set Density = 1
  set Initial displacement = 0.001*x; )" +
           "-0.03 + 0.03*x*x" +
           (three ? " + 0.02*z*z + 0.004*x*z; 0.002*z" : "") + R"(
  set Initial velocity = 0; )" +
           (dynamic ? "-1" : "0") + (three ? "; 0" : "") + R"(
end
subsection Boundary conditions
  set Dirichlet = top: )" +
           (three ? "xyz" : "xy") + R"(: 0
end
subsection Time integration
  set Scheme = )" +
           scheme + R"(
  set Time step = 0.01
end
subsection Contact
  set Formulation = )" +
           formulation + R"(
  set Rigid obstacles = ball
  set Pairs = bottom: ball
  set Initial penetration = allow
  set Friction coefficients = )" +
           (friction ? "0.3" : "0") + R"(
  subsection Rigid obstacle ball
    set Shape          = )" +
           (three ? "sphere" : "cylinder") + R"(
    set Point          = 0, -1)" +
           (three ? ", 0" : "") + R"(
    set Radius         = 1
    set Translation    = 0.1*t; 0.02*t)" +
           (three ? "; 0.05*t" : "") + R"(
    set Rotation angle = 0.5*t
)" + (three ? "    set Rotation axis = 0.2, 1, 0.1\n" : "") +
           R"(  end
  subsection Mortar
    set c_n = 1e3
    set c_t = 1
    set Stabilization = persistency
  end
  subsection Node to segment
    set c_n = 1e3
    set c_t = 1
    set Stabilization = persistency
  end
end
subsection Output
  set Output directory = output_obstacle_jacobian
  set VTU interval = 0
end
)";
  }

  template <int dim>
  void
  check(const std::string &formulation,
        const std::string &scheme,
        const bool         held,
        const bool         friction,
        const unsigned int degree = 1)
  {
    const std::string name = std::to_string(dim) + "-D " + formulation + ", " +
                             scheme + (friction ? ", friction" : "") +
                             (degree == 2 ? ", degree 2 (curved faces)" : "");
    ParameterHandler prm;
    read_test_parameters("obstacle_jacobian.prm",
                         parameters<dim>(formulation, scheme, friction, degree),
                         prm);
    std::ostringstream              screen;
    ContactDynamics::Simulator<dim> simulator(prm, screen);
    simulator.initialize();
    if (held)
      check_true(name + ": first step converges", simulator.advance(0.01));
    const auto &normal = simulator.get_contact()->multiplier_dofs();
    const std::set<types::global_dof_index> lambda(normal.begin(),
                                                   normal.end());
    const auto                             *contact =
      dynamic_cast<const ContactDynamics::SurfaceContact<dim> *>(
        simulator.get_contact());
    std::set<types::global_dof_index> tangential;
    for (const auto &dofs : contact->secondary_surface(0).dofs)
      for (unsigned int c = dim + 1; c < 2 * dim; ++c)
        tangential.insert(dofs[c]);
    std::mt19937                           rng(7);
    std::uniform_real_distribution<double> uniform(-1., 1.);
    VectorType trial(simulator.displacement()), direction(trial), mask(trial);
    mask = 0.;
    for (unsigned int i = 0; i < trial.size(); ++i)
      if (lambda.count(i))
        {
          trial(i) =
            tangential.count(i) ? 20 * uniform(rng) : 20 * (1.5 + uniform(rng));
          direction(i) = 10 * uniform(rng);
          mask(i)      = 1. + uniform(rng);
        }
      else
        {
          trial(i) += 1e-4 * uniform(rng);
          direction(i) = 1e-3 * uniform(rng);
        }
    simulator.get_constraints().set_zero(direction);

    VectorType r(trial);
    const auto errors = contact_row_errors(simulator,
                                           trial,
                                           direction,
                                           mask,
                                           lambda,
                                           1e-6,
                                           0.01,
                                           r);
    const auto [n_active, n_held, n_stick] =
      count_node_states(contact->node_states(0));
    deallog << name << ": multiplier rows " << errors.n_multiplier_rows
            << ", force rows " << errors.n_force_rows << ", active nodes "
            << n_active << " of " << contact->node_states(0).size()
            << std::endl;
    check_true(name + ": some nodes active, some not",
               n_active >= 3 && n_active < contact->node_states(0).size());
    if (held)
      check_true(name + ": held nodes in the checked state", n_held >= 3);
    if (friction)
      check_true(name + ": some active nodes stick, some slip",
                 n_stick >= 1 && n_active - n_stick >= 1);
    check_close(name + ": multiplier rows |J d - FD| / |J d|",
                errors.multiplier_rows,
                0.,
                1e-6);
    check_close(name + ": force rows |J d - FD| / |J d|",
                errors.force_rows,
                0.,
                1e-6);
  }
} // namespace

int
main()
{
  initlog();
  for (const std::string formulation : {"mortar", "nts"})
    {
      check<2>(formulation, "quasi-static", false, false);
      check<2>(formulation, "newmark", true, false);
      check<2>(formulation, "quasi-static", false, true);
      check<3>(formulation, "quasi-static", false, false);
      check<3>(formulation, "newmark", true, true);
      check<2>(formulation, "quasi-static", false, false, 2);
      check<2>(formulation, "newmark", true, false, 2);
      check<2>(formulation, "quasi-static", false, true, 2);
      check<3>(formulation, "quasi-static", false, false, 2);
      check<3>(formulation, "newmark", true, true, 2);
    }
}
