// The Simulator's output: statistics.csv, the screen and the VTU files.
#include <deal.II/base/exceptions.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>

#include <deal.II/numerics/vector_tools.h>

#include <contact_dynamics/output/checkpoint.h>
#include <contact_dynamics/parameters.h>
#include <contact_dynamics/simulator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <csignal>
#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/distributed/tria.h>
#include <filesystem>
#include <iomanip>
#include <limits>
#include <sstream>

namespace ContactDynamics
{
  template <int dim>
  std::vector<std::string>
  Simulator<dim>::statistics_columns() const
  {
    std::vector<std::string> columns{"step",
                                     "time",
                                     "dt",
                                     "newton_iterations",
                                     "cumulative_newton_iterations",
                                     "kinetic_energy",
                                     "elastic_energy",
                                     "damping_dissipation",
                                     "external_work",
                                     "energy_balance_error",
                                     "wall_time",
                                     "final_residual",
                                     "time_step_cuts",
                                     "linear_iterations"};
    if (integrator.is_dissipative())
      columns.insert(columns.begin() + 8, "numerical_dissipation");
    if (contact)
      for (const auto &c : contact->statistics_columns())
        columns.push_back(c);
    if (refinement.adapt_to_contact)
      for (const auto *c :
           {"cells", "unknowns", "mesh_changes", "transfer_energy"})
        columns.emplace_back(c);
    if (integrator.error_tolerance() > 0)
      for (const auto *c : {"error_estimate", "rejected_steps"})
        columns.emplace_back(c);
    columns.emplace_back("energy_created");
    return columns;
  }

  template <int dim>
  void
  Simulator<dim>::open_output_files(const bool append)
  {
    check_collectively(mpi_communicator, [&]() {
      if (is_root(mpi_communicator))
        statistics =
          std::make_unique<StatisticsFile>(output_parameters.directory +
                                             "/statistics.csv",
                                           statistics_columns(),
                                           append);
    });
    solution_writer =
      std::make_unique<SolutionWriter<dim>>(mpi_communicator,
                                            output_parameters.directory,
                                            contact ?
                                              contact->extra_component_names() :
                                              std::vector<std::string>());
  }

  template <int dim>
  void
  Simulator<dim>::print_problem_size()
  {
    pcout << "Scene '" << scene.name()
          << "': " << triangulation->n_global_active_cells() << " cells, "
          << dof_handler.n_dofs() << " unknowns, " << bodies.size() << " bod"
          << (bodies.size() == 1 ? "y" : "ies") << "; linear solver "
          << linear_solver_name << std::endl;
    if (scene.cell_geometry() && discretization.degree() == 1)
      pcout << "Note: the mesh file's cells are of second order; with "
               "Finite element/Polynomial degree = 1 their mid-side and "
               "centre nodes are ignored (straight cells)."
            << std::endl;
    if (balances_between_steps())
      pcout << "Time integration " << integrator.scheme_name()
            << ": alpha_m = " << integrator.alpha_m()
            << ", alpha_f = " << integrator.alpha_f()
            << ", beta = " << integrator.beta()
            << ", gamma = " << integrator.gamma() << std::endl;
    const unsigned int n_processes =
      Utilities::MPI::n_mpi_processes(mpi_communicator);
    if (n_processes > 1)
      {
        const auto cells =
          Utilities::MPI::gather(mpi_communicator,
                                 triangulation->n_locally_owned_active_cells());
        const auto unknowns =
          Utilities::MPI::gather(mpi_communicator, locally_owned.n_elements());
        const auto nodes =
          Utilities::MPI::gather(mpi_communicator,
                                 contact ? contact->n_owned_contact_nodes() :
                                           0u);
        pcout << n_processes << " MPI processes ("
              << (parallel_parameters.mesh ==
                      ParallelParameters::Mesh::distributed ?
                    std::string("distributed mesh") :
                    parallel_parameters.partitioner_name() + " partition")
              << "); cells / unknowns / secondary contact nodes:";
        for (unsigned int p = 0; p < cells.size(); ++p)
          pcout << (p ? ", " : " ") << cells[p] << " / " << unknowns[p] << " / "
                << nodes[p];
        pcout << std::endl;
      }
  }

