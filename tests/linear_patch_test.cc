// Patch test on the distorted five-element patch of MacNeal and Harder
// (1985), read from a Gmsh file: with boundary values of a linear field,
// the discrete solution must reproduce the field at every node and the
// stored energy must be W(F) times the area; for linear elasticity and for
// a finite homogeneous deformation of a neo-Hookean body.
#include <deal.II/base/tensor.h>

#include <contact_dynamics/simulator.h>

#include "tests.h"

#include <fstream>

using namespace dealii;

namespace
{
  const char *mesh = R"($MeshFormat
2.2 0 8
$EndMeshFormat
$PhysicalNames
2
1 1 "boundary"
2 2 "patch"
$EndPhysicalNames
$Nodes
8
1 0 0 0
2 0.24 0 0
3 0.24 0.12 0
4 0 0.12 0
5 0.04 0.02 0
6 0.18 0.03 0
7 0.16 0.08 0
8 0.08 0.08 0
$EndNodes
$Elements
9
1 1 2 1 1 1 2
2 1 2 1 2 2 3
3 1 2 1 3 3 4
4 1 2 1 4 4 1
5 3 2 2 5 1 2 6 5
6 3 2 2 6 2 3 7 6
7 3 2 2 7 3 4 8 7
8 3 2 2 8 4 1 5 8
9 3 2 2 9 5 6 7 8
$EndElements
)";

  // u = G x with the displacement gradient G
  void
  check(const std::string &model, const Tensor<2, 2> &G)
  {
    std::ostringstream dirichlet;
    dirichlet << "boundary: x: " << G[0][0] << "*x + " << G[0][1]
              << "*y; boundary: y: " << G[1][0] << "*x + " << G[1][1] << "*y";
    ParameterHandler prm;
    read_test_parameters("patch.prm",
                         R"(
subsection Scene
  set Scene = gmsh
  set Mesh file = patch.msh
end
subsection Body patch
  set Material model = )" + model +
                           R"(
  set Young's modulus = 1000
  set Poisson's ratio = 0.25
end
subsection Boundary conditions
  set Dirichlet = )" + dirichlet.str() +
                           R"(
end
subsection Time integration
  set Scheme = quasi-static
  set Time step = 1
  set End time = 1
end
subsection Nonlinear solver
  set Absolute tolerance = 1e-13
end
subsection Output
  set Output directory = output_patch
  set VTU interval = 0
end
)",
                         prm);
    std::ostringstream            screen;
    ContactDynamics::Simulator<2> simulator(prm, screen);
    simulator.run();

    const auto &dof_handler = simulator.get_dof_handler();
    double      worst       = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (unsigned int v = 0; v < 4; ++v)
        for (unsigned int d = 0; d < 2; ++d)
          worst = std::max(worst,
                           std::abs(simulator.displacement()(
                                      cell->vertex_dof_index(v, d)) -
                                    G[d] * cell->vertex(v)));
    check_close(model + ": nodal error / max displacement",
                worst / (G.norm() * 0.24),
                0.,
                1e-10);

    ContactDynamics::MaterialParameters p;
    p.model          = ContactDynamics::MaterialParameters::model_named(model);
    p.youngs_modulus = 1000;
    p.poissons_ratio = 0.25;
    Tensor<2, 2> P;
    Tensor<4, 2> A;
    double       W;
    ContactDynamics::create_material<2>(p)->evaluate(G, P, A, W);
    check_close(model + ": stored energy / (W(F) area)",
                simulator.energy().elastic / (W * 0.24 * 0.12),
                1.,
                1e-10);
  }
} // namespace

int
main()
{
  initlog();
  {
    std::ofstream f("patch.msh");
    f << mesh;
  }
  Tensor<2, 2> small;
  small[0][0] = 1e-3;
  small[0][1] = 5e-4;
  small[1][0] = 5e-4;
  small[1][1] = 1e-3;
  check("linear elastic", small);
  Tensor<2, 2> large;
  large[0][0] = 0.2;
  large[0][1] = 0.1;
  large[1][0] = 0.05;
  large[1][1] = -0.1;
  check("neo-Hookean", large);
}
