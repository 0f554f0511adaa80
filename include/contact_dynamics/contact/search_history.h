// The owner of what the swept contact search keeps between steps: the
// committed state the swept boxes start from, and per pair the candidate
// faces the sparsity pattern holds (ContactPairData::pattern).
#ifndef contact_dynamics_contact_search_history_h
#define contact_dynamics_contact_search_history_h

#include <contact_dynamics/contact/contact_history.h>
#include <contact_dynamics/contact/contact_pair_data.h>

#include <functional>
#include <string>
#include <vector>

namespace ContactDynamics
{
  template <int dim>
  class SearchHistory : public ContactHistoryOwner
  {
  public:
    using Pattern = std::vector<std::vector<unsigned int>>;

    /**
     * `n_patches`: a pair's number of patches; `new_pattern`: a pattern
     * found anew at the (committed) state u, for a checkpoint without a
     * usable one. `comm`: the formulation's, as set up.
     */
    SearchHistory(
      std::vector<ContactPairData<dim>> &pairs,
      const MPI_Comm                    &comm,
      const std::function<unsigned int(const ContactPairData<dim> &)>
                                                       &n_patches,
      const std::function<Pattern(const ContactPairData<dim> &,
                                  const VectorType &)> &new_pattern)
      : pairs(pairs)
      , comm(comm)
      , n_patches(n_patches)
      , new_pattern(new_pattern)
    {}

    std::string
    name() const override
    {
      return "contact search";
    }

    /** The swept search of the next step starts from context.u. */
    void
    commit(const ContactHistoryContext &context) override
    {
      committed_u = *context.u;
    }

    /** The patterns, per process. */
    void
    save(CheckpointData &data, const ContactHistoryContext &) const override;

    /**
     * From context.u; the patterns of the run that wrote the checkpoint if
     * numbered as here, else new ones.
     */
    void
    load(const CheckpointData        &data,
         const ContactHistoryContext &context) override;

    /** The state of the old mesh: the next search takes its own. */
    void
    transfer(const ContactHistoryContext &) override
    {
      committed_u.clear();
      committed_is_next = true;
    }

    /**
     * Before a search at u: before the first commit the committed state is
     * the reference configuration (as for PairNodeHistory::position);
     * after a mesh change it is u.
     */
    void
    start_search(const VectorType &u)
    {
      if (committed_u.size() != u.size())
        committed_u.reinit(u);
      if (committed_is_next)
        committed_u = u;
      committed_is_next = false;
    }

    // the state of the last committed step (ghosted like the trial state)
    VectorType committed_u;

  private:
    std::vector<ContactPairData<dim>>                        &pairs;
    const MPI_Comm                                           &comm;
    std::function<unsigned int(const ContactPairData<dim> &)> n_patches;
    std::function<Pattern(const ContactPairData<dim> &, const VectorType &)>
         new_pattern;
    bool committed_is_next = false; // after a mesh change
  };
} // namespace ContactDynamics

#endif
