// The contact Jacobians (automatic differentiation through normals,
// projections and segment end points) of the mortar and node-to-segment
// formulations (the latter also with normal smoothing) against central
// finite differences of the residual, on the non-matching patch-test
// interface, and with Coulomb friction in stick and in slip:
// in contact (tilted penetration, random multipliers), out of contact (open
// gap, multipliers below c_n times the gap: every node inactive), and
// with the persistency (gap velocity) condition after an impact. The
// 'approximate' Jacobian, which drops the geometric derivatives, must
// differ from the finite differences in contact.
// Mortar also on the contact rows alone (the multiplier rows and the force
// rows of surface nodes, each group relative to its own norm, so that the
// bulk rows cannot hide an error): on the curved interface of the Hertz
// cylinder (frictionless, stick, slip) and on the partially covered faces
// of the 'two blocks' scene (the wide lower block as the secondary side:
// the primary surface ends inside two of its faces; frictionless, stick,
// slip). The same contact rows with elements of degree 2 (3-node curved
// faces: Newton projections onto curved segments, the dual basis of the
// covered part with the curve's length element); node-to-segment on 3-node
// primary faces (closest points on the curves, smoothed or not) on the
// patch-test interface.
#include <deal.II/dofs/dof_tools.h>

#include <contact_dynamics/contact/surface_contact.h>
#include <contact_dynamics/simulator.h>

#include "tests.h"

#include <random>

using namespace dealii;
using ContactDynamics::VectorType;

namespace
{
  std::string formulation = "mortar", smoothing = "0", friction = "0";
  double      tangential_scale = 0; // random lambda_t in this range
  std::string degree           = "1";

  std::string
  parameters(const std::string &jacobian,
             const std::string &scheme,
             const std::string &initial_displacement,
             const std::string &initial_velocity)
  {
    return R"(
subsection Scene
  set Scene = patch test
end
subsection Body upper
  set Material model = neo-Hookean
  set Young's modulus = 1000
  set Poisson's ratio = 0.3
  set Density = 1
  set Rayleigh stiffness coefficient = 0.01
  set Initial displacement = )" +
           initial_displacement + R"(
  set Initial velocity = )" +
           initial_velocity + R"(
end
subsection Body lower
  set Material model = neo-Hookean
  set Young's modulus = 3000
  set Poisson's ratio = 0.2
  set Density = 1
end
subsection Boundary conditions
  set Dirichlet = lower_bottom: xy: 0
end
subsection Time integration
  set Scheme = )" +
           scheme + R"(
  set Time step = 0.01
end
subsection Contact
  set Formulation = )" +
           formulation + R"(
  set Pairs = upper_bottom: lower_top
  # the states are penetrating on purpose: derivatives in contact
  set Initial penetration = allow
  set Friction coefficients = )" +
           friction + R"(
  subsection Mortar
    set c_n = 1000
    set c_t = 10
    set Jacobian = )" +
           jacobian + R"(
  end
  subsection Node to segment
    set c_n = 1000
    set c_t = 10
    set Stabilization = persistency
    set Normal smoothing distance = )" +
           smoothing + R"(
    set Jacobian = )" +
           jacobian + R"(
  end
end
subsection Finite element
  set Polynomial degree = )" +
           degree + R"(
end
subsection Output
  set Output directory = output_mortar_jacobian
  set VTU interval = 0
