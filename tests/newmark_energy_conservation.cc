// Newmark beta = 1/4, gamma = 1/2 conserves the discrete energy of an
// undamped linear elastic body exactly: a block clamped at its bottom,
// started with a non-uniform velocity field, vibrates for 400 steps while
// kinetic + elastic energy stays at its initial value to about 1e-10
// relative (the Dirichlet support does no work).
#include <contact_dynamics/simulator.h>

#include "tests.h"

int
main()
{
  initlog();
  dealii::ParameterHandler prm;
  read_test_parameters("energy.prm",
                       R"(
subsection Scene
  set Scene = block
  subsection Block
    set Size = 1, 0.5
    set Subdivisions = 8, 4
  end
end
subsection Body body
  set Young's modulus = 1000
  set Poisson's ratio = 0.3
  set Density = 2
  set Initial velocity = 0.3*y*y; -0.1*x*y
end
subsection Boundary conditions
  set Dirichlet = bottom: xy: 0
end
subsection Time integration
  set Time step = 0.01
  set End time = 4
end
subsection Output
  set Output directory = output_energy
  set VTU interval = 0
end
)",
                       prm);
  std::ostringstream            screen;
  ContactDynamics::Simulator<2> simulator(prm, screen);
  simulator.initialize();
  const double initial = simulator.energy().initial;
  double       worst = 0, min_kinetic = initial;
  for (unsigned int n = 0; n < 400; ++n)
    {
      if (!simulator.advance(0.01))
        check_true("step " + std::to_string(n) + " converged", false);
      const auto &e = simulator.energy();
      worst       = std::max(worst, std::abs(e.kinetic + e.elastic - initial));
      min_kinetic = std::min(min_kinetic, e.kinetic);
    }
  dealii::deallog << "steps: " << simulator.n_steps() << std::endl;
  check_true("the energy is exchanged (kinetic energy drops below half)",
             min_kinetic < 0.5 * initial);
  check_close("relative energy drift over 400 steps",
              worst / initial,
              0.,
              1e-10);
  // informational (numdiff compares values below 1e-6 as equal)
  dealii::deallog << "measured relative drift: " << worst / initial
                  << std::endl;
  check_close("relative energy balance error",
              simulator.energy().error() / initial,
              0.,
              1e-10);
}
