// The owner of the number of captures of each secondary node: how many
// committed steps found the node in contact (active) after a committed step
// that did not. A node that chatters (bounces off and lands again) counts
// every landing; one that stays in contact counts one. Kept by reference
// position, so that it survives mesh changes and restarts on another number
// of processes; written as the `captures` column of contact_surface-*.csv.
#ifndef contact_dynamics_contact_capture_count_h
#define contact_dynamics_contact_capture_count_h

#include <contact_dynamics/contact/contact_history.h>
#include <contact_dynamics/contact/contact_pair_data.h>

#include <array>
#include <map>
#include <string>
#include <vector>

namespace ContactDynamics
{
  template <int dim>
  class CaptureCount : public ContactHistoryOwner
  {
  public:
    explicit CaptureCount(const std::vector<ContactPairData<dim>> &pairs)
      : pairs(pairs)
    {}

    std::string
    name() const override
    {
      return "contact captures";
    }

    /**
     * Counts the nodes in contact now that were not at the last commit (a
     * node in contact at the first step counts one). The committed state
     * evaluated again on a new mesh only records which nodes are in contact
     * there: a node the refinement created counts from then on.
     */
    void
    commit(const ContactHistoryContext &context) override;

    /** Per pair: per node its reference position, count and contact. */
    void
    save(CheckpointData &data, const ContactHistoryContext &) const override;

    /**
     * What save() wrote; a checkpoint of an earlier version without counts
     * starts them at zero, with the contact of the loaded node states.
     */
    void
    load(const CheckpointData &data, const ContactHistoryContext &) override;

    /** Forgets the nodes the new mesh does not have. */
    void
    transfer(const ContactHistoryContext &) override;

    std::vector<NodeColumn>
    node_columns(const unsigned int pair) const override;

  private:
    struct Entry
    {
      unsigned int captures   = 0;
      bool         in_contact = false; // at the last commit
    };

    const std::vector<ContactPairData<dim>>              &pairs;
    std::vector<std::map<std::array<double, dim>, Entry>> nodes; // per pair
  };
} // namespace ContactDynamics

#endif
