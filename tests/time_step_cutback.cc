// Automatic time-step cutback. A neo-Hookean block is stretched
// quasi-statically to four times its length with at most 5 Newton
// iterations per step:
// 1. a step of 1 fails, is halved, and the run still reaches the end time,
//    growing the step back after two good steps; since the material is
//    hyperelastic the final state does not depend on the load path, so it
//    must equal that of a run with fixed small steps;
// 2. with 1 Newton iteration allowed no step can succeed: the run stops
//    with a message naming 'Minimum time step', and statistics.csv keeps the
//    rows written so far.
#include <deal.II/base/utilities.h>

#include <deal.II/numerics/vector_tools.h>

#include <contact_dynamics/simulator.h>

#include "tests.h"

#include <fstream>

using namespace dealii;

namespace
{
  std::string
  parameters(const double time_step, const unsigned int max_iterations)
  {
    return R"(
subsection Scene
  set Scene = block
  subsection Block
    set Size = 1, 1
    set Subdivisions = 2, 2
  end
end
subsection Body body
  set Material model = neo-Hookean
  set Young's modulus = 10
  set Poisson's ratio = 0.3
end
subsection Boundary conditions
  set Dirichlet = left: x: 0; bottom: y: 0; right: x: 1.5*t
end
subsection Time integration
  set Scheme = quasi-static
  set End time = 2
  set Minimum time step = 0.1
  set Time step = )" +
           std::to_string(time_step) + R"(
end
subsection Nonlinear solver
  set Absolute tolerance = 1e-12
  set Maximum iterations = )" +
           std::to_string(max_iterations) + R"(
end
subsection Output
  set Output directory = output_cutback
  set VTU interval = 0
end
)";
  }

  double
  corner_uy(const ContactDynamics::Simulator<2> &simulator)
  {
    Vector<double> value(2);
    VectorTools::point_value(simulator.get_dof_handler(),
                             simulator.displacement(),
                             Point<2>(1, 1),
                             value);
    return value(1);
  }
} // namespace

int
main()
{
  initlog();
  std::ostringstream screen;

  double                                     reference;
  std::map<std::string, std::vector<double>> completed;
  {
    ParameterHandler prm;
    read_test_parameters("fine.prm", parameters(0.125, 25), prm);
    ContactDynamics::Simulator<2> simulator(prm, screen);
    simulator.run();
    reference = corner_uy(simulator);
  }
  {
    ParameterHandler prm;
    read_test_parameters("cut.prm", parameters(1, 5), prm);
    ContactDynamics::Simulator<2> simulator(prm, screen);
    simulator.run();
    check_close("final time", simulator.current_time(), 2., 1e-12);
    check_close("final lateral displacement = that of small fixed steps",
                corner_uy(simulator),
                reference,
                1e-9);
    completed = read_csv_columns("output_cutback/statistics.csv");
    std::string dts;
    for (const double dt : completed.at("dt"))
      dts += (dts.empty() ? "" : " ") + std::to_string(dt).substr(0, 4);
    deallog << "accepted steps: " << completed.at("step").size() - 1
            << ", dt: " << dts << std::endl;
    deallog << "time step cuts: " << completed.at("time_step_cuts").back()
            << std::endl;
  }
  {
    ParameterHandler prm;
    read_test_parameters("fail.prm", parameters(1, 1), prm);
    ContactDynamics::Simulator<2> simulator(prm, screen);
    try
      {
        simulator.run();
        check_true("the run must stop", false);
      }
    catch (const ExceptionBase &e)
      {
        std::ostringstream message;
        e.print_info(message);
        check_true("the message names 'Minimum time step'",
                   message.str().find("Minimum time step") !=
                     std::string::npos);
      }
    // the columns of the completed run, each with the initial row only
    const auto columns = read_csv_columns("output_cutback/statistics.csv");
    bool       kept    = columns.size() == completed.size() &&
                columns.count("energy_balance_error") == 1;
    for (const auto &column : columns)
      kept =
        kept && completed.count(column.first) == 1 && column.second.size() == 1;
    check_true("statistics.csv keeps its header and the initial row", kept);
  }
}
