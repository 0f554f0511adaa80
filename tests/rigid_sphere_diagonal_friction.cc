// A rigid sphere (R = 0.5) pressed 0.01 into a block (4 x 0.5 x 4, bottom
// fixed, quasi-static, E = 1e3) and dragged diagonally across it with
// Coulomb friction mu = 0.2, 3-D mortar. Each secondary node's tangent
// basis used to be built from the sphere's normal at the node's reference
// position at t = 0: a node diagonally away from the sphere's start got the
// vertical axis, and when the sphere arrived every step was rejected (the
// normal "turned by more than 37 degrees"; the run stopped at t = 0.73).
// The axes now come from the block's own surface normal. Asserted, from
// Coulomb's law for a body sliding without rolling (every node in the
// patch slips against the sphere's motion):
// - every step converges, to t = 1.2 (the sphere's centre from (-0.5,
//   -0.5) to (0.5, 0.5) in x and z, indenting by 0.08: contact radius
//   0.2, 1.6 cells);
// - once the sphere slides (t >= 0.4), the tangential force on it points
//   against its motion, (-1, 0, -1)/sqrt(2), within 2 degrees;
// - the mean ratio of the tangential force to mu times the vertical one is
//   within [0.9, 1.15] (Coulomb's law with the tractions tilted on the
//   indented cap, half-angle 24 degrees), for the diagonal and for the same
//   sphere dragged along x as far; the two agree within 10 % (the continuum
//   is isotropic in x and z, the mesh is not: measured 1.070 diagonally,
//   0.989 along x, with 1.6 cells per contact radius).
#include <contact_dynamics/contact/surface_contact.h>
#include <contact_dynamics/simulator.h>

#include "tests.h"

#include <cmath>

using namespace dealii;

namespace
{
  // the mean ratio |F_t| / (mu |F_y|) and the largest angle between F_t and
  // the reversed motion, from t = 0.4 to 1.2; false if a step failed
  bool
  drag(const std::string &translation,
       const Tensor<1, 2> &direction,
       double             &mean_ratio,
       double             &worst_turn)
  {
    ParameterHandler prm;
    read_test_parameters("diagonal_sphere.prm",
                         R"(
set Dimension = 3
subsection Scene
  set Scene = block
  subsection Block
    set Origin       = -1, 0, -1
    set Size         = 2, 0.5, 2
    set Subdivisions = 16, 2, 16
  end
end
subsection Body body
  set Young's modulus = 1e3
  set Poisson's ratio = 0.3
end
subsection Boundary conditions
  set Dirichlet = bottom: xyz: 0
end
subsection Time integration
  set Scheme    = quasi-static
  set Time step = 0.05
  set End time  = 1.2
end
subsection Contact
  set Formulation           = mortar
  set Rigid obstacles       = ball
  set Pairs                 = top: ball
  set Friction coefficients = 0.2
  subsection Rigid obstacle ball
    set Shape       = sphere
    set Point       = -0.5, 1.005, -0.5
    set Radius      = 0.5
    set Translation = )" + translation +
                           R"(
  end
  subsection Mortar
    set c_n = 1e3
    set c_t = 1e3
  end
end
subsection Output
  set Output directory = output_diagonal_sphere
  set VTU interval = 0
end
)",
                         prm);
    std::ostringstream            screen;
    ContactDynamics::Simulator<3> simulator(prm, screen);
    simulator.initialize();
    const double mu = 0.2, dt = 0.05;
    double       sum = 0;
    unsigned int count = 0;
    worst_turn         = 0;
    mean_ratio         = 0;
    for (unsigned int n = 1; n <= 24; ++n)
      {
        if (!simulator.advance(dt))
          return false;
        if (n * dt < 0.4 - 1e-12)
          continue;
        const auto   stats = contact_statistics(*simulator.get_contact());
        const double fx    = stats.at("ball_force_x");
        const double fz    = stats.at("ball_force_z");
        const double ft    = std::hypot(fx, fz);
        const double cosine =
          -(fx * direction[0] + fz * direction[1]) / (ft * direction.norm());
        worst_turn =
          std::max(worst_turn,
                   std::acos(std::min(1., cosine)) * 180 / numbers::PI);
        sum += ft / (mu * std::abs(stats.at("ball_force_y")));
        ++count;
      }
    mean_ratio = sum / count;
    return true;
  }
} // namespace

int
main()
{
  initlog();
  double ratio_diagonal, turn_diagonal, ratio_x, turn_x;
  check_true("diagonal: every step converges to t = 1.2",
             drag("max(t-0.2,0); -0.085*min(t/0.2,1); max(t-0.2,0)",
                  Tensor<1, 2>({1., 1.}),
                  ratio_diagonal,
                  turn_diagonal));
  check_true("along x: every step converges to t = 1.2",
             drag("1.41421356*max(t-0.2,0); -0.085*min(t/0.2,1); 0",
                  Tensor<1, 2>({1., 0.}),
                  ratio_x,
                  turn_x));
  check_range("diagonal: largest angle (degrees) between the friction "
              "force on the sphere and its motion reversed",
              turn_diagonal,
              0.,
              2.);
  check_range("diagonal: mean |F_t| / (mu |F_y|)", ratio_diagonal, 0.9, 1.15);
  check_range("along x: mean |F_t| / (mu |F_y|)", ratio_x, 0.9, 1.15);
  check_range("diagonal / along x, mean |F_t| / (mu |F_y|), - 1",
              ratio_diagonal / ratio_x - 1,
              -0.1,
              0.1);
}