end
)";
  }

  // relative error of J d against central differences of R along d
  double
  fd_error(ContactDynamics::Simulator<2> &simulator,
           const VectorType              &trial,
           const VectorType              &direction,
           const double                   dt)
  {
    VectorType   r_plus(trial), r_minus(trial), r(trial), jd(trial);
    const double h = 1e-7;
    VectorType   shifted(trial);
    shifted.add(h, direction);
    simulator.residual_and_jacobian(shifted, dt, r_plus);
    shifted.add(-2 * h, direction);
    simulator.residual_and_jacobian(shifted, dt, r_minus);
    const auto &J = simulator.residual_and_jacobian(trial, dt, r);
    J.vmult(jd, direction);
    r_plus -= r_minus;
    r_plus /= 2 * h;
    const double norm = jd.l2_norm();
    r_plus -= jd;
    return r_plus.l2_norm() / norm;
  }

  void
  check(const std::string &name,
        const std::string &jacobian,
        const std::string &scheme,
        const std::string &u0,
        const std::string &v0,
        const unsigned int steps,
        const bool         expect_match,
        const double       lambda_scale = 200)
  {
    ParameterHandler prm;
    read_test_parameters("jacobian.prm",
                         parameters(jacobian, scheme, u0, v0),
                         prm);
    std::ostringstream            screen;
    ContactDynamics::Simulator<2> simulator(prm, screen);
    simulator.initialize();
    for (unsigned int s = 0; s < steps; ++s)
      if (!simulator.advance(0.01))
        check_true(name + ": step converged", false);

    std::mt19937                           rng(7);
    std::uniform_real_distribution<double> uniform(-1., 1.);
    VectorType  trial(simulator.displacement()), direction(trial);
    const auto &multipliers = simulator.get_contact()->multiplier_dofs();
    std::set<types::global_dof_index> lambda(multipliers.begin(),
                                             multipliers.end());
    const auto                        tangential =
      DoFTools::extract_dofs(simulator.get_dof_handler(),
                             ComponentMask(
                               std::vector<bool>{false, false, false, true}));
    for (unsigned int i = 0; i < trial.size(); ++i)
      {
        if (lambda.count(i))
          {
            if (steps == 0)
              trial(i) = tangential.is_element(i) ?
                           tangential_scale * uniform(rng) :
                           lambda_scale * (1.5 + uniform(rng));
            direction(i) = 100 * uniform(rng);
          }
        else
          {
            trial(i) += 1e-4 * uniform(rng);
            direction(i) = 1e-3 * uniform(rng);
          }
      }
    // no perturbation of held degrees of freedom (Dirichlet, unused
    // multipliers): their rows are identities
    simulator.get_constraints().set_zero(direction);
    const double error = fd_error(simulator, trial, direction, 0.01);
    const auto  *mortar =
      dynamic_cast<const ContactDynamics::SurfaceContact<2> *>(
        simulator.get_contact());
    unsigned int n_active = 0, n_persistent = 0, n_stick = 0;
    for (const auto &node : mortar->node_states(0))
      {
        n_active += node.active;
        n_persistent += node.persistent;
        n_stick += node.stick;
      }
    deallog << name << ": active nodes " << n_active << ", persistent nodes "
            << n_persistent << ", stick nodes " << n_stick << std::endl;
    if (expect_match)
      check_close(name + ": |J d - FD| / |J d|", error, 0., 1e-6);
    else
      check_true(name + ": differs from FD by more than 1e-3", error > 1e-3);
  }
  // |J d - FD| / |J d| on the multiplier rows and on the force rows (the
  // displacement rows that the multipliers reach) separately
  // `held`: one dynamic step first, so that the nodes in contact hold
  // their gaps (persistency rows) in the checked state
  void
  check_contact_rows(const std::string &name,
                     const std::string &text,
                     const double       lambda_scale,
                     const double       t_scale,
                     const bool         held = false)
  {
    ParameterHandler prm;
    read_test_parameters("rows.prm", text, prm);
    std::ostringstream            screen;
    ContactDynamics::Simulator<2> simulator(prm, screen);
    simulator.initialize();
    if (held)
      check_true(name + ": first step converges", simulator.advance(0.01));
    const auto &constraints = simulator.get_constraints();
    const auto  tangential =
      DoFTools::extract_dofs(simulator.get_dof_handler(),
                             ComponentMask(
                               std::vector<bool>{false, false, false, true}));
    const auto &normal = simulator.get_contact()->multiplier_dofs();
    std::set<types::global_dof_index> lambda(normal.begin(), normal.end());
    for (const auto i : tangential)
      if (!constraints.is_constrained(i))
        lambda.insert(i);

    std::mt19937                           rng(11);
    std::uniform_real_distribution<double> uniform(-1., 1.);
    VectorType trial(simulator.displacement()), direction(trial), mask(trial);
    mask = 0.;
    for (unsigned int i = 0; i < trial.size(); ++i)
      if (lambda.count(i))
        {
          trial(i)     = tangential.is_element(i) ?
                           t_scale * uniform(rng) :
                           lambda_scale * (1.5 + uniform(rng));
          direction(i) = 100 * uniform(rng);
          mask(i)      = 1. + uniform(rng);
        }
      else
        {
          trial(i) += 1e-4 * uniform(rng);
          direction(i) = 1e-3 * uniform(rng);
        }
    constraints.set_zero(direction);

    VectorType  r(trial);
    const auto  errors = contact_row_errors(simulator,
                                           trial,
                                           direction,
                                           mask,
                                           lambda,
                                           1e-7,
                                           0.01,
                                           r);
    const auto *contact =
      dynamic_cast<const ContactDynamics::SurfaceContact<2> *>(
        simulator.get_contact());
    unsigned int n_active = 0, n_stick = 0, n_held = 0;
    for (const auto &node : contact->node_states(0))
      {
        n_active += node.active;
        n_stick += node.stick;
        n_held += node.active && node.persistent;
      }
    deallog << name << ": multiplier rows " << errors.n_multiplier_rows
            << ", force rows " << errors.n_force_rows << ", active nodes "
            << n_active << ", stick nodes " << n_stick << std::endl;
    if (held)
      check_true(name + ": held nodes in the checked state", n_held >= 3);
    check_close(name + ": multiplier rows |J d - FD| / |J d|",
                errors.multiplier_rows,
                0.,
                1e-6);
    check_close(name + ": force rows |J d - FD| / |J d|",
                errors.force_rows,
                0.,
                1e-6);
  }

  std::string
  rows_parameters(const std::string &scene,
                  const std::string &friction,
                  const std::string &scheme = "quasi-static")
  {
    const bool hertz = scene == "hertz";
    return std::string(R"(
subsection Scene
  set Scene = )") +
           scene + R"(
  set Refinement factor = )" +
           (hertz ? "0.3" : "1") + R"(
