// What the classes need to run on several MPI processes: a failure on one
// process must reach all of them, since the others would otherwise wait
// forever in the next collective operation.
#ifndef contact_dynamics_parallel_h
#define contact_dynamics_parallel_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>

#include <functional>
#include <string>

DEAL_II_NAMESPACE_OPEN
class ParameterHandler;
DEAL_II_NAMESPACE_CLOSE

namespace ContactDynamics
{
  using namespace dealii;

  /**
   * Runs `local` (work that may throw on some processes only), then
   * `collective` (compress() and reductions) on every process, and then
   * throws on every process, with the message of the first process that
   * failed, if any did.
   */
  void
  run_collectively(const MPI_Comm               comm,
                   const std::function<void()> &local,
                   const std::function<void()> &collective);

  /** The `Parallel` subsection. */
  struct ParallelParameters
  {
    enum class Partitioner
    {
      metis,
      z_order
    };

    Partitioner partitioner = Partitioner::metis; // the default

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    /** The name of the partitioner in the parameter file. */
    const std::string &
    partitioner_name() const;
  };

  /** The union over all processes of the given sets. */
  IndexSet
  union_over_processes(const IndexSet &set, const MPI_Comm comm);

  /** True on the process that writes files and screen output. */
  inline bool
  is_root(const MPI_Comm comm)
  {
    return Utilities::MPI::this_mpi_process(comm) == 0;
  }
} // namespace ContactDynamics

#endif
