// Everything a run writes: statistics.csv (one flushed row per step) and
// the VTU/PVD solution files.
#ifndef contact_dynamics_output_postprocessing_h
#define contact_dynamics_output_postprocessing_h

#include <deal.II/base/parameter_handler.h>

#include <deal.II/dofs/dof_handler.h>

#include <contact_dynamics/mechanics/solid_mechanics.h>

#include <fstream>
#include <string>
#include <utility>
#include <vector>

namespace ContactDynamics
{
  using namespace dealii;

  struct OutputParameters
  {
    std::string  directory    = "output";
    unsigned int vtu_interval = 1;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };

  /** A CSV file with a header line, written and flushed row by row. */
  class StatisticsFile
  {
  public:
    StatisticsFile(const std::string              &filename,
                   const std::vector<std::string> &columns);

    /** Values in the order of the columns; integers print as integers. */
    void
    write_row(const std::vector<double> &values);

  private:
    std::ofstream file;
    std::size_t   n_columns;
  };

  /** VTU files of the solution and the .pvd record that lists them. */
  template <int dim>
  class SolutionWriter
  {
  public:
    /**
     * `extra_names` name the components after the displacement. On several
     * processes each writes its cells to solution-NNNNN.P.vtu and the first
     * one the solution-NNNNN.pvtu record that joins them.
     */
    SolutionWriter(const MPI_Comm                  comm,
                   const std::string              &directory,
                   const std::vector<std::string> &extra_names = {});

    /**
     * `nodal_fields`: further vectors on the same degrees of freedom, each
     * written as one scalar field: its component `dim` (the first one after
     * the displacement), under the given name. All vectors must hold the
     * ghost entries of the locally owned cells.
     */
    void
    write(const DoFHandler<dim>     &dof_handler,
          const SolidMechanics<dim> &mechanics,
          const VectorType          &displacement,
          const VectorType          &velocity,
          const double               time,
          const unsigned int         step,
          const std::vector<std::pair<const VectorType *, std::string>>
            &nodal_fields = {});

  private:
    MPI_Comm                                    comm;
    std::string                                 directory;
    std::vector<std::string>                    extra_names;
    std::vector<std::pair<double, std::string>> records;
  };
} // namespace ContactDynamics

#endif
