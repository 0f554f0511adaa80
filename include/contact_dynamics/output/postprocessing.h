// Everything a run writes: statistics.csv (one flushed row per step) and
// the VTU/PVD solution files.
#ifndef contact_dynamics_output_postprocessing_h
#define contact_dynamics_output_postprocessing_h

#include <deal.II/base/parameter_handler.h>

#include <deal.II/dofs/dof_handler.h>

#include <contact_dynamics/mechanics/solid_mechanics.h>

#include <fstream>
#include <functional>
#include <ostream>
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
    // checkpoints: every so many steps, and after so many minutes of wall
    // time since the last one (0: never)
    unsigned int checkpoint_interval  = 0;
    double       checkpoint_wall_time = 0;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };

  /**
   * Creates `directory` (Output/Output directory) and its parents; throws
   * naming the parameter, the directory and the reason if it cannot.
   */
  void
  create_output_directory(const std::string &directory);

  /**
   * Writes `filename` through `write` under a temporary name in the same
   * directory and renames it when complete: a run stopped in the middle
   * leaves the old file or the new one, never a truncated one. Throws with
   * the file's name and the system's reason if a write fails; the
   * temporary file is then removed.
   */
  void
  write_file_atomically(const std::string                         &filename,
                        const std::function<void(std::ostream &)> &write);

  /**
   * Throws with the file's name and the system's reason if `stream`, which
   * writes `filename` (under the name `temporary`, if not empty), failed.
   */
  void
  check_written(const std::ostream &stream,
                const std::string  &filename,
                const std::string  &temporary = "");

  /** A CSV file with a header line, written and flushed row by row. */
  class StatisticsFile
  {
  public:
    /** `append`: a restarted run continues the file (no header). */
    StatisticsFile(const std::string              &filename,
                   const std::vector<std::string> &columns,
                   const bool                      append = false);

    /** Values in the order of the columns; integers print as integers. */
    void
    write_row(const std::vector<double> &values);

  private:
    std::string   filename;
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
     * ghost entries of the locally owned cells. Writes nothing and throws,
     * naming the field, the place and the time, if a value is not finite
     * (an element inverted at a corner gives NaN stresses there). Local:
     * call it on every process inside check_collectively(), then
     * write_records() once every piece is known to be written.
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

    /**
     * The first process adds the step of the last write() to solution.pvd
     * (through the .pvtu record on several processes), so that the records
     * never list a piece that was not written. Call it on every process
     * inside check_collectively().
     */
    void
    write_records(const double time, const unsigned int step);

    /** The steps solution.pvd lists (for a checkpoint), and setting them
     * (a restarted run). */
    const std::vector<std::pair<double, std::string>> &
    listed() const
    {
      return records;
    }
    void
    set_listed(const std::vector<std::pair<double, std::string>> &list)
    {
      records = list;
    }

  private:
    /** solution-NNNNN.vtu, or solution-NNNNN.P.vtu on several processes. */
    std::string
    piece_name(const unsigned int step, const unsigned int process) const;

    MPI_Comm                                    comm;
    std::string                                 directory;
    std::vector<std::string>                    extra_names;
    std::vector<std::pair<double, std::string>> records;
    std::string pvtu_record; // of the last write(), first process only
  };
} // namespace ContactDynamics

#endif
