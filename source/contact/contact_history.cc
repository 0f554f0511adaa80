#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <contact_dynamics/contact/contact_history.h>
#include <contact_dynamics/output/checkpoint.h>
#include <contact_dynamics/parallel.h>

#include <algorithm>

namespace ContactDynamics
{
  bool
  ContactHistoryContext::same_numbering() const
  {
    return std::all_of(node_maps->begin(), node_maps->end(), [](const auto &m) {
      return m.empty();
    });
  }

  void
  save_per_process(const MPI_Comm                                comm,
                   CheckpointData                               &data,
                   const std::string                            &name,
                   const std::vector<std::vector<unsigned int>> &lists)
  {
    Message flat;
    flat.write_index(lists.size());
    for (const auto &list : lists)
      flat.write_list(list);
    const auto all = Utilities::MPI::gather(comm, flat.buffer(), 0);
    for (unsigned int r = 0; r < all.size(); ++r)
      data.set(name + "/process " + std::to_string(r), all[r]);
  }

  std::vector<std::vector<unsigned int>>
  load_per_process(const MPI_Comm        comm,
                   const CheckpointData &data,
                   const std::string    &name)
  {
    std::vector<std::vector<unsigned int>> lists;
    if (data.value("processes") != Utilities::MPI::n_mpi_processes(comm))
      return lists;
    const auto &flat =
      data.get(name + "/process " +
               std::to_string(Utilities::MPI::this_mpi_process(comm)));
    std::size_t i = 1;
    lists.resize(flat.at(0));
    for (auto &list : lists)
      {
        const std::size_t size = flat.at(i++);
        AssertThrow(i + size <= flat.size(),
                    ExcMessage("A checkpoint entry '" + name +
                               "' is damaged."));
        list.assign(flat.begin() + i, flat.begin() + i + size);
        i += size;
      }
    return lists;
  }
} // namespace ContactDynamics
