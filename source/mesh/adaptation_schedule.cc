#include <contact_dynamics/mesh/adaptation_schedule.h>
#include <contact_dynamics/output/checkpoint.h>

namespace ContactDynamics
{
  void
  AdaptationSchedule::save(CheckpointData &data, const RunContext &) const
  {
    data.set("mesh adaptation",
             {double(mesh_changes),
              double(cell_limit_reported),
              double(committed_active),
              double(previous_active)});
  }

  void
  AdaptationSchedule::load(const CheckpointData &data, const RunContext &)
  {
    // (before issue 38 the simulator saved these first in `mesh`)
    const auto &values  = data.has("mesh adaptation") ?
                            data.get("mesh adaptation", 4) :
                            data.get("mesh", 5);
    mesh_changes        = values[0];
    cell_limit_reported = values[1] != 0;
    committed_active    = values[2];
    previous_active     = values[3];
  }
} // namespace ContactDynamics
