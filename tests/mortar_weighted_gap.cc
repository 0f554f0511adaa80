// Dual basis and weighted gaps of the mortar formulation on hand-computed
// geometries. The secondary surface is the bottom face (0,0)-(1,0) of a unit
// square (outward normal -y); the primary surface is the top of a body
// below it:
//  - offset: flat at y = -d over x in [-0.3, 1.2]: g_j = d/2 (integral of
//    psi_j = integral of N_j = 1/2);
//  - partial: flat at y = -d over x in [-0.3, 0.5], covering half the face.
//    The dual basis of the covered part [0, 1/2] (by hand: D = diag(3/8,
//    1/8), M = (1/24) [[7, 2], [2, 1]], M^-1 = 8 [[1, -2], [-2, 7]],
//    A = D M^-1 = [[3, -6], [-2, 7]]) is psi_0 = 3 - 9x, psi_1 = 9x - 2:
//    g_0 = d int_0^1/2 (3 - 9x) dx = 3/8 d, g_1 = d int_0^1/2 (9x - 2) dx =
//    1/8 d, both positive for the clear gap (the dual functions of the
//    whole face gave 0.625 d and -0.125 d, a weighted penetration);
//  - partial and tilted: gap d + s x over the same half: linear, so by
//    biorthogonality g_j = (gap at node j) int_0^1/2 N_j: g_0 = 3/8 d,
//    g_1 = (d + s)/8;
//  - tilted: gap d + s x: the gap is linear, so by biorthogonality
//    g_j = (nodal gap) / 2: g_0 = d/2, g_1 = (d + s)/2;
//  - kinked: gap d + s |x - 1/2| over two primary faces:
//    g_j = d/2 + s int_0^1 psi_j |x - 1/2| dx = d/2 + s/8.
// Also: the dual basis is biorthogonal and sums to one, on the whole face
// and on covered parts (one end, the middle, two pieces, a sliver of 1e-3 of
// the face; a face covered by two segments without gap gets the closed form
// exactly), and on the kinked
// interface and on a curved one (the Hertz cylinder's arc, with nodal
// normals that vary) the contact forces on both sides cancel to round-off.
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_tools.h>

#include <contact_dynamics/contact/mortar_contact.h>
#include <contact_dynamics/contact/mortar_geometry.h>
#include <contact_dynamics/simulator.h>

#include "tests.h"

#include <fstream>
#include <random>

using namespace dealii;

