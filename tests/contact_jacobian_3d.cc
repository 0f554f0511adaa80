// 3-D dual mortar: the contact rows of the Jacobian (automatic
// differentiation through the averaged nodal normals, the auxiliary plane,
// the clip polygons and the projections) against central finite
// differences of the residual, on a curved, warped interface between the
// distorted, non-matching meshes of the 3-D patch-test scene: the upper
// block's bottom bent into a paraboloid, the lower block's top twisted,
// every node perturbed at random; quasi-static (the weighted gaps) and
// after one dynamic step (the persistency rows of held nodes). The
// 'approximate' Jacobian, which drops the geometric stiffness, must differ.
// With Coulomb friction (mu = 0.3, random tangential multipliers so that
// some active nodes stick and some slip) the same check covers the friction
// forces (through the tangents of the nodal normals and the mortar matrices)
// and the stick and slip rows (the slip rates, the slip direction). Momentum:
// the contact forces on both bodies sum to zero, and so do their moments
// (frictionless: the normalized gaps are invariant under rigid motions), to
// round-off. The same checks for node-to-segment (closest points on the
// bilinear faces, the nodal force's two tangential components), with the
// face normal and with the normal smoothed near the face edges (blended
// into the interpolated nodal normals); its moments do not balance where
// the smoothed normal is not along x - x_p.
// On a refined interface (the upper, secondary block refined twice along
// x > 0.4, the lower once along x > 0.6: hanging nodes on both surfaces,
// whose gap sums join their parents' and whose forces go to them), the
// same checks with the trial state and the direction satisfying the
// hanging-node constraints, on the rows that are not constrained.
// Degree 2 (9-node faces): dual mortar (segments on the curved faces), with
// friction (the mortar factors of the dual basis of the covered part, the
// tangents of the nodal normals averaged over the curved faces), also
// on the refined interface (hanging nodes with the weights 3/8, 3/4, -1/8
// of their coarse edge), and node-to-segment (closest points on the curved
// faces or their curved edges; the normal smoothed into the nodal normals
// interpolated with the 9 shape functions; friction; the refined interface).
#include <deal.II/fe/mapping_q1.h>

#include <contact_dynamics/contact/surface_contact.h>
#include <contact_dynamics/simulator.h>

#include "patch_test_checks.h"
#include "tests.h"

#include <random>

using namespace dealii;
using ContactDynamics::VectorType;

namespace
{
  std::string
  parameters(const std::string &scheme,
             const std::string &jacobian,
             const bool         friction,
             const double       smoothing,
             const bool         refined,
             const unsigned int degree,
             const double       overhang)
  {
    // smoothing < 0: mortar; else node-to-segment with that smoothing
    // distance (the same complementarity parameters)
    const bool        nts         = smoothing >= 0;
    const std::string formulation = nts ? "Node to segment" : "Mortar";
    // dynamic: the upper block hits the lower one from a small gap, so
    // that the nodes the first step brings into contact hold their gaps
    // after it
    const bool        dynamic = scheme != "quasi-static";
    const std::string offset  = dynamic ? "0.0002" : "-0.003";
    return R"(
set Dimension = 3
subsection Finite element
  set Polynomial degree = )" +
           std::to_string(degree) + R"(
end
subsection Scene
  set Scene = patch test
  set Refinement factor = 0.6
end
subsection Body upper
  set Young's modulus = 1000
  set Poisson's ratio = 0.3
  set Density = 1
  set Initial displacement = 0.001*x + )" +
           std::to_string(overhang) + "; " + offset +
           R"( + 0.02*((x-0.5)^2 + (z-0.5)^2) + 0.004*x*z; 0.002*z
  set Initial velocity = 0; )" +
           (dynamic ? "-1" : "0") + R"(; 0
end
subsection Body lower
  set Young's modulus = 1000
  set Poisson's ratio = 0.3
  set Density = 1
  set Initial displacement = 0; 0.004*x*z - 0.002*z; 0
end
subsection Boundary conditions
  set Dirichlet = lower_bottom: xyz: 0
end
subsection Time integration
  set Scheme = )" +
           scheme + R"(
  set Time step = 0.01
end
subsection Contact
  set Formulation = )" +
           (nts ? "nts" : "mortar") + R"(
  set Pairs = upper_bottom: lower_top
  set Initial penetration = allow
  set Friction coefficients = )" +
           (friction ? "0.3" : "0") + R"(
  subsection )" +
           formulation + R"(
    set c_n = 1e4
    set c_t = 1
    set Stabilization = persistency
    set Jacobian = )" +
           jacobian + R"(
)" +
           (nts ? "    set Normal smoothing distance = " +
                    std::to_string(smoothing) + "\n" :
                  "") +
           R"(  end
end
subsection Output
  set Output directory = output_jacobian_3d
  set VTU interval = 0
