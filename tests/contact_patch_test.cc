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
// - Dual mortar with elements of degree 2 (3-node faces: the mid-side
//   nodes are contact nodes too, 15 on the upper block's bottom) reproduces
//   it to solver tolerance as well; node-to-segment with degree 2 has the
//   one-pass error too (measured 5.3 %).
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
    read_test_parameters(
      "patch.prm",
      patch_test_parameters(formulation,
                            "-1e-3*t",
                            "1",
                            "subsection Finite element\n"
                            "  set Polynomial degree = " +
                              std::to_string(degree) + "\nend\n"),
      prm);
    std::ostringstream            screen;
    ContactDynamics::Simulator<2> simulator(prm, screen);
    simulator.run();

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
  const double quadratic = run("mortar", 2);
  check_close("mortar degree 2: max |pressure - E delta| / (E delta)",
              quadratic,
              0.,
              1e-8);
  const double nts_2 = run("nts", 2);
  deallog << std::setprecision(3)
          << "nts degree 2: measured relative pressure error: " << nts_2
          << std::endl;
  check_true("nts degree 2: the error is that of one-pass NTS (between 1 % "
             "and 50 %)",
             nts_2 > 0.01 && nts_2 < 0.5);
}