namespace
{
  // A Gmsh file: the unit square on top, and quads below whose top nodes
  // are `top` (left to right) and whose bottom is y = -1.
  void
  write_mesh(const std::string &name, const std::vector<Point<2>> &top)
  {
    std::vector<Point<2>> nodes{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (const auto &p : top)
      nodes.push_back(p);
    for (const auto &p : top)
      nodes.emplace_back(p[0], -1);
    const unsigned int n = top.size();
    std::ofstream      f(name);
    f << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n5\n"
      << "1 1 \"secondary\"\n1 2 \"primary\"\n1 3 \"rest\"\n"
      << "2 4 \"upper\"\n2 5 \"lower\"\n$EndPhysicalNames\n$Nodes\n"
      << nodes.size() << "\n";
    for (unsigned int i = 0; i < nodes.size(); ++i)
      f << i + 1 << " " << nodes[i][0] << " " << nodes[i][1] << " 0\n";
    f << "$EndNodes\n";
    std::vector<std::string> elements;
    const auto               line = [&](int tag, unsigned a, unsigned b) {
      elements.push_back("1 2 " + std::to_string(tag) + " " +
                         std::to_string(tag) + " " + std::to_string(a) + " " +
                         std::to_string(b));
    };
    const auto quad =
      [&](int tag, unsigned a, unsigned b, unsigned c, unsigned d) {
        elements.push_back("3 2 " + std::to_string(tag) + " " +
                           std::to_string(tag) + " " + std::to_string(a) + " " +
                           std::to_string(b) + " " + std::to_string(c) + " " +
                           std::to_string(d));
      };
    line(1, 1, 2);
    line(3, 2, 3);
    line(3, 3, 4);
    line(3, 4, 1);
    quad(4, 1, 2, 3, 4);
    for (unsigned int i = 0; i + 1 < n; ++i)
      {
        const unsigned t0 = 5 + i, t1 = 6 + i, b0 = 5 + n + i, b1 = 6 + n + i;
        line(2, t1, t0);
        line(3, b0, b1);
        quad(5, b0, b1, t1, t0);
      }
    line(3, 5, 5 + n);
    line(3, 4 + 2 * n, 4 + n);
    f << "$Elements\n" << elements.size() << "\n";
    for (unsigned int i = 0; i < elements.size(); ++i)
      f << i + 1 << " " << elements[i] << "\n";
    f << "$EndElements\n";
  }

  const ContactDynamics::MortarContact<2> *
  setup(ContactDynamics::Simulator<2> &simulator)
  {
    simulator.initialize();
    return dynamic_cast<const ContactDynamics::MortarContact<2> *>(
      simulator.get_contact());
  }

  std::string
  parameters(const std::string &mesh)
  {
    return R"(
subsection Scene
  set Scene = gmsh
  set Mesh file = )" +
           mesh + R"(
end
subsection Boundary conditions
  set Dirichlet =
end
subsection Time integration
  set Scheme = quasi-static
end
subsection Contact
  set Formulation = mortar
  set Pairs = secondary: primary
  subsection Mortar
    set Segment quadrature points = 3
  end
end
subsection Output
  set Output directory = output_gap
  set VTU interval = 0
end
)";
  }

  // |sum of the residual over x (y) displacement unknowns| / sum of |.|
  void
  check_force_balance(const std::string             &name,
                      ContactDynamics::Simulator<2> &simulator)
  {
    simulator.initialize();
    ContactDynamics::VectorType trial(simulator.displacement()),
      residual(trial);
    // random multipliers: the forces on both sides must cancel
    std::mt19937 rng(3);
    for (const auto i : simulator.get_contact()->multiplier_dofs())
      trial(i) = std::uniform_real_distribution<double>(1, 2)(rng);
    simulator.residual_and_jacobian(trial, 1., residual);
    // less the bodies' own forces at the multiplier-free state: those of an
    // initial rigid translation are round-off of the size eps |K| |u| (the
    // residual of linear elastic bodies is the product K u), not zero
    ContactDynamics::VectorType bodies(residual);
    simulator.residual_and_jacobian(simulator.displacement(), 1., bodies);
    residual -= bodies;
    const auto &dh     = simulator.get_dof_handler();
    double      sum[2] = {0, 0}, size = 0;
    for (unsigned int d = 0; d < 2; ++d)
      {
        std::vector<bool> mask(4, false);
        mask[d] = true;
        for (const auto i : DoFTools::extract_dofs(dh, ComponentMask(mask)))
          {
            sum[d] += residual(i);
            size += std::abs(residual(i));
          }
      }
    check_true(name + ": contact forces present", size > 1e-3);
    check_close(name + ": net contact force / total (x)",
                sum[0] / size,
                0.,
                1e-14);
    check_close(name + ": net contact force / total (y)",
                sum[1] / size,
                0.,
                1e-14);
  }

  // weighted gaps of the two secondary nodes, ordered by x
  std::pair<double, double>
  weighted_gaps(const std::string           &name,
                const std::vector<Point<2>> &top,
                bool                         check_balance = false)
  {
    write_mesh(name + ".msh", top);
    ParameterHandler prm;
    read_test_parameters(name + ".prm", parameters(name + ".msh"), prm);
    std::ostringstream            screen;
    ContactDynamics::Simulator<2> simulator(prm, screen);
    const auto                   *mortar = setup(simulator);

    if (check_balance)
      {
        ContactDynamics::Simulator<2> other(prm, screen);
        check_force_balance(name, other);
      }
    ContactDynamics::VectorType trial(simulator.displacement()),
      residual(trial);
    simulator.residual_and_jacobian(trial, 1., residual);
    const auto &s     = mortar->secondary_surface(0);
    const auto &nodes = mortar->node_states(0);
    return s.reference[0][0] < s.reference[1][0] ?
             std::make_pair(nodes[0].gap, nodes[1].gap) :
             std::make_pair(nodes[1].gap, nodes[0].gap);
  }
} // namespace

