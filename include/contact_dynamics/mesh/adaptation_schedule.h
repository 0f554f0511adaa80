// The owner of when the mesh follows the contact (Mesh refinement/Interval
// and On contact change) and of what the adaptation did so far: the active
// contact nodes of the last two committed steps, the number of mesh changes
// and whether the cell limit was reported.
#ifndef contact_dynamics_mesh_adaptation_schedule_h
#define contact_dynamics_mesh_adaptation_schedule_h

#include <contact_dynamics/history.h>
#include <contact_dynamics/mechanics/body_state.h>
#include <contact_dynamics/mesh/contact_refinement.h>

#include <functional>
#include <string>

namespace ContactDynamics
{
  class AdaptationSchedule : public HistoryOwner<RunContext>
  {
  public:
    /** `active_nodes`: the active contact nodes of the converged state. */
    AdaptationSchedule(const RefinementParameters   &parameters,
                       std::function<unsigned int()> active_nodes)
      : parameters(parameters)
      , active_nodes(std::move(active_nodes))
    {}

    std::string
    name() const override
    {
      return "mesh adaptation";
    }

    /** The active nodes of the step become those of the last step. */
    void
    commit(const RunContext &) override
    {
      previous_active  = committed_active;
      committed_active = active_nodes();
    }

    void
    save(CheckpointData &data, const RunContext &) const override;

    /** Also from a checkpoint before this owner (its `mesh` entry). */
    void
    load(const CheckpointData &data, const RunContext &) override;

    /** Whether to adapt after the committed step `completed`. */
    bool
    due_after(const unsigned int completed) const
    {
      return due(completed, committed_active, previous_active);
    }

    /**
     * Whether to adapt within the step that completes `completed`, whose
     * trial state has `active` active nodes (Re-solve).
     */
    bool
    due_within(const unsigned int completed, const unsigned int active) const
    {
      return due(completed, active, committed_active);
    }

    /**
     * Records `dropped` refinements the cell limit refused; true the first
     * time there are any (they are reported once).
     */
    bool
    cell_limit_reached(const unsigned int dropped)
    {
      const bool first    = dropped > 0 && !cell_limit_reported;
      cell_limit_reported = cell_limit_reported || dropped > 0;
      return first;
    }

    void
    transfer(const RunContext &) override
    {
      ++mesh_changes;
    }

    unsigned int
    n_mesh_changes() const
    {
      return mesh_changes;
    }

  private:
    bool
    due(const unsigned int completed,
        const unsigned int active,
        const unsigned int active_before) const
    {
      return completed % parameters.interval == 0 ||
             (parameters.on_contact_change && active != active_before);
    }

    const RefinementParameters   &parameters;
    std::function<unsigned int()> active_nodes;
    unsigned int                  mesh_changes        = 0;
    bool                          cell_limit_reported = false;
    // active contact nodes at the last and the one before committed steps
    unsigned int committed_active = 0, previous_active = 0;
  };
} // namespace ContactDynamics

#endif
