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
// same. Degree 2 (27-node cells, 9-node faces): a hanging node on a refined
// edge follows the coarse edge's three nodes with weights 3/8, 3/4, -1/8;
// the dual mortar must still give E delta at every secondary node, to the
// segment polygon's error with 8 edge points (contact_patch_test_3d: 6.9e-9
// without hanging nodes; asserted 1e-8). A coarse primary face follows an
// edge that finer faces hang on with their points (without: 6e-5 with the
// primary side refined alone, 3e-4 with both, falling as the square of the
// points: the coarse and fine segment polygons overlapped).
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
    read_test_parameters("patch_3d.prm",
                         patch_test_parameters<3>(formulation,
                                                  "-1e-3*min(t, 1)",
                                                  "2",
                                                  R"(
subsection Parallel
  set Mesh = distributed
end
subsection Finite element
  set Polynomial degree = )" + std::to_string(degree) +
                                                    R"(
end
subsection Contact
  subsection Mortar
    set Jacobian = approximate
    set Segment edge points = 8
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
    return check_patch_test(formulation +
                              (degree == 2 ? std::string(", degree 2") : ""),
                            simulator);
  }
} // namespace

int
main()
{
  initlog();
  report_patch_tests([](const std::string &f) {
    return run(f);
  });
  const double error = run("mortar", 2);
  check_close("mortar, degree 2: max |pressure - E delta| / (E delta)",
              error,
              0.,
              1e-8);
  deallog << "mortar, degree 2: measured relative pressure error: " << error
          << std::endl;
}