  template <int dim>
  void
  Simulator<dim>::output_step(const unsigned int newton_iterations,
                              const double       final_residual,
                              const bool         force_vtu)
  {
    TimerOutput::Scope   t(*timer, "output");
    const EnergyBalance &energies = energy_account.balance();
    std::vector<double>  row{double(step),
                            time,
                            step == 0 ? 0. : controller.dt(),
                            double(newton_iterations),
                            double(controller.newton_iterations()),
                            energies.kinetic,
                            energies.elastic,
                            energies.dissipated,
                            energies.external,
                            energies.error(),
                            wall_time_before + wall_timer.wall_time(),
                            final_residual,
                            double(controller.n_cuts()),
                            double(step == 0 ? 0 : linear_iterations)};
    if (integrator.is_dissipative())
      row.insert(row.begin() + 8, energies.numerical);
    if (contact)
      for (const double x : contact->statistics())
        row.push_back(x);
    if (refinement.adapt_to_contact)
      for (const double x : {double(triangulation->n_global_active_cells()),
                             double(dof_handler.n_dofs()),
                             double(adaptation.n_mesh_changes()),
                             energies.transfer})
        row.push_back(x);
    if (integrator.error_tolerance() > 0)
      for (const double x : {step == 0 ? 0. : controller.estimate(),
                             double(controller.n_rejected())})
        row.push_back(x);
    if (step == 0)
      watchdog.reset(energies);
    const double created = step == 0 ? 0. : watchdog.created_fraction(energies);
    row.push_back(created);
    const unsigned int interval = output_parameters.vtu_interval;
    try
      {
        // a failed write (a full disk) stops every process, naming the file
        check_collectively(mpi_communicator, [&]() {
          if (statistics)
            statistics->write_row(row);
          if (contact && step > 0)
            contact_writer->write_history(*contact, time);
        });
        if (interval > 0 && (force_vtu || step % interval == 0))
          write_solution();
      }
    catch (const ExcCollective &e)
      {
        AssertThrow(false,
                    ExcCollective(
                      exception_message(e) + " The run stops at step " +
                      std::to_string(step) + ", t = " + format_number(time) +
                      "; what was written before is complete."));
      }

    if (step > 0)
      pcout << "Step " << std::setw(5) << step << "  t = " << std::setw(10)
            << std::setprecision(6) << time << "  dt = " << std::setw(9)
            << controller.dt() << "  Newton " << std::setw(2)
            << newton_iterations << "  |R| = " << std::scientific
            << std::setprecision(2) << final_residual
            << "  E_kin+E_el = " << energies.kinetic + energies.elastic
            << "  balance error = " << energies.error() << std::defaultfloat
            << std::endl;
    // after the step's outputs: a stop loses nothing
    watchdog.act(watchdog.warning(created, step), step, pcout);
    if (!small_strain_warned)
      {
        const std::string strain =
          mechanics->small_strain_excess(ghosted(u, scratch_ghost[0]));
        small_strain_warned = !strain.empty();
        if (small_strain_warned)
          pcout << "Warning (step " << step << ", t = " << format_number(time)
                << "; said once per run): " << strain << std::endl;
      }
  }

  template <int dim>
  void
  Simulator<dim>::write_solution()
  {
    std::vector<std::pair<const VectorType *, std::string>> fields;
    std::vector<VectorType>                                 field_ghosts;
    if (contact)
      {
        fields = contact->nodal_output_fields();
        field_ghosts.resize(fields.size());
        for (unsigned int f = 0; f < fields.size(); ++f)
          fields[f].first = &ghosted(*fields[f].first, field_ghosts[f]);
      }
    const VectorType &u_out = ghosted(u, scratch_ghost[0]);
    const VectorType &v_out = ghosted(v, scratch_ghost[1]);
    check_collectively(mpi_communicator, [&]() {
      solution_writer
        ->write(dof_handler, *mechanics, u_out, v_out, time, step, fields);
      if (contact)
        contact_writer->write_surfaces(*contact, step);
    });
    // only once every process has written its piece
    check_collectively(mpi_communicator, [&]() {
      solution_writer->write_records(time, step);
    });
    last_vtu_step = step;
  }

#define INSTANTIATE(dim)                                                 \
  template std::vector<std::string> Simulator<dim>::statistics_columns() \
    const;                                                               \
  template void Simulator<dim>::open_output_files(const bool append);    \
  template void Simulator<dim>::print_problem_size();                    \
  template void Simulator<dim>::output_step(                             \
    const unsigned int newton_iterations,                                \
    const double       final_residual,                                   \
    const bool         force_vtu);                                               \
  template void Simulator<dim>::write_solution();
  INSTANTIATE(2)
  INSTANTIATE(3)
#undef INSTANTIATE
} // namespace ContactDynamics
