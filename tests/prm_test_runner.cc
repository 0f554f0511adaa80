// Runs a .prm test through the library as the executable would, then
// writes "output": the error message of a failed run (to fix its wording),
// or a few robust facts of the finished run read back from statistics.csv.
//
// A test file may state its tolerance on the energy balance error relative
// to the energy scale of the run with a comment line
//   # TEST: energy balance tolerance = 1e-9
#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <contact_dynamics/application.h>

#include "tests.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

using namespace dealii;

namespace
{
  std::string
  significant(const double x, const int digits = 4)
  {
    std::ostringstream s;
    s << std::setprecision(digits) << (std::abs(x) < 1e-300 ? 0. : x);
    return s.str();
  }

  double
  stated_tolerance(const std::string &filename)
  {
    std::ifstream     in(filename);
    std::string       line;
    const std::string key = "# TEST: energy balance tolerance =";
    while (std::getline(in, line))
      if (line.rfind(key, 0) == 0)
        return std::stod(line.substr(key.size()));
    return 1e-8;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  // under mpirun the first process writes the files
  const bool    root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  std::ofstream output(root ? "output" : "/dev/null");
  std::ofstream screen(root ? "screen-output" : "/dev/null");
  const std::string filename = argv[1];
  try
    {
      ContactDynamics::run_parameter_file(filename, screen);
    }
  catch (const ExceptionBase &e)
    {
      std::ostringstream info;
      e.print_info(info);
      // the test directory differs between machines
      std::string text = info.str();
      const auto  pos  = text.find(SOURCE_DIR);
      if (pos != std::string::npos)
        text.replace(pos, std::string(SOURCE_DIR).size(), "SOURCE_DIR");
      output << "Error: " << text << std::endl;
      return 0;
    }

  if (!root)
    return 0;
  ParameterHandler prm;
  ContactDynamics::read_parameters(filename, prm);
  prm.enter_subsection("Output");
  const std::string directory = prm.get("Output directory");
  prm.leave_subsection();

  const auto s    = read_csv_columns(directory + "/statistics.csv");
  const auto last = [&](const std::string &name) {
    return s.at(name).back();
  };

  double scale = 0, worst = 0;
  for (unsigned int i = 0; i < s.at("step").size(); ++i)
    {
      scale = std::max({scale,
                        s.at("kinetic_energy")[i] + s.at("elastic_energy")[i],
                        std::abs(s.at("external_work")[i]),
                        s.at("damping_dissipation")[i]});
      worst = std::max(worst, std::abs(s.at("energy_balance_error")[i]));
    }
  const double tolerance = stated_tolerance(filename);
  output << "steps: " << last("step") << std::endl
         << "final time: " << significant(last("time"), 6) << std::endl
         << "final kinetic energy: " << significant(last("kinetic_energy"))
         << std::endl
         << "final elastic energy: " << significant(last("elastic_energy"))
         << std::endl
         << "energy balance error below " << tolerance
         << " of the energy scale: "
         << (worst <= tolerance * scale ? "yes" :
                                          "NO, " + significant(worst / scale))
         << std::endl;
  return 0;
}
