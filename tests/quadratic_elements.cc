// Finite element/Polynomial degree = 2 in the bulk, against solutions known
// without the code:
// - a quadratic displacement field with the constant body force that
//   balances it in linear elasticity (quasi-static, the field on the whole
//   boundary): degree 2 holds it at every node and gets its stored energy
//   (integrated here by Gauss points) to round-off on straight cells, in
//   2-D and 3-D, where degree 1's energy is off;
// - a slender cantilever (10 x 1, plane strain) under its own weight: the
//   stored energy of a fine 2-D solution within a percent of Timoshenko's
//   beam theory, and against it, degree 2 on n x n/10 cells within 1.5 %
//   (n = 10) and 0.5 % (n = 20) where degree 1 with the same nodes (2n x
//   n/5 cells) locks in shear: off by more than 10 % and 3 %;
// - pure bending of a 10 x 1 beam held at both ends by the exact field
//   (quadratic, traction-free top and bottom): degree 2 on 10 x 1 cells
//   exact, degree 1 on 20 x 2 cells (the same nodes) off by more than 10 %;
// - the Hertz scene's half disc (radius 1, centre (0, 5), the arc below)
//   spinning about the origin, v = (y, -x): its kinetic energy is
//   rho/2 (pi/4 - 20/3 + 25 pi/2) when the cells follow the circle and the
//   velocity is interpolated at nodes on it. The mapping of degree 2 does
//   both: the error falls from that of a polygon (degree 1) by orders of
//   magnitude.
#include <deal.II/base/tensor.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/mapping_q.h>

#include <contact_dynamics/simulator.h>

#include "tests.h"

#include <iomanip>
#include <sstream>

using namespace dealii;

namespace
{
  const double E = 1000, nu = 0.3;

