// Checkpoints of the Simulator: what the next step depends on, written so
// that a restart continues exactly (doc/restart.md).
#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>

#include <contact_dynamics/output/checkpoint.h>
#include <contact_dynamics/parameters.h>
#include <contact_dynamics/scenes/quadratic_geometry.h>
#include <contact_dynamics/simulator.h>

#include <array>
#include <chrono>
#include <cstdlib>
#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/distributed/tria.h>
#include <filesystem>
#include <fstream>
#include <thread>

namespace ContactDynamics
{
  namespace
  {
    // the output files a restarted run continues
    const std::vector<std::string> continued_files{"statistics.csv",
                                                   "contact_history.csv"};

    // what a restart may change (the model must stay)
    const std::vector<std::string> changeable{
      "Time integration/End time",
      "Time integration/Time step",
      "Time integration/Minimum time step",
      "Time integration/Error tolerance",
      "Output/",
      "Nonlinear solver/",
      "Parallel/Partitioner",
      "Parallel/Contact cell weight",
      // warnings only (and absent from checkpoints before issue 39)
      "Energy watchdog/",
      "/Small strain limit"};

    // the coarse mesh's cells and the sum of their vertices' coordinates
    template <int dim>
    std::vector<double>
    coarse_mesh_signature(const Triangulation<dim> &triangulation)
    {
      double sum = 0;
      for (const auto &cell : triangulation.cell_iterators_on_level(0))
        for (const unsigned int v : cell->vertex_indices())
          for (unsigned int d = 0; d < dim; ++d)
            sum += cell->vertex(v)[d];
      return {double(triangulation.n_cells(0)), sum};
    }


    // a replicated mesh: every degree of freedom in the order of the cells
    // (the same on any number of processes), for a checkpoint
    template <int dim>
    std::vector<types::global_dof_index>
    cell_order_of_dofs(const DoFHandler<dim> &dof_handler)
    {
      std::vector<types::global_dof_index> order,
        cell_dofs(dof_handler.get_fe().n_dofs_per_cell());
      std::vector<bool> seen(dof_handler.n_dofs(), false);
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          cell->get_dof_indices(cell_dofs);
          for (const auto i : cell_dofs)
            if (!seen[i])
              {
                seen[i] = true;
                order.push_back(i);
              }
        }
      AssertThrow(order.size() == dof_handler.n_dofs(),
                  ExcInternalError("a degree of freedom on no cell"));
      return order;
    }

    // the vectors of a checkpoint `data` (saved with the distributed mesh
    // or in the order of the cells)
    template <int dim>
    void
    load_vectors(const DoFHandler<dim>     &dof_handler,
                 const CheckpointData      &data,
                 std::vector<VectorType *> &vectors,
                 const bool                 distributed)
    {
      if (distributed)
        {
          parallel::distributed::SolutionTransfer<dim, VectorType> transfer(
            dof_handler);
          transfer.deserialize(vectors);
        }
      else
        {
          const auto order = cell_order_of_dofs(dof_handler);
          for (unsigned int k = 0; k < vectors.size(); ++k)
            {
              const auto &values =
                data.get("vector " + std::to_string(k), order.size());
              for (std::size_t i = 0; i < order.size(); ++i)
                if (dof_handler.locally_owned_dofs().is_element(order[i]))
                  (*vectors[k])(order[i]) = values[i];
              vectors[k]->compress(VectorOperation::insert);
            }
        }
    }

