// The history of a contact formulation: what its owners (history.h) are
// passed, and the checkpoint entries of per-process lists.
#ifndef contact_dynamics_contact_contact_history_h
#define contact_dynamics_contact_contact_history_h

#include <deal.II/base/mpi.h>

#include <contact_dynamics/history.h>

#include <string>
#include <vector>

namespace ContactDynamics
{
  /**
   * What the owners of contact history are passed: the converged state
   * (commit: with the state of the step's start; load: with the map of the
   * saved secondary nodes onto this mesh's, per pair, empty where the
   * numbering is the saved one). Unset where a call has none.
   */
  struct ContactHistoryContext
  {
    const TrilinosWrappers::MPI::Vector          *u         = nullptr;
    const TrilinosWrappers::MPI::Vector          *old_u     = nullptr;
    const std::vector<std::vector<unsigned int>> *node_maps = nullptr;
    // commit: the committed state evaluated again on a new mesh (after
    // transfer()), not a new step; an owner that counts steps skips it
    bool reevaluation = false;

    /** Whether every pair's nodes are numbered as saved (load). */
    bool
    same_numbering() const;
  };

  /** The prefix of a contact pair's checkpoint entries. */
  inline std::string
  contact_pair_key(const unsigned int p)
  {
    return "contact/pair " + std::to_string(p) + "/";
  }

  /** A column of contact_surface-*.csv: a value per secondary node. */
  struct NodeColumn
  {
    std::string         name;
    std::vector<double> values; // in the pair's node numbering
  };

  /** An owner of contact history; its history per node may be output. */
  class ContactHistoryOwner : public HistoryOwner<ContactHistoryContext>
  {
  public:
    /**
     * Columns of contact_surface-*.csv for the secondary nodes of pair p,
     * the same names for every pair; none by default.
     */
    virtual std::vector<NodeColumn>
    node_columns(const unsigned int /*pair*/) const
    {
      return {};
    }
  };

  using ContactHistoryRegistry =
    HistoryRegistry<ContactHistoryContext, ContactHistoryOwner>;

  /**
   * Checkpoints: per-process lists of indices (`lists` on this process),
   * all of them on the first process under `name` (collective).
   */
  void
  save_per_process(const MPI_Comm                                comm,
                   CheckpointData                               &data,
                   const std::string                            &name,
                   const std::vector<std::vector<unsigned int>> &lists);

  /**
   * The lists save_per_process() saved for this process, if the
   * checkpoint comes from as many processes as there are now; else empty.
   */
  std::vector<std::vector<unsigned int>>
  load_per_process(const MPI_Comm        comm,
                   const CheckpointData &data,
                   const std::string    &name);
} // namespace ContactDynamics

#endif