  std::string
  common_parameters(const unsigned int degree)
  {
    return R"(
subsection Finite element
  set Polynomial degree = )" +
           std::to_string(degree) + R"(
end
subsection Body body
  set Young's modulus = 1000
  set Poisson's ratio = 0.3
end
subsection Time integration
  set Scheme = quasi-static
  set Time step = 1
  set End time = 1
end
subsection Nonlinear solver
  set Absolute tolerance = 1e-13
  set Relative tolerance = 1e-12
end
subsection Output
  set Output directory = output_quadratic
  set VTU interval = 0
end
)";
  }

  // u_i = 1/2 H[i][j][k] x_j x_k, H symmetric in j, k
  template <int dim>
  double
  quadratic(const Tensor<3, dim> &H, const unsigned int i, const Point<dim> &x)
  {
    double u = 0;
    for (unsigned int j = 0; j < dim; ++j)
      for (unsigned int k = 0; k < dim; ++k)
        u += 0.5 * H[i][j][k] * x[j] * x[k];
    return u;
  }

  template <int dim>
  std::string
  quadratic_expression(const Tensor<3, dim> &H, const unsigned int i)
  {
    const char        *names = "xyz";
    std::ostringstream s;
    s << std::setprecision(17) << "0";
    for (unsigned int j = 0; j < dim; ++j)
      for (unsigned int k = 0; k < dim; ++k)
        s << " + " << 0.5 * H[i][j][k] << "*" << names[j] << "*" << names[k];
    return s.str();
  }

  // largest |u_h - u| over the nodes (support points) of every cell
  template <int dim, typename Exact>
  double
  nodal_error(const ContactDynamics::Simulator<dim> &simulator,
              const unsigned int                     degree,
              const Exact                           &exact)
  {
    const auto &dof_handler = simulator.get_dof_handler();
    std::map<types::global_dof_index, Point<dim>> points;
    DoFTools::map_dofs_to_support_points(MappingQ<dim>(degree),
                                         dof_handler,
                                         points);
    double worst = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        std::vector<types::global_dof_index> dofs(
          cell->get_fe().n_dofs_per_cell());
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < dofs.size(); ++i)
          {
            const unsigned int c =
              cell->get_fe().system_to_component_index(i).first;
            worst = std::max(worst,
                             std::abs(simulator.displacement()(dofs[i]) -
                                      exact(c, points[dofs[i]])));
          }
      }
    return worst;
  }

  // the stored energy of u = 1/2 H x x on the box [x0, x0 + size]: Gauss
  // points exact for the quadratic integrand
  template <int dim>
  double
  quadratic_field_energy(const Tensor<3, dim> &H,
                         const Point<dim>     &x0,
                         const Point<dim>     &size)
  {
    const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)),
                 mu     = E / (2 * (1 + nu));
    const QGauss<dim> gauss(3);
    double            energy = 0;
    for (unsigned int q = 0; q < gauss.size(); ++q)
      {
        Point<dim> x      = x0;
        double     volume = 1;
        for (unsigned int d = 0; d < dim; ++d)
          {
            x[d] += size[d] * gauss.point(q)[d];
            volume *= size[d];
          }
        Tensor<2, dim> grad; // du_i/dx_j = H_ijk x_k
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            for (unsigned int k = 0; k < dim; ++k)
              grad[i][j] += H[i][j][k] * x[k];
        const Tensor<2, dim> eps = 0.5 * (grad + transpose(grad));
        energy += gauss.weight(q) * volume *
                  (lambda / 2 * trace(eps) * trace(eps) +
                   mu * scalar_product(eps, eps));
      }
    return energy;
  }

  // a box of the block scene with cells and the surfaces held at the field
  template <int dim>
  struct Box
  {
    Point<dim>               origin, size;
    std::string              subdivisions;
    std::vector<std::string> held;
  };

  template <int dim>
  std::string
  list(const Point<dim> &p)
  {
    std::ostringstream s;
    for (unsigned int d = 0; d < dim; ++d)
      s << (d ? ", " : "") << p[d];
    return s.str();
  }

  // u = 1/2 H x x on the box, quasi-static, with the constant body force
  // that balances it: (largest nodal error / largest displacement, stored
  // energy / exact - 1)
  template <int dim>
  std::pair<double, double>
  quadratic_field_error(const unsigned int    degree,
                        const Tensor<3, dim> &H,
                        const Box<dim>       &box)
  {
    const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)),
                 mu     = E / (2 * (1 + nu));
    Tensor<1, dim> body_force; // -(lambda grad div u + mu (lap u + grad div u))
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int k = 0; k < dim; ++k)
        body_force[i] -= (lambda + mu) * H[k][k][i] + mu * H[i][k][k];

    std::ostringstream dirichlet, force;
    for (const auto &s : box.held)
      for (unsigned int i = 0; i < dim; ++i)
        dirichlet << (dirichlet.str().empty() ? "" : "; ") << s << ": "
                  << "xyz"[i] << ": " << quadratic_expression(H, i);
    for (unsigned int i = 0; i < dim; ++i)
      force << (i ? ", " : "") << std::setprecision(17) << body_force[i];

    ParameterHandler prm;
    read_test_parameters("quadratic_field.prm",
                         "set Dimension = " + std::to_string(dim) + R"(
subsection Scene
  set Scene = block
  subsection Block
    set Origin = )" + list(box.origin) +
                           "\n    set Size = " + list(box.size) +
                           "\n    set Subdivisions = " + box.subdivisions +
                           R"(
  end
end
subsection Boundary conditions
  set Dirichlet = )" + dirichlet.str() +
                           R"(
