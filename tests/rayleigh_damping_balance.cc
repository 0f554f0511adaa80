// Energy balance with Rayleigh damping and prescribed boundary motion, for
// a linear elastic body and Newmark 1/4, 1/2, where the discrete balance
//   kinetic + elastic + dissipated - external work - initial = 0
// holds exactly (to solver tolerance):
// 1. free vibration with mass and stiffness damping: the energy decays and
//    the dissipation accounts for all of it;
// 2. a block shaken at its base: the reactions do work, the balance closes.
#include <contact_dynamics/simulator.h>

#include "tests.h"

namespace
{
  const std::string common = R"(
subsection Scene
  set Scene = block
  subsection Block
    set Size = 1, 0.5
    set Subdivisions = 6, 3
  end
end
subsection Time integration
  set Time step = 0.02
end
subsection Nonlinear solver
  set Absolute tolerance = 1e-13
end
subsection Output
  set VTU interval = 0
end
)";

  void
  run(const std::string &name, const std::string &extra, const bool decays)
  {
    dealii::ParameterHandler prm;
    read_test_parameters(name + ".prm", common + extra, prm);
    std::ostringstream            screen;
    ContactDynamics::Simulator<2> simulator(prm, screen);
    simulator.initialize();
    double scale = simulator.energy().initial;
    for (unsigned int n = 0; n < 300; ++n)
      {
        if (!simulator.advance(0.02))
          check_true(name + ": step converged", false);
        const auto &e = simulator.energy();
        scale = std::max({scale, e.kinetic + e.elastic, std::abs(e.external)});
      }
    const auto &e = simulator.energy();
    if (decays)
      {
        check_true(name + ": energy decays below 10 %",
                   e.kinetic + e.elastic < 0.1 * e.initial);
        check_close(name + ": dissipated / (initial - remaining)",
                    e.dissipated / (e.initial - e.kinetic - e.elastic),
                    1.,
                    1e-9);
      }
    else
      check_true(name + ": the support does work",
                 std::abs(e.external) > 1e-3 * scale);
    check_true(name + ": damping dissipates", e.dissipated > 0);
    check_close(name + ": energy balance error / energy scale",
                e.error() / scale,
                0.,
                1e-10);
  }
} // namespace

int
main()
{
  initlog();
  run("free_decay",
      R"(
subsection Body body
  set Young's modulus = 1000
  set Density = 2
  set Rayleigh mass coefficient = 0.2
  set Rayleigh stiffness coefficient = 0.005
  set Initial velocity = 0.3*y*y; -0.1*x*y
end
subsection Boundary conditions
  set Dirichlet = bottom: xy: 0
end
subsection Output
  set Output directory = output_free_decay
end
)",
      true);
  run("shaken_base",
      R"(
subsection Body body
  set Young's modulus = 1000
  set Density = 2
  set Rayleigh stiffness coefficient = 0.005
  set Body force = 0, -5
end
subsection Boundary conditions
  set Dirichlet = bottom: y: 0; bottom: x: 0.01*sin(7*t)
end
subsection Output
  set Output directory = output_shaken_base
end
)",
      false);
}