end
subsection Body )" +
           (hertz ? "cylinder" : "upper") + R"(
  set Young's modulus = 1000
  set Poisson's ratio = 0.3
  set Initial displacement = )" +
           (hertz ? "0.001 + 0.003*x; -0.03 + 0.003*x" :
                    "0.001*x; -0.002 + 0.001*x") +
           R"(
end
subsection Body )" +
           (hertz ? "block" : "lower") + R"(
  set Young's modulus = 1000
  set Poisson's ratio = 0.3
end
subsection Boundary conditions
  set Dirichlet = )" +
           (hertz ? "block_bottom" : "lower_bottom") + R"(: xy: 0
end
subsection Time integration
  set Scheme = )" +
           scheme +
           R"(
  set Time step = 0.01
end
subsection Contact
  set Formulation = mortar
  set Pairs = )" +
           (hertz ? "cylinder_arc: block_top" : "lower_top: upper_bottom") +
           R"(
  set Initial penetration = allow
  set Friction coefficients = )" +
           friction + R"(
  subsection Mortar
    set c_n = 1e4
    set c_t = 10
    set Segment quadrature points = 3
  end
end
subsection Finite element
  set Polynomial degree = )" +
           degree + R"(
end
subsection Output
  set Output directory = output_rows
  set VTU interval = 0
end
)";
  }
} // namespace

void
check_contact_rows_all()
{
  for (const std::string scene : {"hertz", "two blocks"})
    {
      const std::string label =
        "mortar rows" + (degree == "1" ? "" : ", degree " + degree) + ", " +
        std::string(scene == "hertz" ?
                                        "curved (Hertz)" :
                                        "partially covered (two blocks)");
      check_contact_rows(label + ", frictionless",
                         rows_parameters(scene, "0"),
                         200,
                         0);
      check_contact_rows(label + ", stick",
                         rows_parameters(scene, "0.3"),
                         200,
                         1);
      check_contact_rows(label + ", slip",
                         rows_parameters(scene, "0.3"),
                         200,
                         500);
    }
  // dynamic, after one step: the persistency rows of held nodes on the
  // curved interface (the Newmark rate of the whole weighted gap)
  check_contact_rows("mortar rows" +
                       (degree == "1" ? "" : ", degree " + degree) +
                       ", curved (Hertz), held (persistency)",
                     rows_parameters("hertz", "0", "newmark"),
                     200,
                     0,
                     true);
}

void
check_all(const std::string &prefix)
{
  const std::string tilted = "0.002*x; -0.003 + 0.002*x";
  check(prefix + "in contact, exact",
        "exact",
        "quasi-static",
        tilted,
        "0; 0",
        0,
        true);
  check(prefix + "in contact, approximate",
        "approximate",
        "quasi-static",
        tilted,
        "0; 0",
        0,
        false);
  check(prefix + "out of contact, exact",
        "exact",
        "quasi-static",
        "0; 0.01",
        "0; 0",
        0,
        true,
        2);
  check(prefix + "persistent contact after impact, exact",
        "exact",
        "newmark",
        "0; 0.0015",
        "0.02; -0.1",
        4,
        true);
}

void
check_friction(const std::string &prefix)
{
  const std::string tilted = "0.002*x; -0.003 + 0.002*x";
  friction                 = "0.3";
  tangential_scale         = 1; // |lambda_t| << mu lambda_n: stick
  check(prefix + "friction, stick, exact",
        "exact",
        "quasi-static",
        tilted,
        "0; 0",
        0,
        true);
  tangential_scale = 500; // |lambda_t| > mu lambda_n: slip
  check(prefix + "friction, slip, exact",
        "exact",
        "quasi-static",
        tilted,
        "0; 0",
        0,
        true);
  friction         = "0";
  tangential_scale = 0;
}

int
main()
{
  initlog();
  check_all("mortar: ");
  check_friction("mortar: ");
  check_contact_rows_all();
  degree = "2";
  check_contact_rows_all();
  check_all("mortar degree 2: ");
  check_friction("mortar degree 2: ");
  degree      = "1";
  formulation = "nts";
  check_all("nts: ");
  check_friction("nts: ");
  smoothing = "0.5";
  check_all("nts smoothed: ");
  // node-to-segment on 3-node curved primary faces
  smoothing = "0";
  degree    = "2";
  check_all("nts degree 2: ");
  check_friction("nts degree 2: ");
  smoothing = "0.5";
  check_all("nts smoothed degree 2: ");
}
