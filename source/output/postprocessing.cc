#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <contact_dynamics/output/postprocessing.h>
#include <contact_dynamics/parallel.h>
#include <contact_dynamics/parameters.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iomanip>
#include <sstream>
#include <system_error>

namespace ContactDynamics
{
  void
  OutputParameters::declare_parameters(ParameterHandler &prm)
  {
    const OutputParameters defaults;
    prm.declare_entry("Output directory",
                      defaults.directory,
                      Patterns::DirectoryName(),
                      "Where statistics.csv, parameters.prm, solution.pvd and "
                      "the VTU files go (created if missing; relative to the "
                      "working directory).");
    prm.declare_entry("VTU interval",
                      default_text(defaults.vtu_interval),
                      Patterns::Integer(0),
                      "Write the solution every this many time steps (and "
                      "at the first and last); 0 writes none.");
    prm.declare_entry(
      "Checkpoint interval",
      default_text(defaults.checkpoint_interval),
      Patterns::Integer(0),
      "Write a checkpoint every this many time steps (0: none), to "
      "Output directory/checkpoints/step-NNNNNNN; the last two are kept. "
      "'contact-dynamics --restart DIR' continues from the newest one "
      "under DIR (an output directory or a checkpoint), with the same "
      "statistics as a run that was never stopped (doc/restart.md). A "
      "checkpoint is also written when the run receives SIGTERM or SIGINT. "
      "Cost: one write of the state (a few tenths of the time of a step "
      "for the shipped scenes) and a new factorization (or multigrid "
      "hierarchy) at the next step.");
    prm.declare_entry(
      "Checkpoint wall time",
      default_text(defaults.checkpoint_wall_time),
      Patterns::Double(0),
      "Also write a checkpoint once this many minutes of wall time have "
      "passed since the start or the last checkpoint (0: no such limit), "
      "e.g. a little less than what a batch system allows between "
      "restarts.");
  }

  void
  OutputParameters::parse_parameters(ParameterHandler &prm)
  {
    directory            = prm.get("Output directory");
    vtu_interval         = prm.get_integer("VTU interval");
    checkpoint_interval  = prm.get_integer("Checkpoint interval");
    checkpoint_wall_time = prm.get_double("Checkpoint wall time");
    AssertThrow(!directory.empty(),
                ExcMessage("Output/Output directory must not be empty."));
  }



  void
  create_output_directory(const std::string &directory)
  {
    std::error_code error;
    std::filesystem::create_directories(directory, error);
    if (!error && !std::filesystem::is_directory(directory, error))
      error = std::make_error_code(std::errc::not_a_directory);
    AssertThrow(!error,
                ExcMessage("Output/Output directory = " + directory +
                           ": cannot create this directory (" +
                           error.message() +
                           "). Give a directory that can be created or "
                           "written."));
  }

  void
  check_written(const std::ostream &stream,
                const std::string  &filename,
                const std::string  &temporary)
  {
    // errno still holds the reason of the failed open or write
    const int error = errno;
    AssertThrow(stream.good(),
                ExcMessage("Cannot write the file '" + filename + "'" +
                           (temporary.empty() ? std::string() :
                                                " (as '" + temporary + "')") +
                           (error != 0 ?
                              std::string(": ") + std::strerror(error) :
                              std::string()) +
                           "."));
  }

  void
  write_file_atomically(const std::string                         &filename,
                        const std::function<void(std::ostream &)> &write)
  {
    const std::string temporary = filename + ".part";
    try
      {
        errno = 0;
        std::ofstream out(temporary);
        check_written(out, filename, temporary);
        try
          {
            write(out);
          }
        catch (...)
          {
            // deal.II's writers throw a generic ExcIO when the stream
            // fails (a full disk): name the file and the reason instead
            check_written(out, filename, temporary);
            throw;
          }
        out.flush();
        check_written(out, filename, temporary);
        out.close();
        check_written(out, filename, temporary);
      }
    catch (...)
      {
        std::remove(temporary.c_str());
        throw;
      }
    errno = 0;
    if (std::rename(temporary.c_str(), filename.c_str()) != 0)
      {
        const int error = errno;
        std::remove(temporary.c_str());
        AssertThrow(false,
                    ExcMessage("Cannot write the file '" + filename +
                               "': " + std::strerror(error) + "."));
      }
  }

  StatisticsFile::StatisticsFile(const std::string              &filename,
                                 const std::vector<std::string> &columns,
                                 const bool                      append)
    : filename(filename)
    , n_columns(columns.size())
  {
    errno = 0;
    file.open(filename, append ? std::ios::app : std::ios::out);
    check_written(file, filename);
    if (append)
      return;
    for (std::size_t i = 0; i < columns.size(); ++i)
      file << (i ? "," : "") << columns[i];
    file << std::endl;
    check_written(file, filename);
  }