int
main()
{
  initlog();
  using namespace ContactDynamics::MortarGeometry;
  using namespace ContactDynamics::SegmentGeometry;

  // dual basis: integral(psi_i N_j) = delta_ij integral(N_j), sum psi = 1
  const QGauss<1> gauss(3);
  double          worst = 0, worst_sum = 0;
  for (unsigned int i = 0; i < 2; ++i)
    for (unsigned int j = 0; j < 2; ++j)
      {
        double integral = 0;
        for (unsigned int q = 0; q < gauss.size(); ++q)
          {
            const double xi = 2 * gauss.point(q)[0] - 1;
            integral += dual_shape(xi)[i] * shape(xi)[j] * 2 * gauss.weight(q);
            worst_sum =
              std::max(worst_sum,
                       std::abs(dual_shape(xi)[0] + dual_shape(xi)[1] - 1));
          }
        worst = std::max(worst, std::abs(integral - (i == j ? 1. : 0.)));
      }
  check_close("biorthogonality of the dual basis", worst, 0., 1e-15);
  check_close("partition of unity of the dual basis", worst_sum, 0., 1e-15);

  // the dual basis of covered parts: biorthogonal on what is covered
  {
    using Segments = std::vector<std::pair<double, double>>;
    const QGauss<1> q3(3); // integrates psi_i N_j exactly
    const auto      check_covered = [&](const std::string &name,
                                   const Segments    &segments,
                                   const double       tolerance) {
      const auto a     = dual_coefficients(segments);
      double     error = 0, sum_error = 0, D[2] = {0, 0};
      double     integral[2][2] = {{0, 0}, {0, 0}};
      for (const auto &seg : segments)
        for (unsigned int q = 0; q < q3.size(); ++q)
          {
            const double xi =
              seg.first + (seg.second - seg.first) * q3.point(q)[0];
            const double w   = (seg.second - seg.first) * q3.weight(q);
            const auto   psi = dual_shape(xi, a);
            const auto   N   = shape(xi);
            sum_error = std::max(sum_error, std::abs(psi[0] + psi[1] - 1));
            for (unsigned int i = 0; i < 2; ++i)
              {
                D[i] += N[i] * w;
                for (unsigned int j = 0; j < 2; ++j)
                  integral[i][j] += psi[i] * N[j] * w;
              }
          }
      // relative to integral N_j of the node
      for (unsigned int i = 0; i < 2; ++i)
        for (unsigned int j = 0; j < 2; ++j)
          error =
            std::max(error,
                     std::abs(integral[i][j] - (i == j ? D[j] : 0.)) / D[j]);
      check_close(name + ": biorthogonality on the covered part",
                  error,
                  0.,
                  tolerance);
      check_close(name + ": partition of unity", sum_error, 0., tolerance);
    };
    check_covered("one end", {{-1., 0.}}, 1e-14);
    check_covered("middle", {{-0.3, 0.4}}, 1e-14);
    check_covered("two pieces", {{-1., -0.5}, {0.2, 0.9}}, 1e-14);
    // condition number of M about 1.2e7; measured 2e-13
    check_covered("sliver of 1e-3", {{-1., -1. + 2e-3}}, 1e-11);
    const auto a = dual_coefficients(Segments{{-1., 0.1}, {0.1, 1.}});
    check_true("covered by two segments: closed form exactly",
               a[0][0] == 2. && a[0][1] == -1. && a[1][0] == -1. &&
                 a[1][1] == 2.);
    const auto h = dual_coefficients(Segments{{-1., 0.}});
    check_close("one end: A = [[3, -6], [-2, 7]] (by hand)",
                std::abs(h[0][0] - 3) + std::abs(h[0][1] + 6) +
                  std::abs(h[1][0] + 2) + std::abs(h[1][1] - 7),
                0.,
                1e-13);
  }

  const double d = 0.01, s = 0.02;
  auto         g = weighted_gaps("offset", {{-0.3, -d}, {1.2, -d}});
  check_close("offset: g_0", g.first, d / 2, 1e-14);
  check_close("offset: g_1", g.second, d / 2, 1e-14);
  g = weighted_gaps("partial", {{-0.3, -d}, {0.5, -d}});
  check_close("partial: g_0", g.first, 3. / 8 * d, 1e-14);
  check_close("partial: g_1", g.second, 1. / 8 * d, 1e-14);
  g = weighted_gaps("partial_tilted",
                    {{-0.3, -d + 0.3 * s}, {0.5, -d - 0.5 * s}});
  check_close("partial tilted: g_0", g.first, 3. / 8 * d, 1e-14);
  check_close("partial tilted: g_1", g.second, (d + s) / 8, 1e-14);
  g = weighted_gaps("tilted", {{-0.3, -d + 0.3 * s}, {1.2, -d - 1.2 * s}});
  check_close("tilted: g_0", g.first, d / 2, 1e-14);
  check_close("tilted: g_1", g.second, (d + s) / 2, 1e-14);
  g = weighted_gaps("kinked",
                    {{-0.3, -d - 0.8 * s}, {0.5, -d}, {1.3, -d - 0.8 * s}},
                    true);
  check_close("kinked: g_0", g.first, d / 2 + s / 8, 1e-14);
  check_close("kinked: g_1", g.second, d / 2 + s / 8, 1e-14);

  // a curved secondary surface (the Hertz cylinder) pressed into the block
  ParameterHandler prm;
  read_test_parameters("curved.prm",
                       R"(
subsection Scene
  set Scene = hertz
  set Refinement factor = 0.3
end
subsection Body cylinder
  set Initial displacement = 0.001; -0.01
end
subsection Time integration
  set Scheme = quasi-static
end
subsection Contact
  set Formulation = mortar
  set Pairs = cylinder_arc: block_top
  set Initial penetration = allow
end
subsection Output
  set Output directory = output_curved
  set VTU interval = 0
end
)",
                       prm);
  std::ostringstream            screen;
  ContactDynamics::Simulator<2> curved(prm, screen);
  check_force_balance("curved (Hertz) interface", curved);
}
