// Hertz contact of a rigid cylinder (an obstacle with no mesh and no
// unknowns, R = 1) pressed into an elastic block (E = 1000, nu = 0.3,
// plane strain, clamped at its base), frictionless and quasi-static: the
// cylinder starts 1e-4 above the block (the dual weighted gap of a convex
// surface that touches a node is -h^2/12 there, below zero: a start at
// contact would count as an overlap) and indents it by 0.01 in two steps.
// Reference: Hertz's solution of a rigid cylinder on a half-space for the load
// P per unit length that the run reports on the obstacle (analytic): E* = E /
// (1 - nu^2), a = sqrt(4 P R / (pi E*)), p0 = 2 P / (pi a). The block [-0.5,
// 0.5] x
// [-1, 0] (80 x 80 elements, h = 0.0125) is a finite body: on a block half
// as deep the half-width fell 2 % short of Hertz's. The half-width is
// measured from the second moment of the nodal pressures (a^2 = 4 int p x^2
// / int p for the Hertz profile), with the weights integral N_j of the
// current surface. Asserted, for mortar and node-to-segment:
// - the half-width and the peak pressure within 2.5 % of Hertz's (measured
//   -0.75 % and +1.3 %; a 10 % error in the pressures fails);
// - the load on the cylinder equals the integral of the nodal pressures
//   (equilibrium, 0.5 %; measured 0.07 %).
// With elements of degree 2 (issue 41) on 40 x 40 cells (the same nodes):
// the same bounds (measured a -1.35 %, p0 +2.05 %: the nodal multipliers
// are averages int N_j p / int N_j, and the vertex functions of degree 2
// weigh the peak's flanks negatively), and for mortar the load at the
// fixed indentation on 20 x 20, 40 x 40 and 80 x 80 cells: its observed
// order of convergence at least 2.5 on these coarse meshes (measured 2.8;
// on 40, 80, 160 it is 1.2, doc/accuracy-vs-cost.md; degree 1 on 40, 80,
// 160 measured 1.9), and degree 2 on 20 x 20 cells within half the
// distance of degree 1 on 80 x 80 (4 times the nodes) from the 80 x 80
// solution of degree 2 (measured 0.0027 against 0.0077, 0.36). Degree 2
// adapted to the contact (2-D: no hanging nodes on the contact surface)
// against the same bounds and the uniform 80 x 80 load.
#include "rigid_hertz_2d.h"

#include <array>
#include <cmath>

using namespace dealii;

namespace
{
  using Result = HertzResult;

  Result
  run(const std::string &formulation,
      const unsigned int degree,
      const unsigned int n,
      const unsigned int levels = 0)
  {
    const std::string adapt =
      levels == 0 ? "" :
                    "subsection Mesh refinement\n  set Adapt to contact = "
                    "true\n  set Maximum levels = " +
                      std::to_string(levels) +
                      "\n  set Buffer cells = 8\n  set Passes per step = "
                      "5\nend\n";
    ParameterHandler prm;
    read_test_parameters("rigid_hertz.prm",
                         R"(
subsection Finite element
  set Polynomial degree = )" +
                           std::to_string(degree) +
                           R"(
end
subsection Scene
  set Scene = block
  subsection Block
    set Origin       = -0.5, -1
    set Size         = 1, 1
    set Subdivisions = )" + std::to_string(n) +
                           ", " + std::to_string(n) + R"(
  end
end
subsection Body body
  set Young's modulus = 1000
  set Poisson's ratio = 0.3
end
subsection Boundary conditions
  set Dirichlet = bottom: xy: 0
end
subsection Time integration
  set Scheme    = quasi-static
  set Time step = 0.5
  set End time  = 1
end
subsection Contact
  set Formulation     = )" +
                           formulation + R"(
  set Rigid obstacles = roller
  set Pairs           = top: roller
  subsection Rigid obstacle roller
    set Shape       = cylinder
    set Point       = 0, 1.0001
    set Radius      = 1
    set Translation = 0; -0.0101*t
  end
end
subsection Output
  set Output directory = output_rigid_hertz
  set VTU interval     = 0
end
)" + adapt,
                         prm);
    const std::string name = formulation + ", degree " +
                             std::to_string(degree) + ", " + std::to_string(n) +
                             " cells: ";
    std::ostringstream            screen;
    ContactDynamics::Simulator<2> simulator(prm, screen);
    simulator.initialize();
    while (simulator.current_time() < 1 - 1e-9)
      if (!simulator.advance(0.5))
        check_true(name + "step converged", false);

    return rigid_hertz_2d(simulator, "roller", degree);
  }

  void
  check_hertz(const std::string &formulation,
              const unsigned int degree,
              const Result      &r)
  {
    const std::string name =
      formulation + (degree == 2 ? ", degree 2" : "") + ": ";
    check_rigid_hertz(name, r, 0.025);
  }
} // namespace

int
main()
{
  initlog();
  const Result linear = run("mortar", 1, 80);
  check_hertz("mortar", 1, linear);
  check_hertz("nts", 1, run("nts", 1, 80));
  check_hertz("nts", 2, run("nts", 2, 40));

  std::array<Result, 3> quadratic = {
    {run("mortar", 2, 20), run("mortar", 2, 40), run("mortar", 2, 80)}};
  check_hertz("mortar", 2, quadratic[1]);
  const double order = std::log2((quadratic[0].load - quadratic[1].load) /
                                 (quadratic[1].load - quadratic[2].load));
  check_range("mortar, degree 2: observed order of the load on 20, 40, 80",
              order,
              2.5,
              4);
  record_measured("mortar, degree 2: load order", order, 2.5, 4);
  const double reference = quadratic[2].load;
  check_range("mortar: |load - reference|, degree 2 on 20 x 20 / degree 1 "
              "on 80 x 80",
              std::abs(quadratic[0].load - reference) /
                std::abs(linear.load - reference),
              0.,
              0.5);

  // adapted to the contact: 3 levels from 10 x 10 cells reach the finest
  // uniform mesh's contact resolution (80 x 80) and its load within 1e-3
  // (measured 8e-5, a third of the unknowns; the mass projection of the
  // coarsening is of degree 2 too)
  const Result adapted = run("mortar", 2, 10, 3);
  check_hertz("mortar, adapted", 2, adapted);
  check_range("mortar, degree 2, adapted: load / uniform 80 x 80 - 1",
              adapted.load / reference - 1,
              -1e-3,
              1e-3);
}