end
)" + (refined ? "subsection Parallel\n  set Mesh = distributed\nend\n" : "");
  }

  void
  check(const std::string &name,
        const std::string &scheme,
        const std::string &jacobian,
        const bool         held,
        const bool         friction  = false,
        const double       smoothing = -1,
        const bool         refined   = false,
        const unsigned int degree    = 1,
        const double       overhang  = 0)
  {
    ParameterHandler prm;
    read_test_parameters("jacobian_3d.prm",
                         parameters(scheme,
                                    jacobian,
                                    friction,
                                    smoothing,
                                    refined,
                                    degree,
                                    overhang),
                         prm);
    std::ostringstream            screen;
    ContactDynamics::Simulator<3> simulator(prm, screen);
    simulator.initialize();
    if (refined)
      refine_interface(simulator,
                       name,
                       2,
                       [](const bool         lower,
                          const unsigned int round,
                          const double       x) {
                         return lower ? round == 0 && x > 0.6 : x > 0.4;
                       });
    if (held)
      check_true(name + ": first step converges", simulator.advance(0.01));
    const auto &constraints = simulator.get_constraints();
    const auto &normal      = simulator.get_contact()->multiplier_dofs();
    const std::set<types::global_dof_index> lambda(normal.begin(),
                                                   normal.end());

    const auto *contact =
      dynamic_cast<const ContactDynamics::SurfaceContact<3> *>(
        simulator.get_contact());
    std::set<types::global_dof_index> tangential;
    for (const auto &dofs : contact->secondary_surface(0).dofs)
      tangential.insert({dofs[4], dofs[5]});
    std::mt19937                           rng(5);
    std::uniform_real_distribution<double> uniform(-1., 1.);
    VectorType trial(simulator.displacement()), direction(trial), mask(trial);
    mask = 0.;
    for (unsigned int i = 0; i < trial.size(); ++i)
      if (lambda.count(i))
        {
          trial(i) =
            tangential.count(i) ? 10 * uniform(rng) : 20 * (1.5 + uniform(rng));
          direction(i) = 10 * uniform(rng);
          mask(i)      = 1. + uniform(rng);
        }
      else
        {
          trial(i) += 1e-4 * uniform(rng);
          direction(i) = 1e-3 * uniform(rng);
        }
    constraints.set_zero(direction);
    // hanging nodes follow their parents (the constraints are closed: the
    // entries are unconstrained)
    unsigned int n_hanging = 0;
    for (const auto &line : constraints.get_lines())
      if (!line.entries.empty())
        {
          ++n_hanging;
          trial(line.index)     = line.inhomogeneity;
          direction(line.index) = 0;
          mask(line.index)      = 0;
          for (const auto &[j, c] : line.entries)
            {
              trial(line.index) += c * trial(j);
              direction(line.index) += c * direction(j);
            }
        }
    check_true(name + ": hanging dofs if and only if refined",
               (n_hanging > 0) == refined);
    if (refined)
      deallog << name << ": hanging nodes on the secondary surface "
              << hanging_surface_nodes(contact->secondary_surface(0),
                                       constraints)
              << ", on the primary surface "
              << hanging_surface_nodes(contact->primary_surface(0), constraints)
              << std::endl;

    // (round-off dominates the differences below: 1e-7 gives 1e-6)
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
            << n_active << std::endl;
    check_true(name + ": some nodes active, some not",
               n_active > 3 && n_active < contact->node_states(0).size());
    if (held)
      check_true(name + ": held nodes in the checked state", n_held >= 3);
    if (friction)
      {
        deallog << name << ": stick nodes " << n_stick << std::endl;
        check_true(name + ": some active nodes stick, some slip",
                   n_stick >= 3 && n_active - n_stick >= 3);
      }
    const double multiplier_error = errors.multiplier_rows;
    const double force_error      = errors.force_rows;
    if (jacobian == "exact")
      {
        check_close(name + ": multiplier rows |J d - FD| / |J d|",
                    multiplier_error,
                    0.,
                    1e-6);
        check_close(name + ": force rows |J d - FD| / |J d|",
                    force_error,
                    0.,
                    1e-6);
      }
    else
      check_true(name + ": force rows differ from FD by more than 1e-3",
                 force_error > 1e-3);

    if (held || jacobian != "exact")
      return;
    // momentum: the contact forces alone are the residual with the
    // multipliers minus the residual without them (the bulk terms cancel);
    // no surface node is held by a Dirichlet condition here. Node k of a
    // cell carries f_k = int N_k t: sum_k x_k x f_k is the moment of the
    // traction for an isoparametric field of any degree.
    VectorType without(trial), r0(trial);
    for (const auto i : lambda)
      without(i) = 0;
    simulator.residual_and_jacobian(without, 0.01, r0);
    r -= r0;
    Tensor<1, 3>      force, moment, one_side;
    std::vector<bool> seen(trial.size(), false);
    const auto       &dof_handler = simulator.get_dof_handler();
    const auto       &fe          = dof_handler.get_fe();
    const auto       &base        = fe.base_element(0);
    // (the scene's cells are straight-sided: their support points are
    // those of the trilinear mapping for either degree)
    const MappingQ1<3>                   mapping;
    std::vector<types::global_dof_index> local(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(local);
        for (unsigned int k = 0; k < base.n_dofs_per_cell(); ++k)
          {
            const auto first = local[fe.component_to_system_index(0, k)];
            if (seen[first])
              continue;
            seen[first] = true;
            Tensor<1, 3> f;
            Point<3>     x =
              mapping.transform_unit_to_real_cell(cell,
                                                  base.unit_support_point(k));
            for (unsigned int d = 0; d < 3; ++d)
              {
                const auto i = local[fe.component_to_system_index(d, k)];
                f[d]         = r(i);
                x[d] += trial(i);
              }
            force += f;
            moment += cross_product_3d(x, f);
            if (cell->material_id() == 0)
              one_side += f;
          }
      }
    deallog << name << ": contact force on the upper body " << one_side.norm()
            << std::endl;
    check_close(name + ": |sum of contact forces| / |force on one body|",
                force.norm() / one_side.norm(),
                0.,
                1e-10);
    if (!friction && smoothing < 0)
      check_close(name + ": |sum of contact moments| / |force on one body|",
                  moment.norm() / one_side.norm(),
                  0.,
                  1e-10);
  }
} // namespace

