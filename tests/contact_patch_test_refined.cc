// The contact patch test (as contact_patch_test: two stacked blocks with
// non-matching meshes, nu = 0, the upper one pressed down by delta = 1e-3,
// exact pressure E delta = 1000 everywhere) on adapted meshes: after the
// load step, in contact, the lower block is refined twice along the left
// half of the contact surface and the upper block once along its right
// part, so both surfaces are graded with hanging nodes next to them (in
// 2-D a hanging node is never on a surface); the state, the multipliers
// and the contact history move to the new mesh and a second step holds
// the load. Dual mortar must reproduce the uniform pressure to 1e-8 at
// every secondary node, with force balance between the contact, the top
// and the bottom (1e-9); node-to-segment is recorded (its one-pass
// error), as in contact_patch_test. Dual mortar with elements of degree 2
// (3-node faces) too. On two processes (.mpirun=2) the same.
#include <contact_dynamics/contact/surface_contact.h>
#include <contact_dynamics/simulator.h>

#include "patch_test_checks.h"
#include "tests.h"

using namespace dealii;

namespace
{
  double
  run(const std::string &formulation, const unsigned int degree = 1)
  {
    ParameterHandler prm;
    read_test_parameters("patch.prm",
                         patch_test_parameters(formulation,
                                               "-1e-3*min(t, 1)",
                                               "2",
                                               R"(subsection Parallel
  set Mesh = distributed
end
subsection Finite element
  set Polynomial degree = )" + std::to_string(degree) +
                                                 R"(
end
)"),
                         prm);
    std::ostringstream            screen;
    ContactDynamics::Simulator<2> simulator(prm, screen);
    simulator.initialize();
    advance_to(simulator, 1);
    // the lower block left of x = 0.5 twice, the upper one right of 0.4 once
    refine_interface(simulator,
                     formulation,
                     2,
                     [](const bool         lower,
                        const unsigned int round,
                        const double       x) {
                       return lower ? x < 0.5 : round == 0 && x > 0.4;
                     });
    unsigned int hanging = 0;
    for (const auto &line : simulator.get_constraints().get_lines())
      hanging += !line.entries.empty();
    check_true(formulation + ": hanging nodes",
               Utilities::MPI::sum(hanging, MPI_COMM_WORLD) > 0);
    advance_to(simulator, 2);

    return check_patch_test(formulation +
                              (degree == 2 ? " degree 2" : std::string()),
                            simulator);
  }
} // namespace

int
main()
{
  initlog();
  report_patch_tests([](const std::string &formulation) {
    return run(formulation);
  });
  check_close("mortar degree 2: max |pressure - E delta| / (E delta)",
              run("mortar", 2),
              0.,
              1e-8);
}