end
)" + common_parameters(degree) +
                           "subsection Body body\n  set Body force = " +
                           force.str() + "\nend\n",
                         prm);
    std::ostringstream              screen;
    ContactDynamics::Simulator<dim> simulator(prm, screen);
    simulator.run();
    double scale = 0; // the largest displacement
    for (const auto &cell : simulator.get_dof_handler().active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        for (unsigned int i = 0; i < dim; ++i)
          scale = std::max(scale, std::abs(quadratic(H, i, cell->vertex(v))));
    return {nodal_error(simulator,
                        degree,
                        [&](const unsigned int c, const Point<dim> &x) {
                          return c < dim ? quadratic(H, c, x) : 0.;
                        }) /
              scale,
            simulator.energy().elastic /
                quadratic_field_energy(H, box.origin, box.size) -
              1};
  }

  // any H: the body force -div sigma is constant; the field on the whole
  // boundary of a box with few cells
  template <int dim>
  std::pair<double, double>
  general_quadratic_field_error(const unsigned int degree)
  {
    Tensor<3, dim> H;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        for (unsigned int k = j; k < dim; ++k)
          H[i][j][k] = H[i][k][j] = 1e-3 * (1 + i + 2 * j - 0.7 * k);
    Box<dim> box;
    box.origin[0]    = -0.3;
    box.origin[1]    = 0.2;
    box.size[0]      = 1;
    box.size[1]      = 0.6;
    box.held         = {"left", "right", "bottom", "top"};
    box.subdivisions = dim == 2 ? "3, 2" : "2, 2, 2";
    if (dim == 3)
      {
        box.origin[dim - 1] = 0.1;
        box.size[dim - 1]   = 0.8;
        box.held.push_back("front");
        box.held.push_back("back");
      }
    return quadratic_field_error(degree, H, box);
  }

  // pure bending of a 10 x 1 plane-strain beam about y = 0, curvature k:
  // u_x = -k x y, u_y = k x^2 / 2 + nu / (1 - nu) k y^2 / 2 (sigma_yy =
  // sigma_xy = 0, no body force), held at both ends; n x n/10 cells
  double
  pure_bending_error(const unsigned int degree, const unsigned int n)
  {
    const double k = 1e-3;
    Tensor<3, 2> H;
    H[0][0][1] = H[0][1][0] = -k;
    H[1][0][0]              = k;
    H[1][1][1]              = nu / (1 - nu) * k;
    Box<2> box;
    box.origin       = Point<2>(0, -0.5);
    box.size         = Point<2>(10, 1);
    box.subdivisions = std::to_string(n) + ", " + std::to_string(n / 10);
    box.held         = {"left", "right"};
    return quadratic_field_error(degree, H, box).second;
  }

  // stored energy of the cantilever, 10 x 1 with n x m cells of `degree`
  double
  cantilever_energy(const unsigned int degree,
                    const unsigned int n,
                    const unsigned int m,
                    const double       q,
                    const std::string &solver = "auto")
  {
    ParameterHandler prm;
    read_test_parameters("cantilever.prm",
                         R"(
subsection Scene
  set Scene = block
  subsection Block
    set Origin = 0, 0
    set Size = 10, 1
    set Subdivisions = )" + std::to_string(n) +
                           ", " + std::to_string(m) + R"(
  end
end
subsection Boundary conditions
  set Dirichlet = left: xy: 0
end
)" + common_parameters(degree) +
                           "subsection Body body\n  set Body force = 0, " +
                           std::to_string(-q) +
                           "\nend\nsubsection Nonlinear solver\n  set Linear "
                           "solver = " +
                           solver + "\nend\n",
                         prm);
    std::ostringstream            screen;
    ContactDynamics::Simulator<2> simulator(prm, screen);
    simulator.run();
    return simulator.energy().elastic;
  }

  // kinetic energy of the Hertz scene's half disc (radius 1, density 1)
  // spinning about the origin beside the block at rest, over the exact
  // value, minus one
  double
  half_disc_energy_error(const unsigned int degree, const double factor)
  {
    ParameterHandler prm;
    read_test_parameters("half_disc.prm",
                         R"(
subsection Scene
  set Scene = hertz
  set Refinement factor = )" +
                           std::to_string(factor) +
                           R"(
end
subsection Finite element
  set Polynomial degree = )" +
                           std::to_string(degree) +
                           R"(
end
subsection Body cylinder
  set Density = 1
  set Initial velocity = y; -x
end
subsection Time integration
  set Time step = 1e-3
  set End time = 1e-3
end
subsection Output
  set Output directory = output_half_disc
  set VTU interval = 0
end
)",
                         prm);
    std::ostringstream            screen;
    ContactDynamics::Simulator<2> simulator(prm, screen);
    simulator.run();
    // 1/2 int (x^2 + y^2): pi/8 + (pi/8 + 2 * 5 * (-2/3) + 25 pi/2)
    const double exact = 0.5 * (numbers::PI / 4 - 20. / 3 + 12.5 * numbers::PI);
    return simulator.energy().kinetic / exact - 1;
  }
} // namespace