  void
  StatisticsFile::write_row(const std::vector<double> &values)
  {
    Assert(values.size() == n_columns,
           ExcDimensionMismatch(values.size(), n_columns));
    for (std::size_t i = 0; i < values.size(); ++i)
      {
        if (i)
          file << ',';
        const double v = values[i];
        if (std::isfinite(v) && v == std::round(v) && std::abs(v) < 1e15)
          file << static_cast<long long>(v);
        else
          file << std::setprecision(12) << v;
      }
    errno = 0;
    file << std::endl; // flushes: a crash keeps every finished step
    check_written(file, filename);
  }



  namespace
  {
    template <int dim>
    class StressPostprocessor : public DataPostprocessor<dim>
    {
    public:
      explicit StressPostprocessor(const SolidMechanics<dim> &mechanics)
        : mechanics(mechanics)
      {}

      void
      evaluate_vector_field(
        const DataPostprocessorInputs::Vector<dim> &inputs,
        std::vector<Vector<double>>                &computed) const override
      {
        const auto           cell     = inputs.template get_cell<dim>();
        const Material<dim> &material = mechanics.material(cell->material_id());
        for (unsigned int q = 0; q < computed.size(); ++q)
          {
            Tensor<2, dim> grad_u;
            for (unsigned int d = 0; d < dim; ++d)
              grad_u[d] = inputs.solution_gradients[q][d];
            const Tensor<2, 3> sigma = material.cauchy_stress(grad_u);
            unsigned int       k     = 0;
            for (unsigned int i = 0; i < 3; ++i)
              for (unsigned int j = i; j < 3; ++j)
                computed[q][k++] = sigma[i][j];
            computed[q][k] = von_mises_stress(sigma);
          }
      }

      std::vector<std::string>
      get_names() const override
      {
        return {"stress_xx",
                "stress_xy",
                "stress_xz",
                "stress_yy",
                "stress_yz",
                "stress_zz",
                "von_mises_stress"};
      }

      UpdateFlags
      get_needed_update_flags() const override
      {
        return update_gradients;
      }

    private:
      const SolidMechanics<dim> &mechanics;
    };

    // One component of a vector as a scalar field.
    template <int dim>
    class ComponentField : public DataPostprocessorScalar<dim>
    {
    public:
      ComponentField(const std::string &name, const unsigned int component)
        : DataPostprocessorScalar<dim>(name, update_values)
        , component(component)
      {}

      void
      evaluate_vector_field(
        const DataPostprocessorInputs::Vector<dim> &inputs,
        std::vector<Vector<double>>                &computed) const override
      {
        for (unsigned int q = 0; q < computed.size(); ++q)
          computed[q](0) = inputs.solution_values[q](component);
      }

    private:
      const unsigned int component;
    };

    // The displacement part (first dim components) of a vector.
    template <int dim>
    class DisplacementPart : public DataPostprocessorVector<dim>
    {
    public:
      explicit DisplacementPart(const std::string &name)
        : DataPostprocessorVector<dim>(name, update_values)
      {}

      void
      evaluate_vector_field(
        const DataPostprocessorInputs::Vector<dim> &inputs,
        std::vector<Vector<double>>                &computed) const override
      {
        for (unsigned int q = 0; q < computed.size(); ++q)
          for (unsigned int d = 0; d < dim; ++d)
            computed[q](d) = inputs.solution_values[q](d);
      }
    };

    // DataOut with the names of its fields, to say which one is not finite
    template <int dim>
    class NamedDataOut : public DataOut<dim>
    {
    public:
      using DataOut<dim>::get_dataset_names;
    };
  } // namespace



  template <int dim>
  SolutionWriter<dim>::SolutionWriter(
    const MPI_Comm                  comm,
    const std::string              &directory,
    const std::vector<std::string> &extra_names)
    : comm(comm)
    , directory(directory)
    , extra_names(extra_names)
  {}

