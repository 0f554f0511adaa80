#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <contact_dynamics/output/postprocessing.h>
#include <contact_dynamics/parallel.h>
#include <contact_dynamics/parameters.h>

#include <cmath>
#include <iomanip>

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
  }

  void
  OutputParameters::parse_parameters(ParameterHandler &prm)
  {
    directory    = prm.get("Output directory");
    vtu_interval = prm.get_integer("VTU interval");
    AssertThrow(!directory.empty(),
                ExcMessage("Output/Output directory must not be empty."));
  }



  StatisticsFile::StatisticsFile(const std::string              &filename,
                                 const std::vector<std::string> &columns)
    : file(filename)
    , n_columns(columns.size())
  {
    AssertThrow(file, ExcMessage("Cannot write the file " + filename + "."));
    for (std::size_t i = 0; i < columns.size(); ++i)
      file << (i ? "," : "") << columns[i];
    file << std::endl;
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
    file << std::endl; // flushes: a crash keeps every finished step
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
    DataOut<dim>             data_out;
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
    data_out.build_patches();

    const unsigned int n_processes = Utilities::MPI::n_mpi_processes(comm);
    const std::string  base  = "solution-" + Utilities::int_to_string(step, 5);
    const auto         piece = [&](const unsigned int p) {
      return n_processes == 1 ? base + ".vtu" :
                                        base + "." + std::to_string(p) + ".vtu";
    };
    const std::string name = piece(Utilities::MPI::this_mpi_process(comm));
    std::ofstream     out(directory + "/" + name);
    AssertThrow(out, ExcMessage("Cannot write " + directory + "/" + name));
    data_out.write_vtu(out);
    if (!is_root(comm))
      return;
    std::string record = name;
    if (n_processes > 1)
      {
        std::vector<std::string> pieces;
        for (unsigned int p = 0; p < n_processes; ++p)
          pieces.push_back(piece(p));
        record = base + ".pvtu";
        std::ofstream pvtu(directory + "/" + record);
        data_out.write_pvtu_record(pvtu, pieces);
      }
    records.emplace_back(time, record);
    std::ofstream pvd(directory + "/solution.pvd");
    DataOutBase::write_pvd_record(pvd, records);
  }

  template class SolutionWriter<2>;
  template class SolutionWriter<3>;
} // namespace ContactDynamics