int
main()
{
  initlog();
  for (const unsigned int dim : {2, 3})
    {
      const auto [nodal, energy] = dim == 2 ?
                                     general_quadratic_field_error<2>(2) :
                                     general_quadratic_field_error<3>(2);
      const std::string name =
        std::to_string(dim) + "-D quadratic field, degree 2: ";
      check_close(name + "largest nodal error / largest displacement",
                  nodal,
                  0,
                  1e-10);
      check_close(name + "stored energy / exact - 1", energy, 0, 1e-10);
    }
  // degree 1 happens to be exact at the nodes of this uniform mesh (as
  // linear elements in 1-D), not in between: its energy is off
  check_range("2-D quadratic field, degree 1: |stored energy / exact - 1|",
              std::abs(general_quadratic_field_error<2>(1).second),
              1e-4,
              1);

  // the bending scene with an exact reference: at the same nodes (10 x 1
  // cells of degree 2, 20 x 2 of degree 1) degree 2 is exact, degree 1
  // locks in shear and stores too much energy
  check_close("pure bending, degree 2 on 10 x 1 cells: stored energy / "
              "exact - 1",
              pure_bending_error(2, 10),
              0,
              1e-10);
  check_range("pure bending, degree 1 on 20 x 2 cells (the same nodes): "
              "stored energy / exact - 1 (shear locking)",
              pure_bending_error(1, 20),
              0.1,
              100);

  // Timoshenko: plane strain E' = E / (1 - nu^2), I = H^3 / 12, shear
  // correction 5/6; load q per unit length (body force q, H = 1).
  // U = q/2 int w dx = q^2 L^5 / (40 E' I) + q^2 L^3 / (6 k G A).
  const double L = 10, q = 1e-3, Ep = E / (1 - nu * nu), I = 1. / 12,
               G = E / (2 * (1 + nu)), k = 5. / 6;
  const double timoshenko = q * q * std::pow(L, 5) / (40 * Ep * I) +
                            q * q * std::pow(L, 3) / (6 * k * G);
  // the 2-D solution: degree 2 on 160 x 16 cells (1e-4 from a run on
  // 320 x 32, doc/degree-bending-table.md); its clamped end makes it
  // stiffer than the beam by about half a percent
  const double reference = cantilever_energy(2, 160, 16, q);
  check_range("cantilever, 2-D solution / Timoshenko",
              reference / timoshenko,
              0.99,
              1);
  // the same nodes: degree 2 on n x m cells, degree 1 on 2n x 2m
  const auto error = [&](const unsigned int degree, const unsigned int n) {
    return 1 - cantilever_energy(degree, n, n / 10, q) / reference;
  };
  check_range("cantilever, 126 unknowns, degree 2 (10 x 1 cells): energy "
              "error",
              error(2, 10),
              0,
              0.015);
  check_range("cantilever, 126 unknowns, degree 1 (20 x 2 cells): energy "
              "error (shear locking)",
              error(1, 20),
              0.1,
              1);
  check_range("cantilever, 410 unknowns, degree 2 (20 x 2 cells): energy "
              "error",
              error(2, 20),
              0,
              0.005);
  check_range("cantilever, 410 unknowns, degree 1 (40 x 4 cells): energy "
              "error",
              error(1, 40),
              0.03,
              1);
  // AMG with the rigid-body modes at the nodes of degree 2
  check_close("cantilever, degree 2 on 40 x 4 cells: AMG's energy / the "
              "direct solver's - 1",
              cantilever_energy(2, 40, 4, q, "AMG") /
                  cantilever_energy(2, 40, 4, q) -
                1,
              0,
              1e-8);

  const double q1_disc = half_disc_energy_error(1, 0.5),
               q2_disc = half_disc_energy_error(2, 0.5);
  check_range("spinning half disc, degree 1: 1 - kinetic energy / exact "
              "(a polygon)",
              -q1_disc,
              1e-4,
              1e-2);
  check_range("spinning half disc, degree 2: |kinetic energy / exact - 1| "
              "(cells on the circle)",
              std::abs(q2_disc),
              0,
              1e-3 * std::abs(q1_disc));
}
