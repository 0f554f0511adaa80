// The owner of the history of the secondary nodes of all contact pairs:
// their states (PairNodeHistory::nodes), their positions at the last
// committed step, and the normalized gap and slip rates on the multiplier
// unknowns for the output.
#ifndef contact_dynamics_contact_node_history_h
#define contact_dynamics_contact_node_history_h

#include <contact_dynamics/contact/contact_history.h>
#include <contact_dynamics/contact/contact_pair_data.h>

#include <array>
#include <map>
#include <string>
#include <vector>

namespace ContactDynamics
{
  template <int dim>
  class NodeHistory : public ContactHistoryOwner
  {
  public:
    /** `comm`: the formulation's, as set up. */
    NodeHistory(std::vector<ContactPairData<dim>> &pairs,
                const ComplementarityParameters   &complementarity,
                const MPI_Comm                    &comm)
      : pairs(pairs)
      , complementarity(complementarity)
      , comm(comm)
    {}

    std::string
    name() const override
    {
      return "contact nodes";
    }

    /**
     * The held gaps and rates and the persistency of the next step, the
     * output fields and the positions of the converged state context.u.
     * The re-evaluation after a mesh change keeps the held gap, its rates
     * and the persistency of every node that was held before it (by
     * reference position): the new mesh's weighted gap of the same state
     * differs, and a fresh start from the velocity rate broke the hold.
     */
    void
    commit(const ContactHistoryContext &context) override;

    /**
     * Per pair the node states (in the order of node_state_fields(), from
     * the processes that own them) and the reference positions that
     * saved_node_map() compares.
     */
    void
    save(CheckpointData &data, const ContactHistoryContext &) const override;

    /** The states through context.node_maps; positions from context.u. */
    void
    load(const CheckpointData        &data,
         const ContactHistoryContext &context) override;

    /** The output fields refer to the old mesh: on the new one, again. */
    void
    transfer(const ContactHistoryContext &) override;

    void
    list_vectors(std::vector<VectorType *> &vectors) override;

    /** The output fields on the layout of u, if they are not yet. */
    void
    reinit_fields(const IndexSet &owned_dofs, const VectorType &u);

    VectorType gap_field; // normalized gap at the multiplier dofs
    std::array<VectorType, dim - 1> slip_field; // slip rates, likewise

  private:
    // after commit()'s values of node j of pair p: records or restores
    // them (see commit())
    void
    keep_held(unsigned int p, unsigned int j, bool reevaluation);

    std::vector<ContactPairData<dim>> &pairs;
    const ComplementarityParameters   &complementarity;
    const MPI_Comm                    &comm;
    // per pair, the nodes held after the last step: held gap, rate and
    // acceleration by reference position (position_key())
    std::vector<std::map<std::array<double, dim>, std::array<double, 3>>>
      held;
  };
} // namespace ContactDynamics

#endif
