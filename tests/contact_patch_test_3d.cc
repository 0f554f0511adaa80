// 3-D contact patch test: two stacked unit blocks whose meshes neither
// match nor align at the interface (7 x 6 against 5 x 4 faces, both grids
// distorted differently in the horizontal plane), nu = 0, the lower block
// clamped at its bottom, the upper one pressed down by delta = 1e-3 at its
// top and held sideways on one side each in x and z (frictionless and
// quasi-static, nothing else fixes its rigid sliding). The exact solution
// is a uniform stress -E delta / H (H = 1): the contact pressure is
// E delta = 1000 everywhere. Dual mortar with segment clipping reproduces
// it up to the error of the triangle rule on the integration cells: the
// parameters of a face are not polynomial in the auxiliary plane where its
// quadrilateral is not a parallelogram, so the default 6-point rule leaves
// about 2e-8 and the 15-point rule (Segment quadrature points = 4) 1e-10.
// The contact force balances the reactions. One-pass node-to-segment does
// not pass the test (as in 2-D, contact_patch_test): its nodal forces load
// the primary surface unevenly, and the pressures are off by up to a
// quarter (recorded, so that a change is noticed); the gaps of its nodes
// are closed exactly. A monitored point given by its three coordinates
// reports the pressure of its nearest node. Degree 2 (9-node faces) with
// both formulations: dual mortar to the error of the segments' edges
// (below), node-to-segment with the same checks as degree 1. (The
// approximate Jacobian
// keeps the test fast; the exact one is checked in contact_jacobian_3d.)
#include <contact_dynamics/contact/surface_contact.h>
#include <contact_dynamics/simulator.h>

#include "patch_test_checks.h"
#include "tests.h"

using namespace dealii;

// the largest relative pressure error with the given triangle rule
double
run(const unsigned int n_points_1d,
    const bool         nts         = false,
    const unsigned int degree      = 1,
    const unsigned int edge_points = 4)
{
  ParameterHandler prm;
  read_test_parameters("patch_3d.prm",
                       std::string(R"(
set Dimension = 3
subsection Finite element
  set Polynomial degree = )" + std::to_string(degree) +
                                   R"(
end
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
  set Dirichlet = lower_bottom: xyz: 0; upper_top: y: -1e-3*t; upper_left: x: 0; upper_front: z: 0
end
subsection Time integration
  set Scheme = quasi-static
  set Time step = 1
  set End time = 1
end
subsection Nonlinear solver
  set Absolute tolerance = 1e-11
end
subsection Contact
  set Formulation = )" + std::string(nts ? "nts" : "mortar") +
                                   R"(
  set Pairs = upper_bottom: lower_top
  set Monitored points = 0.5, 0.5, 0.5
  subsection Mortar
    set c_n = 1e6
    set Jacobian = approximate
    set Segment quadrature points = )" +
                                   std::to_string(n_points_1d) + R"(
    set Segment edge points = )" + std::to_string(edge_points) +
                                   R"(
  end
  subsection Node to segment
    set c_n = 1e6
  end
end
subsection Output
  set Output directory = output_patch_3d
  set VTU interval = 0