  template <int dim>
  void
  SolutionWriter<dim>::write(
    const DoFHandler<dim>                                         &dof_handler,
    const SolidMechanics<dim>                                     &mechanics,
    const VectorType                                              &displacement,
    const VectorType                                              &velocity,
    const double                                                   time,
    const unsigned int                                             step,
    const std::vector<std::pair<const VectorType *, std::string>> &nodal_fields)
  {
    const unsigned int n_components = dof_handler.get_fe().n_components();
    std::vector<DataComponentInterpretation::DataComponentInterpretation>
                             interpretation(n_components,
                     DataComponentInterpretation::component_is_scalar);
    std::vector<std::string> u_names(n_components);
    for (unsigned int d = 0; d < dim; ++d)
      {
        interpretation[d] =
          DataComponentInterpretation::component_is_part_of_vector;
        u_names[d] = "displacement";
      }
    for (unsigned int c = dim; c < n_components; ++c)
      u_names[c] = c - dim < extra_names.size() ? extra_names[c - dim] :
                                                  "field_" + std::to_string(c);

    StressPostprocessor<dim> stress(mechanics);
    NamedDataOut<dim>        data_out;
    data_out.attach_dof_handler(dof_handler);
    data_out.add_data_vector(displacement,
                             u_names,
                             DataOut<dim>::type_dof_data,
                             interpretation);
    const DisplacementPart<dim> velocity_field("velocity");
    data_out.add_data_vector(velocity, velocity_field);
    data_out.add_data_vector(displacement, stress);
    std::vector<std::unique_ptr<ComponentField<dim>>> fields;
    for (const auto &field : nodal_fields)
      {
        fields.push_back(
          std::make_unique<ComponentField<dim>>(field.second, dim));
        data_out.add_data_vector(*field.first, *fields.back());
      }

    Vector<float> material_id(dof_handler.get_triangulation().n_active_cells());
    for (const auto &cell : dof_handler.active_cell_iterators())
      material_id(cell->active_cell_index()) = cell->material_id();
    data_out.add_data_vector(material_id, "material_id");
    // degree 2: cells of degree 2 (ParaView draws them curved), every cell
    // through the mapping, whose interior follows the curved boundary
    const unsigned int degree = dof_handler.get_fe().degree;
    data_out.build_patches(mechanics.get_mapping(),
                           degree > 1 ? degree : 0,
                           degree > 1 ? DataOut<dim>::curved_inner_cells :
                                        DataOut<dim>::no_curved_cells);
    // zlib's best compression cost 12 % of a bouncing-block run for files
    // about 10 % smaller than the fastest level's
    DataOutBase::VtkFlags flags;
    flags.compression_level        = DataOutBase::VtkFlags::best_speed;
    flags.write_higher_order_cells = degree > 1;
    data_out.set_flags(flags);

    // NaN or infinite values never reach a file: they name their field
    const auto names = data_out.get_dataset_names();
    for (const auto &patch : data_out.get_patches())
      for (unsigned int i = 0; i < patch.data.n_rows(); ++i)
        for (unsigned int j = 0; j < patch.data.n_cols(); ++j)
          if (!std::isfinite(patch.data(i, j)))
            {
              // the patch's corners: where it is, within a cell
              const auto        &where = patch.vertices[std::min<
                unsigned int>(j, GeometryInfo<dim>::vertices_per_cell - 1)];
              std::ostringstream message;
              message << "The solution at t = " << time << " (step " << step
                      << ") is not finite: "
                      << (i < names.size() ? names[i] : "a field") << " = "
                      << patch.data(i, j) << " at (" << where << ")"
                      << (i < names.size() &&
                              names[i].find("stress") != std::string::npos ?
                            ", in an element inverted at a corner (det F "
                            "<= 0 there)" :
                            "")
                      << ". Its VTU file is not written.";
              AssertThrow(false, ExcMessage(message.str()));
            }

    write_file_atomically(directory + "/" +
                            piece_name(step,
                                       Utilities::MPI::this_mpi_process(comm)),
                          [&](std::ostream &out) {
                            data_out.write_vtu(out);
                          });
    // the record that joins the pieces, written once every piece is
    pvtu_record.clear();
    if (is_root(comm) && Utilities::MPI::n_mpi_processes(comm) > 1)
      {
        std::vector<std::string> pieces;
        for (unsigned int p = 0; p < Utilities::MPI::n_mpi_processes(comm); ++p)
          pieces.push_back(piece_name(step, p));
        std::ostringstream record;
        data_out.write_pvtu_record(record, pieces);
        pvtu_record = record.str();
      }
  }

  template <int dim>
  std::string
  SolutionWriter<dim>::piece_name(const unsigned int step,
                                  const unsigned int process) const
  {
    const std::string base = "solution-" + Utilities::int_to_string(step, 5);
    return Utilities::MPI::n_mpi_processes(comm) == 1 ?
             base + ".vtu" :
             base + "." + std::to_string(process) + ".vtu";
  }

  template <int dim>
  void
  SolutionWriter<dim>::write_records(const double time, const unsigned int step)
  {
    if (!is_root(comm))
      return;
    const unsigned int n_processes = Utilities::MPI::n_mpi_processes(comm);
    std::string        record      = piece_name(step, 0);
    if (n_processes > 1)
      {
        record = "solution-" + Utilities::int_to_string(step, 5) + ".pvtu";
        write_file_atomically(directory + "/" + record, [&](std::ostream &out) {
          out << pvtu_record;
        });
      }
    auto listed = records;
    listed.emplace_back(time, record);
    write_file_atomically(directory + "/solution.pvd", [&](std::ostream &out) {
      DataOutBase::write_pvd_record(out, listed);
    });
    records = listed;
  }

  template class SolutionWriter<2>;
  template class SolutionWriter<3>;
} // namespace ContactDynamics
