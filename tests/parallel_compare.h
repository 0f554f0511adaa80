// Runs a shipped scene on all processes of MPI_COMM_WORLD and on the first
// one alone, and compares the statistics (used by the .mpirun=N tests).
#ifndef contact_dynamics_tests_parallel_compare_h
#define contact_dynamics_tests_parallel_compare_h

#include <deal.II/base/mpi.h>

#include <contact_dynamics/contact/contact_formulation.h>
#include <contact_dynamics/simulator.h>

#include "tests.h"

using Sim     = ContactDynamics::Simulator<2>;
using Columns = std::map<std::string, std::vector<double>>;
using Changes = std::vector<std::pair<std::string, std::string>>;

namespace
{
  double
  max_abs(const std::vector<double> &values)
  {
    double m = 0;
    for (const double x : values)
      m = std::max(m, std::abs(x));
    return m;
  }

  // largest difference over the steps, relative to the column's own scale
  // (energies and work: to the largest kinetic + elastic energy; forces: to
  // the largest contact force)
  double
  worst_difference(const Columns &parallel, const Columns &serial)
  {
    std::vector<double> energy;
    for (unsigned int i = 0; i < serial.at("time").size(); ++i)
      energy.push_back(serial.at("kinetic_energy")[i] +
                       serial.at("elastic_energy")[i]);
    const double energy_scale = std::max(max_abs(energy), 1e-300);
    double       force_scale  = 1e-300;
    for (const char *f : {"contact_force_x", "contact_force_y"})
      if (serial.count(f))
        force_scale = std::max(force_scale, max_abs(serial.at(f)));

    double worst = 0;
    for (const auto &column : serial)
      {
        const std::string &name = column.first;
        if (name == "wall_time" || name == "final_residual" ||
            name.find("newton") != std::string::npos ||
            name == "linear_iterations")
          continue; // differ with the order of the round-off
        double scale = energy_scale;
        if (name.find("force") != std::string::npos)
          scale = force_scale;
        else if (name.find("nodes") != std::string::npos || name == "step" ||
                 name == "time" || name == "dt" || name == "time_step_cuts" ||
                 name == "energy_created")
          scale = 1; // counts, times and fractions
        const auto &p = parallel.at(name);
        for (unsigned int i = 0; i < column.second.size(); ++i)
          worst = std::max(worst, std::abs(p[i] - column.second[i]) / scale);
      }
    return worst;
  }

  // the histories of the monitored nodes (pressure and gap), relative to
  // each column's largest value
  double
  history_difference(const Columns &parallel, const Columns &serial)
  {
    double worst = 0;
    for (const auto &column : serial)
      {
        const double scale = std::max(max_abs(column.second), 1e-300);
        const auto  &p     = parallel.at(column.first);
        if (p.size() != column.second.size())
          return 1e300;
        for (unsigned int i = 0; i < p.size(); ++i)
          worst = std::max(worst, std::abs(p[i] - column.second[i]) / scale);
      }
    return worst;
  }

  template <int dim = 2>
  void
  compare(const std::string &name,
          const std::string &file,
          Changes            changes,
          const double       tolerance = 1e-7)
  {
    using Sim            = ContactDynamics::Simulator<dim>;
    const MPI_Comm world = MPI_COMM_WORLD;
    changes.emplace_back("Output/VTU interval", "0");
    Changes parallel_changes = changes, serial_changes = changes;
    parallel_changes.emplace_back("Output/Output directory",
                                  name + "_parallel");
    serial_changes.emplace_back("Output/Output directory", name + "_serial");

    std::vector<unsigned int> owned_nodes;
    const Columns             parallel =
      run_shipped<Sim>(file, parallel_changes, [&](const Sim &simulator) {
        owned_nodes = dealii::Utilities::MPI::gather(
          world,
          simulator.get_contact()->n_owned_contact_nodes());
      });
    Columns serial;
    if (dealii::Utilities::MPI::this_mpi_process(world) == 0)
      serial =
        run_shipped<Sim>(file, serial_changes, {}, nullptr, MPI_COMM_SELF);
    MPI_Barrier(world);
    if (dealii::Utilities::MPI::this_mpi_process(world) != 0)
      return;

    dealii::deallog << name << ": secondary nodes per process";
    for (const unsigned int n : owned_nodes)
      dealii::deallog << ' ' << n;
    dealii::deallog << std::endl;
    check_true(name + ": same steps",
               parallel.at("time").size() == serial.at("time").size() &&
                 serial.at("time").size() > 1);
    const double       worst = worst_difference(parallel, serial);
    std::ostringstream within;
    within << tolerance;
    check_true(name + ": statistics equal to serial within " + within.str(),
               worst <= tolerance);
    if (worst > tolerance)
      dealii::deallog << "  worst relative difference " << worst << std::endl;
    const Columns history =
      read_csv_columns(name + "_serial/contact_history.csv");
    if (history.size() > 1)
      check_true(name + ": monitored pressures and gaps equal to serial",
                 history_difference(read_csv_columns(
                                      name + "_parallel/contact_history.csv"),
                                    history) <= 1e-6);
    const auto &active = serial.at("active_contact_nodes");
    check_true(name + ": in contact", max_abs(active) > 0);
  }
} // namespace

#endif
