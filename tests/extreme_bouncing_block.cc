// Extreme cases on the paper's bouncing block (stabilized mortar), through
// the first contact (1 s unless said): each completes with bounded energy
// or stops with a clear message (tests/extreme.h).
#include "extreme.h"

int
main()
{
  initlog();
  const std::string file = "prm/bouncing_block/mortar_stabilized.prm";
  const std::string top  = "substrate_bottom: xy: 0; block_top: x: ";
  const std::vector<ExtremeCase> cases = {
    {"stiffness ratio 1e6",
     file,
     {{"Body substrate/Young's modulus", "1e12"}},
     1},
    {"nu = 0.49",
     file,
     {{"Body block/Poisson's ratio", "0.49"},
      {"Body substrate/Poisson's ratio", "0.49"}},
     1},
    {"time step 10 x", file, {{"Time integration/Time step", "0.25"}}, 2},
    {"time step / 100",
     file,
     {{"Time integration/Time step", "0.00025"},
      {"Time integration/Minimum time step", "1e-7"}},
     0.26},
    {"c_n = 1e2", file, {{"Contact/Mortar/c_n", "1e2"}}, 1},
    {"c_n = 1e10", file, {{"Contact/Mortar/c_n", "1e10"}}, 1},
    // friction: the top also slides sideways at 0.5 (and the block with
    // it from the start: an impulsive start has its own energy error)
    {"mu = 0.5, c_t = 1e-2",
     file,
     {{"Contact/Friction coefficients", "0.5"},
      {"Body block/Initial velocity", "0.5; 0"},
      {"Contact/Mortar/c_t", "1e-2"},
      {"Boundary conditions/Dirichlet",
       top + "0.5*t; block_top: y: 0.2*cos(2*pi/4*t) - 0.19"}},
     1},
    {"mu = 1, c_t = 1e6",
     file,
     {{"Contact/Friction coefficients", "1"},
      {"Body block/Initial velocity", "0.5; 0"},
      {"Contact/Mortar/c_t", "1e6"},
      {"Boundary conditions/Dirichlet",
       top + "0.5*t; block_top: y: 0.2*cos(2*pi/4*t) - 0.19"}},
     1},
    // the block starts 0.01 inside the substrate: stops before the first
    // step and says where (pushing them apart would create energy)
    {"initial penetration 0.01",
     file,
     {{"Body block/Initial displacement", "0; -0.01"},
      {"Boundary conditions/Dirichlet",
       top + "0; block_top: y: 0.2*cos(2*pi/4*t) - 0.21"}},
     1,
     "Initial penetration"},
  };
  for (const auto &c : cases)
    check_extreme_case(c);
}
