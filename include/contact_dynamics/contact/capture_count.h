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
     * node in contact at the first step counts one; a node a mesh change
     * created counts from its first commit on).
     */
    void
    commit(const ContactHistoryContext &) override;

    /** Per pair: per counted node its reference position, count, state. */
    void
    save(CheckpointData &data, const ContactHistoryContext &) const override;

    /**
     * What save() wrote; a checkpoint of an earlier version without counts
     * starts them at zero.
     */
    void
    load(const CheckpointData &data, const ContactHistoryContext &) override;

    /** Keeps the nodes of the new mesh that the old one had. */
    void
    transfer(const ContactHistoryContext &) override;

    std::vector<NodeColumn>
    node_columns(const unsigned int pair) const override;

  private:
    using Key = std::array<double, dim>;

    enum Contact
    {
      out     = 0,
      in      = 1,
      unknown = 2 // a node new since a mesh change, until its first commit
    };

    struct Entry
    {
      unsigned int captures = 0;
      Contact      contact  = out;
    };

    static Key
    key(const Point<dim> &x);

    const std::vector<ContactPairData<dim>> &pairs;
    std::vector<std::map<Key, Entry>>        nodes; // per pair
  };
} // namespace ContactDynamics

#endif