end
)"),
                       prm);
  std::ostringstream            screen;
  ContactDynamics::Simulator<3> simulator(prm, screen);
  simulator.run();

  const auto *contact =
    dynamic_cast<const ContactDynamics::SurfaceContact<3> *>(
      simulator.get_contact());
  const double exact                      = 1000;
  const auto [worst, worst_gap, n_active] = nodal_errors(*contact, exact);
  const auto stats                        = contact_statistics(*contact);
  deallog.push(nts ? std::string(degree == 2 ? "nts degree 2" : "nts") :
               degree == 2 ?
                     "degree 2, edge points " + std::to_string(edge_points) :
                     "rule " + std::to_string(n_points_1d));
  const auto top    = simulator.reaction_force("upper_top");
  const auto bottom = simulator.reaction_force("lower_bottom");
  deallog << "secondary nodes " << contact->node_states(0).size() << ", active "
          << n_active << std::endl;
  check_close("contact force on the upper block + reaction at its top",
              (stats.at("contact_force_y") + top[1]) / exact,
              0.,
              1e-9);
  check_close("reactions at top and bottom cancel",
              (top[1] + bottom[1]) / exact,
              0.,
              1e-9);
  // (NTS: the primary surface bends under its uneven nodal loads, and its
  // normals tilt: measured 1.2e-5 sideways, 0.19 % less load)
  check_close("tangential contact force x",
              stats.at("contact_force_x") / exact,
              0.,
              nts ? 1e-4 : 1e-9);
  check_close("tangential contact force z",
              stats.at("contact_force_z") / exact,
              0.,
              nts ? 1e-4 : 1e-9);
  check_close("gap at active nodes / delta", worst_gap / 1e-3, 0., 1e-9);
  check_close("total load / (E delta area)",
              -top[1] / exact,
              1.,
              nts ? 0.01 : 1e-9);
  // the monitored point (x, y, z): the nearest secondary node's pressure
  // in contact_history.csv
  const auto history = read_csv_columns("output_patch_3d/contact_history.csv");
  check_true("contact_history.csv: time and one monitored node",
             history.size() == 3);
  for (const auto &[name, values] : history)
    if (name.rfind("pressure(", 0) == 0)
      check_close("monitored node's pressure / (E delta), " + name,
                  values.back() / exact,
                  1.,
                  nts ? 0.5 : (degree == 2 ? 1e-5 : 1e-8));
  deallog.pop();
  return worst / exact;
}

int
main()
{
  initlog();
  const double error_15 = run(4);
  check_close("15-point rule: max |pressure - E delta| / (E delta)",
              error_15,
              0.,
              1e-8);
  const double error_6 = run(2);
  check_true("6-point rule: the rule's error, between 1e-10 and 1e-7",
             error_6 > 1e-10 && error_6 < 1e-7);
  deallog << std::setprecision(2)
          << "measured relative pressure errors: 6-point rule " << error_6
          << ", 15-point rule " << error_15 << std::endl;
  // degree 2: 9-node faces, integrated on the curved faces but for the
  // segments' edges, straight between the primary edges' points projected
  // onto the secondary face: the one approximation, whose error falls with
  // the fourth power of the points per edge on these distorted faces
  // (Segment edge points)
  std::array<double, 3> error_2;
  for (unsigned int k = 0; k < 3; ++k)
    error_2[k] = run(4, false, 2, 2u << k);
  deallog << std::setprecision(2)
          << "degree 2: measured relative pressure errors with 2, 4, 8 edge "
          << "points: " << error_2[0] << ", " << error_2[1] << ", "
          << error_2[2] << std::endl;
  check_close("degree 2, 8 edge points: max |pressure - E delta| / (E delta)",
              error_2[2],
              0.,
              1e-8);
  check_true("degree 2: the error falls by at least 8 per doubling of the "
             "edge points",
             error_2[0] > 8 * error_2[1] && error_2[1] > 8 * error_2[2]);
  const double error_nts = run(2, true);
  deallog << std::setprecision(3)
          << "nts: measured relative pressure error: " << error_nts
          << std::endl;
  check_true("nts: the error is that of one-pass NTS (between 1 % and 50 %)",
             error_nts > 0.01 && error_nts < 0.5);
  // node-to-segment of degree 2: every node of the 9-node faces projected
  // onto the curved primary faces; one pass, so not exact either
  const double error_nts_2 = run(2, true, 2);
  deallog << std::setprecision(3)
          << "nts degree 2: measured relative pressure error: " << error_nts_2
          << std::endl;
  check_true("nts degree 2: the error of one-pass NTS (between 1 % and 50 %)",
             error_nts_2 > 0.01 && error_nts_2 < 0.5);
}
