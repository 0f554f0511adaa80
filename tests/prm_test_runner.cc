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

  std::ifstream csv(directory + "/statistics.csv");
  std::string   header, line;
  std::getline(csv, header);
  const auto columns = Utilities::split_string_list(header);
  std::vector<std::vector<double>> rows;
  while (std::getline(csv, line))
    rows.push_back(
      Utilities::string_to_double(Utilities::split_string_list(line)));
  const auto col = [&](const std::string &name) {
    return std::find(columns.begin(), columns.end(), name) - columns.begin();
  };

  double scale = 0, worst = 0;
  for (const auto &r : rows)
    {
      scale = std::max({scale,
                        r[col("kinetic_energy")] + r[col("elastic_energy")],
                        std::abs(r[col("external_work")]),
                        r[col("damping_dissipation")]});
      worst = std::max(worst, std::abs(r[col("energy_balance_error")]));
    }
  const double tolerance = stated_tolerance(filename);
  const auto  &last      = rows.back();
  output << "steps: " << last[col("step")] << std::endl
         << "final time: " << significant(last[col("time")], 6) << std::endl
         << "final kinetic energy: " << significant(last[col("kinetic_energy")])
         << std::endl
         << "final elastic energy: " << significant(last[col("elastic_energy")])
         << std::endl
         << "energy balance error below " << tolerance
         << " of the energy scale: "
         << (worst <= tolerance * scale ? "yes" :
                                          "NO, " + significant(worst / scale))
         << std::endl;
  return 0;
}
