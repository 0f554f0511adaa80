#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <contact_dynamics/parallel.h>
#include <contact_dynamics/parameters.h>

#include <csignal>
#include <exception>
#include <sstream>
#include <vector>

namespace ContactDynamics
{
  std::string
  exception_message(const std::exception &e)
  {
    if (const auto *deal = dynamic_cast<const ExceptionBase *>(&e))
      {
        std::ostringstream message;
        deal->print_info(message);
        const std::string text = Utilities::trim(message.str());
        if (!text.empty())
          return text;
      }
    return e.what();
  }

  void
  run_collectively(const MPI_Comm               comm,
                   const std::function<void()> &local,
                   const std::function<void()> &collective)
  {
    std::string failure;
    try
      {
        local();
      }
    catch (const std::exception &e)
      {
        failure = exception_message(e);
        if (failure.empty())
          failure = "unknown error";
      }
    collective();
    if (Utilities::MPI::n_mpi_processes(comm) > 1)
      for (const auto &f : Utilities::MPI::all_gather(comm, failure))
        if (!f.empty())
          {
            failure = f;
            break;
          }
    AssertThrow(failure.empty(), ExcCollective(failure));
  }

  namespace
  {
    volatile std::sig_atomic_t received_signal = 0;

    extern "C" void
    request_stop(const int signal)
    {
      received_signal = signal;
    }
  } // namespace

  void
  install_stop_handlers()
  {
    std::signal(SIGINT, request_stop);
    std::signal(SIGTERM, request_stop);
  }

  int
  stop_signal(const MPI_Comm comm)
  {
    const int local = received_signal;
    return Utilities::MPI::n_mpi_processes(comm) > 1 ?
             Utilities::MPI::max(local, comm) :
             local;
  }

  namespace
  {
    const Selection<ParallelParameters::Partitioner> partitioner_names{
      {ParallelParameters::Partitioner::metis, "metis"},
      {ParallelParameters::Partitioner::z_order, "z-order"}};
  } // namespace

  void
  ParallelParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry(
      "Partitioner",
      partitioner_names.name(ParallelParameters().partitioner),
      partitioner_names.pattern(),
      "How the cells are divided among the MPI processes (every process "
      "keeps the whole mesh, a parallel::shared::Triangulation, and "
      "assembles its own cells and the contact conditions of its own "
      "secondary nodes): 'metis' minimizes the cut between the parts; "
      "'z-order' cuts a space-filling curve through the cells. Without "
      "mpirun there is one part and this has no effect.");
  }

  void
  ParallelParameters::parse_parameters(ParameterHandler &prm)
  {
    partitioner = partitioner_names.value(prm.get("Partitioner"));
  }

  const std::string &
  ParallelParameters::partitioner_name() const
  {
    return partitioner_names.name(partitioner);
  }

  IndexSet
  union_over_processes(const IndexSet &set, const MPI_Comm comm)
  {
    if (Utilities::MPI::n_mpi_processes(comm) == 1)
      return set;
    IndexSet                             result(set.size());
    std::vector<types::global_dof_index> mine;
    set.fill_index_vector(mine);
    for (const auto &indices : Utilities::MPI::all_gather(comm, mine))
      result.add_indices(indices.begin(), indices.end());
    result.compress();
    return result;
  }
} // namespace ContactDynamics