    // the continued output files cut to where the checkpoint `data` ends
    // them, and the parameters of the continued run
    void
    continue_output_files(const MPI_Comm        mpi_communicator,
                          const std::string    &directory,
                          const std::string    &checkpoint,
                          const CheckpointData &data,
                          const std::string    &parameters_text)
    {
      // every check passed: rows written after the checkpoint (before the
      // stop) go, and so do the checkpoints of that abandoned continuation
      const auto &sizes = data.get("output/file sizes", continued_files.size());
      check_collectively(mpi_communicator, [&]() {
        if (!is_root(mpi_communicator))
          return;
        // (first: a kill in between leaves files longer than the newest
        // checkpoint needs, which a restart accepts)
        std::error_code same;
        if (std::filesystem::equivalent(
              std::filesystem::path(checkpoint).parent_path(),
              directory + "/checkpoints",
              same))
          Checkpoints::remove_later(checkpoint);
        for (unsigned int k = 0; k < continued_files.size(); ++k)
          if (sizes[k] >= 0)
            std::filesystem::resize_file(directory + "/" + continued_files[k],
                                         sizes[k]);
        write_file_atomically(directory + "/parameters.prm",
                              [&](std::ostream &out) {
                                out << parameters_text;
                              });
      });
    }
  } // namespace

  template <int dim>
  std::vector<VectorType *>
  Simulator<dim>::checkpoint_vectors()
  {
    std::vector<VectorType *> vectors = history.vectors();
    if (contact)
      for (VectorType *x : contact->history_vectors())
        vectors.push_back(x);
    return vectors;
  }


  template <int dim>
  void
  Simulator<dim>::write_checkpoint()
  {
    TimerOutput::Scope t(*timer, "checkpoint");
    const bool         root = is_root(mpi_communicator);
    const std::string  final =
      Checkpoints::directory(output_parameters.directory, step);
    const std::string temporary = final + ".part";
    // p4est aborts the program on a full disk: the space is checked first
    // (the vectors per cell of a distributed mesh, the quadrants, the
    // history and the texts: measured within a factor 2 above)
    const double cells = triangulation->n_global_active_cells();
    const double bytes =
      8. * checkpoint_vectors().size() *
        std::max<double>(dof_handler.n_dofs(),
                         cells * discretization.fe().n_dofs_per_cell()) +
      64. * cells + 4. * parameters_text.size() + 1e6;
    check_collectively(mpi_communicator, [&]() {
      if (root)
        {
          Checkpoints::check_free_space(output_parameters.directory, bytes);
          Checkpoints::create_temporary(temporary, final);
        }
    });
    try
      {
        write_checkpoint_files(temporary, final);
      }
    catch (...)
      {
        // nothing half-written stays behind
        std::error_code error;
        if (root)
          std::filesystem::remove_all(temporary, error);
        throw;
      }
    last_checkpoint_step = step;
    checkpoint_timer.restart();
    // a restart starts without the factorization, pivot order or
    // multigrid hierarchy of earlier steps: so does this run
    newton.reset_linear_solver();
    structure_changed = true;
    pcout << "  checkpoint of step " << step << " in '" << final << "'"
          << std::endl;
  }

  template <int dim>
  void
  Simulator<dim>::write_checkpoint_files(const std::string &temporary,
                                         const std::string &final)
  {
    const bool     root = is_root(mpi_communicator);
    CheckpointData data;
    save_run(data);
    const bool distributed = save_vectors(data, temporary);
    // for the test of a kill during a write (tests/CMakeLists.txt)
    if (const char *pause = std::getenv("CONTACT_DYNAMICS_CHECKPOINT_PAUSE"))
      {
        pcout << "  checkpoint write paused in '" << temporary << "'"
              << std::endl;
        std::this_thread::sleep_for(
          std::chrono::duration<double>(std::atof(pause)));
      }
    check_collectively(mpi_communicator, [&]() {
      if (root)
        {
          data.write(temporary + "/" + Checkpoints::data_file);
          write_file_atomically(temporary + "/" + Checkpoints::parameter_file,
                                [&](std::ostream &out) {
                                  out << parameters_text;
                                });
          // last: a restart verifies every file against it
          Checkpoints::write_checksums(temporary);
        }
    });
    // complete on every process: only now does it replace the older ones
    check_collectively(mpi_communicator, [&]() {
      if (root)
        Checkpoints::commit(temporary, final, 2);
    });
    // a restart starts on a distributed mesh with the cells in the order a
    // load gives them (refinement and coarsening leave another order, and
    // the sums of the assembly follow it): this run continues from the
    // checkpoint
    if (distributed)
      {
        CheckpointData saved;
        check_collectively(mpi_communicator, [&]() {
          saved.read(final + "/" + Checkpoints::data_file);
        });
        load_checkpoint(final, saved);
      }
  }

  template <int dim>
  void
  Simulator<dim>::save_run(CheckpointData &data)
  {
    const bool root = is_root(mpi_communicator);
    data.set("processes", Utilities::MPI::n_mpi_processes(mpi_communicator));
    data.set("dimension", dim);
    data.set("cells", triangulation->n_global_active_cells());
    data.set("unknowns", dof_handler.n_dofs());
    data.set("time", time);
    data.set("step", step);
    // the controller, the energies
    history.save(data, RunContext());
    data.set("output/last vtu step", last_vtu_step);
    data.set("wall time", wall_time_before + wall_timer.wall_time());
    data.set("coarse mesh", coarse_mesh_signature(*triangulation));
    // (a mesh file of second order: its nodes shape the cells too)
    if (const auto geometry = scene.cell_geometry())
      data.set("coarse mesh nodes", std::vector<double>{geometry->node_sum()});
    data.set_text("parameters", parameters_text);
    data.set_text("statistics columns", join(statistics_columns(), ","));
    // where the continued files end (their rows are flushed as written),
    // and what they end with
    std::vector<double> sizes;
    std::string         hashes;
    for (const auto &name : continued_files)
      {
        const std::string file = output_parameters.directory + "/" + name;
        std::error_code   error;
        const auto        size = std::filesystem::file_size(file, error);
        sizes.push_back(root && !error ? double(size) : -1.);
        hashes +=
          (root && !error ? Checkpoints::tail_hash(file, size) : "") + "\n";
      }
    data.set("output/file sizes", sizes);
    data.set_text("output/file hashes", hashes);
    {
      std::vector<double> times;
      std::string         names;
      for (const auto &[t, name] : solution_writer->listed())
        {
          times.push_back(t);
          names += name + "\n";
        }
      data.set("output/pvd times", times);
      data.set_text("output/pvd files", names);
    }
    if (contact)
      contact->save_history(data);
  }

  template <int dim>
  bool
  Simulator<dim>::save_vectors(CheckpointData    &data,
                               const std::string &temporary)
  {
    // the vectors: with the distributed mesh (its refinement and
    // partition) or in the order of the cells of the replicated one
    const bool                      root    = is_root(mpi_communicator);
    const std::vector<VectorType *> vectors = checkpoint_vectors();
    data.set("vectors", vectors.size());
    auto *distributed =
      dynamic_cast<parallel::distributed::Triangulation<dim> *>(
        triangulation.get());
    if (distributed != nullptr)
      {
        std::vector<VectorType>         ghosts(vectors.size());
        std::vector<const VectorType *> pointers;
        for (unsigned int k = 0; k < vectors.size(); ++k)
          pointers.push_back(&ghosted(*vectors[k], ghosts[k]));
        parallel::distributed::SolutionTransfer<dim, VectorType> transfer(
          dof_handler);
        transfer.prepare_for_serialization(pointers);
        check_collectively(mpi_communicator, [&]() {
          distributed->save(temporary + "/" + Checkpoints::mesh_file);
        });
      }
    else
      {
        const auto order = cell_order_of_dofs(dof_handler);
        VectorType all(locally_owned,
                       complete_index_set(dof_handler.n_dofs()),
                       mpi_communicator);
        for (unsigned int k = 0; k < vectors.size(); ++k)
          {
            all = *vectors[k];
            if (!root)
              continue;
            std::vector<double> values(order.size());
            for (std::size_t i = 0; i < order.size(); ++i)
              values[i] = all(order[i]);
            data.set("vector " + std::to_string(k), values);
          }
      }
    return distributed != nullptr;
  }

  template <int dim>
  void
  Simulator<dim>::restart(const std::string &checkpoint)
  {
    wall_timer.restart();
    CheckpointData data;
    // everything is checked before any file is touched; the files first,
    // once, before p4est or anything else reads a byte of them
    check_collectively(mpi_communicator, [&]() {
      if (is_root(mpi_communicator))
        Checkpoints::verify(checkpoint);
    });
    check_collectively(mpi_communicator, [&]() {
      check_checkpoint(checkpoint, data);
    });
    restarting       = true;
    wall_time_before = data.value("wall time");
    load_checkpoint(checkpoint, data);
    watchdog.reset(energy_account.balance());
    // (the columns are known once the contact is set up)
    check_collectively(mpi_communicator, [&]() {
      AssertThrow(data.text("statistics columns") ==
                    join(statistics_columns(), ","),
                  ExcMessage("The statistics of these parameters have other "
                             "columns than those of the checkpoint '" +
                             checkpoint + "' (" +
                             data.text("statistics columns") +
                             "): restart with the parameters of the run "
                             "(Error tolerance switched on or off?)."));
    });

    continue_output_files(mpi_communicator,
                          output_parameters.directory,
                          checkpoint,
                          data,
                          parameters_text);
    open_output_files(true);
    {
      const auto &times = data.get("output/pvd times");
      std::vector<std::pair<double, std::string>> listed;
      std::istringstream names(data.text("output/pvd files"));
      std::string        name;
      for (const double t : times)
        {
          std::getline(names, name);
          listed.emplace_back(t, name);
        }
      solution_writer->set_listed(listed);
    }
    print_problem_size();
    pcout << "Restarted from '" << checkpoint << "' at step " << step
          << ", t = " << time << std::endl;
  }

  template <int dim>
  void
  Simulator<dim>::load_checkpoint(const std::string    &checkpoint,
                                  const CheckpointData &data)
  {
    const auto mismatch =
      [&](const std::string &what, const double saved, const double here) {
        AssertThrow(saved == here,
                    ExcCollective(
                      "The checkpoint '" + checkpoint + "' has " +
                      format_number(saved) + " " + what +
                      ", the mesh of these parameters " + format_number(here) +
                      ": restart with the parameters of the run that wrote "
                      "it (its " +
                      Checkpoints::parameter_file +
                      "; only the End time, the outputs and the solver "
                      "settings may change)."));
      };
    auto *distributed =
      dynamic_cast<parallel::distributed::Triangulation<dim> *>(
        triangulation.get());
    if (distributed != nullptr)
      {
        dof_handler.clear();
        distributed->clear();
        scene.create_triangulation(*distributed);
        discretization.set_geometry(scene.cell_geometry());
        check_collectively(mpi_communicator, [&]() {
          distributed->load(checkpoint + "/" + Checkpoints::mesh_file);
        });
        // saved on as many processes: its partition; else p4est balances
        // the cells (unweighted until the next mesh change: repartition()
        // here would drop the vectors attached to the loaded mesh)
        dof_handler.reinit(*triangulation);
      }
    mismatch("cells",
             data.value("cells"),
             triangulation->n_global_active_cells());

    time = data.value("time");
    step = data.value("step");
    // (before issue 38 last in `mesh`)
    last_vtu_step = data.has("output/last vtu step") ?
                      data.value("output/last vtu step") :
                      data.get("mesh", 5)[4];
    // the controller, the energies
    history.load(data, RunContext{checkpoint});

    // (with contact the pattern follows the loaded candidates, below)
    setup_system(true, contact == nullptr);
    mismatch("unknowns", data.value("unknowns"), dof_handler.n_dofs());
    history.reinit_vectors(v);
    std::vector<VectorType *> vectors = checkpoint_vectors();
    mismatch("saved vectors", data.value("vectors"), vectors.size());
    load_vectors(dof_handler, data, vectors, distributed != nullptr);
    ghosted(u, u_ghost);
    ghosted(v, v_ghost);
    if (contact)
      {
        contact->load_history(data, u_ghost);
        setup_sparsity();
      }
    structure_changed    = true;
    last_checkpoint_step = step;
    checkpoint_timer.restart();
  }

  template <int dim>
  void
  Simulator<dim>::check_checkpoint(const std::string &checkpoint,
                                   CheckpointData    &data) const
  {
    data.read(checkpoint + "/" + Checkpoints::data_file);
    AssertThrow(data.value("dimension") == dim,
                ExcMessage("The checkpoint '" + checkpoint + "' is " +
                           format_number(data.value("dimension")) +
                           "-dimensional, the parameters are " +
                           std::to_string(dim) + "-dimensional."));
    const auto changed = Checkpoints::changed_entries(data.text("parameters"),
                                                      parameters_text,
                                                      changeable);
    AssertThrow(changed.empty(),
                ExcMessage(
                  "The parameters differ from those of the run that wrote "
                  "the checkpoint '" +
                  checkpoint + "' in " + std::to_string(changed.size()) +
                  (changed.size() == 1 ? " entry" : " entries") +
                  " that describe the model: " +
                  join(std::vector<std::string>(
                         changed.begin(),
                         changed.begin() +
                           std::min<std::size_t>(changed.size(), 5)),
                       "; ") +
                  ". A restart may change only " + join(changeable, ", ") +
                  " (restart without a parameter file to use the run's "
                  "own)."));
    AssertThrow(integrator.end_time() > data.value("time"),
                ExcMessage("Time integration/End time = " +
                           format_number(integrator.end_time()) +
                           " is not beyond the time of the checkpoint '" +
                           checkpoint +
                           "', t = " + format_number(data.value("time")) +
                           ": nothing to continue (give a later End "
                           "time)."));
    const auto geometry = scene.cell_geometry();
    AssertThrow(data.get("coarse mesh", 2) ==
                    coarse_mesh_signature(*triangulation) &&
                  data.has("coarse mesh nodes") == (geometry != nullptr) &&
                  (!geometry ||
                   data.get("coarse mesh nodes", 1)[0] == geometry->node_sum()),
                ExcMessage("The checkpoint '" + checkpoint +
                           "' was written on another coarse mesh than "
                           "these parameters build (a changed mesh "
                           "file?)."));
    // the continued files must be those the checkpoint was written
    // with (rows written after it, before the stop, are cut below)
    if (!is_root(mpi_communicator))
      return;
    const auto &sizes = data.get("output/file sizes", continued_files.size());
    std::istringstream hashes(data.text("output/file hashes"));
    for (unsigned int k = 0; k < continued_files.size(); ++k)
      {
        std::string hash;
        std::getline(hashes, hash);
        if (sizes[k] < 0)
          continue;
        const std::string file =
          output_parameters.directory + "/" + continued_files[k];
        std::error_code error;
        const double    size = std::filesystem::file_size(file, error);
        AssertThrow(
          !error && size >= sizes[k] &&
            (hash.empty() || Checkpoints::tail_hash(file, sizes[k]) == hash),
          ExcMessage("Cannot continue '" + file + "' from the checkpoint '" +
                     checkpoint + "': it " +
                     (error ? std::string("does not exist") :
                      size < sizes[k] ?
                              "has " + format_number(size) +
                                " bytes, the checkpoint needs its first " +
                                format_number(sizes[k]) :
                              std::string("is not the file the checkpoint "
                                          "was written with (another run "
                                          "wrote it since)")) +
                     ". Restart in the output directory of the run that "
                     "wrote the checkpoint."));
      }
  }



#define INSTANTIATE(dim)                                                     \
  template std::vector<VectorType *> Simulator<dim>::checkpoint_vectors();   \
  template void                      Simulator<dim>::write_checkpoint();     \
  template void Simulator<dim>::write_checkpoint_files(const std::string &,  \
                                                       const std::string &); \
  template void Simulator<dim>::restart(const std::string &);                \
  template void Simulator<dim>::load_checkpoint(const std::string &,         \
                                                const CheckpointData &);     \
  template void Simulator<dim>::save_run(CheckpointData &);                  \
  template bool Simulator<dim>::save_vectors(CheckpointData &,               \
                                             const std::string &);           \
  template void Simulator<dim>::check_checkpoint(const std::string &,        \
                                                 CheckpointData &) const;
  INSTANTIATE(2)
  INSTANTIATE(3)
#undef INSTANTIATE
} // namespace ContactDynamics
