// Contact patch test (../shared/reference/benchmarks.md section 3): two
// stacked blocks with non-matching meshes (7 and 5 elements across), nu = 0,
// the lower one clamped at its bottom, the upper one pressed down by
// delta = 1e-3 at its top. With mortar its left side is held horizontally:
// frictionless and quasi-static, nothing else holds it, and the mortar
// Jacobian (the derivative of the forces) is singular along that sliding
// (the exact solution, with nu = 0, has no horizontal displacement); NTS
// keeps the free side, where its tangential force error shows. The exact
// solution is a uniform stress
// -E delta / H in both blocks (H = 1), so the contact pressure is
// E delta = 1000 everywhere.
// - Dual mortar with segment integration reproduces it to solver tolerance.
// - One-pass node-to-segment does not: its nodal pressures (nodal force /
//   tributary length) are off by a fixed amount that does not vanish with
//   refinement; the test records how much, so that a change is noticed.
// For both: the contact force equals the reactions at the top and at the
// bottom (force balance), and active nodes do not penetrate.
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
    read_test_parameters("patch.prm",
                         patch_test_parameters(formulation, "-1e-3*t", "1"),
                         prm);
    std::ostringstream            screen;
    ContactDynamics::Simulator<2> simulator(prm, screen);
    simulator.run();

    return check_patch_test(formulation, simulator);
  }
} // namespace

int
main()
{
  initlog();
  const double mortar = run("mortar");
  check_close("mortar: max |pressure - E delta| / (E delta)", mortar, 0., 1e-8);
  // informational (numdiff compares values below 1e-6 as equal)
  deallog << "mortar: measured relative pressure error: " << mortar
          << std::endl;
  const double nts = run("nts");
  deallog << std::setprecision(3)
          << "nts: measured relative pressure error: " << nts << std::endl;
  check_true("nts: the error is that of one-pass NTS (between 1 % and 50 %)",
             nts > 0.01 && nts < 0.5);
}
