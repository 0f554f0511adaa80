// What the classes need to run on several MPI processes: a failure on one
// process must reach all of them, since the others would otherwise wait
// forever in the next collective operation.
#ifndef contact_dynamics_parallel_h
#define contact_dynamics_parallel_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

DEAL_II_NAMESPACE_OPEN
class ParameterHandler;
DEAL_II_NAMESPACE_CLOSE

namespace ContactDynamics
{
  using namespace dealii;

  /**
   * An error every process of the communicator raised together (with the
   * same message): the command line prints it once and exits normally. Any
   * other exception that escapes on several processes may have been raised
   * on some of them only, while the others wait in a collective operation:
   * the command line then aborts the job (doc/parallel.md).
   */
  class ExcCollective : public StandardExceptions::ExcMessage
  {
  public:
    using StandardExceptions::ExcMessage::ExcMessage;
  };

  /**
   * A run stopped at the end of a step because of a signal (SIGINT,
   * SIGTERM): every output is complete; the exit status is 128 + signal.
   */
  class ExcStopped : public ExcCollective
  {
  public:
    ExcStopped(const std::string &message, const int signal)
      : ExcCollective(message)
      , signal(signal)
    {}
    int signal;
  };

  /**
   * The message of an exception without the decoration of deal.II's
   * print_info().
   */
  std::string
  exception_message(const std::exception &e);

  /**
   * Runs `local` (work that may throw on some processes only), then
   * `collective` (compress() and reductions) on every process, and then
   * throws ExcCollective on every process, with the message of the first
   * process that failed, if any did.
   */
  void
  run_collectively(const MPI_Comm               comm,
                   const std::function<void()> &local,
                   const std::function<void()> &collective);

  /**
   * run_collectively() without collective work: for what the first
   * process alone does (file output) or what may fail on some processes.
   */
  inline void
  check_collectively(const MPI_Comm comm, const std::function<void()> &local)
  {
    run_collectively(comm, local, []() {});
  }

  /**
   * SIGINT and SIGTERM then only set a flag: the time loop stops at the end
   * of the current step (Simulator::run()).
   */
  void
  install_stop_handlers();

  /** The signal that asked to stop on any process of `comm`, or 0
   * (collective). */
  int
  stop_signal(const MPI_Comm comm);

  /** The `Parallel` subsection. */
  struct ParallelParameters
  {
    enum class Partitioner
    {
      metis,
      z_order
    };

    enum class Mesh
    {
      replicated,
      distributed
    };

    // the defaults
    Partitioner  partitioner         = Partitioner::metis;
    Mesh         mesh                = Mesh::replicated;
    unsigned int global_refinements  = 0;
    unsigned int contact_cell_weight = 10;

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

  /**
   * A message between processes as one buffer of doubles: values, indices
   * and counts (exact as doubles below 2^53) written in order and read back
   * in the same order. The contact classes send sums to the owners of
   * nodes with it and gather lists from every process.
   */
  class Message
  {
  public:
    Message() = default;

    explicit Message(std::vector<double> data)
      : data(std::move(data))
    {}

    void
    write(const double x)
    {
      data.push_back(x);
    }

    /** An index or a count. */
    void
    write_index(const std::uint64_t i)
    {
      data.push_back(double(i));
    }

    /** A sparse map index -> value: its size, then the pairs. */
    template <typename Map>
    void
    write_sparse(const Map &map)
    {
      write_index(map.size());
      for (const auto &[i, x] : map)
        {
          write_index(i);
          write(x);
        }
    }

    /** A list of indices: its size, then the indices. */
    template <typename List>
    void
    write_list(const List &list)
    {
      write_index(list.size());
      for (const auto i : list)
        write_index(i);
    }

    bool
    at_end() const
    {
      return position == data.size();
    }

    double
    read()
    {
      return data[position++];
    }

    std::uint64_t
    read_index()
    {
      return std::llround(read());
    }

    /** Adds the pairs of a write_sparse() to `map`. */
    template <typename Map>
    void
    add_sparse(Map &map)
    {
      const std::uint64_t n = read_index();
      for (std::uint64_t k = 0; k < n; ++k)
        {
          const auto i = read_index();
          map[i] += read();
        }
    }

    /** The buffer (for a checkpoint entry). */
    const std::vector<double> &
    buffer() const
    {
      return data;
    }

  private:
    std::vector<double> data;
    std::size_t         position = 0;
  };

  /**
   * Sends outgoing[rank] to each rank and reads the messages received, in
   * the order of the ranks that sent them (collective).
   */
  void
  send_messages(const MPI_Comm                                comm,
                const std::map<unsigned int, Message>        &outgoing,
                const std::function<void(Message &received)> &read);

  /**
   * Every process's message, read on every process in the order of the
   * ranks (collective).
   */
  void
  gather_messages(const MPI_Comm                                comm,
                  const Message                                &mine,
                  const std::function<void(Message &received)> &read);

  /**
   * Values of this process that become their sums over all processes, in
   * one reduction: add() them, then sum().
   */
  class ProcessSums
  {
  public:
    void
    add(double &x)
    {
      values.push_back(&x);
    }

    /** A count (exact as a double). */
    void
    add(unsigned int &n)
    {
      counts.emplace_back(values.size(), &n);
      values.push_back(nullptr);
    }

    /** Every component of a tensor. */
    template <typename TensorType>
    void
    add_all(TensorType &t)
    {
      for (double *x = t.begin_raw(); x != t.end_raw(); ++x)
        add(*x);
    }

    /** Replaces each value by its sum over the processes (collective). */
    void
    sum(const MPI_Comm comm);

  private:
    std::vector<double *>                               values;
    std::vector<std::pair<std::size_t, unsigned int *>> counts;
  };
} // namespace ContactDynamics

#endif
