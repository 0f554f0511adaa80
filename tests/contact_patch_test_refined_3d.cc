// The 3-D contact patch test (as contact_patch_test_3d: non-matching,
// distorted meshes, nu = 0, the upper block pressed down by delta = 1e-3,
// exact pressure E delta = 1000 everywhere) with hanging nodes on both
// contact surfaces: after the load step, in contact, the upper (secondary)
// block is refined twice along the part x > 0.4 of the interface and the
// lower (primary) block once along x > 0.6, and a second step holds the
// load (the secondary side stays the finer one, which node-to-segment
// needs: under a finer primary side its load is off by 20 %, hanging nodes
// or not). A refined patch of a 3-D surface has hanging nodes on the surface:
// their displacements and multipliers follow their neighbours', and their
// weighted gaps join those of the nodes they follow. Dual mortar must still
// reproduce the uniform pressure at every secondary node, hanging or not
// (1e-8, with the 15-point segment rule that contact_patch_test_3d uses for
// the same bound), with force balance (1e-9). Node-to-segment is recorded
// (its one-pass error, as on the uniform mesh: 25 %), with its force balance
// and closed gaps. The approximate Jacobian keeps the test fast (the exact
// one is checked in contact_jacobian_3d). On two processes (.mpirun=2) the
// same.
#include <contact_dynamics/contact/surface_contact.h>
#include <contact_dynamics/simulator.h>

#include "patch_test_checks.h"
#include "tests.h"

using namespace dealii;

namespace
{
  double
  run(const std::string &formulation)
  {
    ParameterHandler prm;
    read_test_parameters("patch_3d.prm",
                         patch_test_parameters<3>(formulation,
                                                  "-1e-3*min(t, 1)",
                                                  "2",
                                                  R"(
subsection Parallel
  set Mesh = distributed
end
subsection Contact
  subsection Mortar
    set Jacobian = approximate
  end
end
)"),
                         prm);
    std::ostringstream            screen;
    ContactDynamics::Simulator<3> simulator(prm, screen);
    simulator.initialize();
    advance_to(simulator, 1);
    // the upper block right of x = 0.4 twice, the lower one right of 0.6 once
    refine_interface(simulator,
                     formulation,
                     2,
                     [](const bool         lower,
                        const unsigned int round,
                        const double       x) {
                       return lower ? round == 0 && x > 0.6 : x > 0.4;
                     });
    const auto *contact =
      dynamic_cast<const ContactDynamics::SurfaceContact<3> *>(
        simulator.get_contact());
    // (every process knows the constraints of all surface nodes)
    const auto        &constraints = simulator.get_constraints();
    const unsigned int on_secondary =
      hanging_surface_nodes(contact->secondary_surface(0), constraints);
    const unsigned int on_primary =
      hanging_surface_nodes(contact->primary_surface(0), constraints);
    deallog << formulation << ": hanging nodes on the secondary surface "
            << on_secondary << ", on the primary surface " << on_primary
            << std::endl;
    check_true(formulation + ": hanging nodes on both surfaces",
               on_secondary > 0 && on_primary > 0);
    advance_to(simulator, 2);
    return check_patch_test(formulation, simulator);
  }
} // namespace

int
main()
{
  initlog();
  report_patch_tests(run);
}
