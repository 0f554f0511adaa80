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
    const Selection<ParallelParameters::Mesh> mesh_names{
      {ParallelParameters::Mesh::replicated, "replicated"},
      {ParallelParameters::Mesh::distributed, "distributed"}};
  } // namespace

  void
  ParallelParameters::declare_parameters(ParameterHandler &prm)
  {
    const ParallelParameters defaults;
    prm.declare_entry(
      "Mesh",
      mesh_names.name(defaults.mesh),
      mesh_names.pattern(),
      "'replicated': every process keeps the whole mesh "
      "(parallel::shared::Triangulation), divided by the Partitioner; "
      "simple, and the memory of the mesh grows with the processes. "
      "'distributed': p4est (parallel::distributed::Triangulation); every "
      "process keeps the scene's mesh as its coarse mesh, and the cells of "
      "the Global refinements only where it works (its own and one layer "
      "of ghosts), partitioned along a space-filling curve with the cells "
      "at secondary surfaces weighted by Contact cell weight. Both gather "
      "the contact surfaces on every process (O(surface) data), and each "
      "process assembles its own cells and the contact conditions of its "
      "own secondary nodes.");
    prm.declare_entry(
      "Global refinements",
      std::to_string(defaults.global_refinements),
      Patterns::Integer(0, 12),
      "Times every cell of the scene's mesh is split in 2^dim after it is "
      "built, in [0, 12] (each one multiplies the cells by 4 in 2-D). "
      "Curved surfaces of the built-in scenes stay on their circles; with "
      "Polynomial degree = 2 the refined cells of a Gmsh mesh of second "
      "order stay on its curved cells (a Gmsh mesh of first order, or "
      "degree 1: the refined boundaries are polygons). With Mesh = "
      "distributed the "
      "scene's mesh is the coarse mesh every process stores and only the "
      "refined cells are distributed: a coarse Refinement factor and "
      "refinements here keep the replicated part small.");
    prm.declare_entry(
      "Partitioner",
      partitioner_names.name(defaults.partitioner),
      partitioner_names.pattern(),
      "Mesh = replicated: how the cells are divided among the MPI "
      "processes: 'metis' minimizes the cut between the parts; 'z-order' "
      "cuts a space-filling curve through the cells. Without mpirun there "
      "is one part and this has no effect.");
    prm.declare_entry(
      "Contact cell weight",
      std::to_string(defaults.contact_cell_weight),
      Patterns::Integer(1, 1000),
      "Mesh = distributed: the load of a cell with a face on a secondary "
      "contact surface, in units of a bulk cell's, in [1, 1000], for the "
      "partition (a mortar node in contact costs about 20 neo-Hookean "
      "cells per assembly, doc/parallel.md). Ignored with Mesh = "
      "replicated.");
  }

  void
  ParallelParameters::parse_parameters(ParameterHandler &prm)
  {
    partitioner         = partitioner_names.value(prm.get("Partitioner"));
    mesh                = mesh_names.value(prm.get("Mesh"));
    global_refinements  = prm.get_integer("Global refinements");
    contact_cell_weight = prm.get_integer("Contact cell weight");
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
  void
  send_messages(const MPI_Comm                                comm,
                const std::map<unsigned int, Message>        &outgoing,
                const std::function<void(Message &received)> &read)
  {
    std::map<unsigned int, std::vector<double>> buffers;
    for (const auto &[rank, message] : outgoing)
      buffers[rank] = message.buffer();
    for (auto &[rank, data] : Utilities::MPI::some_to_some(comm, buffers))
      {
        Message received(std::move(data));
        read(received);
      }
  }

  void
  gather_messages(const MPI_Comm                                comm,
                  const Message                                &mine,
                  const std::function<void(Message &received)> &read)
  {
    for (auto &data : Utilities::MPI::all_gather(comm, mine.buffer()))
      {
        Message received(std::move(data));
        read(received);
      }
  }

  void
  ProcessSums::sum(const MPI_Comm comm)
  {
    std::vector<double> sums(values.size());
    for (std::size_t k = 0; k < values.size(); ++k)
      if (values[k] != nullptr)
        sums[k] = *values[k];
    for (const auto &[k, n] : counts)
      sums[k] = double(*n);
    Utilities::MPI::sum(sums, comm, sums);
    for (std::size_t k = 0; k < values.size(); ++k)
      if (values[k] != nullptr)
        *values[k] = sums[k];
    for (const auto &[k, n] : counts)
      *n = std::lround(sums[k]);
  }
} // namespace ContactDynamics