int
main()
{
  initlog();
  check("quasi-static, exact", "quasi-static", "exact", false);
  check("quasi-static, approximate", "quasi-static", "approximate", false);
  check("held (persistency), exact", "newmark", "exact", true);
  check("friction, quasi-static", "quasi-static", "exact", false, true);
  check("friction, held", "newmark", "exact", true, true);
  check("nts, quasi-static, exact", "quasi-static", "exact", false, false, 0);
  check("nts, quasi-static, approximate",
        "quasi-static",
        "approximate",
        false,
        false,
        0);
  check("nts smoothed, quasi-static, exact",
        "quasi-static",
        "exact",
        false,
        false,
        0.3);
  check("nts, held (persistency), exact", "newmark", "exact", true, false, 0);
  check("nts smoothed, held (persistency), exact",
        "newmark",
        "exact",
        true,
        false,
        0.3);
  check("nts, friction, quasi-static", "quasi-static", "exact", false, true, 0);
  check("nts smoothed, friction, held", "newmark", "exact", true, true, 0.3);
  check("refined, quasi-static, exact",
        "quasi-static",
        "exact",
        false,
        false,
        -1,
        true);
  check("refined, held (persistency), exact",
        "newmark",
        "exact",
        true,
        false,
        -1,
        true);
  check("refined, friction, quasi-static",
        "quasi-static",
        "exact",
        false,
        true,
        -1,
        true);
  check("nts, refined, quasi-static, exact",
        "quasi-static",
        "exact",
        false,
        false,
        0,
        true);
  check("nts, refined, held (persistency), exact",
        "newmark",
        "exact",
        true,
        false,
        0,
        true);
  // degree 2: 9-node faces, the segments on the curved faces
  check("degree 2, quasi-static, exact",
        "quasi-static",
        "exact",
        false,
        false,
        -1,
        false,
        2);
  check("degree 2, held (persistency), exact",
        "newmark",
        "exact",
        true,
        false,
        -1,
        false,
        2);
  check("degree 2, refined, quasi-static, exact",
        "quasi-static",
        "exact",
        false,
        false,
        -1,
        true,
        2);
  check("degree 2, friction, quasi-static",
        "quasi-static",
        "exact",
        false,
        true,
        -1,
        false,
        2);
  check("degree 2, friction, held",
        "newmark",
        "exact",
        true,
        true,
        -1,
        false,
        2);
  check("degree 2, refined, friction, quasi-static",
        "quasi-static",
        "exact",
        false,
        true,
        -1,
        true,
        2);
  // the upper block 0.15 beyond the lower one along x: faces over the
  // edge are partly covered, nodes below 10 % of their weight leave the
  // face's multipliers (S_jk no longer diagonal)
  check("degree 2, overhanging, friction, quasi-static",
        "quasi-static",
        "exact",
        false,
        true,
        -1,
        false,
        2,
        0.15);
  // node-to-segment of degree 2: closest points on the curved faces, on
  // their surface or their curved edges, the normal smoothed near the
  // edges into the nodal normals interpolated with the 9 shape functions
  check("nts degree 2, quasi-static, exact",
        "quasi-static",
        "exact",
        false,
        false,
        0,
        false,
        2);
  check("nts degree 2 smoothed, held (persistency), exact",
        "newmark",
        "exact",
        true,
        false,
        0.3,
        false,
        2);
  check("nts degree 2, refined, quasi-static, exact",
        "quasi-static",
        "exact",
        false,
        false,
        0,
        true,
        2);
  check("nts degree 2 smoothed, friction, held",
        "newmark",
        "exact",
        true,
        true,
        0.3,
        false,
        2);
}
